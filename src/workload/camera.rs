//! `camera`: primary rays of a pinhole camera looking at the torus.

use super::{Batch, Frame, unit_vector};
use glam::DVec3;
use rand::RngExt;
use rand_pcg::Pcg64;

/// The pinhole view a camera batch was shot from (world space).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraView {
    /// Eye position.
    pub eye: DVec3,
    /// Unit view direction.
    pub forward: DVec3,
    /// Unit right vector.
    pub right: DVec3,
    /// Unit up vector.
    pub up: DVec3,
    /// tan of the half field of view (square image).
    pub tan_half_fov: f64,
}

/// Distribution: the eye is at a distance uniform in [2, 6]·(R + r) from the centre in a
/// direction uniform on the sphere, looks at the centre with a uniform roll, and its
/// square field of view is 15 % wider than the bounding sphere's silhouette. Each ray
/// goes through a point uniform on the image plane; directions are not normalized, as a
/// renderer's often are not.
pub(super) fn fill(frame: &Frame, count: usize, rng: &mut Pcg64, batch: &mut Batch) {
    let outer = frame.outer();
    let distance = rng.random_range(2.0..6.0) * outer;
    let eye_local = unit_vector(rng) * distance;
    let forward_local = -eye_local / distance;
    let (e1, e2) = forward_local.any_orthonormal_pair();
    let roll = rng.random_range(0.0..std::f64::consts::TAU);
    let right_local = e1 * roll.cos() + e2 * roll.sin();
    let up_local = right_local.cross(forward_local);
    let tan_half_fov = (outer / distance).asin().tan() * 1.15;
    for _ in 0..count {
        let u = rng.random_range(-1.0..=1.0) * tan_half_fov;
        let v = rng.random_range(-1.0..=1.0) * tan_half_fov;
        let d = forward_local + right_local * u + up_local * v;
        batch.rays.push(frame.ray(eye_local, d));
    }
    let to_world = |v: DVec3| frame.torus.to_local_rotation_f64().transpose() * v;
    batch.camera = Some(CameraView {
        eye: to_world(eye_local) + frame.torus.center().as_dvec3(),
        forward: to_world(forward_local),
        right: to_world(right_local),
        up: to_world(up_local),
        tan_half_fov,
    });
}
