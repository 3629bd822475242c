//! The batch culls: each cull's one kernel (in [`crate::cull`]) over SIMD lanes.
//!
//! There is nothing to mirror here any more: the kernel that [`crate::Cull::keeps`] runs
//! at `pulp::Scalar` is the kernel this module runs at the dispatch level, so each batch
//! verdict is the scalar verdict, bit for bit (see `src/num/lanes.rs` for why the
//! arithmetic agrees, and `tests/batch/batch.rs` for the check at every dispatch level). What
//! is left is the loop over blocks of lines, inside pulp's `#[target_feature]` context.

use super::lines::{BLOCK, Lines};
use super::mask::KeepMask;
use crate::CullBounds;
use crate::cull::BatchCull;
use crate::cull::KernelVisitor;
use crate::cull::kernel::{CullKernel, LaneBounds};
use crate::num::Dispatch;
use crate::num::F32s;
use crate::num::Vec3s;
use pulp::{Simd, WithSimd};

/// Runs `cull` on every line of `lines` at the dispatch level `dispatch`, writing one
/// keep bit per line into `keep` (resized to `lines.len()`).
///
/// Bit `i` equals `cull.keeps(bounds, line i)` of the scalar cull, bit for bit. Like
/// [`crate::Cull::keeps`] it works in the torus frame: `bounds` is
/// [`crate::Torus::bounds`] of the torus whose frame `lines` are in.
pub fn cull_batch(
    dispatch: &Dispatch,
    cull: BatchCull,
    bounds: &CullBounds,
    lines: &Lines,
    keep: &mut KeepMask,
) {
    /// Runs the visited kernel at `dispatch`.
    struct Visit<'a> {
        dispatch: &'a Dispatch,
        bounds: &'a CullBounds,
        lines: &'a Lines,
        words: &'a mut [u64],
    }
    impl KernelVisitor for Visit<'_> {
        type Output = ();
        fn visit<K: CullKernel>(self, kernel: K) {
            self.dispatch.run(Run {
                kernel,
                bounds: self.bounds,
                lines: self.lines,
                words: self.words,
            });
        }
    }

    keep.resize(lines.len());
    cull.visit_kernel(Visit {
        dispatch,
        bounds,
        lines,
        words: &mut keep.words,
    });
    keep.clear_tail();
}

/// One kernel over every block of lines, inside pulp's `#[target_feature]` context.
struct Run<'a, K> {
    kernel: K,
    bounds: &'a CullBounds,
    lines: &'a Lines,
    words: &'a mut [u64],
}

impl<K: CullKernel> WithSimd for Run<'_, K> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = S::F32_LANES;
        debug_assert!(BLOCK % lanes == 0);
        let Run {
            kernel,
            bounds,
            lines,
            words,
        } = self;
        // The bounds in lanes, once for every block.
        let bounds = LaneBounds::new(bounds, F32s::splat(s, 0.0));
        let [ox, oy, oz] = &lines.origin;
        let [dx, dy, dz] = &lines.dir;
        for (block, word) in words.iter_mut().enumerate().take(lines.blocks()) {
            let base = block * BLOCK;
            let mut bits = 0u64;
            // The last block stops at the register holding the last line: a small batch
            // (a BVH leaf's rays) pays for its own lanes, not for a whole block.
            for k in (0..BLOCK.min(lines.len() - base)).step_by(lanes) {
                let at = base + k..base + k + lanes;
                // A macro, not a closure: a closure that LLVM leaves outlined would run
                // without the SIMD target features.
                macro_rules! load {
                    ($v:expr) => {
                        F32s::load(s, &$v[at.clone()])
                    };
                }
                let origin = Vec3s::new(load!(ox), load!(oy), load!(oz));
                let dir = Vec3s::new(load!(dx), load!(dy), load!(dz));
                bits |= kernel.keeps_lanes(&bounds, origin, dir).bits() << k;
            }
            *word = bits;
        }
    }
}
