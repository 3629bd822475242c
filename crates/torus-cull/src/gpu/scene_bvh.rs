//! The host's side of the GPU BVH ([`SceneBvh`]): an obvhs BVH2 over ring tori in the
//! layout the WGSL traversal reads (`wgsl/scene.wgsl`), the rays prepared for it, the
//! host's f64 answer for a ray the device could not prove, and the traversal's WGSL text
//! ([`wgsl_scene_module`]) for a renderer's own shader. The device's side is
//! [`super::GpuScene`] (`scene.rs`); the layout and the method are in its module docs
//! and in docs/gpu.md, "Tori in a GPU BVH".

use super::{GpuError, ModuleTorus, as_bytes};
use crate::family::Toroid;
use crate::{Ray, Torus};
use glam::{DVec3, Vec3};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use std::fmt::Write;

/// The own torus: run the module's surface path.
pub(crate) const OWN_CERTIFY: u32 = 0;
/// The own torus: the host proved a miss.
pub(crate) const OWN_MISS: u32 = 1;
/// The own torus: neither; the f64 finish from the surface, or the host.
pub(crate) const OWN_ESCALATE: u32 = 2;

/// Entries of the kernel's traversal stack: the BVH may be at most this deep less one
/// (each popped inner node pushes two). A deeper tree is refused by [`SceneBvh::new`].
pub const STACK: u32 = 64;

/// The largest coordinate of a torus's box or a ray's origin the kernel takes.
pub const MAX_COORDINATE: f32 = 1e12;

/// The range of a ray direction's largest component the kernel takes.
pub const DIRECTION_RANGE: (f32, f32) = (1e-6, 1e6);

/// A direction component at most this part of the largest is parallel to its axis in the
/// kernel's slab test.
pub(crate) const PARALLEL: f32 = 8.673_617e-19; // 2⁻⁶⁰

/// The slab test widens each slab's ends by this part of their size: the computed
/// `(b − o)/d` is within about 5u (u = 2⁻²⁴) of the true value.
pub(crate) const WIDEN: f32 = 3.814_697_3e-6; // 2⁻¹⁸

/// An origin farther than this many R from a torus's centre skips the f32 module there,
/// as the library's host does (`Escalation::FarOrigin`).
pub(crate) const FAR: f32 = 1_048_576.0; // 2²⁰

/// A leaf's plan (`TcScenePlan.code`, `wgsl/scene.wgsl`) to run the module: a code the
/// module's results (`TORUS_MISS`, `_HIT`, `_ESCALATE`, `_KEPT`) do not use.
const PLAN_RUN: u32 = u32::MAX - 1;

/// `status` of a traced ray: a proved miss, a hit, or the host's.
pub(crate) const STATUS_MISS: u32 = 0;
pub(crate) const STATUS_HIT: u32 = 1;
pub(crate) const STATUS_HOST: u32 = 2;

/// The nearest hit of a ray in a [`super::GpuScene`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneHit {
    /// The torus's index in the slice [`SceneBvh::new`] was given.
    pub torus: u32,
    /// t along the ray (units of its direction): within 2·10⁻⁴·(R + r)/|d| of the torus's
    /// first root in range where f32 proved it, to rounding where f64 gave it.
    pub t: f32,
    /// The unit outward world normal.
    pub normal: Vec3,
}

#[derive(Debug, Clone, Copy)]
struct Node {
    lo: Vec3,
    hi: Vec3,
    /// 0: inner, 1: leaf.
    count: u32,
    index: u32,
}

/// The scene traversal as WGSL a renderer includes in its own shader: the f32 module
/// ([`super::wgsl_module`]), the f64 finish ([`super::wgsl_finish_module`]) where `f64`,
/// the bindings `torus_scene_nodes` (binding 0), `torus_scene_tori` (1) and, where
/// `f64`, `torus_scene_tori64` (2) at `@group(group)`, and
/// `torus_scene_trace(ray: TorusRay, cull: u32, any_hit: bool) -> TorusSceneHit` and, for a
/// ray spawned on a torus, `torus_scene_trace_from(ray, own: TorusSceneOwn, cull, any_hit)`
/// (`wgsl/scene.wgsl`). Fill the buffers with [`SceneBvh::node_bytes`],
/// [`SceneBvh::tori_bytes`] and [`SceneBvh::tori64_bytes`], each ray with
/// [`SceneBvh::prepare`] (a spawned one with [`SceneBvh::prepare_from`]); an answer with
/// status `TORUS_SCENE_HOST` is finished by [`SceneBvh::host_trace`] (or
/// [`SceneBvh::host_occluded`], [`SceneBvh::host_trace_from`],
/// [`SceneBvh::host_occluded_from`]). `f64` needs `wgpu::Features::SHADER_F64`.
pub fn wgsl_scene_module(group: u32, f64: bool) -> String {
    let mut out = super::wgsl_module();
    if f64 {
        out.push_str(&super::wgsl_finish_module());
    }
    out.push_str(&scene_header());
    let _ = writeln!(
        out,
        "@group({group}) @binding(0) var<storage, read> torus_scene_nodes: TorusSceneNodes;\n\
         @group({group}) @binding(1) var<storage, read> torus_scene_tori: array<TorusSceneTorus>;"
    );
    if f64 {
        let _ = writeln!(
            out,
            "@group({group}) @binding(2) var<storage, read> torus_scene_tori64: array<TorusParams64>;"
        );
    }
    out.push_str(SCENE_FILES[0].1);
    out.push_str(if f64 {
        SCENE_FILES[1].1
    } else {
        SCENE_FILES[2].1
    });
    out
}

/// The traversal's WGSL files `(path under src/gpu, text)`: the walk, the escalated leaf
/// with f64 and without, the library kernel's entry point (for the `mirrors:` test).
pub(crate) const SCENE_FILES: [(&str, &str); 4] = [
    ("wgsl/scene.wgsl", include_str!("wgsl/scene.wgsl")),
    ("wgsl/scene_f64.wgsl", include_str!("wgsl/scene_f64.wgsl")),
    ("wgsl/scene_host.wgsl", include_str!("wgsl/scene_host.wgsl")),
    (
        "wgsl/scene_kernel.wgsl",
        include_str!("wgsl/scene_kernel.wgsl"),
    ),
];

/// The traversal's constants, from the Rust ones.
fn scene_header() -> String {
    format!(
        "// The scene traversal's constants (torus_cull::gpu::scene).\n\
         const TC_SCENE_STACK: u32 = {STACK}u;\n\
         const TC_SCENE_PARALLEL: f32 = {PARALLEL:e};\n\
         const TC_SCENE_WIDEN: f32 = {WIDEN:e};\n\
         const TC_SCENE_FAR: f32 = {FAR:e};\n\
         const TORUS_SCENE_MISS: u32 = {STATUS_MISS}u;\n\
         const TORUS_SCENE_HIT: u32 = {STATUS_HIT}u;\n\
         const TORUS_SCENE_HOST: u32 = {STATUS_HOST}u;\n\
         const TORUS_SCENE_NONE: u32 = {}u;\n\
         const TC_SCENE_REBASE: f32 = {:e};\n\
         const TC_SCENE_F32_MAX: f32 = {:e};\n\
         const TORUS_SCENE_OWN_CERTIFY: u32 = {OWN_CERTIFY}u;\n\
         const TORUS_SCENE_OWN_MISS: u32 = {OWN_MISS}u;\n\
         const TORUS_SCENE_OWN_ESCALATE: u32 = {OWN_ESCALATE}u;\n\
         const TC_SCENE_RUN: u32 = {PLAN_RUN}u;\n",
        u32::MAX,
        super::frame::REBASE_REL,
        f32::MAX,
    )
}

/// Tori in an obvhs BVH2, laid out for the WGSL traversal: what a renderer uploads
/// (its bytes), how it prepares a ray, and the host's answer where the device has none.
#[derive(Debug, Clone)]
pub struct SceneBvh {
    tori: Vec<Torus>,
    /// The BVH2's nodes as uploaded: `(lo, count)`, `(hi, index)`.
    nodes: Vec<Node>,
    /// The bounding sphere of every box: centre, radius.
    sphere: (DVec3, f64),
    depth: u32,
}

impl SceneBvh {
    /// Builds an obvhs BVH2 over `tori` (one torus a leaf), as the kernel reads it.
    ///
    /// # Errors
    ///
    /// [`GpuError::Scene`] for no tori, more than 2²⁴, a box coordinate beyond
    /// [`MAX_COORDINATE`], or a tree deeper than the kernel's stack ([`STACK`]).
    pub fn new(tori: &[Torus]) -> Result<SceneBvh, GpuError> {
        let nodes = build(tori)?;
        let depth = depth(&nodes);
        if depth + 1 > STACK {
            return Err(GpuError::Scene(format!(
                "the BVH over {} tori is {depth} nodes deep; the kernel's stack holds {STACK} \
                 (allowed: depth <= {})",
                tori.len(),
                STACK - 1
            )));
        }
        let (lo, hi) = nodes.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), n| {
            (lo.min(n.lo), hi.max(n.hi))
        });
        let (lo, hi) = (lo.as_dvec3(), hi.as_dvec3());
        let sphere = ((lo + hi) * 0.5, (hi - lo).length() * 0.5 * (1.0 + 1e-6));
        Ok(SceneBvh {
            tori: tori.to_vec(),
            nodes,
            sphere,
            depth,
        })
    }

    /// [`SceneBvh::new`] over members of the torus family: the circular ring members, as
    /// the certified f32 path takes them ([`crate::family::Toroid::as_torus`], the same
    /// answers bit for bit as the [`Torus`]).
    ///
    /// # Errors
    ///
    /// [`GpuError::Member`] for the first member that is not a circular ring torus (a
    /// horn, a spindle, an elliptical tube: the kernel's module, its f64 finish and the
    /// culls' bounds are the circular ring's), naming its index and why; then as
    /// [`SceneBvh::new`].
    pub fn from_family(members: &[Toroid]) -> Result<SceneBvh, GpuError> {
        SceneBvh::new(&ring_tori(members)?)
    }

    /// Nodes in the BVH.
    pub fn node_count(&self) -> u32 {
        self.nodes.len() as u32
    }

    /// The tori, in the order of [`SceneHit::torus`].
    pub fn tori(&self) -> &[Torus] {
        &self.tori
    }

    /// The BVH's depth (the root alone is 0).
    pub fn depth(&self) -> u32 {
        self.depth
    }

    /// The node buffer's bytes (`TorusSceneNodes`, header row zero).
    pub fn node_bytes(&self) -> Vec<u8> {
        let mut out = vec![0u8; 32];
        for n in &self.nodes {
            for (v, w) in [(n.lo, n.count), (n.hi, n.index)] {
                out.extend(as_bytes(&v.to_array()));
                out.extend(w.to_le_bytes());
            }
        }
        out
    }

    /// The f64 tori buffer's bytes (`TorusParams64`).
    pub fn tori64_bytes(&self) -> Vec<u8> {
        self.tori
            .iter()
            .flat_map(|t| ModuleTorus::new(t).params64_bytes())
            .collect()
    }

    /// The tori buffer's bytes (`TorusSceneTorus`: `TorusParams`, then `(c, R + r)`, with
    /// `−(R + r)` where the centre is not an f32 value: without f64 in the shader that
    /// torus skips the f32 leaf; with it, the leaf forms `o − c` from the f64 centre).
    pub fn tori_bytes(&self) -> Vec<u8> {
        let mut words = Vec::with_capacity(self.tori.len() * 32);
        for t in &self.tori {
            words.extend(ModuleTorus::new(t).params());
            words.extend(t.center().to_array());
            // A centre given in f64 (`Torus::new_f64`) that f32 does not hold: the f32
            // module's line error assumes o − c rounded once from the true difference,
            // which an f32 centre no longer gives, so without f64 in the shader such a
            // torus skips the f32 leaf (marked by a negative R + r) and goes to the host.
            let size = t.major_radius() + t.minor_radius();
            let exact = t.center().as_dvec3() == t.center_f64();
            words.push(if exact { size } else { -size });
        }
        as_bytes(&words)
    }

    /// The kernel's `TorusRay` for `ray` (the world ray, its range clipped to the scene's
    /// bounding sphere), or `None` where the host answers the ray (module docs).
    pub fn prepare(&self, ray: &Ray) -> Option<[f32; 8]> {
        let (o, d) = (ray.origin(), ray.dir());
        let dmax = d.abs().max_element();
        if ray.starts_on_surface()
            || o.abs().max_element() >= MAX_COORDINATE
            || !(DIRECTION_RANGE.0..=DIRECTION_RANGE.1).contains(&dmax)
        {
            return None;
        }
        let (c, radius) = self.sphere;
        // No point of the sphere lies beyond `reach` along the ray, so nothing is lost.
        let reach = ((o.as_dvec3() - c).length() + radius) / d.as_dvec3().length() * (1.0 + 1e-6);
        if reach >= f64::from(f32::MAX) {
            return None;
        }
        let reach = reach as f32;
        let (t_min, t_max) = (
            ray.t_min().clamp(-reach, reach),
            ray.t_max().clamp(-reach, reach),
        );
        Some([o.x, o.y, o.z, t_min, d.x, d.y, d.z, t_max])
    }

    /// The host's answer for a ray the device could not prove: the f64 path
    /// ([`crate::intersect()`]) at every leaf whose box the ray enters, in f64, the
    /// nearest kept (the lowest index on a tie, as a brute force in index order).
    pub fn host_trace(&self, ray: &Ray) -> Option<SceneHit> {
        self.host_trace_skipping(ray, None)
    }

    /// [`SceneBvh::host_trace`] over every torus but `skip`.
    pub(crate) fn host_trace_skipping(&self, ray: &Ray, skip: Option<u32>) -> Option<SceneHit> {
        let mut best: Option<SceneHit> = None;
        self.walk(ray, skip, |i| {
            if let Some(h) = host_leaf(&self.tori[i as usize], ray) {
                if best.is_none_or(|b| h.t < b.t || (h.t == b.t && i < b.torus)) {
                    best = Some(SceneHit {
                        torus: i,
                        t: h.t,
                        normal: h.normal,
                    });
                }
            }
            false
        });
        best
    }

    /// The host's any-hit answer ([`crate::occluded()`] at the leaves the ray enters).
    pub fn host_occluded(&self, ray: &Ray) -> bool {
        self.host_occluded_skipping(ray, None)
    }

    /// [`SceneBvh::host_occluded`] over every torus but `skip`.
    pub(crate) fn host_occluded_skipping(&self, ray: &Ray, skip: Option<u32>) -> bool {
        self.walk(ray, skip, |i| crate::occluded(&self.tori[i as usize], ray))
    }

    /// Calls `leaf(torus)` at each leaf whose box the ray's range enters (in f64, widened
    /// by 10⁻⁹ of each slab), but `skip`'s, until it returns true.
    fn walk(&self, ray: &Ray, skip: Option<u32>, mut leaf: impl FnMut(u32) -> bool) -> bool {
        let (o, d) = (ray.origin().as_dvec3(), ray.dir().as_dvec3());
        let range = (f64::from(ray.t_min()), f64::from(ray.t_max()));
        let mut stack = vec![0u32];
        while let Some(k) = stack.pop() {
            let n = self.nodes[k as usize];
            if !enters(o, d, (n.lo.as_dvec3(), n.hi.as_dvec3()), range) {
                continue;
            }
            if n.count == 0 {
                stack.extend([n.index, n.index + 1]);
            } else if Some(n.index) != skip && leaf(n.index) {
                return true;
            }
        }
        false
    }
}

/// The family's members as the tori they are ([`SceneBvh::from_family`]).
pub(crate) fn ring_tori(members: &[Toroid]) -> Result<Vec<Torus>, GpuError> {
    members
        .iter()
        .enumerate()
        .map(|(index, m)| {
            m.as_torus()
                .copied()
                .map_err(|error| GpuError::Member { index, error })
        })
        .collect()
}

/// The f64 path for one leaf on the host: the ray's nearest hit on `torus`.
pub(crate) fn host_leaf(torus: &Torus, ray: &Ray) -> Option<crate::Hit> {
    crate::intersect(torus, ray)
}

/// Whether the ray's range `(lo_t, hi_t)` can meet the box, in f64 (each slab widened by
/// 10⁻⁹ of its size; a zero direction component keeps the slab where the origin is in it).
pub(crate) fn enters(
    o: DVec3,
    d: DVec3,
    (lo, hi): (DVec3, DVec3),
    (lo_t, hi_t): (f64, f64),
) -> bool {
    let (mut near, mut far) = (lo_t, hi_t);
    for a in 0..3 {
        if d[a] == 0.0 {
            if o[a] < lo[a] || o[a] > hi[a] {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]);
        let (tn, tf) = (t0.min(t1), t0.max(t1));
        near = near.max(tn - 1e-9 * tn.abs());
        far = far.min(tf + 1e-9 * tf.abs());
    }
    near <= far
}

/// The BVH2 over the tori's boxes, one torus a leaf, as the kernel reads it.
fn build(tori: &[Torus]) -> Result<Vec<Node>, GpuError> {
    if tori.is_empty() {
        return Err(GpuError::Scene("a scene needs at least one torus".into()));
    }
    if tori.len() >= 1 << 24 {
        return Err(GpuError::Scene(format!(
            "{} tori (allowed: fewer than 2^24, an index exact in f32)",
            tori.len()
        )));
    }
    let mut aabbs = Vec::with_capacity(tori.len());
    for (i, t) in tori.iter().enumerate() {
        let (lo, hi) = t.world_aabb();
        if lo.abs().max(hi.abs()).max_element() >= MAX_COORDINATE {
            return Err(GpuError::Scene(format!(
                "torus {i}'s box reaches {:e} (allowed: coordinates below {MAX_COORDINATE:e})",
                lo.abs().max(hi.abs()).max_element()
            )));
        }
        aabbs.push(Aabb::new(lo.into(), hi.into()));
    }
    let params = BvhBuildParams {
        max_prims_per_leaf: 1,
        ..BvhBuildParams::medium_build()
    };
    let bvh = obvhs::bvh2::builder::build_bvh2(&aabbs, params, &mut Default::default());
    let mut seen = vec![false; tori.len()];
    let nodes: Vec<Node> = bvh
        .nodes
        .iter()
        .map(|n| {
            let leaf = n.prim_count > 0;
            let index = if leaf {
                bvh.primitive_indices[n.first_index as usize]
            } else {
                n.first_index
            };
            Node {
                lo: n.aabb.min.into(),
                hi: n.aabb.max.into(),
                count: u32::from(leaf),
                index,
            }
        })
        .collect();
    for (n, b) in nodes.iter().zip(&bvh.nodes) {
        if n.count == 1 {
            if b.prim_count != 1 {
                return Err(GpuError::Scene(format!(
                    "obvhs built a leaf of {} tori (the kernel takes one a leaf)",
                    b.prim_count
                )));
            }
            seen[n.index as usize] = true;
        }
    }
    if let Some(i) = seen.iter().position(|s| !s) {
        return Err(GpuError::Scene(format!(
            "torus {i} is in no leaf of the BVH"
        )));
    }
    Ok(nodes)
}

/// The deepest leaf's depth (the root's is 0).
fn depth(nodes: &[Node]) -> u32 {
    let mut deepest = 0;
    let mut stack = vec![(0u32, 0u32)];
    while let Some((k, d)) = stack.pop() {
        let n = nodes[k as usize];
        deepest = deepest.max(d);
        if n.count == 0 {
            stack.extend([(n.index, d + 1), (n.index + 1, d + 1)]);
        }
    }
    deepest
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both kernels (with and without f64) and the includable module at another group
    /// validate in naga, no adapter needed.
    #[test]
    fn the_scene_kernels_validate() {
        use wgpu::naga;
        for (source, caps) in [
            (
                super::super::scene_kernel::kernel_source(false),
                naga::valid::Capabilities::default(),
            ),
            (
                super::super::scene_kernel::kernel_source(true),
                naga::valid::Capabilities::FLOAT64,
            ),
            (
                wgsl_scene_module(2, false),
                naga::valid::Capabilities::default(),
            ),
        ] {
            let module = naga::front::wgsl::parse_str(&source)
                .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&source)));
            naga::valid::Validator::new(naga::valid::ValidationFlags::all(), caps)
                .validate(&module)
                .unwrap_or_else(|e| panic!("{e:?}"));
        }
        assert!(wgsl_scene_module(2, false).contains("@group(2) @binding(1)"));
    }

    /// A scene's BVH: every torus in one leaf, inner nodes' children inside them, and the
    /// host's f64 walk visits the leaf a ray through a torus's centre region enters.
    #[test]
    fn the_bvh_holds_every_torus_once() {
        let tori: Vec<Torus> = (0..40)
            .map(|i| {
                let c = Vec3::new((i % 7) as f32 * 3.0, (i / 7) as f32 * 3.0, (i % 3) as f32);
                Torus::new(c, Vec3::new(0.1, 1.0, 0.2 * i as f32), 1.0, 0.3).unwrap()
            })
            .collect();
        let nodes = build(&tori).unwrap();
        let mut leaves: Vec<u32> = nodes
            .iter()
            .filter(|n| n.count == 1)
            .map(|n| n.index)
            .collect();
        leaves.sort_unstable();
        assert_eq!(leaves, (0..40).collect::<Vec<u32>>());
        for n in nodes.iter().filter(|n| n.count == 0) {
            for child in [nodes[n.index as usize], nodes[n.index as usize + 1]] {
                assert!(child.lo.cmpge(n.lo).all() && child.hi.cmple(n.hi).all());
            }
        }
        assert!(depth(&nodes) >= 5 && depth(&nodes) < STACK);
        let e = build(&[]).unwrap_err();
        assert!(e.to_string().contains("at least one torus"), "{e}");
        // The slab test: a ray along x through a box, one parallel outside it, one whose
        // range ends before it.
        let b = (DVec3::splat(-1.0), DVec3::splat(1.0));
        let x = DVec3::X;
        assert!(enters(DVec3::new(-5.0, 0.0, 0.0), x, b, (0.0, 10.0)));
        assert!(!enters(DVec3::new(-5.0, 2.0, 0.0), x, b, (0.0, 10.0)));
        assert!(!enters(DVec3::new(-5.0, 0.0, 0.0), x, b, (0.0, 3.9)));
    }
}
