//! The exact intersection in f32, certified: f32 decides only what it proves, and hands
//! every other ray to the f64 solver ("escalates" it).
//!
//! WORK IN PROGRESS (issue 19): the certificate is being written; until it lands every
//! ray escalates, which is conservative (the f64 answer) but saves nothing.

use crate::intersect::Hit;
use crate::{Ray, Torus, intersect};
use glam::Vec3;

/// What the f32 path proved about one ray.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum F32Verdict {
    /// A hit, proved: the first root in `[t_min, t_max]` lies within the certified
    /// bracket around `t`.
    Hit {
        /// Ray parameter, in units of the ray's direction.
        t: f32,
        /// Unit outward surface normal, world space.
        normal: Vec3,
    },
    /// No root in `[t_min, t_max]`, proved.
    Miss,
    /// Not proved either way in f32: the f64 solver must answer.
    Escalate,
}

/// The nearest hit as the f32 path finishes it: the certified f32 answer, or the f64
/// solver's where f32 could not prove one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct F32Hit {
    /// The nearest hit, or `None`.
    pub hit: Option<Hit>,
    /// The f64 solver answered (f32 could not certify).
    pub escalated: bool,
}

/// The certified f32 verdict alone (no f64 fallback): what a GPU kernel returns.
#[must_use]
pub fn intersect_f32_certified(_torus: &Torus, _ray: &Ray) -> F32Verdict {
    F32Verdict::Escalate
}

/// The nearest hit through the f32 path: certified in f32, escalated to [`intersect`]
/// otherwise. Never misses a hit the f64 path finds.
#[must_use]
pub fn intersect_f32(torus: &Torus, ray: &Ray) -> F32Hit {
    match intersect_f32_certified(torus, ray) {
        F32Verdict::Hit { t, normal } => F32Hit {
            hit: Some(Hit { t, normal }),
            escalated: false,
        },
        F32Verdict::Miss => F32Hit {
            hit: None,
            escalated: false,
        },
        F32Verdict::Escalate => F32Hit {
            hit: intersect(torus, ray),
            escalated: true,
        },
    }
}
