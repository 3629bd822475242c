//! The two cube roots Cardano's formula needs, over f64 lanes, without libm: the real
//! cube root ∛y and the trisection cos(arccos(x)/3).
//!
//! The scalar solver calls libm's `cbrt`, `acos` and `cos`, which have no SIMD form in
//! the standard library. Both are roots of cubics, so each is a cheap seed and a few
//! Halley steps (cubic convergence: every step triples the correct digits). They need
//! not match libm bit for bit: the resolvent root they feed is Newton-polished on the
//! cubic itself afterwards, exactly as in the scalar solver.

use crate::batch::lanes::F64s;
use pulp::Simd;

/// The range of y where [`cbrt`] is accurate: t³, 2t³ + y and t times the Halley ratio
/// stay far from overflow and underflow. The caller hands other lanes to the scalar
/// solver (the torus quartics, with lengths in units of R, never come near either end).
pub(crate) const CBRT_RANGE: (f64, f64) = (1e-290, 1e290);

/// ∛y for y in [`CBRT_RANGE`] (other lanes: unspecified).
///
/// Seed: Kahan's bit trick (as in fdlibm's `cbrt`): the high 32 bits of y, divided by 3,
/// plus the bias 715 094 163, over a zero low word, is ∛y within about 6 %. Then three
/// Halley steps t ← t·((t³ + 2y)/(2t³ + y)): 6 % → 10⁻⁴ → 10⁻¹² → below rounding. The
/// one-lane scalar fallback, whose f64 and u32 registers differ in size, calls libm.
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
    let two = F64s::splat(s, 2.0);
    for _ in 0..3 {
        let t3 = t * t * t;
        t = t * ((t3 + two * y) / (two * t3 + y));
    }
    t
}

/// cos(arccos(x)/3) for x ∈ [−1, 1]: the largest root t ∈ [½, 1] of 4t³ − 3t = x.
///
/// With u = 2t − 1 ∈ [0, 1] the cubic is u²(3 + u) = 2(1 + x), whose left side is
/// increasing and convex on u ≥ 0. Seed u₀ = min(√(2(1 + x)/3), 1), within 16 % (as
/// √(3 + u) ∈ [√3, 2]); three Halley steps bring that below rounding. Near x = −1 the
/// seed keeps its relative accuracy where the cubic has a double root, so no digits are
/// lost to it (the scalar solver sends lanes that close to a double root of the
/// resolvent to its careful path anyway).
#[inline(always)]
pub(crate) fn trisect_cos<S: Simd>(x: F64s<S>) -> F64s<S> {
    let s = x.s;
    macro_rules! c {
        ($x:expr) => {
            F64s::splat(s, $x)
        };
    }
    let rhs = c!(2.0) * (c!(1.0) + x);
    let mut u = (rhs / c!(3.0)).sqrt().min_num(c!(1.0));
    for _ in 0..3 {
        let f = u * u * (c!(3.0) + u) - rhs;
        let df = c!(6.0) * u + c!(3.0) * u * u;
        let d2f = c!(6.0) + c!(6.0) * u;
        u = u - c!(2.0) * f * df / (c!(2.0) * df * df - f * d2f);
    }
    // rhs = 0 (x = −1) has the double root u = 0, where Halley's step is 0/0.
    let u = rhs.gt(c!(0.0)).select(u, c!(0.0));
    c!(0.5) * (c!(1.0) + u)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::{Dispatch, Isa};
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
                    Kind::Trisect => trisect_cos(x),
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
