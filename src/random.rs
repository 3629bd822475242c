//! The lab's random directions, in one home: the workloads', the checks' and the oracle
//! tests' rays all draw from here.

use glam::DVec3;
use rand::{Rng, RngExt};

/// A direction uniform on the unit sphere (Archimedes: z uniform, azimuth uniform).
pub fn unit_vector(rng: &mut impl Rng) -> DVec3 {
    let z: f64 = rng.random_range(-1.0..1.0);
    let phi = rng.random_range(0.0..std::f64::consts::TAU);
    let s = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(s * phi.cos(), s * phi.sin(), z)
}

/// A direction uniform on the unit sphere by rejection: a point of the cube [-1, 1]³ kept
/// when it lies in the unit ball and |v|² > `floor` (shorter ones are redrawn: their
/// direction is mostly rounding). A check's rays depend on its `floor`: keep it.
pub fn ball_direction(rng: &mut impl Rng, floor: f64) -> DVec3 {
    let v = ball_point(rng, floor);
    v / v.length_squared().sqrt()
}

/// [`ball_direction`]'s point before it is made unit: in the unit ball, |v|² > `floor`
/// (a caller that takes any length, the same stream).
pub fn ball_point(rng: &mut impl Rng, floor: f64) -> DVec3 {
    loop {
        let v = cube_point(rng, 1.0);
        let l2 = v.length_squared();
        if l2 > floor && l2 <= 1.0 {
            return v;
        }
    }
}

/// A point uniform in the cube [-`half`, `half`]³ (x, y, z drawn in turn).
pub fn cube_point(rng: &mut impl Rng, half: f64) -> DVec3 {
    DVec3::new(
        rng.random_range(-half..half),
        rng.random_range(-half..half),
        rng.random_range(-half..half),
    )
}
