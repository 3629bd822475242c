//! The exact intersection in f32, certified: f32 decides only what it proves, and hands
//! every other ray to the f64 solver ("escalates" it).
//!
//! Renderers trace in f32 (every GPU; twice the SIMD lanes of f64), and the f32 closed
//! forms that shaders use lose hits near tangents and silhouettes. Here the f32 solve is
//! the f64 solver's method (depressed quartic at the foot point, Ferrari's split on the
//! resolvent's greatest root) run in f32, and each answer comes with a proof built from
//! error bounds (the module `certificate`): a hit is a proved sign change of the signed distance
//! within 1.9·10⁻⁴·R of the reported root, with F > 0 proved before it; a miss is F > 0
//! proved over the whole range. A ray with neither proof — near-tangent, near-double
//! roots, an origin inside the tube, a non-finite value — escalates to
//! [`crate::intersect()`]. The bound and why it holds: docs/math.md, "The certified f32
//! path".
//!
//! ```
//! use torus_cull::{F32Verdict, Ray, Torus, intersect_f32, intersect_f32_certified};
//! use glam::Vec3;
//! let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
//! let ray = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?;
//! // Straight down onto the top of the tube: f32 proves the hit at t = 9.
//! let F32Verdict::Hit { t, .. } = intersect_f32_certified(&torus, &ray) else {
//!     panic!("a clear hit is proved in f32");
//! };
//! assert!((t - 9.0).abs() < 1e-4);
//! // intersect_f32 finishes what f32 cannot prove with the f64 solver.
//! let answer = intersect_f32(&torus, &ray);
//! assert!(!answer.escalated && answer.hit.is_some());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod certificate;
pub(crate) mod line;
mod occlusion;
pub(crate) mod on_surface;
pub(crate) mod surface_cubic;

use crate::intersect::Hit;
use crate::num::F32s;
use crate::{Cull, Ray, Torus, intersect};
use certificate::{ScaledLine, decide};
use glam::Vec3;
pub use occlusion::{F32Occluded, occluded_f32, occluded_f32_culled};
use pulp::Scalar;

/// What the f32 path proved about one ray.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum F32Verdict {
    /// A hit, proved: the first root in `[t_min, t_max]` lies within 1.9·10⁻⁴·R (along the
    /// unit direction) of the point at `t`.
    Hit {
        /// Ray parameter, in units of the ray's direction.
        t: f32,
        /// Unit outward surface normal, world space (f32-accurate).
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
#[non_exhaustive]
pub struct F32Hit {
    /// The nearest hit, or `None`.
    pub hit: Option<Hit>,
    /// The f64 solver answered (f32 could not certify).
    pub escalated: bool,
}

/// The hit alone, as [`crate::intersect()`] answers: `intersect_f32(…).into()` is a drop-in
/// for `intersect(…)` where the escalation count does not matter.
impl From<F32Hit> for Option<Hit> {
    fn from(answer: F32Hit) -> Option<Hit> {
        answer.hit
    }
}

#[inline(always)]
fn sc32(x: f32) -> F32s<Scalar> {
    F32s {
        s: Scalar::new(),
        v: x,
    }
}

/// The certified f32 verdict alone (no f64 fallback): what a GPU kernel returns.
#[must_use]
pub fn intersect_f32_certified(torus: &Torus, ray: &Ray) -> F32Verdict {
    match prove(torus, ray) {
        Proof::Miss => F32Verdict::Miss,
        Proof::Escalate => F32Verdict::Escalate,
        Proof::Hit { t, scaled, u } => {
            let n = certificate::normal_at(&scaled, u);
            let normal = torus
                .dir_to_world(Vec3::new(n.x.v, n.y.v, n.z.v))
                .normalize_or_zero();
            F32Verdict::Hit { t, normal }
        }
    }
}

/// What the certificate proved about one ray, before a hit's normal is formed (which a
/// shadow ray does not need).
pub(crate) enum Proof {
    /// No root in range.
    Miss,
    /// Neither proved.
    Escalate,
    /// The first root in range is within the bracket of `u`, at the ray's `t` (finite).
    Hit {
        t: f32,
        scaled: ScaledLine<F32s<Scalar>>,
        u: F32s<Scalar>,
    },
}

/// The certificate on one ray.
#[inline]
pub(crate) fn prove(torus: &Torus, ray: &Ray) -> Proof {
    // A ray from a surface point: the cubic left once the origin's root is divided out
    // (`surface_cubic`); where that proves nothing, the literal certificate past the
    // origin's own root (`on_surface`), where it leaves into the outside.
    if ray.starts_on_surface() {
        if let Some(proof) = prove_surface_cubic(torus, ray) {
            return proof;
        }
        return match on_surface::start(torus, ray) {
            on_surface::Start::Literal(literal) => prove(torus, &literal),
            on_surface::Start::Miss => Proof::Miss,
            on_surface::Start::Escalate => Proof::Escalate,
        };
    }
    let Some((columns, back)) = line::of_ray(torus, ray) else {
        return Proof::Escalate;
    };
    let [q, d, rest] = columns.map(|c| c.map(sc32));
    let scaled = line::lanes(sc32(0.0), q, d, rest);
    let decision = decide(&scaled);
    if decision.miss.m {
        return Proof::Miss;
    }
    if !decision.hit.m {
        return Proof::Escalate;
    }
    let t = back.t(f64::from(decision.u.v)) as f32;
    if !t.is_finite() {
        return Proof::Escalate;
    }
    Proof::Hit {
        t,
        scaled,
        u: decision.u,
    }
}

/// The cubic certificate on a ray from a surface point ([`surface_cubic`]); `None` where it
/// proves nothing.
fn prove_surface_cubic(torus: &Torus, ray: &Ray) -> Option<Proof> {
    let line = torus.line_to_local_f64(ray);
    let (t_min, t_max) = (f64::from(ray.t_min()), f64::from(ray.t_max()));
    match surface_cubic::prove(torus, line, t_min, t_max) {
        surface_cubic::Verdict::Miss => Some(Proof::Miss),
        surface_cubic::Verdict::Escalate => None,
        surface_cubic::Verdict::Clear(from) => {
            // No root but the origin's before `from`: the literal ray from there.
            let literal =
                Ray::with_range(ray.origin(), ray.dir(), ray.t_min().max(from), ray.t_max())
                    .ok()?;
            match prove(torus, &literal) {
                Proof::Escalate => None,
                proof => Some(proof),
            }
        }
        surface_cubic::Verdict::Hit { t, u, .. } => {
            // The same foot-point frame as the cubic's: its normal at `u`.
            let (columns, _) = line::of_ray(torus, ray)?;
            let [q, d, rest] = columns.map(|c| c.map(sc32));
            Some(Proof::Hit {
                t,
                scaled: line::lanes(sc32(0.0), q, d, rest),
                u: sc32(u),
            })
        }
    }
}

/// The nearest hit through the f32 path: certified in f32, escalated to [`intersect()`]
/// otherwise. Never misses a hit the f64 path finds.
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, Torus, intersect, intersect_f32};
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// // A clear hit: proved in f32, within 1.9e-4·R of the f64 answer.
/// let down = Ray::new(Vec3::new(4.2, 10.0, 0.3), Vec3::NEG_Y)?;
/// let answer = intersect_f32(&torus, &down);
/// let exact = intersect(&torus, &down).expect("the tube");
/// assert!(!answer.escalated);
/// assert!((answer.hit.expect("proved").t - exact.t).abs() < 1.9e-4 * 4.0);
/// // A ray that starts inside the tube has no proof: the f64 solver answers it, exactly.
/// let inside = Ray::new(Vec3::new(4.0, 0.0, 0.0), Vec3::X)?;
/// let answer = intersect_f32(&torus, &inside);
/// assert!(answer.escalated);
/// assert_eq!(answer.hit, intersect(&torus, &inside));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn intersect_f32(torus: &Torus, ray: &Ray) -> F32Hit {
    finish(intersect_f32_certified(torus, ray), torus, ray)
}

/// One ray's answer from a verdict: the proved one, or the f64 solver's where f32 (on the
/// CPU or the GPU) escalated.
pub(crate) fn finish(verdict: F32Verdict, torus: &Torus, ray: &Ray) -> F32Hit {
    match verdict {
        F32Verdict::Hit { t, normal } => F32Hit {
            hit: Some(proved_hit(t, normal, ray)),
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

/// The [`Hit`] of a proved f32 root: the point `o + t·d` formed in f64 at the reported
/// `t`. `front_face` is true for a literal ray, because the proof is a sign change of the
/// signed distance from outside (> 0) to inside (< 0) with the distance proved positive
/// before it: the ray enters the solid there. A ray from a surface point may be proved to
/// leave the tube from inside (`surface_cubic`, a ray into the tube): its face is the f64
/// path's, `d·n < 0`.
fn proved_hit(t: f32, normal: Vec3, ray: &Ray) -> Hit {
    let point = ray.origin().as_dvec3() + ray.dir().as_dvec3() * f64::from(t);
    Hit {
        t,
        normal,
        point: point.as_vec3(),
        front_face: !ray.starts_on_surface() || ray.dir().dot(normal) < 0.0,
    }
}

/// [`intersect_f32`] behind a cull: a line the cull rejects is a miss (proved by the
/// cull, not escalated); a kept one goes through the certified f32 path. What
/// [`crate::intersect_culled`] is to [`crate::intersect()`].
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, SkalaCull, Torus, intersect_f32_culled};
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
/// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::NEG_Y)?;
/// let answer = intersect_f32_culled(&SkalaCull, &torus, &hole);
/// assert!(answer.hit.is_none() && !answer.escalated);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn intersect_f32_culled<C: Cull + ?Sized>(cull: &C, torus: &Torus, ray: &Ray) -> F32Hit {
    if crate::intersect::kept_by(cull, torus, ray) {
        intersect_f32(torus, ray)
    } else {
        F32Hit {
            hit: None,
            escalated: false,
        }
    }
}
