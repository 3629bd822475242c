//! Every cull by its stable name ([`CullKind`], used in results, the CLI and the plots),
//! parsed from text ([`Named`]), and the ones with a batch form ([`BatchCull`]): generated
//! from the one table of culls ([`super::table`]).

use super::CullBounds;
use super::kernel::{Cull, CullKernel, CullVisitor};
use super::table::{Shape, cull_table, define_culls};
use crate::names::Named;
use glam::Vec3;

cull_table!(define_culls);

impl CullKind {
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

    fn shapes(&self) -> &'static [super::Shape] {
        CullKind::shapes(*self)
    }

    #[inline]
    fn keeps(&self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        CullKind::keeps(*self, bounds, origin, dir)
    }
}

crate::named_display_and_from_str!(CullKind);

/// Generic code that runs with a concrete cull kernel; see [`BatchCull::visit_kernel`].
pub(crate) trait KernelVisitor {
    /// What the visit returns.
    type Output;
    /// Called once with the concrete kernel.
    fn visit<K: CullKernel>(self, kernel: K) -> Self::Output;
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
