//! The certified f32 path against the oracle: 0 definite hits missed, 0 misses given a t,
//! every accepted t within 2e-4·(R + r) + 4 ulp(t) of the first root, on the workload
//! generators and the adversarial families at ν from 1.01 to 1000.

// Every check here runs against the harness's oracle.

use rand::SeedableRng;
use torus_cull::Named;
use torus_cull::{F32Verdict, Ray, Torus, intersect_f32_certified};
use torus_cull_lab::oracle::{OracleClass, Query, reference_roots};
use torus_cull_lab::workload::adversarial::{LineFamily, family_rays};
use torus_cull_lab::workload::{Case, Pose, generate};

#[derive(Default, Debug)]
struct Tally {
    rays: usize,
    hits: usize,
    missed: usize,
    spurious: usize,
    far: usize,
    escalated: usize,
    worst: f64,
}

impl Tally {
    /// Prints the tally of `what` with its escalation rate, and adds it to `bad` where a
    /// hit was missed or invented or a t fell outside the tolerance.
    fn report(&self, what: &str, bad: &mut Vec<String>) {
        let escalated = 100.0 * self.escalated as f64 / self.rays as f64;
        eprintln!("{what}: {self:?} esc {escalated:.3} %");
        if self.missed + self.spurious + self.far > 0 {
            bad.push(format!("{what}: {self:?}"));
        }
    }
}

fn check(tally: &mut Tally, torus: &Torus, ray: &Ray) {
    let query = Query::ray(torus, ray);
    let label = query.classify();
    tally.rays += 1;
    let verdict = intersect_f32_certified(torus, ray);
    let outer = f64::from(torus.major_radius() + torus.minor_radius());
    match (label.class, verdict) {
        (_, F32Verdict::Escalate) => tally.escalated += 1,
        (OracleClass::Hit, F32Verdict::Miss) => tally.missed += 1,
        (OracleClass::Miss, F32Verdict::Hit { .. }) => tally.spurious += 1,
        (OracleClass::Hit, F32Verdict::Hit { t, .. }) => {
            tally.hits += 1;
            let first = reference_roots(&query)[0];
            let err = (f64::from(t) - first).abs() * f64::from(ray.dir().length());
            let allowed = 2e-4 * outer
                + 4.0
                    * f64::from(t.abs().max(f32::MIN_POSITIVE))
                    * f64::from(f32::EPSILON)
                    * f64::from(ray.dir().length());
            tally.worst = tally.worst.max(err / outer);
            if err > allowed {
                tally.far += 1;
            }
        }
        _ => {}
    }
}

const NUS: [f64; 6] = [1.01, 1.2, 2.0, 4.0, 32.0, 1000.0];

#[test]
fn generators_and_families_never_miss() {
    let mut bad = Vec::new();
    for nu in NUS {
        for &case in Case::ALL {
            if nu < case.min_nu() {
                continue;
            }
            let batch = generate(case, nu, 4000, 7, Pose::Random).unwrap();
            let mut tally = Tally::default();
            for ray in &batch.rays {
                check(&mut tally, &batch.torus, ray);
            }
            tally.report(&format!("{:>10} nu {nu:>7}", case.name()), &mut bad);
        }
        for family in [
            LineFamily::HoleEdge,
            LineFamily::Tangent,
            LineFamily::TangentLimit,
        ] {
            let mut rng = rand_pcg::Pcg64::seed_from_u64(11);
            let (torus, rays) = family_rays(family, nu, 4000, &mut rng);
            let mut tally = Tally::default();
            for ray in &rays {
                check(&mut tally, &torus, ray);
            }
            tally.report(&format!("{family:>10?} nu {nu:>7}"), &mut bad);
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
}

fn unit(rng: &mut rand_pcg::Pcg64) -> glam::DVec3 {
    // |v| > 0.1: the lab's rejection-sampled direction.
    torus_cull_lab::random::ball_direction(rng, 0.01)
}

/// Scales from 1e-3 to 1e3, origins from 1.5 to 250·(R + r), at random poses; and
/// secondary rays: from a point on the surface (rounded to f32), leaving it uniformly over
/// the hemisphere (shadow rays) or cosine-weighted (diffuse bounces), t_min = 1e-4·(R + r).
#[test]
fn scales_far_origins_and_secondary_rays_never_miss() {
    use glam::{DVec3, Vec3};
    use rand::RngExt;
    let mut bad = Vec::new();
    let mut rng = rand_pcg::Pcg64::seed_from_u64(19);
    for major in [1e-3f32, 1.0, 1e3] {
        for nu in [1.05f32, 4.0, 32.0, 1000.0] {
            let minor = major / nu;
            let center = Vec3::new(0.3, -0.2, 0.1) * major;
            let axis = unit(&mut rng).as_vec3();
            let torus = Torus::new(center, axis, major, minor).unwrap();
            let (outer, c) = (f64::from(major + minor), center.as_dvec3());
            let to_world = torus.to_local_rotation_f64().transpose();
            let (mut far, mut secondary, mut bounce) =
                (Tally::default(), Tally::default(), Tally::default());
            for _ in 0..3000 {
                // Far: aim at a random point of the bounding sphere from k·(R + r) away.
                let k = 1.5 * (250.0f64 / 1.5).powf(rng.random_range(0.0..1.0));
                let target = c + unit(&mut rng) * outer * rng.random_range(0.0..1.0);
                let o = target + unit(&mut rng) * k * outer;
                if let Ok(ray) = Ray::new(o.as_vec3(), (target - o).as_vec3()) {
                    check(&mut far, &torus, &ray);
                }
                // Secondary: a surface point, a direction in the outer hemisphere.
                let (phi, theta) = (
                    rng.random_range(0.0..std::f64::consts::TAU),
                    rng.random_range(0.0..std::f64::consts::TAU),
                );
                let (big, small) = (f64::from(major), f64::from(minor));
                let normal_local = DVec3::new(
                    theta.cos() * phi.cos(),
                    theta.sin(),
                    theta.cos() * phi.sin(),
                );
                let point_local =
                    DVec3::new(big * phi.cos(), 0.0, big * phi.sin()) + normal_local * small;
                let mut dir = unit(&mut rng);
                if dir.dot(normal_local) < 0.0 {
                    dir = -dir;
                }
                // A diffuse bounce: cosine-weighted about the normal (normal + unit vector).
                let bounce_dir = (normal_local + unit(&mut rng)).normalize_or(normal_local);
                let o = to_world * point_local + c;
                let epsilon = 1e-4 * (major + minor);
                for (tally, dir) in [(&mut secondary, dir), (&mut bounce, bounce_dir)] {
                    let d = to_world * dir;
                    if let Ok(ray) =
                        Ray::with_range(o.as_vec3(), d.as_vec3(), epsilon, f32::INFINITY)
                    {
                        check(tally, &torus, &ray);
                    }
                }
            }
            for (name, tally) in [
                ("far", &far),
                ("secondary", &secondary),
                ("bounce", &bounce),
            ] {
                tally.report(&format!("{name:>10} R {major:e} nu {nu:>7}"), &mut bad);
            }
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
}

/// The f32 wavefront gives the scalar f32 path's answers, bit for bit, at every dispatch
/// level (one source: `decide` at width 1 is the scalar path), and its escalations.
#[test]
fn wavefront_f32_is_the_scalar_f32_path() {
    use torus_cull::batch::{BatchCull, Dispatch, Isa, Wavefront};
    use torus_cull::intersect_f32;
    let mut wavefront = Wavefront::new();
    let mut hits = Vec::new();
    for nu in [1.2, 4.0, 32.0, 1000.0] {
        for case in [Case::Grazing, Case::Uniform, Case::Camera, Case::Hole] {
            if nu < case.min_nu() {
                continue;
            }
            let batch = generate(case, nu, 3001, 3, Pose::Random).unwrap();
            let scalar: Vec<_> = batch
                .rays
                .iter()
                .map(|r| intersect_f32(&batch.torus, r))
                .collect();
            let escalated = scalar.iter().filter(|a| a.escalated).count();
            for dispatch in Isa::available()
                .into_iter()
                .map(|isa| Dispatch::forced(isa).unwrap())
            {
                for cull in [
                    BatchCull::NoCull,
                    BatchCull::Cychosz,
                    BatchCull::Discriminant,
                ] {
                    let stats = wavefront.intersect_f32(
                        &dispatch,
                        cull,
                        &batch.torus,
                        &batch.rays,
                        &mut hits,
                    );
                    for (i, (lane, one)) in hits.iter().zip(&scalar).enumerate() {
                        assert_eq!(
                            lane.is_some(),
                            one.hit.is_some(),
                            "{} nu {nu} {dispatch:?} {cull}: ray {i}",
                            case.name()
                        );
                        if let (Some(a), Some(b), false) = (lane, one.hit, one.escalated) {
                            assert_eq!(a.t.to_bits(), b.t.to_bits(), "ray {i}");
                        }
                    }
                    if cull == BatchCull::NoCull {
                        assert_eq!(
                            stats.escalated,
                            escalated,
                            "{} nu {nu} {dispatch:?}",
                            case.name()
                        );
                    }
                }
            }
        }
    }
}
