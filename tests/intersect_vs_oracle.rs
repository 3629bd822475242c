//! The timed exact intersection agrees with the oracle, and the oracle's two methods agree.

mod common;

use common::{NUS, family, pairs, pushed_back};
use torus_cull::intersect;
use torus_cull::oracle::{OracleClass, classify, margin_by_sampling, reference_roots};
use torus_cull::workload::Case;

/// |t − t_ref| / max(|t_ref|, (R + r)/|d|) allowed between `intersect` (its t is f32) and
/// the oracle's reference root: relative to the hit distance, or to the torus size for
/// hits close to the origin. Rounding t to f32 alone costs up to 2⁻²⁴ ≈ 6e-8; the f64
/// solve must add almost nothing to that.
const T_TOLERANCE_REL: f64 = 1.2e-7;

#[test]
fn intersect_finds_a_hit_exactly_when_the_oracle_says_hit() {
    let (mut checked, mut hits, mut worst) = (0usize, 0usize, 0f64);
    let mut failures = Vec::new();
    for nu in NUS {
        let mut batches = Vec::new();
        for case in Case::ALL {
            batches.extend(family(case, nu, 4_000, 0x1A7E ^ nu.to_bits()));
        }
        for (torus, ray) in pairs(&batches) {
            for ray in [*ray, pushed_back(ray, 100.0 * torus.outer_radius())] {
                let label = classify(torus, &ray);
                if label.class == OracleClass::Ambiguous {
                    continue;
                }
                checked += 1;
                let found = intersect(torus, &ray);
                if found.is_some() != (label.class == OracleClass::Hit) {
                    failures.push(format!(
                        "nu={nu}: intersect {found:?} but oracle {label:?} for {ray:?} on {torus:?}"
                    ));
                    continue;
                }
                let Some(hit) = found else { continue };
                hits += 1;
                let roots = reference_roots(
                    torus.center().as_dvec3(),
                    torus.axis().as_dvec3(),
                    torus.major_radius() as f64,
                    torus.minor_radius() as f64,
                    ray.origin().as_dvec3(),
                    ray.dir().as_dvec3(),
                    ray.t_min() as f64,
                    ray.t_max() as f64,
                );
                let size = torus.outer_radius() as f64 / ray.dir().as_dvec3().length();
                let err = (hit.t as f64 - roots[0]).abs() / roots[0].abs().max(size);
                worst = worst.max(err);
                if err > T_TOLERANCE_REL {
                    failures.push(format!(
                        "nu={nu}: t {} vs reference {} ({err:e})",
                        hit.t, roots[0]
                    ));
                }
            }
        }
    }
    println!("{checked} rays checked, {hits} hits, worst relative t error {worst:e}");
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures[..failures.len().min(10)].join("\n")
    );
    assert!(hits > 50_000);
}

#[test]
fn oracle_methods_agree_outside_the_band() {
    let mut checked = 0;
    for nu in NUS {
        let mut batches = Vec::new();
        for case in [Case::Uniform, Case::Hole, Case::Grazing, Case::OuterBand] {
            batches.extend(family(case, nu, 300, 0x0AC1 ^ nu.to_bits()));
        }
        for (torus, ray) in pairs(&batches) {
            let label = classify(torus, ray);
            let sampled = margin_by_sampling(
                torus.center().as_dvec3(),
                torus.axis().as_dvec3(),
                torus.major_radius() as f64,
                torus.minor_radius() as f64,
                ray.origin().as_dvec3(),
                ray.dir().as_dvec3(),
                ray.t_min() as f64,
                ray.t_max() as f64,
            );
            let band = torus_cull::oracle::AMBIGUITY_REL * torus.outer_radius() as f64;
            if label.margin.abs() > band {
                assert_eq!(
                    label.margin < 0.0,
                    sampled < 0.0,
                    "nu={nu}: classes differ, margin {:e} vs sampled {sampled:e}",
                    label.margin
                );
            }
            // Sampling can only overestimate a minimum, and not by much.
            assert!(sampled >= label.margin - 1e-12 * torus.outer_radius() as f64);
            assert!(
                sampled - label.margin <= band,
                "{sampled:e} vs {:e}",
                label.margin
            );
            checked += 1;
        }
    }
    assert!(checked >= 8_000);
}
