//! Secondary rays from a batch's hits: for each ray that hits the torus (f64 path), one
//! diffuse bounce spawned from the hit (`Torus::spawn`: the point projected onto the
//! surface, the ray marked as starting there), its direction cosine-weighted about the
//! outward normal. What a path tracer sends after its primary rays, for timing the f32
//! and f64 paths on rays that start on the surface.

use super::{Batch, unit_vector};
use glam::DVec3;
use rand::SeedableRng;
use rand_pcg::Pcg64;
use torus_cull::{Ray, intersect};

/// The suffix of a case's name for its bounces (`camera` → `camera_bounce`).
pub const BOUNCE_SUFFIX: &str = "_bounce";

/// `batch` with its rays replaced by one cosine-weighted bounce per hit (fewer rays
/// when some miss), deterministic in the batch's stream seed.
#[must_use]
pub fn bounces(batch: &Batch) -> Batch {
    let mut rng = Pcg64::seed_from_u64(batch.stream_seed ^ 0xB0B0_CE5E_C0DA_0026);
    let torus = &batch.torus;
    let rays = batch
        .rays
        .iter()
        .filter_map(|ray| {
            let hit = intersect(torus, ray)?;
            let normal = hit.normal.as_dvec3();
            // Cosine-weighted: the unit normal plus a uniform unit vector (never the
            // opposite of the normal but with probability 0).
            let dir: DVec3 = normal + unit_vector(&mut rng);
            if dir.length_squared() < 1e-12 {
                return None;
            }
            torus.spawn(ray, hit.t, dir.as_vec3()).ok()
        })
        .collect::<Vec<Ray>>();
    Batch {
        rays,
        offsets: Vec::new(),
        camera: None,
        ..batch.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workload::{Case, Pose, generate};

    #[test]
    fn bounces_start_on_the_surface_and_leave_it() {
        let batch = generate(Case::Camera, 4.0, 2000, 7, Pose::Random).unwrap();
        let hits = batch
            .rays
            .iter()
            .filter(|r| intersect(&batch.torus, *r).is_some())
            .count();
        let out = bounces(&batch);
        assert!(out.rays.len() > hits * 9 / 10 && out.rays.len() <= hits);
        assert!(out.rays.iter().all(|r| r.starts_on_surface()));
        // Never a hit on the origin: every re-hit is well away from it.
        for r in &out.rays {
            if let Some(h) = intersect(&batch.torus, r) {
                assert!(h.t * r.dir().length() > 1e-4, "{r:?} {h:?}");
            }
        }
        assert_eq!(bounces(&batch).rays, out.rays, "deterministic");
    }
}
