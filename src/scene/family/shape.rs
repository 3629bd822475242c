//! One shape of the family scene: a [`Toroid`] or a [`PipeBend`], its box, its exact
//! intersection, the library's cull for it, and its spawn API.

use glam::Vec3;
use torus_cull::bend::{BendFace, PipeBend};
use torus_cull::family::{Toroid, ToroidKind};
use torus_cull::{Cull, NoCull, Ray};

/// A shape of the torus family in a scene.
// A bend (two tori and a wedge) is twice a `Toroid`'s size; the scene holds its shapes
// once, in one Vec that the leaves read by index, so they stay unboxed: a leaf reads its
// shape in place, and what a `Toroid` leaves unused is a few hundred bytes a shape.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FamilyShape {
    /// A ring, horn or spindle torus with a circular or elliptical tube.
    Toroid(Toroid),
    /// A torus segment with a bore and end caps.
    Bend(PipeBend),
}

/// Which kind of shape, for counting a test's hits per kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ShapeClass {
    /// A ring torus with a circular tube (a = b).
    Ring,
    /// A ring torus with an elliptical tube (a ≠ b).
    Elliptic,
    /// R = a, either tube.
    Horn,
    /// R < a, either tube: the apple.
    Spindle,
    /// A pipe bend that is a whole ring with a bore.
    BoredRing,
    /// A pipe bend cut to a φ segment (with or without a bore): end caps.
    Segment,
}

impl ShapeClass {
    /// Every class, in the order the scene cycles through them.
    pub const ALL: [ShapeClass; 6] = [
        ShapeClass::Ring,
        ShapeClass::Elliptic,
        ShapeClass::Horn,
        ShapeClass::Spindle,
        ShapeClass::BoredRing,
        ShapeClass::Segment,
    ];
}

/// A shape's nearest hit: t, the unit outward normal, whether the ray enters there, and
/// on a bend the face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeHit {
    /// Ray parameter, in units of the ray's direction.
    pub t: f32,
    /// Unit outward normal, world space.
    pub normal: Vec3,
    /// The ray enters the solid here.
    pub front_face: bool,
    /// The bend's face hit (`None` on a [`Toroid`]).
    pub face: Option<BendFace>,
}

impl FamilyShape {
    /// Which kind of shape.
    pub fn class(&self) -> ShapeClass {
        match self {
            FamilyShape::Toroid(t) => match t.kind() {
                ToroidKind::Ring if t.aspect() == 1.0 => ShapeClass::Ring,
                ToroidKind::Ring => ShapeClass::Elliptic,
                ToroidKind::Horn => ShapeClass::Horn,
                ToroidKind::Spindle => ShapeClass::Spindle,
            },
            FamilyShape::Bend(b) if b.delta_phi() < std::f64::consts::TAU => ShapeClass::Segment,
            FamilyShape::Bend(_) => ShapeClass::BoredRing,
        }
    }

    /// The world box `(min, max)` that holds the solid: [`Toroid::world_aabb`]; for a
    /// bend its outer torus's ([`torus_cull::Torus::world_aabb`]), as the solid lies in the
    /// outer torus.
    pub fn world_box(&self) -> (Vec3, Vec3) {
        match self {
            FamilyShape::Toroid(t) => t.world_aabb(),
            FamilyShape::Bend(b) => b.outer().world_aabb(),
        }
    }

    /// The nearest hit in `[t_min, t_max]`: [`Toroid::intersect`] or
    /// [`PipeBend::intersect`], each the shape's own exact intersection.
    pub fn intersect(&self, ray: &Ray) -> Option<ShapeHit> {
        match self {
            FamilyShape::Toroid(t) => t.intersect(ray).map(|h| ShapeHit {
                t: h.t,
                normal: h.normal,
                front_face: h.front_face,
                face: None,
            }),
            FamilyShape::Bend(b) => b.intersect(ray).map(|h| ShapeHit {
                t: h.t,
                normal: h.normal,
                front_face: h.front_face,
                face: Some(h.face),
            }),
        }
    }

    /// Whether the ray meets the solid in `[t_min, t_max]`: the shape's own `occluded`.
    pub fn occluded(&self, ray: &Ray) -> bool {
        match self {
            FamilyShape::Toroid(t) => t.occluded(ray),
            FamilyShape::Bend(b) => b.occluded(ray),
        }
    }

    /// Whether `cull` keeps the ray, by the library's own rule for the shape: a member
    /// runs it on its image line ([`Toroid::kept_by`], which declines a cull not proved
    /// for its shape), a bend on its outer torus with the segment's wedge after it
    /// ([`PipeBend::wedge_cull`]). Both are conservative: a kept-out ray misses the solid.
    /// `none` keeps every ray, a bend's included: it is the exact intersection alone (the
    /// wedge is a cull, timed as `wedge+none` by `time --bend`), so that every cull's
    /// ratio over it counts the wedge's saving too.
    pub fn kept_by<C: Cull>(&self, cull: &C, ray: &Ray) -> bool {
        match self {
            FamilyShape::Toroid(t) => t.kept_by(cull, ray),
            FamilyShape::Bend(_) if cull.name() == NoCull.name() => true,
            FamilyShape::Bend(b) => {
                // `wedge_cull` takes the torus cull by value; the wedge alone on the outer
                // torus's line is the same test after `kept_by`.
                let line = b.outer().line_to_local(ray);
                b.kept_by(cull, ray) && b.wedge_cull(NoCull).wedge_keeps(line.origin, line.dir)
            }
        }
    }

    /// The ray leaving the hit at `t` on `ray` in `dir`, marked as starting on the surface:
    /// [`Toroid::spawn`] or [`PipeBend::spawn`]; `None` where the spawn fails.
    pub fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Option<Ray> {
        match self {
            FamilyShape::Toroid(s) => s.spawn(ray, t, dir).ok(),
            FamilyShape::Bend(s) => s.spawn(ray, t, dir).ok(),
        }
    }
}
