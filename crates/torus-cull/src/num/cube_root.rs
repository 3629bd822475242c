//! The cube root ∛y, the one step of the quartic solver whose seed depends on the width,
//! and the Halley step both seeds share. The resolvent needs ∛ of a cubic's terms on the
//! critical path; a polynomial or bit-trick seed and Halley steps (each cubes the relative
//! error) replace libm's `cbrt`: inline, a few bit operations, a degree-5 polynomial and
//! one division per step, where libm's is an out-of-line call with no lane form.
//!
//! * Scalar ([`cbrt`]): the exponent of one `f64`, a table of 2^(j/3) and a degree-5 fit,
//!   then one Halley step.
//! * Lanes ([`cbrt_lanes`]): reading an exponent per lane and looking up 2^(j/3) is not
//!   cheap on lanes, so they start from Kahan's bit trick instead and take more of the
//!   same Halley steps ([`cbrt_halley`]).
//!
//! [`Cbrt::cbrt`] picks between them by width.

use super::lanes::{F32s, F64s};
use super::poly::poly5;
use pulp::Simd;
use std::ops::{Add, Div, Mul};

/// ∛x for x ≥ 0, without libm on the hot path, for each lane type: the scalar seed at
/// width 1, a bit-trick seed and Halley steps on wider f64 lanes (accurate on
/// [`CBRT_RANGE`], which the lane solver checks), the same bits at every width for f32.
/// A supertrait of [`super::Real`], so every solver step has it.
pub trait Cbrt: Sized {
    /// ∛self.
    fn cbrt(self) -> Self;
}

impl<S: Simd> Cbrt for F64s<S> {
    #[inline(always)]
    fn cbrt(self) -> Self {
        if S::F64_LANES == 1 {
            let y: f64 = pulp::bytemuck::cast(self.v);
            F64s {
                s: self.s,
                v: pulp::bytemuck::cast(cbrt(y)),
            }
        } else {
            cbrt_lanes(self)
        }
    }
}

impl<S: Simd> Cbrt for F32s<S> {
    /// ∛y for y ≥ 0 normal, at every width the same bits (the certified f32 path's scalar
    /// and lane forms agree): Kahan's seed on the f32 word (⌊w/3⌋ + 709 958 130, as
    /// fdlibm's `cbrtf`, within about 6 %), then two Halley steps (6 % → 10⁻⁴ → below
    /// f32's rounding). Zero, subnormal and non-finite lanes come out unspecified: the
    /// certificate, not the cube root, decides what f32 may claim.
    #[inline(always)]
    fn cbrt(self) -> Self {
        let s = self.s;
        let words: S::u32s = pulp::bytemuck::cast(self.v);
        // ⌊w/3⌋ = ⌊w·⌈2³³/3⌉ / 2³³⌋ for every 32-bit w.
        let (_, high) = s.widening_mul_u32s(words, s.splat_u32s(0xAAAA_AAAB));
        let third = s.wrapping_dyn_shr_u32s(high, s.splat_u32s(1));
        let seed = s.add_u32s(third, s.splat_u32s(CBRT_F32_SEED));
        let mut t = F32s {
            s,
            v: pulp::bytemuck::cast(seed),
        };
        for _ in 0..2 {
            t = cbrt_halley(t, self, F32s::splat(s, 2.0));
        }
        t
    }
}

/// Kahan's seed for the f32 cube root: ∛y ≈ the float whose word is ⌊w/3⌋ + this, w the
/// word of y (fdlibm's `cbrtf`; within about 6 %). The GPU kernel's seed too.
pub(crate) const CBRT_F32_SEED: u32 = 709_958_130;

/// One Halley step for `t ≈ ∛y`: `t·(t³ + 2y)/(2t³ + y)`, which cubes the relative error.
/// `two` is 2 in `t`'s type (one float or a register of lanes).
#[inline(always)]
pub(crate) fn cbrt_halley<T>(t: T, y: T, two: T) -> T
where
    T: Copy + Add<Output = T> + Mul<Output = T> + Div<Output = T>,
{
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
    let t = poly5(FIT, mu) * scale;
    cbrt_halley(t, y, 2.0)
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
/// register never comes here: [`Cbrt::cbrt`] gives it the scalar
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
        t = cbrt_halley(t, y, F64s::splat(s, 2.0));
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

#[cfg(test)]
mod f32_cbrt {
    use super::*;

    #[test]
    fn f32_cube_root_is_within_two_ulps_on_normal_numbers() {
        let s = pulp::Scalar::new();
        let mut worst = 0.0f64;
        for i in 0..200_000 {
            let y = 10f32.powf(-37.0 + 75.0 * (i as f32) / 200_000.0);
            let got = F32s { s, v: y }.cbrt().v;
            let want = f64::from(y).cbrt();
            worst = worst.max(((f64::from(got) - want) / want).abs());
        }
        assert!(
            worst < 2.0 * f64::from(f32::EPSILON),
            "worst relative error {worst:e}"
        );
    }
}
