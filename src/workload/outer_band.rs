//! `outer_band`: lines in Skala's case c), planes at distance [R, R + r) from the axis.

use super::{Batch, Frame};
use glam::DVec3;
use rand::RngExt;
use rand_pcg::Pcg64;

/// Distribution: the holding plane (parallel to the axis) is at distance a uniform in
/// [R, R + r) with a uniform azimuth. In that plane the line passes through a point
/// uniform in the section's bounding rectangle |X| ≤ √((R + r)² − a²),
/// |Y| ≤ √(r² − (a − R)²), with an in-plane direction of uniform angle. The origin is
/// 2(R + r) back along the line.
pub(super) fn fill(frame: &Frame, count: usize, rng: &mut Pcg64, batch: &mut Batch) {
    let (big_r, small_r, outer) = (frame.major, frame.minor, frame.outer());
    for _ in 0..count {
        let a = rng.random_range(big_r..outer);
        let azimuth = rng.random_range(0.0..std::f64::consts::TAU);
        let normal = DVec3::new(azimuth.cos(), 0.0, azimuth.sin());
        let along = DVec3::new(-azimuth.sin(), 0.0, azimuth.cos());
        let half_width = (outer * outer - a * a).max(0.0).sqrt();
        let half_height = (small_r * small_r - (a - big_r).powi(2)).max(0.0).sqrt();
        let x = rng.random_range(-1.0..=1.0) * half_width;
        let y = rng.random_range(-1.0..=1.0) * half_height;
        let angle = rng.random_range(0.0..std::f64::consts::TAU);
        let d = along * angle.cos() + DVec3::Y * angle.sin();
        let target = normal * a + along * x + DVec3::Y * y;
        batch.rays.push(frame.ray(target - d * (2.0 * outer), d));
    }
}
