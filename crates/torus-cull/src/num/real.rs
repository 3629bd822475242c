//! [`Real`]: the thin number trait that lets a solver step be written once for the scalar
//! solver and for every lane width (docs/layout.md, "One source for scalar and lanes").
//!
//! One source for scalar and lane steps: a solver step is written once, generic over
//! [`Real`], and is the scalar step at width 1 and the lane step at every other width.
//! The trait holds only what the quartic solver and the exact intersection use:
//! `+ − × ÷`, `√`, `|x|`, `min`/`max`, `copysign`, comparisons into a [`RealMask`],
//! `select`, constants ([`Real::k`]), and "is any lane / every lane still active" for
//! early exits; and for the culls, glam's compare-and-select `min`/`max` and their
//! NaN-ignoring forms.
//!
//! It is implemented by the lane wrappers [`F64s<S>`] and [`F32s<S>`] of
//! [`super::lanes`]. `pulp::Scalar` is a [`pulp::Simd`] whose `f64s` is `f64` and whose
//! `m64s` is `bool`, so a step generic over `R: Real` instantiated at [`Sc`] =
//! `F64s<pulp::Scalar>` *is* the scalar step: the scalar solver in [`crate::quartic`]
//! wraps its `f64`s with [`sc`] and calls the same function the lanes call. A step at
//! width 1 keeps its early exits: `if !active.any() { return … }` is the scalar `if`.
//!
//! **Operation order.** Every method is one IEEE operation (or, for `min`/`max`, the
//! float type's own `min`/`max` at width 1 and its lane form, IEEE `minNum`/`maxNum`,
//! on wider lanes), never fused and never reordered, so a step computes the same bits at
//! every width; the bit-identity tests rest on that.

use super::cube_root::Cbrt;
use super::lanes::{F32s, F64s, M32s, M64s};
use pulp::Simd;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Not, Sub};

/// A lane mask of a [`Real`]: each lane true or false (at width 1, a `bool`).
pub trait RealMask:
    Copy + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self>
{
    /// Some lane is true (at width 1: the lane).
    fn any(self) -> bool;
    /// Every lane is true (at width 1: the lane).
    fn all(self) -> bool;
}

/// A float, or a register of float lanes, with the operations of the solver's steps.
///
/// Constants are made with [`Real::k`] from any value of the type (which carries the
/// SIMD token), so a step needs no token argument: `x.k(2.0)`.
pub trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Cbrt
{
    /// The lane mask of comparisons.
    type Mask: RealMask;
    /// How many lanes (1: the scalar instantiation). For a step whose two forms give the
    /// same bits but suit latency (one lane) or throughput (many) better.
    const LANES: usize;
    /// The constant `x` in every lane, with `self`'s SIMD token: rounded to the lane type
    /// (exact for an f64, or an f32 into f32 lanes). From any `f32` or `f64`, so that a
    /// step names its constants (`x.k(2.0)`, `o.x.k(AXIS_PARALLEL_H2)`) without a macro.
    fn k(self, x: impl Into<f64>) -> Self;
    /// The mask with every lane `value`, with `self`'s SIMD token.
    #[inline(always)]
    fn mask(self, value: bool) -> Self::Mask {
        let zero = self.k(0.0);
        if value { zero.eq(zero) } else { zero.lt(zero) }
    }
    /// `−x` (exact: flips the sign bit). Not the `Neg` operator on purpose: pulp's scalar
    /// "register" negates natively here, where the lane wrappers' `-` xors the sign bit
    /// through integer bit operations: at width 1 a round trip from float to integer bits
    /// and back on each negation of the solver's dependency chain.
    fn negate(self) -> Self;
    /// √x, correctly rounded.
    fn sqrt(self) -> Self;
    /// |x|.
    fn abs(self) -> Self;
    /// The float type's `min`: the smaller, ignoring a NaN operand.
    fn min(self, o: Self) -> Self;
    /// The float type's `max`: the larger, ignoring a NaN operand.
    fn max(self, o: Self) -> Self;
    /// glam's `min`: `if self < o { self } else { o }` (a NaN operand may come out).
    fn min_cmp(self, o: Self) -> Self;
    /// glam's `max`: `if self > o { self } else { o }`.
    fn max_cmp(self, o: Self) -> Self;
    /// The smaller, ignoring a NaN operand, chosen as [`Real::min_cmp`] chooses (at width
    /// 1 a branch on `o`'s NaN around it): the culls' clips, whose scalar form always was
    /// this select, where [`Real::min`] is the float type's own `min`.
    fn min_num(self, o: Self) -> Self;
    /// The larger, ignoring a NaN operand, chosen as [`Real::max_cmp`] chooses.
    fn max_num(self, o: Self) -> Self;
    /// The magnitude of `self` with the sign bit of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// `self < o`.
    fn lt(self, o: Self) -> Self::Mask;
    /// `self ≤ o`.
    fn le(self, o: Self) -> Self::Mask;
    /// `self > o`.
    fn gt(self, o: Self) -> Self::Mask;
    /// `self ≥ o`.
    fn ge(self, o: Self) -> Self::Mask;
    /// `self == o` (false for NaN).
    fn eq(self, o: Self) -> Self::Mask;
    /// `self != o` (true for NaN).
    #[inline(always)]
    fn ne(self, o: Self) -> Self::Mask {
        !self.eq(o)
    }
    /// `if mask { a } else { b }`, per lane.
    fn select(mask: Self::Mask, a: Self, b: Self) -> Self;
    /// Lanes that are finite (not ±∞, not NaN).
    fn is_finite(self) -> Self::Mask;
    /// Lanes that are NaN.
    #[inline(always)]
    fn is_nan(self) -> Self::Mask {
        self.ne(self)
    }
}

/// The scalar instantiation: one f64 in pulp's scalar "register".
pub type Sc = F64s<pulp::Scalar>;

/// `x` as the scalar instantiation of [`Real`].
#[inline(always)]
pub fn sc(x: f64) -> Sc {
    F64s {
        s: pulp::Scalar::new(),
        v: x,
    }
}

/// `b` as the scalar instantiation's mask.
#[inline(always)]
pub fn sc_mask(b: bool) -> M64s<pulp::Scalar> {
    M64s {
        s: pulp::Scalar::new(),
        m: b,
    }
}

/// Trait methods `fn f(self, o: Self) -> Self` (or `-> $mask<S>`, the comparisons) that
/// are the lane type's own `f`.
macro_rules! forward {
    ($name:ident: $($f:ident),*) => {$(
        #[inline(always)]
        fn $f(self, o: Self) -> Self {
            $name::$f(self, o)
        }
    )*};
    ($name:ident => $mask:ident: $($f:ident),*) => {$(
        #[inline(always)]
        fn $f(self, o: Self) -> $mask<S> {
            $name::$f(self, o)
        }
    )*};
}

macro_rules! real {
    ($name:ident, $mask:ident, $elem:ty, $m:ident, $lanes:ident, $neg:ident) => {
        impl<S: Simd> RealMask for $mask<S> {
            #[inline(always)]
            fn any(self) -> bool {
                if S::$lanes == 1 {
                    // The one lane's `bool`, by value (`bits` reads the mask's bytes).
                    pulp::bytemuck::cast::<S::$m, u8>(self.m) != 0
                } else {
                    self.bits() != 0
                }
            }
            #[inline(always)]
            fn all(self) -> bool {
                if S::$lanes == 1 {
                    self.any()
                } else {
                    self.bits() == u64::MAX >> (64 - S::$lanes)
                }
            }
        }

        impl<S: Simd> $name<S> {
            /// `f(self, o)` at width 1 (only there: the lanes are cast to one float), in the
            /// float type's own operation, as the scalar solver's code computes it.
            #[inline(always)]
            fn one_lane(self, o: Self, f: impl FnOnce($elem, $elem) -> $elem) -> Self {
                let (a, b): ($elem, $elem) =
                    (pulp::bytemuck::cast(self.v), pulp::bytemuck::cast(o.v));
                $name {
                    s: self.s,
                    v: pulp::bytemuck::cast(f(a, b)),
                }
            }
        }

        impl<S: Simd> Real for $name<S> {
            type Mask = $mask<S>;
            const LANES: usize = S::$lanes;
            #[inline(always)]
            fn k(self, x: impl Into<f64>) -> Self {
                $name::splat(self.s, x.into() as $elem)
            }
            #[inline(always)]
            fn negate(self) -> Self {
                $name {
                    s: self.s,
                    v: self.s.$neg(self.v),
                }
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $name::sqrt(self)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                if S::$lanes == 1 {
                    // At width 1, the float type's own operations (not pulp's bit
                    // manipulations through integer registers): the scalar solver's code.
                    let a: $elem = pulp::bytemuck::cast(self.v);
                    $name {
                        s: self.s,
                        v: pulp::bytemuck::cast(a.abs()),
                    }
                } else {
                    $name::abs(self)
                }
            }
            #[inline(always)]
            fn min(self, o: Self) -> Self {
                if S::$lanes == 1 {
                    // The float type's own `min`, which the scalar code always used
                    // (it may differ from the select below in the sign of a zero).
                    self.one_lane(o, <$elem>::min)
                } else {
                    self.min_num(o)
                }
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                if S::$lanes == 1 {
                    self.one_lane(o, <$elem>::max)
                } else {
                    self.max_num(o)
                }
            }
            forward!($name: min_cmp, max_cmp, min_num, max_num);
            #[inline(always)]
            fn copysign(self, sign: Self) -> Self {
                if S::$lanes == 1 {
                    self.one_lane(sign, <$elem>::copysign)
                } else {
                    $name::copysign(self, sign)
                }
            }
            forward!($name => $mask: lt, le, gt, ge, eq);
            #[inline(always)]
            fn is_finite(self) -> $mask<S> {
                $name::is_finite(self)
            }
            #[inline(always)]
            fn select(mask: $mask<S>, a: Self, b: Self) -> Self {
                if S::$lanes == 1 {
                    if mask.any() { a } else { b }
                } else {
                    mask.select(a, b)
                }
            }
        }
    };
}

real!(F64s, M64s, f64, m64s, F64_LANES, neg_f64s);
real!(F32s, M32s, f32, m32s, F32_LANES, neg_f32s);

/// [`Real`] on f32 lanes, with the one step the culls take beyond it: an exact rescale by
/// a power of two read from a float's exponent bits (integer lanes of f32 width).
pub trait Real32: Real {
    /// `self` times 2^(127 − e), e the biased exponent of `exp_of` (exact; see
    /// [`F32s::times_inverse_exponent`]).
    fn times_inverse_exponent(self, exp_of: Self) -> Self;
}

impl<S: Simd> Real32 for F32s<S> {
    #[inline(always)]
    fn times_inverse_exponent(self, exp_of: Self) -> Self {
        F32s::times_inverse_exponent(self, exp_of)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At width 1 the trait is the scalar arithmetic, bit for bit.
    #[test]
    fn scalar_instantiation_is_f64() {
        let xs = [
            0.0,
            -0.0,
            1.5,
            -2.25,
            1e-300,
            3e300,
            f64::INFINITY,
            f64::NAN,
        ];
        for &a in &xs {
            for &b in &xs {
                let (x, y) = (sc(a), sc(b));
                let same = |got: Sc, want: f64| {
                    assert_eq!(
                        got.v.to_bits(),
                        want.to_bits(),
                        "{a} {b}: {} vs {want}",
                        got.v
                    )
                };
                same(x + y, a + b);
                same(x.negate(), -a);
                same(x - y, a - b);
                same(x * y, a * b);
                same(x / y, a / b);
                same(Real::min(x, y), a.min(b));
                same(Real::max(x, y), a.max(b));
                same(Real::copysign(x, y), a.copysign(b));
                same(Real::sqrt(x), a.sqrt());
                same(Real::abs(x), a.abs());
                assert_eq!(Real::lt(x, y).any(), a < b);
                assert_eq!(Real::le(x, y).all(), a <= b);
                assert_eq!(Real::gt(x, y).any(), a > b);
                assert_eq!(Real::ge(x, y).all(), a >= b);
                assert_eq!(Real::eq(x, y).any(), a == b);
                assert_eq!(Real::ne(x, y).any(), a != b);
                same(Sc::select(Real::lt(x, y), x, y), if a < b { a } else { b });
            }
        }
    }
}
