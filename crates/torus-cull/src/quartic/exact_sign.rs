//! The exact sign of `p² − 4r` without a fused multiply-add: the even quartic's tangent
//! test as the GPU's f64 pass computes it (`gpu/wgsl/finish_module/solver.wgsl`,
//! `tc_disc_sign64`), step for step. The CPU itself uses `f64::mul_add`, rounded once
//! (`even.rs`); this twin exists so that the WGSL's method is proved here, on every
//! input, against that fused sign (the tests below).
//!
//! **Why not floating-point tricks.** WGSL lets a compiler contract `a·b + c` into an
//! fma or not, and a shader compiler may also re-associate additions it is not told are
//! exact, which undoes Veltkamp's split and Knuth's two-sum alike. So the sign is decided
//! on **integers held exactly in f64**: every value below is an integer under 2⁵³ (or an
//! exact power-of-two scaling of the input), so every sum and product is exact, and any
//! contraction or re-association gives the same bits.
//!
//! **Method.** `|p| = m_p·2^{e_p}` and `4r = m_r·2^{e_r}` with integers `m ∈ [2⁵², 2⁵³)`
//! (exact scalings by powers of two). Then `p² − 4r` has the sign of
//! `m_p² − m_r·2^k`, `k = e_r − 2e_p`. As `m_p² ∈ [2¹⁰⁴, 2¹⁰⁶)` and
//! `m_r·2^k ∈ [2^{52+k}, 2^{53+k})`, only `k ∈ {52, 53}` needs the product: there the
//! difference is formed in limbs of 18 bits (base `B = 2¹⁸`, products below 2³⁶, column sums
//! below 2⁴⁰) and carried from the lowest limb up; after the carries every limb but the top
//! lies in `[0, B)`, so the top limb's sign is the sign, or, if it is 0, whether any other
//! limb is nonzero.
//!
//! The result is the exact sign. The fused one equals it wherever `p² − 4r` does not
//! underflow, which holds for coefficients within 2^±100 (the solver's range,
//! `nearest_root_in_range`): there `|p² − 4r|` is 0 or at least an ulp of numbers above
//! 2⁻³⁰⁰.

use core::cmp::Ordering;

/// 2¹⁸, the limb base.
const B: f64 = 262_144.0;
/// 2⁻¹⁸.
const B_INV: f64 = 1.0 / 262_144.0;

/// `(m, e)` with `|x| = m·2^e` and `m` an integer in `[2⁵², 2⁵³)`, for finite nonzero `x`:
/// scalings by powers of two, each exact (no bit leaves a number at least 2⁵²·2⁻³²).
/// The loops are bounded by f64's exponent range.
#[must_use]
pub(crate) fn mantissa(x: f64) -> (f64, i32) {
    const TWO_32: f64 = 4_294_967_296.0;
    const TWO_M32: f64 = 1.0 / 4_294_967_296.0;
    const TWO_52: f64 = 4_503_599_627_370_496.0;
    const TWO_53: f64 = 9_007_199_254_740_992.0;
    let mut m = x.abs();
    let mut e = 0i32;
    let mut i = 0;
    while i < 40 && m >= TWO_53 * TWO_32 {
        m *= TWO_M32;
        e += 32;
        i += 1;
    }
    i = 0;
    while i < 40 && m < TWO_52 * TWO_M32 {
        m *= TWO_32;
        e -= 32;
        i += 1;
    }
    i = 0;
    while i < 40 && m >= TWO_53 {
        m *= 0.5;
        e += 1;
        i += 1;
    }
    i = 0;
    while i < 40 && m < TWO_52 {
        m *= 2.0;
        e -= 1;
        i += 1;
    }
    (m, e)
}

/// The three base-2¹⁸ limbs `[m₀, m₁, m₂]` of an integer `m < 2⁵³`, lowest first.
#[must_use]
fn limbs(m: f64) -> [f64; 3] {
    let m2 = (m * (B_INV * B_INV)).floor();
    let rest = m - m2 * (B * B);
    let m1 = (rest * B_INV).floor();
    [rest - m1 * B, m1, m2]
}

/// The sign of `p² − 4r`, exactly, for finite `p, r` with `p² + 4|r|` finite (module docs).
#[must_use]
pub(crate) fn disc_sign(p: f64, r: f64) -> Ordering {
    if r <= 0.0 {
        // p² ≥ 0 ≥ 4r: zero only when both are.
        return if p == 0.0 && r == 0.0 {
            Ordering::Equal
        } else {
            Ordering::Greater
        };
    }
    if p == 0.0 {
        return Ordering::Less;
    }
    let (mp, ep) = mantissa(p);
    let (mr, er) = mantissa(4.0 * r);
    let k = er - 2 * ep;
    if k <= 51 {
        return Ordering::Greater;
    }
    if k >= 54 {
        return Ordering::Less;
    }
    let [a0, a1, a2] = limbs(mp);
    let [d0, d1, d2] = limbs(mr);
    // m_r·2^k = Σ d_j·2^s·B^{j+2}, k = 36 + s.
    let s = if k == 52 { 65_536.0 } else { 131_072.0 };
    let mut limb = [
        a0 * a0,
        2.0 * a0 * a1,
        2.0 * a0 * a2 + a1 * a1 - d0 * s,
        2.0 * a1 * a2 - d1 * s,
        a2 * a2 - d2 * s,
        0.0,
    ];
    for i in 0..5 {
        let carry = (limb[i] * B_INV).floor();
        limb[i] -= carry * B;
        limb[i + 1] += carry;
    }
    if limb[5] > 0.0 {
        Ordering::Greater
    } else if limb[5] < 0.0 {
        Ordering::Less
    } else if limb[..5].iter().any(|&l| l != 0.0) {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_pcg::Pcg64;

    /// The CPU's sign: `p² − 4r` rounded once, whose sign is exact where it does not
    /// underflow (`|p² − 4r| ≥ 2⁻¹⁰²²`; every case here; the twin's is exact everywhere).
    fn fused(p: f64, r: f64) -> Ordering {
        p.mul_add(p, -4.0 * r).partial_cmp(&0.0).unwrap()
    }

    #[test]
    fn mantissa_is_exact_and_normalised() {
        for x in [
            1.0,
            -3.0,
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            0.1,
            1e300,
            -1e-300,
        ] {
            let (m, e) = mantissa(x);
            assert!(
                (4_503_599_627_370_496.0..9_007_199_254_740_992.0).contains(&m),
                "{x}"
            );
            assert_eq!(m.fract(), 0.0, "{x}");
            // m·2^e back, in two exact steps where 2^e alone would leave f64.
            let half = e / 2;
            let back = m * 2f64.powi(half) * 2f64.powi(e - half);
            assert_eq!(back, x.abs(), "{x}: {m}·2^{e}");
        }
    }

    /// `r` within a few ulps of `p²/4`, both ways, over every scale: the band where an
    /// unfused `p·p − 4r` gets the sign wrong. The twin gives the fused sign on every one,
    /// and the unfused form is wrong on many (the test's own check that it reaches the band).
    #[test]
    fn the_band_gives_the_fused_sign() {
        let mut rng = Pcg64::seed_from_u64(0x36_5167);
        let (mut cases, mut unfused_wrong) = (0, 0);
        for _ in 0..200_000 {
            let p = rng.random_range(1.0..2.0f64)
                * 2f64.powi(rng.random_range(-60..60))
                * if rng.random::<bool>() { 1.0 } else { -1.0 };
            let quarter = p * p / 4.0;
            let step: i64 = rng.random_range(-6..=6);
            let r = f64::from_bits((quarter.to_bits() as i64 + step) as u64);
            let want = fused(p, r);
            assert_eq!(disc_sign(p, r), want, "p = {p:e}, r = {r:e}");
            cases += 1;
            if (p * p - 4.0 * r).partial_cmp(&0.0).unwrap() != want {
                unfused_wrong += 1;
            }
        }
        assert!(unfused_wrong > cases / 20, "{unfused_wrong} of {cases}");
    }

    /// Exact zeros, signs of `r`, p = 0, and values far from the band.
    #[test]
    fn edges_and_far_values() {
        let cases = [
            (2.0, 1.0),
            (2.0, 1.0 + f64::EPSILON),
            (2.0, 1.0 - f64::EPSILON / 2.0),
            (-6.0, 9.0),
            (0.0, 0.0),
            (0.0, 1e-300),
            (0.0, -1.0),
            (1e-100, 0.0),
            (1e100, 1e-100),
            (1e-100, 1e100),
            (3.0, -1e300),
            (1e150, 2.5e299),
        ];
        for (p, r) in cases {
            assert_eq!(disc_sign(p, r), fused(p, r), "p = {p:e}, r = {r:e}");
        }
        let mut rng = Pcg64::seed_from_u64(7);
        for _ in 0..100_000 {
            let p = rng.random_range(-1e3..1e3f64);
            let r = rng.random_range(-1e6..1e6f64);
            assert_eq!(disc_sign(p, r), fused(p, r), "p = {p:e}, r = {r:e}");
        }
    }
}
