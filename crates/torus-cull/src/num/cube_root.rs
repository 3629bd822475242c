//! The cube root ∛y, the one step of the quartic solver whose seed depends on the width,
//! and the Halley step both seeds share. The resolvent needs ∛ of a cubic's terms on the
//! critical path; a polynomial or bit-trick seed and Halley steps (each cubes the relative
//! error) replace libm's `cbrt`.
//!
//! * Scalar ([`cbrt`]): the exponent of one `f64`, a table of 2^(j/3) and a degree-5 fit,
//!   then one Halley step.
//! * Lanes ([`cbrt_lanes`]): reading an exponent per lane and looking up 2^(j/3) is not
//!   cheap on lanes, so they start from Kahan's bit trick instead and take more of the
//!   same Halley steps ([`cbrt_halley`]).
//!
//! [`Real::cbrt`] picks between them by width.

use super::lanes::F64s;
use super::poly::poly5;
use super::real::{Real, sc};
use pulp::Simd;

/// One Halley step for `t ≈ ∛y`: `t·(t³ + 2y)/(2t³ + y)`, which cubes the relative error.
#[inline(always)]
pub(crate) fn cbrt_halley<R: Real>(t: R, y: R) -> R {
    let two = t.splat(2.0);
    let t3 = t * t * t;
    t * ((t3 + two * y) / (two * t3 + y))
}

/// ∛y for y ≥ 0.
///
/// `y = 2^(3k + j)·μ` with `μ ∈ [1, 2)` (from the bits); a degree-5 fit of ∛μ on [1, 2]
/// (Chebyshev, error 1.7·10⁻⁶) times `2^k·2^(j/3)`, then one Halley step
/// `t ← t·(t³ + 2y)/(2t³ + y)`, which cubes the relative error (to below rounding).
#[inline]
pub(crate) fn cbrt(y: f64) -> f64 {
    // Written so that NaN also takes the cold call.
    if !(1e-300..=1e300).contains(&y) {
        return cbrt_outside(y);
    }
    /// ∛μ on [1, 2].
    const FIT: [f64; 6] = [
        0.005072953325277491,
        -0.04831832068166114,
        0.19665479701360078,
        -0.4602977267696209,
        0.8317431442479309,
        0.47514693623890253,
    ];
    /// 2^(j/3).
    const CBRT_2J: [f64; 3] = [1.0, 1.259_921_049_894_873_2, 1.587_401_051_968_199_5];
    let bits = y.to_bits();
    let biased = (bits >> 52) as u32;
    // y = 2^(biased − 1023)·μ and 1023 = 3·341, so k = ⌊biased/3⌋ − 341, j = biased mod 3.
    let (k_plus, j) = (u64::from(biased / 3), (biased % 3) as usize);
    let mu = f64::from_bits((bits & ((1 << 52) - 1)) | (1023 << 52));
    let scale = f64::from_bits((k_plus + 1023 - 341) << 52) * CBRT_2J[j];
    let t = poly5(&FIT, sc(mu)) * sc(scale);
    cbrt_halley(t, sc(y)).v
}

/// libm's cube root, for the arguments outside the fast path's range (0, subnormal, huge).
#[cold]
fn cbrt_outside(y: f64) -> f64 {
    y.cbrt()
}

/// The range of y where [`cbrt_lanes`] is accurate: t³, 2t³ + y and t times the Halley ratio
/// stay far from overflow and underflow. The caller hands other lanes to the scalar
/// solver (the torus quartics, with lengths in units of R, never come near either end).
pub(crate) const CBRT_RANGE: (f64, f64) = (1e-290, 1e290);

/// ∛y for y in [`CBRT_RANGE`] (other lanes: unspecified).
///
/// Seed: Kahan's bit trick (as in fdlibm's `cbrt`): the high 32 bits of y, divided by 3,
/// plus the bias 715 094 163, over a zero low word, is ∛y within about 6 %. Then three
/// Halley steps t ← t·((t³ + 2y)/(2t³ + y)): 6 % → 10⁻⁴ → 10⁻¹² → below rounding. A
/// register whose f64 and u32 lanes differ in number calls libm (the one-lane scalar
/// register never comes here: [`Real::cbrt`] gives it the scalar
/// solver's cube root).
#[inline(always)]
pub(crate) fn cbrt_lanes<S: Simd>(y: F64s<S>) -> F64s<S> {
    let s = y.s;
    if size_of::<S::f64s>() != size_of::<S::u32s>() || S::F64_LANES == 1 {
        let mut v = y.v;
        for x in pulp::bytemuck::cast_slice_mut::<S::f64s, f64>(std::slice::from_mut(&mut v)) {
            *x = x.cbrt();
        }
        return F64s { s, v };
    }
    let words: S::u32s = pulp::bytemuck::cast(y.v);
    // ⌊w/3⌋ = ⌊w·⌈2³³/3⌉ / 2³³⌋ for every 32-bit w.
    let (_, high) = s.widening_mul_u32s(words, s.splat_u32s(0xAAAA_AAAB));
    let third = s.wrapping_dyn_shr_u32s(high, s.splat_u32s(1));
    let seed_words = s.add_u32s(third, s.splat_u32s(715_094_163));
    // Keep the high word of each f64 lane (little-endian: the odd u32 lane), zero the low.
    let high_words: S::u32s = pulp::bytemuck::cast(s.splat_u64s(0xFFFF_FFFF_0000_0000));
    let seed = s.and_u32s(seed_words, high_words);
    let mut t = F64s {
        s,
        v: pulp::bytemuck::cast(seed),
    };
    for _ in 0..3 {
        t = cbrt_halley(t, y);
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::lane_tests::{LaneFn, on_every_isa};

    struct Cbrt;
    impl LaneFn for Cbrt {
        #[inline(always)]
        fn call<S: Simd>(x: F64s<S>) -> F64s<S> {
            cbrt_lanes(x)
        }
    }

    #[test]
    fn cbrt_is_within_two_ulps_of_libm() {
        let (low, high) = CBRT_RANGE;
        let mut xs = vec![low, 1e-20, 0.1, 1.0, 2.0, 8.0, 27.0, 1e20, high];
        xs.extend((1..4000).map(|i| 10f64.powf(-290.0 + 580.0 * f64::from(i) / 4000.0)));
        for (isa, got) in on_every_isa::<Cbrt>(&xs) {
            for (x, g) in xs.iter().zip(got) {
                let want = x.cbrt();
                assert!(
                    ((g - want) / want).abs() <= 2.0 * f64::EPSILON,
                    "{isa}: cbrt({x}) = {g}, libm {want}"
                );
            }
        }
    }

    #[test]
    fn scalar_cbrt_is_within_two_ulps_of_libm() {
        let mut xs = vec![0.0, 1e-310, 1e-300, 0.1, 1.0, 2.0, 8.0, 27.0, 1e300, 1e305];
        xs.extend((1..20_000).map(|i| 10f64.powf(-300.0 + 600.0 * f64::from(i) / 20_000.0)));
        xs.extend((0..3000).map(|i| 1.0 + f64::from(i) / 1000.0));
        for x in xs {
            let (got, want) = (cbrt(x), x.cbrt());
            assert!(
                (got - want).abs() <= 2.0 * f64::EPSILON * want,
                "cbrt({x}) = {got}, libm {want}"
            );
        }
    }
}
