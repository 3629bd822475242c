//! The line in the torus's frame, by unit arc length from its foot point, and the
//! critical points of its distance to the core circle.

use super::Query;
use super::interval::{bisect, cubic_real_roots};
use glam::DVec3;
use std::ops::ControlFlow;

/// Up to how far from the foot point, in units of R + r, the origin may be for the plain
/// foot point `q − (q·u) u` (error about 1e-16·|q|, a fifth of the ambiguity band there);
/// beyond, [`foot_point`].
const NEAR: f64 = 1e6;

/// How far from the centre, in units of R + r, a line's foot point makes it a far line
/// ([`LineFrame::is_far`]).
pub(super) const FAR: f64 = 1e100;

/// The line in the torus's own terms, parametrized by unit arc length `s` from the foot
/// point: `x(s) − c = p + s u`, `s = s0 + t |d|`.
///
/// With `uh`, `ph` the parts of `u`, `p` perpendicular to the axis, the distance from the
/// axis is `ρ(s)² = A (s − s_m)² + m2`, with `A = |uh|²`, `s_m = −(ph·uh)/A` and
/// `m2 = |ph × uh|²/A` (the closest approach to the axis, exact via the cross product).
pub(super) struct LineFrame {
    pub(super) major: f64,
    pub(super) minor: f64,
    pub(super) axis: DVec3,
    /// The foot point relative to the centre.
    pub(super) p: DVec3,
    /// The unit direction.
    pub(super) u: DVec3,
    /// |d|: t = (s − s0)/|d|.
    pub(super) len: f64,
    /// The s of the ray origin.
    pub(super) s0: f64,
    /// p·u, zero up to rounding; kept so that x(s)·u is exact to rounding.
    pub(super) e: f64,
    /// u·u, one up to rounding.
    pub(super) uu: f64,
    pub(super) a_h: f64,
    pub(super) s_m: f64,
    pub(super) m2: f64,
}

/// s = s0 + t·len, the arc length of parameter t on a line whose origin is at s0 and whose
/// direction has length len; an infinite t stays itself.
pub(super) fn s_of_t(s0: f64, len: f64, t: f64) -> f64 {
    if t.is_infinite() { t } else { s0 + t * len }
}

/// (ρ, y) of the point `p + s u`: its distance from the axis and its height along it,
/// from the point itself.
pub(super) fn meridian(p: DVec3, u: DVec3, axis: DVec3, s: f64) -> (f64, f64) {
    let (y, radial) = across_axis(p + s * u, axis);
    (radial.length(), y)
}

/// A point relative to the centre split along the unit `axis`: its height `y` on the axis
/// and its part across it, `rel − y·axis` (of length ρ, the distance from the axis).
pub(super) fn across_axis(rel: DVec3, axis: DVec3) -> (f64, DVec3) {
    let y = rel.dot(axis);
    (y, rel - axis * y)
}

/// a·b − c·d to about one rounding of the result (Kahan's algorithm with a fused
/// multiply-add), however much the two products cancel.
fn diff_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let w = c * d;
    let err = (-c).mul_add(d, w);
    a.mul_add(b, -w) + err
}

/// a × b, each component to about one rounding of itself.
fn cross(a: DVec3, b: DVec3) -> DVec3 {
    DVec3::new(
        diff_of_products(a.y, b.z, a.z, b.y),
        diff_of_products(a.z, b.x, a.x, b.z),
        diff_of_products(a.x, b.y, a.y, b.x),
    )
}

/// The foot point of the line `q + t d` (the point closest to the origin of q's frame):
/// `d × (q × d) / |d|²`, the part of q perpendicular to d, with d first scaled by a power
/// of two (exactly) to a largest component in [1, 2).
///
/// Removing the along-line part first keeps |p| ≤ |q| and makes every later quantity
/// O(R) for lines near the torus, however far the origin. Both cross products are exact
/// to rounding of their own components, so p is accurate to rounding of |p| itself, not
/// of |q|: the plain `q − (q·u) u` is off by about 1e-16·|q|, which for an origin at
/// 1e200 is 1e184, far more than the torus (issue 36: such a line through the centre
/// came out a miss, or made the oracle's cubic overflow).
pub(super) fn foot_point(q: DVec3, d: DVec3) -> DVec3 {
    let big = d.abs().max_element();
    let k = big.log2().floor().clamp(-1000.0, 1000.0) as i32;
    let d = d * 2f64.powi(-k);
    cross(d, cross(q, d)) / d.length_squared()
}

impl LineFrame {
    pub(super) fn new(query: &Query) -> LineFrame {
        query.check_line();
        let Query {
            center,
            axis,
            major,
            minor,
            o,
            d,
            ..
        } = *query;
        let axis = axis.normalize();
        let len = d.length();
        let u = d / len;
        let q = o - center;
        let s_origin = q.dot(u);
        // The plain foot point is off by about 1e-16·|q|: well inside the ambiguity band
        // up to |q| = NEAR·(R + r), and what every test of the oracle's tangencies was
        // calibrated on; beyond, the exact cross products.
        let p = if s_origin.abs() <= NEAR * (major + minor) {
            q - s_origin * u
        } else {
            foot_point(q, d)
        };
        let uh = u - u.dot(axis) * axis;
        let ph = p - p.dot(axis) * axis;
        let a_h = uh.length_squared();
        let (s_m, m2) = if a_h > 0.0 {
            (-ph.dot(uh) / a_h, ph.cross(uh).length_squared() / a_h)
        } else {
            (0.0, ph.length_squared())
        };
        LineFrame {
            major,
            minor,
            axis,
            p,
            u,
            len,
            s0: s_origin,
            e: p.dot(u),
            uu: u.length_squared(),
            a_h,
            s_m,
            m2,
        }
    }

    /// Whether the line passes so far from the torus (its foot point beyond
    /// [`FAR`]·(R + r) from the centre) that D along it equals the distance from the centre
    /// to rounding: D differs from |x| by at most R, a relative 1e-100. Such lines are
    /// answered by [`LineFrame::far_min_dist`]; the cubic and the squares of the general
    /// method would overflow for them.
    pub(super) fn is_far(&self) -> bool {
        self.p.abs().max_element() > FAR * (self.major + self.minor)
    }

    /// For a line with [`LineFrame::is_far`]: the minimum of D over [lo, hi], as the
    /// distance from the centre of the range's point closest to it (x·u = e + s|u|² = 0
    /// at s ≈ −e), computed without squaring |p| or s.
    pub(super) fn far_min_dist(&self, lo: f64, hi: f64) -> f64 {
        // max/min, not clamp: no panic whatever the ends.
        let s = (-self.e).max(lo).min(hi);
        let big = self.p.abs().max_element();
        let pn = big * (self.p / big).length();
        pn.hypot(s + self.e)
    }

    /// Whether every number the oracle derives from the line is finite: false where the
    /// origin or the direction is so large that they overflow f64 (|o − c| near 1e308).
    pub(super) fn is_finite(&self) -> bool {
        self.p.is_finite() && self.s0.is_finite() && self.u.is_finite() && self.len.is_finite()
    }

    pub(super) fn s_of_t(&self, t: f64) -> f64 {
        s_of_t(self.s0, self.len, t)
    }

    pub(super) fn t_of_s(&self, s: f64) -> f64 {
        (s - self.s0) / self.len
    }

    pub(super) fn s_range(&self, t_min: f64, t_max: f64) -> (f64, f64) {
        assert!(t_min <= t_max, "bad range [{t_min}, {t_max}]");
        (self.s_of_t(t_min), self.s_of_t(t_max))
    }

    /// D(s), from the point itself (not from the ρ² formula), so that it is accurate to
    /// rounding wherever the point is.
    pub(super) fn dist(&self, s: f64) -> f64 {
        let (rho, y) = meridian(self.p, self.u, self.axis, s);
        (rho - self.major).hypot(y)
    }

    /// h(s) = ½ dD²/ds = x·u − R (A (s − s_m))/ρ(s), from D² = |x|² + R² − 2Rρ.
    ///
    /// h′(s) = |u|² − R·A·m2/ρ³, which changes sign only where ρ² = k = (R A m2)^(2/3):
    /// so h is monotone on at most three pieces, split at s_m ± √((k − m2)/A). When the
    /// line crosses the axis (m2 = 0) h jumps at s_m by −2R√A; `side` (−1 from the left,
    /// +1 from the right) picks the one-sided limit there.
    pub(super) fn half_slope(&self, s: f64, side: f64) -> f64 {
        let along = self.e + s * self.uu;
        if self.a_h == 0.0 {
            return along;
        }
        let sigma = s - self.s_m;
        let rho = (self.a_h * sigma * sigma + self.m2).sqrt();
        if rho == 0.0 {
            along - side * self.major * self.a_h.sqrt()
        } else {
            along - self.major * self.a_h * sigma / rho
        }
    }

    /// Where h′ changes sign (and s_m itself), sorted; empty for a line parallel to the axis.
    pub(super) fn breakpoints(&self) -> Vec<f64> {
        if self.a_h == 0.0 || !self.s_m.is_finite() {
            return Vec::new();
        }
        let k = (self.major * self.a_h * self.m2).cbrt().powi(2);
        let off = ((k - self.m2).max(0.0) / self.a_h).sqrt();
        vec![self.s_m - off, self.s_m, self.s_m + off]
    }

    /// Every critical point of D (both kinds) and every breakpoint, within [lo, hi]: those
    /// of [`LineFrame::each_d_candidate`], collected in its order.
    pub(super) fn d_candidates(&self, lo: f64, hi: f64) -> Vec<f64> {
        let mut out = Vec::new();
        let _ = self.each_d_candidate(lo, hi, &mut |s| {
            out.push(s);
            ControlFlow::Continue(())
        });
        out
    }

    /// Hands `visit` every critical point of D (both kinds) and every breakpoint within
    /// [lo, hi], the breakpoints first, then each monotone piece's root from left to right;
    /// stops where `visit` breaks. One candidate at a time, so that a caller who has its
    /// answer after a few (a margin already too low) need not bisect the other pieces.
    ///
    /// Critical points satisfy |x·u| = R|A(s − s_m)|/ρ ≤ R√A ≤ R, so they lie in
    /// |s + p·u| ≤ R; the scan covers a little more.
    pub(super) fn each_d_candidate(
        &self,
        lo: f64,
        hi: f64,
        visit: &mut dyn FnMut(f64) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let mut in_range = |s: f64| {
            if s >= lo && s <= hi {
                visit(s)
            } else {
                ControlFlow::Continue(())
            }
        };
        let reach = 1.01 * self.major + self.e.abs() + f64::MIN_POSITIVE;
        let mut cuts = vec![-reach];
        cuts.extend(self.breakpoints().into_iter().filter(|s| s.abs() < reach));
        cuts.push(reach);
        for &s in &cuts[1..cuts.len() - 1] {
            in_range(s)?;
        }
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if a >= b {
                continue;
            }
            let ha = self.half_slope(a, 1.0);
            let hb = self.half_slope(b, -1.0);
            if ha == 0.0 {
                in_range(a)?;
            }
            if hb == 0.0 {
                in_range(b)?;
            }
            if (ha < 0.0) != (hb < 0.0) && ha != 0.0 && hb != 0.0 {
                // Inside the open piece ρ > 0 (or m2 > 0), so the plain formula is fine.
                if let Some(s) = bisect(&|s| self.half_slope(s, 0.0), a, b, ha) {
                    in_range(s)?;
                }
            }
        }
        ControlFlow::Continue(())
    }

    /// The real roots of F′(s), F the torus quartic written in s:
    /// F = W² − 4R²ρ², W = ρ² + y² + R² − r² = w2 s² + w1 s + w0, ρ² = A s² + 2B s + C.
    pub(super) fn f_prime_roots(&self) -> Vec<f64> {
        let ax = self.axis;
        let (uy, py) = (self.u.dot(ax), self.p.dot(ax));
        let uh = self.u - uy * ax;
        let ph = self.p - py * ax;
        let (a, b, c) = (uh.length_squared(), ph.dot(uh), ph.length_squared());
        let r2 = self.major * self.major;
        let w2 = a + uy * uy;
        let w1 = 2.0 * (b + py * uy);
        let w0 = c + py * py + r2 - self.minor * self.minor;
        // ½F′ = W W′ − 4R²(A s + B), expanded by powers of s.
        let c3 = 2.0 * w2 * w2;
        let c2 = 3.0 * w1 * w2;
        let c1 = w1 * w1 + 2.0 * w0 * w2 - 4.0 * r2 * a;
        let c0 = w0 * w1 - 4.0 * r2 * b;
        cubic_real_roots(c3, c2, c1, c0)
    }
}
