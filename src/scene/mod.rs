//! Many-torus scenes in an obvhs BVH, with a cull at the leaves.
//!
//! Inside a BVH a ray reaches a torus only after it entered that torus's box, so what a
//! cull can still save is its **marginal** value: quartic solves per ray beyond the box
//! test. [`Scene::trace`] counts leaf visits, cull rejections and quartic solves, and the
//! closest hit must be identical to [`Scene::brute_force`] whatever the cull.
//!
//! [`family::FamilyScene`] puts the torus family's shapes (horn and spindle tori,
//! elliptical tubes, pipe bends) in the same BVH, through the same traversals.

pub mod batched;
pub mod family;
pub mod rays;
pub mod traverse;

pub use crate::scene_kind::SceneKind;
pub use batched::{LeafBatchStats, LeafBatcher, trace_leaves_batched, trace_spawned_batched};

use crate::workload::CameraView;
use glam::{DVec3, Vec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use obvhs::cwbvh::CwBvh;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::fmt;
use torus_cull::{Cull, Ray, Torus, intersect};

/// Per-ray work counters of a traversal.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Leaf (primitive) visits: boxes the ray entered.
    pub leaf_visits: u64,
    /// Leaves where the cull rejected the ray.
    pub cull_rejects: u64,
    /// Leaves where the quartic ran.
    pub quartic_solves: u64,
}

impl TraceStats {
    /// A leaf visit of `ray` at `torus`: whether `cull` keeps it, counted as a cull reject
    /// where it does not and as a quartic solve (the caller's next step) where it does.
    #[inline]
    fn kept_by<C: Cull>(&mut self, cull: &C, torus: &Torus, ray: &Ray) -> bool {
        self.leaf_visits += 1;
        let line = torus.line_to_local(ray);
        if !cull.keeps(torus.bounds(), line.origin, line.dir) {
            self.cull_rejects += 1;
            return false;
        }
        self.quartic_solves += 1;
        true
    }

    /// A closest-hit leaf: t of `ray`'s nearest hit on `torus` within `t_max`, or +∞ where
    /// `cull` rejects the ray or there is none; counted as [`TraceStats::kept_by`].
    #[inline]
    fn leaf_t<C: Cull>(&mut self, cull: &C, torus: &Torus, ray: &Ray, t_max: f32) -> f32 {
        if !self.kept_by(cull, torus, ray) {
            return f32::INFINITY;
        }
        // t_max is a hit's t or +∞, never NaN.
        let cut = ray.with_t_max(t_max).expect("t_max is not NaN");
        intersect(torus, &cut).map_or(f32::INFINITY, |h| h.t)
    }
}

impl std::ops::AddAssign for TraceStats {
    fn add_assign(&mut self, o: TraceStats) {
        self.leaf_visits += o.leaf_visits;
        self.cull_rejects += o.cull_rejects;
        self.quartic_solves += o.quartic_solves;
    }
}

/// The closest hit: torus index (into [`Scene::tori`]) and t.
pub type SceneHit = Option<(u32, f32)>;

/// Whether two closest hits agree: same t, and the same torus unless two tori tie at it.
pub fn same_hit(a: SceneHit, b: SceneHit) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some((_, ta)), Some((_, tb))) => ta == tb,
        _ => false,
    }
}

/// A scene: tori (each with its cull bounds), the BVH over their boxes, and the camera framing it.
pub struct Scene {
    /// Layout.
    pub kind: SceneKind,
    /// ν of every torus (R = 1, r = 1/ν).
    pub nu: f64,
    /// The length unit: R of every torus.
    pub scale: f64,
    /// The tori.
    pub tori: Vec<Torus>,
    bvh: CwBvh,
    /// A pinhole view that frames the scene.
    pub camera: CameraView,
    /// Centre and radius of the scene's bounding sphere.
    pub bounding_sphere: (DVec3, f64),
}

/// Why a scene could not be built.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError(pub String);

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SceneError {}

/// A scene's length unit must be a positive finite number (the torus and family scenes).
pub(crate) fn check_scale(scale: f64) -> Result<(), SceneError> {
    if scale.is_finite() && scale > 0.0 {
        Ok(())
    } else {
        Err(SceneError(format!(
            "scale = {} is invalid (allowed: a positive finite number)",
            crate::number::Num(scale)
        )))
    }
}

impl Scene {
    /// Build `count` tori of `kind` at ν, deterministically from `seed`.
    pub fn build(kind: SceneKind, nu: f64, count: usize, seed: u64) -> Result<Scene, SceneError> {
        Scene::build_scaled(kind, nu, count, seed, 1.0)
    }

    /// [`Scene::build`] with every length times `scale`: R = `scale`, r = `scale`/ν, the
    /// same layout and camera scaled about the world origin.
    pub fn build_scaled(
        kind: SceneKind,
        nu: f64,
        count: usize,
        seed: u64,
        scale: f64,
    ) -> Result<Scene, SceneError> {
        check_scale(scale)?;
        if !(nu.is_finite() && nu > 1.0 && nu <= torus_cull::MAX_NU) {
            return Err(SceneError(format!(
                "nu = {} is invalid (allowed: 1 < nu <= {})",
                crate::number::Num(nu),
                torus_cull::MAX_NU
            )));
        }
        if count == 0 {
            return Err(SceneError("a scene needs at least one torus".into()));
        }
        let mut rng = Pcg64::seed_from_u64(
            crate::workload::stream_seed(seed, crate::workload::Case::Uniform, nu)
                ^ (kind as u64 + 1).wrapping_mul(0xA24B_AED4_963E_E407),
        );
        let (major, minor) = (1.0f64, 1.0 / nu);
        let (placed, eye) = match kind {
            SceneKind::RingField => ring_field(count, major + minor, 1.5, &mut rng),
            SceneKind::Chain => chain(count, major, major + minor),
            SceneKind::FacingGrid => facing_grid(count, major + minor),
            SceneKind::MixedNu => ring_field(count, major + 1.0 / MIXED_NU.0, 1.5, &mut rng),
            SceneKind::Dense => ring_field(count, major + minor, 0.5, &mut rng),
        };
        // Every torus's r: 1/ν, or in the mixed scene 1/ν with ν log-uniform in MIXED_NU.
        let minors: Vec<f64> = (0..count)
            .map(|_| match kind {
                SceneKind::MixedNu => {
                    let (lo, hi) = (MIXED_NU.0.ln(), MIXED_NU.1.ln());
                    1.0 / rng.random_range(lo..hi).exp()
                }
                _ => minor,
            })
            .collect();
        let placed: Vec<(DVec3, DVec3)> = placed.into_iter().map(|(c, a)| (c * scale, a)).collect();
        let (eye, major) = (eye * scale, major * scale);
        let tori: Vec<Torus> = placed
            .iter()
            .zip(&minors)
            .map(|((c, a), r)| {
                Torus::new(c.as_vec3(), a.as_vec3(), major as f32, (r * scale) as f32)
            })
            .collect::<Result<_, _>>()
            .map_err(|e| SceneError(e.to_string()))?;
        let boxes: Vec<(Vec3, Vec3)> = tori.iter().map(Torus::world_aabb).collect();
        let Boxed {
            bvh,
            camera,
            bounding_sphere,
        } = Boxed::over(&boxes, eye);
        Ok(Scene {
            kind,
            nu,
            scale,
            tori,
            bvh,
            camera,
            bounding_sphere,
        })
    }

    /// The `size`×`size` pinhole rays through pixel centres, row-major from the top left.
    pub fn camera_rays(&self, size: usize) -> Vec<Ray> {
        pinhole_rays(&self.camera, size)
    }

    /// `count` isotropic lines through the scene's bounding sphere (as in the `uniform`
    /// case), starting outside it.
    pub fn random_rays(&self, count: usize, seed: u64) -> Vec<Ray> {
        lines_through(self.bounding_sphere, count, seed)
    }

    /// The closest hit through the BVH, with `cull` at the leaves; adds to `stats`.
    #[inline]
    pub fn trace<C: Cull>(&self, cull: &C, ray: &Ray, stats: &mut TraceStats) -> SceneHit {
        self.trace_with(ray, |torus, ray, t_max| {
            stats.leaf_t(cull, torus, ray, t_max)
        })
    }

    /// [`Scene::trace`] of a spawned ray: its own torus sees the surface ray, every other
    /// the literal one ([`rays::Spawned::literal`]).
    #[inline]
    pub fn trace_spawned<C: Cull>(
        &self,
        cull: &C,
        spawned: &rays::Spawned,
        stats: &mut TraceStats,
    ) -> SceneHit {
        let literal = spawned.literal();
        traverse::closest(&self.bvh, &spawned.ray, |prim, t_max| {
            let ray = spawned.seen_by(prim, &literal);
            stats.leaf_t(cull, &self.tori[prim], ray, t_max)
        })
    }

    /// [`Scene::occluded`] of a spawned shadow ray (its own torus sees the surface ray,
    /// every other the literal one).
    #[inline]
    pub fn occluded_spawned<C: Cull>(
        &self,
        cull: &C,
        spawned: &rays::Spawned,
        stats: &mut TraceStats,
    ) -> bool {
        let literal = spawned.literal();
        traverse::any(&self.bvh, &spawned.ray, |prim| {
            let torus = &self.tori[prim];
            let ray = spawned.seen_by(prim, &literal);
            stats.kept_by(cull, torus, ray) && torus_cull::occluded(torus, ray)
        })
    }

    /// Traverse the BVH, calling `leaf(torus, ray, current t_max)` at each leaf whose box
    /// the ray enters within `[t_min, current t_max]`; it returns the torus's t or +∞.
    /// The lab's traversal ([`traverse`]): obvhs's own skips boxes the ray leaves before
    /// t = 10⁻⁴.
    pub fn trace_with(
        &self,
        ray: &Ray,
        mut leaf: impl FnMut(&Torus, &Ray, f32) -> f32,
    ) -> SceneHit {
        traverse::closest(&self.bvh, ray, |prim, t_max| {
            leaf(&self.tori[prim], ray, t_max)
        })
    }

    /// Whether anything blocks `ray` within `[t_min, t_max]` (a shadow ray), through the
    /// BVH with `cull` at the leaves, stopping at the first blocker; adds to `stats`.
    #[inline]
    pub fn occluded<C: Cull>(&self, cull: &C, ray: &Ray, stats: &mut TraceStats) -> bool {
        self.occluded_with(ray, |torus, ray| {
            stats.kept_by(cull, torus, ray) && torus_cull::occluded(torus, ray)
        })
    }

    /// Any-hit traversal: calls `leaf(torus, ray)` at the leaves whose box the ray
    /// enters, until one returns `true`.
    pub fn occluded_with(&self, ray: &Ray, mut leaf: impl FnMut(&Torus, &Ray) -> bool) -> bool {
        traverse::any(&self.bvh, ray, |prim| leaf(&self.tori[prim], ray))
    }

    /// Whether any torus blocks `ray` within its range, with no BVH and no cull: the
    /// ground truth for [`Scene::occluded`].
    pub fn brute_force_occluded(&self, ray: &Ray) -> bool {
        self.tori.iter().any(|t| torus_cull::occluded(t, ray))
    }

    /// [`Scene::brute_force`] of a spawned ray (its own torus sees the surface ray, every
    /// other the literal one).
    pub fn brute_force_spawned(&self, spawned: &rays::Spawned) -> SceneHit {
        let literal = spawned.literal();
        let mut best: SceneHit = None;
        for (i, torus) in self.tori.iter().enumerate() {
            let ray = if i == spawned.from as usize {
                &spawned.ray
            } else {
                &literal
            };
            if let Some(h) = intersect(torus, ray) {
                if best.is_none_or(|(_, t)| h.t < t) {
                    best = Some((i as u32, h.t));
                }
            }
        }
        best
    }

    /// [`Scene::brute_force_occluded`] of a spawned shadow ray.
    pub fn brute_force_occluded_spawned(&self, spawned: &rays::Spawned) -> bool {
        let literal = spawned.literal();
        self.tori.iter().enumerate().any(|(i, t)| {
            let ray = if i == spawned.from as usize {
                &spawned.ray
            } else {
                &literal
            };
            torus_cull::occluded(t, ray)
        })
    }

    /// The BVH, for the batch traversal of [`trace_leaves_batched`].
    pub(crate) fn bvh(&self) -> &CwBvh {
        &self.bvh
    }

    /// The closest hit over every torus with no cull: the ground truth for the BVH.
    pub fn brute_force(&self, ray: &Ray) -> SceneHit {
        let mut best: SceneHit = None;
        for (i, torus) in self.tori.iter().enumerate() {
            if let Some(h) = intersect(torus, ray) {
                if best.is_none_or(|(_, t)| h.t < t) {
                    best = Some((i as u32, h.t));
                }
            }
        }
        best
    }
}

/// A scene's BVH over one box per shape (`max_prims_per_leaf = 1`, so a leaf is a
/// shape), and the camera at `eye` and the bounding sphere that frame the boxes.
struct Boxed {
    bvh: CwBvh,
    camera: CameraView,
    bounding_sphere: (DVec3, f64),
}

impl Boxed {
    fn over(boxes: &[(Vec3, Vec3)], eye: DVec3) -> Boxed {
        let aabbs: Vec<Aabb> = boxes
            .iter()
            .map(|&(lo, hi)| Aabb::new(Vec3A::from(lo), Vec3A::from(hi)))
            .collect();
        let params = BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::medium_build()
        };
        let bvh = obvhs::cwbvh::builder::build_cwbvh(&aabbs, params, &mut Default::default());
        let (lo, hi) = aabbs.iter().fold((Vec3A::MAX, Vec3A::MIN), |(lo, hi), b| {
            (lo.min(b.min), hi.max(b.max))
        });
        let centre = ((lo + hi) * 0.5).as_dvec3();
        let radius = ((hi - lo) * 0.5).as_dvec3().length();
        Boxed {
            bvh,
            camera: CameraView::framing(eye, centre, (lo.as_dvec3(), hi.as_dvec3())),
            bounding_sphere: (centre, radius),
        }
    }
}

/// The `size`×`size` pinhole rays of `cam` through pixel centres, row-major from the top
/// left.
fn pinhole_rays(cam: &CameraView, size: usize) -> Vec<Ray> {
    let mut rays = Vec::with_capacity(size * size);
    for row in 0..size {
        for col in 0..size {
            let u = ((col as f64 + 0.5) / size as f64 * 2.0 - 1.0) * cam.tan_half_fov;
            let v = (1.0 - (row as f64 + 0.5) / size as f64 * 2.0) * cam.tan_half_fov;
            let d = cam.forward + cam.right * u + cam.up * v;
            rays.push(Ray::new(cam.eye.as_vec3(), d.as_vec3()).expect("camera rays are finite"));
        }
    }
    rays
}

/// `count` isotropic lines through the sphere `(centre, radius)` (as in the `uniform`
/// case), starting outside it.
fn lines_through((centre, radius): (DVec3, f64), count: usize, seed: u64) -> Vec<Ray> {
    let mut rng = Pcg64::seed_from_u64(seed ^ 0x5CE7_E0FF);
    (0..count)
        .map(|_| {
            let d = crate::workload::unit_vector(&mut rng);
            let p = centre + crate::workload::disk_point(&mut rng, d, radius);
            Ray::new((p - d * (2.0 * radius)).as_vec3(), d.as_vec3())
                .expect("random rays are finite")
        })
        .collect()
}

/// The range of ν in the `mixed_nu` scene.
pub const MIXED_NU: (f64, f64) = (1.25, 16.0);

/// Tori at random positions and axes in a cube sized for `count` of them (`spread` outer
/// diameters apart on average: 1.5 leaves room, 0.5 packs them so that they overlap),
/// and an eye outside it in a random direction.
fn ring_field(
    count: usize,
    outer: f64,
    spread: f64,
    rng: &mut Pcg64,
) -> (Vec<(DVec3, DVec3)>, DVec3) {
    let side = 2.0 * outer * (count as f64).cbrt() * spread;
    let placed = (0..count)
        .map(|_| {
            let c = DVec3::new(
                rng.random_range(-0.5..0.5),
                rng.random_range(-0.5..0.5),
                rng.random_range(-0.5..0.5),
            ) * side;
            (c, crate::workload::unit_vector(rng))
        })
        .collect();
    let view = crate::workload::unit_vector(rng);
    (placed, view * side * 1.8)
}

/// Chain links in rows: consecutive links R apart, rings in perpendicular planes that both
/// hold the row direction, so each passes through the other's hole.
fn chain(count: usize, major: f64, outer: f64) -> (Vec<(DVec3, DVec3)>, DVec3) {
    let row_gap = 2.0 * outer * 1.25;
    let per_row = ((count as f64 * row_gap / major).sqrt().ceil() as usize).max(1);
    let rows = count.div_ceil(per_row);
    let placed = (0..count)
        .map(|i| {
            let (row, k) = (i / per_row, i % per_row);
            let c = DVec3::new(
                (k as f64 - per_row as f64 / 2.0) * major,
                0.0,
                (row as f64 - rows as f64 / 2.0) * row_gap,
            );
            (c, if k % 2 == 0 { DVec3::Y } else { DVec3::Z })
        })
        .collect();
    let extent = (per_row as f64 * major).max(rows as f64 * row_gap);
    // From above and slightly off-vertical, so face-on links dominate.
    (
        placed,
        DVec3::new(0.05, 1.0, 0.08).normalize() * extent * 1.2,
    )
}

/// A square grid of tori in the plane z = 0, each facing the eye on the z axis.
fn facing_grid(count: usize, outer: f64) -> (Vec<(DVec3, DVec3)>, DVec3) {
    let side = (count as f64).sqrt().ceil() as usize;
    let spacing = 2.0 * outer * 1.05;
    let eye = DVec3::new(0.0, 0.0, side as f64 * spacing * 1.3);
    let placed = (0..count)
        .map(|i| {
            let (row, col) = (i / side, i % side);
            let c = DVec3::new(
                (col as f64 - (side as f64 - 1.0) / 2.0) * spacing,
                (row as f64 - (side as f64 - 1.0) / 2.0) * spacing,
                0.0,
            );
            (c, (eye - c).normalize())
        })
        .collect();
    (placed, eye)
}

impl CameraView {
    /// A pinhole at `eye` looking at `centre`, its field of view just wide enough for the
    /// box `lo..hi`'s projected corners (not its bounding sphere: a flat grid would
    /// otherwise fill half the picture).
    fn framing(eye: DVec3, centre: DVec3, (lo, hi): (DVec3, DVec3)) -> CameraView {
        let forward = (centre - eye).normalize();
        let (right, _) = forward.any_orthonormal_pair();
        let up = right.cross(forward);
        let tan_half_fov = (0..8)
            .map(|i| {
                let corner = DVec3::new(
                    if i & 1 == 0 { lo.x } else { hi.x },
                    if i & 2 == 0 { lo.y } else { hi.y },
                    if i & 4 == 0 { lo.z } else { hi.z },
                );
                let v = corner - eye;
                let z = v.dot(forward).max(1e-9);
                (v.dot(right) / z).abs().max((v.dot(up) / z).abs())
            })
            .fold(0.0, f64::max)
            * 1.03;
        CameraView {
            eye,
            forward,
            right,
            up,
            tan_half_fov,
        }
    }
}
