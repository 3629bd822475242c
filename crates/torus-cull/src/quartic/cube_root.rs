//! The resolvent's two transcendental steps without libm: the cube root, and the
//! trisection `cos(arccos(x)/3)`. Each is the root of a cubic, so a polynomial seed good
//! to 2·10⁻⁶ and one Halley step (which cubes the relative error) replaces libm's `cbrt`,
//! `acos` and `cos` on the critical path: each is inline, a few bit operations or one
//! square root, a degree-5 polynomial and one division, where libm's are out-of-line
//! calls with their own range reduction (`acos` then `cos` a chain of two) and no lane
//! form.
//!
//! One source for the scalar solver and the lanes ([`Real`]): the polynomial seed, the
//! Halley step of the cube root and the whole trisection are generic; only the cube
//! root's seed (bits of one `f64` here, Kahan's bit trick on wider lanes in
//! `crate::batch::quartic::cube_root`) depends on the width.

use crate::batch::real::{Real, sc};

/// The degree-5 polynomial `c` (highest coefficient first) at `x`, by Estrin's scheme: half
/// the dependency chain of Horner's.
#[inline(always)]
fn poly5<R: Real>(c: &[f64; 6], x: R) -> R {
    // Macros, not closures, here and in every generic step: a closure that LLVM leaves
    // outlined would run without the SIMD target features.
    macro_rules! k {
        ($i:expr) => {
            x.splat(c[$i])
        };
    }
    let x2 = x * x;
    let x4 = x2 * x2;
    let low = k!(4) * x + k!(5);
    let mid = k!(2) * x + k!(3);
    let high = k!(0) * x + k!(1);
    (low + x2 * mid) + x4 * high
}

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

/// `u = 2 cos(arccos(x)/3) − 1` for x ∈ [−1, 1]: with `t = cos(arccos(x)/3)` the largest
/// root of `4t³ − 3t = x`, `u ∈ [0, 1]` is the root of `u²(3 + u) = 2(1 + x)`.
///
/// That root is `u = s·g(s)` with `s = √(2(1 + x)/3) ∈ [0, 2/√3]` and `g` smooth (`g(0) = 1`);
/// a degree-5 fit of `g` (error 1.7·10⁻⁶, relative) and one Halley step, which cubes the
/// relative error even next to the double root `u = 0` at `x = −1`.
#[inline(always)]
pub(crate) fn trisect_u<R: Real>(x: R) -> R {
    /// g(1/√3 + d) on [−1/√3, 1/√3].
    const FIT: [f64; 6] = [
        -0.0023725581002014035,
        0.005384607441641353,
        -0.011844823329350508,
        0.03242038506892554,
        -0.11181286004396555,
        0.9216062482255146,
    ];
    const HALF_RANGE: f64 = 0.5773502691896257;
    macro_rules! k {
        ($c:expr) => {
            x.splat($c)
        };
    }
    let rhs = k!(2.0) * (k!(1.0) + x);
    let s = (rhs * k!(1.0 / 3.0)).sqrt();
    let u = s * poly5(&FIT, s - k!(HALF_RANGE));
    let f = u * u * (k!(3.0) + u) - rhs;
    let df = (k!(3.0) * u + k!(6.0)) * u;
    let d2f = k!(6.0) * u + k!(6.0);
    let u = u - k!(2.0) * f * df / (k!(2.0) * df * df - f * d2f);
    // rhs = 0 (x = −1) has the double root u = 0, where Halley's step is 0/0.
    R::select(rhs.gt(k!(0.0)), u, k!(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cbrt_is_within_two_ulps_of_libm() {
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
}
