//! [`Solid`] for the ring [`Torus`]: its free functions and methods, its hits on
//! [`NoFace`]; and the conversions from the ring torus's answer types.

use crate::certified::F32Hit;
use crate::geometry::{
    NoFace, PointQueryError, SolidCrossing, SolidCrossings, SolidF32Hit, SolidHit, SolidProjection,
};
use crate::intersect::{Crossing, Crossings, Hit};
use crate::{
    DRay, DRayError, Precision, Ray, RayError, Solid, Torus, intersect, intersect_all,
    intersect_f32, occluded,
};
use glam::{DVec3, Vec3};

impl<P: Precision> From<Hit<P>> for SolidHit<P, NoFace> {
    fn from(hit: Hit<P>) -> Self {
        SolidHit::new(hit.t, hit.normal, hit.point, hit.front_face, NoFace)
    }
}

/// Any solid's hit as the ring torus's: the face dropped (what [`crate::RayCast`]
/// answers for every shape).
impl<P: Precision, F> From<SolidHit<P, F>> for Hit<P> {
    fn from(hit: SolidHit<P, F>) -> Self {
        Hit {
            t: hit.t,
            normal: hit.normal,
            point: hit.point,
            front_face: hit.front_face,
        }
    }
}

impl<P: Precision> From<Crossing<P>> for SolidCrossing<P, NoFace> {
    fn from(c: Crossing<P>) -> Self {
        SolidCrossing::new(c.t, c.normal, c.passage, NoFace)
    }
}

/// The same crossings over the same range, on [`NoFace`].
impl<P: Precision> From<Crossings<P>> for SolidCrossings<P, NoFace> {
    fn from(all: Crossings<P>) -> Self {
        let (t_min, t_max) = all.range();
        let mut out = SolidCrossings::new(t_min, t_max, all.starts_inside());
        for &c in &all {
            out.push(c.into());
        }
        out
    }
}

impl From<F32Hit> for SolidF32Hit<NoFace> {
    fn from(answer: F32Hit) -> Self {
        SolidF32Hit::new(answer.hit.map(SolidHit::from), answer.escalated)
    }
}

/// [`intersect()`], [`occluded()`], [`intersect_all`], [`intersect_f32`] (hits and misses
/// proved in f32), [`Torus::spawn`] and the point queries.
impl Solid for Torus {
    type Face = NoFace;

    fn world_aabb(&self) -> (Vec3, Vec3) {
        Torus::world_aabb(self)
    }

    fn hit(&self, ray: &Ray) -> Option<SolidHit<Vec3, NoFace>> {
        intersect(self, ray).map(SolidHit::from)
    }

    fn hit_f64(&self, ray: &DRay) -> Option<SolidHit<DVec3, NoFace>> {
        intersect(self, ray).map(SolidHit::from)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        occluded(self, ray)
    }

    fn occluded_f64(&self, ray: &DRay) -> bool {
        occluded(self, ray)
    }

    fn crossings(&self, ray: &Ray) -> SolidCrossings<Vec3, NoFace> {
        intersect_all(self, ray).into()
    }

    fn crossings_f64(&self, ray: &DRay) -> SolidCrossings<DVec3, NoFace> {
        intersect_all(self, ray).into()
    }

    fn hit_f32_certified(&self, ray: &Ray) -> SolidF32Hit<NoFace> {
        intersect_f32(self, ray).into()
    }

    fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Result<Ray, RayError> {
        Torus::spawn(self, ray, t, dir)
    }

    fn spawn_f64(&self, ray: &DRay, t: f64, dir: DVec3) -> Result<DRay, DRayError> {
        Torus::spawn(self, ray, t, dir)
    }

    fn contains(&self, p: DVec3) -> Result<bool, PointQueryError> {
        Ok(Torus::contains(self, p)?)
    }

    fn signed_distance(&self, p: DVec3) -> Result<f64, PointQueryError> {
        Ok(Torus::signed_distance(self, p)?)
    }

    fn project_point(&self, p: DVec3) -> Result<SolidProjection<NoFace>, PointQueryError> {
        Ok(Torus::project_point(self, p)?.into())
    }
}
