//! The wedge cull ([`WedgeCull`]): a torus cull on the outer torus with the segment's
//! cone test ([`super::wedge::Wedge::line_meets`]) after it.

use super::PipeBend;
use super::wedge::Wedge;
use crate::{Cull, CullBounds, Ray, TorusRay};
use glam::Vec3;

/// A torus cull with the pipe bend's wedge in front of it: a line is kept only if the
/// torus cull keeps it against the outer torus and it passes the segment's cone within
/// the culls' margin inside the outer torus's bounding ball. Conservative when the torus
/// cull is: the solid lies in the outer torus and in the segment. Made by
/// [`PipeBend::wedge_cull`]; the wedge alone is `bend.wedge_cull(NoCull)`.
#[derive(Debug, Clone, Copy)]
pub struct WedgeCull<C> {
    torus_cull: C,
    wedge: Option<Wedge>,
    reach: f64,
    eta: f64,
}

impl<C: Cull> WedgeCull<C> {
    /// The wedge test alone, on a line from the outer torus's
    /// [`crate::Torus::line_to_local`].
    #[must_use]
    pub fn wedge_keeps(&self, origin: Vec3, dir: Vec3) -> bool {
        self.wedge
            .is_none_or(|w| w.line_meets(origin.as_dvec3(), dir.as_dvec3(), self.reach, self.eta))
    }
}

impl<C: Cull> Cull for WedgeCull<C> {
    fn name(&self) -> &'static str {
        self.torus_cull.name()
    }

    #[inline]
    fn keeps(&self, bounds: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        self.torus_cull.keeps(bounds, origin, dir) && self.wedge_keeps(origin, dir)
    }
}

impl PipeBend {
    /// `cull` (a torus cull, applied to the outer torus) with the segment's wedge test
    /// after it ([`WedgeCull`]); for the whole ring the wedge keeps every line.
    #[must_use]
    pub fn wedge_cull<C: Cull>(&self, cull: C) -> WedgeCull<C> {
        let bounds = self.outer.bounds();
        let eta = f64::from(bounds.minor_safe - bounds.minor_radius);
        WedgeCull {
            torus_cull: cull,
            wedge: self.wedge,
            reach: f64::from(bounds.outer_safe),
            eta,
        }
    }

    /// Whether `cull` keeps the ray against the outer torus (`cull` may be a
    /// [`WedgeCull`]). Conservative for the solid, as the solid lies in the outer torus.
    #[must_use]
    pub fn kept_by<C: Cull + ?Sized, R: TorusRay>(&self, cull: &C, ray: &R) -> bool {
        let ray: &Ray<R::Precision> = ray.as_ray();
        let line = self.outer.line_to_local(ray);
        cull.keeps(self.outer.bounds(), line.origin, line.dir)
    }
}
