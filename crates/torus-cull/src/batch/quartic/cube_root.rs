//! The lane seed of the cube root ∛y, the one step of the solver whose form depends on
//! the width: the scalar solver's seed reads the exponent of one `f64` and looks up
//! 2^(j/3), which lanes cannot do cheaply, so lanes start from Kahan's bit trick instead
//! and take more of the same Halley steps ([`crate::quartic::cube_root::cbrt_halley`]).
//! The trisection cos(arccos(x)/3) is the scalar solver's own
//! ([`crate::quartic::cube_root::trisect_u`]).

use crate::batch::lanes::F64s;
use crate::quartic::cube_root::cbrt_halley;
use pulp::Simd;

/// The range of y where [`cbrt`] is accurate: t³, 2t³ + y and t times the Halley ratio
/// stay far from overflow and underflow. The caller hands other lanes to the scalar
/// solver (the torus quartics, with lengths in units of R, never come near either end).
pub(crate) const CBRT_RANGE: (f64, f64) = (1e-290, 1e290);

/// ∛y for y in [`CBRT_RANGE`] (other lanes: unspecified).
///
/// Seed: Kahan's bit trick (as in fdlibm's `cbrt`): the high 32 bits of y, divided by 3,
/// plus the bias 715 094 163, over a zero low word, is ∛y within about 6 %. Then three
/// Halley steps t ← t·((t³ + 2y)/(2t³ + y)): 6 % → 10⁻⁴ → 10⁻¹² → below rounding. A
/// register whose f64 and u32 lanes differ in number calls libm (the one-lane scalar
/// register never comes here: [`crate::batch::real::Real::cbrt`] gives it the scalar
/// solver's cube root).
#[inline(always)]
pub(crate) fn cbrt<S: Simd>(y: F64s<S>) -> F64s<S> {
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
    use crate::batch::real::Real;
    use crate::batch::{Dispatch, Isa};
    use crate::quartic::cube_root::trisect_u;
    use pulp::WithSimd;

    /// Runs one function over `xs`, a register at a time (padded with 1.0).
    struct Apply<'a>(&'a [f64], Kind);
    #[derive(Clone, Copy)]
    enum Kind {
        Cbrt,
        Trisect,
    }
    impl WithSimd for Apply<'_> {
        type Output = Vec<f64>;
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) -> Vec<f64> {
            let n = S::F64_LANES;
            let mut out = Vec::new();
            for chunk in self.0.chunks(n) {
                let mut lanes = vec![1.0; n];
                lanes[..chunk.len()].copy_from_slice(chunk);
                let x = F64s::load(s, &lanes);
                let y = match self.1 {
                    Kind::Cbrt => cbrt(x),
                    Kind::Trisect => x.splat(0.5) * (x.splat(1.0) + trisect_u(x)),
                };
                let v = y.v;
                let got = pulp::bytemuck::cast_slice::<S::f64s, f64>(std::slice::from_ref(&v));
                out.extend_from_slice(&got[..chunk.len()]);
            }
            out
        }
    }

    fn run(kind: Kind, xs: &[f64]) -> Vec<(Isa, Vec<f64>)> {
        Isa::available()
            .into_iter()
            .map(|isa| {
                let d = Dispatch::forced(isa).unwrap();
                (isa, d.run(Apply(xs, kind)))
            })
            .collect()
    }

    #[test]
    fn cbrt_is_within_two_ulps_of_libm() {
        let (low, high) = CBRT_RANGE;
        let mut xs = vec![low, 1e-20, 0.1, 1.0, 2.0, 8.0, 27.0, 1e20, high];
        xs.extend((1..4000).map(|i| 10f64.powf(-290.0 + 580.0 * f64::from(i) / 4000.0)));
        for (isa, got) in run(Kind::Cbrt, &xs) {
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
    fn trisection_matches_cos_of_a_third_of_acos() {
        let mut xs: Vec<f64> = (0..=4000).map(|i| -1.0 + f64::from(i) / 2000.0).collect();
        xs.extend([-1.0 + 1e-15, -1.0 + 1e-9, -1.0 + 1e-6, 1.0 - 1e-12]);
        for (isa, got) in run(Kind::Trisect, &xs) {
            for (x, g) in xs.iter().zip(got) {
                let want = (x.acos() / 3.0).cos();
                assert!(
                    (g - want).abs() <= 4.0 * f64::EPSILON,
                    "{isa}: x = {x}: {g} vs {want}"
                );
            }
        }
    }
}
