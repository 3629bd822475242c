//! The greatest root of Ferrari's resolvent, solved for `z = m²` directly.
//!
//! For `x⁴ + p x² + q x + r = (x² + m x + n₁)(x² − m x + n₂)` the square `z = m²` is a root
//! of the resolvent cubic
//!
//! `h(z) = z³ + 2p z² + (p² − 4r) z − q²`
//!
//! (Descartes' form: its roots are `(x₁ + x₂)²` over the pairings of the quartic's roots).
//! Since `h(0) = −q² ≤ 0` and `h → +∞`, the greatest root is real and `≥ 0`, so `m` is real.
//!
//! **Why `z` and not Ferrari's `ξ` (with `m² = 2ξ − p`).** When `q` is small, `m²` is about
//! `q²/(p² − 4r)`, tiny next to `|p|`, and `2ξ − p` cannot represent it: the old solver got
//! `ξ` one ulp *below* `p/2`, took that as impossible, fell back to a Newton search that
//! stalled at a local minimum of the cubic, and then lost every real root (a line inside the
//! tube near the hole edge, whose quartic has two real roots and a near-double complex pair
//! near 0). In `z`, the small root keeps full relative precision through Vieta:
//! `z·|z₂|² = q²`, with `z₂` the larger complex root that Cardano gives along with `z`
//! (or, with three real roots, by the fixed point `z = q²/((z + 2p)z + p² − 4r)`).
//!
//! **No libm.** The cube root and the trisection `cos(arccos(x)/3)` are roots of cubics:
//! each is a polynomial seed good to 2·10⁻⁶ and one Halley step (cubic convergence), which
//! is far shorter than libm's `cbrt`, `acos` and `cos` on the critical path.

/// Below this `|Δ| / scale` the sign of the cubic's discriminant is not trusted: a
/// near-double pair of roots may be real or complex by rounding. Then the pair is classified
/// by the value of `h` at its local minimum instead.
use super::cube_root::{cbrt, trisect_u};

pub(crate) const DISC_NEAR: f64 = 1e-9;

/// Below this `|Δ| / scale` the closed form is Newton-polished.
const POLISH_BELOW: f64 = 1e-4;

/// The resolvent's greatest root `z = m² ≥ 0`, with what Ferrari's split needs of it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Root {
    pub z: f64,
    /// `h'(z)` (at `z_early`: it only sizes errors).
    pub dh: f64,
    /// `m = √z`.
    pub m: f64,
    /// `q/m` (garbage when `m = 0`).
    pub q_over_m: f64,
    /// `q/m` is good to a few ulps, whatever `h'(z)` says (Vieta's `z`, below).
    pub q_over_m_exact: bool,
    /// `z` to within a few `ε·|p|`, earlier on the dependency chain than `z` itself: for
    /// `p + z`, whose rounding is that large anyway.
    pub z_early: f64,
}

/// The greatest real root of `h` for the depressed quartic `x⁴ + p x² + q x + r` (finite
/// inputs).
#[inline]
pub(super) fn greatest_root(p: f64, q: f64, r: f64) -> Root {
    let a = 2.0 * p;
    let b = p * p - 4.0 * r;
    let c = -q * q;
    // z = w − a/3 gives w³ + P w + Q. Thirds by multiplication: a division is on the
    // critical path, and the last bit of these is below what the formulas resolve.
    // In p, q, r directly: P' = −(p²/9 + 4r/3), Q' = p(4r/3 − p²/27) − q²/2 (a shorter
    // chain than through a, b and c).
    let a3 = a * (1.0 / 3.0);
    let (p2, r43) = (p * p, r * (4.0 / 3.0));
    let third_p = -(p2 * (1.0 / 9.0) + r43);
    let half_q = p * (r43 - p2 * (1.0 / 27.0)) - 0.5 * (q * q);
    let disc = half_q * half_q + third_p * third_p * third_p;
    let scale = half_q * half_q + (third_p * third_p * third_p).abs();

    let h = |z: f64| ((z + a) * z + b) * z + c;
    let dh = |z: f64| (3.0 * z + 2.0 * a) * z + b;
    let near = disc.abs() <= DISC_NEAR * scale;
    let (mut z, mut m, mut q_over_m, mut z_early);
    let mut small_root = false;
    let mut vieta = false;
    if !near && disc > 0.0 {
        let (u, v) = cardano(third_p, half_q, disc);
        z = (u + v - a3).max(0.0);
        // The other roots are a complex pair z₂, z̄₂ with 4|z₂|² = (z + a)² + 3(u − v)²
        // (both squares free of cancellation), and z·|z₂|² = q². When z is small next to
        // |a|, w − a/3 has cancelled and z = 4q²/pair keeps full relative precision; m and
        // q/m then follow from √pair without the two divisions. Both are computed and
        // one is selected: which one applies is a coin toss from ray to ray.
        let pair = (z + a) * (z + a) + 3.0 * (u - v) * (u - v);
        vieta = z < a3.abs() && pair > 0.0;
        let half_sp = 0.5 * pair.sqrt();
        let (m_direct, m_vieta) = (z.sqrt(), q.abs() / half_sp);
        m = if vieta { m_vieta } else { m_direct };
        q_over_m = if vieta {
            half_sp.copysign(q)
        } else {
            q / m_direct
        };
        z_early = z;
        z = if vieta { 4.0 * q * q / pair } else { z };
    } else {
        let w = if near {
            near_double(a, b, c, a3, third_p, half_q)
        } else {
            trigonometric(third_p, half_q)
        };
        z = (w - a3).max(0.0);
        // A root far below ε·|a| is out of the closed form's reach, and Newton from there
        // only gains a factor ε per step. Near 0, h = z·((z + a)z + b) − q², so the fixed
        // point z = q²/((z + a)z + b) gives it to full relative precision at once (it
        // contracts by about z·|a|/b per step). Rare: the greatest of three real roots is
        // seldom tiny.
        small_root = b > 0.0 && z * (z + a.abs()) <= 1e-3 * b;
        if small_root {
            z = q * q / b;
            z = q * q / ((z + a) * z + b);
        }
        m = z.sqrt();
        // q/m = (q/z)·m: the division overlaps the root instead of waiting for it.
        q_over_m = q / z * m;
        z_early = z;
    }
    // Two Newton steps polish the closed form where it loses digits: a small discriminant
    // (close roots: the trisection near −1, Cardano's cancellation; one step was
    // measurably short on tangents at the inner equator) or a root found by the fixed
    // point above. Elsewhere the closed form is good to a few ulps and the steps would
    // only lengthen the hot path; so is Vieta's z even at a small discriminant (its pair
    // is dominated by (z + a)², which has no cancellation: a tangent at the foot point).
    // A step is kept only if it lowers |h|, so a double root cannot be thrown away.
    if !vieta && (small_root || disc.abs() <= POLISH_BELOW * scale) {
        let mut hz = h(z);
        for _ in 0..2 {
            let zn = (z - hz / dh(z)).max(0.0);
            let hn = h(zn);
            // Written so that NaN (h' = 0) keeps z.
            if hn.abs() < hz.abs() {
                z = zn;
                hz = hn;
            }
        }
        m = z.sqrt();
        q_over_m = q / m;
        z_early = z;
    }
    Root {
        z,
        dh: dh(z_early),
        m,
        q_over_m,
        q_over_m_exact: vieta,
        z_early,
    }
}

/// Cardano's `(u, v)` for `w³ + 3P' w + 2Q'` (`third_p = P'`, `half_q = Q'`, `disc > 0`):
/// the one real root is `w = u + v` with `v = −P'/u`, the cube root taken of the
/// larger-magnitude term to avoid cancellation.
#[inline]
fn cardano(third_p: f64, half_q: f64, disc: f64) -> (f64, f64) {
    let cube = half_q.abs() + disc.sqrt();
    // u = ±∛cube and v = −P'/u = ±(−P'/cube)·∛cube²: the division runs while the cube
    // root does.
    let ratio = -third_p / cube;
    let big = cbrt(cube);
    let v = ratio * big * big;
    let (u, v) = if half_q > 0.0 { (-big, -v) } else { (big, v) };
    if big != 0.0 { (u, v) } else { (0.0, 0.0) }
}

/// The greatest of three real roots (`disc ≤ 0`, so `third_p ≤ 0`): `2k cos(θ/3)` with
/// `k = √(−P')` and `cos θ = −Q'/k³`.
#[inline]
fn trigonometric(third_p: f64, half_q: f64) -> f64 {
    let k = (-third_p).max(0.0).sqrt();
    // −Q'/k³ = (Q'/P')·√(−1/P'): both divisions and the root overlap the root k. P' = 0
    // makes it NaN or infinite, which `max` and `min` clamp (`clamp` would keep NaN);
    // then k·… is 0.
    #[allow(clippy::manual_clamp)]
    let cos3 = ((half_q / third_p) * (-1.0 / third_p).sqrt())
        .max(-1.0)
        .min(1.0);
    // 2k·cos(θ/3) = k·(1 + u).
    k + k * trisect_u(cos3)
}

/// `disc ≈ 0`: two roots of `h` (nearly) coincide. If the pair is the top one, whether it is
/// real decides the greatest root; `h` at its local minimum `z₊` tells: `h(z₊) ≤ 0` means
/// a real root at or right of `z₊`, otherwise the only real root is left of the pair.
#[cold]
fn near_double(a: f64, b: f64, c: f64, a3: f64, third_p: f64, half_q: f64) -> f64 {
    let crit = a * a - 3.0 * b;
    if crit <= 0.0 {
        // h is monotone: one real root (a triple one when crit = 0).
        let (u, v) = cardano(third_p, half_q, 0.0);
        return u + v;
    }
    let sq = crit.sqrt();
    // Larger root of h' = 3z² + 2az + b, without cancellation.
    let z_min = if a > 0.0 {
        -b / (a + sq)
    } else {
        (sq - a) / 3.0
    };
    let h_min = ((z_min + a) * z_min + b) * z_min + c;
    if h_min <= 0.0 {
        trigonometric(third_p, half_q).max(z_min + a3)
    } else {
        let (u, v) = cardano(third_p, half_q, 0.0);
        u + v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h(p: f64, q: f64, r: f64, z: f64) -> f64 {
        ((z + 2.0 * p) * z + p * p - 4.0 * r) * z - q * q
    }

    #[test]
    fn tiny_root_has_full_relative_precision() {
        // The reproducer: m² ≈ q²/(p² − 4r) ≈ 7.6e-26, next to |p| ≈ 3.3.
        let (p, q, r) = (
            -3.3331887926483623,
            9.194867089945546e-13,
            -0.00023409507477270552,
        );
        let Root { z, dh, .. } = greatest_root(p, q, r);
        let want = q * q / (p * p - 4.0 * r);
        assert!(((z - want) / want).abs() < 1e-6, "{z:e} vs {want:e}");
        assert!(dh > 0.0);
        // And it really is the greatest root: h > 0 everywhere right of it (h has a
        // complex pair near 3.33 here, where the old solver's search stalled).
        for i in 1..=4000 {
            let zz = z + f64::from(i) * 1e-3;
            assert!(h(p, q, r, zz) > 0.0, "h({zz}) ≤ 0");
        }
    }

    #[test]
    fn greatest_of_three_real_roots() {
        // x⁴ − 5x² + 4 = (x² − 1)(x² − 4): pairings give z ∈ {0, 1, 9}.
        let z = greatest_root(-5.0, 0.0, 4.0).z;
        assert!((z - 9.0).abs() < 1e-12, "{z}");
        // (x² − 1)²: z ∈ {0, 0, 4}.
        let z = greatest_root(-2.0, 0.0, 1.0).z;
        assert!((z - 4.0).abs() < 1e-12, "{z}");
    }

    #[test]
    fn never_negative_and_always_a_root() {
        // Random depressed quartics over many scales: z ≥ 0, h(z) ≈ 0 and h > 0 beyond z.
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(0x7051_0100);
        for _ in 0..50_000 {
            let s: f64 = 10f64.powf(rng.random_range(-3.0..3.0));
            let p = rng.random_range(-4.0..4.0) * s * s;
            let q =
                rng.random_range(-4.0..4.0) * s * s * s * 10f64.powf(rng.random_range(-14.0..0.0));
            let r = rng.random_range(-4.0..4.0) * s * s * s * s;
            let z = greatest_root(p, q, r).z;
            assert!(z >= 0.0);
            let zs = s * s;
            let mag = ((z + 2.0 * p.abs()) * z + p * p + 4.0 * r.abs()) * z + q * q;
            let hz = h(p, q, r, z);
            // A near-double top root is √-conditioned; everywhere else h(z) is at rounding.
            let beyond = h(p, q, r, z + 1e-6 * zs.max(z));
            assert!(
                hz.abs() <= 1e-9 * mag.max(f64::MIN_POSITIVE) || beyond > 0.0,
                "p={p} q={q} r={r}: z={z} h={hz} beyond={beyond}"
            );
            assert!(
                beyond >= -1e-9 * mag,
                "p={p} q={q} r={r}: not the greatest root"
            );
        }
    }
}
