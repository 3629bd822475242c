//! Lane arithmetic: pulp's registers wrapped in operators, so that each cull kernel in
//! `src/cull/` reads like scalar code and runs at every width, `pulp::Scalar` (width 1,
//! the scalar cull) included.
//!
//! **Why the wrappers only ever do what the scalar code does.** IEEE 754 makes `+ − × ÷`
//! and `√` correctly rounded, lane by lane, whatever the vector width. Rust never fuses a
//! multiply and an add behind the programmer's back, and neither does pulp unless asked
//! (`mul_add`), which these wrappers never do. So a lane that evaluates the scalar cull's
//! expression tree in the same order gets the same bits, and the same verdict; the tests
//! in `tests/batch/batch.rs` check it on every line at every dispatch level.
//!
//! Two kinds of `min`/`max` appear in the scalar culls and are kept apart here:
//! glam's `Vec3::min`/`max`/`min_element`/`max_element` are `if a < b { a } else { b }`
//! (a NaN operand may come out), while `f32::min`/`max` ignore a NaN operand (IEEE
//! `minNum`). [`F32s::min_cmp`] and [`F32s::min_num`] are those two, exactly.

use pulp::Simd;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

/// The comparison methods `fn f(self, o: Self) -> $mask<S>` of a lane type, each one
/// pulp comparison.
macro_rules! lane_cmp {
    ($mask:ident: $($(#[$doc:meta])* $f:ident $simd:ident),*) => {$(
        $(#[$doc])*
        #[inline(always)]
        pub fn $f(self, o: Self) -> $mask<S> {
            $mask { s: self.s, m: self.s.$simd(self.v, o.v) }
        }
    )*};
}

/// Binary operator impls of a lane (or mask) type whose register is the field `$field`,
/// each one pulp operation.
macro_rules! lane_op {
    ($name:ident, $field:ident: $($op:ident $f:ident $simd:ident),*) => {$(
        impl<S: Simd> $op for $name<S> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                $name { s: self.s, $field: self.s.$simd(self.$field, o.$field) }
            }
        }
    )*};
}

macro_rules! lanes {
    (
        $(#[$doc:meta])* $name:ident, $mask:ident, $elem:ty, $vec:ident, $m:ident, $lanes:ident,
        $splat:ident, $add:ident, $sub:ident, $mul:ident, $div:ident, $sqrt:ident,
        $abs:ident, $lt:ident, $le:ident, $gt:ident, $ge:ident, $eq:ident,
        $select:ident, $and_m:ident, $or_m:ident, $not_m:ident, $and_f:ident,
        $or_f:ident, $xor_f:ident
    ) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy)]
        pub struct $name<S: Simd> {
            /// The instruction set's token.
            pub s: S,
            /// The lanes.
            pub v: S::$vec,
        }

        /// A lane mask: each lane true or false.
        #[derive(Debug, Clone, Copy)]
        pub struct $mask<S: Simd> {
            pub s: S,
            pub m: S::$m,
        }

        impl<S: Simd> $name<S> {
            #[doc = concat!(
                "The lanes of `slice` (exactly `S::", stringify!($lanes), "` values)."
            )]
            #[inline(always)]
            pub fn load(s: S, slice: &[$elem]) -> Self {
                $name {
                    s,
                    v: pulp::bytemuck::pod_read_unaligned(
                        pulp::bytemuck::cast_slice::<$elem, u8>(slice),
                    ),
                }
            }
            #[doc = concat!(
                "Writes the lanes to `slice` (exactly `S::", stringify!($lanes), "` values)."
            )]
            #[inline(always)]
            pub fn store(self, slice: &mut [$elem]) {
                pulp::bytemuck::cast_slice_mut::<$elem, u8>(slice)
                    .copy_from_slice(pulp::bytemuck::bytes_of(&self.v));
            }
            /// Every lane `x`.
            #[inline(always)]
            pub fn splat(s: S, x: $elem) -> Self {
                $name { s, v: s.$splat(x) }
            }
            /// √x, correctly rounded.
            #[inline(always)]
            pub fn sqrt(self) -> Self {
                $name { s: self.s, v: self.s.$sqrt(self.v) }
            }
            /// |x| (clears the sign bit, as `abs` does).
            #[inline(always)]
            pub fn abs(self) -> Self {
                $name { s: self.s, v: self.s.$abs(self.v) }
            }
            lane_cmp!($mask:
                /// `self < o`.
                lt $lt,
                /// `self ≤ o`.
                le $le,
                /// `self > o`.
                gt $gt,
                /// `self ≥ o`.
                ge $ge,
                /// `self == o` (false for NaN).
                eq $eq
            );
            /// Lanes that are finite (neither infinite nor NaN).
            #[allow(dead_code, reason = "generated for f32 and f64 lanes; only one width uses it")]
            #[inline(always)]
            pub fn is_finite(self) -> $mask<S> {
                self.abs().le(Self::splat(self.s, <$elem>::MAX))
            }
            /// Lanes that are NaN.
            #[inline(always)]
            pub fn is_nan(self) -> $mask<S> {
                !self.eq(self)
            }
            /// glam's `min`: `if self < o { self } else { o }`.
            #[inline(always)]
            pub fn min_cmp(self, o: Self) -> Self {
                self.lt(o).select(self, o)
            }
            /// glam's `max`: `if self > o { self } else { o }`.
            #[inline(always)]
            pub fn max_cmp(self, o: Self) -> Self {
                self.gt(o).select(self, o)
            }
            /// `min` of the float type: the smaller, ignoring a NaN operand.
            ///
            /// At width 1 the same choice is made as a branch on `o`'s NaN (never taken on
            /// sane input) around [`Self::min_cmp`]: `(a < b ∨ b ≠ b) ? a : b`
            /// is `b ≠ b ? a : (a < b ? a : b)`, bit for bit, signed zeros included.
            #[inline(always)]
            pub fn min_num(self, o: Self) -> Self {
                if S::$lanes == 1 {
                    return if o.is_nan().bits() != 0 { self } else { self.min_cmp(o) };
                }
                (self.lt(o) | o.is_nan()).select(self, o)
            }
            /// `max` of the float type: the larger, ignoring a NaN operand (at width 1 a
            /// branch around [`Self::max_cmp`], as in [`Self::min_num`]).
            #[inline(always)]
            pub fn max_num(self, o: Self) -> Self {
                if S::$lanes == 1 {
                    return if o.is_nan().bits() != 0 { self } else { self.max_cmp(o) };
                }
                (self.gt(o) | o.is_nan()).select(self, o)
            }
            /// `self.copysign(sign)`: the magnitude of `self` with the sign bit of `sign`.
            #[inline(always)]
            pub fn copysign(self, sign: Self) -> Self {
                let s = self.s;
                let sign_bit = s.$and_f(sign.v, s.$splat(-0.0));
                $name { s, v: s.$or_f(s.$abs(self.v), sign_bit) }
            }
        }

        impl<S: Simd> $mask<S> {
            /// Bit i of the result is lane i (at most 64 lanes).
            #[inline(always)]
            pub fn bits(self) -> u64 {
                lane_bits(&self.m, S::$lanes)
            }
            /// `if self { a } else { b }`, per lane.
            #[inline(always)]
            pub fn select(self, a: $name<S>, b: $name<S>) -> $name<S> {
                $name { s: self.s, v: self.s.$select(self.m, a.v, b.v) }
            }
            /// `if self { a } else { b }` for masks.
            #[allow(dead_code, reason = "generated for f32 and f64 lanes; only one width uses it")]
            #[inline(always)]
            pub fn select_mask(self, a: $mask<S>, b: $mask<S>) -> $mask<S> {
                (self & a) | (!self & b)
            }
        }

        lane_op!($name, v: Add add $add, Sub sub $sub, Mul mul $mul, Div div $div);
        impl<S: Simd> Neg for $name<S> {
            type Output = Self;
            /// Flips the sign bit, as scalar negation does (exact).
            #[inline(always)]
            fn neg(self) -> Self {
                let s = self.s;
                $name { s, v: s.$xor_f(self.v, s.$splat(-0.0)) }
            }
        }
        lane_op!($mask, m: BitAnd bitand $and_m, BitOr bitor $or_m);
        impl<S: Simd> Not for $mask<S> {
            type Output = Self;
            #[inline(always)]
            fn not(self) -> Self {
                $mask { s: self.s, m: self.s.$not_m(self.m) }
            }
        }
    };
}

lanes!(
    /// f32 lanes (16 with AVX-512, 8 with AVX2, 4 with NEON, 1 in the scalar fallback).
    F32s, M32s, f32, f32s, m32s, F32_LANES,
    splat_f32s, add_f32s, sub_f32s, mul_f32s, div_f32s, sqrt_f32s, abs_f32s,
    less_than_f32s, less_than_or_equal_f32s, greater_than_f32s,
    greater_than_or_equal_f32s, equal_f32s, select_f32s, and_m32s, or_m32s, not_m32s,
    and_f32s, or_f32s, xor_f32s
);

lanes!(
    /// f64 lanes (8 with AVX-512, 4 with AVX2, 2 with NEON, 1 in the scalar fallback).
    F64s, M64s, f64, f64s, m64s, F64_LANES,
    splat_f64s, add_f64s, sub_f64s, mul_f64s, div_f64s, sqrt_f64s, abs_f64s,
    less_than_f64s, less_than_or_equal_f64s, greater_than_f64s,
    greater_than_or_equal_f64s, equal_f64s, select_f64s, and_m64s, or_m64s, not_m64s,
    and_f64s, or_f64s, xor_f64s
);

impl<S: Simd> F32s<S> {
    /// `self` times the power of two 2^(127 − e), e the biased exponent of `exp_of`:
    /// the integer half of [`crate::cull`]'s `rescaled` (exact). An infinite or NaN
    /// `exp_of` (e = 255) is taken as e = 254 (factor 2⁻¹²⁷ → 1: `self` unchanged), so the
    /// exponent arithmetic never wraps whatever the input.
    #[inline(always)]
    pub fn times_inverse_exponent(self, exp_of: Self) -> Self {
        let s = self.s;
        let bits = s.transmute_u32s_f32s(exp_of.v);
        let exponent = s.min_u32s(
            s.and_u32s(
                s.wrapping_dyn_shr_u32s(bits, s.splat_u32s(23)),
                s.splat_u32s(0xff),
            ),
            s.splat_u32s(254),
        );
        let scale_bits =
            s.wrapping_dyn_shl_u32s(s.sub_u32s(s.splat_u32s(254), exponent), s.splat_u32s(23));
        self * F32s {
            s,
            v: s.transmute_f32s_u32s(scale_bits),
        }
    }
}

impl<S: Simd> M32s<S> {
    /// All lanes `value`.
    #[inline(always)]
    pub fn splat(s: S, value: bool) -> Self {
        let zero = F32s::splat(s, 0.0);
        if value { zero.eq(zero) } else { zero.lt(zero) }
    }
}

/// A mask register as bits. pulp gives AVX-512 masks as bit masks already (`b8`, `b16`:
/// one byte or two); every other level as one all-ones or all-zeros element per lane,
/// whose top bit is the lane's bit.
#[inline(always)]
fn lane_bits<M: pulp::bytemuck::NoUninit>(mask: &M, lanes: usize) -> u64 {
    let bytes = pulp::bytemuck::bytes_of(mask);
    match bytes.len() {
        1 => u64::from(bytes[0]),
        2 => u64::from(u16::from_le_bytes([bytes[0], bytes[1]])),
        n => {
            let width = n / lanes;
            let mut out = 0u64;
            for lane in 0..lanes {
                // The lane's most significant byte (little-endian) carries its top bit.
                let top = bytes[lane * width + width - 1] >> 7;
                out |= u64::from(top) << lane;
            }
            out
        }
    }
}
