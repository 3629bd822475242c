//! The number layer, on the ground floor: everything the culls, the solver and the exact
//! intersection compute with, and nothing above it.
//!
//! * [`lanes`]: pulp's registers wrapped in operators ([`F32s`], [`F64s`] and their masks
//!   [`M32s`](lanes::M32s), [`M64s`]); at `pulp::Scalar` (width 1) a lane is one float and a mask a
//!   `bool`.
//! * [`real`]: the [`Real`] trait, the operations a solver step needs, so that one generic
//!   function is the scalar step at width 1 ([`Sc`]) and the lane step on wider registers.
//! * [`v3`]: [`V3`], one 3-vector per lane ([`Vec3s`] over f32 lanes, [`DVec3s`] over f64).
//! * [`cube_root`] and [`poly`]: the cube root's scalar and lane seeds with their shared
//!   Halley step, and the fitted polynomials' evaluation.
//! * [`isa`]: the instruction set, detected at run time ([`Dispatch`], [`Isa`]).
//! * `round`: f64 values rounded to f32 up or down, for boxes and bounds.
//!
//! Every operation is one IEEE operation, never fused or reordered, so a step computes the
//! same bits at every width; the bit-identity of scalar and lane verdicts rests on that.

pub mod cube_root;
pub(crate) mod fixed_list;
pub mod isa;
pub mod lanes;
pub mod poly;
pub mod real;
pub(crate) mod round;
pub mod v3;

pub(crate) use cube_root::CBRT_RANGE;
pub(crate) use fixed_list::fixed_list;
pub use isa::{Dispatch, ISA_ENV, Isa, IsaError};
pub use lanes::{F32s, F64s, M64s};
pub(crate) use poly::poly5;
pub use real::{Real, Real32, RealMask, Sc, sc, sc_mask};
pub use v3::{DVec3s, V3, Vec3s};

/// Runs a lane function over a list of f64s at every instruction set this CPU has, for the
/// number layer's and the solver's lane tests.
#[cfg(test)]
pub(crate) mod lane_tests {
    use super::{Dispatch, F64s, Isa};
    use pulp::{Simd, WithSimd};

    /// A function of one f64 register, at any width.
    pub(crate) trait LaneFn {
        fn call<S: Simd>(x: F64s<S>) -> F64s<S>;
    }

    struct Apply<'a, F>(&'a [f64], std::marker::PhantomData<F>);

    impl<F: LaneFn> WithSimd for Apply<'_, F> {
        type Output = Vec<f64>;
        #[inline(always)]
        fn with_simd<S: Simd>(self, s: S) -> Vec<f64> {
            let n = S::F64_LANES;
            let mut out = Vec::new();
            for chunk in self.0.chunks(n) {
                // Padded with 1.0, a value every tested function takes.
                let mut lanes = vec![1.0; n];
                lanes[..chunk.len()].copy_from_slice(chunk);
                let v = F::call(F64s::load(s, &lanes)).v;
                let got = pulp::bytemuck::cast_slice::<S::f64s, f64>(std::slice::from_ref(&v));
                out.extend_from_slice(&got[..chunk.len()]);
            }
            out
        }
    }

    /// `F` on `xs`, once per available instruction set.
    pub(crate) fn on_every_isa<F: LaneFn>(xs: &[f64]) -> Vec<(Isa, Vec<f64>)> {
        Isa::available()
            .into_iter()
            .map(|isa| {
                let dispatch = Dispatch::forced(isa).expect("an available ISA");
                (isa, dispatch.run(Apply::<F>(xs, std::marker::PhantomData)))
            })
            .collect()
    }
}
