//! The ray families of the f32 check (issue 19): the adversarial lines, the scale, ν and
//! distance sweeps, secondary rays, and the five workload generators at a ν sweep. Each
//! family draws `(Torus, Ray)` pairs deterministically from a seed (Pcg64).
//!
//! Families whose name does not say otherwise draw ν = R/r per ray, log-uniform in
//! [[`NU_MIN`], [`NU_MAX`]]. The adversarial lines are built on the canonical torus
//! (centre 0, axis +y, R = 1) directly in world coordinates, so that only the rounding of
//! the ray to f32 moves them; the sweeps and the generators use a random pose.
//!
//! An offset "±δ·r" is the requested one; after the ray is rounded to f32 the true margin
//! can differ by about 1e-7 of the origin's distance, which is more than δ·r for thin
//! tori. Every ray is labelled by the oracle as it is, so this changes what a family
//! holds, never the counts' meaning.

use crate::workload::adversarial::{
    SpecialCircle, hole_edge_line, random_azimuth, random_pose_torus, tangent_line,
};
use crate::workload::{self, Case, GenerateError, Pose, disk_point, unit_vector};
use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::Named;
use torus_cull::{Ray, Torus};

/// The smallest ν the sweeps draw.
pub const NU_MIN: f64 = 1.01;
/// The largest ν the sweeps draw ([`torus_cull::MAX_NU`]).
pub const NU_MAX: f64 = torus_cull::MAX_NU;
/// The ν values each workload generator runs at.
pub const GENERATOR_NUS: [f64; 8] = [1.01, 1.1, 1.5, 2.0, 4.0, 10.0, 100.0, 1000.0];
/// The tangent offsets (× r) of the `tangent_*` families; each family alternates ±.
pub const TANGENT_OFFSETS: [f64; 2] = [1e-6, 1e-7];
/// The farthest origin of the `far_*` families, × (R + r).
pub const FAR_MAX: f64 = 250.0;
/// The smallest and largest R of the `scale_*` families.
pub const SCALE_RANGE: [f64; 2] = [1e-3, 1e3];
/// `t_min` of the secondary rays, × r (× (R + r) for `secondary_scene_eps`).
pub const SECONDARY_EPS: f64 = 1e-4;

/// What a family draws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FamilyKind {
    /// [`hole_edge_line`]s (inside the tube 3 times in 4), origin 3(R + r) back.
    HoleEdge,
    /// [`tangent_line`]s on `circle`, pushed ±`offset`·r (alternating), origin 3(R + r)
    /// back.
    Tangent {
        /// The special circle.
        circle: SpecialCircle,
        /// |δ|.
        offset: f64,
    },
    /// Lines tangent to the torus at two points, pushed ±1e-6·r: horizontal lines in the
    /// planes y = ±r (touching the top or bottom circle twice), and lines through the
    /// centre in a meridian plane touching the tube on both sides of the hole.
    Bitangent,
    /// Isotropic lines through the bounding sphere, origin log-uniform in [2, 250]·(R + r)
    /// back, random pose.
    FarUniform,
    /// Tangent lines (the four circles in turn, δ cycling ±1e-2, ±1e-4), origin
    /// log-uniform in [2, 250]·(R + r) back, random pose.
    FarTangent,
    /// Isotropic lines, R log-uniform in [1e-3, 1e3], random pose, origin 2(R + r) back.
    ScaleUniform,
    /// Tangent lines (±1e-6·r, the four circles in turn), R log-uniform in [1e-3, 1e3],
    /// random pose, origin 3(R + r) back.
    ScaleTangent,
    /// Shadow and bounce rays: origin a point of the surface (area-uniform, f64, rounded
    /// to f32), direction uniform in the outward hemisphere, `t_min` = 1e-4·r.
    Secondary,
    /// The same with grazing directions: the angle to the tangent plane log-uniform in
    /// [1e-4, 1e-1] rad.
    SecondaryGrazing,
    /// [`FamilyKind::Secondary`] with `t_min` = 1e-4·(R + r), a scene-scale ε (for thin
    /// tubes 1000 times the tube-scale one).
    SecondarySceneEps,
    /// Spawned secondary rays ([`Ray::from_surface`]: the origin's own root excluded, as a
    /// renderer gets from `Torus::spawn`), R log-uniform in [1e-3, 1e3], ν log-uniform,
    /// random pose; the origin a surface point (area-uniform, f64, rounded to f32).
    Spawned {
        /// The directions.
        aim: SpawnAim,
        /// `t_min` = [`SECONDARY_EPS`]·(R + r) (a scene-scale ε), else
        /// [`SECONDARY_EPS`]·r.
        scene_eps: bool,
    },
    /// A workload generator at one ν ([`workload::generate`], random pose).
    Generator {
        /// The case.
        case: Case,
        /// ν.
        nu: f64,
    },
}

/// The directions of a [`FamilyKind::Spawned`] family.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpawnAim {
    /// Cosine-weighted about the outward normal (a diffuse bounce).
    Bounce,
    /// The angle to the tangent plane log-uniform in [1e-4, 1e-1] rad, outward.
    Grazing,
    /// At another surface point (area-uniform): across the hole, over or through the
    /// tube, where re-hits are common; about half go into the tube.
    Across,
    /// From the inner half of the tube (the saddle, where the surface curves toward the
    /// hole along the ring), within [`SADDLE_TURN`] of the ring's direction, at an angle to
    /// the tangent plane log-uniform in [`SADDLE_ANGLES`], outward: the surface comes back
    /// to meet such a ray after an excursion that can be below an f32 origin's rounding.
    Saddle,
}

/// The angles above the tangent plane (rad) of the `spawned_saddle` family.
pub const SADDLE_ANGLES: [f64; 2] = [1e-5, 1e-2];
/// How far (rad) a `spawned_saddle` ray turns from the ring's direction in the tangent
/// plane.
pub const SADDLE_TURN: f64 = 0.05;

/// One family: a name (stable, for the JSON) and what it draws.
#[derive(Debug, Clone, PartialEq)]
pub struct Family {
    /// The stable name; a generator family is named after its case (ν apart).
    pub name: String,
    /// What it draws.
    pub kind: FamilyKind,
}

impl Family {
    /// ν if the whole family has one, else `None` (ν drawn per ray).
    pub fn nu(&self) -> Option<f64> {
        match self.kind {
            FamilyKind::Generator { nu, .. } => Some(nu),
            _ => None,
        }
    }

    /// Whether the family is one of the five workload generators.
    pub fn is_generator(&self) -> bool {
        matches!(self.kind, FamilyKind::Generator { .. })
    }

    /// `count` rays of the family, deterministic in `seed`.
    pub fn generate(&self, count: usize, seed: u64) -> Result<Vec<(Torus, Ray)>, GenerateError> {
        if let FamilyKind::Generator { case, nu } = self.kind {
            let batch = workload::generate(case, nu, count, seed, Pose::Random)?;
            return Ok(batch.rays.into_iter().map(|r| (batch.torus, r)).collect());
        }
        let mut rng = Pcg64::seed_from_u64(family_seed(seed, &self.name));
        let mut out = Vec::with_capacity(count);
        let mut i = 0usize;
        // A candidate f32 cannot hold (it never happens for these sizes) is redrawn; the
        // bound only keeps a bug from spinning.
        while out.len() < count && i < 4 * count + 100 {
            if let Some(pair) = self.draw(&mut rng, out.len()) {
                out.push(pair);
            }
            i += 1;
        }
        Ok(out)
    }

    fn draw(&self, rng: &mut Pcg64, i: usize) -> Option<(Torus, Ray)> {
        let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
        match self.kind {
            FamilyKind::HoleEdge => {
                let torus = canonical(rng);
                let r = minor(&torus);
                let (p, d) = hole_edge_line(rng, 1.0, r);
                Some((torus, world_ray(&torus, p - d * 3.0 * (1.0 + r), d, 0.0)?))
            }
            FamilyKind::Tangent { circle, offset } => {
                let torus = canonical(rng);
                let r = minor(&torus);
                let (p, d) = tangent_line(rng, 1.0, r, circle, sign * offset);
                Some((torus, world_ray(&torus, p - d * 3.0 * (1.0 + r), d, 0.0)?))
            }
            FamilyKind::Bitangent => {
                let torus = canonical(rng);
                let delta = if (i / 2) % 2 == 0 { 1e-6 } else { -1e-6 };
                Some((torus, bitangent_ray(rng, &torus, delta, i % 2 == 0)?))
            }
            FamilyKind::FarUniform => {
                let torus = posed_unit_torus(rng);
                let outer = outer(&torus);
                let d = unit_vector(rng);
                let p = disk_point(rng, d, outer);
                let back = log_uniform(rng, 2.0, FAR_MAX) * outer;
                Some((torus, world_ray(&torus, p - d * back, d, 0.0)?))
            }
            FamilyKind::FarTangent => {
                let torus = posed_unit_torus(rng);
                let (outer, r) = (outer(&torus), minor(&torus));
                let delta = [1e-2, -1e-2, 1e-4, -1e-4][(i / 4) % 4];
                let (p, d) = tangent_line(rng, 1.0, r, SpecialCircle::ALL[i % 4], delta);
                let back = log_uniform(rng, 2.0, FAR_MAX) * outer;
                Some((torus, world_ray(&torus, p - d * back, d, 0.0)?))
            }
            FamilyKind::ScaleUniform => {
                let torus = scaled_torus(rng);
                let outer = outer(&torus);
                let d = unit_vector(rng);
                let p = disk_point(rng, d, outer);
                Some((torus, world_ray(&torus, p - d * 2.0 * outer, d, 0.0)?))
            }
            FamilyKind::ScaleTangent => {
                let torus = scaled_torus(rng);
                let (big, r) = (f64::from(torus.major_radius()), minor(&torus));
                let circle = SpecialCircle::ALL[i % 4];
                let delta = if (i / 4) % 2 == 0 { 1e-6 } else { -1e-6 };
                let (p, d) = tangent_line(rng, big, r, circle, delta);
                Some((torus, world_ray(&torus, p - d * 3.0 * (big + r), d, 0.0)?))
            }
            FamilyKind::Secondary | FamilyKind::SecondaryGrazing => {
                let torus = canonical(rng);
                let grazing = self.kind == FamilyKind::SecondaryGrazing;
                let eps = SECONDARY_EPS * minor(&torus);
                Some((torus, secondary_ray(rng, &torus, grazing, eps)?))
            }
            FamilyKind::SecondarySceneEps => {
                let torus = canonical(rng);
                let eps = SECONDARY_EPS * outer(&torus);
                Some((torus, secondary_ray(rng, &torus, false, eps)?))
            }
            FamilyKind::Spawned { aim, scene_eps } => {
                let torus = scaled_torus(rng);
                let eps = SECONDARY_EPS
                    * if scene_eps {
                        outer(&torus)
                    } else {
                        minor(&torus)
                    };
                Some((torus, spawned_ray(rng, &torus, aim, eps)?))
            }
            FamilyKind::Generator { .. } => unreachable!("generated by workload::generate"),
        }
    }
}

/// Every family, in table order: the adversarial lines, the sweeps, the secondary rays,
/// then the five generators at each of [`GENERATOR_NUS`].
pub fn all() -> Vec<Family> {
    let mut out = vec![Family {
        name: "hole_edge".into(),
        kind: FamilyKind::HoleEdge,
    }];
    for offset in TANGENT_OFFSETS {
        for circle in SpecialCircle::ALL {
            out.push(Family {
                name: format!("tangent_{offset:e}_{}", circle.name()),
                kind: FamilyKind::Tangent { circle, offset },
            });
        }
    }
    for (name, kind) in [
        ("bitangent", FamilyKind::Bitangent),
        ("far_uniform", FamilyKind::FarUniform),
        ("far_tangent", FamilyKind::FarTangent),
        ("scale_uniform", FamilyKind::ScaleUniform),
        ("scale_tangent", FamilyKind::ScaleTangent),
        ("secondary", FamilyKind::Secondary),
        ("secondary_grazing", FamilyKind::SecondaryGrazing),
        ("secondary_scene_eps", FamilyKind::SecondarySceneEps),
        (
            "spawned_bounce",
            FamilyKind::Spawned {
                aim: SpawnAim::Bounce,
                scene_eps: false,
            },
        ),
        (
            "spawned_bounce_scene_eps",
            FamilyKind::Spawned {
                aim: SpawnAim::Bounce,
                scene_eps: true,
            },
        ),
        (
            "spawned_grazing",
            FamilyKind::Spawned {
                aim: SpawnAim::Grazing,
                scene_eps: false,
            },
        ),
        (
            "spawned_across",
            FamilyKind::Spawned {
                aim: SpawnAim::Across,
                scene_eps: false,
            },
        ),
        (
            "spawned_saddle",
            FamilyKind::Spawned {
                aim: SpawnAim::Saddle,
                scene_eps: false,
            },
        ),
    ] {
        out.push(Family {
            name: name.into(),
            kind,
        });
    }
    for &case in Case::ALL {
        for nu in GENERATOR_NUS {
            out.push(Family {
                name: case.name().into(),
                kind: FamilyKind::Generator { case, nu },
            });
        }
    }
    out
}

/// A line tangent to the torus at two points, pushed off by `delta·r` at both, from the
/// canonical torus's frame:
///
/// - `in_plane`: a horizontal line in the plane y = ±(1 + δ)·r, at a distance uniform in
///   [0, 0.98 R) from the axis. The plane touches the torus along the top (or bottom)
///   circle and the torus lies below it, so the line touches it where it crosses that
///   circle, twice. Its direction has dy = 0 and its origin's y is (1 + δ)·r rounded once.
/// - otherwise: a line through the centre in a meridian plane at angle asin((1 + δ)·r/R)
///   to the equatorial plane, tangent to the tube's section on both sides of the hole.
///   The ray is `o = −3(R + r)·d̂` rounded to f32 with direction `−o` exactly, so the line
///   passes through the centre whatever the rounding, and the angle keeps δ to ~1e-7.
fn bitangent_ray(rng: &mut Pcg64, torus: &Torus, delta: f64, in_plane: bool) -> Option<Ray> {
    let (big, r) = (f64::from(torus.major_radius()), minor(torus));
    let side = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
    let (radial, along) = random_azimuth(rng);
    if in_plane {
        let y = side * (1.0 + delta) * r;
        let a = rng.random_range(0.0..0.98) * big;
        let anchor = radial * a + DVec3::Y * y;
        world_ray(torus, anchor - along * 3.0 * (big + r), along, 0.0)
    } else {
        let alpha = ((1.0 + delta) * r / big).asin();
        let d = radial * alpha.cos() + DVec3::Y * (side * alpha.sin());
        let o = (-d * 3.0 * (big + r)).as_vec3();
        Ray::new(o, -o).ok()
    }
}

/// A secondary ray on the canonical torus: a surface point (area-uniform), a direction
/// leaving the surface, `t_min` = `eps`.
fn secondary_ray(rng: &mut Pcg64, torus: &Torus, grazing: bool, eps: f64) -> Option<Ray> {
    let (big, r) = (f64::from(torus.major_radius()), minor(torus));
    // θ around the tube, weighted by the area element (R + r cos θ).
    let theta = loop {
        let theta = rng.random_range(0.0..std::f64::consts::TAU);
        if rng.random_range(0.0..big + r) < big + r * theta.cos() {
            break theta;
        }
    };
    let (radial, along) = random_azimuth(rng);
    let (st, ct) = theta.sin_cos();
    let point = radial * (big + r * ct) + DVec3::Y * (r * st);
    let normal = radial * ct + DVec3::Y * st;
    let tube = -radial * st + DVec3::Y * ct;
    let cos_out = if grazing {
        log_uniform(rng, 1e-4, 1e-1).sin()
    } else {
        rng.random_range(0.0..1.0f64).max(1e-12)
    };
    let sin_out = (1.0 - cos_out * cos_out).sqrt();
    let beta = rng.random_range(0.0..std::f64::consts::TAU);
    let d = normal * cos_out + (along * beta.cos() + tube * beta.sin()) * sin_out;
    Ray::with_range(point.as_vec3(), d.as_vec3(), eps as f32, f32::INFINITY).ok()
}

/// A point of the canonical-frame surface, area-uniform (θ around the tube weighted by
/// R + r·cos θ), and the outward normal there.
fn surface_point(rng: &mut Pcg64, big: f64, r: f64) -> (DVec3, DVec3) {
    let theta = loop {
        let theta = rng.random_range(0.0..std::f64::consts::TAU);
        if rng.random_range(0.0..big + r) < big + r * theta.cos() {
            break theta;
        }
    };
    let (radial, _) = random_azimuth(rng);
    tube_point(radial, theta, big, r)
}

/// The canonical-frame surface point at angle θ around the tube (0 on the outer equator)
/// in the meridian plane of the unit horizontal `radial`, and the outward normal there.
pub fn tube_point(radial: DVec3, theta: f64, big: f64, r: f64) -> (DVec3, DVec3) {
    let (st, ct) = theta.sin_cos();
    (
        radial * (big + r * ct) + DVec3::Y * (r * st),
        radial * ct + DVec3::Y * st,
    )
}

/// A saddle ray's direction from the canonical-frame surface point `p` with outward
/// normal `n`: along the ring (`sign` picks the way), turned by `turn` toward the
/// meridian in the tangent plane, then `alpha` above it.
pub fn saddle_direction(p: DVec3, n: DVec3, alpha: f64, turn: f64, sign: f64) -> DVec3 {
    let ring = DVec3::Y.cross(DVec3::new(p.x, 0.0, p.z)).normalize() * sign;
    let meridian = n.cross(ring);
    (ring * turn.cos() + meridian * turn.sin()) * alpha.cos() + n * alpha.sin()
}

/// A point of the inner half of the tube (cos θ < 0, θ uniform) and its outward normal.
fn saddle_point(rng: &mut Pcg64, big: f64, r: f64) -> (DVec3, DVec3) {
    let theta = rng.random_range(0.5..1.5) * std::f64::consts::PI;
    let (radial, _) = random_azimuth(rng);
    tube_point(radial, theta, big, r)
}

/// A spawned secondary ray ([`Ray::from_surface`]) from a surface point of `torus`
/// (posed), aimed by `aim`, over `t ≥ eps` (|d| = 1 but for `Across`, whose `eps` is
/// divided by |d|).
fn spawned_ray(rng: &mut Pcg64, torus: &Torus, aim: SpawnAim, eps: f64) -> Option<Ray> {
    let (big, r) = (f64::from(torus.major_radius()), minor(torus));
    let (p, n) = if aim == SpawnAim::Saddle {
        saddle_point(rng, big, r)
    } else {
        surface_point(rng, big, r)
    };
    let t1 = n.any_orthonormal_vector();
    let t2 = n.cross(t1);
    let d = match aim {
        SpawnAim::Bounce | SpawnAim::Grazing => {
            let cos_out = if aim == SpawnAim::Grazing {
                log_uniform(rng, 1e-4, 1e-1).sin()
            } else {
                rng.random_range(0.0..1.0f64).sqrt().max(1e-12)
            };
            let sin_out = (1.0 - cos_out * cos_out).sqrt();
            let beta = rng.random_range(0.0..std::f64::consts::TAU);
            n * cos_out + (t1 * beta.cos() + t2 * beta.sin()) * sin_out
        }
        SpawnAim::Saddle => {
            let alpha = log_uniform(rng, SADDLE_ANGLES[0], SADDLE_ANGLES[1]);
            let turn = rng.random_range(-SADDLE_TURN..SADDLE_TURN);
            let sign = if rng.random_range(0.0..1.0f64) < 0.5 {
                -1.0
            } else {
                1.0
            };
            saddle_direction(p, n, alpha, turn, sign)
        }
        SpawnAim::Across => {
            let (q, _) = surface_point(rng, big, r);
            (q - p).normalize_or_zero()
        }
    };
    if d == DVec3::ZERO {
        return None;
    }
    let to_world = torus.to_local_rotation_f64().transpose();
    let origin = (to_world * p + torus.center().as_dvec3()).as_vec3();
    let dir: Vec3 = (to_world * d).as_vec3();
    Ray::from_surface_with_range(origin, dir, eps as f32, f32::INFINITY).ok()
}

/// The torus-frame line `o + t·d` as a world ray over `t ≥ t_min` (f64, rounded once).
fn world_ray(torus: &Torus, o: DVec3, d: DVec3, t_min: f32) -> Option<Ray> {
    let to_world = torus.to_local_rotation_f64().transpose();
    let origin = (to_world * o + torus.center().as_dvec3()).as_vec3();
    let dir: Vec3 = (to_world * d).as_vec3();
    Ray::with_range(origin, dir, t_min, f32::INFINITY).ok()
}

/// The canonical torus R = 1 with ν log-uniform in [NU_MIN, NU_MAX].
fn canonical(rng: &mut Pcg64) -> Torus {
    Torus::canonical(1.0, (1.0 / log_nu(rng)) as f32).expect("1 < nu <= MAX_NU")
}

/// R = 1, ν log-uniform, a random pose.
fn posed_unit_torus(rng: &mut Pcg64) -> Torus {
    let nu = log_nu(rng);
    random_pose_torus(rng, 1.0, (1.0 / nu) as f32)
}

/// R log-uniform in [`SCALE_RANGE`], ν log-uniform, a random pose.
fn scaled_torus(rng: &mut Pcg64) -> Torus {
    let big = log_uniform(rng, SCALE_RANGE[0], SCALE_RANGE[1]);
    let nu = log_nu(rng);
    random_pose_torus(rng, big as f32, (big / nu) as f32)
}

fn log_nu(rng: &mut Pcg64) -> f64 {
    // NU_MAX itself would round r to just under R/1000 in f32 and fail the limit's slack
    // only if that slack were zero; stay a hair inside anyway.
    log_uniform(rng, NU_MIN, NU_MAX * (1.0 - 1e-6))
}

fn log_uniform(rng: &mut Pcg64, lo: f64, hi: f64) -> f64 {
    rng.random_range(lo.ln()..hi.ln()).exp()
}

fn minor(torus: &Torus) -> f64 {
    f64::from(torus.minor_radius())
}

fn outer(torus: &Torus) -> f64 {
    f64::from(torus.major_radius()) + f64::from(torus.minor_radius())
}

/// A family's stream seed: SplitMix64 over the seed and the name's FNV-1a hash.
fn family_seed(seed: u64, name: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
    }
    let mut z = seed ^ h;
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::oracle::Query;

    #[test]
    fn families_are_deterministic_and_full() {
        for family in all().iter().filter(|f| !f.is_generator()) {
            let a = family.generate(50, 7).unwrap();
            let b = family.generate(50, 7).unwrap();
            assert_eq!(a, b, "{}", family.name);
            assert_eq!(a.len(), 50, "{}", family.name);
            assert_ne!(a, family.generate(50, 8).unwrap(), "{}", family.name);
        }
    }

    /// The bitangent lines touch where they should: at δ = ±1e-3 (which f32 resolves at
    /// every ν drawn) the oracle's margin is δ·r.
    #[test]
    fn bitangent_lines_are_pushed_by_delta() {
        let mut rng = Pcg64::seed_from_u64(3);
        for i in 0..400 {
            let torus = canonical(&mut rng);
            let r = minor(&torus);
            let delta = if i % 4 < 2 { 1e-3 } else { -1e-3 };
            let ray = bitangent_ray(&mut rng, &torus, delta, i % 2 == 0).unwrap();
            let margin = Query::line(&torus, &ray).classify().margin;
            assert!(
                (margin - delta * r).abs() < 1e-5 * r + 1e-7,
                "#{i} nu {}: margin {margin:e}, want {:e}",
                torus.nu(),
                delta * r
            );
        }
    }

    /// A secondary ray starts on the surface (to rounding) and leaves it: at its t_min it
    /// is outside the tube or within rounding of it.
    #[test]
    fn secondary_rays_leave_the_surface() {
        let mut rng = Pcg64::seed_from_u64(4);
        let mut outside = 0;
        for _ in 0..1000 {
            let torus = canonical(&mut rng);
            let ray =
                secondary_ray(&mut rng, &torus, false, SECONDARY_EPS * minor(&torus)).unwrap();
            let x = ray.at(ray.t_min()).as_dvec3();
            let rho = (x.x * x.x + x.z * x.z).sqrt();
            let g = (rho - 1.0).hypot(x.y) - minor(&torus);
            assert!(g > -1e-6, "{g:e}");
            outside += usize::from(g > 0.0);
        }
        // The rest start inside by f32's rounding of the surface point (thin tubes, grazing
        // directions): the oracle labels them as they are.
        assert!(outside > 900, "{outside}");
    }
}
