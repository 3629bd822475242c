//! Every cull by its stable name ([`CullKind`], used in results, the CLI and the plots),
//! parsed from text ([`Named`]), and the ones with a batch form ([`BatchCull`]).

use super::kernel::{Cull, CullKernel, CullVisitor};
use super::{
    AabbCull, CullBounds, CychoszCull, DiscriminantCull, DiscriminantF64Cull, EllipsoidCull,
    NoCull, QuadricCull, SkalaCull, SphereCull, ThickCylinderCull,
};
use crate::names::Named;
use glam::Vec3;

/// The one map from a cull's name to its type: binds the cull of `$kind` (a [`CullKind`]
/// or a [`BatchCull`], `$enum`) to `$cull` and evaluates `$body`, for every cull with a
/// kernel; `discriminant_f64` (a [`CullKind`] only: no kernel, no batch form) evaluates
/// `$f64` instead. [`CullKind::visit`] and [`BatchCull::visit_kernel`] are this map with
/// two different trait bounds.
macro_rules! by_kind {
    ($enum:ident, $kind:expr, $cull:ident => $body:expr $(, f64: $f64:expr)?) => {
        match $kind {
            $enum::NoCull => by_kind!(@bind $cull = NoCull, $body),
            $enum::Sphere => by_kind!(@bind $cull = SphereCull, $body),
            $enum::Aabb => by_kind!(@bind $cull = AabbCull, $body),
            $enum::Cychosz => by_kind!(@bind $cull = CychoszCull, $body),
            $enum::ThickCylinder => by_kind!(@bind $cull = ThickCylinderCull, $body),
            $enum::Skala => by_kind!(@bind $cull = SkalaCull, $body),
            $enum::Ellipsoid => by_kind!(@bind $cull = EllipsoidCull, $body),
            $enum::Quadric => by_kind!(@bind $cull = QuadricCull, $body),
            $enum::Discriminant => by_kind!(@bind $cull = DiscriminantCull, $body),
            $(CullKind::DiscriminantF64 => $f64,)?
        }
    };
    (@bind $cull:ident = $value:expr, $body:expr) => {{
        let $cull = $value;
        $body
    }};
}

/// Every cull by name: the registry.
///
/// A cull chosen at run time (from a results file, the command line, a setting) is a
/// `CullKind`; it is a [`Cull`] itself, and [`CullKind::visit`] hands generic code the
/// concrete cull type instead. The names are stable ([`Named`]): they are what results
/// files record.
///
/// ```
/// use torus_cull::{CullKind, Named, Ray, Torus, intersect_culled};
/// use glam::Vec3;
///
/// let kind: CullKind = "skala".parse()?;
/// assert_eq!(kind, CullKind::Skala);
/// assert_eq!(kind.to_string(), "skala");
/// assert_eq!(CullKind::NoCull.name(), "none"); // the baseline: no test at all
/// assert!("donut".parse::<CullKind>().is_err());
///
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::NEG_Y)?; // straight down the hole
/// let line = torus.line_to_local(&hole);
/// assert!(!kind.keeps(torus.bounds(), line.origin, line.dir)); // a proven miss
/// assert!(CullKind::NoCull.keeps(torus.bounds(), line.origin, line.dir)); // keeps all
///
/// // Every cull gives the same answer; they differ in how many quartics they spare.
/// for kind in CullKind::TIMED {
///     assert_eq!(intersect_culled(&kind, &torus, &hole), None, "{kind}");
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CullKind {
    /// No test: always run the quartic (the baseline), [`NoCull`]; named `none`.
    NoCull,
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
        CullKind::NoCull,
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

    /// Hands the concrete cull to `visitor`, so generic code is monomorphized per cull.
    pub fn visit<V: CullVisitor>(self, visitor: V) -> V::Output {
        by_kind!(CullKind, self, cull => visitor.visit(cull), f64: visitor.visit(DiscriminantF64Cull))
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
        Named::name(*self)
    }

    #[inline]
    fn keeps(&self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        CullKind::keeps(*self, bounds, origin, dir)
    }
}

/// The registry by stable name: `"skala".parse::<CullKind>()`, `format!("{kind}")`.
impl Named for CullKind {
    const KIND: &'static str = "cull";
    const ALL: &'static [CullKind] = &CullKind::TIMED;

    fn name(self) -> &'static str {
        match self {
            CullKind::NoCull => "none",
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
}

crate::named_display_and_from_str!(CullKind);

/// Generic code that runs with a concrete cull kernel; see [`CullKind::visit_kernel`].
pub(crate) trait KernelVisitor {
    /// What the visit returns.
    type Output;
    /// Called once with the concrete kernel.
    fn visit<K: CullKernel>(self, kernel: K) -> Self::Output;
}

/// The culls with a batch form ([`crate::batch::cull_batch`], the
/// [`crate::batch::Wavefront`]): every [`CullKind`] but `discriminant_f64`, whose point is
/// the f64 evaluation, which the f32 `discriminant` already makes unnecessary at this
/// padding. The batch API takes a `BatchCull`, so a cull without a batch form is refused
/// when the program is compiled, not when it runs; [`CullKind::batched`] converts a cull
/// chosen at run time.
///
/// ```
/// use torus_cull::batch::{BATCHED, BatchCull};
/// use torus_cull::{CullKind, Named};
///
/// assert_eq!(CullKind::Skala.batched(), Some(BatchCull::Skala));
/// assert_eq!(CullKind::DiscriminantF64.batched(), None);
/// assert_eq!(CullKind::from(BatchCull::Skala), CullKind::Skala);
/// // The same stable names as the scalar culls, in the same table order.
/// assert_eq!(BatchCull::Quadric.name(), "quadric");
/// assert_eq!(BATCHED.len(), CullKind::TIMED.len() - 1);
/// let err = BatchCull::parse("discriminant_f64").unwrap_err().to_string();
/// assert!(err.starts_with("unknown batched cull 'discriminant_f64' (allowed: none, "));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum BatchCull {
    /// [`CullKind::NoCull`]: no cull stage, every ray is intersected (the baseline).
    NoCull,
    /// [`CullKind::Sphere`].
    Sphere,
    /// [`CullKind::Aabb`].
    Aabb,
    /// [`CullKind::Cychosz`].
    Cychosz,
    /// [`CullKind::ThickCylinder`].
    ThickCylinder,
    /// [`CullKind::Skala`].
    Skala,
    /// [`CullKind::Ellipsoid`].
    Ellipsoid,
    /// [`CullKind::Quadric`].
    Quadric,
    /// [`CullKind::Discriminant`].
    Discriminant,
}

/// Every [`BatchCull`], in [`CullKind::TIMED`] order.
pub const BATCHED: [BatchCull; 9] = [
    BatchCull::NoCull,
    BatchCull::Sphere,
    BatchCull::Aabb,
    BatchCull::Cychosz,
    BatchCull::ThickCylinder,
    BatchCull::Skala,
    BatchCull::Ellipsoid,
    BatchCull::Quadric,
    BatchCull::Discriminant,
];

impl CullKind {
    /// This cull's batch form, or `None` for the one cull without one
    /// (`discriminant_f64`).
    pub const fn batched(self) -> Option<BatchCull> {
        Some(match self {
            CullKind::NoCull => BatchCull::NoCull,
            CullKind::Sphere => BatchCull::Sphere,
            CullKind::Aabb => BatchCull::Aabb,
            CullKind::Cychosz => BatchCull::Cychosz,
            CullKind::ThickCylinder => BatchCull::ThickCylinder,
            CullKind::Skala => BatchCull::Skala,
            CullKind::Ellipsoid => BatchCull::Ellipsoid,
            CullKind::Quadric => BatchCull::Quadric,
            CullKind::Discriminant => BatchCull::Discriminant,
            CullKind::DiscriminantF64 => return None,
        })
    }
}

impl BatchCull {
    /// The same cull in the registry of every cull.
    pub const fn kind(self) -> CullKind {
        match self {
            BatchCull::NoCull => CullKind::NoCull,
            BatchCull::Sphere => CullKind::Sphere,
            BatchCull::Aabb => CullKind::Aabb,
            BatchCull::Cychosz => CullKind::Cychosz,
            BatchCull::ThickCylinder => CullKind::ThickCylinder,
            BatchCull::Skala => CullKind::Skala,
            BatchCull::Ellipsoid => CullKind::Ellipsoid,
            BatchCull::Quadric => CullKind::Quadric,
            BatchCull::Discriminant => CullKind::Discriminant,
        }
    }

    /// Hands the cull's one-source kernel to `visitor`.
    pub(crate) fn visit_kernel<V: KernelVisitor>(self, visitor: V) -> V::Output {
        by_kind!(BatchCull, self, kernel => visitor.visit(kernel))
    }
}

impl From<BatchCull> for CullKind {
    fn from(cull: BatchCull) -> CullKind {
        cull.kind()
    }
}

/// The stable names of [`CullKind`], in its table order.
impl Named for BatchCull {
    const KIND: &'static str = "batched cull";
    const ALL: &'static [BatchCull] = &BATCHED;

    fn name(self) -> &'static str {
        Named::name(self.kind())
    }
}

crate::named_display_and_from_str!(BatchCull);

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
    fn the_batched_culls_are_the_timed_ones_with_a_kernel() {
        // The type each enum hands over: the same cull type for the same name.
        struct Kernel;
        impl KernelVisitor for Kernel {
            type Output = &'static str;
            fn visit<K: CullKernel>(self, _: K) -> &'static str {
                std::any::type_name::<K>()
            }
        }
        struct Scalar;
        impl CullVisitor for Scalar {
            type Output = &'static str;
            fn visit<C: Cull>(self, _: C) -> &'static str {
                std::any::type_name::<C>()
            }
        }
        let batched: Vec<CullKind> = CullKind::TIMED
            .iter()
            .filter_map(|c| c.batched())
            .map(CullKind::from)
            .collect();
        assert_eq!(batched, BATCHED.map(CullKind::from));
        for b in BATCHED {
            assert_eq!(b.kind().batched(), Some(b));
            assert_eq!(b.visit_kernel(Kernel), b.kind().visit(Scalar));
            assert_eq!(b.to_string(), b.kind().to_string());
        }
        assert_eq!(CullKind::DiscriminantF64.batched(), None);
    }
}
