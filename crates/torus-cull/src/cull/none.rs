//! `none`: the baseline that keeps every line, so the quartic always runs.

use super::kernel::{CullKernel, LaneBounds, scalar_cull};
use crate::num::{Real32, V3};

scalar_cull! {
    /// Keeps every line.
    pub struct NoCull = "none";
}

impl CullKernel for NoCull {
    #[inline(always)]
    fn keeps_lanes<R: Real32>(self, _: &LaneBounds<R>, o: V3<R>, _: V3<R>) -> R::Mask {
        o.x.mask(true)
    }
}
