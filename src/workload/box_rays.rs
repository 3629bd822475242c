//! Uniform rays at a shape in its own frame (centre 0, axis +y), for the shapes beyond the
//! ring torus (the family's members, pipe bends) whose timing has no workload case of its
//! own: origins uniform on the sphere of radius `4·(R + max(a, b))` about the centre, each
//! aimed at a uniform point of the box `[−(R + a), R + a] × [−b, b] × [−(R + a), R + a]`
//! (a: the tube's radial extent, b: its axial one). Seeded Pcg64: the same inputs give
//! the same rays.

use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::Ray;

/// `count` rays at the box of R = `major`, radial extent `radial`, axial extent `axial`.
pub fn box_rays(major: f64, radial: f64, axial: f64, count: usize, seed: u64) -> Vec<Ray> {
    let mut rng = Pcg64::seed_from_u64(seed);
    let reach = 4.0 * (major + radial.max(axial));
    (0..count)
        .map(|_| {
            loop {
                let y: f64 = rng.random_range(-1.0..1.0);
                let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                let s = (1.0 - y * y).sqrt();
                let o = DVec3::new(s * phi.cos(), y, s * phi.sin()) * reach;
                let aim = DVec3::new(
                    rng.random_range(-1.0..1.0) * (major + radial),
                    rng.random_range(-1.0..1.0) * axial,
                    rng.random_range(-1.0..1.0) * (major + radial),
                );
                if let Ok(ray) = Ray::new(o.as_vec3(), (aim - o).as_vec3()) {
                    break ray;
                }
            }
        })
        .collect()
}
