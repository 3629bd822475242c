//! Workload generators: deterministic ray batches per case and ν.
//!
//! Each case has its own file and documents its distribution. A batch is one torus with
//! R = 1 and r = 1/ν at a random world pose (or the canonical pose on request) and rays
//! in world space, drawn from a Pcg64 stream seeded from (seed, case, ν): the same
//! inputs always give the same rays, whatever else is generated.
//!
//! Rays start before the torus. For every case but `grazing` the origin is outside the
//! bounding sphere, so the ray t ≥ 0 and the whole line meet the torus alike; a grazing
//! origin is (R + r) back from its tangent point and can lie inside the sphere (about
//! 15 % of them at ν = 1.25), so there the ray may miss a part of the torus its line
//! meets behind the origin. The false-reject counts are safe either way: a ray hit is a
//! line hit, and every cull is a line test.

pub mod adversarial;
pub mod bend_spec;
pub mod box_rays;
mod camera;
mod field_list;
mod grazing;
mod hole;
mod outer_band;
pub mod secondary;
pub mod shapes_spec;
pub mod spec;
mod uniform;

pub use crate::random::unit_vector;
pub use camera::CameraView;
pub use grazing::GRAZING_OFFSETS;

use crate::oracle::{OracleLabel, classify};
use glam::{DMat3, DVec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use serde::{Deserialize, Serialize};
use std::fmt;
use torus_cull::{Ray, Torus};

crate::named::named_enum! {
    /// A workload case; [`Named::ALL`](torus_cull::Named::ALL) lists every case by its stable name, in table order.
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
    #[serde(rename_all = "snake_case")]
    pub enum Case: "case" {
        /// Lines that fall through the hole (all misses).
        Hole = "hole",
        /// Lines in planes at distance [R, R + r) from the axis (Skala's case c).
        OuterBand = "outer_band",
        /// Lines tangent to the surface, pushed off it by ±1e-2, ±1e-4, ±1e-6 of r.
        Grazing = "grazing",
        /// Isotropic lines through the bounding sphere.
        Uniform = "uniform",
        /// Primary rays of a pinhole camera framing the torus.
        Camera = "camera",
    }
}

impl Case {
    /// Whether the case is defined only for a torus with a hole (ν > 1).
    pub fn needs_hole(self) -> bool {
        matches!(self, Case::Hole)
    }

    /// The smallest ν a workload may ask of this case. `hole` draws lines through the
    /// hole's disk and keeps the misses: about 0.4·(ν − 1) of them, so below ν ≈ 1.0025
    /// its 1000 tries per ray cannot succeed (ν = 1.0000001 once spun for minutes before
    /// failing); 1.01 keeps a margin of 4 (about 0.4 % kept). Every other case takes any
    /// ν > 1.
    pub fn min_nu(self) -> f64 {
        match self {
            Case::Hole => 1.01,
            _ => f64::MIN_POSITIVE,
        }
    }
}

torus_cull::named_display_and_from_str!(Case);

/// Where the torus sits in the world.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Pose {
    /// Centre uniform in the cube [−(R+r), R+r]³, axis uniform on the sphere.
    #[default]
    Random,
    /// Centre at the origin, axis +y.
    Canonical,
}

/// One generated batch: a torus and rays in world space.
#[derive(Debug, Clone)]
pub struct Batch {
    /// The case.
    pub case: Case,
    /// ν = R/r as requested.
    pub nu: f64,
    /// The stream seed the batch was drawn from.
    pub stream_seed: u64,
    /// The torus (R = 1, r = 1/ν).
    pub torus: Torus,
    /// The rays, world space.
    pub rays: Vec<Ray>,
    /// Grazing only: the requested signed offset of each ray from the surface, length units.
    pub offsets: Vec<f64>,
    /// Camera only: the view the rays were shot from.
    pub camera: Option<CameraView>,
}

/// Why a batch could not be generated.
#[derive(Debug, Clone, PartialEq)]
pub enum GenerateError {
    /// ν is not a valid ring torus ratio.
    BadNu(f64),
    /// Rejection sampling gave up: too few candidates survived.
    Exhausted {
        /// The case.
        case: Case,
        /// ν.
        nu: f64,
        /// Rays produced before giving up.
        produced: usize,
        /// Rays requested.
        requested: usize,
    },
}

impl fmt::Display for GenerateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GenerateError::BadNu(nu) => {
                write!(
                    f,
                    "nu = {} is invalid (allowed: 1 < nu <= {})",
                    crate::number::Num(*nu),
                    torus_cull::MAX_NU
                )
            }
            GenerateError::Exhausted {
                case,
                nu,
                produced,
                requested,
            } => write!(
                f,
                "case {case} at nu = {nu}: rejection sampling produced only {produced} of {requested} rays"
            ),
        }
    }
}

impl std::error::Error for GenerateError {}

/// The stream seed for (seed, case, ν): SplitMix64 over the three, so neighbouring
/// seeds or ν values give unrelated streams.
pub fn stream_seed(seed: u64, case: Case, nu: f64) -> u64 {
    let mut h = splitmix64(seed);
    h = splitmix64(h ^ (case as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    splitmix64(h ^ nu.to_bits())
}

fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Generate `count` rays of `case` for ν with the given seed and pose.
pub fn generate(
    case: Case,
    nu: f64,
    count: usize,
    seed: u64,
    pose: Pose,
) -> Result<Batch, GenerateError> {
    draw(case, nu, count, seed, pose).map(|(batch, _)| batch)
}

/// [`generate`] for a workload's (case, ν), with the oracle's label of every ray
/// ([`crate::oracle::classify`], ray mode): a rejection-sampled case (`hole`, `grazing`)
/// kept each ray by its label, so those labels are handed on, not asked of the oracle a
/// second time; the other cases' rays are labeled here.
pub fn generate_labeled(
    workload: &spec::Workload,
    case: Case,
    nu: f64,
) -> Result<Drawn, GenerateError> {
    let (batch, mut labels) = draw(case, nu, workload.rays, workload.seed, workload.pose)?;
    if labels.len() != batch.rays.len() {
        labels = batch
            .rays
            .iter()
            .map(|r| classify(&batch.torus, r))
            .collect();
    }
    Ok((batch, labels))
}

/// A batch and the oracle's labels of its rays.
pub type Drawn = (Batch, Vec<OracleLabel>);

/// The batch, with the labels of its rays where the case drew them by rejection sampling
/// (none otherwise).
fn draw(case: Case, nu: f64, count: usize, seed: u64, pose: Pose) -> Result<Drawn, GenerateError> {
    if !(nu.is_finite() && nu > 1.0) {
        return Err(GenerateError::BadNu(nu));
    }
    let stream_seed = stream_seed(seed, case, nu);
    let mut rng = Pcg64::seed_from_u64(stream_seed);
    let torus = Torus::new(glam::Vec3::ZERO, glam::Vec3::Y, 1.0, (1.0 / nu) as f32)
        .map_err(|_| GenerateError::BadNu(nu))?;
    let frame = PosedTorus::draw(&torus, pose, &mut rng);
    let mut batch = Batch {
        case,
        nu,
        stream_seed,
        torus: frame.torus,
        rays: Vec::with_capacity(count),
        offsets: Vec::new(),
        camera: None,
    };
    let mut labels = Vec::new();
    match case {
        Case::Hole => rejection_sample(&mut batch, count, hole::MAX_TRIES_PER_RAY, |b| {
            labels.extend(hole::candidate(&frame, &mut rng, b));
        })?,
        Case::OuterBand => outer_band::fill(&frame, count, &mut rng, &mut batch),
        Case::Grazing => rejection_sample(&mut batch, count, grazing::MAX_TRIES_PER_RAY, |b| {
            labels.extend(grazing::candidate(&frame, &mut rng, b));
        })?,
        Case::Uniform => uniform::fill(&frame, count, &mut rng, &mut batch),
        Case::Camera => camera::fill(&frame, count, &mut rng, &mut batch),
    }
    Ok((batch, labels))
}

/// The torus at its pose, with the f64 torus-frame → world map used to place rays.
pub(crate) struct PosedTorus {
    pub torus: Torus,
    pub major: f64,
    pub minor: f64,
    center: DVec3,
    to_world: DMat3,
}

/// The generators' name for [`PosedTorus`] (their files still say `Frame`).
pub(crate) type Frame = PosedTorus;

impl PosedTorus {
    fn draw(canonical: &Torus, pose: Pose, rng: &mut Pcg64) -> PosedTorus {
        let (major, minor) = (
            canonical.major_radius() as f64,
            canonical.minor_radius() as f64,
        );
        let torus = match pose {
            Pose::Canonical => *canonical,
            Pose::Random => {
                let extent = major + minor;
                let center = DVec3::new(
                    rng.random_range(-extent..extent),
                    rng.random_range(-extent..extent),
                    rng.random_range(-extent..extent),
                );
                let axis = unit_vector(rng);
                Torus::new(center.as_vec3(), axis.as_vec3(), major as f32, minor as f32)
                    .expect("a valid canonical torus stays valid at any pose")
            }
        };
        PosedTorus {
            center: torus.center().as_dvec3(),
            to_world: torus.to_local_rotation_f64().transpose(),
            torus,
            major,
            minor,
        }
    }

    /// The torus-frame line `o + t·d` as a world-space f32 ray over t ≥ 0.
    pub fn ray(&self, o: DVec3, d: DVec3) -> Ray {
        let origin = (self.to_world * o + self.center).as_vec3();
        let dir = (self.to_world * d).as_vec3();
        Ray::new(origin, dir).expect("generated rays are finite with unit-scale directions")
    }

    /// R + r.
    pub fn outer(&self) -> f64 {
        self.major + self.minor
    }
}

/// Rejection sampling: `draw` is called once per candidate and pushes the rays it keeps,
/// until `count` are kept; after `max_tries_per_ray · count` candidates it gives up with
/// [`GenerateError::Exhausted`] rather than loop forever.
pub(crate) fn rejection_sample(
    batch: &mut Batch,
    count: usize,
    max_tries_per_ray: usize,
    mut draw: impl FnMut(&mut Batch),
) -> Result<(), GenerateError> {
    let max_tries = max_tries_per_ray * count.max(1);
    let mut tries = 0usize;
    while batch.rays.len() < count {
        if tries == max_tries {
            return Err(GenerateError::Exhausted {
                case: batch.case,
                nu: batch.nu,
                produced: batch.rays.len(),
                requested: count,
            });
        }
        tries += 1;
        draw(batch);
    }
    Ok(())
}

/// A point uniform in the disk of `radius` across the unit direction `d`.
pub(crate) fn disk_point(rng: &mut Pcg64, d: DVec3, radius: f64) -> DVec3 {
    let (e1, e2) = d.any_orthonormal_pair();
    let rad = radius * rng.random::<f64>().sqrt();
    let phi = rng.random_range(0.0..std::f64::consts::TAU);
    e1 * (rad * phi.cos()) + e2 * (rad * phi.sin())
}
