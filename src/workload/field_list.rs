//! One numeric list of a workload key, checked the same way wherever a key has one: not
//! empty, every value allowed, and no value twice where the key's records are keyed by the
//! value; a fault names the field, the index and what is allowed.

use crate::number::Num;

/// (the field at fault, what is wrong and what is allowed).
pub(super) type FieldError = (String, String);

/// Whether a list may name a value twice: refused where each value makes records keyed by
/// it (a repeat would only write the same records again), allowed where it always was.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Repeats {
    Allowed,
    Refused,
}

/// Checks the list `field` (its full name, e.g. `shapes.family.nu`): not empty and every
/// value `ok`, each value judged in order (so the first fault is the one named); with
/// [`Repeats::Refused`] a value listed before is a fault too.
pub(super) fn check_list(
    field: &str,
    values: &[f64],
    ok: impl Fn(f64) -> bool,
    allowed: &str,
    repeats: Repeats,
) -> Result<(), FieldError> {
    if values.is_empty() {
        return Err((
            field.to_string(),
            format!("must list at least one value (allowed: {allowed})"),
        ));
    }
    for (i, &v) in values.iter().enumerate() {
        if !ok(v) {
            return Err((
                format!("{field}[{i}]"),
                format!("{} is invalid (allowed: {allowed})", Num(v)),
            ));
        }
        if repeats == Repeats::Refused && values[..i].contains(&v) {
            return Err((
                format!("{field}[{i}]"),
                format!("{} is listed twice", Num(v)),
            ));
        }
    }
    Ok(())
}
