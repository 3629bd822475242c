//! [`Solid`] and [`RayCast`] for the family's [`Toroid`]: its methods, its hits on
//! [`NoFace`].

use crate::family::{FamilyPointError, Toroid};
use crate::geometry::{
    NoFace, PointQueryError, SolidCrossings, SolidF32Hit, SolidHit, SolidProjection,
};
use crate::{Cull, Culled, DRay, DRayError, Precision, Ray, RayCast, RayError, Solid, TorusRay};
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
/// [`Toroid::spawn`], [`Toroid::kept_by`] and the point queries.
impl Solid for Toroid {
    type Face = NoFace;

    fn world_aabb(&self) -> (Vec3, Vec3) {
        Toroid::world_aabb(self)
    }

    ray_verbs!(
        Toroid::intersect,
        Toroid::occluded,
        Toroid::intersect_all,
        Toroid::spawn,
        Toroid::intersect_f32,
        Toroid::kept_by
    );

    point_verbs!(Toroid);
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
