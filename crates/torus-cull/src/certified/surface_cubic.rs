//! The certified f32 path for rays from a surface point ([`crate::Ray::from_surface`]) on
//! what is left once the origin's root is divided out: the cubic of
//! [`crate::intersect::from_surface`], proved in f32 (docs/math.md §9, "The certified
//! cubic").
//!
//! **Setup (f64, rounded once, as the literal path forms its line).** In the foot-point
//! frame (u in units of R along the unit direction) the line's quartic is
//! `Q(u) = u⁴ + c2 u² + c1 u + c0`. Expanded about the f64 point `p` (the origin's own
//! root by Newton, [`SurfaceCubic`]), exactly for any `p`,
//!
//! `Q(p + v) = v·g(v) + δ`, `g(v) = v³ + a3 v² + a2 v + a1`, `δ = Q(p)`.
//!
//! f64 forms `a3, a2, a1, δ` within `Δ = 8·10⁻¹²·S` (`S` the sum of the magnitudes of the
//! terms that make them; a few dozen f64 roundings of 2⁻⁵³ each and the line's own f64 error, about 2⁻⁵³·(1 + r/R) per coordinate, through polynomials of degree 4 with terms below 16, stay far below that).
//!
//! **1. The origin's zone.** With `A = |a1| − Δ > 0`, `D₀ = |δ| + Δ` and `v_s = 4·D₀/A`:
//! on `[−v_s, v_s]`, `|Q′(p + v) − a1| ≤ 2|a2|v_s + 3|a3|v_s² + 4v_s³` and
//! `|Q(p ± v_s) ∓ a1·v_s| ≤ |a2|v_s² + |a3|v_s³ + v_s⁴ + |δ|` (coefficients taken at
//! their upper bounds). Where the first is below `A` and the second below `A·v_s`, `Q` is
//! strictly monotone on `[p − v_s, p + v_s]` and changes sign there: that stretch holds
//! exactly one root, the origin's, and past it `Q` has the sign `s` of `a1` (outside for
//! `s > 0`: the ray leaves; inside for `s < 0`: the ray enters the tube). Otherwise the ray
//! is not proved here.
//!
//! **2. Past the zone.** For `v ≥ α > 0`, `s·Q(p + v) ≥ v·(s·g(v) − |δ|/v)`, so
//! `s·g(v) > D := (|δ| + Δ)/α` on `[α, β]` proves `Q ≠ 0` there. `g` is evaluated in f32
//! from its rounded coefficients `ã_i`, each within `e_i = |a_i − ã_i| + Δ` of the true
//! one (the difference is exact in f64): Horner's rounding is at most
//! `γ₆·Σ|ã_i|·v^i` (Higham), so `|g̃(v) − g(v)| ≤ 8u·Σ|ã_i|v^i + e3 v² + e2 v + e1`,
//! formed in f32 and inflated by `1 + 2⁻²⁰` for its own roundings. A comparison
//! `fl(fl(x − y) − z) > 0` with `z` an f32 number proves `x − y > z` (rounding is
//! monotone), so the f32 tests below decide exactly what they state.
//!
//! `g″(v) = 6v + 2a3` is linear: with `a3 ∈ [ã3 − e3, ã3 + e3]`, `g` is concave left of
//! `w_lo = −(ã3 + e3)/3` and convex right of `w_hi = −(ã3 − e3)/3`. So `f = s·g − D` is
//! positive on a concave piece where it is at both ends (the chord lies below); on a
//! convex piece where the tangents at both ends (slopes bounded like `g`) have zeros that
//! do not overlap, as the literal certificate proves `F > 0`, the piece split at `g`'s
//! critical point where one pair of tangents is not enough; and on the narrow band
//! `[w_lo, w_hi]` (`|g″| ≤ 6(w_hi − w_lo)`) where both ends clear the chord's sag.
//!
//! **3. The verdict.** With `α = max(v_s, v_min)` (the range's start, rounded down to
//! f32) and the range's end `v_max` (at most `1 + rr − p`: every root lies in the bounding
//! sphere): a **miss** is `f > 0` on `[α, v_max]`; a **hit** at the f32 root `v̂` of `g̃`
//! is `f > 0` on `[α, v̂ − B]` and `s·g(v̂ + B) < −|δ|/(v̂ + B)` (a sign change of `Q`),
//! `B` the literal certificate's bracket, so the first root past the origin's lies within
//! `B·R` of the reported point. Its face is the side the ray came from: outside (front)
//! for `s > 0`, inside (back) for `s < 0`.
//!
//! A ray none of this proves escalates (or goes on to the t* lemma, [`super::on_surface`]).

use super::certificate::{BRACKET, U32};
use crate::Torus;
use crate::intersect::from_surface::{SurfaceCubic, starts_on_the_surface};
use glam::DVec3;

/// The f64 setup's error on each of `a3, a2, a1, δ`, relative to the size of what forms
/// them (module docs).
const F64_REL: f64 = 1e-12;

/// What the cubic certificate proved about a ray from a surface point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Verdict {
    /// The first root past the origin's, in range, is within [`BRACKET`]·R of `u` (the
    /// foot-point frame of [`crate::intersect::reduce::foot_line`]), at the ray's `t`.
    Hit { t: f32, u: f32, front_face: bool },
    /// No root in range but the origin's own.
    Miss,
    /// Not proved.
    Escalate,
}

/// `x` rounded up to f32 (for non-negative bounds); `+∞` past f32's range.
fn up(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) < x { next_up(y) } else { y }
}

/// `x` rounded down to f32.
fn down(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) > x { -next_up(-y) } else { y }
}

/// The next f32 above `y` (finite `y`).
fn next_up(y: f32) -> f32 {
    if y == 0.0 {
        return f32::from_bits(1);
    }
    let bits = y.to_bits();
    f32::from_bits(if y > 0.0 { bits + 1 } else { bits - 1 })
}

/// 1 + 2⁻²⁰: inflates a bound formed in f32 past its own roundings (a handful, 2⁻²⁴ each).
const INFLATE: f32 = 1.0 + 1.0 / 1_048_576.0;

/// The cubic in f32 with its bounds.
#[derive(Debug, Clone, Copy)]
struct Cubic32 {
    a3: f32,
    a2: f32,
    a1: f32,
    /// Bounds on the true coefficients' distance from `a3, a2, a1`.
    e3: f32,
    e2: f32,
    e1: f32,
    /// The sign of `Q` just past the origin's root.
    s: f32,
    /// The band holding `g`'s inflection point.
    w_lo: f32,
    w_hi: f32,
}

/// Bounds at one point `v ≥ 0` of `f = s·g − d`.
#[derive(Debug, Clone, Copy)]
struct At {
    /// A lower bound of `f` (what is proved when `> 0`).
    f_lo: f32,
    /// Bounds of `f′ = s·g′`.
    slope_lo: f32,
    slope_hi: f32,
}

impl Cubic32 {
    /// `s·g̃(v)` and a bound on its distance from `s·g(v)`.
    fn value(&self, v: f32) -> (f32, f32) {
        let g = ((v + self.a3) * v + self.a2) * v + self.a1;
        let size = ((v + self.a3.abs()) * v + self.a2.abs()) * v + self.a1.abs();
        let err = (size * (8.0 * U32) as f32 + (self.e3 * v + self.e2) * v + self.e1) * INFLATE
            + f32::MIN_POSITIVE;
        (self.s * g, err)
    }

    fn at(&self, v: f32, d: f32) -> At {
        let (sg, err) = self.value(v);
        let slope = (3.0 * v + 2.0 * self.a3) * v + self.a2;
        let size = (3.0 * v + 2.0 * self.a3.abs()) * v + self.a2.abs();
        let slope_err =
            (size * (8.0 * U32) as f32 + 2.0 * self.e3 * v + self.e2) * INFLATE + f32::MIN_POSITIVE;
        let s_slope = self.s * slope;
        At {
            f_lo: sg - err - d,
            slope_lo: s_slope - slope_err,
            slope_hi: s_slope + slope_err,
        }
    }

    /// Proved: `s·g(v) < −d` at `v`.
    fn below(&self, v: f32, d: f32) -> bool {
        let (sg, err) = self.value(v);
        sg + err + d < 0.0
    }

    /// The critical points of `g̃` (roots of `3v² + 2a3 v + a2`), ascending; NaN where
    /// there are fewer than two. Approximate: any point is sound where one is used.
    fn critical(&self) -> [f32; 2] {
        let disc = self.a3 * self.a3 - 3.0 * self.a2;
        if disc.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return [f32::NAN; 2];
        }
        let q = -(self.a3 + disc.sqrt().copysign(self.a3));
        let (x, y) = (q / 3.0, if q != 0.0 { self.a2 / q } else { 0.0 });
        [x.min(y), x.max(y)]
    }

    /// Proved: `f = s·g − d > 0` on `[x, y]` (`0 < x ≤ y`, finite).
    fn positive(&self, x: f32, y: f32, d: f32) -> bool {
        let (at_x, at_y) = (self.at(x, d), self.at(y, d));
        if !(at_x.f_lo > 0.0 && at_y.f_lo > 0.0) {
            return false;
        }
        // s·g is convex right of w_hi for s > 0, left of w_lo for s < 0.
        let (lo, hi) = (self.w_lo, self.w_hi);
        let mut ok = true;
        // Left of w_lo.
        if x <= lo {
            let b = y.min(lo);
            ok &= self.piece(x, b, &at_x, d, self.s < 0.0);
        }
        // The band.
        let (a, b) = (x.max(lo), y.min(hi));
        if ok && a <= b {
            let (fa, fb) = (self.at(a, d).f_lo, self.at(b, d).f_lo);
            let span = b - a;
            let sag = (hi - lo) * span * span * INFLATE;
            ok &= fa > 0.0 && fb > 0.0 && fa.min(fb) > sag;
        }
        // Right of w_hi.
        if ok && y >= hi {
            let a = x.max(hi);
            ok &= self.piece(a, y, &self.at(a, d), d, self.s > 0.0);
        }
        ok
    }

    /// Proved: `f > 0` on `[a, b]`, a piece where `f` is convex (`convex`) or concave.
    fn piece(&self, a: f32, b: f32, at_a: &At, d: f32, convex: bool) -> bool {
        let at_b = self.at(b, d);
        if !(at_a.f_lo > 0.0 && at_b.f_lo > 0.0) {
            return false;
        }
        if !convex || tangents(a, b, at_a, &at_b) {
            return true;
        }
        // Split at f's lowest point (g's critical point inside the piece).
        self.critical()
            .into_iter()
            .find(|&m| m > a && m < b)
            .is_some_and(|m| {
                let at_m = self.at(m, d);
                tangents(a, m, at_a, &at_m) && tangents(m, b, &at_m, &at_b)
            })
    }

    /// The smallest `v` in `(x, y]` where `s·g̃` stops being positive (`s·g̃(x) > 0`), by
    /// pieces between `g̃`'s critical points; `None` if there is none.
    fn first_root(&self, x: f32, y: f32) -> Option<f32> {
        let [c0, c1] = self.critical();
        let mut from = x;
        for end in [c0, c1, y] {
            if !(end > from && end <= y) {
                continue;
            }
            if self.value(end).0 <= 0.0 {
                return Some(self.bisect(from, end));
            }
            from = end;
        }
        None
    }

    /// The sign change of `s·g̃` in `(x, y]` (positive at `x`, not at `y`): safeguarded
    /// Newton inside the shrinking bracket.
    fn bisect(&self, mut x: f32, mut y: f32) -> f32 {
        let mut v = y;
        for _ in 0..60 {
            let sg = self.value(v).0;
            if sg > 0.0 {
                x = v;
            } else {
                y = v;
            }
            let slope = self.s * ((3.0 * v + 2.0 * self.a3) * v + self.a2);
            let newton = v - sg / slope;
            let next = if newton > x && newton < y {
                newton
            } else {
                0.5 * (x + y)
            };
            if next == v || !(next > x && next < y) {
                break;
            }
            v = next;
        }
        y
    }
}

/// Proved: `f > 0` on the convex piece `[α, β]` from bounds at its ends: the tangents at
/// `α` and `β` lie below `f`, and their zeros do not overlap (the literal certificate's
/// `convex_positive`, with the same reasoning on rounding).
fn tangents(alpha: f32, beta: f32, at_a: &At, at_b: &At) -> bool {
    if !(at_a.f_lo > 0.0 && at_b.f_lo > 0.0) {
        return false;
    }
    let (sa, sb) = (at_a.slope_lo, at_b.slope_hi);
    if sa >= 0.0 || sb <= 0.0 {
        return true;
    }
    let lhs = at_a.f_lo * sb + at_b.f_lo * -sa;
    let rhs = -sa * sb * (beta - alpha) * INFLATE;
    lhs > rhs
}

/// The cubic certificate on a torus-frame line `o + t·d` from a surface point over
/// `t ∈ [t_min, t_max]` (module docs).
pub(crate) fn prove(torus: &Torus, (o, d): (DVec3, DVec3), t_min: f64, t_max: f64) -> Verdict {
    let tube = torus.tube();
    let len_sq = d.length_squared();
    if !starts_on_the_surface(tube, o) || len_sq.is_nan() || len_sq <= 0.0 {
        return Verdict::Escalate;
    }
    let g = SurfaceCubic::new(tube, (o, d));
    let [c2, c1, c0] = g.c;
    let p = g.own;
    // What forms a3, a2, a1 and δ: each of them at most a few of these.
    let size = 1.0 + p.abs().powi(4) + c2.abs() * p * p + c1.abs() * p.abs() + c0.abs();
    let delta_err = F64_REL * 8.0 * size;
    let (a3, a2, a1) = (g.a3, g.a2, g.a1);
    if !(size.is_finite() && a3.is_finite() && a2.is_finite() && a1.is_finite()) {
        return Verdict::Escalate;
    }
    // 1. The origin's zone.
    let margin = 1.0 + 1e-12;
    let big_a = a1.abs() - delta_err;
    let d0 = (g.residual.abs() + delta_err) * margin;
    if !(big_a > 0.0 && d0.is_finite()) {
        return Verdict::Escalate;
    }
    let v_s = 4.0 * d0 / big_a;
    let (b2, b3) = (a2.abs() + delta_err, a3.abs() + delta_err);
    let slope_drift = (2.0 * b2 * v_s + 3.0 * b3 * v_s * v_s + 4.0 * v_s.powi(3)) * margin;
    let value_drift = (b2 * v_s * v_s + b3 * v_s.powi(3) + v_s.powi(4) + d0) * margin;
    if !(slope_drift < big_a && value_drift < big_a * v_s) {
        return Verdict::Escalate;
    }
    let s: f32 = if a1 > 0.0 { 1.0 } else { -1.0 };
    // 3. The range in v (from p).
    let v_min = t_min.max(0.0) * g.v_per_t - g.shift;
    let v_cap = (1.0 + tube.minor_rel) * (1.0 + 1e-9) - p;
    let v_end = t_max * g.v_per_t - g.shift;
    let v_max = v_end.min(v_cap);
    if !(v_min.is_finite() && v_cap.is_finite() && !v_max.is_nan()) {
        return Verdict::Escalate;
    }
    if v_max < v_s.max(v_min) {
        // Nothing in range but (at most) the origin's root.
        return Verdict::Miss;
    }
    let alpha = down(v_s.max(v_min));
    let (hi_up, hi_dn) = (up(v_max), down(v_max));
    if !(alpha > 0.0 && hi_up.is_finite() && alpha <= hi_up) {
        return Verdict::Escalate;
    }
    let coefficient = |a: f64| {
        let r = a as f32;
        (r, up((a - f64::from(r)).abs() + delta_err))
    };
    let ((r3, e3), (r2, e2), (r1, e1)) = (coefficient(a3), coefficient(a2), coefficient(a1));
    let cubic = Cubic32 {
        a3: r3,
        a2: r2,
        a1: r1,
        e3,
        e2,
        e1,
        s,
        w_lo: down((-a3 - f64::from(e3)) / 3.0),
        w_hi: up((-a3 + f64::from(e3)) / 3.0),
    };
    let dist = up(d0 / f64::from(alpha));
    let verdict = match cubic.first_root(alpha, hi_up) {
        None => cubic.positive(alpha, hi_up, dist).then_some(Verdict::Miss),
        Some(root) => {
            let bracket = BRACKET as f32;
            let left = (root - bracket).max(alpha);
            let right = (root + bracket).min(hi_dn);
            let sign_change = right > left
                && cubic.below(right, up(d0 / f64::from(right)))
                && cubic.positive(alpha, left, dist);
            let t = (f64::from(root) + g.shift) / g.v_per_t;
            let (t32, u) = (t as f32, (p + f64::from(root)) as f32);
            (sign_change && t32.is_finite() && u.is_finite()).then_some(Verdict::Hit {
                t: t32,
                u,
                front_face: s > 0.0,
            })
        }
    };
    verdict.unwrap_or(Verdict::Escalate)
}
