//! Batch culls against the scalar culls and the oracle, at every dispatch level this
//! CPU has (scalar, AVX2, AVX-512 here; scalar and NEON on AArch64).
//!
//! The claim is **bit-identical verdicts** (and bit-identical lines from the lane transform
//! of world rays, `Lines::fill_from_rays_batch`, against `Torus::line_to_local`): each
//! cull is one kernel, generic over the lane width, and `Cull::keeps` is that kernel at
//! width 1; the lanes evaluate the same expressions in the same order with IEEE-exact
//! operations and no fused multiply-add, and its early exits ("no lane is still
//! undecided") take no lane's answer from another, so every line's keep bit must equal
//! `Cull::keeps` on the same f32 line.
//! Equality is asserted on every line, and so is the consequence the renderer cares
//! about: no batch cull rejects a line the oracle calls a hit.
//!
//! Lines: the conservativeness families (uniform, hole, grazing, outer band, camera at
//! ν = 1.01 … 1000, random world poses, grazing copies pushed 100, 250, 10⁴ and 10⁶·(R + r)
//! back); tangents to the four special circles pushed off by ±1e-6·r, ±1e-4·r and
//! η(1 ± 1e-3) (the padded surface, where the padded culls decide) and hole-edge lines, at
//! R = 1e-3, 1, 1e3; axis-parallel and d_y = 0 lines across the case boundaries; and
//! copies of lines with the direction scaled by 1e-19 … 1e19 (the `moderate` and
//! `rescaled` paths).

// Every check here runs against the harness's oracle or CLI.

use crate::common::{NUS, family, on_two_threads, pushed_back};
use glam::{DMat3, DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::batch::{BATCHED, BatchCull, Dispatch, Isa, KeepMask, Lines, cull_batch};
use torus_cull::{CullBounds, CullKind, Named, Ray, Torus};
use torus_cull_lab::oracle::{OracleClass, classify_line};
use torus_cull_lab::workload::Case;
use torus_cull_lab::workload::adversarial::{SpecialCircle, hole_edge_line, tangent_line};

/// One torus and rays on it.
struct Set {
    torus: Torus,
    rays: Vec<Ray>,
}

#[derive(Default)]
struct Tally {
    /// Line verdicts compared (lines × culls × dispatch levels).
    verdicts: usize,
    lines: usize,
    hits: usize,
    /// Batch bit ≠ scalar verdict, per cull in `BATCHED` order.
    mismatches: [usize; BATCHED.len()],
    /// Batch rejects an oracle hit, per cull.
    false_rejects: [usize; BATCHED.len()],
    /// Lines from the lane transform that differ from `Torus::line_to_local`'s.
    transform_mismatches: usize,
    examples: Vec<String>,
}

impl Tally {
    fn check(&mut self, set: &Set, levels: &[Dispatch]) {
        self.check_against(set, levels, CullKind::keeps);
    }

    /// [`Tally::check`] with the width-1 verdict taken from `reference` (the real one is
    /// `CullKind::keeps`; a test swaps in a wrong one to show the comparison sees it).
    fn check_against(
        &mut self,
        set: &Set,
        levels: &[Dispatch],
        reference: impl Fn(CullKind, &CullBounds, Vec3, Vec3) -> bool,
    ) {
        let Set { torus, rays } = set;
        let bounds = torus.bounds();
        let lines = Lines::from_rays(torus, rays);
        let labels: Vec<OracleClass> = rays.iter().map(|r| classify_line(torus, r).class).collect();
        self.lines += rays.len();
        self.hits += labels.iter().filter(|&&c| c == OracleClass::Hit).count();
        // The lane transform gives the scalar transform's lines, bit for bit (far origins
        // take the same f64 foot-point path).
        for dispatch in levels {
            let mut batch_lines = Lines::new();
            batch_lines.fill_from_rays_batch(dispatch, torus, rays);
            assert_eq!(batch_lines.len(), lines.len());
            for (i, ray) in rays.iter().enumerate() {
                let (a, b) = (batch_lines.get(i), lines.get(i));
                let bits = |v: glam::Vec3| v.to_array().map(f32::to_bits);
                if bits(a.origin) != bits(b.origin) || bits(a.dir) != bits(b.dir) {
                    self.transform_mismatches += 1;
                    self.note(format!(
                        "transform at {}: {a:?} vs {b:?}: ray {ray:?}",
                        dispatch.isa()
                    ));
                }
            }
        }
        let mut keep = KeepMask::new();
        for (k, &cull) in BATCHED.iter().enumerate() {
            let scalar: Vec<bool> = (0..lines.len())
                .map(|i| {
                    let l = lines.get(i);
                    reference(cull.kind(), bounds, l.origin, l.dir)
                })
                .collect();
            for dispatch in levels {
                cull_batch(dispatch, cull, bounds, &lines, &mut keep);
                assert_eq!(keep.len(), rays.len());
                for (i, (&want, label)) in scalar.iter().zip(&labels).enumerate() {
                    let got = keep.get(i);
                    self.verdicts += 1;
                    if got != want {
                        self.mismatches[k] += 1;
                        self.note(format!(
                            "{cull} at {}: batch {got}, scalar {want}: torus {torus:?} ray {:?}",
                            dispatch.isa(),
                            rays[i]
                        ));
                    }
                    if !got && *label == OracleClass::Hit {
                        self.false_rejects[k] += 1;
                        self.note(format!(
                            "{cull} at {} rejects a hit: torus {torus:?} ray {:?}",
                            dispatch.isa(),
                            rays[i]
                        ));
                    }
                }
                // The bits past the last line stay clear (the padding lines are dropped).
                assert_eq!(keep.count_kept(), keep.kept().count());
                assert!(keep.kept().all(|i| i < rays.len()));
            }
        }
    }

    fn note(&mut self, text: String) {
        if self.examples.len() < 8 {
            self.examples.push(text);
        }
    }

    fn merge(&mut self, o: Tally) {
        self.verdicts += o.verdicts;
        self.lines += o.lines;
        self.hits += o.hits;
        self.transform_mismatches += o.transform_mismatches;
        for k in 0..BATCHED.len() {
            self.mismatches[k] += o.mismatches[k];
            self.false_rejects[k] += o.false_rejects[k];
        }
        for e in o.examples {
            self.note(e);
        }
    }

    fn assert_clean(&self, what: &str) {
        println!(
            "{what}: {} lines ({} oracle hits), {} verdicts compared; transform mismatches {}, \
             mismatches {:?}, rejected hits {:?} (cull order {:?})",
            self.lines,
            self.hits,
            self.verdicts,
            self.transform_mismatches,
            self.mismatches,
            self.false_rejects,
            BATCHED.map(|c| c.name())
        );
        assert!(
            self.transform_mismatches == 0
                && self.mismatches.iter().all(|&n| n == 0)
                && self.false_rejects.iter().all(|&n| n == 0),
            "{what}: mismatches {:?}, rejected hits {:?}\n{}",
            self.mismatches,
            self.false_rejects,
            self.examples.join("\n")
        );
    }
}

/// Every dispatch level this CPU has; at least the scalar fallback.
fn levels() -> Vec<Dispatch> {
    let levels = crate::dispatch_levels();
    println!(
        "dispatch levels tested: {:?}",
        levels.iter().map(|d| d.isa().name()).collect::<Vec<_>>()
    );
    levels
}

/// The shared ν sweep plus the extremes.
fn all_nus() -> Vec<f64> {
    NUS.iter().copied().chain([1.01, 1000.0]).collect()
}

/// The conservativeness families at one ν, with far-origin copies of the grazing lines.
fn workload_sets(nu: f64) -> Vec<Set> {
    let seed = 0xBA7C ^ nu.to_bits();
    let hole = if nu < 1.05 { 1_000 } else { 6_000 };
    let mut sets = Vec::new();
    for (case, count) in [
        (Case::Uniform, 8_000),
        (Case::Hole, hole),
        (Case::Grazing, 8_000),
        (Case::OuterBand, 4_000),
        (Case::Camera, 4_000),
    ] {
        for batch in family(case, nu, count, seed) {
            if case == Case::Grazing {
                for k in [100.0, 250.0, 1e4, 1e6] {
                    let far = batch.torus.outer_radius() * k;
                    sets.push(Set {
                        torus: batch.torus,
                        rays: batch.rays.iter().map(|r| pushed_back(r, far)).collect(),
                    });
                }
            }
            sets.push(Set {
                torus: batch.torus,
                rays: batch.rays,
            });
        }
    }
    sets
}

/// A torus at a random world pose and the f64 map of its frame to the world.
fn posed(big: f64, small: f64, rng: &mut Pcg64) -> (Torus, DMat3, DVec3) {
    let extent = 2.0 * (big + small);
    let mut coordinate = |w: f64| rng.random_range(-w..w);
    let center = DVec3::new(coordinate(extent), coordinate(extent), coordinate(extent));
    let axis = DVec3::new(coordinate(1.0), coordinate(1.0), coordinate(1.0));
    let torus = Torus::new(center.as_vec3(), axis.as_vec3(), big as f32, small as f32).unwrap();
    let to_world = torus.to_local_rotation_f64().transpose();
    (torus, to_world, torus.center().as_dvec3())
}

/// Tangents to the special circles and hole-edge lines at random poses, R = 1e-3, 1, 1e3.
fn adversarial_sets(nu: f64) -> Vec<Set> {
    let mut rng = Pcg64::seed_from_u64(0xBA7D ^ nu.to_bits());
    let mut sets = Vec::new();
    for scale in [1e-3, 1.0, 1e3] {
        let (torus, to_world, center) = posed(scale, scale / nu, &mut rng);
        let (big, small) = (
            f64::from(torus.major_radius()),
            f64::from(torus.minor_radius()),
        );
        let eta = f64::from(torus.bounds().minor_safe()) - small;
        let offsets = [1e-6 * small, -1e-6 * small, 1e-4 * small, -1e-4 * small]
            .into_iter()
            .chain([eta * (1.0 + 1e-3), eta * (1.0 - 1e-3)]);
        let mut rays = Vec::new();
        for offset in offsets {
            for circle in SpecialCircle::ALL {
                for _ in 0..100 {
                    let (p, d) = tangent_line(&mut rng, big, small, circle, offset / small);
                    for back in [1.0, 250.0] {
                        let o = p - d * (back * (big + small));
                        rays.push(world_ray(&to_world, center, o, d));
                    }
                }
            }
        }
        for _ in 0..800 {
            let (p, d) = hole_edge_line(&mut rng, big, small);
            rays.push(world_ray(
                &to_world,
                center,
                p - d * (3.0 * (big + small)),
                d,
            ));
        }
        sets.push(Set { torus, rays });
    }
    sets
}

fn world_ray(to_world: &DMat3, center: DVec3, o: DVec3, d: DVec3) -> Ray {
    Ray::new(
        (*to_world * o + center).as_vec3(),
        (*to_world * d).as_vec3(),
    )
    .unwrap()
}

/// Axis-parallel and d_y = 0 lines across the case boundaries a = R − r, R, R + r (the
/// canonical torus, so the lines are exactly axis-parallel or horizontal), and steep
/// lines through y = 0 at every X.
fn degenerate_set(nu: f64) -> Set {
    let torus = Torus::canonical(1.0, (1.0 / nu) as f32).unwrap();
    let (big_r, r) = (1.0f32, (1.0 / nu) as f32);
    let mut rays = Vec::new();
    for i in 0..=200 {
        let s = i as f32 / 200.0;
        let rho = (big_r + r) * 1.05 * s;
        rays.push(Ray::new(Vec3::new(rho, 3.0, 0.0), Vec3::NEG_Y).unwrap());
        rays.push(Ray::new(Vec3::new(0.0, -3.0, rho), Vec3::new(0.0, 2.5, 0.0)).unwrap());
        let y = (2.0 * s - 1.0) * r * 1.05;
        for a in [big_r - r, big_r, big_r + r] {
            rays.push(Ray::new(Vec3::new(-5.0, y, a), Vec3::X).unwrap());
            rays.push(Ray::new(Vec3::new(a, y, 5.0), Vec3::NEG_Z).unwrap());
            let x = (2.0 * s - 1.0) * (big_r + r);
            rays.push(
                Ray::new(Vec3::new(x - 0.1, -3.0, a), Vec3::new(0.1 / 3.0, 1.0, 0.0)).unwrap(),
            );
        }
    }
    Set { torus, rays }
}

/// The same lines with the direction scaled from 1e-19 to 1e19: the culls' `moderate`
/// and `rescaled` paths (exact powers of two) must agree lane for lane too.
fn scaled_copies(set: &Set) -> Vec<Set> {
    [1e-19f32, 1e-10, 1e10, 1e19]
        .into_iter()
        .map(|k| Set {
            torus: set.torus,
            rays: set
                .rays
                .iter()
                .take(2_000)
                .filter_map(|r| Ray::new(r.origin(), r.dir() * k).ok())
                .collect(),
        })
        .collect()
}

fn tally_for(nu: f64, levels: &[Dispatch]) -> Tally {
    let mut t = Tally::default();
    let mut sets = workload_sets(nu);
    sets.extend(adversarial_sets(nu));
    sets.push(degenerate_set(nu));
    let copies: Vec<Set> = sets.iter().take(3).flat_map(scaled_copies).collect();
    sets.extend(copies);
    for set in &sets {
        t.check(set, levels);
    }
    t
}

#[test]
fn batch_verdicts_equal_scalar_verdicts_at_every_dispatch_level() {
    let levels = levels();
    assert!(levels.iter().any(|d| d.isa() == Isa::Scalar));
    let nus = all_nus();
    let tallies = on_two_threads(&nus, |&nu| (nu, tally_for(nu, &levels)));
    let mut total = Tally::default();
    for (nu, t) in tallies {
        assert!(t.hits > 5_000, "nu={nu}: only {} hits", t.hits);
        t.assert_clean(&format!("nu={nu}"));
        total.merge(t);
    }
    total.assert_clean("all");
}

/// Lengths that are not a multiple of the block, and zero lines.
#[test]
fn any_length_and_the_padding_never_shows() {
    let torus = Torus::canonical(1.0, 0.25).unwrap();
    let bounds = torus.bounds();
    let batch = torus_cull_lab::workload::generate(
        Case::Uniform,
        4.0,
        300,
        7,
        torus_cull_lab::workload::Pose::Canonical,
    )
    .unwrap();
    for dispatch in crate::dispatch_levels() {
        for n in [0, 1, 15, 16, 17, 63, 64, 65, 127, 300] {
            let lines = Lines::from_rays(&torus, &batch.rays[..n]);
            let mut keep = KeepMask::new();
            cull_batch(&dispatch, BatchCull::NoCull, bounds, &lines, &mut keep);
            assert_eq!(keep.count_kept(), n, "{} n={n}", dispatch.isa());
            cull_batch(&dispatch, BatchCull::Skala, bounds, &lines, &mut keep);
            let want: Vec<bool> = batch.rays[..n]
                .iter()
                .map(|r| {
                    let l = torus.line_to_local(r);
                    CullKind::Skala.keeps(bounds, l.origin, l.dir)
                })
                .collect();
            assert_eq!(keep.to_vec(), want, "{} n={n}", dispatch.isa());
        }
    }
    // A cull without a batch form has no `BatchCull`: asked for by name, a clear error,
    // not a silent fallback.
    assert_eq!(CullKind::DiscriminantF64.batched(), None);
    let err = BatchCull::parse("discriminant_f64")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("discriminant_f64") && err.contains("skala"),
        "{err}"
    );
}

/// The test can fail: [`Tally::check`]'s comparison, fed a wrong width-1 verdict (skala's
/// replaced by cychosz's, which keeps every hole line skala rejects), counts the
/// disagreements on skala alone, at every level, and reports them.
#[test]
fn the_comparison_sees_a_wrong_verdict() {
    let levels = levels();
    let torus = Torus::canonical(1.0, 0.25).unwrap();
    let rays: Vec<Ray> = (0..64)
        .map(|i| {
            // Straight down the hole (skala rejects, cychosz keeps), then through the tube.
            let x = if i % 2 == 0 {
                0.1 + 0.005 * i as f32
            } else {
                1.0
            };
            Ray::new(Vec3::new(x, 5.0, 0.0), Vec3::NEG_Y).unwrap()
        })
        .collect();
    let set = Set { torus, rays };
    let mut honest = Tally::default();
    honest.check(&set, &levels);
    assert_eq!(
        honest.mismatches,
        [0; BATCHED.len()],
        "{:?}",
        honest.examples
    );
    let mut fooled = Tally::default();
    fooled.check_against(&set, &levels, |cull, b, o, d| {
        let cull = if cull == CullKind::Skala {
            CullKind::Cychosz
        } else {
            cull
        };
        cull.keeps(b, o, d)
    });
    let skala = BATCHED.iter().position(|&c| c == BatchCull::Skala).unwrap();
    for (k, &count) in fooled.mismatches.iter().enumerate() {
        let want = if k == skala { 32 * levels.len() } else { 0 };
        assert_eq!(count, want, "{}: {:?}", BATCHED[k], fooled.examples);
    }
    assert!(fooled.examples.iter().any(|e| e.starts_with("skala at")));
}
