//! What a [`crate::Solid`] answers for one ray: the nearest hit with its face, and the
//! certified f32 answer with whether f64 had to finish it.

use super::ray::Precision;
use glam::Vec3;

/// The face of a solid whose surface is one face: a ring torus or a family member
/// ([`crate::Solid::Face`] of `Torus` and `Toroid`). A pipe bend names its faces
/// (`BendFace`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct NoFace;

/// The nearest hit of a ray on a [`crate::Solid`], in the ray's precision: the fields of
/// the ring torus's `Hit` and the face struck ([`NoFace`] for a one-face solid).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SolidHit<P: Precision, F> {
    /// Ray parameter, in units of the ray's direction.
    pub t: P::Float,
    /// The face's unit outward normal (out of the solid), world space.
    pub normal: P,
    /// The hit point `o + t·d`, world space, formed in f64 and rounded once.
    pub point: P,
    /// The ray enters the solid here (`d·n < 0`); `false` where it leaves it.
    pub front_face: bool,
    /// The face struck.
    pub face: F,
}

impl<P: Precision, F> SolidHit<P, F> {
    /// A hit from its fields (a solid of your own, or a test's expectation).
    #[must_use]
    pub const fn new(t: P::Float, normal: P, point: P, front_face: bool, face: F) -> Self {
        SolidHit {
            t,
            normal,
            point,
            front_face,
            face,
        }
    }
}

/// The nearest hit of an f32 ray as the certified f32 path finishes it
/// ([`crate::Solid::hit_f32_certified`]): f32's answer where it proved one, the f64
/// solid's where it could not (`escalated`). Either way `hit` is the shape's f32 answer.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SolidF32Hit<F> {
    /// The nearest hit in range, or `None`.
    pub hit: Option<SolidHit<Vec3, F>>,
    /// f32 proved nothing; the f64 path answered.
    pub escalated: bool,
}

impl<F> SolidF32Hit<F> {
    /// An answer from its fields.
    #[must_use]
    pub const fn new(hit: Option<SolidHit<Vec3, F>>, escalated: bool) -> Self {
        SolidF32Hit { hit, escalated }
    }
}

/// The hit alone, as [`crate::Solid::hit`] answers.
impl<F> From<SolidF32Hit<F>> for Option<SolidHit<Vec3, F>> {
    fn from(answer: SolidF32Hit<F>) -> Self {
        answer.hit
    }
}
