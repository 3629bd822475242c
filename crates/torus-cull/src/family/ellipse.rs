//! The nearest point of a tube's ellipse `(u/a)² + (v/b)² = 1` in the meridian half-plane
//! (`u = ρ − R`, `v = y`), for the family's point queries: of the whole ellipse (a ring or
//! a horn, whose surface is all of it) and of the apple's arc `u ≥ −R` (a spindle).
//!
//! **Whole ellipse:** Eberly's method ("Distance from a point to an ellipse", 2011): in
//! the first quadrant with the longer semi-axis first, the nearest point is the root of a
//! function monotone on a bracket, bisected to adjacent floats.
//!
//! **The apple's arc** (R < a): its nearest point is the nearest of its critical points
//! (the feet of the normals from `q`, on the arc) and its ends, the cusps `(−R, ±v_c)`,
//! `v_c = b·√(1 − (R/a)²)`. The feet are the points `(a² q_u/(t + a²), b² q_v/(t + b²))`
//! at the roots t of `F(t) = (a q_u/(t + a²))² + (b q_v/(t + b²))² − 1` (the Lagrange
//! condition `x − q = t·(x_u/a², x_v/b²)` on the ellipse). With m, M the smaller and larger
//! of a², b², F rises from −1 to +∞ on `(−∞, −M)` (the farthest point), falls from +∞ to
//! −1 on `(−m, ∞)` (the nearest point of the whole ellipse), and is convex between the
//! poles, with 0 or 2 roots there (q inside the evolute: a second local minimum and a
//! maximum). Each is bisected to adjacent floats (the middle interval's minimum first,
//! on F′, which increases there); `q_u = 0` or `q_v = 0` removes a pole, and the feet are
//! then the vertices and the pole's own pair, in closed form. A foot's coordinate whose
//! denominator `t + e²` cancels (below [`POLE`]) is taken from the other one and the
//! ellipse's equation instead (near the pole it is 0/0 to rounding).
//!
//! **Error.** Each foot is on the ellipse to rounding and at its critical t to the last
//! bit; the distance at a critical point is stationary, so a foot off by δ along the
//! ellipse changes it by O(δ²/curvature radius). The stated bound: the distance is within
//! 10⁻¹³·(R + max(a, b) + |q|) of the exact one (tests/oracle/family_points.rs, against a
//! brute-force reference on 10⁶ points: worst 0.82 of it).

use glam::DVec2;

/// The nearest point of the ellipse `(u/a)² + (v/b)² = 1` to `q` (module docs: Eberly's
/// bisection, in the first quadrant with the longer semi-axis first, then mapped back).
pub(super) fn nearest_on_ellipse(a: f64, b: f64, q: DVec2) -> DVec2 {
    let swap = a < b;
    let (e0, e1) = if swap { (b, a) } else { (a, b) };
    let (y0, y1) = if swap {
        (q.y.abs(), q.x.abs())
    } else {
        (q.x.abs(), q.y.abs())
    };
    let (x0, x1) = first_quadrant(e0, e1, y0, y1);
    let (x0, x1) = (
        x0.copysign(if swap { q.y } else { q.x }),
        x1.copysign(if swap { q.x } else { q.y }),
    );
    if swap {
        DVec2::new(x1, x0)
    } else {
        DVec2::new(x0, x1)
    }
}

/// The nearest point of the apple's arc `u ≥ −big` of the ellipse to `q`, `big < a`
/// (module docs): the whole ellipse's nearest point where it lies on the arc, else the
/// nearest of the arc's critical points and its two cusps.
pub(super) fn nearest_on_arc(big: f64, a: f64, b: f64, q: DVec2) -> DVec2 {
    let global = nearest_on_ellipse(a, b, q);
    if global.x >= -big {
        return global;
    }
    let v_c = b * (1.0 - (big / a) * (big / a)).max(0.0).sqrt();
    let mut best = DVec2::new(-big, if q.y >= 0.0 { v_c } else { -v_c });
    let mut best_d = q.distance_squared(best);
    for foot in feet(a, b, q).into_iter().flatten() {
        let d = q.distance_squared(foot);
        if foot.x >= -big && d < best_d {
            (best, best_d) = (foot, d);
        }
    }
    best
}

/// Every foot of a normal from `q` to the ellipse (module docs), at most four; where a
/// coordinate of q is 0, the four vertices and the removed pole's pair (points of the
/// ellipse that are no foot change nothing: the nearest of a set that holds every foot).
fn feet(a: f64, b: f64, q: DVec2) -> [Option<DVec2>; 6] {
    let (aa, bb) = (a * a, b * b);
    let mut out = [None; 6];
    if q.x == 0.0 || q.y == 0.0 {
        out[0] = Some(DVec2::new(a, 0.0));
        out[1] = Some(DVec2::new(-a, 0.0));
        out[2] = Some(DVec2::new(0.0, b));
        out[3] = Some(DVec2::new(0.0, -b));
        // On the u axis (q_v = 0, the pole t = −b² removed): u = a² q_u/(a² − b²).
        let u = aa * q.x / ((a - b) * (a + b));
        if q.y == 0.0 && u.abs() < a {
            let v = b * (1.0 - (u / a) * (u / a)).sqrt();
            out[4] = Some(DVec2::new(u, v));
            out[5] = Some(DVec2::new(u, -v));
        }
        // On the v axis (q_u = 0): v = b² q_v/(b² − a²).
        let v = bb * q.y / ((b - a) * (b + a));
        if q.x == 0.0 && q.y != 0.0 && v.abs() < b {
            let u = a * (1.0 - (v / b) * (v / b)).sqrt();
            out[4] = Some(DVec2::new(u, v));
            out[5] = Some(DVec2::new(-u, v));
        }
        return out;
    }
    let (ka, kb) = ((a * q.x).powi(2), (b * q.y).powi(2));
    let f = |t: f64| ka / ((t + aa) * (t + aa)) + kb / ((t + bb) * (t + bb)) - 1.0;
    let slope = |t: f64| -ka / (t + aa).powi(3) - kb / (t + bb).powi(3);
    // The foot at t, whose side of each pole (the sign of t + e²) the caller knows: at a
    // root next to a pole, t + e² may round to 0 and lose it.
    let foot = |t: f64, side_a: f64, side_b: f64| {
        let (da, db) = (cancels(t, aa), cancels(t, bb));
        let u = (aa * q.x.abs() / (t + aa).abs()).copysign(q.x * side_a);
        let v = (bb * q.y.abs() / (t + bb).abs()).copysign(q.y * side_b);
        // A coordinate at its pole from the other and the equation (module docs).
        if da < db.min(POLE) {
            let w = (1.0 - (v / b) * (v / b)).max(0.0).sqrt();
            DVec2::new((a * w).copysign(u), v)
        } else if db < POLE {
            let w = (1.0 - (u / a) * (u / a)).max(0.0).sqrt();
            DVec2::new(u, (b * w).copysign(v))
        } else {
            DVec2::new(u, v)
        }
    };
    let (lo, hi) = (aa.min(bb), aa.max(bb));
    // The sides of the poles between them: t + m < 0 < t + M.
    let (mid_a, mid_b) = if aa < bb { (-1.0, 1.0) } else { (1.0, -1.0) };
    let reach = a.max(b) * q.length();
    // (−m, ∞): F falls from +∞ to ≤ 0 at t = reach (each term ≤ its share of |q|²·e²/t²).
    out[0] = Some(foot(root(&f, -lo, reach.max(hi) + reach, false), 1.0, 1.0));
    // (−∞, −M): F rises from ≤ 0 at −M − reach to +∞.
    out[1] = Some(foot(root(&f, -hi - reach, -hi, true), -1.0, -1.0));
    if lo < hi {
        // (−M, −m): convex; its minimum where F′ (increasing) changes sign.
        let t_min = root(&slope, -hi, -lo, true);
        if f(t_min) < 0.0 {
            out[2] = Some(foot(root(&f, -hi, t_min, false), mid_a, mid_b));
            out[3] = Some(foot(root(&f, t_min, -lo, true), mid_a, mid_b));
        }
    }
    out
}

/// How far `t + e` is from cancelling: `|t + e| / max(|t|, e)`, 1 where nothing cancels,
/// down to ε where t + e is rounding (a coordinate `e·y/(t + e)` is then 0/0).
fn cancels(t: f64, e: f64) -> f64 {
    (t + e).abs() / t.abs().max(e)
}

/// Below this [`cancels`], a coordinate is taken from the other one and the ellipse's
/// equation: 10⁻³, where its formula has lost 3 of its digits to the cancellation (the
/// equation's `√(1 − n²)` is then well conditioned: the other coordinate is not near its
/// vertex).
const POLE: f64 = 1e-3;

/// The sign change of `g` on `(lo, hi)`, bisected to adjacent floats: `rising` where g is
/// ≤ 0 at lo's side and > 0 at hi's (else the reverse). The ends need not be evaluable
/// (poles): only midpoints are.
fn root(g: &impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, rising: bool) -> f64 {
    for _ in 0..2200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let v = g(mid);
        if (v > 0.0) == rising {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Eberly's nearest point for `e0 ≥ e1 > 0`, `y0, y1 ≥ 0`.
fn first_quadrant(e0: f64, e1: f64, y0: f64, y1: f64) -> (f64, f64) {
    if y1 > 0.0 {
        if y0 > 0.0 {
            let (z0, z1) = (y0 / e0, y1 / e1);
            let g = z0 * z0 + z1 * z1 - 1.0;
            if g == 0.0 {
                return (y0, y1);
            }
            let r0 = (e0 / e1) * (e0 / e1);
            let s = bisect(r0, z0, z1, g);
            let (x0, x1) = (r0 * y0 / (s + r0), y1 / (s + 1.0));
            // A coordinate whose denominator cancels (s + 1 ≈ 0 for a point near the longer
            // axis, inside) is 0/0 to rounding there: it is taken from the other one and
            // the ellipse's equation instead.
            let (c0, c1) = (cancels(s, r0), cancels(s, 1.0));
            return if c1 < c0.min(POLE) {
                (x0, e1 * (1.0 - (x0 / e0) * (x0 / e0)).max(0.0).sqrt())
            } else if c0 < POLE {
                (e0 * (1.0 - (x1 / e1) * (x1 / e1)).max(0.0).sqrt(), x1)
            } else {
                (x0, x1)
            };
        }
        return (0.0, e1);
    }
    let numer = e0 * y0;
    let denom = e0 * e0 - e1 * e1;
    if numer < denom {
        let xde0 = numer / denom;
        return (e0 * xde0, e1 * (1.0 - xde0 * xde0).max(0.0).sqrt());
    }
    (e0, 0.0)
}

/// The root `s` of `(r0 z0/(s + r0))² + (z1/(s + 1))² = 1` on its bracket, bisected to
/// adjacent floats (the function decreases in `s` there).
fn bisect(r0: f64, z0: f64, z1: f64, g: f64) -> f64 {
    let n0 = r0 * z0;
    let mut s0 = z1 - 1.0;
    let mut s1 = if g < 0.0 { 0.0 } else { n0.hypot(z1) - 1.0 };
    let mut s = 0.0;
    for _ in 0..2200 {
        s = 0.5 * (s0 + s1);
        if s == s0 || s == s1 {
            break;
        }
        let (t0, t1) = (n0 / (s + r0), z1 / (s + 1.0));
        let h = t0 * t0 + t1 * t1 - 1.0;
        if h > 0.0 {
            s0 = s;
        } else if h < 0.0 {
            s1 = s;
        } else {
            break;
        }
    }
    s
}
