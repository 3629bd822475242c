//! The exact intersection of a ray that starts **on the surface** ([`crate::Ray::from_surface`]):
//! the origin's own root divided out.
//!
//! In the scaled foot-point frame the line meets the torus where the depressed quartic
//! `Q(u) = u⁴ + c2 u² + c1 u + c0` vanishes, and the origin sits at `u₀ = (o·d̂)/R`. In
//! `v = u − u₀` (so `t = v·R/|d|`), `Q(u₀ + v) = v⁴ + a3 v³ + a2 v² + a1 v + Q(u₀)` with
//!
//! `a3 = 4u₀`, `a2 = 6u₀² + c2`, `a1 = Q′(u₀) = (4u₀² + 2c2)·u₀ + c1`.
//!
//! An origin on the surface has `Q(u₀) = 0`, so `v = 0` is a root (the origin's) and the
//! others are the roots of the cubic `g(v) = v³ + a3 v² + a2 v + a1`.
//!
//! **Solved from the surface point.** The stored origin is the surface point the caller
//! meant, rounded (to f32, say): off the surface by its rounding δ along the normal. That
//! offset is not information: solved literally, a ray leaving the saddle (the inner half
//! of the tube, nearly along the ring) at an angle α above the tangent plane rises only
//! α²/(2κ) before the surface comes back to meet it at s ≈ 2α/κ (κ the surface's
//! curvature along the ray), which is below an f32 origin's δ at α ≈ 10⁻⁴, so the literal
//! ray starts inside the tube and the re-hit is lost. The origin is therefore first
//! moved onto the surface in f64 ([`Tube::nearest_surface_point`], a few ulps of |o| off
//! it), the line is formed from that point, and `Q(u₀)`, now f64 rounding, is dropped:
//! the origin's root is removed exactly, no rounding can turn the origin into a hit, and
//! a re-hit is found wherever f64 separates it from `v = 0`. Whether it exists depends on
//! α and κ, which the rounding of the origin along the normal does not change (moving
//! the point by δ along the surface changes α by about δ/r only). `t` is measured from
//! the moved origin, within δ/|d| of the literal one. The nearest root of `g` in `(0,
//! hi]`, in range, is the hit (docs/math.md §9).

use super::reduce::{FootLine, coefficients, foot_line, normal};
use crate::geometry::Tube;
use crate::num::{Sc, V3, sc};
use crate::quartic::eval;
use glam::DVec3;

/// The nearest crossing with `t ∈ [t_min, t_max]`, `t > 0`, of the torus-frame line
/// `o + t·d` whose origin `o` lies on the surface, and the unit outward normal there.
pub(crate) fn intersect_from_surface(
    tube: &Tube,
    line: (DVec3, DVec3),
    (t_min, t_max): (f64, f64),
) -> Option<(f64, DVec3)> {
    let g = SurfaceCubic::new(tube, line);
    let (lo, hi) = g.v_range(t_min, t_max);
    let v = nearest_cubic_root(g.a3, g.a2, g.a1, lo, hi)?;
    Some((g.t_at(v), g.normal(tube, v)))
}

/// The cubic `g(v) = v³ + a3 v² + a2 v + a1` left once the origin's root is divided out of
/// the quartic of a line from a surface point (module docs), with what maps its roots `v`
/// back to the ray.
pub(crate) struct SurfaceCubic {
    /// The foot-point line (scaled by 1/R) through the origin moved onto the surface.
    pub(crate) line: FootLine<Sc>,
    /// The origin's own root `u₀` (v = 0).
    pub(crate) own: f64,
    pub(crate) a3: f64,
    pub(crate) a2: f64,
    pub(crate) a1: f64,
    /// The quartic's coefficients `[c2, c1, c0]`.
    pub(crate) c: [f64; 3],
    /// `v` per unit `t`: `|d|/R`.
    pub(crate) v_per_t: f64,
}

impl SurfaceCubic {
    /// The cubic of the torus-frame line `o + t·d` whose origin lies on the surface: `o` is
    /// moved onto the surface first (module docs); an origin with no unique nearest
    /// surface point (the axis, the core circle) is taken as it is.
    pub(crate) fn new(tube: &Tube, (o, d): (DVec3, DVec3)) -> SurfaceCubic {
        let o = tube.nearest_surface_point(o).unwrap_or(o);
        let inv_major = sc(tube.inv_major);
        let line = foot_line(V3::from_dvec3(o), V3::from_dvec3(d), inv_major);
        let [c2, c1, c0] = coefficients(line.p, line.dh, sc(tube.minor_rel));
        let (c2, c1, c0) = (c2.v, c1.v, c0.v);
        let own = line.s.v * tube.inv_major;
        // Q(u₀) is f64 rounding on a surface point: dropped; Q′(u₀) is the cubic's constant.
        let (_residual, a1) = eval(&[1.0, 0.0, c2, c1, c0], own);
        SurfaceCubic {
            line,
            own,
            a3: 4.0 * own,
            a2: 6.0 * own * own + c2,
            a1,
            c: [c2, c1, c0],
            v_per_t: tube.inv_major / line.inv_len.v,
        }
    }

    /// The ray's range in `v`, its lower end at least 0 (only crossings past the origin
    /// count; [`nearest_cubic_root`] takes `(0, hi]` open at 0).
    pub(crate) fn v_range(&self, t_min: f64, t_max: f64) -> (f64, f64) {
        let lo = (t_min.max(0.0) * self.v_per_t).max(0.0);
        (lo, t_max * self.v_per_t)
    }

    /// The ray parameter of the root `v`.
    pub(crate) fn t_at(&self, v: f64) -> f64 {
        v / self.v_per_t
    }

    /// The unit outward normal (torus frame) at the root `v`.
    pub(crate) fn normal(&self, tube: &Tube, v: f64) -> DVec3 {
        let u = sc(self.own + v);
        normal(self.line.p, self.line.dh, u, sc(tube.k)).to_dvec3()
    }
}

/// Whether a ray marked as starting on the surface really does: its torus-frame origin `o`
/// within [`OWN_ROOT_REACH`]·R of the surface (`|√((ρ − R)² + y²) − r|`, in units of R).
/// Farther, there is no root of its own to divide out (an origin 10⁶⁹ away, say, whose
/// dropped constant would leave the mirror image of the origin as a "crossing"): such a
/// ray is answered as a literal one. NaN is not on the surface.
pub(crate) fn starts_on_the_surface(tube: &Tube, o: DVec3) -> bool {
    let x = o * tube.inv_major;
    let rho = x.x.hypot(x.z);
    let off = ((rho - 1.0).hypot(x.y) - tube.minor_rel).abs();
    off <= OWN_ROOT_REACH
}

/// How far from the surface (in units of R) an origin marked as on it may lie and still be
/// moved onto it: an origin rounded to f32 at up to 10⁴·R from the world origin is off the
/// surface by about 10⁻³·R; beyond this reach it is not a rounded surface point.
pub(crate) const OWN_ROOT_REACH: f64 = 1e-2;

/// `g(v) = v³ + a v² + b v + c` and `g′(v)`.
#[inline]
fn cubic(a: f64, b: f64, c: f64, v: f64) -> (f64, f64) {
    (((v + a) * v + b) * v + c, (3.0 * v + 2.0 * a) * v + b)
}

/// A bound on `g`'s rounding at `v`: a few ulps of the sum of its terms' sizes.
#[inline]
fn rounding(a: f64, b: f64, c: f64, v: f64) -> f64 {
    let x = v.abs();
    8.0 * f64::EPSILON * (((x + a.abs()) * x + b.abs()) * x + c.abs())
}

/// The smallest root of `g(v) = v³ + a v² + b v + c` in `(lo, hi]` (in `[lo, hi]` for
/// `lo > 0`), or `None`.
///
/// `g` is monotone between its critical points (the roots of `3v² + 2av + b`), so each
/// piece of `(lo, hi]` between them holds at most one simple root, found by a sign change
/// and safeguarded Newton; a double root (a tangent) sits at a critical point whose `|g|`
/// is within rounding. The pieces are visited in order, so the first root found is the
/// nearest.
pub(crate) fn nearest_cubic_root(a: f64, b: f64, c: f64, lo: f64, hi: f64) -> Option<f64> {
    // NaN ends (a non-finite line) compare false: no root.
    if lo.partial_cmp(&hi).is_none_or(|o| o.is_gt()) {
        return None;
    }
    // Every root has |v| < 1 + max(|a|, |b|, |c|) (Cauchy).
    let bound = 1.0 + a.abs().max(b.abs()).max(c.abs());
    let hi = hi.min(bound);
    if lo > hi {
        return None;
    }
    let mut ends = [lo, hi, hi, hi];
    let mut n = 1;
    for x in critical_points(a, b) {
        if x > lo && x < hi {
            ends[n] = x;
            n += 1;
        }
    }
    ends[n] = hi;
    let open = lo == 0.0;
    let (mut x, mut gx) = (lo, cubic(a, b, c, lo).0);
    if gx == 0.0 && !open {
        return Some(lo);
    }
    for &y in &ends[1..=n] {
        let gy = cubic(a, b, c, y).0;
        if (gx < 0.0 && gy > 0.0) || (gx > 0.0 && gy < 0.0) {
            return Some(bracketed_root(a, b, c, x, y, gx));
        }
        // A double root at a critical point (or a root exactly at a piece's end).
        let at_end = y == hi;
        if gy == 0.0 || (!at_end && gy.abs() <= rounding(a, b, c, y)) {
            return Some(y);
        }
        (x, gx) = (y, gy);
    }
    None
}

/// Every real root of `g(v) = v³ + a v² + b v + c`, ascending, each with whether it is a
/// double root (a tangent, reported once): at most three. The same pieces as
/// [`nearest_cubic_root`] over the whole line `[−B, B]`, `B = 1 + max(|a|, |b|, |c|)`
/// (Cauchy: `g(−B) < 0 < g(B)`): a sign change between consecutive ends is a simple root;
/// a critical point whose `|g|` is within rounding is a double root, after which `g`
/// turns back, so the next piece starts from the sign before it.
pub(crate) fn cubic_roots(a: f64, b: f64, c: f64) -> ([(f64, bool); 3], usize) {
    let mut out = [(0.0, false); 3];
    let mut n = 0;
    let bound = 1.0 + a.abs().max(b.abs()).max(c.abs());
    // Non-finite coefficients (a non-finite line): no root.
    if !(a.is_finite() && b.is_finite() && c.is_finite() && bound.is_finite()) {
        return (out, 0);
    }
    let (mut x, mut negative) = (-bound, true);
    let crit = critical_points(a, b);
    for (i, y) in crit.into_iter().chain([bound]).enumerate() {
        // NaN: fewer than two critical points.
        if !(y > x && y <= bound) {
            continue;
        }
        let gy = cubic(a, b, c, y).0;
        let at_end = i == 2;
        if !at_end && gy.abs() <= rounding(a, b, c, y) {
            // A double root at the critical point; g turns back there.
            if n < 3 {
                out[n] = (y, true);
                n += 1;
            }
            x = y;
            continue;
        }
        let below = gy < 0.0;
        if below != negative && n < 3 {
            // g(x) is nonzero (the Cauchy end, or a critical point beyond rounding) or a
            // double root already reported: its side is `negative` either way.
            let side = if negative { -1.0 } else { 1.0 };
            out[n] = (bracketed_root(a, b, c, x, y, side), false);
            n += 1;
        }
        (x, negative) = (y, below);
    }
    (out, n)
}

/// The critical points of `g` (roots of `3v² + 2av + b`), ascending; NaN where there are
/// fewer than two.
fn critical_points(a: f64, b: f64) -> [f64; 2] {
    let disc = a * a - 3.0 * b;
    if disc.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return [f64::NAN; 2];
    }
    // (−a ∓ √disc)/3 without cancellation: q/3 and b/q, whose product is b/3.
    let q = -(a + disc.sqrt().copysign(a));
    let (x, y) = (q / 3.0, if q != 0.0 { b / q } else { 0.0 });
    [x.min(y), x.max(y)]
}

/// The root of `g` in `[x, y]`, where `g` is monotone and changes sign (`gx` = g(x), or
/// any number of its sign):
/// Newton's steps inside the shrinking bracket, a bisection where a step would leave it.
fn bracketed_root(a: f64, b: f64, c: f64, mut x: f64, mut y: f64, gx: f64) -> f64 {
    let rising = gx < 0.0;
    let mut v = 0.5 * (x + y);
    for _ in 0..200 {
        let (g, dg) = cubic(a, b, c, v);
        if g == 0.0 {
            return v;
        }
        if (g < 0.0) == rising {
            x = v;
        } else {
            y = v;
        }
        let newton = v - g / dg;
        let next = if newton > x && newton < y {
            newton
        } else {
            0.5 * (x + y)
        };
        if (next - v).abs() <= 2.0 * f64::EPSILON * next.abs()
            || y - x <= 2.0 * f64::EPSILON * y.abs().max(x.abs())
        {
            return next;
        }
        v = next;
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_roots_in_order_and_range() {
        // (v − 1)(v − 2)(v − 3) = v³ − 6v² + 11v − 6: g's rounding near a root is about
        // 60ε against |g′| ≥ 1, so each root to 1e-14.
        let r = |lo, hi| nearest_cubic_root(-6.0, 11.0, -6.0, lo, hi);
        assert!((r(0.0, 10.0).unwrap() - 1.0).abs() < 1e-14);
        assert!((r(1.5, 10.0).unwrap() - 2.0).abs() < 1e-14);
        assert!((r(2.5, 10.0).unwrap() - 3.0).abs() < 1e-14);
        assert_eq!(r(3.5, 10.0), None);
        assert_eq!(r(0.0, 0.5), None);
        // A double root (tangent): (v − 1)²(v + 2) = v³ − 3v + 2.
        assert!((nearest_cubic_root(0.0, -3.0, 2.0, 0.0, 5.0).unwrap() - 1.0).abs() < 1e-7);
        // A root at 0 itself (a1 = 0: the origin tangent) is the origin's, not a hit.
        assert_eq!(nearest_cubic_root(0.0, 1.0, 0.0, 0.0, 5.0), None);
        // Root ratios of 10⁸: (v − 1e-8)(v − 1)(v − 2).
        let (p, q, s) = (1e-8, 1.0, 2.0);
        let (a, b, c) = (-(p + q + s), p * q + q * s + p * s, -(p * q * s));
        assert!((nearest_cubic_root(a, b, c, 0.0, 10.0).unwrap() - 1e-8).abs() < 1e-20);
    }
}
