//! [`Solid`] for the ring [`Torus`]: its free functions and methods, its hits on
//! [`NoFace`]; and the conversions from the ring torus's answer types.

use crate::certified::F32Hit;
use crate::geometry::{
    NoFace, PointQueryError, SolidCrossing, SolidCrossings, SolidF32Hit, SolidHit, SolidProjection,
};
use crate::intersect::{Crossing, Crossings, Hit};
use crate::{
    Cull, DRay, DRayError, Precision, Ray, RayError, Solid, Torus, intersect, intersect_all,
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
/// proved in f32), [`Torus::spawn`], the cull step of [`crate::intersect_culled`] and the
/// point queries.
impl Solid for Torus {
    type Face = NoFace;

    fn world_aabb(&self) -> (Vec3, Vec3) {
        Torus::world_aabb(self)
    }

    ray_verbs!(
        intersect,
        occluded,
        intersect_all,
        Torus::spawn,
        intersect_f32,
        kept_by
    );

    point_verbs!(Torus);
}

/// [`Torus::with_cull`]'s step ([`crate::intersect_culled`]'s): the ray's line in the
/// torus frame against the torus's own bounds; in the order the other shapes'
/// `kept_by` take their arguments.
#[inline]
fn kept_by<C: Cull + ?Sized, P: Precision>(torus: &Torus, cull: &C, ray: &Ray<P>) -> bool {
    crate::intersect::kept_by(cull, torus, ray)
}
