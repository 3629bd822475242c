//! `uniform`: the "average" line, isotropic through the bounding sphere.

use super::{Batch, Frame, disk_point, unit_vector};
use rand_pcg::Pcg64;

/// Distribution: a direction uniform on the sphere and a point uniform in the disk of
/// radius R + r across it through the centre: the isotropic measure on lines that meet
/// the bounding sphere. The origin is 2(R + r) back along the line.
pub(super) fn fill(frame: &Frame, count: usize, rng: &mut Pcg64, batch: &mut Batch) {
    let outer = frame.outer();
    for _ in 0..count {
        let d = unit_vector(rng);
        let p = disk_point(rng, d, outer);
        batch.rays.push(frame.ray(p - d * (2.0 * outer), d));
    }
}
