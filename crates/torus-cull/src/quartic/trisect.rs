//! The resolvent's trisection `cos(arccos(x)/3)` without libm: the root of a cubic, so a
//! polynomial seed good to 2·10⁻⁶ and one Halley step replace libm's `acos` and `cos` on
//! the critical path: inline, one square root, a degree-5 polynomial and one division,
//! where libm's are out-of-line calls with their own range reduction (`acos` then `cos`, a
//! chain of two) and no lane form. Generic over [`Real`]: the scalar solver and the lanes call the same
//! function.

use crate::num::{Real, poly5};

/// g(1/√3 + d) on [−1/√3, 1/√3]: the degree-5 fit of [`trisect_u`] (also the GPU
/// kernel's, generated from here: `crate::gpu`'s kernel source).
pub(crate) const FIT: [f64; 6] = [
    -0.0023725581002014035,
    0.005384607441641353,
    -0.011844823329350508,
    0.03242038506892554,
    -0.11181286004396555,
    0.9216062482255146,
];

/// The fit's centre, 1/√3.
pub(crate) const HALF_RANGE: f64 = 0.5773502691896257;

/// `u = 2 cos(arccos(x)/3) − 1` for x ∈ [−1, 1]: with `t = cos(arccos(x)/3)` the largest
/// root of `4t³ − 3t = x`, `u ∈ [0, 1]` is the root of `u²(3 + u) = 2(1 + x)`.
///
/// That root is `u = s·g(s)` with `s = √(2(1 + x)/3) ∈ [0, 2/√3]` and `g` smooth (`g(0) = 1`);
/// a degree-5 fit of `g` (error 1.7·10⁻⁶, relative) and one Halley step, which cubes the
/// relative error even next to the double root `u = 0` at `x = −1`.
#[inline(always)]
pub(crate) fn trisect_u<R: Real>(x: R) -> R {
    let rhs = x.k(2.0) * (x.k(1.0) + x);
    let s = (rhs * x.k(1.0 / 3.0)).sqrt();
    let fit = [
        x.k(FIT[0]),
        x.k(FIT[1]),
        x.k(FIT[2]),
        x.k(FIT[3]),
        x.k(FIT[4]),
        x.k(FIT[5]),
    ];
    let u = s * poly5(fit, s - x.k(HALF_RANGE));
    let f = u * u * (x.k(3.0) + u) - rhs;
    let df = (x.k(3.0) * u + x.k(6.0)) * u;
    let d2f = x.k(6.0) * u + x.k(6.0);
    let u = u - x.k(2.0) * f * df / (x.k(2.0) * df * df - f * d2f);
    // rhs = 0 (x = −1) has the double root u = 0, where Halley's step is 0/0.
    R::select(rhs.gt(x.k(0.0)), u, x.k(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::F64s;
    use crate::num::lane_tests::{LaneFn, on_every_isa};
    use crate::num::sc;
    use pulp::Simd;

    #[test]
    fn trisection_matches_cos_of_a_third_of_acos() {
        let mut xs: Vec<f64> = (0..=20_000)
            .map(|i| -1.0 + f64::from(i) / 10_000.0)
            .collect();
        xs.extend([
            -1.0 + 1e-15,
            -1.0 + 1e-12,
            -1.0 + 1e-9,
            -1.0 + 1e-6,
            1.0 - 1e-12,
        ]);
        for x in xs {
            let (got, want) = (0.5 * (1.0 + trisect_u(sc(x)).v), (x.acos() / 3.0).cos());
            assert!(
                (got - want).abs() <= 2.0 * f64::EPSILON,
                "x = {x}: {got} vs {want}"
            );
        }
    }

    struct Trisect;
    impl LaneFn for Trisect {
        #[inline(always)]
        fn call<S: Simd>(x: F64s<S>) -> F64s<S> {
            x.k(0.5) * (x.k(1.0) + trisect_u(x))
        }
    }

    #[test]
    fn lane_trisection_matches_cos_of_a_third_of_acos() {
        let mut xs: Vec<f64> = (0..=4000).map(|i| -1.0 + f64::from(i) / 2000.0).collect();
        xs.extend([-1.0 + 1e-15, -1.0 + 1e-9, -1.0 + 1e-6, 1.0 - 1e-12]);
        for (isa, got) in on_every_isa::<Trisect>(&xs) {
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
