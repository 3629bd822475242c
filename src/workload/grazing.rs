//! `grazing`: lines tangent to the surface, pushed off it by a signed fraction of r.

use super::{Batch, Frame};
use crate::oracle::{OracleLabel, Query};
use glam::DVec3;
use rand::RngExt;
use rand_pcg::Pcg64;

/// The signed offsets δ, as fractions of r, cycled over the batch.
pub const GRAZING_OFFSETS: [f64; 6] = [1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6];

/// How close (× (R + r)) the oracle's margin must be to δ·r for a candidate to be kept.
/// f32 rays place a line only to about 1e-7·(R + r), so smaller offsets are not resolved.
pub const GRAZING_TOLERANCE_REL: f64 = 1e-6;

/// Candidates per requested ray before giving up.
pub(super) const MAX_TRIES_PER_RAY: usize = 200;

/// One candidate of the rejection sampling ([`super::rejection_sample`]): pushed to `batch`
/// if kept, and its oracle label returned.
///
/// Distribution: a tangent point uniform in the torus parameters (φ, θ), a direction of
/// uniform angle in the tangent plane there, and the line pushed along the outward normal
/// by δ·r, δ cycling through [`GRAZING_OFFSETS`]. The origin is (R + r) back along the
/// line. A candidate whose closest approach is not at its tangent point (on the saddle
/// side a tangent line can dip into the tube elsewhere) is redrawn, so every ray's oracle
/// margin is within `GRAZING_TOLERANCE_REL·(R + r)` of δ·r.
pub(super) fn candidate(frame: &Frame, rng: &mut Pcg64, batch: &mut Batch) -> Option<OracleLabel> {
    let (big_r, small_r) = (frame.major, frame.minor);
    let offset = GRAZING_OFFSETS[batch.rays.len() % GRAZING_OFFSETS.len()] * small_r;
    let phi = rng.random_range(0.0..std::f64::consts::TAU);
    let theta = rng.random_range(0.0..std::f64::consts::TAU);
    let (sp, cp) = phi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let rho = big_r + small_r * ct;
    let point = DVec3::new(rho * cp, small_r * st, rho * sp);
    let normal = DVec3::new(ct * cp, st, ct * sp);
    let along_ring = DVec3::new(-sp, 0.0, cp);
    let along_tube = DVec3::new(-st * cp, ct, -st * sp);
    let alpha = rng.random_range(0.0..std::f64::consts::TAU);
    let d = along_ring * alpha.cos() + along_tube * alpha.sin();
    let touch = point + normal * offset;
    let ray = frame.ray(touch - d * frame.outer(), d);
    // A candidate is thrown away as soon as its margin is proved below δ·r − tolerance.
    let tolerance = GRAZING_TOLERANCE_REL * frame.outer();
    let too_deep = |m: f64| m - offset < -tolerance;
    let label = Query::ray(&frame.torus, &ray)
        .classify_unless(too_deep)
        .filter(|l| (l.margin - offset).abs() <= tolerance)?;
    batch.rays.push(ray);
    batch.offsets.push(offset);
    Some(label)
}
