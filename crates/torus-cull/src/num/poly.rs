//! Polynomial evaluation on one float or a register of lanes, for the fitted seeds of the
//! cube root and the trisection.

use std::ops::{Add, Mul};

/// The degree-5 polynomial `c` (highest coefficient first, already in `x`'s type) at `x`,
/// by Estrin's scheme: half the dependency chain of Horner's. The same operations in the
/// same order at every width, so a scalar and a lane evaluation give the same bits.
#[inline(always)]
pub(crate) fn poly5<T>(c: [T; 6], x: T) -> T
where
    T: Copy + Add<Output = T> + Mul<Output = T>,
{
    let x2 = x * x;
    let x4 = x2 * x2;
    let low = c[4] * x + c[5];
    let mid = c[2] * x + c[3];
    let high = c[0] * x + c[1];
    (low + x2 * mid) + x4 * high
}
