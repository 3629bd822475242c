//! The nearest point of an ellipse, by bisection (the on-surface rule moves a ray's origin
//! onto the surface with it). Follows D. Eberly, "Distance from a Point to an Ellipse, an
//! Ellipsoid, or a Hyperellipsoid" (2013): in the first quadrant, with `e0 ≥ e1` and
//! `z = (u/e0, v/e1)`, the nearest point is `(r0 u/(σ + r0), v/(σ + 1))`, `r0 = (e0/e1)²`,
//! where σ is the unique root of the decreasing
//! `G(σ) = (r0 z0/(σ + r0))² + (z1/(σ + 1))² − 1` on `[z1 − 1, |(r0 z0, z1)| − 1]`
//! (or `[z1 − 1, 0]` inside), bisected here to adjacent floats; then polished on the
//! angle parameter (`polish`).

/// The point `(u′, v′)` of the ellipse `(u/a)² + (v/b)² = 1` nearest to `(u, v)`, with
/// the same signs as `(u, v)`. Where it is not unique (inside, on the longer axis, closer
/// to the centre than the evolute's cusp) the one on the side of the zero coordinate's
/// sign (+ for +0.0) is given.
///
/// # Panics
/// If a or b is not positive and finite, or u or v not finite.
pub fn nearest_on_ellipse(a: f64, b: f64, u: f64, v: f64) -> (f64, f64) {
    assert!(
        a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite(),
        "bad axes {a}, {b}"
    );
    assert!(u.is_finite() && v.is_finite(), "bad point ({u}, {v})");
    let (x, y) = if a >= b {
        first_quadrant(a, b, u.abs(), v.abs())
    } else {
        let (y, x) = first_quadrant(b, a, v.abs(), u.abs());
        (x, y)
    };
    let (x, y) = polish(a, b, u, v, x.copysign(u), y.copysign(v));
    (x.copysign(u), y.copysign(v))
}

/// The bisected point to the last bits: its angle parameter θ (x = a cos θ, y = b sin θ,
/// so the point is on the ellipse to rounding, which the root σ alone does not give
/// where σ + 1 or σ + r0 cancels), then a few safeguarded Newton steps on
/// `f(θ) = ½ d|(a cos θ, b sin θ) − (u, v)|²/dθ = (b² − a²) sin θ cos θ + a u sin θ − b v cos θ`:
/// a step is taken only while it shrinks |f| and is small (bisection already brackets θ to
/// rounding, so Newton only removes the last rounding).
fn polish(a: f64, b: f64, u: f64, v: f64, x: f64, y: f64) -> (f64, f64) {
    let k = (b - a) * (b + a);
    let f = |th: f64| {
        let (s, c) = th.sin_cos();
        k * s * c + a * u * s - b * v * c
    };
    let mut th = (y / b).atan2(x / a);
    let mut ft = f(th);
    for _ in 0..8 {
        let (s, c) = th.sin_cos();
        let df = k * (c - s) * (c + s) + a * u * c + b * v * s;
        if df == 0.0 || ft == 0.0 {
            break;
        }
        let step = ft / df;
        if step.is_nan() || step.abs() > 1e-6 {
            break;
        }
        let next = th - step;
        let fn_ = f(next);
        if fn_.abs() >= ft.abs() {
            break;
        }
        th = next;
        ft = fn_;
    }
    let (s, c) = th.sin_cos();
    (a * c, b * s)
}

/// The nearest point for `e0 ≥ e1 > 0`, `y0, y1 ≥ 0`.
fn first_quadrant(e0: f64, e1: f64, y0: f64, y1: f64) -> (f64, f64) {
    if y1 > 0.0 {
        if y0 > 0.0 {
            let (z0, z1) = (y0 / e0, y1 / e1);
            let g = z0.hypot(z1) - 1.0;
            if g == 0.0 {
                return (y0, y1);
            }
            let r0 = (e0 / e1) * (e0 / e1);
            let sigma = root(r0, z0, z1, g);
            (r0 * y0 / (sigma + r0), y1 / (sigma + 1.0))
        } else {
            (0.0, e1)
        }
    } else {
        // On the longer axis: the vertex, or (inside the evolute's reach) the point above.
        let numer = e0 * y0;
        let denom = (e0 - e1) * (e0 + e1);
        if numer < denom {
            let xde = numer / denom;
            (e0 * xde, e1 * ((1.0 - xde) * (1.0 + xde)).max(0.0).sqrt())
        } else {
            (e0, 0.0)
        }
    }
}

/// The root of G by bisection, to adjacent floats.
fn root(r0: f64, z0: f64, z1: f64, g: f64) -> f64 {
    let n0 = r0 * z0;
    let mut s0 = z1 - 1.0;
    let mut s1 = if g < 0.0 { 0.0 } else { n0.hypot(z1) - 1.0 };
    let mut s = s0;
    for _ in 0..super::super::interval::MAX_BISECTIONS {
        s = 0.5 * (s0 + s1);
        if s == s0 || s == s1 {
            break;
        }
        let gs = (n0 / (s + r0)).hypot(z1 / (s + 1.0)) - 1.0;
        if gs > 0.0 {
            s0 = s;
        } else if gs < 0.0 {
            s1 = s;
        } else {
            break;
        }
    }
    s
}
