//! Polynomial evaluation on any [`Real`], for the fitted seeds of the cube root and the
//! trisection.

use super::real::Real;

/// The degree-5 polynomial `c` (highest coefficient first) at `x`, by Estrin's scheme: half
/// the dependency chain of Horner's.
#[inline(always)]
pub(crate) fn poly5<R: Real>(c: &[f64; 6], x: R) -> R {
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
