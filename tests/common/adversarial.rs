//! The adversarial ray sets the GPU tests share: lines along the hole's edge and tangent
//! to the special circles, and the families whose rays the f32 kernel escalates.

use super::{family, pairs, pushed_back};
use glam::DVec3;
use rand::SeedableRng;
use rand_pcg::Pcg64;
use torus_cull::{Ray, Torus};
use torus_cull_lab::workload::Case;
use torus_cull_lab::workload::adversarial::{
    SpecialCircle, hole_edge_line, random_pose_torus, tangent_line,
};

/// Rays on their torus.
pub type RaySet = (Torus, Vec<Ray>);

/// |t − t_ref| / max(|t_ref|, (R + r)/|d|) allowed between a device-finished hit (its t
/// rounded to f32, as the CPU's f64 path rounds it) and the oracle's first root, or the
/// CPU's f64 answer: tests/oracle/intersect_vs_oracle.rs's bound for the CPU's f64 path.
pub const DEVICE_T_TOLERANCE_REL: f64 = 1.2e-7;

/// The major radii every adversarial torus is drawn at: tiny, unit and large.
pub const MAJOR_RADII: [f32; 3] = [1e-3, 1.0, 1e3];

/// A torus-frame line (point, unit direction, f64) as a world ray starting 3·(R + r)
/// back along it.
pub fn world_ray(torus: &Torus, point: DVec3, dir: DVec3) -> Option<Ray> {
    let back = 3.0 * f64::from(torus.outer_radius());
    let m = torus.to_local_rotation_f64().transpose();
    let origin = torus.center().as_dvec3() + m * (point - dir * back);
    Ray::new(origin.as_vec3(), (m * dir).as_vec3()).ok()
}

/// Lines that decide a cull's or a solver's hardest cases, on random-pose tori.
pub struct EdgeSets {
    /// Per torus: lines hugging the hole's edge.
    pub hole_edge: Vec<RaySet>,
    /// Per special circle ([`SpecialCircle::ALL`]), per torus: lines tangent to it at
    /// ±10⁻⁶·r (alternately inside and outside).
    pub tangent: Vec<Vec<RaySet>>,
}

/// [`EdgeSets`] on one random-pose torus per ν of `nus` and major radius of
/// [`MAJOR_RADII`], drawn from `rng` in that order: `hole_edge` lines through the hole's
/// edge, then `tangent` lines per special circle.
pub fn edge_sets(rng: &mut Pcg64, nus: &[f64], hole_edge: usize, tangent: usize) -> EdgeSets {
    let mut sets = EdgeSets {
        hole_edge: Vec::new(),
        tangent: SpecialCircle::ALL.iter().map(|_| Vec::new()).collect(),
    };
    for &nu in nus {
        for major in MAJOR_RADII {
            let torus = random_pose_torus(rng, major, major / nu as f32);
            let (big, small) = (
                f64::from(torus.major_radius()),
                f64::from(torus.minor_radius()),
            );
            let rays: Vec<Ray> = (0..hole_edge)
                .filter_map(|_| {
                    let (p, d) = hole_edge_line(rng, big, small);
                    world_ray(&torus, p, d)
                })
                .collect();
            sets.hole_edge.push((torus, rays));
            for (circle, slot) in SpecialCircle::ALL.into_iter().zip(&mut sets.tangent) {
                let rays: Vec<Ray> = (0..tangent)
                    .filter_map(|i| {
                        let delta = if i % 2 == 0 { 1e-6 } else { -1e-6 };
                        let (p, d) = tangent_line(rng, big, small, circle, delta);
                        world_ray(&torus, p, d)
                    })
                    .collect();
                slot.push((torus, rays));
            }
        }
    }
    sets
}

/// ν from a torus whose hole nearly closes (1.01) to a thin ring (1000): the range of
/// the GPU tests' generated families.
pub const WIDE_NUS: [f64; 6] = [1.01, 1.5, 3.0, 10.0, 100.0, 1000.0];

/// The families whose rays the f32 kernel escalates, by name: the hole at ν = 1.01,
/// grazing rays at every ν of [`WIDE_NUS`], near and 10⁵·(R + r) away, lines hugging
/// the hole's edge, the f32-check families of secondary rays from hit points (100 each),
/// and lines tangent to the special circles at ±10⁻⁶·r. `size` scales the first four:
/// 1 gives 4000 hole, 1000 grazing, 300 hole-edge and 200 tangent rays (per torus for the
/// last two); 2 halves them.
pub fn escalating_families(size: usize) -> Vec<(String, Vec<RaySet>)> {
    let n = |full: usize| full / size.max(1);
    let batches = |case: Case, nu: f64, count: usize, seed: u64, back: f32| {
        family(case, nu, count, seed)
            .iter()
            .map(|batch| {
                let torus = batch.torus;
                let rays = pairs(std::slice::from_ref(batch))
                    .map(|(_, ray)| {
                        if back == 0.0 {
                            *ray
                        } else {
                            pushed_back(ray, back * torus.outer_radius())
                        }
                    })
                    .collect();
                (torus, rays)
            })
            .collect::<Vec<_>>()
    };
    let mut families: Vec<(String, Vec<RaySet>)> = vec![(
        "hole ν=1.01".into(),
        batches(Case::Hole, 1.01, n(4000), 0xF1, 0.0),
    )];
    for nu in WIDE_NUS {
        families.push((
            format!("grazing ν={nu}"),
            batches(Case::Grazing, nu, n(1000), 0xF2 ^ nu.to_bits(), 0.0),
        ));
    }
    families.push((
        "grazing ν=1.01 back 1e5·(R+r)".into(),
        batches(Case::Grazing, 1.01, n(1000), 0xF3, 1e5),
    ));
    let mut rng = Pcg64::seed_from_u64(0x0F1_5E64);
    let edges = edge_sets(&mut rng, &[1.01, 2.0, 100.0], n(300), n(200));
    families.push(("hole_edge_line".into(), edges.hole_edge));
    for family in super::spawned_families() {
        let mut sets: Vec<RaySet> = Vec::new();
        for (torus, ray) in family.generate(100, 0xF1_5E64).unwrap() {
            match sets.last_mut() {
                Some((last, rays)) if *last == torus => rays.push(ray),
                _ => sets.push((torus, vec![ray])),
            }
        }
        families.push((family.name, sets));
    }
    for (circle, sets) in SpecialCircle::ALL.into_iter().zip(edges.tangent) {
        families.push((format!("tangent ±1e-6 r {}", circle.name()), sets));
    }
    families
}
