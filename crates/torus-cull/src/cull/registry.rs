//! Every cull by its stable name ([`CullKind`], used in results, the CLI and the plots),
//! parsed from text ([`UnknownCull`]), and the ones with a batch form ([`BATCHED`]).

use super::kernel::{Cull, CullKernel, CullVisitor};
use super::{
    AabbCull, CullBounds, CychoszCull, DiscriminantCull, DiscriminantF64Cull, EllipsoidCull,
    NoCull, QuadricCull, SkalaCull, SphereCull, ThickCylinderCull,
};
use glam::Vec3;
use std::fmt;
use std::str::FromStr;

/// The one map from [`CullKind`] to its cull type: binds the cull of `$kind` to `$cull`
/// and evaluates `$body`, for every cull with a kernel; `discriminant_f64` (no kernel, no
/// batch form) evaluates `$f64` instead. [`CullKind::visit`] and
/// [`CullKind::visit_kernel`] are this map with two different trait bounds.
macro_rules! by_kind {
    ($kind:expr, $cull:ident => $body:expr, f64: $f64:expr) => {
        match $kind {
            CullKind::None => by_kind!(@bind $cull = NoCull, $body),
            CullKind::Sphere => by_kind!(@bind $cull = SphereCull, $body),
            CullKind::Aabb => by_kind!(@bind $cull = AabbCull, $body),
            CullKind::Cychosz => by_kind!(@bind $cull = CychoszCull, $body),
            CullKind::ThickCylinder => by_kind!(@bind $cull = ThickCylinderCull, $body),
            CullKind::Skala => by_kind!(@bind $cull = SkalaCull, $body),
            CullKind::Ellipsoid => by_kind!(@bind $cull = EllipsoidCull, $body),
            CullKind::Quadric => by_kind!(@bind $cull = QuadricCull, $body),
            CullKind::Discriminant => by_kind!(@bind $cull = DiscriminantCull, $body),
            CullKind::DiscriminantF64 => $f64,
        }
    };
    (@bind $cull:ident = $value:expr, $body:expr) => {{
        let $cull = $value;
        $body
    }};
}

/// Every cull by name: the registry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CullKind {
    /// No test: always run the quartic (the baseline).
    None,
    /// Bounding sphere of radius R + r.
    Sphere,
    /// The torus's box [−(R+r), R+r] × [−r, r] × [−(R+r), R+r].
    Aabb,
    /// Cychosz (Graphics Gems II, 1991): sphere R + r, then the slab |y| ≤ r at the chord ends.
    Cychosz,
    /// The shell R − r ≤ ρ ≤ R + r, |y| ≤ r (POV-Ray's `Test_Thick_Cylinder`).
    ThickCylinder,
    /// Skala's circle-based test, with the paper's misprints corrected.
    Skala,
    /// Cychosz with the sphere replaced by the outer ellipsoid ρ² + (ν + 1)·y² ≤ (R + r)².
    Ellipsoid,
    /// The outer ellipsoid ∩ the slab ∩ the inner hyperboloid ρ² − (ν − 1)·y² ≥ (R − r)².
    Quadric,
    /// The quartic's real-root classification (no root, no branch), in f32.
    Discriminant,
    /// The same classification evaluated in f64.
    DiscriminantF64,
}

impl CullKind {
    /// The culls measured by the harness, in table order.
    pub const TIMED: [CullKind; 10] = [
        CullKind::None,
        CullKind::Sphere,
        CullKind::Aabb,
        CullKind::Cychosz,
        CullKind::ThickCylinder,
        CullKind::Skala,
        CullKind::Ellipsoid,
        CullKind::Quadric,
        CullKind::Discriminant,
        CullKind::DiscriminantF64,
    ];

    /// The stable name.
    pub fn name(self) -> &'static str {
        match self {
            CullKind::None => "none",
            CullKind::Sphere => "sphere",
            CullKind::Aabb => "aabb",
            CullKind::Cychosz => "cychosz",
            CullKind::ThickCylinder => "thick_cylinder",
            CullKind::Skala => "skala",
            CullKind::Ellipsoid => "ellipsoid",
            CullKind::Quadric => "quadric",
            CullKind::Discriminant => "discriminant",
            CullKind::DiscriminantF64 => "discriminant_f64",
        }
    }

    /// Hands the concrete cull to `visitor`, so generic code is monomorphized per cull.
    pub fn visit<V: CullVisitor>(self, visitor: V) -> V::Output {
        by_kind!(self, cull => visitor.visit(cull), f64: visitor.visit(DiscriminantF64Cull))
    }

    /// One line through the registry: convenient, but dispatches per call.
    #[must_use]
    pub fn keeps(self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        struct One<'a>(&'a CullBounds, Vec3, Vec3);
        impl CullVisitor for One<'_> {
            type Output = bool;
            fn visit<C: Cull>(self, cull: C) -> bool {
                cull.keeps(self.0, self.1, self.2)
            }
        }
        self.visit(One(bounds, origin, dir))
    }
}

/// A cull chosen at run time is a cull: `intersect_culled(&kind, …)` works as with the
/// cull's own type, one `match` per line dearer.
impl Cull for CullKind {
    fn name(&self) -> &'static str {
        CullKind::name(*self)
    }

    #[inline]
    fn keeps(&self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        CullKind::keeps(*self, bounds, origin, dir)
    }
}

impl fmt::Display for CullKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown cull name.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UnknownCull(pub String);

impl fmt::Display for UnknownCull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<_> = CullKind::TIMED.iter().map(|c| c.name()).collect();
        write!(
            f,
            "unknown cull '{}' (allowed: {})",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for UnknownCull {}

impl FromStr for CullKind {
    type Err = UnknownCull;
    fn from_str(s: &str) -> Result<CullKind, UnknownCull> {
        CullKind::TIMED
            .iter()
            .copied()
            .find(|c| c.name() == s)
            .ok_or_else(|| UnknownCull(s.to_string()))
    }
}

/// Generic code that runs with a concrete cull kernel; see [`CullKind::visit_kernel`].
pub(crate) trait KernelVisitor {
    /// What the visit returns.
    type Output;
    /// Called once with the concrete kernel.
    fn visit<K: CullKernel>(self, kernel: K) -> Self::Output;
}

impl CullKind {
    /// Hands the cull's one-source kernel to `visitor`, or `None` for a cull without a
    /// lane form (`discriminant_f64`): the kernels are exactly [`BATCHED`].
    pub(crate) fn visit_kernel<V: KernelVisitor>(self, visitor: V) -> Option<V::Output> {
        Some(by_kind!(self, kernel => visitor.visit(kernel), f64: return None))
    }
}

/// The culls with a batch form, in [`CullKind::TIMED`] order: every one but
/// `discriminant_f64`, whose point is the f64 evaluation, which the f32 `discriminant`
/// already makes unnecessary at this padding.
pub const BATCHED: [CullKind; 9] = {
    let mut out = [CullKind::None; 9];
    let (mut i, mut n) = (0, 0);
    while i < CullKind::TIMED.len() {
        if !matches!(CullKind::TIMED[i], CullKind::DiscriminantF64) {
            out[n] = CullKind::TIMED[i];
            n += 1;
        }
        i += 1;
    }
    assert!(n == out.len());
    out
};

/// A cull without a batch form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct NoBatchForm(pub CullKind);

impl fmt::Display for NoBatchForm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = BATCHED.iter().map(|c| c.name()).collect();
        write!(
            f,
            "cull '{}' has no batch form (batched: {})",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for NoBatchForm {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_round_trips_names() {
        for c in CullKind::TIMED {
            assert_eq!(c.name().parse::<CullKind>().unwrap(), c);
            struct Name;
            impl CullVisitor for Name {
                type Output = &'static str;
                fn visit<C: Cull>(self, cull: C) -> &'static str {
                    cull.name()
                }
            }
            assert_eq!(c.visit(Name), c.name());
        }
        let err = "bogus".parse::<CullKind>().unwrap_err().to_string();
        assert!(err.contains("bogus") && err.contains("skala"), "{err}");
    }

    #[test]
    fn the_kernels_are_the_batched_culls() {
        struct Has;
        impl KernelVisitor for Has {
            type Output = ();
            fn visit<K: CullKernel>(self, _: K) {}
        }
        for c in CullKind::TIMED {
            assert_eq!(c.visit_kernel(Has).is_some(), BATCHED.contains(&c), "{c}");
        }
    }
}
