//! The certified f32 path for shadow rays: is there *any* root in `[t_min, t_max]`?
//!
//! The certificate's two proofs answer it as they stand: a proved hit is a proved root in
//! range (the first one), a proved miss is "no root in range". Neither the normal nor
//! the hit point is formed. A ray with neither proof (near-tangent, from a surface point,
//! an origin inside the tube, …) escalates to the f64 [`crate::occluded()`], so the answer
//! is conservative in both directions: never a shadow the f64 path does not cast, never
//! a light it blocks let through.

use super::{Proof, prove};
use crate::{Cull, Ray, Torus, occluded};

/// A shadow ray's answer through the f32 path: [`occluded_f32`], [`occluded_f32_culled`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct F32Occluded {
    /// The ray meets the torus at some `t ∈ [t_min, t_max]`.
    pub occluded: bool,
    /// The f64 [`crate::occluded()`] answered (f32 could not prove it either way).
    pub escalated: bool,
}

/// Whether the ray meets the torus in its range, proved in f32 or answered by the f64
/// [`crate::occluded()`]: always [`crate::occluded()`]'s answer, for the cost of the f32
/// certificate where it proves one.
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, Torus, occluded_f32};
/// let torus = Torus::canonical(4.0, 1.0)?;
/// let to_light = Ray::with_range(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y, 0.0, 20.0)?;
/// let answer = occluded_f32(&torus, &to_light);
/// assert!(answer.occluded && !answer.escalated); // the tube, at t = 9, proved in f32
/// assert!(!occluded_f32(&torus, &to_light.with_t_max(8.5)?).occluded);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn occluded_f32(torus: &Torus, ray: &Ray) -> F32Occluded {
    match prove(torus, ray) {
        Proof::Hit { .. } => F32Occluded {
            occluded: true,
            escalated: false,
        },
        Proof::Miss => F32Occluded {
            occluded: false,
            escalated: false,
        },
        Proof::Escalate => F32Occluded {
            occluded: occluded(torus, ray),
            escalated: true,
        },
    }
}

/// [`occluded_f32`] behind a cull: a line the cull rejects is not occluded (proved by the
/// cull, not escalated).
#[must_use]
pub fn occluded_f32_culled<C: Cull + ?Sized>(cull: &C, torus: &Torus, ray: &Ray) -> F32Occluded {
    if crate::intersect::kept_by(cull, torus, ray) {
        occluded_f32(torus, ray)
    } else {
        F32Occluded {
            occluded: false,
            escalated: false,
        }
    }
}
