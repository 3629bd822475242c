//! Enums with stable names: [`Named`], and the one error for a name that is none of them
//! ([`UnknownName`]).
//!
//! A cull, an instruction set, a scene or a workload case is written into results files
//! and read back from the command line and workload files by a stable string name. Each
//! such enum says what it is called ([`Named::KIND`]), lists its values ([`Named::ALL`])
//! and names each one ([`Named::name`]); parsing and the list of allowed names follow, so
//! every "unknown … (allowed: …)" message is written here, once.

use std::fmt;

/// An enum whose values have stable string names.
///
/// Implementors usually also implement [`fmt::Display`] as `f.write_str(self.name())` and
/// [`std::str::FromStr`] as [`Named::parse`], so that `format!("{value}")` and
/// `s.parse()` work too.
///
/// ```
/// use torus_cull::{CullKind, Named};
///
/// assert_eq!(CullKind::parse("skala"), Ok(CullKind::Skala));
/// assert_eq!(CullKind::Skala.name(), "skala");
/// assert_eq!(CullKind::allowed()[..3], ["none", "sphere", "aabb"]);
///
/// let err = CullKind::parse("donut").unwrap_err();
/// assert_eq!(err.name(), "donut");
/// assert!(err.to_string().starts_with("unknown cull 'donut' (allowed: none, sphere, aabb, "));
/// ```
pub trait Named: Copy + PartialEq + 'static {
    /// What one value is called in messages: `cull`, `scene`, `case`.
    const KIND: &'static str;

    /// Every value, in table order (the order of [`Named::allowed`]).
    const ALL: &'static [Self];

    /// The stable name: what results files record and [`Named::parse`] reads.
    fn name(self) -> &'static str;

    /// The names of [`Named::ALL`], in its order.
    fn allowed() -> Vec<&'static str> {
        Self::ALL.iter().map(|v| v.name()).collect()
    }

    /// The value named `s` (exactly, case-sensitive), or an error that names the allowed
    /// values.
    fn parse(s: &str) -> Result<Self, UnknownName> {
        Self::ALL
            .iter()
            .copied()
            .find(|v| v.name() == s)
            .ok_or_else(|| UnknownName {
                kind: Self::KIND,
                name: s.to_string(),
                allowed: Self::allowed(),
            })
    }
}

/// A name that is none of a [`Named`] enum's: `unknown KIND 'NAME' (allowed: a, b, c)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownName {
    kind: &'static str,
    name: String,
    allowed: Vec<&'static str>,
}

impl UnknownName {
    /// The name that was asked for.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// What was asked for ([`Named::KIND`]).
    pub fn kind(&self) -> &'static str {
        self.kind
    }

    /// The names that would have been accepted ([`Named::allowed`]).
    pub fn allowed(&self) -> &[&'static str] {
        &self.allowed
    }
}

impl fmt::Display for UnknownName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown {} '{}' (allowed: {})",
            self.kind,
            self.name,
            self.allowed.join(", ")
        )
    }
}

impl std::error::Error for UnknownName {}
