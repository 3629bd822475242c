//! The certified f32 path for rays from a surface point ([`crate::Ray::from_surface`]) on
//! what is left once the origin's root is divided out: the cubic of
//! [`crate::intersect::from_surface`], proved in f32 (docs/math.md §9, "The certified
//! cubic").
//!
//! **What is proved.** In the foot-point frame (u in units of R along the unit direction)
//! the line's quartic is `Q(u) = u⁴ + c2 u² + c1 u + c0`, formed (as on the f64 path,
//! [`SurfaceCubic`]) through the origin moved onto the surface, whose own root is `p = u₀`.
//! Exactly,
//!
//! `Q(p + v) − Q(p) = v·g(v)`, `g(v) = v³ + a3 v² + a2 v + a1`.
//!
//! The on-surface rule (docs/math.md §9) takes the origin to be that surface point: the
//! answer is the smallest root of `g` with `v > 0` in the range, which is what the f64
//! path computes. The certificate proves exactly that statement, so it agrees with the
//! f64 path by construction; the dropped `δ = Q(p)` is f64 rounding, which moves a root
//! by the f64 path's documented `|δ|/|v·g′(v)|`, not an error of this proof.
//!
//! **The bounds.** f64 forms `a3, a2, a1` within `Δ = 8·10⁻¹²·S`, `S = 1 + p⁴ +
//! |c2|p² + |c1||p| + |c0|` (a few dozen f64 roundings of 2⁻⁵³·S each, and the line's own f64
//! error, about 2⁻⁵³·(1 + r/R) per coordinate through polynomials of degree 4 with terms
//! below 16, stay far below that). They are rounded to f32 once; each true coefficient is
//! within `e_i = |a_i − ã_i| + Δ` of its f32 `ã_i` (the difference is exact in f64). `g`
//! is evaluated in f32 by Horner at f32 points `v ≥ 0`, whose rounding is at most
//! `γ₆·Σ|ã_i|·v^i` (Higham, γ₆ < 6.01·2⁻²⁴), so `|g̃(v) − g(v)| ≤ 8·2⁻²⁴·Σ|ã_i|v^i + e3 v² +
//! e2 v + e1`, formed in f32 and inflated by `1 + 2⁻²⁰` for its own roundings; `g′`
//! likewise (`γ₄`, `2e3 v + e2`). A test `fl(fl(x − y) − z) > 0` with `y, z` f32 numbers
//! proves `x − y > z` (rounding to nearest is monotone), so each f32 test decides exactly
//! what it states.
//!
//! **The pieces.** `g″(v) = 6v + 2a3` is linear: with `a3` within `e3` of `ã3`, `g` is
//! concave left of `w_lo = −(a3 + e3)/3` and convex right of `w_hi = −(a3 − e3)/3`. With
//! `s` the sign of `a1` (the side of the surface the ray leaves into: outside for `s > 0`,
//! into the tube for `s < 0`), `f = s·g` is proved positive on `[x, y]`:
//! - on a piece where `f` is concave, by its values at both ends (it lies above its chord);
//! - on a piece where `f` is convex, by the tangents at both ends (slopes bounded as
//!   above): they lie below `f`, and their zeros do not overlap; where one pair is not
//!   enough, the piece is split at `g̃`'s critical point (`f`'s lowest point) and each half
//!   proved so (the literal certificate's `convex_positive`);
//! - on the band `[w_lo, w_hi]`, where `|g″| ≤ 6(w_hi − w_lo)`, by both ends clearing the
//!   chord's sag `(w_hi − w_lo)·(y − x)²`.
//!
//! **The verdict.** `|a1| > 2Δ` (else `v = 0` is not a simple root: escalate). The range
//! in `v` is `[v_min, v_max]`, `v_min = max(0, v(t_min))` (rounded down to f32) and
//! `v_max = min(v(t_max), (1 + r/R)(1 + 10⁻⁹) − p)` (every root lies in the bounding
//! sphere). A **miss** is `f > 0` on `[v_min, v_max]` (rounded up). A **hit** at the f32
//! root `v̂` of `g̃` (the first sign change of `s·g̃`, by pieces between `g̃`'s critical
//! points and safeguarded Newton) is `f > 0` on `[v_min, v̂ − B]` and `f(v̂ + B) < 0`
//! (`v̂ + B` clipped to the range's end rounded down), `B` = [`BRACKET`]: the first root
//! past the origin's lies within `B·R` of the reported point, as for a literal ray. Its
//! face is the side the ray came from: outside (front) for `s > 0`, inside for `s < 0`.
//!
//! **Handing over.** Near a far, near-tangent crossing `g` loses digits to cancellation
//! (`|v| ≈ 1`, terms of size 10 summing to 10⁻⁴), where the literal certificate's signed
//! distance does not. Where the hit or miss is not proved, `f > 0` on `[v_min, m]`,
//! `m` halfway to the candidate root (or to the range's end), still proves that no root
//! past the origin's lies before `t(m)` ([`Verdict::Clear`]), and the literal certificate
//! proves the literal ray over `[t(m), t_max]` (`t(m)` rounded down; the stretch it adds
//! back is inside the proved one). Only for a ray that leaves into the outside: the
//! literal line, off the surface point by the origin's rounding, may be outside where a
//! ray into the tube is inside. That replaces the t* lemma's start, which for a
//! grazing ray comes too early for f32 to see `F > 0`. A ray none of this proves
//! escalates, or goes on to the t* lemma ([`super::on_surface`]).

use super::certificate::{BRACKET, U32};
use crate::Torus;
use crate::intersect::from_surface::{SurfaceCubic, starts_on_the_surface};
use crate::num::round::{down, up};
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
    /// No root but the origin's before this `t` (f32, at least the range's start): the
    /// literal certificate may prove the rest of the range.
    Clear(f32),
    /// Not proved.
    Escalate,
}

/// 1 + 2⁻²⁰: inflates a bound formed in f32 past its own roundings (a handful, 2⁻²⁴ each).
const INFLATE: f32 = 1.0 + 1.0 / 1_048_576.0;

/// The cubic in f32 with its bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Cubic32 {
    a3: f32,
    a2: f32,
    a1: f32,
    /// Bounds on the true coefficients' distance from `a3, a2, a1`.
    e3: f32,
    e2: f32,
    e1: f32,
    /// The sign of `a1`: of `Q` just past the origin's root.
    s: f32,
    /// The band holding `g`'s inflection point.
    w_lo: f32,
    w_hi: f32,
}

/// Bounds at one point `v ≥ 0` of `f = s·g − d` (`d` a margin `f` must clear; 0 in
/// [`prove`]).
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

    /// Proved: `f = s·g − d > 0` on `[x, y]` (`0 ≤ x ≤ y`, finite).
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

/// The cubic's f64 setup for one ray, rounded for the f32 proof: what [`prove`] forms in
/// f64 before its f32 steps, and what the GPU kernel's `TorusSurfaceRay` carries
/// ([`Prepared::words`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Setup {
    /// The range ends before any root past the origin's: a miss, proved in f64.
    Miss,
    /// Nothing to prove from (not a surface point, `v = 0` not a simple root, or a value
    /// not finite).
    Escalate,
    /// The cubic and its range, for [`Prepared::decide`].
    Cubic(Prepared),
}

/// The rounded cubic and its range in `v`, for the f32 proof.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Prepared {
    cubic: Cubic32,
    /// The range's start rounded down, and its end rounded up and down.
    alpha: f32,
    hi_up: f32,
    hi_dn: f32,
    /// The origin's own root `u₀` (the foot-point frame).
    own: f64,
    /// `v` per unit `t`: `|d|/R`.
    v_per_t: f64,
}

/// The cubic's setup on a torus-frame line `o + t·d` from a surface point over `t ∈
/// [t_min, t_max]` (module docs, "The bounds" and "The verdict").
pub(crate) fn setup(torus: &Torus, (o, d): (DVec3, DVec3), t_min: f64, t_max: f64) -> Setup {
    let tube = torus.tube();
    let len_sq = d.length_squared();
    if !starts_on_the_surface(tube, o) || len_sq.is_nan() || len_sq <= 0.0 {
        return Setup::Escalate;
    }
    let g = SurfaceCubic::new(tube, (o, d));
    let [c2, c1, c0] = g.c;
    let p = g.own;
    // What forms a3, a2 and a1: each of them at most a few of these terms.
    let size = 1.0 + p.abs().powi(4) + c2.abs() * p * p + c1.abs() * p.abs() + c0.abs();
    let delta_err = F64_REL * 8.0 * size;
    let (a3, a2, a1) = (g.a3, g.a2, g.a1);
    if !(size.is_finite() && a3.is_finite() && a2.is_finite() && a1.is_finite()) {
        return Setup::Escalate;
    }
    // g(0) = a1 must be told from 0: then v = 0 is a simple root of v·g, the origin's.
    if a1.abs() <= 2.0 * delta_err {
        return Setup::Escalate;
    }
    let s: f32 = if a1 > 0.0 { 1.0 } else { -1.0 };
    // The range in v (from p), past the origin's root: (0, v_max] ∩ [v_min, v_max].
    let v_min = (t_min.max(0.0) * g.v_per_t).max(0.0);
    let v_cap = (1.0 + tube.minor_rel) * (1.0 + 1e-9) - p;
    let v_end = t_max * g.v_per_t;
    let v_max = v_end.min(v_cap);
    if !(v_min.is_finite() && v_cap.is_finite()) || v_max.is_nan() {
        return Setup::Escalate;
    }
    if v_max < v_min {
        return Setup::Miss;
    }
    let alpha = down(v_min);
    let (hi_up, hi_dn) = (up(v_max), down(v_max));
    if !(alpha >= 0.0 && hi_up.is_finite() && alpha <= hi_up) {
        return Setup::Escalate;
    }
    let coefficient = |a: f64| {
        let r = a as f32;
        (r, up((a - f64::from(r)).abs() + delta_err))
    };
    let ((r3, e3), (r2, e2), (r1, e1)) = (coefficient(a3), coefficient(a2), coefficient(a1));
    Setup::Cubic(Prepared {
        cubic: Cubic32 {
            a3: r3,
            a2: r2,
            a1: r1,
            e3,
            e2,
            e1,
            s,
            w_lo: down((-a3 - f64::from(e3)) / 3.0),
            w_hi: up((-a3 + f64::from(e3)) / 3.0),
        },
        alpha,
        hi_up,
        hi_dn,
        own: p,
        v_per_t: g.v_per_t,
    })
}

/// The cubic certificate on a torus-frame line `o + t·d` from a surface point over
/// `t ∈ [t_min, t_max]` (module docs).
pub(crate) fn prove(torus: &Torus, line: (DVec3, DVec3), t_min: f64, t_max: f64) -> Verdict {
    match setup(torus, line, t_min, t_max) {
        Setup::Miss => Verdict::Miss,
        Setup::Escalate => Verdict::Escalate,
        Setup::Cubic(prepared) => prepared.decide(t_min, t_max),
    }
}

impl Prepared {
    /// The proof over the range of [`setup`] (`t_min`, `t_max` as given to it).
    fn decide(&self, t_min: f64, t_max: f64) -> Verdict {
        let Prepared {
            cubic,
            alpha,
            hi_up,
            hi_dn,
            own: p,
            v_per_t,
        } = *self;
        let t_of = |v: f32| f64::from(v) / v_per_t;
        let first = cubic.first_root(alpha, hi_up);
        let verdict = match first {
            None => cubic.positive(alpha, hi_up, 0.0).then_some(Verdict::Miss),
            Some(root) => {
                let bracket = BRACKET as f32;
                let left = (root - bracket).max(alpha);
                let right = (root + bracket).min(hi_dn);
                let sign_change =
                    right > left && cubic.below(right, 0.0) && cubic.positive(alpha, left, 0.0);
                // Within the range as the ray states it (the ends were rounded to f32 in v).
                let t32 = (t_of(root).max(t_min).min(t_max)) as f32;
                let u = (p + f64::from(root)) as f32;
                (sign_change && t32.is_finite() && u.is_finite()).then_some(Verdict::Hit {
                    t: t32,
                    u,
                    front_face: cubic.s > 0.0,
                })
            }
        };
        verdict.unwrap_or_else(|| {
            // A far crossing the cubic cannot resolve (near-tangent, where g loses digits
            // to cancellation): prove the stretch halfway to it clear, for the literal
            // certificate to go on from.
            let mid = 0.5 * (alpha + first.unwrap_or(hi_up));
            let t_mid = down(t_of(mid));
            // Only out of the tube: the literal ray, off the surface point by the origin's
            // rounding, is inside where this one is (or its certificate escalates) only
            // when both leave into the outside.
            let clear = cubic.s > 0.0
                && mid > alpha
                && f64::from(t_mid) >= t_of(alpha)
                && t_mid >= 0.0
                && cubic.positive(alpha, mid, 0.0);
            if clear {
                Verdict::Clear(t_mid)
            } else {
                Verdict::Escalate
            }
        })
    }

    #[cfg(feature = "gpu")]
    /// The GPU kernel's `TorusSurfaceRay` words but the last row's literal start:
    /// `(a3, a2, a1, s)`, `(e3, e2, e1, u₀)`, `(α, v_max↑, v_max↓, t per v)`, `(w_lo,
    /// w_hi)`. `t per v` is `R/|d|` rounded to f32, whose rounding the kernel bounds.
    pub(crate) fn words(&self) -> [f32; 14] {
        let c = &self.cubic;
        [
            c.a3,
            c.a2,
            c.a1,
            c.s,
            c.e3,
            c.e2,
            c.e1,
            self.own as f32,
            self.alpha,
            self.hi_up,
            self.hi_dn,
            (1.0 / self.v_per_t) as f32,
            c.w_lo,
            c.w_hi,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Ray, intersect};
    use glam::{DVec3, Vec3};

    /// A small deterministic generator (splitmix64) for the adversarial sweep.
    struct Mix(u64);
    impl Mix {
        fn unit(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Rays from surface points (posed tori, ν 1.01…1000, R 10⁻³…10³): grazing 10⁻⁶…10⁻¹
    /// rad above and below the tangent plane (out of and into the tube), and across the
    /// hole or the tube to another surface point. Every verdict the cubic certificate
    /// gives must be the f64 path's answer (a proved miss where f64 finds none, a proved
    /// hit within the bracket of f64's), and it must prove most of them (or the test
    /// would prove nothing).
    #[test]
    fn proved_verdicts_are_the_f64_answers() {
        let mut rng = Mix(26);
        let (mut rays, mut proved, mut hits) = (0, 0, 0);
        for &nu in &[1.01, 1.5, 4.0, 30.0, 300.0, 1000.0] {
            for &major in &[1e-3f32, 1.0, 1e3] {
                let minor = major / nu as f32;
                let axis = Vec3::new(0.3, 1.0, -0.2).normalize();
                let center = Vec3::new(2.0, -1.0, 0.5) * major;
                let torus = Torus::new(center, axis, major, minor).expect("torus");
                let to_world = torus.to_local_rotation_f64().transpose();
                let (big, r) = (f64::from(major), f64::from(minor));
                let point = |theta: f64, phi: f64| {
                    let radial = DVec3::new(phi.cos(), 0.0, phi.sin());
                    let (st, ct) = theta.sin_cos();
                    (
                        radial * (big + r * ct) + DVec3::Y * (r * st),
                        radial * ct + DVec3::Y * st,
                    )
                };
                for k in 0..400 {
                    let tau = std::f64::consts::TAU;
                    let (p, n) = point(rng.unit() * tau, rng.unit() * tau);
                    let d = if k % 4 == 3 {
                        point(rng.unit() * tau, rng.unit() * tau).0 - p
                    } else {
                        let angle = 10f64.powf(-6.0 + 5.0 * rng.unit());
                        let side = if k % 4 == 2 { -1.0 } else { 1.0 };
                        let t1 = n.any_orthonormal_vector();
                        let beta = rng.unit() * tau;
                        let along = t1 * beta.cos() + n.cross(t1) * beta.sin();
                        n * (side * angle.sin()) + along * angle.cos()
                    };
                    let origin = (to_world * p + center.as_dvec3()).as_vec3();
                    let dir = (to_world * d).as_vec3();
                    let t_min = if k % 2 == 0 { 0.0 } else { 1e-4 * minor };
                    let Ok(ray) = Ray::from_surface_with_range(origin, dir, t_min, f32::INFINITY)
                    else {
                        continue;
                    };
                    rays += 1;
                    let line = torus.line_to_local_f64(&ray);
                    let exact = intersect(&torus, &ray);
                    let tol = 2e-4 * (big + r) / f64::from(dir.length());
                    match prove(&torus, line, f64::from(t_min), f64::INFINITY) {
                        Verdict::Escalate => {}
                        Verdict::Clear(from) => {
                            // No crossing but the origin's before `from`.
                            if let Some(exact) = exact {
                                assert!(
                                    f64::from(exact.t - from) >= -tol,
                                    "ν {nu} R {major} k {k}: clear to {from}, hit at {}",
                                    exact.t
                                );
                            }
                        }
                        Verdict::Miss => {
                            proved += 1;
                            assert!(exact.is_none(), "ν {nu} R {major} k {k}: {exact:?}");
                        }
                        Verdict::Hit { t, front_face, .. } => {
                            proved += 1;
                            hits += 1;
                            let exact = exact.expect("a proved hit is the f64 path's hit");
                            assert!(
                                f64::from((t - exact.t).abs()) <= tol,
                                "ν {nu} R {major} k {k}: t {t} vs {}",
                                exact.t
                            );
                            assert_eq!(front_face, exact.front_face, "ν {nu} R {major} k {k}");
                        }
                    }
                }
            }
        }
        assert!(hits > rays / 10, "{hits} hits of {rays}");
        assert!(proved * 10 >= rays * 9, "{proved} proved of {rays}");
    }

    #[test]
    fn rays_into_the_tube_prove_their_exit() {
        let torus = Torus::canonical(4.0, 1.0).expect("torus");
        // From the top of the tube straight down: out through the bottom at t = 2.
        let down = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::NEG_Y).expect("ray");
        let line = torus.line_to_local_f64(&down);
        let Verdict::Hit { t, front_face, .. } = prove(&torus, line, 0.0, f64::INFINITY) else {
            panic!("the exit is proved");
        };
        assert!((t - 2.0).abs() < 1e-3 && !front_face, "{t}");
        // Ending before the exit: a miss.
        assert_eq!(prove(&torus, line, 0.0, 1.5), Verdict::Miss);
        // Along the tangent plane: a1 = 0, not a simple root, so no proof.
        let along = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::X).expect("ray");
        let line = torus.line_to_local_f64(&along);
        assert_eq!(prove(&torus, line, 0.0, f64::INFINITY), Verdict::Escalate);
    }
}
