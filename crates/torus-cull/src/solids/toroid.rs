//! [`Solid`] and [`RayCast`] for the family's [`Toroid`]: its methods, its hits on
//! [`NoFace`].

use crate::family::{FamilyPointError, Toroid};
use crate::geometry::{
    NoFace, PointQueryError, SolidCrossings, SolidF32Hit, SolidHit, SolidProjection,
};
use crate::{Cull, Culled, DRay, DRayError, Ray, RayCast, RayError, Solid, TorusRay};
use glam::{DVec3, Vec3};

/// The text of [`FamilyPointError::Unsupported`] as the interface's error.
const UNSUPPORTED: &str = "the closest point of an elliptical horn or spindle torus is not \
                           supported (circular tubes and elliptical ring tori are)";

impl From<FamilyPointError> for PointQueryError {
    fn from(e: FamilyPointError) -> Self {
        match e {
            FamilyPointError::NonFinite(p) => PointQueryError::NonFinite(p),
            FamilyPointError::Unsupported => PointQueryError::Unsupported(UNSUPPORTED),
        }
    }
}

/// [`Toroid::intersect`], `occluded`, `intersect_all`, `intersect_f32` (a circular ring
/// member's hits and misses proved in f32, every other member escalated),
/// [`Toroid::spawn`] and the point queries.
impl Solid for Toroid {
    type Face = NoFace;

    fn world_aabb(&self) -> (Vec3, Vec3) {
        Toroid::world_aabb(self)
    }

    fn hit(&self, ray: &Ray) -> Option<SolidHit<Vec3, NoFace>> {
        self.intersect(ray).map(SolidHit::from)
    }

    fn hit_f64(&self, ray: &DRay) -> Option<SolidHit<DVec3, NoFace>> {
        self.intersect(ray).map(SolidHit::from)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        Toroid::occluded(self, ray)
    }

    fn occluded_f64(&self, ray: &DRay) -> bool {
        Toroid::occluded(self, ray)
    }

    fn crossings(&self, ray: &Ray) -> SolidCrossings<Vec3, NoFace> {
        self.intersect_all(ray).into()
    }

    fn crossings_f64(&self, ray: &DRay) -> SolidCrossings<DVec3, NoFace> {
        self.intersect_all(ray).into()
    }

    fn hit_f32_certified(&self, ray: &Ray) -> SolidF32Hit<NoFace> {
        self.intersect_f32(ray).into()
    }

    fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Result<Ray, RayError> {
        Toroid::spawn(self, ray, t, dir)
    }

    fn spawn_f64(&self, ray: &DRay, t: f64, dir: DVec3) -> Result<DRay, DRayError> {
        Toroid::spawn(self, ray, t, dir)
    }

    fn contains(&self, p: DVec3) -> Result<bool, PointQueryError> {
        Ok(Toroid::contains(self, p)?)
    }

    fn signed_distance(&self, p: DVec3) -> Result<f64, PointQueryError> {
        Ok(Toroid::signed_distance(self, p)?)
    }

    fn project_point(&self, p: DVec3) -> Result<SolidProjection<NoFace>, PointQueryError> {
        Ok(Toroid::project_point(self, p)?.into())
    }
}

/// [`Toroid::intersect`]; the bool is [`Toroid::occluded`].
impl<R: TorusRay> RayCast<R> for Toroid {
    #[inline]
    fn cast_ray_and_get_normal(&self, ray: &R) -> Option<R::Hit> {
        self.intersect(ray)
    }

    #[inline]
    fn intersects_ray(&self, ray: &R) -> bool {
        Toroid::occluded(self, ray)
    }
}

impl Toroid {
    /// This member behind `cull`, for the [`RayCast`] queries ([`Toroid::intersect_culled`]).
    #[inline]
    #[must_use]
    pub fn with_cull<C: Cull>(&self, cull: C) -> Culled<'_, C, Toroid> {
        Culled { shape: self, cull }
    }
}

/// [`Toroid::intersect_culled`]; the bool is [`Toroid::kept_by`] then [`Toroid::occluded`].
impl<C: Cull, R: TorusRay> RayCast<R> for Culled<'_, C, Toroid> {
    #[inline]
    fn cast_ray_and_get_normal(&self, ray: &R) -> Option<R::Hit> {
        self.shape.intersect_culled(&self.cull, ray)
    }

    #[inline]
    fn intersects_ray(&self, ray: &R) -> bool {
        self.shape.kept_by(&self.cull, ray) && self.shape.occluded(ray)
    }
}
