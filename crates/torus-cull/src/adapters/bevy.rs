//! Bevy's torus (bevy_shape 0.20's `Torus`, posed by bevy_math 0.20's `Isometry3d`) as the
//! library's, and a ray cast a Bevy user can call today.
//!
//! The feature `bevy` needs Rust 1.94 (Bevy 0.20's minimum); the library without it needs
//! 1.85. Bevy's torus lies in its own frame with the axis +y and the centre at the origin,
//! as the library's does, so the pose carries over as it is: centre = the isometry's
//! translation, axis = its rotation of +y.
//!
//! **Kinds** (Bevy's `TorusKind`, from the radii alone) map to the family:
//! * `Ring` (R > r) → a ring [`Torus`] ([`torus_from_bevy`]) or its [`Toroid`]
//!   ([`toroid_from_bevy`]);
//! * `Horn` (R = r) and `Spindle` (R < r) → a [`Toroid`] of [`ToroidKind::Horn`] or
//!   [`ToroidKind::Spindle`], whose surface is the outer "apple": any 0 < R < r down to
//!   R/r = [`crate::family::MIN_FAMILY_NU`], 1/100 (a fatter spindle is refused as the
//!   family refuses it, [`crate::family::ToroidError::TooFat`]);
//! * `Invalid` (a radius non-positive, infinite or NaN) → [`BevyTorusError::Invalid`].
//!
//! **The ray cast** ([`BevyTorus::local_ray_cast`]) has the signature of Bevy's proposed
//! `PrimitiveRayCast3d::local_ray_cast(&self, ray: Ray3d, max_distance: f32, solid: bool)
//! -> Option<RayHit3d>`, returning this module's [`RayHit`] (distance, normal: `Dir3`).
//! Its distance is the library's [`Toroid::intersect`] `t` on the ray `[0, max_distance]`,
//! bit for bit; the normal is the library's outward normal, negated where the ray leaves
//! the solid (it faces the ray, as parry's shapes report it). `solid = true` with the
//! origin in the solid (surface included) gives distance 0 and normal `−direction`. A
//! non-finite origin or a NaN or negative `max_distance` hits nothing (`None`, never a NaN).
//! [`BevyTorus::ray_cast`] is Bevy's provided method: the ray moved into the local frame
//! by the isometry's f32 inverse, the local cast, the normal rotated back.
//!
//! **Bounds:** [`world_aabb`] is the library's box (`R·√(1 − aᵢ²) + r` per axis for the unit
//! axis `a`, in f64, rounded outward to f32); Bevy's `Bounded3d::aabb_3d` is the same
//! formula in f32 (iq's disc box), so the two agree to f32 rounding and the library's
//! holds the exact box.

use crate::family::{Toroid, ToroidError, ToroidKind};
use crate::{Ray, Torus, TorusError};
use bevy_math::{Dir3, Isometry3d, Vec3 as BevyVec3};
use bevy_shape::{Ray3d, Torus as BevyTorusShape, TorusKind};
use glam::Vec3;
use std::fmt;

/// Why a Bevy torus was not converted.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum BevyTorusError {
    /// Bevy's `TorusKind::Invalid`: a radius non-positive, infinite or NaN.
    Invalid {
        /// R as given.
        major_radius: f32,
        /// r as given.
        minor_radius: f32,
    },
    /// [`torus_from_bevy`] was given a horn or a spindle, which only the family
    /// ([`toroid_from_bevy`]) holds.
    NotRing(ToroidKind),
    /// The library refused the ring torus (its ν or size range, or a non-finite pose).
    Torus(TorusError),
    /// The family refused the member (a spindle fatter than it supports, the size range,
    /// or a non-finite pose).
    Toroid(ToroidError),
}

impl fmt::Display for BevyTorusError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BevyTorusError::Invalid {
                major_radius,
                minor_radius,
            } => write!(
                f,
                "Bevy torus of kind Invalid (major_radius {major_radius}, minor_radius \
                 {minor_radius}): radii must be finite and > 0"
            ),
            BevyTorusError::NotRing(kind) => write!(
                f,
                "a {kind:?} torus has no hole: convert it with toroid_from_bevy"
            ),
            BevyTorusError::Torus(e) => write!(f, "{e}"),
            BevyTorusError::Toroid(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for BevyTorusError {}

/// A Bevy vector as the library's glam vector (same f32 components).
#[inline]
fn from_bevy(v: BevyVec3) -> Vec3 {
    Vec3::from_array(v.to_array())
}

/// The library's glam vector as a Bevy vector (same f32 components).
#[inline]
fn to_bevy(v: Vec3) -> BevyVec3 {
    BevyVec3::from_array(v.to_array())
}

/// The pose's centre and axis in the library's glam.
fn pose(iso: Isometry3d) -> (Vec3, Vec3) {
    (
        from_bevy(BevyVec3::from(iso.translation)),
        from_bevy(iso.rotation * BevyVec3::Y),
    )
}

/// Refuses `TorusKind::Invalid`; otherwise the kind.
fn kind(torus: &BevyTorusShape) -> Result<TorusKind, BevyTorusError> {
    match torus.kind() {
        TorusKind::Invalid => Err(BevyTorusError::Invalid {
            major_radius: torus.major_radius,
            minor_radius: torus.minor_radius,
        }),
        k => Ok(k),
    }
}

/// Bevy's ring torus at `iso` as the library's [`Torus`].
///
/// # Errors
///
/// [`BevyTorusError::Invalid`] for `TorusKind::Invalid`, [`BevyTorusError::NotRing`] for
/// a horn or spindle, [`BevyTorusError::Torus`] where [`Torus::new`] refuses it.
pub fn torus_from_bevy(torus: &BevyTorusShape, iso: Isometry3d) -> Result<Torus, BevyTorusError> {
    match kind(torus)? {
        TorusKind::Horn => return Err(BevyTorusError::NotRing(ToroidKind::Horn)),
        TorusKind::Spindle => return Err(BevyTorusError::NotRing(ToroidKind::Spindle)),
        _ => {}
    }
    let (center, axis) = pose(iso);
    Torus::new(center, axis, torus.major_radius, torus.minor_radius).map_err(BevyTorusError::Torus)
}

/// Bevy's torus of any valid kind at `iso` as the family's [`Toroid`] (a circular tube:
/// both semi-axes r), its [`Toroid::kind`] Bevy's `TorusKind`.
///
/// # Errors
///
/// [`BevyTorusError::Invalid`] for `TorusKind::Invalid`, [`BevyTorusError::Toroid`] where
/// [`Toroid::new`] refuses it.
pub fn toroid_from_bevy(torus: &BevyTorusShape, iso: Isometry3d) -> Result<Toroid, BevyTorusError> {
    kind(torus)?;
    let (center, axis) = pose(iso);
    let r = torus.minor_radius;
    Toroid::new(center, axis, torus.major_radius, r, r).map_err(BevyTorusError::Toroid)
}

/// The library's world bounding box of Bevy's torus at `iso` (module docs), as Bevy
/// vectors `(min, max)`.
///
/// # Errors
///
/// As [`toroid_from_bevy`].
pub fn world_aabb(
    torus: &BevyTorusShape,
    iso: Isometry3d,
) -> Result<(BevyVec3, BevyVec3), BevyTorusError> {
    // A circular member's image is the member itself (R, r): its exact box.
    let (lo, hi) = toroid_from_bevy(torus, iso)?.image().world_aabb();
    Ok((to_bevy(lo), to_bevy(hi)))
}

/// A ray hit in Bevy's terms: the distance along the ray's unit direction and the unit
/// normal (module docs: it faces the ray).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RayHit {
    /// Distance from the ray's origin, along its unit direction.
    pub distance: f32,
    /// Unit normal at the hit, facing the ray's origin side.
    pub normal: Dir3,
}

/// Bevy's torus in its own frame, converted once, with Bevy's proposed ray cast.
///
/// ```
/// use bevy_math::{Dir3, Isometry3d, Vec3};
/// use bevy_shape::{Ray3d, Torus};
/// use torus_cull::adapters::bevy::BevyTorus;
/// let torus = BevyTorus::try_from(Torus::new(1.0, 4.0))?; // inner 1 (r = 1.5), outer 4
/// let ray = Ray3d::new(Vec3::new(0.0, 10.0, 2.5), Dir3::NEG_Y);
/// let hit = torus.local_ray_cast(ray, 100.0, false).expect("the top of the tube");
/// assert_eq!((hit.distance, hit.normal), (8.5, Dir3::Y));
/// let moved = Isometry3d::from_translation(Vec3::new(0.0, 0.0, 10.0));
/// assert!(torus.ray_cast(moved, ray, 100.0, false).is_none());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BevyTorus {
    toroid: Toroid,
}

impl TryFrom<BevyTorusShape> for BevyTorus {
    type Error = BevyTorusError;

    /// [`toroid_from_bevy`] at the identity.
    fn try_from(torus: BevyTorusShape) -> Result<BevyTorus, BevyTorusError> {
        Ok(BevyTorus {
            toroid: toroid_from_bevy(&torus, Isometry3d::IDENTITY)?,
        })
    }
}

impl BevyTorus {
    /// The family member in the local frame (centre at the origin, axis +y).
    #[must_use]
    pub const fn toroid(&self) -> &Toroid {
        &self.toroid
    }

    /// The nearest hit within `max_distance` of the ray in the torus's own frame (module
    /// docs: the library's `t` and normal, `solid`'s meaning).
    #[must_use]
    pub fn local_ray_cast(&self, ray: Ray3d, max_distance: f32, solid: bool) -> Option<RayHit> {
        // The member is a Solid: its hit is `Toroid::intersect`, its inside test
        // `Toroid::contains`, so the generic cast is this one.
        solid_ray_cast(&self.toroid, ray, max_distance, solid)
    }

    /// [`BevyTorus::local_ray_cast`] of the torus posed by `iso`: the ray moved into its
    /// frame by the isometry's inverse (f32), the hit's normal rotated back.
    #[must_use]
    pub fn ray_cast(
        &self,
        iso: impl Into<Isometry3d>,
        ray: Ray3d,
        max_distance: f32,
        solid: bool,
    ) -> Option<RayHit> {
        let iso = iso.into();
        let local = Ray3d {
            origin: iso.inverse_transform_point(ray.origin).into(),
            direction: iso.rotation.inverse() * ray.direction,
        };
        let hit = self.local_ray_cast(local, max_distance, solid)?;
        Some(RayHit {
            distance: hit.distance,
            normal: iso.rotation * hit.normal,
        })
    }

    /// Whether [`BevyTorus::ray_cast`] hits (solid).
    #[must_use]
    pub fn intersects_ray(
        &self,
        iso: impl Into<Isometry3d>,
        ray: Ray3d,
        max_distance: f32,
    ) -> bool {
        self.ray_cast(iso, ray, max_distance, true).is_some()
    }
}

/// Bevy's proposed `local_ray_cast` for any of the library's solids ([`crate::Solid`]: a
/// [`Torus`], a [`Toroid`], a [`crate::bend::PipeBend`]), in the solid's frame: the
/// library's nearest hit `t` within `max_distance` and its normal facing the ray;
/// `solid = true` from inside (the surface included) gives distance 0 and the reversed
/// direction as the normal, as [`BevyTorus::local_ray_cast`]. A ray or range the library
/// refuses hits nothing.
///
/// ```
/// use bevy_math::{Dir3, Vec3};
/// use bevy_shape::Ray3d;
/// use torus_cull::adapters::bevy::solid_ray_cast;
/// use torus_cull::bend::PipeBend;
/// // A bend with a bore of 0.5 in a tube of 1, over φ ∈ [−0.5, 0.5]: down through its top.
/// let bend = PipeBend::canonical(4.0, 0.5, 1.0, -0.5, 1.0)?;
/// let ray = Ray3d::new(Vec3::new(4.0, 10.0, 0.0), Dir3::NEG_Y);
/// let hit = solid_ray_cast(&bend, ray, 100.0, false).expect("the top of the tube");
/// assert_eq!((hit.distance, hit.normal), (9.0, Dir3::Y));
/// // From the bore, solid or not: the bore is outside the solid, so its wall is hit.
/// let up = Ray3d::new(Vec3::new(4.0, 0.0, 0.0), Dir3::Y);
/// assert_eq!(solid_ray_cast(&bend, up, 100.0, true).unwrap().distance, 0.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn solid_ray_cast<S: crate::Solid + ?Sized>(
    shape: &S,
    ray: Ray3d,
    max_distance: f32,
    solid: bool,
) -> Option<RayHit> {
    let (origin, dir) = (from_bevy(ray.origin), from_bevy(*ray.direction));
    let lib = Ray::with_range(origin, dir, 0.0, max_distance).ok()?;
    if solid && shape.contains(origin.as_dvec3()).ok()? {
        return Some(RayHit {
            distance: 0.0,
            normal: -ray.direction,
        });
    }
    let hit = shape.hit(&lib)?;
    let normal = if hit.front_face {
        hit.normal
    } else {
        -hit.normal
    };
    Some(RayHit {
        distance: hit.t,
        normal: Dir3::new_unchecked(to_bevy(normal)),
    })
}
