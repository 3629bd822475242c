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
//! near 0). In `z`, the small root is found to full relative precision by the fixed point
//! `z = q²/((z + 2p)z + p² − 4r)`, because every term of `h` is small there.

/// Below this `|Δ| / scale` the sign of the cubic's discriminant is not trusted: a
/// near-double pair of roots may be real or complex by rounding. Then the pair is classified
/// by the value of `h` at its local minimum instead.
pub(crate) const DISC_NEAR: f64 = 1e-9;

/// Below this `|Δ| / scale` the closed form is Newton-polished.
const POLISH_BELOW: f64 = 1e-4;

/// `(z, h'(z))` with `z ≥ 0` the greatest real root of `h` for the depressed quartic
/// `x⁴ + p x² + q x + r` (finite inputs).
#[inline]
pub(super) fn greatest_root(p: f64, q: f64, r: f64) -> (f64, f64) {
    let a = 2.0 * p;
    let b = p * p - 4.0 * r;
    let c = -q * q;
    // z = w − a/3 gives w³ + P w + Q.
    let a3 = a / 3.0;
    let third_p = (b - a * a3) / 3.0;
    let half_q = 0.5 * (c - a3 * (b - 2.0 * a3 * a3));
    let disc = half_q * half_q + third_p * third_p * third_p;
    let scale = half_q * half_q + (third_p * third_p * third_p).abs();

    let w = if disc.abs() <= DISC_NEAR * scale {
        near_double(a, b, c, a3, third_p, half_q)
    } else if disc > 0.0 {
        cardano(third_p, half_q, disc)
    } else {
        trigonometric(third_p, half_q)
    };

    let h = |z: f64| ((z + a) * z + b) * z + c;
    let dh = |z: f64| (3.0 * z + 2.0 * a) * z + b;
    let mut z = (w - a3).max(0.0);
    // A root far below ε·|a| is out of the closed form's reach, and Newton from there only
    // gains a factor ε per step. Near 0, h = z·((z + a)z + b) − q², so the fixed point
    // z = q²/((z + a)z + b) gives it to full relative precision at once (it contracts by
    // about z·|a|/b per step).
    let small_root = b > 0.0 && z * (z + a.abs()) <= 1e-3 * b;
    if small_root {
        z = q * q / b;
        z = q * q / ((z + a) * z + b);
    }
    // Two Newton steps polish the closed form where it loses digits: a small discriminant
    // (close roots: the trigonometric form's acos near ±1, Cardano's cancellation; one
    // step was measurably short on tangents at the inner equator) or a root found by the
    // fixed point above. Elsewhere the closed form is good to a few ulps and the steps
    // would only lengthen the hot path. A step is kept only if it lowers |h|, so a double
    // root cannot be thrown away.
    if small_root || disc.abs() <= POLISH_BELOW * scale {
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
    }
    (z, dh(z))
}

/// The one real root of `w³ + 3P' w + 2Q'` (`third_p = P'`, `half_q = Q'`, `disc > 0`), with
/// the cube root taken of the larger-magnitude term to avoid cancellation.
#[inline]
fn cardano(third_p: f64, half_q: f64, disc: f64) -> f64 {
    let big = (half_q.abs() + disc.sqrt()).cbrt();
    let u = if half_q > 0.0 { -big } else { big };
    if u != 0.0 { u - third_p / u } else { 0.0 }
}

/// The greatest of three real roots (`disc ≤ 0`, so `third_p ≤ 0`): `2k cos(θ/3)`.
#[inline]
fn trigonometric(third_p: f64, half_q: f64) -> f64 {
    let k = (-third_p).max(0.0).sqrt();
    if k == 0.0 {
        return 0.0;
    }
    let cos3 = (-half_q / (k * k * k)).clamp(-1.0, 1.0);
    2.0 * k * (cos3.acos() / 3.0).cos()
}

/// `disc ≈ 0`: two roots of `h` (nearly) coincide. If the pair is the top one, whether it is
/// real decides the greatest root; `h` at its local minimum `z₊` tells: `h(z₊) ≤ 0` means
/// a real root at or right of `z₊`, otherwise the only real root is left of the pair.
#[cold]
fn near_double(a: f64, b: f64, c: f64, a3: f64, third_p: f64, half_q: f64) -> f64 {
    let crit = a * a - 3.0 * b;
    if crit <= 0.0 {
        // h is monotone: one real root (a triple one when crit = 0).
        return cardano(third_p, half_q, 0.0);
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
        cardano(third_p, half_q, 0.0)
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
        let (z, dh) = greatest_root(p, q, r);
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
        let (z, _) = greatest_root(-5.0, 0.0, 4.0);
        assert!((z - 9.0).abs() < 1e-12, "{z}");
        // (x² − 1)²: z ∈ {0, 0, 4}.
        let (z, _) = greatest_root(-2.0, 0.0, 1.0);
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
            let (z, _) = greatest_root(p, q, r);
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
