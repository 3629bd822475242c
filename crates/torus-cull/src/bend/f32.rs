//! The pipe bend on the certified f32 path: f32 proves what it can of the outer torus, and
//! the f64 solid answers every other ray.
//!
//! The whole torus is the ring torus: [`crate::intersect_f32`], its hits on the face
//! `Outer`. A cut bend (a bore or a segment) is proved only where it is missed: every face
//! of the solid lies in the closed outer tube, so a segment that starts outside the tube
//! and never meets the outer torus stays outside the solid. Everything else (a hit of the
//! outer torus, which may fall in the cut-away arc or lead to the bore or a cap; a segment
//! that starts inside; a ray from a surface point) escalates to [`PipeBend::intersect`].

use super::{BendHit, PipeBend};
use crate::geometry::ray::sealed::Scalar;
use crate::{F32Verdict, Precision, Ray, intersect_f32, intersect_f32_certified};

/// A bend's nearest hit as the f32 path finishes it ([`PipeBend::intersect_f32`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct BendF32Hit {
    /// The nearest crossing in range, or `None`.
    pub hit: Option<BendHit>,
    /// The f64 [`PipeBend::intersect`] answered (f32 proved nothing).
    pub escalated: bool,
}

/// How far outside the outer tube, in units of R + r_max, a segment's start must lie for
/// the f64 distance to say so for certain: its error is a few 10⁻¹⁶ of the point's
/// distance from the centre, so this holds out to 10⁶·(R + r_max).
const OUTSIDE_MARGIN: f64 = 1e-9;

impl PipeBend {
    /// [`PipeBend::intersect`] through the certified f32 path: the same answer, from f32
    /// where it proves one (a whole bend's hits and misses; a cut bend's misses of the outer
    /// torus from outside it), else from the f64 solid (`escalated`). Module docs: why.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::Ray;
    /// use torus_cull::bend::PipeBend;
    /// use std::f64::consts::FRAC_PI_2;
    /// let bend = PipeBend::canonical(4.0, 0.5, 1.0, 0.0, FRAC_PI_2)?;
    /// let away = Ray::new(Vec3::new(0.0, 10.0, 0.0), Vec3::X)?; // misses the outer torus
    /// let answer = bend.intersect_f32(&away);
    /// assert_eq!((answer.hit, answer.escalated), (None, false));
    /// let down = Ray::new(Vec3::new(2.828, 10.0, -2.828), Vec3::NEG_Y)?; // φ = π/4: a hit
    /// let answer = bend.intersect_f32(&down);
    /// assert!(answer.escalated);
    /// assert_eq!(answer.hit, bend.intersect(&down));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn intersect_f32(&self, ray: &Ray) -> BendF32Hit {
        if let Ok(torus) = self.as_torus() {
            let answer = intersect_f32(torus, ray);
            return BendF32Hit {
                hit: answer.hit.map(BendHit::on_outer),
                escalated: answer.escalated,
            };
        }
        if self.proved_clear(ray) && intersect_f32_certified(&self.outer, ray) == F32Verdict::Miss {
            return BendF32Hit {
                hit: None,
                escalated: false,
            };
        }
        BendF32Hit {
            hit: self.intersect(ray),
            escalated: true,
        }
    }

    /// Whether a ray's segment may be called a miss once its line is shown to meet the
    /// outer torus nowhere in range: it is not a ray from a surface point (whose origin
    /// may lie on the bore or a cap), and it starts outside the outer tube by
    /// [`OUTSIDE_MARGIN`] (f64).
    pub(crate) fn proved_clear<P: Precision>(&self, ray: &Ray<P>) -> bool {
        if ray.starts_on_surface() {
            return false;
        }
        let (o, d) = (ray.origin().to_dvec3(), ray.dir().to_dvec3());
        let start = o + d * ray.t_min().to_f64();
        let x = self.local_point(start);
        let core = (x.x.hypot(x.z) - self.major_radius_f64()).hypot(x.y);
        let scale = self.major_radius_f64() + self.tube_radius_f64();
        core > self.tube_radius_f64() + OUTSIDE_MARGIN * scale
    }
}
