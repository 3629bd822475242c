//! The cull the kernel runs before the intersection ([`GpuCull`]): every cull with a batch
//! form, by the kernel's code, and its conversions to and from the CPU's culls.

use crate::cull::BatchCull;
use crate::{CullKind, Named};
use std::fmt;

/// The cull the kernel runs before the intersection (a rejected ray is a miss): every
/// cull with a batch form ([`BatchCull`]), the CPU's math on the torus padded by the
/// GPU's margin (the CPU's η plus the kernel's line error; see the module doc and
/// docs/math.md, "The GPU's culls").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum GpuCull {
    /// No cull: every ray goes to the certified intersection.
    None,
    /// The bounding sphere R + r ([`crate::SphereCull`]).
    Sphere,
    /// The torus's box ([`crate::AabbCull`]).
    Aabb,
    /// Cychosz's bounding sphere R + r plus the slab |y| ≤ r ([`crate::CychoszCull`]).
    Cychosz,
    /// The shell R − r ≤ ρ ≤ R + r, |y| ≤ r ([`crate::ThickCylinderCull`]).
    ThickCylinder,
    /// Skala's circle-based test ([`crate::SkalaCull`]).
    Skala,
    /// The outer ellipsoid and the slab ([`crate::EllipsoidCull`]).
    Ellipsoid,
    /// The outer ellipsoid, the slab and the inner hyperboloid ([`crate::QuadricCull`]),
    /// with the hyperboloid's test widened by its evaluation error.
    Quadric,
    /// The quartic's real-root classification ([`crate::DiscriminantCull`]), rejecting
    /// only where a running error bound proves the classification.
    Discriminant,
}

impl GpuCull {
    /// Every cull, in [`CullKind::TIMED`] order (the kernel's codes 0 to 8).
    pub const ALL: [GpuCull; 9] = [
        GpuCull::None,
        GpuCull::Sphere,
        GpuCull::Aabb,
        GpuCull::Cychosz,
        GpuCull::ThickCylinder,
        GpuCull::Skala,
        GpuCull::Ellipsoid,
        GpuCull::Quadric,
        GpuCull::Discriminant,
    ];

    /// The same cull in the registry of every cull.
    pub const fn kind(self) -> CullKind {
        self.batched().kind()
    }

    /// The same cull's batch form on the CPU.
    pub const fn batched(self) -> BatchCull {
        match self {
            GpuCull::None => BatchCull::NoCull,
            GpuCull::Sphere => BatchCull::Sphere,
            GpuCull::Aabb => BatchCull::Aabb,
            GpuCull::Cychosz => BatchCull::Cychosz,
            GpuCull::ThickCylinder => BatchCull::ThickCylinder,
            GpuCull::Skala => BatchCull::Skala,
            GpuCull::Ellipsoid => BatchCull::Ellipsoid,
            GpuCull::Quadric => BatchCull::Quadric,
            GpuCull::Discriminant => BatchCull::Discriminant,
        }
    }

    /// The stable name (as [`crate::CullKind`]'s).
    pub fn name(self) -> &'static str {
        Named::name(self.kind())
    }

    /// The kernel's code for the cull (`Params.config.y`).
    pub(crate) fn code(self) -> u32 {
        GpuCull::ALL
            .iter()
            .position(|&c| c == self)
            .expect("every cull is in ALL") as u32
    }
}

/// Every batch cull runs on the GPU.
impl From<BatchCull> for GpuCull {
    fn from(cull: BatchCull) -> GpuCull {
        match cull {
            BatchCull::NoCull => GpuCull::None,
            BatchCull::Sphere => GpuCull::Sphere,
            BatchCull::Aabb => GpuCull::Aabb,
            BatchCull::Cychosz => GpuCull::Cychosz,
            BatchCull::ThickCylinder => GpuCull::ThickCylinder,
            BatchCull::Skala => GpuCull::Skala,
            BatchCull::Ellipsoid => GpuCull::Ellipsoid,
            BatchCull::Quadric => GpuCull::Quadric,
            BatchCull::Discriminant => GpuCull::Discriminant,
        }
    }
}

impl From<GpuCull> for CullKind {
    fn from(cull: GpuCull) -> CullKind {
        cull.kind()
    }
}

/// A [`CullKind`] on the GPU: every one but `discriminant_f64` (no batch form).
impl TryFrom<CullKind> for GpuCull {
    type Error = CullKind;

    fn try_from(kind: CullKind) -> Result<GpuCull, CullKind> {
        kind.batched().map(GpuCull::from).ok_or(kind)
    }
}

impl fmt::Display for GpuCull {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cull::BATCHED;

    #[test]
    fn every_batch_cull_is_a_gpu_cull_by_the_same_name() {
        assert_eq!(GpuCull::ALL.len(), BATCHED.len());
        for (i, (&gpu, &batch)) in GpuCull::ALL.iter().zip(&BATCHED).enumerate() {
            assert_eq!(GpuCull::from(batch), gpu);
            assert_eq!(gpu.batched(), batch);
            assert_eq!(gpu.kind(), batch.kind());
            assert_eq!(gpu.name(), Named::name(batch.kind()));
            assert_eq!(GpuCull::try_from(batch.kind()), Ok(gpu));
            // The kernel's switch reads the code in this order.
            assert_eq!(gpu.code(), i as u32);
        }
        assert_eq!(
            GpuCull::try_from(CullKind::DiscriminantF64),
            Err(CullKind::DiscriminantF64)
        );
    }
}
