//! Every GPU cull against the oracle and the CPU's cull of the same name, on families
//! scaled and posed.

use super::*;

/// One family's rays on their tori, with the oracle's line label and each ray's line in
/// the torus frame (what the CPU's culls take), computed once for every cull.
struct CullFamily {
    name: String,
    /// Per torus: the torus, its rays, their line labels.
    sets: Vec<(Torus, Vec<Ray>, Vec<OracleClass>)>,
}

impl CullFamily {
    fn new(name: String) -> CullFamily {
        CullFamily {
            name,
            sets: Vec::new(),
        }
    }

    fn push(&mut self, torus: Torus, rays: Vec<Ray>) {
        let labels = rays
            .iter()
            .map(|ray| Query::line(&torus, ray).classify().class)
            .collect();
        self.sets.push((torus, rays, labels));
    }
}

/// The same world scaled by `k` about the origin: the torus's centre and radii, the
/// rays' origins (directions as they were).
fn scaled(torus: &Torus, rays: &[Ray], k: f32) -> (Torus, Vec<Ray>) {
    let scaled = Torus::new(
        torus.center() * k,
        torus.axis(),
        torus.major_radius() * k,
        torus.minor_radius() * k,
    )
    .unwrap();
    let rays = rays
        .iter()
        .map(|r| Ray::new(r.origin() * k, r.dir()).unwrap())
        .collect();
    (scaled, rays)
}

/// The GPU's cull (`cull_keeps`) and the CPU's on one family.
#[derive(Default)]
struct CullTally {
    rays: usize,
    hits: usize,
    gpu_rejected: usize,
    cpu_rejected: usize,
    gpu_only: usize,
    cpu_only: usize,
    false_rejects: Vec<String>,
}

impl CullTally {
    fn run(gpu: &GpuIntersector, cull: GpuCull, family: &CullFamily) -> CullTally {
        let mut t = CullTally::default();
        let kind = cull.kind();
        for (torus, rays, labels) in &family.sets {
            let keeps = gpu.cull_keeps(torus, cull, rays).expect("dispatch");
            assert_eq!(keeps.len(), rays.len());
            for ((ray, &class), gpu_keep) in rays.iter().zip(labels).zip(keeps) {
                let line = torus.line_to_local(ray);
                let cpu_keep = kind.keeps(torus.bounds(), line.origin, line.dir);
                t.rays += 1;
                t.gpu_rejected += usize::from(!gpu_keep);
                t.cpu_rejected += usize::from(!cpu_keep);
                t.gpu_only += usize::from(!gpu_keep && cpu_keep);
                t.cpu_only += usize::from(gpu_keep && !cpu_keep);
                if class == OracleClass::Hit {
                    t.hits += 1;
                    if !gpu_keep && t.false_rejects.len() < 10 {
                        t.false_rejects
                            .push(format!("{cull}: rejected a hit: {ray:?} on {torus:?}"));
                    }
                }
            }
        }
        t
    }

    fn rate(&self, n: usize) -> f64 {
        100.0 * n as f64 / self.rays.max(1) as f64
    }
}

/// Every cull in the kernel against the oracle and the CPU's cull, on the adversarial
/// families (the five generators at ν from 1.01 to 1000 and R from 10⁻³ to 10³, the same
/// seen from 10³·(R + r) away, lines hugging the hole's edge, lines tangent to the four
/// special circles at ±10⁻⁶·r): no line the oracle says hits is rejected, and the
/// rejection rate is the CPU's within 0.5 % of the family's rays.
///
/// Why 0.5 %: the GPU's margin is the CPU's η = 2⁻¹²·(R + r) plus the kernel's line
/// error (at most 2.1·10⁻⁵·R more, `gpu::bounds`), and `thick_cylinder`, `quadric` and
/// `discriminant` reject only what their error bounds prove. So the two differ only on
/// lines within about 10⁻⁴·(R + r) of the padded torus's surface (and on the lines where
/// the CPU's own f32 rounding decides), a thin shell that the grazing and tangent
/// families aim at. The printed table gives the measured rates.
#[test]
fn every_cull_against_the_oracle_and_the_cpu() {
    let Some(gpu) = gpu() else { return };
    let mut families = Vec::new();
    for &case in Case::ALL {
        for back in [0.0f32, 1e3] {
            let mut set = CullFamily::new(format!("{case} back {back:e}"));
            for nu in WIDE_NUS {
                if nu < case.min_nu() {
                    continue;
                }
                for (i, k) in [1e-3f32, 1.0, 1e3].into_iter().enumerate() {
                    let seed = 0xC011 ^ nu.to_bits() ^ (i as u64) << 8;
                    for batch in &family(case, nu, 250, seed) {
                        let rays: Vec<Ray> = batch
                            .rays
                            .iter()
                            .map(|ray| {
                                if back == 0.0 {
                                    *ray
                                } else {
                                    pushed_back(ray, back * batch.torus.outer_radius())
                                }
                            })
                            .collect();
                        let (torus, rays) = scaled(&batch.torus, &rays, k);
                        set.push(torus, rays);
                    }
                }
            }
            families.push(set);
        }
    }
    let mut rng = Pcg64::seed_from_u64(0x0C01_1ADD);
    let edges = edge_sets(&mut rng, &[1.01, 1.1, 2.0, 8.0, 100.0, 1000.0], 300, 150);
    let mut hole = CullFamily::new("hole_edge_line".into());
    for (torus, rays) in edges.hole_edge {
        hole.push(torus, rays);
    }
    let mut tangent: Vec<CullFamily> = SpecialCircle::ALL
        .iter()
        .map(|c| CullFamily::new(format!("tangent ±1e-6 r {}", c.name())))
        .collect();
    for (family, per_torus) in tangent.iter_mut().zip(edges.tangent) {
        for (torus, rays) in per_torus {
            family.push(torus, rays);
        }
    }
    families.push(hole);
    families.extend(tangent);

    println!(
        "{:<34} {:<15} {:>7} {:>6} {:>9} {:>9} {:>8} {:>8}",
        "family", "cull", "rays", "hits", "GPU rej%", "CPU rej%", "GPU-only", "CPU-only"
    );
    let mut failures = Vec::new();
    for cull in GpuCull::ALL {
        for family in &families {
            let t = CullTally::run(gpu, cull, family);
            println!(
                "{:<34} {:<15} {:>7} {:>6} {:>9.2} {:>9.2} {:>8} {:>8}",
                family.name,
                cull.name(),
                t.rays,
                t.hits,
                t.rate(t.gpu_rejected),
                t.rate(t.cpu_rejected),
                t.gpu_only,
                t.cpu_only
            );
            failures.extend(t.false_rejects.iter().cloned());
            let gap = (t.rate(t.gpu_rejected) - t.rate(t.cpu_rejected)).abs();
            if gap > 0.5 {
                failures.push(format!(
                    "{cull} on {}: GPU rejects {:.2} %, CPU {:.2} %",
                    family.name,
                    t.rate(t.gpu_rejected),
                    t.rate(t.cpu_rejected)
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The kernel resized (`GpuIntersector::with_workgroup`, `time --workgroup`) answers every
/// ray as the default size does: each invocation is one ray, whatever the group. A size
/// outside the allowed ones is an error naming them.
#[test]
fn a_resized_workgroup_gives_the_same_answers() {
    let Some(gpu) = gpu() else { return };
    let refused = GpuIntersector::with_workgroup(48).unwrap_err().to_string();
    assert!(
        refused.contains("48") && refused.contains("256"),
        "{refused}"
    );
    // Every case at ν = 4 (1000 rays: not a multiple of any size, so the last group is
    // partial); lavapipe pays per dispatch, so one ν and two culls.
    let sets: Vec<_> = Case::ALL
        .iter()
        .flat_map(|&case| family(case, 4.0, 1000, 0x3C0))
        .collect();
    let culls = [GpuCull::NoCull, GpuCull::Discriminant];
    let want: Vec<Vec<_>> = sets
        .iter()
        .flat_map(|b| culls.map(|cull| gpu.intersect(&b.torus, cull, &b.rays).unwrap()))
        .collect();
    // The smallest and the largest size (each compile costs lavapipe seconds).
    for threads in [32, 256] {
        assert!(torus_cull::gpu::WORKGROUP_SIZES.contains(&threads));
        let resized = GpuIntersector::with_workgroup(threads).unwrap();
        assert_eq!(resized.workgroup(), threads);
        let got: Vec<Vec<_>> = sets
            .iter()
            .flat_map(|b| culls.map(|cull| resized.intersect(&b.torus, cull, &b.rays).unwrap()))
            .collect();
        assert!(got == want, "workgroup {threads} answers differently");
    }
}
