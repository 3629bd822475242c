//! Any of the library's solids as a parry3d shape, over the [`Solid`] interface:
//! [`ParrySolid`] (with [`ParryToroid`] and [`ParryBend`] naming the family member and
//! the pipe bend) implements parry's `Shape`, `RayCast` and `PointQuery` with
//! `ShapeType::Custom`, answering every local query with the shape's own through the
//! interface.
//!
//! **The shape's frame is parry's local frame.** The solid keeps whatever pose it was
//! built with; parry's pose then places that frame in parry's world. A solid built in its
//! own frame (`canonical`) is the common case, and then parry's pose is the solid's pose.
//!
//! **Local queries are the library's, bit for bit**, as [`super::ParryTorus`]'s: a local
//! ray is the library's [`Ray`] over `[0, max_time_of_impact]` and its time of impact is
//! [`Solid::hit`]'s `t`; a local point's projection, inside test and distance are
//! [`Solid::project_point`]'s, [`Solid::contains`]'s and [`Solid::signed_distance`]'s,
//! rounded once to f32. The edges as the torus's: `solid = true` from inside gives time 0
//! and a zero normal; the normal faces the ray; a ray the library refuses hits nothing; a
//! non-finite point is never inside, its distance `+∞`. A point query the shape refuses
//! (an elliptical horn or spindle's closest point, [`crate::PointQueryError::Unsupported`])
//! projects the point onto itself and reports it inside or not by [`Solid::contains`],
//! with the distance `+∞` outside and `−∞` inside: parry's trait has no error, and no
//! number is invented. The feature id of a bend's hit is its face
//! (`FeatureId::Face(0..4)`: outer, bore, start cap, end cap).
//!
//! **Boxes:** the local AABB is [`Solid::world_aabb`] (the bend's: its outer torus's),
//! the bounding sphere the box's (centre the box's, radius its half-diagonal rounded
//! up), a posed AABB parry's transform of the local box.
//!
//! **Mass properties, for a uniform density ρ, where a closed form exists** (Pappus: a
//! solid of revolution's volume is its section's area times the path of its centroid):
//! * an elliptical ring member (R > a, semi-axes a radial and b axial): `m = ρ·2π²Rab`,
//!   `I_axis = m(R² + 3a²/4)`, `I_diameter = m(R²/2 + 3a²/8 + b²/4)` (the circular
//!   ring's `m(R² + 3r²/4)` and `m(R²/2 + 5r²/8)` at a = b = r);
//! * a whole bend (Δφ = 2π) with a bore r_min: the outer ring's minus the bore's.
//!
//!   [`ParrySolid::try_mass_properties`] refuses, in words, a horn or spindle member (its
//!   section crosses the axis: the apple's integrals are not provided) and a bend segment
//!   (Δφ < 2π: its centre of mass leaves the axis; not provided); `Shape::mass_properties`
//!   then answers zero mass and inertia (parry's `MassProperties::zero()`), as parry's own
//!   shapes without a volume do, so
//!   a rigid body needs its mass set by hand.
//! * `scale_dyn` answers `None` (a scaled member is rebuilt by its constructor), and
//!   contacts are not supported, as for the torus.

use super::{from_parry, to_parry};
use crate::bend::{BendFace, PipeBend};
use crate::family::{Toroid, ToroidKind};
use crate::{Ray, Solid};
use glam::{DQuat, DVec3};
use parry3d::bounding_volume::{Aabb, BoundingSphere};
use parry3d::mass_properties::MassProperties;
use parry3d::math::{Real, Rotation, Vector};
use parry3d::query::{PointProjection, PointQuery, Ray as ParryRay, RayCast, RayIntersection};
use parry3d::shape::{FeatureId, Shape, ShapeType, SubShapeId, TypedShape};
use std::f64::consts::{PI, TAU};
use std::fmt;

/// What the parry adapter asks of a solid beyond [`Solid`]: its faces as parry feature
/// ids, its mass properties where a closed form exists, and its thinnest part.
pub trait ParryAdapted: Solid + Clone + fmt::Debug + Send + Sync + 'static {
    /// The face as parry's feature index.
    fn face_index(face: Self::Face) -> u32;

    /// Mass, centre of mass and principal inertia `(I_x, I_axis, I_z)` about axes whose
    /// second is the solid's axis, for density ρ; or why not.
    ///
    /// # Errors
    ///
    /// Words naming the shape and why no closed form is provided.
    fn mass(&self, density: f64) -> Result<(f64, DVec3, DVec3), &'static str>;

    /// The solid's axis, world space (the principal inertia frame takes +y to it).
    fn axis(&self) -> DVec3;

    /// The thinnest the solid is (parry's CCD thickness).
    fn thickness(&self) -> f64;
}

/// Mass and principal inertia `(I_diameter, I_axis, I_diameter)` of an elliptical ring
/// (module docs: Pappus).
fn ring_mass(density: f64, big: f64, a: f64, b: f64) -> (f64, DVec3) {
    let mass = density * 2.0 * PI * PI * big * a * b;
    let axial = mass * (big * big + 0.75 * a * a);
    let diameter = mass * (0.5 * big * big + 0.375 * a * a + 0.25 * b * b);
    (mass, DVec3::new(diameter, axial, diameter))
}

impl ParryAdapted for Toroid {
    fn face_index(_: crate::NoFace) -> u32 {
        0
    }

    fn mass(&self, density: f64) -> Result<(f64, DVec3, DVec3), &'static str> {
        if self.kind() != ToroidKind::Ring {
            return Err(
                "the mass properties of a horn or spindle torus (its section \
                        crosses the axis) are not provided: set the body's mass by hand",
            );
        }
        let (big, a, b) = (
            self.major_radius_f64(),
            self.radial_semi_axis_f64(),
            self.axial_semi_axis_f64(),
        );
        let (mass, inertia) = ring_mass(density, big, a, b);
        Ok((mass, self.center_f64(), inertia))
    }

    fn axis(&self) -> DVec3 {
        self.axis_f64()
    }

    fn thickness(&self) -> f64 {
        self.radial_semi_axis_f64().min(self.axial_semi_axis_f64())
    }
}

impl ParryAdapted for PipeBend {
    fn face_index(face: BendFace) -> u32 {
        match face {
            BendFace::Outer => 0,
            BendFace::Inner => 1,
            BendFace::StartCap => 2,
            BendFace::EndCap => 3,
        }
    }

    fn mass(&self, density: f64) -> Result<(f64, DVec3, DVec3), &'static str> {
        if self.delta_phi() < TAU {
            return Err(
                "the mass properties of a bend segment (Δφ < 2π: its centre of \
                        mass leaves the axis) are not provided: set the body's mass by hand",
            );
        }
        let big = self.major_radius_f64();
        let (r, s) = (self.tube_radius_f64(), self.bore_radius_f64());
        let (outer, outer_inertia) = ring_mass(density, big, r, r);
        let (bore, bore_inertia) = ring_mass(density, big, s, s);
        Ok((
            outer - bore,
            self.outer().center_f64(),
            outer_inertia - bore_inertia,
        ))
    }

    fn axis(&self) -> DVec3 {
        self.outer().axis_f64()
    }

    fn thickness(&self) -> f64 {
        self.tube_radius_f64() - self.bore_radius_f64()
    }
}

/// A library solid as a parry3d shape (module docs: what each query returns).
///
/// ```
/// use parry3d::math::{Pose, Vector};
/// use parry3d::query::{PointQuery, Ray, RayCast};
/// use torus_cull::adapters::parry::{ParryBend, ParryToroid};
/// use torus_cull::bend::PipeBend;
/// use torus_cull::family::Toroid;
/// let toroid = ParryToroid::new(Toroid::canonical(4.0, 1.0, 0.5)?);
/// let down = Ray::new(Vector::new(4.0, 10.0, 0.0), Vector::new(0.0, -1.0, 0.0));
/// assert_eq!(toroid.cast_ray(&Pose::identity(), &down, 100.0, true), Some(9.5));
/// let bend = ParryBend::new(PipeBend::canonical(4.0, 0.5, 1.0, -0.5, 1.0)?);
/// assert!(bend.contains_point(&Pose::identity(), Vector::new(4.0, 0.75, 0.0)));
/// assert!(!bend.contains_point(&Pose::identity(), Vector::new(4.0, 0.0, 0.0))); // the bore
/// assert!(bend.try_mass_properties(1.0).is_err()); // a segment: refused in words
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParrySolid<S> {
    solid: S,
}

/// The family's [`Toroid`] as a parry shape.
pub type ParryToroid = ParrySolid<Toroid>;

/// A [`PipeBend`] as a parry shape.
pub type ParryBend = ParrySolid<PipeBend>;

impl<S: ParryAdapted> ParrySolid<S> {
    /// The solid as a parry shape, its frame parry's local frame.
    #[must_use]
    pub const fn new(solid: S) -> Self {
        ParrySolid { solid }
    }

    /// The library's solid.
    #[must_use]
    pub const fn solid(&self) -> &S {
        &self.solid
    }

    /// The mass properties for `density` where a closed form exists (module docs).
    ///
    /// # Errors
    ///
    /// Words naming the shape and why not: a horn or spindle member, a bend segment, or
    /// a density that is not finite and positive.
    pub fn try_mass_properties(&self, density: Real) -> Result<MassProperties, &'static str> {
        if !(density.is_finite() && density > 0.0) {
            return Err("the density must be finite and > 0");
        }
        let (mass, center, inertia) = self.solid.mass(f64::from(density))?;
        let frame = DQuat::from_rotation_arc(DVec3::Y, self.solid.axis()).as_quat();
        Ok(MassProperties::with_principal_inertia_frame(
            to_parry(center.as_vec3()),
            mass as f32,
            to_parry(inertia.as_vec3()),
            Rotation::from_array(frame.to_array()),
        ))
    }
}

impl<S: ParryAdapted> RayCast for ParrySolid<S> {
    fn cast_local_ray_and_get_normal(
        &self,
        ray: &ParryRay,
        max_time_of_impact: Real,
        solid: bool,
    ) -> Option<RayIntersection> {
        let (origin, dir) = (from_parry(ray.origin), from_parry(ray.dir));
        let ray = Ray::with_range(origin, dir, 0.0, max_time_of_impact).ok()?;
        if solid && self.solid.contains(origin.as_dvec3()).ok()? {
            return Some(RayIntersection::new(0.0, Vector::ZERO, FeatureId::Face(0)));
        }
        let hit = self.solid.hit(&ray)?;
        let normal = if hit.front_face {
            hit.normal
        } else {
            -hit.normal
        };
        Some(RayIntersection::new(
            hit.t,
            to_parry(normal),
            FeatureId::Face(S::face_index(hit.face)),
        ))
    }
}

impl<S: ParryAdapted> PointQuery for ParrySolid<S> {
    fn project_local_point(&self, pt: Vector, solid: bool) -> PointProjection {
        self.project_local_point_and_get_feature_solid(pt, solid).0
    }

    fn project_local_point_and_get_feature(&self, pt: Vector) -> (PointProjection, FeatureId) {
        self.project_local_point_and_get_feature_solid(pt, false)
    }

    /// The library's signed distance rounded to f32 (module docs for a refused query).
    fn distance_to_local_point(&self, pt: Vector, solid: bool) -> Real {
        let p = from_parry(pt).as_dvec3();
        let d = match self.solid.signed_distance(p) {
            Ok(d) => d as f32,
            Err(crate::PointQueryError::Unsupported(_)) if self.contains(p) => Real::NEG_INFINITY,
            Err(_) => Real::INFINITY,
        };
        if solid { d.max(0.0) } else { d }
    }

    fn contains_local_point(&self, pt: Vector) -> bool {
        self.contains(from_parry(pt).as_dvec3())
    }
}

impl<S: ParryAdapted> ParrySolid<S> {
    /// Inside, the surface included; a non-finite point never.
    fn contains(&self, p: DVec3) -> bool {
        self.solid.contains(p).unwrap_or(false)
    }

    /// The projection and the face's feature id.
    fn project_local_point_and_get_feature_solid(
        &self,
        pt: Vector,
        solid: bool,
    ) -> (PointProjection, FeatureId) {
        let p = from_parry(pt).as_dvec3();
        match self.solid.project_point(p) {
            Ok(q) => {
                let inside = q.signed_distance <= 0.0;
                let face = FeatureId::Face(S::face_index(q.face));
                if solid && inside {
                    (PointProjection::new(true, pt), face)
                } else {
                    (
                        PointProjection::new(inside, to_parry(q.point.as_vec3())),
                        face,
                    )
                }
            }
            Err(_) => (
                PointProjection::new(self.contains(p), pt),
                FeatureId::Unknown,
            ),
        }
    }
}

impl<S: ParryAdapted> Shape for ParrySolid<S> {
    /// [`Solid::world_aabb`] of the solid in its own frame, rounded outward.
    fn compute_local_aabb(&self) -> Aabb {
        let (lo, hi) = self.solid.world_aabb();
        Aabb::new(to_parry(lo), to_parry(hi))
    }

    /// The local box's centre, its half-diagonal rounded up.
    fn compute_local_bounding_sphere(&self) -> BoundingSphere {
        let (lo, hi) = self.solid.world_aabb();
        let (lo, hi) = (lo.as_dvec3(), hi.as_dvec3());
        let center = (lo + hi) * 0.5;
        let radius = (hi - lo).length() * 0.5;
        // The centre rounded to f32 moves by at most half an ulp of each component: the
        // radius grows by that much, then rounds up.
        let slack = (center - center.as_vec3().as_dvec3()).length();
        BoundingSphere::new(
            to_parry(center.as_vec3()),
            crate::num::round::up(radius + slack),
        )
    }

    fn clone_dyn(&self) -> Box<dyn Shape> {
        Box::new(self.clone())
    }

    /// `None`: a scaled member is rebuilt by its constructor (module docs).
    fn scale_dyn(&self, _scale: Vector, _num_subdivisions: u32) -> Option<Box<dyn Shape>> {
        None
    }

    /// [`ParrySolid::try_mass_properties`], or zero mass and inertia where it refuses
    /// (module docs).
    fn mass_properties(&self, density: Real) -> MassProperties {
        self.try_mass_properties(density)
            .unwrap_or_else(|_| MassProperties::new(Vector::ZERO, 0.0, Vector::ZERO))
    }

    fn shape_type(&self) -> ShapeType {
        ShapeType::Custom
    }

    fn as_typed_shape(&self) -> TypedShape<'_> {
        TypedShape::Custom(self)
    }

    /// The thinnest the solid is: the smaller semi-axis, the bend's wall.
    fn ccd_thickness(&self) -> Real {
        self.solid.thickness() as f32
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
            .solid
            .project_point(from_parry(point).as_dvec3())
            .ok()?;
        Some(to_parry(p.normal.as_vec3()))
    }
}

impl<S: ParryAdapted> From<S> for ParrySolid<S> {
    fn from(solid: S) -> Self {
        ParrySolid::new(solid)
    }
}
