//! The batch solver: the nearest root in [lo, hi] of many depressed monic quartics
//! u⁴ + p u² + q u + r at once, on f64 lanes.
//!
//! Same method as the scalar [`crate::quartic::nearest_root_depressed`], and mostly the
//! same source: the resolvent's steps, Ferrari's split and the nearest-root pick of the
//! common ("clear") path are the scalar solver's own functions, generic over
//! `crate::num::Real` and instantiated here on f64 lanes. What this driver does
//! differently is branch-free: both resolvent formulas are evaluated where any lane of a
//! register needs them and selected. The rare lanes that need the scalar solver's
//! careful paths (a near-double root of the resolvent, or a factor whose discriminant is
//! within rounding of zero: tangent lines) are flagged and solved by the scalar solver
//! afterwards, so the accuracy is the scalar solver's: 0 missed and 0 spurious roots
//! against the oracle on the solver families (checked in `tests/batch/batch_solve.rs`).
//!
//! The roots are not bit-identical to the scalar solver's, because the driver differs
//! where a lane cannot branch: every lane's resolvent root gets the two Newton steps
//! (the scalar solver polishes only where the closed form loses digits), a small Cardano
//! root is polished rather than taken in Vieta's form, and the cube root starts from a
//! lane seed (`cube_root.rs`).

use super::lines::BLOCK;
use super::mask::set_bits;
use crate::num::Dispatch;
use crate::num::F64s;
use crate::quartic::nearest_root_depressed;
use pulp::{Simd, WithSimd};

/// Depressed monic quartics u⁴ + p u² + q u + r with a search interval [lo, hi] each,
/// structure of arrays, padded to whole blocks (with u⁴ − 1 on [0, 0], whose answer is
/// dropped).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Quartics {
    len: usize,
    /// p, q, r, lo, hi.
    columns: [Vec<f64>; 5],
}

impl Quartics {
    /// None.
    pub fn new() -> Quartics {
        Quartics::default()
    }

    /// Removes every quartic (keeps the memory).
    pub fn clear(&mut self) {
        self.len = 0;
        for c in &mut self.columns {
            c.clear();
        }
    }

    /// Appends u⁴ + p u² + q u + r, searched on [lo, hi] (either end may be infinite).
    #[inline]
    pub fn push(&mut self, p: f64, q: f64, r: f64, lo: f64, hi: f64) {
        if self.len == self.columns[0].len() {
            for (c, pad) in self.columns.iter_mut().zip([0.0, 0.0, -1.0, 0.0, 0.0]) {
                c.resize(c.len() + BLOCK, pad);
            }
        }
        for (c, v) in self.columns.iter_mut().zip([p, q, r, lo, hi]) {
            c[self.len] = v;
        }
        self.len += 1;
    }

    /// How many quartics.
    pub fn len(&self) -> usize {
        self.len
    }

    /// None.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Quartic `i` as `(p, q, r, lo, hi)`.
    ///
    /// # Panics
    ///
    /// If `i ≥ self.len()`.
    #[must_use]
    pub fn get(&self, i: usize) -> (f64, f64, f64, f64, f64) {
        assert!(i < self.len, "quartic {i} of {}", self.len);
        let c = &self.columns;
        (c[0][i], c[1][i], c[2][i], c[3][i], c[4][i])
    }
}

/// How a batch solve went: how many lanes the scalar solver took over.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SolveStats {
    /// Quartics solved.
    pub quartics: usize,
    /// Of them, solved by the scalar solver (near-double resolvent roots, near-tangent
    /// factors, non-finite input).
    pub scalar_fallbacks: usize,
}

/// The nearest root in [lo, hi] of every quartic, into `roots` (resized; `None` where
/// there is none): `roots[i]` answers `quartics.get(i)` as
/// [`nearest_root_depressed`] would, to rounding.
pub fn nearest_roots(
    dispatch: &Dispatch,
    quartics: &Quartics,
    roots: &mut Vec<Option<f64>>,
) -> SolveStats {
    let padded = quartics.columns[0].len();
    let mut raw = vec![0.0; padded];
    let mut fallback = vec![0u64; padded / BLOCK];
    dispatch.run(Solve {
        quartics,
        roots: &mut raw,
        fallback: &mut fallback,
    });
    let mut stats = SolveStats {
        quartics: quartics.len(),
        scalar_fallbacks: 0,
    };
    roots.clear();
    roots.extend(
        raw[..quartics.len()]
            .iter()
            .map(|&u| (!u.is_nan()).then_some(u)),
    );
    for i in set_bits(&fallback, quartics.len()) {
        let (p, q, r, lo, hi) = quartics.get(i);
        roots[i] = nearest_root_depressed(p, q, r, lo, hi);
        stats.scalar_fallbacks += 1;
    }
    stats
}

/// The lane kernel over every block, inside pulp's `#[target_feature]` context.
struct Solve<'a> {
    quartics: &'a Quartics,
    roots: &'a mut [f64],
    fallback: &'a mut [u64],
}

impl WithSimd for Solve<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = S::F64_LANES;
        debug_assert!(BLOCK % lanes == 0);
        let [p, q, r, lo, hi] = &self.quartics.columns;
        for (block, word) in self.fallback.iter_mut().enumerate() {
            let mut bits = 0u64;
            // The last block stops at the register holding the last quartic.
            for k in (0..BLOCK.min(self.quartics.len() - block * BLOCK)).step_by(lanes) {
                let at = block * BLOCK + k..block * BLOCK + k + lanes;
                // A macro, not a closure: a closure that LLVM leaves outlined would run
                // without the SIMD target features.
                macro_rules! load {
                    ($v:expr) => {
                        F64s::load(s, &$v[at.clone()])
                    };
                }
                let (root, cold) = crate::quartic::lanes::nearest_root(
                    load!(p),
                    load!(q),
                    load!(r),
                    load!(lo),
                    load!(hi),
                );
                let out = pulp::bytemuck::cast_slice_mut::<f64, u8>(&mut self.roots[at]);
                out.copy_from_slice(pulp::bytemuck::bytes_of(&root.v));
                bits |= cold.bits() << k;
            }
            *word = bits;
        }
    }
}
