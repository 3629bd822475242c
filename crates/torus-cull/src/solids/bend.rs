//! [`Solid`] and [`RayCast`] for the [`PipeBend`]: its methods, its hits on the face
//! struck ([`BendFace`]); and the conversions from the bend's answer types.

use crate::bend::{BendCrossing, BendF32Hit, BendFace, BendHit, BendProjection, PipeBend};
use crate::geometry::{
    NonFinitePoint, PointQueryError, SolidCrossing, SolidCrossings, SolidF32Hit, SolidHit,
    SolidProjection,
};
use crate::intersect::Hit;
use crate::{Cull, Culled, DRay, DRayError, Precision, Ray, RayCast, RayError, Solid};
use glam::{DVec3, Vec3};

impl<P: Precision> From<BendHit<P>> for SolidHit<P, BendFace> {
    fn from(hit: BendHit<P>) -> Self {
        SolidHit::new(hit.t, hit.normal, hit.point, hit.front_face, hit.face)
    }
}

/// A bend's hit as the ring torus's, the face dropped (what [`RayCast`] answers).
impl<P: Precision> From<BendHit<P>> for Hit<P> {
    fn from(hit: BendHit<P>) -> Self {
        SolidHit::from(hit).into()
    }
}

impl<P: Precision> From<BendCrossing<P>> for SolidCrossing<P, BendFace> {
    fn from(c: BendCrossing<P>) -> Self {
        SolidCrossing::new(c.t, c.normal, c.passage, c.face)
    }
}

impl From<BendF32Hit> for SolidF32Hit<BendFace> {
    fn from(answer: BendF32Hit) -> Self {
        SolidF32Hit::new(answer.hit.map(SolidHit::from), answer.escalated)
    }
}

impl From<BendProjection> for SolidProjection<BendFace> {
    fn from(p: BendProjection) -> Self {
        SolidProjection {
            point: p.point,
            normal: p.normal,
            signed_distance: p.signed_distance,
            face: p.face,
        }
    }
}

/// [`PipeBend::intersect`], `occluded`, `intersect_all`, `intersect_f32` (a whole bend's
/// hits and misses proved in f32; a cut bend's misses of the outer torus from outside the
/// outer tube, every other ray the f64 solid's), [`PipeBend::spawn`],
/// [`PipeBend::kept_by`] and the point queries. The world box is the outer torus's (the whole
/// ring's, holding any segment).
impl Solid for PipeBend {
    type Face = BendFace;

    fn world_aabb(&self) -> (Vec3, Vec3) {
        self.outer().world_aabb()
    }

    ray_verbs!(
        PipeBend::intersect,
        PipeBend::occluded,
        PipeBend::intersect_all,
        PipeBend::spawn,
        PipeBend::intersect_f32,
        PipeBend::kept_by
    );

    /// [`PipeBend::contains`], which answers `false` for a non-finite point: refused here
    /// first, as the other shapes refuse it.
    fn contains(&self, p: DVec3) -> Result<bool, PointQueryError> {
        if !p.is_finite() {
            return Err(NonFinitePoint(p).into());
        }
        Ok(PipeBend::contains(self, p))
    }

    fn signed_distance(&self, p: DVec3) -> Result<f64, PointQueryError> {
        Ok(PipeBend::signed_distance(self, p)?)
    }

    fn project_point(&self, p: DVec3) -> Result<SolidProjection<BendFace>, PointQueryError> {
        Ok(PipeBend::project_point(self, p)?.into())
    }
}

/// [`PipeBend::intersect`] with the face dropped; the bool is [`PipeBend::occluded`].
impl<P: Precision> RayCast<Ray<P>> for PipeBend {
    #[inline]
    fn cast_ray_and_get_normal(&self, ray: &Ray<P>) -> Option<Hit<P>> {
        self.intersect(ray).map(Hit::from)
    }

    #[inline]
    fn intersects_ray(&self, ray: &Ray<P>) -> bool {
        PipeBend::occluded(self, ray)
    }
}

impl PipeBend {
    /// This bend behind `cull`, for the [`RayCast`] queries
    /// ([`PipeBend::intersect_culled`]: the cull on the outer torus; for the wedge too,
    /// pass [`PipeBend::wedge_cull`]'s).
    #[inline]
    #[must_use]
    pub fn with_cull<C: Cull>(&self, cull: C) -> Culled<'_, C, PipeBend> {
        Culled { shape: self, cull }
    }
}

/// [`PipeBend::intersect_culled`]; the bool is [`PipeBend::kept_by`] then
/// [`PipeBend::occluded`].
impl<C: Cull, P: Precision> RayCast<Ray<P>> for Culled<'_, C, PipeBend> {
    #[inline]
    fn cast_ray_and_get_normal(&self, ray: &Ray<P>) -> Option<Hit<P>> {
        self.shape.intersect_culled(&self.cull, ray).map(Hit::from)
    }

    #[inline]
    fn intersects_ray(&self, ray: &Ray<P>) -> bool {
        self.shape.kept_by(&self.cull, ray) && self.shape.occluded(ray)
    }
}
