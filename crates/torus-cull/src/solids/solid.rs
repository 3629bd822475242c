//! One interface for the library's solids, in the manner of pbrt-v4's `Shape` (the same
//! verbs with the same signatures for every shape) and parry's `Shape: RayCast +
//! PointQuery` (a new shape is one impl, and the compiler names what it lacks).

use crate::Cull;
use crate::geometry::{
    DRay, DRayError, PointQueryError, Precision, Ray, RayError, SolidCrossings, SolidF32Hit,
    SolidHit, SolidProjection,
};
use glam::{DVec3, Vec3};
use std::fmt;

/// A solid a renderer traces and queries: the ring [`crate::Torus`], the family's
/// [`crate::family::Toroid`] and the [`crate::bend::PipeBend`] implement it, each by
/// delegating to its own methods (which stay, and answer bit for bit the same).
///
/// Every ray verb honours the ray's `[t_min, t_max]` and a ray marked as starting on the
/// surface ([`Ray::from_surface`], a `spawn`); an f32 [`Ray`] gets f32 answers, an f64
/// [`DRay`] f64 ones. Every point verb takes an f64 world point and refuses a NaN or
/// infinite one ([`PointQueryError::NonFinite`]), never answering with a NaN.
///
/// The verbs, per shape:
///
/// * [`Solid::world_aabb`]: the exact world box, rounded outward.
/// * [`Solid::hit`] / [`Solid::hit_f64`]: the nearest crossing in range, with its unit
///   outward normal, point, `front_face` and [`Solid::Face`]: the torus's
///   `intersect`, the toroid's and the bend's `intersect` (the bend's face named, the
///   others' [`crate::NoFace`]).
/// * [`Solid::occluded`] / [`Solid::occluded_f64`]: a shadow ray's bool, for less than a
///   hit (`occluded` of each).
/// * [`Solid::crossings`] / [`Solid::crossings_f64`]: every crossing in range, ascending,
///   with its passage, and the spans inside the solid (`intersect_all` of each; a torus
///   crosses a line at most 4 times, a bend at most 10).
/// * [`Solid::hit_f32_certified`]: the nearest hit of an f32 ray on the certified f32 path,
///   escalated to the f64 answer where f32 cannot prove one. What each proves in f32: a
///   ring torus (and a `Toroid` or whole `PipeBend` that is one) its hits and misses
///   (`intersect_f32`); any other `Toroid` nothing (every ray escalated); a cut
///   `PipeBend` its misses of the outer torus from outside the outer tube, the rest
///   escalated (`PipeBend::intersect_f32`). The hit always equals [`Solid::hit`]'s but
///   for the certified path's f32 rounding where it proved one.
/// * [`Solid::kept_by`]: a cull's verdict on the ray's line, `false` only where the line
///   provably misses the solid: the torus's [`crate::Torus::with_cull`] step, the
///   toroid's [`crate::family::Toroid::kept_by`] (the cull on the circular image, declined
///   and keeping every ray where the cull does not accept the member's shape), the bend's
///   [`crate::bend::PipeBend::kept_by`] (the cull on the outer torus; a
///   [`crate::bend::WedgeCull`] adds the segment's wedge).
/// * [`Solid::spawn`] / [`Solid::spawn_f64`]: the secondary ray leaving the hit at `t`
///   on `ray`, its origin moved onto the surface (the face, for a bend) and marked as
///   starting there, so the next [`Solid::hit`] skips the origin's own root.
/// * [`Solid::contains`], [`Solid::signed_distance`], [`Solid::project_point`]: inside
///   (surface included), the signed distance (negative inside) and the closest surface
///   point with its outward normal and face. A `Toroid` refuses the closest point and
///   distance of an elliptical horn or spindle ([`PointQueryError::Unsupported`]).
///
/// The trait is object safe: a scene of one face type holds `Box<dyn Solid<Face = F>>`;
/// of any shape, `Box<dyn crate::RayCast>`, which all three implement too. Its one generic
/// verb, [`Solid::kept_by`], is for a concrete shape (`where Self: Sized`), so that a
/// loop over rays stays monomorphic in the cull.
///
/// ```
/// use glam::{DVec3, Vec3};
/// use torus_cull::bend::PipeBend;
/// use torus_cull::family::Toroid;
/// use torus_cull::{Passage, Ray, Solid, Torus};
///
/// // Written against the interface alone: the first entry and the count of spans.
/// fn first_entry<S: Solid>(shape: &S, ray: &Ray) -> Option<(f32, usize)> {
///     let all = shape.crossings(ray);
///     let entry = all.iter().find(|c| c.passage == Passage::Enter)?;
///     Some((entry.t, all.spans().len()))
/// }
/// let down = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?;
/// let torus = Torus::canonical(4.0, 1.0)?;
/// let toroid = Toroid::canonical(4.0, 1.0, 0.5)?;
/// let bend = PipeBend::canonical(4.0, 0.0, 1.0, -0.5, 1.0)?;
/// assert_eq!(first_entry(&torus, &down), Some((9.0, 1)));
/// assert_eq!(first_entry(&toroid, &down), Some((9.5, 1)));
/// assert_eq!(first_entry(&bend, &down), Some((9.0, 1)));
/// // A shape's own method of the same name wins in method syntax (`bend.contains` is
/// // the bend's bool); name the trait's where the concrete type is known.
/// assert!(Solid::contains(&bend, DVec3::new(4.0, 0.0, 0.0))?);
/// assert!(Solid::contains(&bend, DVec3::NAN).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait Solid {
    /// The face type of the solid's hits, crossings and projections: [`crate::NoFace`]
    /// for a one-face solid, `BendFace` for a pipe bend.
    type Face: Copy + Default + PartialEq + fmt::Debug;

    /// The world-space box `(lo, hi)` holding the solid, rounded outward.
    #[must_use]
    fn world_aabb(&self) -> (Vec3, Vec3);

    /// The nearest hit of an f32 ray in `[t_min, t_max]`.
    #[must_use]
    fn hit(&self, ray: &Ray) -> Option<SolidHit<Vec3, Self::Face>>;

    /// The nearest hit of an f64 ray in `[t_min, t_max]`.
    #[must_use]
    fn hit_f64(&self, ray: &DRay) -> Option<SolidHit<DVec3, Self::Face>>;

    /// Whether an f32 ray meets the solid's surface in `[t_min, t_max]`.
    #[must_use]
    fn occluded(&self, ray: &Ray) -> bool;

    /// Whether an f64 ray meets the solid's surface in `[t_min, t_max]`.
    #[must_use]
    fn occluded_f64(&self, ray: &DRay) -> bool;

    /// Every crossing of an f32 ray in `[t_min, t_max]`, ascending.
    fn crossings(&self, ray: &Ray) -> SolidCrossings<Vec3, Self::Face>;

    /// Every crossing of an f64 ray in `[t_min, t_max]`, ascending.
    fn crossings_f64(&self, ray: &DRay) -> SolidCrossings<DVec3, Self::Face>;

    /// The nearest hit on the certified f32 path, escalated to f64 where f32 proves
    /// nothing (trait docs: what each shape proves).
    #[must_use]
    fn hit_f32_certified(&self, ray: &Ray) -> SolidF32Hit<Self::Face>;

    /// Whether `cull` keeps the ray: `false` only if the ray's line provably misses the
    /// solid, so a renderer skips the exact intersection for it; `true` otherwise,
    /// including every ray of a shape the cull is not proved for (the cull is declined).
    ///
    /// **Why one verb generic over the cull and the precision.** A cull is a test on the
    /// line in the frame of a torus that bounds the solid (the torus itself, a toroid's
    /// circular image, a bend's outer torus), taken in f32 whatever the ray's precision
    /// ([`Cull::keeps`]): so one method answers an f32 [`Ray`] and an f64 [`DRay`] alike
    /// (`Ray<P>`), where the exact verbs come in twins. It is generic in `C`, not
    /// `&dyn Cull`, so that a loop over rays calls the cull's kernel directly (a shared
    /// indirect call cost 7–10 % on the family's ring members); `C: ?Sized` still takes
    /// a `&dyn Cull` where the cull is chosen at run time. `where Self: Sized` keeps the
    /// trait object safe.
    ///
    /// **Conservative:** the solid must lie inside the bounding torus the cull is applied
    /// to (with the culls' margin, [`crate::CullBounds`]); a new shape without such a
    /// torus keeps every ray.
    #[must_use]
    fn kept_by<C: Cull + ?Sized, P: Precision>(&self, cull: &C, ray: &Ray<P>) -> bool
    where
        Self: Sized;

    /// The secondary f32 ray leaving the hit at `t` on `ray` in direction `dir`.
    ///
    /// # Errors
    ///
    /// A [`RayError`] (a non-finite or zero `dir`, a non-finite point at `t`), never a
    /// panic or a NaN ray.
    fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Result<Ray, RayError>;

    /// The secondary f64 ray leaving the hit at `t` on `ray` in direction `dir`.
    ///
    /// # Errors
    ///
    /// A [`DRayError`], as [`Solid::spawn`]'s.
    fn spawn_f64(&self, ray: &DRay, t: f64, dir: DVec3) -> Result<DRay, DRayError>;

    /// Whether `p` lies in the closed solid.
    ///
    /// # Errors
    ///
    /// [`PointQueryError::NonFinite`] for a NaN or infinite coordinate.
    fn contains(&self, p: DVec3) -> Result<bool, PointQueryError>;

    /// The signed distance from `p` to the surface: negative inside.
    ///
    /// # Errors
    ///
    /// [`PointQueryError`]: a non-finite point, or a shape without a supported answer.
    fn signed_distance(&self, p: DVec3) -> Result<f64, PointQueryError>;

    /// The closest surface point to `p`, its outward normal and face, and `p`'s signed
    /// distance.
    ///
    /// # Errors
    ///
    /// [`PointQueryError`], as [`Solid::signed_distance`]'s.
    fn project_point(&self, p: DVec3) -> Result<SolidProjection<Self::Face>, PointQueryError>;
}
