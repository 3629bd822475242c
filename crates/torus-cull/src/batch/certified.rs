//! The certified f32 intersection over lanes: [`crate::intersect_f32`] for many rays at
//! once, 16 rays a register on AVX-512 (8 on AVX2), twice the f64 path's width.
//!
//! Per block of [`BLOCK`] rays, two stages:
//! 1. **f64 lanes**: the world ray to the torus frame and to the scaled foot-point line,
//!    as `crate::certified::line::scale` does per ray (the coordinates the certificate's
//!    error bounds assume: rounded to f32 once), into f32 columns on the stack;
//! 2. **f32 lanes**: the f32 solve and its proof, [`crate::certified`]'s own `decide`
//!    (one source with the scalar path: that function at width 1 *is* the scalar path),
//!    and the normal.
//!
//! A lane that proves neither hit nor miss is flagged, and the wavefront gives that ray to
//! the f64 [`crate::intersect()`].

use super::intersect::{RaysF64, TorusF64};
use super::lines::{BLOCK, size_lane_output};
use crate::Torus;
use crate::certified::certificate::{ScaledLine, V3, decide, normal_at, solve_uncertified};
use crate::certified::line::{LINE_ABS, LINE_REL, scale};
use crate::intersect::reduce::t_at;
use crate::num::sc;
use crate::num::{F32s, F64s};
use glam::Mat3;
use pulp::{Simd, WithSimd};

/// The lanes' answers: the root `u` (f32) and the back map to `t` (f64), the world normal
/// (f32), and per block a bit of "hit proved" and a bit of "miss proved".
#[derive(Debug, Clone, Default)]
pub(crate) struct F32Answers {
    pub(crate) u: Vec<f32>,
    /// `o·d̂` and `1/|d|` per ray: `t = (u·R − s)/|d|`.
    pub(crate) s: Vec<f64>,
    pub(crate) inv_len: Vec<f64>,
    pub(crate) normal: [Vec<f32>; 3],
    pub(crate) hit: Vec<u64>,
    pub(crate) miss: Vec<u64>,
}

impl F32Answers {
    /// The ray parameter of lane `j`'s root.
    #[inline]
    pub(crate) fn t(&self, major: f64, j: usize) -> f64 {
        let u = f64::from(self.u[j]);
        t_at(sc(u), sc(major), sc(self.s[j]), sc(self.inv_len[j])).v
    }
}

/// Whether the lanes prove their answers ([`decide`]) or only solve
/// ([`solve_uncertified`], every lane "proved": for timing the proof's cost only).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Proof {
    Certify,
    Uncertified,
}

/// Runs the f32 path on every ray of `rays` for `torus`.
pub(crate) fn certify_lanes(
    dispatch: &super::Dispatch,
    torus: &Torus,
    rays: &RaysF64,
    proof: Proof,
    out: &mut F32Answers,
) {
    let n = rays.padded();
    out.u.resize(n, 0.0);
    out.s.resize(n, 0.0);
    out.inv_len.resize(n, 0.0);
    size_lane_output(n, &mut out.normal, [&mut out.hit, &mut out.miss]);
    dispatch.run(Kernel {
        frame: TorusF64::of(torus),
        to_world: torus.to_local_rotation().transpose(),
        rays,
        proof,
        out,
    });
}

struct Kernel<'a> {
    frame: TorusF64,
    to_world: Mat3,
    rays: &'a RaysF64,
    proof: Proof,
    out: &'a mut F32Answers,
}

/// The f32 columns of one block: q (3), d̂ (3), lo, hi.
type Columns = [[f32; BLOCK]; 8];

impl WithSimd for Kernel<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let Kernel {
            frame,
            to_world,
            rays,
            proof,
            out,
        } = self;
        // Block scratch, reused from block to block (no clearing: a block writes every
        // lane it reads, but for the last register's tail past the last ray, whose
        // answers are never read).
        let mut columns: Columns = [[0.0; BLOCK]; 8];
        let mut wide = [[0.0f64; BLOCK]; 8];
        for block in 0..rays.padded() / BLOCK {
            let base = block * BLOCK;
            // The last block stops at the register holding the last ray.
            let live = BLOCK.min(rays.len() - base);
            let far = foot_points(s, &frame, rays, (base, live), &mut wide, &mut columns, out);
            let (hit, miss) = f32_stage(s, &frame, &to_world, &columns, base, live, proof, out);
            out.hit[block] = hit & !far;
            out.miss[block] = miss & !far;
        }
    }
}

/// Stage 1 on f64 lanes: the scaled foot-point lines of rays `base..base + live` into
/// `columns` (f32) and the back maps into `out`; returns the block's bits of origins too
/// far for the bounds (see `FAR_SCALED`), which escalate.
#[inline(always)]
fn foot_points<S: Simd>(
    s: S,
    frame: &TorusF64,
    rays: &RaysF64,
    (base, live): (usize, usize),
    wide: &mut [[f64; BLOCK]; 8],
    columns: &mut Columns,
    out: &mut F32Answers,
) -> u64 {
    let lanes = S::F64_LANES;
    let mut far = 0u64;
    for k in (0..live).step_by(lanes) {
        let at = base + k..base + k + lanes;
        let (origin, dir, t_min, t_max) = rays.lanes(s, at.start);
        let (o, d) = frame.line_to_local(origin, dir);
        let line = scale(o, d, F64s::splat(s, frame.tube.inv_major), t_min, t_max);
        far |= line.far.bits() << k;
        let (q, dh) = (line.foot.p, line.foot.dh);
        for (j, v) in [q.x, q.y, q.z, dh.x, dh.y, dh.z, line.lo, line.hi]
            .into_iter()
            .enumerate()
        {
            v.store(&mut wide[j][k..k + lanes]);
        }
        line.foot.s.store(&mut out.s[at.clone()]);
        line.foot.inv_len.store(&mut out.inv_len[at]);
    }
    for (narrow, wide) in columns.iter_mut().zip(wide.iter()) {
        for (n, w) in narrow.iter_mut().zip(wide) {
            *n = *w as f32;
        }
    }
    far
}

/// Stage 2 on f32 lanes: solve and prove (or only solve), the normal; the block's hit and
/// miss bits.
#[expect(
    clippy::too_many_arguments,
    reason = "one stage's inputs and outputs, inlined"
)]
#[inline(always)]
fn f32_stage<S: Simd>(
    s: S,
    frame: &TorusF64,
    to_world: &Mat3,
    columns: &Columns,
    base: usize,
    live: usize,
    proof: Proof,
    out: &mut F32Answers,
) -> (u64, u64) {
    let lanes = S::F32_LANES;
    let (mut hit_bits, mut miss_bits) = (0u64, 0u64);
    for k in (0..live).step_by(lanes) {
        let line = load_line(s, frame, columns, k);
        let (u, hit, miss) = match proof {
            Proof::Certify => {
                let d = decide(&line);
                (d.u, d.hit, d.miss)
            }
            Proof::Uncertified => {
                let u = solve_uncertified(&line);
                let found = !u.is_nan();
                (u, found, !found)
            }
        };
        store(to_world, &line, u, base + k, out);
        hit_bits |= hit.bits() << k;
        miss_bits |= miss.bits() << k;
    }
    (hit_bits, miss_bits)
}

/// Lanes `k..k + F32_LANES` of a block's columns as a [`ScaledLine`].
#[inline(always)]
fn load_line<S: Simd>(s: S, frame: &TorusF64, columns: &Columns, k: usize) -> ScaledLine<F32s<S>> {
    let lanes = S::F32_LANES;
    macro_rules! load {
        ($j:expr) => {
            F32s::load(s, &columns[$j][k..k + lanes])
        };
    }
    ScaledLine {
        q: V3 {
            x: load!(0),
            y: load!(1),
            z: load!(2),
        },
        d: V3 {
            x: load!(3),
            y: load!(4),
            z: load!(5),
        },
        rr: F32s::splat(s, frame.tube.minor_rel as f32),
        lo: load!(6),
        hi: load!(7),
        line_rel: F32s::splat(s, LINE_REL as f32),
        line_abs: F32s::splat(s, LINE_ABS as f32),
    }
}

/// Stores `u` and the world normal at `u` for lanes `at..at + F32_LANES`.
#[inline(always)]
fn store<S: Simd>(
    to_world: &Mat3,
    line: &ScaledLine<F32s<S>>,
    u: F32s<S>,
    at: usize,
    out: &mut F32Answers,
) {
    let at = at..at + S::F32_LANES;
    let n = normal_at(line, u);
    u.store(&mut out.u[at.clone()]);
    let [nx, ny, nz] = &mut out.normal;
    // Exact: the f32 matrix in f64, rounded back to f32 in the lanes.
    let world = n.rotated(&to_world.as_dmat3());
    world.x.store(&mut nx[at.clone()]);
    world.y.store(&mut ny[at.clone()]);
    world.z.store(&mut nz[at]);
}
