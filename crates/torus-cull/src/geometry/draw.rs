//! Test draws: random points in a box, for the unit tests of the modules above (`bend`,
//! `family`, `intersect`, `batch`), which each drew them with the same three lines.

use glam::{DVec3, Vec3};
use rand::RngExt;

/// A point drawn uniformly from the box [−half, half]: x, then y, then z, each one
/// `random_range(−h..h)`.
pub(crate) fn dvec3_in<R: RngExt + ?Sized>(rng: &mut R, half: DVec3) -> DVec3 {
    DVec3::new(
        rng.random_range(-half.x..half.x),
        rng.random_range(-half.y..half.y),
        rng.random_range(-half.z..half.z),
    )
}

/// [`dvec3_in`] in f32.
pub(crate) fn vec3_in<R: RngExt + ?Sized>(rng: &mut R, half: Vec3) -> Vec3 {
    Vec3::new(
        rng.random_range(-half.x..half.x),
        rng.random_range(-half.y..half.y),
        rng.random_range(-half.z..half.z),
    )
}
