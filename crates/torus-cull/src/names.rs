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
/// The crate's internal macro `named_display_and_from_str!` gives an implementor
/// [`fmt::Display`] (its name) and [`std::str::FromStr`] ([`Named::parse`]), so that
/// `format!("{value}")` and `s.parse()` work too.
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

/// Implements [`fmt::Display`] (the stable name) and [`std::str::FromStr`]
/// ([`Named::parse`], erring with [`UnknownName`]) for each [`Named`] type given.
///
/// ```
/// use torus_cull::batch::Isa;
/// // Isa's impls come from this macro.
/// assert_eq!(Isa::Scalar.to_string(), "scalar");
/// assert_eq!("scalar".parse::<Isa>(), Ok(Isa::Scalar));
/// ```
///
/// Internal: exported only because the lab crate of this workspace uses it for its own
/// names, and hidden from the docs; not part of the public API.
#[doc(hidden)]
#[macro_export]
macro_rules! named_display_and_from_str {
    ($($named:ty),+ $(,)?) => {$(
        impl ::std::fmt::Display for $named {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str($crate::Named::name(*self))
            }
        }

        impl ::std::str::FromStr for $named {
            type Err = $crate::UnknownName;
            fn from_str(s: &str) -> ::std::result::Result<$named, $crate::UnknownName> {
                <$named as $crate::Named>::parse(s)
            }
        }
    )+};
}
