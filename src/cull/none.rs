//! `none`: the baseline that keeps every line, so the quartic always runs.

use super::{Cull, CullBounds};
use glam::Vec3;

/// Keeps every line.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoCull;

impl Cull for NoCull {
    fn name(&self) -> &'static str {
        "none"
    }

    #[inline(always)]
    fn keeps(&self, _bounds: &CullBounds, _origin: Vec3, _dir: Vec3) -> bool {
        true
    }
}
