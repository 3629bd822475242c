//! One shape of the family scene: a [`Toroid`] or a [`PipeBend`], answered through the
//! library's shape interface ([`Solid`]: its box, exact intersection, shadow test and
//! spawn), and the library's cull for it, which the interface has no verb for (a bend's
//! adds its wedge).

use glam::Vec3;
use torus_cull::bend::{BendFace, PipeBend};
use torus_cull::family::{Toroid, ToroidKind};
use torus_cull::{Cull, NoCull, Ray, Solid, SolidHit};

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

/// A shape's nearest hit, the interface's [`SolidHit`] with the face of either shape: t,
/// the unit outward normal, the point, whether the ray enters there, and on a bend the
/// face (`None` on a [`Toroid`], whose [`Solid::Face`] is the one-face `NoFace`).
pub type ShapeHit = SolidHit<Vec3, Option<BendFace>>;

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

    /// The world box `(min, max)` that holds the solid: [`Solid::world_aabb`], the
    /// toroid's own box, and for a bend its outer torus's (the whole ring's: the solid lies
    /// in the outer torus), the box the scene always gave it.
    pub fn world_box(&self) -> (Vec3, Vec3) {
        match self {
            FamilyShape::Toroid(t) => Solid::world_aabb(t),
            FamilyShape::Bend(b) => Solid::world_aabb(b),
        }
    }

    /// The nearest hit in `[t_min, t_max]`: [`Solid::hit`], each shape's own exact
    /// intersection (`Toroid::intersect`, `PipeBend::intersect`).
    // One match a leaf, each arm a concrete shape's call: the leaf loop stays monomorphic
    // (a shared closure there once cost 7–10 %).
    pub fn intersect(&self, ray: &Ray) -> Option<ShapeHit> {
        match self {
            FamilyShape::Toroid(t) => Solid::hit(t, ray).map(|h| with_face(h, None)),
            FamilyShape::Bend(b) => Solid::hit(b, ray).map(|h| with_face(h, Some(h.face))),
        }
    }

    /// Whether the ray meets the solid in `[t_min, t_max]`: [`Solid::occluded`].
    pub fn occluded(&self, ray: &Ray) -> bool {
        match self {
            FamilyShape::Toroid(t) => Solid::occluded(t, ray),
            FamilyShape::Bend(b) => Solid::occluded(b, ray),
        }
    }

    /// Whether `cull` keeps the ray, by the library's own rule for the shape: a member
    /// runs it on its image line ([`Toroid::kept_by`], which declines a cull not proved
    /// for its shape), a bend on its outer torus with the segment's wedge after it
    /// ([`PipeBend::wedge_cull`]). Both are conservative: a kept-out ray misses the solid.
    /// `none` keeps every ray, a bend's included: it is the exact intersection alone (the
    /// wedge is a cull, timed as `wedge+none` by `time bend`), so that every cull's
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
    /// [`Solid::spawn`]; `None` where the spawn fails.
    pub fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Option<Ray> {
        match self {
            FamilyShape::Toroid(s) => Solid::spawn(s, ray, t, dir).ok(),
            FamilyShape::Bend(s) => Solid::spawn(s, ray, t, dir).ok(),
        }
    }
}

/// A shape's [`SolidHit`] with its face as the scene's ([`ShapeHit`]).
#[inline]
fn with_face<F>(hit: SolidHit<Vec3, F>, face: Option<BendFace>) -> ShapeHit {
    SolidHit::new(hit.t, hit.normal, hit.point, hit.front_face, face)
}
