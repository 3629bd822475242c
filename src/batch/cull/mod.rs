//! The batch culls: each scalar cull of [`crate::cull`] over SIMD lanes, branch-free.
//!
//! Every file here mirrors the scalar file of the same name: the same bound, the same
//! padded [`CullBounds`], the same expressions in the same operation order. Where the
//! scalar cull leaves early (`skala`, `quadric`, `thick_cylinder`), the batch cull
//! evaluates every case on every lane and selects, which changes nothing a lane computes:
//! so each batch verdict is the scalar verdict, bit for bit (see [`super::lanes`] for
//! why the arithmetic agrees, and `tests/batch.rs` for the check at every dispatch
//! level).

mod aabb;
mod cychosz;
mod discriminant;
mod ellipsoid;
mod quadric;
mod skala;
mod sphere;
mod thick_cylinder;

use super::isa::Dispatch;
use super::lanes::{F32s, M32s};
use super::lines::{BLOCK, Lines};
use super::mask::KeepMask;
use super::vec3s::Vec3s;
use crate::cull::{MODERATE_HIGH, MODERATE_LOW};
use crate::{CullBounds, CullKind};
use pulp::{Simd, WithSimd};
use std::fmt;

/// One cull over the lanes of a SIMD register.
pub(crate) trait LaneCull: Copy {
    /// The verdict for each lane's line: true keeps it.
    fn keeps<S: Simd>(self, s: S, b: &CullBounds, origin: Vec3s<S>, dir: Vec3s<S>) -> M32s<S>;
}

/// `none`: keeps everything (the baseline of a wavefront).
#[derive(Clone, Copy)]
struct KeepAll;

impl LaneCull for KeepAll {
    #[inline(always)]
    fn keeps<S: Simd>(self, s: S, _: &CullBounds, _: Vec3s<S>, _: Vec3s<S>) -> M32s<S> {
        M32s::splat(s, true)
    }
}

/// The culls with a batch form, in [`CullKind::TIMED`] order. `discriminant_f64` has
/// none: its point is the f64 evaluation, which the f32 `discriminant` already makes
/// unnecessary at this padding.
pub const BATCHED: [CullKind; 9] = [
    CullKind::None,
    CullKind::Sphere,
    CullKind::Aabb,
    CullKind::Cychosz,
    CullKind::ThickCylinder,
    CullKind::Skala,
    CullKind::Ellipsoid,
    CullKind::Quadric,
    CullKind::Discriminant,
];

/// A cull without a batch form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NoBatchForm(pub CullKind);

impl fmt::Display for NoBatchForm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = BATCHED.iter().map(|c| c.name()).collect();
        write!(
            f,
            "cull '{}' has no batch form (batched: {})",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for NoBatchForm {}

/// Runs `cull` on every line of `lines` at the dispatch level `dispatch`, writing one
/// keep bit per line into `keep` (resized to `lines.len()`).
///
/// Bit `i` equals `cull.keeps(bounds, line i)` of the scalar cull, bit for bit.
pub fn cull_batch(
    dispatch: &Dispatch,
    cull: CullKind,
    bounds: &CullBounds,
    lines: &Lines,
    keep: &mut KeepMask,
) -> Result<(), NoBatchForm> {
    keep.resize(lines.len());
    let words = &mut keep.words[..];
    match cull {
        CullKind::None => dispatch.run(Run {
            cull: KeepAll,
            bounds,
            lines,
            words,
        }),
        CullKind::Sphere => dispatch.run(Run {
            cull: sphere::Sphere,
            bounds,
            lines,
            words,
        }),
        CullKind::Aabb => dispatch.run(Run {
            cull: aabb::Aabb,
            bounds,
            lines,
            words,
        }),
        CullKind::Cychosz => dispatch.run(Run {
            cull: cychosz::Cychosz,
            bounds,
            lines,
            words,
        }),
        CullKind::ThickCylinder => dispatch.run(Run {
            cull: thick_cylinder::ThickCylinder,
            bounds,
            lines,
            words,
        }),
        CullKind::Skala => dispatch.run(Run {
            cull: skala::Skala,
            bounds,
            lines,
            words,
        }),
        CullKind::Ellipsoid => dispatch.run(Run {
            cull: ellipsoid::Ellipsoid,
            bounds,
            lines,
            words,
        }),
        CullKind::Quadric => dispatch.run(Run {
            cull: quadric::Quadric,
            bounds,
            lines,
            words,
        }),
        CullKind::Discriminant => dispatch.run(Run {
            cull: discriminant::Discriminant,
            bounds,
            lines,
            words,
        }),
        other => return Err(NoBatchForm(other)),
    }
    keep.clear_tail();
    Ok(())
}

/// One cull over every block of lines, inside pulp's `#[target_feature]` context.
struct Run<'a, C> {
    cull: C,
    bounds: &'a CullBounds,
    lines: &'a Lines,
    words: &'a mut [u64],
}

impl<C: LaneCull> WithSimd for Run<'_, C> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = S::F32_LANES;
        debug_assert!(BLOCK % lanes == 0);
        let Run {
            cull,
            bounds,
            lines,
            words,
        } = self;
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
                bits |= cull.keeps(s, bounds, origin, dir).bits() << k;
            }
            *word = bits;
        }
    }
}

/// [`crate::cull`]'s `foot_point` over lanes: p = o − d (o·d)/|d|², and 1/|d|².
#[inline(always)]
pub(crate) fn foot_point<S: Simd>(origin: Vec3s<S>, dir: Vec3s<S>) -> (Vec3s<S>, F32s<S>) {
    let one = F32s::splat(origin.x.s, 1.0);
    let inv_len_sq = one / dir.length_squared();
    (origin - dir * (origin.dot(dir) * inv_len_sq), inv_len_sq)
}

/// [`crate::cull`]'s `rescaled` over lanes: `v` times the power of two that brings its
/// largest component into [1, 2) (exact).
#[inline(always)]
pub(crate) fn rescaled<S: Simd>(v: Vec3s<S>) -> Vec3s<S> {
    let largest = v.abs().max_element();
    Vec3s::new(
        v.x.times_inverse_exponent(largest),
        v.y.times_inverse_exponent(largest),
        v.z.times_inverse_exponent(largest),
    )
}

/// [`crate::cull`]'s `moderate` over lanes: `v` when |v|² ∈ (2⁻⁴⁰, 2⁴⁰), else
/// [`rescaled`] (selected, not branched).
#[inline(always)]
pub(crate) fn moderate<S: Simd>(v: Vec3s<S>) -> Vec3s<S> {
    let s = v.x.s;
    let len_sq = v.length_squared();
    let plain = len_sq.gt(F32s::splat(s, MODERATE_LOW)) & len_sq.lt(F32s::splat(s, MODERATE_HIGH));
    let r = rescaled(v);
    Vec3s::new(
        plain.select(v.x, r.x),
        plain.select(v.y, r.y),
        plain.select(v.z, r.z),
    )
}
