//! The family scene: [`Toroid`]s (ring, horn, spindle; circular and elliptical tubes) and
//! [`PipeBend`]s (bores, φ segments) at random poses, one box per shape in the obvhs
//! CWBVH, each shape's own exact intersection at the leaves (docs/bvh.md).
//!
//! The traversals are [`super::traverse`]'s, which honour the ray's `t_min` where obvhs's
//! node test clamps the entry to 10⁻⁴; a spawned ray is a surface ray for its own shape
//! only and the literal segment for every other ([`Spawned::literal`]), as in [`Scene`].
//!
//! [`Scene`]: super::Scene

mod shape;

pub use shape::{FamilyShape, ShapeClass, ShapeHit};

use super::rays::{Spawned, Surfaces};
use super::{Boxed, SceneError, SceneHit, TraceStats, traverse};
use crate::workload::CameraView;
use glam::{DVec3, Vec3};
use obvhs::cwbvh::CwBvh;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::TAU;
use torus_cull::bend::PipeBend;
use torus_cull::family::Toroid;
use torus_cull::{Cull, Ray};

/// The tube aspects b/a the elliptical, horn and spindle members cycle through; the last,
/// 0, stands for one drawn log-uniform in 1/4 … 4 (the library's whole range).
const ASPECTS: [f64; 6] = [0.25, 0.5, 1.0, 2.0, 4.0, 0.0];

/// The outer radius a shape reaches, in units of R, for the spacing: a spindle of
/// ν = 1/2 reaches 3R, a ring of ν = 1.5 1.67R.
const OUTER: f64 = 2.0;

/// Shapes of the torus family in an obvhs BVH, and the camera framing them.
pub struct FamilyScene {
    /// The length unit: R of every shape.
    pub scale: f64,
    /// The shapes, cycling through [`ShapeClass::ALL`].
    pub shapes: Vec<FamilyShape>,
    bvh: CwBvh,
    /// A pinhole view that frames the scene.
    pub camera: CameraView,
    /// Centre and radius of the scene's bounding sphere.
    pub bounding_sphere: (DVec3, f64),
}

impl FamilyScene {
    /// `count` shapes of R = `scale` at random centres and axes in a cube (`spread` outer
    /// diameters apart on average, as the `ring_field` and `dense` scenes: 1.5 leaves
    /// room, 0.5 packs them so that they overlap), deterministically from `seed`. Shape
    /// `i` is of class `ShapeClass::ALL[i % 6]`:
    ///
    /// - ring: ν = R/a log-uniform in 1.5–8, a = b;
    /// - elliptic: ν log-uniform in 1.5–6, b/a cycling through 1/4, 1/2, 3, 2, 4 and one
    ///   drawn log-uniform in 1/4–4;
    /// - horn: a = R, b/a cycling through 1/4, 1/2, 1, 2, 4 and a draw;
    /// - spindle: ν uniform in 0.5–0.95, b/a as the horn's;
    /// - bored ring: a whole pipe bend, r_max = R/ν (ν log-uniform in 1.5–4), r_min
    ///   uniform in 0.5–0.9 of r_max;
    /// - segment: as the bored ring but Δφ uniform in 0.4–5.8 rad from a random φ₀, one
    ///   in three without a bore.
    pub fn build(
        count: usize,
        seed: u64,
        scale: f64,
        spread: f64,
    ) -> Result<FamilyScene, SceneError> {
        super::check_scale(scale)?;
        if count == 0 {
            return Err(SceneError("a scene needs at least one shape".into()));
        }
        let mut rng = Pcg64::seed_from_u64(seed ^ 0xFA41_17B3_5CE7_E000);
        let (placed, eye) = super::ring_field(count, OUTER, spread, &mut rng);
        let shapes: Vec<FamilyShape> = placed
            .iter()
            .enumerate()
            .map(|(i, &(c, axis))| shape(i, c * scale, axis, scale, &mut rng))
            .collect::<Result<_, _>>()?;
        let boxes: Vec<(Vec3, Vec3)> = shapes.iter().map(FamilyShape::world_box).collect();
        let Boxed {
            bvh,
            camera,
            bounding_sphere,
        } = Boxed::over(&boxes, eye * scale);
        Ok(FamilyScene {
            scale,
            shapes,
            bvh,
            camera,
            bounding_sphere,
        })
    }

    /// The `size`×`size` pinhole rays through pixel centres, row-major from the top left.
    pub fn camera_rays(&self, size: usize) -> Vec<Ray> {
        super::pinhole_rays(&self.camera, size)
    }

    /// `count` isotropic lines through the scene's bounding sphere, starting outside it.
    pub fn random_rays(&self, count: usize, seed: u64) -> Vec<Ray> {
        super::lines_through(self.bounding_sphere, count, seed)
    }

    /// Rays into the bores of the segments: for each cut end of a bored segment, `per_end`
    /// lines that start outside the end, 3·r_max back along the core circle's tangent,
    /// and head into the pipe through a point uniform in the inner 0.8·r_min of the
    /// bore's opening, tilted up to 0.2 rad. A line from outside meets the bore only
    /// through such an opening, which camera and random rays seldom find.
    pub fn bore_rays(&self, per_end: usize, seed: u64) -> Vec<Ray> {
        let mut rng = Pcg64::seed_from_u64(seed ^ 0xB0BE_0000_0000_0001);
        let mut rays = Vec::new();
        for shape in &self.shapes {
            let FamilyShape::Bend(bend) = shape else {
                continue;
            };
            let bore = bend.bore_radius_f64();
            if bore == 0.0 || bend.delta_phi() == TAU {
                continue;
            }
            let (c, axis) = (bend.outer().center_f64(), bend.outer().axis_f64());
            let e0 = phi_zero(axis);
            let e1 = axis.cross(e0);
            let (major, tube) = (bend.major_radius_f64(), bend.tube_radius_f64());
            for (phi, inward) in [
                (bend.start_phi(), 1.0),
                (bend.start_phi() + bend.delta_phi(), -1.0),
            ] {
                let radial = e0 * phi.cos() + e1 * phi.sin();
                // The direction of growing φ at the end; into the pipe at the start,
                // out of it at the end.
                let along = (e1 * phi.cos() - e0 * phi.sin()) * inward;
                for _ in 0..per_end {
                    let (rho, angle) = (
                        0.8 * bore * rng.random_range(0.0f64..1.0).sqrt(),
                        rng.random_range(0.0..TAU),
                    );
                    let at = c + radial * (major + rho * angle.cos()) + axis * (rho * angle.sin());
                    let tilt =
                        radial * rng.random_range(-0.2..0.2) + axis * rng.random_range(-0.2..0.2);
                    let dir = (along + tilt).normalize();
                    rays.extend(Ray::new(
                        (at - along * (3.0 * tube)).as_vec3(),
                        dir.as_vec3(),
                    ));
                }
            }
        }
        rays
    }

    /// The closest hit through the BVH, with `cull` at the leaves by each shape's own rule
    /// ([`FamilyShape::kept_by`]; [`torus_cull::NoCull`] for the exact intersection
    /// alone); adds to `stats`.
    pub fn trace<C: Cull>(&self, cull: &C, ray: &Ray, stats: &mut TraceStats) -> SceneHit {
        traverse::closest(&self.bvh, ray, |prim, t_max| {
            self.leaf_t(cull, prim, ray, t_max, stats)
        })
    }

    /// [`FamilyScene::trace`] of a spawned ray: its own shape sees the surface ray, every
    /// other the literal one.
    pub fn trace_spawned<C: Cull>(
        &self,
        cull: &C,
        spawned: &Spawned,
        stats: &mut TraceStats,
    ) -> SceneHit {
        let literal = spawned.literal();
        traverse::closest(&self.bvh, &spawned.ray, |prim, t_max| {
            let ray = own_or_literal(spawned, &literal, prim);
            self.leaf_t(cull, prim, ray, t_max, stats)
        })
    }

    /// Whether a spawned shadow ray is blocked within its range, any-hit through the BVH
    /// (the first blocker ends it), with `cull` at the leaves; adds to `stats`.
    pub fn occluded_spawned<C: Cull>(
        &self,
        cull: &C,
        spawned: &Spawned,
        stats: &mut TraceStats,
    ) -> bool {
        let literal = spawned.literal();
        traverse::any(&self.bvh, &spawned.ray, |prim| {
            let ray = own_or_literal(spawned, &literal, prim);
            let shape = &self.shapes[prim];
            stats.leaf_visits += 1;
            if !shape.kept_by(cull, ray) {
                stats.cull_rejects += 1;
                return false;
            }
            stats.quartic_solves += 1;
            shape.occluded(ray)
        })
    }

    /// The closest hit over every shape with no BVH and no cull: the ground truth.
    pub fn brute_force(&self, ray: &Ray) -> SceneHit {
        self.nearest(|_| ray)
    }

    /// [`FamilyScene::brute_force`] of a spawned ray.
    pub fn brute_force_spawned(&self, spawned: &Spawned) -> SceneHit {
        let literal = spawned.literal();
        self.nearest(|i| own_or_literal(spawned, &literal, i))
    }

    /// Whether any shape blocks the spawned ray within its range, with no BVH and no cull.
    pub fn brute_force_occluded_spawned(&self, spawned: &Spawned) -> bool {
        let literal = spawned.literal();
        (0..self.shapes.len())
            .any(|i| self.shapes[i].occluded(own_or_literal(spawned, &literal, i)))
    }

    /// Shape `prim`'s t on `ray` within `[t_min, t_max]` behind `cull`, or +∞.
    #[inline]
    fn leaf_t<C: Cull>(
        &self,
        cull: &C,
        prim: usize,
        ray: &Ray,
        t_max: f32,
        stats: &mut TraceStats,
    ) -> f32 {
        let shape = &self.shapes[prim];
        stats.leaf_visits += 1;
        if !shape.kept_by(cull, ray) {
            stats.cull_rejects += 1;
            return f32::INFINITY;
        }
        stats.quartic_solves += 1;
        // t_max is a hit's t or +∞, never NaN.
        let cut = ray.with_t_max(t_max).expect("t_max is not NaN");
        shape.intersect(&cut).map_or(f32::INFINITY, |h| h.t)
    }

    /// The nearest hit over every shape `i`, each on the ray `ray_for(i)`; ties keep the
    /// first shape.
    fn nearest<'r>(&self, ray_for: impl Fn(usize) -> &'r Ray) -> SceneHit {
        let mut best: SceneHit = None;
        for (i, shape) in self.shapes.iter().enumerate() {
            if let Some(h) = shape.intersect(ray_for(i)) {
                if best.is_none_or(|(_, t)| h.t < t) {
                    best = Some((i as u32, h.t));
                }
            }
        }
        best
    }
}

impl Surfaces for FamilyScene {
    fn view(&self) -> (&CameraView, (DVec3, f64)) {
        (&self.camera, self.bounding_sphere)
    }

    fn facing_hit(&self, id: u32, ray: &Ray) -> Option<(f32, DVec3)> {
        let h = self.shapes[id as usize].intersect(ray)?;
        let normal = h.normal.as_dvec3();
        Some((h.t, if h.front_face { normal } else { -normal }))
    }

    fn spawn(&self, id: u32, ray: &Ray, t: f32, dir: Vec3) -> Option<Ray> {
        self.shapes[id as usize].spawn(ray, t, dir)
    }
}

/// The spawned ray as shape `i` sees it: the surface ray on its own shape, the literal
/// segment on every other.
fn own_or_literal<'r>(spawned: &'r Spawned, literal: &'r Ray, i: usize) -> &'r Ray {
    if i == spawned.from as usize {
        &spawned.ray
    } else {
        literal
    }
}

/// Shape `i` (of class `ShapeClass::ALL[i % 6]`, [`FamilyScene::build`]) at centre `c`
/// with unit `axis`, R = `scale`.
fn shape(
    i: usize,
    c: DVec3,
    axis: DVec3,
    scale: f64,
    rng: &mut Pcg64,
) -> Result<FamilyShape, SceneError> {
    let class = ShapeClass::ALL[i % ShapeClass::ALL.len()];
    // The j-th shape of its class: cycles the aspects, and the segments' bores.
    let j = i / ShapeClass::ALL.len();
    let aspect = match ASPECTS[j % ASPECTS.len()] {
        0.0 => log_uniform(rng, 0.25, 4.0),
        a => a,
    };
    let toroid = |a: f64, b: f64| {
        Toroid::new(
            c.as_vec3(),
            axis.as_vec3(),
            scale as f32,
            (a * scale) as f32,
            (b * scale) as f32,
        )
        .map(FamilyShape::Toroid)
        .map_err(|e| SceneError(e.to_string()))
    };
    match class {
        ShapeClass::Ring => {
            let a = 1.0 / log_uniform(rng, 1.5, 8.0);
            toroid(a, a)
        }
        ShapeClass::Elliptic => {
            // Never 1: an elliptical tube.
            let aspect = if aspect == 1.0 { 3.0 } else { aspect };
            let a = 1.0 / log_uniform(rng, 1.5, 6.0);
            toroid(a, a * aspect)
        }
        ShapeClass::Horn => toroid(1.0, aspect),
        ShapeClass::Spindle => {
            let a = 1.0 / rng.random_range(0.5..0.95);
            toroid(a, a * aspect)
        }
        ShapeClass::BoredRing | ShapeClass::Segment => {
            let tube = 1.0 / log_uniform(rng, 1.5, 4.0);
            let segment = class == ShapeClass::Segment;
            // A ray meets the bore from outside only through a cut end's opening: wide
            // bores, and two segments in three with one.
            let bore = if segment && j % 3 == 0 {
                0.0
            } else {
                tube * rng.random_range(0.5..0.9)
            };
            let (start, delta) = if segment {
                (rng.random_range(0.0..TAU), rng.random_range(0.4..5.8))
            } else {
                (0.0, TAU)
            };
            PipeBend::new_f64(
                c,
                axis,
                phi_zero(axis),
                scale,
                bore * scale,
                tube * scale,
                start,
                delta,
            )
            .map(FamilyShape::Bend)
            .map_err(|e| SceneError(e.to_string()))
        }
    }
}

/// A number log-uniform in `lo..hi`.
fn log_uniform(rng: &mut Pcg64, lo: f64, hi: f64) -> f64 {
    rng.random_range(lo.ln()..hi.ln()).exp()
}

/// The direction of φ = 0 of a bend with unit `axis`: any direction across it, the same
/// for the bend's build and for [`FamilyScene::bore_rays`].
fn phi_zero(axis: DVec3) -> DVec3 {
    axis.any_orthonormal_pair().0
}
