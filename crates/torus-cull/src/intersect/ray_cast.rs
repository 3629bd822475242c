//! The ray queries as one trait, in the manner of parry's `RayCast`: one required method
//! (the nearest hit with its normal), the time-only and the yes/no queries provided.
//! [`crate::Torus`] casts exactly; [`Culled`], a torus with a cull in front, casts through
//! the cull. Both answer in the ray's own precision ([`TorusRay`]).

use super::{TorusRay, intersect, occluded};
use crate::{Cull, Torus, intersect_culled};

/// Something a ray can be cast at: the three queries a renderer asks.
///
/// Only [`RayCast::cast_ray_and_get_normal`] is required; [`RayCast::cast_ray`] (the
/// hit's `t`) and [`RayCast::intersects_ray`] (a shadow ray's bool) follow from it, and an
/// implementation overrides them where it can answer for less ([`crate::Torus`] skips
/// the normal for the bool, with [`crate::occluded()`]). Every query honours the ray's
/// `[t_min, t_max]`, and an [`crate::Ray`] gets f32 answers, a [`crate::DRay`] f64 ones.
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, RayCast, SkalaCull, Torus};
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// let down = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?;
/// let hit = torus.cast_ray_and_get_normal(&down).expect("the top of the tube");
/// assert!((hit.t - 9.0).abs() < 1e-4 && (hit.normal - Vec3::Y).length() < 1e-4);
/// assert_eq!(torus.cast_ray(&down), Some(hit.t));
/// assert!(!torus.intersects_ray(&down.with_t_max(8.5)));
/// // The same queries with a cull in front: the same answers, and a proven miss costs no
/// // quartic.
/// let culled = torus.with_cull(SkalaCull);
/// assert_eq!(culled.cast_ray_and_get_normal(&down), Some(hit));
/// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::NEG_Y)?;
/// assert!(!culled.intersects_ray(&hole));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait RayCast {
    /// The nearest hit with `t ∈ [t_min, t_max]`, with the unit outward normal in world
    /// space; `None` for a miss.
    #[must_use]
    fn cast_ray_and_get_normal<R: TorusRay>(&self, ray: &R) -> Option<R::Hit>;

    /// The nearest hit's `t` only.
    #[must_use]
    #[inline]
    fn cast_ray<R: TorusRay>(&self, ray: &R) -> Option<R::Float> {
        self.cast_ray_and_get_normal(ray).map(|hit| R::hit_t(&hit))
    }

    /// Whether the ray meets the surface at some `t ∈ [t_min, t_max]`.
    #[must_use]
    #[inline]
    fn intersects_ray<R: TorusRay>(&self, ray: &R) -> bool {
        self.cast_ray_and_get_normal(ray).is_some()
    }
}

/// The exact intersection, [`crate::intersect()`]; the bool is [`crate::occluded()`].
impl RayCast for Torus {
    #[inline]
    fn cast_ray_and_get_normal<R: TorusRay>(&self, ray: &R) -> Option<R::Hit> {
        intersect(self, ray)
    }

    #[inline]
    fn intersects_ray<R: TorusRay>(&self, ray: &R) -> bool {
        occluded(self, ray)
    }
}

/// A torus with a cull in front of its exact intersection ([`Torus::with_cull`]): a
/// [`RayCast`] whose cast is [`crate::intersect_culled`]. The cull never changes an
/// answer; it only saves the quartic on the lines it proves to miss.
#[derive(Debug, Clone, Copy)]
pub struct Culled<'a, C> {
    torus: &'a Torus,
    cull: C,
}

impl Torus {
    /// This torus behind `cull`, for the [`RayCast`] queries (a cull is a unit struct or a
    /// [`crate::CullKind`]: cheap to copy in).
    #[inline]
    #[must_use]
    pub fn with_cull<C: Cull>(&self, cull: C) -> Culled<'_, C> {
        Culled { torus: self, cull }
    }
}

impl<C: Cull> RayCast for Culled<'_, C> {
    #[inline]
    fn cast_ray_and_get_normal<R: TorusRay>(&self, ray: &R) -> Option<R::Hit> {
        intersect_culled(&self.cull, self.torus, ray)
    }

    #[inline]
    fn intersects_ray<R: TorusRay>(&self, ray: &R) -> bool {
        crate::kept_by(&self.cull, self.torus, ray) && occluded(self.torus, ray)
    }
}
