//! `hole`: lines that fall through the hole.

use super::{Batch, Frame, unit_vector};
use crate::oracle::OracleClass::Miss;
use crate::oracle::{OracleLabel, Query};
use glam::DVec3;
use rand::RngExt;
use rand_pcg::Pcg64;

/// Candidates per requested ray before giving up (ν = 1.1 keeps about 4 %).
pub(super) const MAX_TRIES_PER_RAY: usize = 1000;

/// One candidate of the rejection sampling ([`super::rejection_sample`]): pushed to `batch`
/// if kept, and its oracle label returned.
///
/// Distribution: the line crosses y = 0 at a point uniform in the hole disk ρ < R − r,
/// with a direction uniform on the sphere; the origin is 2(R + r) back along the line.
/// Candidates the oracle does not call a miss are redrawn (rejection sampling), so every
/// ray of this case misses and miss capture equals rejection rate. Cychosz rejects none
/// of them: the crossing is inside its sphere and between its planes.
pub(super) fn candidate(frame: &Frame, rng: &mut Pcg64, batch: &mut Batch) -> Option<OracleLabel> {
    let hole_radius = frame.major - frame.minor;
    let rho = hole_radius * rng.random::<f64>().sqrt();
    let phi = rng.random_range(0.0..std::f64::consts::TAU);
    let crossing = DVec3::new(rho * phi.cos(), 0.0, rho * phi.sin());
    let d = unit_vector(rng);
    let ray = frame.ray(crossing - d * (2.0 * frame.outer()), d);
    // A candidate is thrown away as soon as its margin is proved not above the band.
    let query = Query::ray(&frame.torus, &ray);
    let not_miss = |m| OracleLabel::from_margin(m, query.major, query.minor).class != Miss;
    let label = query
        .classify_unless(not_miss)
        .filter(|label| label.class == Miss)?;
    batch.rays.push(ray);
    Some(label)
}
