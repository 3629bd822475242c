//! The lab's own traversal of obvhs's CWBVH nodes, one that honours the ray's `t_min`.
//!
//! obvhs 0.4's node test (`CwBvhNode::intersect_ray`, in `obvhs-0.4.0/src/cwbvh/node.rs` and
//! `simd.rs`) ignores `ray.tmin` and clamps each child box's entry distance to
//! `EPSILON = 1e-4` (`let tmin = tmin3.max_element().max(EPSILON); //ray.tmin?`): a child
//! box that the ray leaves before t = 10⁻⁴, in units of the ray's direction, is skipped,
//! whatever the ray's own range. A torus whose box lies that close to the ray's origin,
//! measured along the ray, is never visited: with a unit direction a box shallower than
//! 10⁻⁴ (tori with R + r ≲ 5·10⁻⁵), with a long direction vector (the lab passes
//! directions unnormalized: a shadow ray to a light has t = 1 at the light) boxes of any
//! size, for a ray that starts near them (a bounce or shadow ray spawned on a
//! neighbour). See docs/bvh.md.
//!
//! Here the node test is the lab's: the same slab test on the same quantized child
//! boxes (a child's plane is `p + q·2^e`, `q` the byte stored for it), with the entry
//! distance clamped to the ray's `t_min` instead of 10⁻⁴ and the exit to the current
//! `t_max`. Two more differences from obvhs's test:
//!
//! - the reciprocal direction is `1/d` (±∞ for a zero component), not obvhs's
//!   `safe_inverse`, which caps |1/d| at 1/ε_f32 ≈ 8.4·10⁶ and so shortens the slab of
//!   a ray within 10⁻⁷ rad of a box face;
//! - the plane offset is formed before the product, `(q·2^e + (p − o))·(1/d)`, so that a
//!   zero component gives ±∞ (the ray is inside or outside that slab for all t), or NaN
//!   when the origin lies on the plane, which the `max`/`min` order below ignores (the
//!   slab then does not cull: conservative).
//!
//! The stack walk is obvhs's own [`obvhs::traverse!`] macro, the crate's public way to
//! traverse with a custom node test; only the node test is replaced.

use glam::{UVec2, Vec3A, Vec4};
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::node::{CwBvhNode, extract_byte64};
use torus_cull::Ray;

/// The ray as the node test reads it.
#[derive(Debug, Clone, Copy)]
pub struct NodeRay {
    origin: Vec3A,
    /// The direction with `-0.0` turned into `+0.0` (obvhs's octant order reads `< 0`).
    dir: Vec3A,
    inv: Vec3A,
    t_min: f32,
    t_max: f32,
}

impl NodeRay {
    /// The node test's view of `ray`: origin, direction, 1/direction and range.
    #[inline]
    pub fn new(ray: &Ray) -> NodeRay {
        let dir = Vec3A::from(ray.dir()) + Vec3A::ZERO;
        NodeRay {
            origin: Vec3A::from(ray.origin()),
            dir,
            inv: Vec3A::ONE / dir,
            t_min: ray.t_min(),
            t_max: ray.t_max(),
        }
    }
}

/// The four quantized planes `v[4·half .. 4·half + 4]` as floats.
#[inline(always)]
fn quad(v: &[u8; 8], half: usize) -> Vec4 {
    let b = 4 * half;
    Vec4::new(
        f32::from(v[b]),
        f32::from(v[b + 1]),
        f32::from(v[b + 2]),
        f32::from(v[b + 3]),
    )
}

/// Which of `node`'s children the ray enters within `[ray.t_min, t_max]`, as obvhs's
/// traversal reads a node's hit mask (inner children in the top byte by traversal
/// priority, leaf primitives in the low 24 bits).
#[inline(always)]
pub fn node_hits(node: &CwBvhNode, ray: &NodeRay, t_max: f32, oct_inv4: u32) -> u32 {
    let extent = node.compute_extent();
    let corner = Vec3A::from(node.p) - ray.origin;
    let planes = [
        (&node.child_min_x, &node.child_max_x),
        (&node.child_min_y, &node.child_max_y),
        (&node.child_min_z, &node.child_max_z),
    ];
    let (child_bits8, bit_index8) = node.get_child_and_index_bits(oct_inv4);
    let mut mask = 0;
    for half in 0..2 {
        let mut near = Vec4::splat(ray.t_min);
        let mut far = Vec4::splat(t_max);
        for (axis, (lo, hi)) in planes.iter().enumerate() {
            let (enter, leave) = if ray.dir[axis] < 0.0 {
                (quad(hi, half), quad(lo, half))
            } else {
                (quad(lo, half), quad(hi, half))
            };
            let (e, c, inv) = (extent[axis], corner[axis], ray.inv[axis]);
            // The slab's value first: a NaN one loses to the running bound (both for
            // SSE's `max_ps` and for `f32::max`), so it does not cull.
            near = ((enter * e + c) * inv).max(near);
            far = ((leave * e + c) * inv).min(far);
        }
        let entered = near.cmple(far).bitmask();
        for j in 0..4 {
            if entered & (1 << j) != 0 {
                let child = 4 * half + j;
                mask |= extract_byte64(child_bits8, child) << extract_byte64(bit_index8, child);
            }
        }
    }
    mask
}

/// The closest hit: calls `leaf(primitive, current t_max)` at every leaf whose box the
/// ray enters before the nearest hit so far; `leaf` returns the primitive's t, or +∞.
/// Returns the primitive (an index into the scene's tori) and t of the nearest hit in
/// `[t_min, t_max]`.
#[inline]
pub fn closest(
    bvh: &CwBvh,
    ray: &Ray,
    mut leaf: impl FnMut(usize, f32) -> f32,
) -> Option<(u32, f32)> {
    let r = NodeRay::new(ray);
    let mut best: Option<(u32, f32)> = None;
    let mut bound = r.t_max;
    let mut state = bvh.new_traversal(r.dir);
    let mut node;
    obvhs::traverse!(
        bvh,
        node,
        state,
        node_hits(node, &r, bound, state.oct_inv4),
        {
            let prim = bvh.primitive_indices[state.primitive_id as usize];
            let t = leaf(prim as usize, bound);
            // +∞ is a miss, even under an infinite t_max.
            if t <= bound && t < f32::INFINITY && best.is_none_or(|(_, b)| t < b) {
                best = Some((prim, t));
                bound = t;
            }
        }
    );
    best
}

/// Whether any leaf says the ray is blocked: calls `leaf(primitive)` at the leaves whose
/// box the ray enters within `[t_min, t_max]`, and stops at the first `true`.
#[inline]
pub fn any(bvh: &CwBvh, ray: &Ray, mut leaf: impl FnMut(usize) -> bool) -> bool {
    let r = NodeRay::new(ray);
    let mut state = bvh.new_traversal(r.dir);
    let mut node;
    let mut blocked = false;
    'walk: {
        obvhs::traverse!(
            bvh,
            node,
            state,
            node_hits(node, &r, r.t_max, state.oct_inv4),
            {
                if leaf(bvh.primitive_indices[state.primitive_id as usize] as usize) {
                    blocked = true;
                    break 'walk;
                }
            }
        );
    }
    blocked
}

/// Calls `leaf(primitive)` at every leaf whose box the ray enters within
/// `[t_min, t_max]`: the candidates of the batched traversal.
#[inline]
pub fn each_leaf(bvh: &CwBvh, ray: &Ray, mut leaf: impl FnMut(usize)) {
    // An any-hit walk that nothing blocks: inlined, its never-taken exit folds away.
    any(bvh, ray, |prim| {
        leaf(prim);
        false
    });
}
