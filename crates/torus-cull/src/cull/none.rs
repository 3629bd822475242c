//! `none`: the baseline that keeps every line, so the quartic always runs.

use super::CullBounds;
use super::kernel::{CullKernel, scalar_cull};
use crate::num::M32s;
use crate::num::Vec3s;
use pulp::Simd;

scalar_cull! {
    /// Keeps every line.
    pub struct NoCull = "none";
}

impl CullKernel for NoCull {
    #[inline(always)]
    fn keeps_lanes<S: Simd>(self, s: S, _: &CullBounds, _: Vec3s<S>, _: Vec3s<S>) -> M32s<S> {
        M32s::splat(s, true)
    }
}
