//! The f64 ground truth: hit / miss / ambiguous with a signed margin. Never timed.
//!
//! **Definition.** The true torus is the one given by the f32 centre, the f32 axis
//! normalized in f64, and R, r, all converted to f64 exactly; the ray's f32 origin,
//! direction and range are converted exactly too. For a point x, with `c` the centre and
//! `â` the unit axis, `y = (x − c)·â` and `ρ = |(x − c) − y â|`, and
//!
//! `D(x) = √((ρ − R)² + y²)` (the distance from x to the core circle),
//! `margin = min over t ∈ [t_min, t_max] of D(o + t d) − r`.
//!
//! A negative margin means the ray enters the tube. Nothing here calls the crate's quartic
//! solver, its exact intersection or the f32 rotation of [`Torus`]: the oracle must be able
//! to catch their bugs, so it shares no code with them.
//!
//! **Method** (see also the repository's `docs/math.md`). Along the line, in unit arc
//! length `s` measured from the foot point p (the point closest to the centre, which keeps
//! far origins well conditioned), the minimum of D over an interval is at an end or at a critical point of D. Two sets
//! of candidates are evaluated with D itself:
//! - every critical point of D, found exactly by splitting `½ dD²/ds` into at most three
//!   monotone pieces (see `LineFrame::half_slope`) and bisecting each sign change to the last
//!   bit: this makes the minimum exact, not just close;
//! - every real root of the cubic F′, where F is the torus quartic (own cubic solver,
//!   by monotone pieces and bisection). Since F = (D² − r²)·G with G > 0, F < 0 exactly
//!   where D < r, so these alone already give the right *sign*; the test
//!   `f_prime_candidates_give_the_same_class` checks that.
//!
//! Every candidate is a real point of the interval, so each evaluation is an upper bound
//! on the true minimum and extra candidates can only help.
//!
//! [`margin_by_sampling`] is the second, independent method (dense samples in world
//! coordinates + golden-section refinement) that the tests compare against.
//!
//! [`family`] is the oracle for the whole torus family (ring, horn and spindle, elliptical
//! tube), by its own method on `E = √(((ρ − R)/a)² + (y/b)²)`, with its own second method
//! and on-surface rule.

pub mod bend;
pub mod family;
mod frame;
mod from_surface;
mod interval;
mod roots;
mod sampling;
mod spawned_rule;
#[cfg(test)]
mod tests;

pub use from_surface::{classify_from_surface, first_crossing_from_surface, on_surface_line};
pub use roots::reference_roots;
pub use sampling::margin_by_sampling;

use frame::LineFrame;
use glam::DVec3;
use std::ops::ControlFlow;
use torus_cull::{DRay, Ray, Torus};

/// Relative half-width ε of the ambiguity band: a label is [`OracleClass::Ambiguous`] iff
/// `|margin| ≤ ε·(R + r)`.
///
/// The oracle's own error is about 1e-16·(R + r + distance of the origin), so 1e-9 leaves
/// orders of magnitude of room for origins up to ~10⁵·R while still being far below what an
/// f32 renderer can resolve.
pub const AMBIGUITY_REL: f64 = 1e-9;

/// The oracle's class for a line or ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OracleClass {
    /// Enters the tube by more than the ambiguity band.
    Hit,
    /// Stays outside the tube by more than the ambiguity band.
    Miss,
    /// |margin| ≤ AMBIGUITY_REL·(R + r).
    Ambiguous,
}

/// The oracle's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OracleLabel {
    /// The class.
    pub class: OracleClass,
    /// min over t of dist(P(t), core circle) − r, in length units; negative enters the tube.
    pub margin: f64,
}

impl OracleLabel {
    /// The label for a margin on a torus with radii R, r.
    pub fn from_margin(margin: f64, major: f64, minor: f64) -> OracleLabel {
        let band = AMBIGUITY_REL * (major + minor);
        let class = if margin.abs() <= band {
            OracleClass::Ambiguous
        } else if margin < 0.0 {
            OracleClass::Hit
        } else {
            OracleClass::Miss
        };
        OracleLabel { class, margin }
    }
}

/// One question to the oracle: the line `o + t d`, `t ∈ [t_min, t_max]` (either end may
/// be infinite; `t` in units of `d`, which need not be unit length), against the torus
/// with centre `center`, axis `axis` (normalized by the oracle), R = `major`, r = `minor`;
/// all in f64, world frame.
///
/// Every method panics if `d` or `axis` is zero or not finite, if `o` or `center` is not
/// finite, if the radii are not `major > minor > 0`, or if `t_min > t_max` or either is NaN.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Query {
    /// The torus's centre.
    pub center: DVec3,
    /// The torus's axis (any length).
    pub axis: DVec3,
    /// R.
    pub major: f64,
    /// r.
    pub minor: f64,
    /// The line's origin.
    pub o: DVec3,
    /// The line's direction.
    pub d: DVec3,
    /// The range's start.
    pub t_min: f64,
    /// The range's end.
    pub t_max: f64,
}

impl Query {
    /// The ray over its range, on the torus as the oracle defines it (f32 fields converted
    /// exactly, the axis normalized in f64).
    pub fn ray(torus: &Torus, ray: &Ray) -> Query {
        Query::dray(torus, &DRay::from(*ray))
    }

    /// An f64 ray over its range, on the torus as the oracle defines it: its f64 pose and
    /// radii (for a torus built from f32 values, those widened exactly, the axis
    /// normalized in f64; for `Torus::new_f64`, the f64 values given).
    pub fn dray(torus: &Torus, ray: &DRay) -> Query {
        Query {
            center: torus.center_f64(),
            axis: torus.axis_f64(),
            major: torus.major_radius_f64(),
            minor: torus.minor_radius_f64(),
            o: ray.origin(),
            d: ray.dir(),
            t_min: ray.t_min(),
            t_max: ray.t_max(),
        }
    }

    /// The ray's whole line, `t ∈ (−∞, +∞)`.
    pub fn line(torus: &Torus, ray: &Ray) -> Query {
        Query {
            t_min: f64::NEG_INFINITY,
            t_max: f64::INFINITY,
            ..Query::ray(torus, ray)
        }
    }

    /// The same line over `[t_min, t_max]`.
    pub fn over(self, t_min: f64, t_max: f64) -> Query {
        Query {
            t_min,
            t_max,
            ..self
        }
    }

    /// The oracle's class and margin: [`classify`] for any [`Query`].
    ///
    /// A line whose numbers overflow f64 ([`Query::check_reach`] fails) gets a NaN margin
    /// and the class [`OracleClass::Ambiguous`]: call `check_reach` first to refuse it.
    pub fn classify(&self) -> OracleLabel {
        match self.classify_unless(|_| false) {
            Some(label) => label,
            None => unreachable!("a test that rejects nothing never stops the search"),
        }
    }

    /// [`Query::classify`] for a caller who throws the label away when `rejects(margin)`
    /// holds: `None` as soon as one candidate's margin makes `rejects` true, without
    /// bisecting the others; otherwise the label `classify` gives, bit for bit.
    ///
    /// `rejects` must hold for every margin below one it holds for (`m ≤ band`, say):
    /// the margin is the minimum over the candidates, so it only falls as they come in, and
    /// `None` is then returned exactly where `rejects(self.classify().margin)` holds. For
    /// the workload's rejection samplers, which throw most candidates away (a `hole` at
    /// ν = 1.1 keeps 4 % of them) and need not pay for the whole minimum of each.
    pub fn classify_unless(&self, rejects: impl Fn(f64) -> bool) -> Option<OracleLabel> {
        let frame = LineFrame::new(self);
        let (lo, hi) = frame.s_range(self.t_min, self.t_max);
        if !frame.is_finite() {
            return Some(OracleLabel {
                class: OracleClass::Ambiguous,
                margin: f64::NAN,
            });
        }
        if frame.is_far() {
            let margin = frame.far_min_dist(lo, hi) - self.minor;
            return Some(OracleLabel::from_margin(margin, self.major, self.minor));
        }
        // The minimum of D over the candidates, in any order (min is exact).
        let mut best = f64::INFINITY;
        let searched = each_candidate(&frame, lo, hi, &mut |s| {
            best = best.min(frame.dist(s));
            if rejects(best - self.minor) {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        searched
            .is_continue()
            .then(|| OracleLabel::from_margin(best - self.minor, self.major, self.minor))
    }

    /// Whether the oracle can answer this line: `Err`, saying why, where the origin or the
    /// direction is so large (|o − c| or |d| near f64's largest value, 1.8e308) that the
    /// numbers the oracle derives from them overflow. Any finite line short of that is
    /// answered, however far: its foot point is computed to rounding of itself, and a line
    /// that passes farther than 1e100·(R + r) from the centre by the distance alone.
    ///
    /// # Panics
    /// As [`Query`], for an invalid torus or line.
    pub fn check_reach(&self) -> Result<(), String> {
        let frame = LineFrame::new(self);
        if frame.is_finite() {
            Ok(())
        } else {
            Err(format!(
                "the oracle cannot answer this line: its numbers overflow f64 (origin \
                 components up to {:e} from the centre's, direction components up to {:e})",
                (self.o - self.center).abs().max_element(),
                self.d.abs().max_element()
            ))
        }
    }

    /// The torus and the line are valid (the range is checked where it is used).
    pub(super) fn check_line(&self) {
        check_pose(self.center, self.axis, self.o, self.d);
        let (major, minor) = (self.major, self.minor);
        assert!(
            minor > 0.0 && major > minor && major.is_finite(),
            "need R > r > 0, got R = {major}, r = {minor}"
        );
    }

    /// [`Query::check_line`] and the range.
    pub(super) fn check(&self) {
        self.check_line();
        let (t_min, t_max) = (self.t_min, self.t_max);
        assert!(t_min <= t_max, "bad range [{t_min}, {t_max}]");
    }
}

/// Hands `visit` every point of [lo, hi] whose D the minimum is taken over, until it
/// breaks: the range's finite ends first (two evaluations), then D's critical points and
/// breakpoints ([`LineFrame::each_d_candidate`]), then F′'s real roots.
fn each_candidate(
    frame: &LineFrame,
    lo: f64,
    hi: f64,
    visit: &mut dyn FnMut(f64) -> ControlFlow<()>,
) -> ControlFlow<()> {
    for s in [lo, hi] {
        if s.is_finite() {
            visit(s)?;
        }
    }
    frame.each_d_candidate(lo, hi, visit)?;
    for s in frame.f_prime_roots() {
        if s >= lo && s <= hi {
            visit(s)?;
        }
    }
    ControlFlow::Continue(())
}

/// Classify the ray over `t ∈ [t_min, t_max]` (ray mode; `t_max` may be +∞).
pub fn classify(torus: &Torus, ray: &Ray) -> OracleLabel {
    Query::ray(torus, ray).classify()
}

/// Classify the ray's whole line, `t ∈ (−∞, +∞)` (line mode: the range is ignored).
pub fn classify_line(torus: &Torus, ray: &Ray) -> OracleLabel {
    Query::line(torus, ray).classify()
}

/// Panics unless the centre and origin are finite and the axis and direction finite and
/// nonzero: the pose and line checks every oracle query starts with.
fn check_pose(center: DVec3, axis: DVec3, origin: DVec3, dir: DVec3) {
    assert!(center.is_finite() && origin.is_finite(), "non-finite point");
    assert!(
        axis.is_finite() && axis.length_squared() > 0.0,
        "bad axis {axis}"
    );
    assert!(
        dir.is_finite() && dir.length_squared() > 0.0,
        "bad dir {dir}"
    );
}
