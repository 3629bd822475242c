//! The ray queries as one trait, in the manner of parry's `RayCast`: one required method
//! (the nearest hit with its normal), the time-only and the yes/no queries provided.
//! [`crate::Torus`] casts exactly (as do `Toroid` and `PipeBend`, through their own
//! impls in the `solids` module); [`Culled`], a shape with a cull in front, casts through
//! the cull. Both answer in the ray's own precision ([`TorusRay`]). The ray type is the
//! trait's parameter, not its methods', so the trait is object safe: a mixed scene holds
//! `Box<dyn RayCast>` (f32 rays) or `Box<dyn RayCast<DRay>>` (f64 rays).

use super::{TorusRay, intersect, occluded};
use crate::{Cull, Ray, Torus, intersect_culled};

/// Something a ray of type `R` can be cast at: the three queries a renderer asks.
///
/// Only [`RayCast::cast_ray_and_get_normal`] is required; [`RayCast::cast_ray`] (the
/// hit's `t`) and [`RayCast::intersects_ray`] (a shadow ray's bool) follow from it, and an
/// implementation overrides them where it can answer for less ([`crate::Torus`] skips
/// the normal for the bool, with [`crate::occluded()`]). Every query honours the ray's
/// `[t_min, t_max]`, and an [`crate::Ray`] (`R`'s default) gets f32 answers, a
/// [`crate::DRay`] f64 ones: [`crate::Torus`] and [`Culled`] implement both.
///
/// The trait is object safe (no generic method), so a scene of mixed primitives keeps
/// them as trait objects, your own shapes beside the tori:
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{CullKind, Hit, Ray, RayCast, Torus};
/// let big = Torus::canonical(4.0, 1.0)?;
/// let small = Torus::new(Vec3::new(0.0, 5.0, 0.0), Vec3::Y, 1.0, 0.25)?;
/// let scene: Vec<Box<dyn RayCast + '_>> = vec![
///     Box::new(big),
///     Box::new(small.with_cull(CullKind::Skala)),
/// ];
/// // The nearest hit over the scene: each object cut at the best t so far.
/// let down = Ray::new(Vec3::new(1.0, 10.0, 0.0), Vec3::NEG_Y)?;
/// let nearest = scene.iter().fold(None::<Hit>, |best, object| {
///     let ray = best.map_or(Ok(down), |b| down.with_t_max(b.t)).expect("t is not NaN");
///     object.cast_ray_and_get_normal(&ray).or(best)
/// });
/// assert!((nearest.expect("the small torus's top").t - 4.75).abs() < 1e-4);
/// assert!(!scene[1].intersects_ray(&down.with_t_max(4.5)?));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, RayCast, SkalaCull, Torus};
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// let down = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?;
/// let hit = torus.cast_ray_and_get_normal(&down).expect("the top of the tube");
/// assert!((hit.t - 9.0).abs() < 1e-4 && (hit.normal - Vec3::Y).length() < 1e-4);
/// assert_eq!(torus.cast_ray(&down), Some(hit.t));
/// assert!(!torus.intersects_ray(&down.with_t_max(8.5)?));
/// // The same queries with a cull in front: the same answers, and a proven miss costs no
/// // quartic.
/// let culled = torus.with_cull(SkalaCull);
/// assert_eq!(culled.cast_ray_and_get_normal(&down), Some(hit));
/// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::NEG_Y)?;
/// assert!(!culled.intersects_ray(&hole));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait RayCast<R: TorusRay = Ray> {
    /// The nearest hit with `t ∈ [t_min, t_max]`, with the unit outward normal in world
    /// space; `None` for a miss.
    #[must_use]
    fn cast_ray_and_get_normal(&self, ray: &R) -> Option<R::Hit>;

    /// The nearest hit's `t` only.
    #[must_use]
    #[inline]
    fn cast_ray(&self, ray: &R) -> Option<R::Float> {
        self.cast_ray_and_get_normal(ray).map(|hit| R::hit_t(&hit))
    }

    /// Whether the ray meets the surface at some `t ∈ [t_min, t_max]`.
    #[must_use]
    #[inline]
    fn intersects_ray(&self, ray: &R) -> bool {
        self.cast_ray_and_get_normal(ray).is_some()
    }
}

/// The exact intersection, [`crate::intersect()`]; the bool is [`crate::occluded()`].
impl<R: TorusRay> RayCast<R> for Torus {
    #[inline]
    fn cast_ray_and_get_normal(&self, ray: &R) -> Option<R::Hit> {
        intersect(self, ray)
    }

    #[inline]
    fn intersects_ray(&self, ray: &R) -> bool {
        occluded(self, ray)
    }
}

/// A solid with a cull in front of its exact intersection ([`Torus::with_cull`],
/// `Toroid::with_cull`, `PipeBend::with_cull`): a [`RayCast`] whose cast is the shape's
/// culled intersection ([`crate::intersect_culled`] for a torus). The cull never changes
/// an answer; it only saves the exact path on the lines it proves to miss.
#[derive(Debug, Clone, Copy)]
pub struct Culled<'a, C, S: ?Sized = Torus> {
    pub(crate) shape: &'a S,
    pub(crate) cull: C,
}

impl Torus {
    /// This torus behind `cull`, for the [`RayCast`] queries (a cull is a unit struct or a
    /// [`crate::CullKind`]: cheap to copy in).
    #[inline]
    #[must_use]
    pub fn with_cull<C: Cull>(&self, cull: C) -> Culled<'_, C> {
        Culled { shape: self, cull }
    }
}

impl<C: Cull, R: TorusRay> RayCast<R> for Culled<'_, C> {
    #[inline]
    fn cast_ray_and_get_normal(&self, ray: &R) -> Option<R::Hit> {
        intersect_culled(&self.cull, self.shape, ray)
    }

    #[inline]
    fn intersects_ray(&self, ray: &R) -> bool {
        crate::intersect::kept_by(&self.cull, self.shape, ray) && occluded(self.shape, ray)
    }
}
