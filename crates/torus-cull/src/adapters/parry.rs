//! The torus as a parry3d (0.31, f32, 3-D) shape: [`ParryTorus`] implements parry's
//! `Shape`, `RayCast` and `PointQuery` with `ShapeType::Custom`, so it sits in a
//! `Compound`, a BVH or a rapier collider beside parry's own shapes, and every ray cast
//! and point query parry asks of it is answered by the library's exact ones.
//!
//! **Local queries are the library's, bit for bit.** A local ray is the library's [`Ray`]
//! over `[0, max_time_of_impact]` and its time of impact is [`intersect()`]'s `t`; a
//! local point's projection, inside test and distance are [`Torus::project_point`]'s,
//! [`Torus::contains`]'s and [`Torus::signed_distance`]'s, rounded once to f32.
//! **World queries** are parry's own: the ray or point is moved into the local frame by
//! parry's f32 pose (`inverse_transform_by`), then answered locally, so they differ from
//! the library's posed [`Torus`] by that transform's rounding only. The world AABB
//! ([`Shape::compute_aabb`]) is the library's exact box of the posed torus
//! ([`Torus::world_aabb`], rounded outward), not the local box rotated.
//!
//! **Semantics at the edges:**
//! * `solid = true` with the origin in the solid (the surface included, [`Torus::contains`])
//!   returns time of impact 0 with a zero normal, as parry's support-map shapes do;
//!   `solid = false` returns where the ray leaves the tube.
//! * The normal faces the ray, as parry's `Ball` reports it: the library's outward normal,
//!   negated where the library's hit has `front_face` false (the ray leaves the solid).
//! * A ray the library refuses (non-finite origin or direction, a zero direction or one
//!   whose `|d|²` overflows f32, a negative or NaN `max_time_of_impact`) hits nothing.
//! * A non-finite point is never inside: its projection is the point itself, its distance
//!   `+∞` (no NaN is invented).
//! * `mass_properties`: exact, for a uniform density ρ: mass `m = ρ·2π²Rr²`, centre of mass
//!   at the centre, inertia `m(R² + 3r²/4)` about the axis (y) and `m(R²/2 + 5r²/8)` about a
//!   diameter (x and z), computed in f64 and rounded to f32.
//! * `scale_dyn`: a uniform scale `s` gives the torus with radii `|s|R` and `|s|r` (a torus
//!   centred at the origin is symmetric under `x ↦ −x`); a non-uniform scale returns `None`,
//!   since a non-uniformly scaled torus is not a torus (nor is a scale the library's range
//!   refuses, or zero).
//! * **Contacts are not supported.** The torus is not convex and has no support map, so
//!   parry's `DefaultQueryDispatcher` answers contact, distance, intersection and
//!   shape-cast queries between it and another shape with `Unsupported`; a custom
//!   `QueryDispatcher` would be needed for those and is not provided.
//!
//! The family's [`crate::family::Toroid`] and the [`crate::bend::PipeBend`] are adapted
//! over the [`crate::Solid`] interface by [`ParrySolid`] ([`ParryToroid`], [`ParryBend`]),
//! with the same local queries and edges; their mass properties where a closed form exists.

use crate::{Ray, Torus, TorusError, intersect};
use glam::{DVec3, Quat, Vec3};
use parry3d::bounding_volume::{Aabb, BoundingSphere};
use parry3d::mass_properties::MassProperties;
use parry3d::math::{Pose, Real, Vector};
use parry3d::query::{PointProjection, PointQuery, Ray as ParryRay, RayCast, RayIntersection};
use parry3d::shape::{FeatureId, Shape, ShapeType, SubShapeId, TypedShape};
use std::f64::consts::PI;

mod solid;
pub use solid::{ParryAdapted, ParryBend, ParrySolid, ParryToroid};

/// A ring torus in its own frame (centre at the origin, axis +y), as a parry3d shape:
/// place it with a parry `Pose` (the pose's rotation takes +y to the torus axis). See the
/// module docs for what each parry query returns.
///
/// ```
/// use parry3d::math::{Pose, Vector};
/// use parry3d::query::{PointQuery, Ray, RayCast};
/// use torus_cull::adapters::parry::ParryTorus;
/// let torus = ParryTorus::new(4.0, 1.0)?;
/// let down = Ray::new(Vector::new(4.0, 10.0, 0.0), Vector::new(0.0, -1.0, 0.0));
/// assert_eq!(torus.cast_ray(&Pose::identity(), &down, 100.0, true), Some(9.0));
/// assert!(torus.contains_point(&Pose::translation(0.0, 5.0, 0.0), Vector::new(4.0, 5.0, 0.0)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParryTorus {
    torus: Torus,
}

impl ParryTorus {
    /// The torus with R = `major_radius` and r = `minor_radius`, validated as
    /// [`Torus::canonical`] validates them.
    ///
    /// # Errors
    ///
    /// [`TorusError`], as [`Torus::canonical`].
    pub fn new(major_radius: f32, minor_radius: f32) -> Result<ParryTorus, TorusError> {
        Ok(ParryTorus {
            torus: Torus::canonical(major_radius, minor_radius)?,
        })
    }

    /// The library's torus in the shape's local frame (centre at the origin, axis +y).
    #[must_use]
    pub const fn torus(&self) -> &Torus {
        &self.torus
    }

    /// The library's torus at a parry pose: centre at the pose's translation, axis the
    /// pose's rotation of +y.
    ///
    /// # Errors
    ///
    /// [`TorusError`] for a non-finite pose.
    pub fn posed(&self, pose: &Pose) -> Result<Torus, TorusError> {
        Torus::new(
            from_parry(pose.translation),
            Quat::from_array(pose.rotation.to_array()) * Vec3::Y,
            self.torus.major_radius(),
            self.torus.minor_radius(),
        )
    }
}

/// A parry vector as the library's glam vector (same f32 components).
#[inline]
pub(super) fn from_parry(v: Vector) -> Vec3 {
    Vec3::from_array(v.to_array())
}

/// The library's glam vector as a parry vector (same f32 components).
#[inline]
pub(super) fn to_parry(v: Vec3) -> Vector {
    Vector::from_array(v.to_array())
}

impl RayCast for ParryTorus {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &ParryRay,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        let (origin, dir) = (from_parry(ray.origin), from_parry(ray.dir));
        let ray = Ray::with_range(origin, dir, 0.0, max_time_of_impact).ok()?;
        if solid && self.torus.contains(origin.as_dvec3()).ok()? {
            return Some(RayIntersection::new(0.0, Vector::ZERO, FeatureId::Face(0)));
        }
        let hit = intersect(&self.torus, &ray)?;
        let normal = if hit.front_face {
            hit.normal
        } else {
            -hit.normal
        };
        Some(RayIntersection::new(
            hit.t,
            to_parry(normal),
            FeatureId::Face(0),
        ))
    }
}

impl PointQuery for ParryTorus {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        match self.torus.project_point(from_parry(pt).as_dvec3()) {
            Ok(p) => {
                let inside = p.signed_distance <= 0.0;
                if solid && inside {
                    PointProjection::new(true, pt)
                } else {
                    PointProjection::new(inside, to_parry(p.point.as_vec3()))
                }
            }
            Err(_) => PointProjection::new(false, pt),
        }
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        (self.project_local_point(pt, false), FeatureId::Face(0))
    }

    /// The library's signed distance rounded to f32: `D − r`, negative inside unless
    /// `solid` (then 0 inside), `+∞` for a non-finite point.
    fn distance_to_local_point(&self, pt: Vector, solid: bool) -> Real {
        match self.torus.signed_distance(from_parry(pt).as_dvec3()) {
            Ok(d) if solid => d.max(0.0) as f32,
            Ok(d) => d as f32,
            Err(_) => Real::INFINITY,
        }
    }

    fn contains_local_point(&self, pt: Vector) -> bool {
        self.torus
            .contains(from_parry(pt).as_dvec3())
            .unwrap_or(false)
    }
}

impl Shape for ParryTorus {
    /// `[−(R + r), −r, −(R + r)] … [R + r, r, R + r]`, rounded outward.
    fn compute_local_aabb(&self) -> Aabb {
        let (lo, hi) = self.torus.world_aabb();
        Aabb::new(to_parry(lo), to_parry(hi))
    }

    /// Centre 0, radius R + r rounded up.
    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        let (_, radius) = self.torus.bounding_sphere();
        BoundingSphere::new(Vector::ZERO, crate::num::round::up(radius))
    }

    /// The library's exact box of the posed torus ([`Torus::world_aabb`]: each half-width
    /// `R·√(1 − aᵢ²) + r` for the unit axis `a`, rounded outward); a non-finite pose
    /// falls back to parry's rotated local box.
    fn compute_aabb(&self, position: &Pose) -> Aabb {
        match self.posed(position) {
            Ok(t) => {
                let (lo, hi) = t.world_aabb();
                Aabb::new(to_parry(lo), to_parry(hi))
            }
            Err(_) => self.compute_local_aabb().transform_by(position),
        }
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(*self)
    }

    /// Uniform scale only (module docs): `None` for a non-uniform one.
    fn scale_dyn(&self, scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        if scale.x != scale.y || scale.y != scale.z {
            return None;
        }
        let s = scale.x.abs();
        let (big, small) = (self.torus.major_radius(), self.torus.minor_radius());
        Some(Box::new(ParryTorus::new(big * s, small * s).ok()?))
    }

    /// Exact torus mass properties (module docs).
    fn mass_properties(&self, density: Real) -> MassProperties {
        let (big, small) = (self.torus.major_radius_f64(), self.torus.minor_radius_f64());
        let mass = f64::from(density) * 2.0 * PI * PI * big * small * small;
        let axial = mass * (big * big + 0.75 * small * small);
        let diameter = mass * (0.5 * big * big + 0.625 * small * small);
        MassProperties::new(
            Vector::ZERO,
            mass as f32,
            to_parry(DVec3::new(diameter, axial, diameter).as_vec3()),
        )
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    /// The tube's radius r: the thinnest the torus is.
    fn ccd_thickness(&self) -> Real {
        self.torus.minor_radius()
    }

    /// π/2, as parry's round shapes report it.
    fn ccd_angular_thickness(&self) -> Real {
        std::f32::consts::FRAC_PI_2
    }

    /// The library's outward normal at the closest surface point to `point` (local frame).
    fn feature_normal_at_point(
        &self,
        _subshape: SubShapeId,
        _feature: FeatureId,
        point: Vector,
    ) -> Option<Vector> {
        let p = self
            .torus
            .project_point(from_parry(point).as_dvec3())
            .ok()?;
        Some(to_parry(p.normal.as_vec3()))
    }
}
