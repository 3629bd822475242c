//! The wavefront (batch cull → compaction → batch solve → hits) against the scalar path
//! `intersect_culled`, ray by ray, for every batched cull at every dispatch level, and
//! against the oracle: a ray the oracle calls a hit always comes back with a hit.
//!
//! Rays: every workload case (uniform, hole, grazing at ±1e-2 … ±1e-6·r, outer band,
//! camera) at ν = 1.01 … 1000 and random world poses, plus the grazing rays pushed
//! 250·(R + r) back.

// Every check here runs against the harness's oracle or CLI.

use crate::common::{family, on_two_threads, pushed_back};
use torus_cull::batch::{BATCHED, BatchCull, Dispatch, Wavefront};
use torus_cull::{CullKind, CullVisitor, Hit, Named, Ray, Torus, intersect_culled};
use torus_cull_lab::oracle::{OracleClass, classify};
use torus_cull_lab::workload::Case;

/// The scalar path for one cull, ray by ray.
struct Scalar<'a>(&'a Torus, &'a [Ray]);

impl CullVisitor for Scalar<'_> {
    type Output = Vec<Option<Hit>>;
    fn visit<C: torus_cull::Cull>(self, cull: C) -> Vec<Option<Hit>> {
        self.1
            .iter()
            .map(|r| intersect_culled(&cull, self.0, r))
            .collect()
    }
}

#[derive(Default, Debug)]
struct Tally {
    rays: usize,
    oracle_hits: usize,
    compared: usize,
    hits: usize,
    /// Hit in one path, none in the other.
    presence_mismatch: usize,
    /// Both hit, but t or the normal differ beyond rounding.
    value_mismatch: usize,
    /// The oracle says hit, the wavefront says none.
    missed_hits: usize,
    examples: Vec<String>,
}

fn check(t: &mut Tally, torus: &Torus, rays: &[Ray], levels: &[Dispatch]) {
    let labels: Vec<OracleClass> = rays.iter().map(|r| classify(torus, r).class).collect();
    t.rays += rays.len();
    t.oracle_hits += labels.iter().filter(|&&c| c == OracleClass::Hit).count();
    let mut wavefront = Wavefront::new();
    let mut hits = Vec::new();
    for cull in BATCHED {
        let want = cull.kind().visit(Scalar(torus, rays));
        for d in levels {
            let stats = wavefront.intersect(d, cull, torus, rays, &mut hits);
            assert_eq!(stats.rays, rays.len());
            assert_eq!(stats.hits, hits.iter().filter(|h| h.is_some()).count());
            for (i, ((got, want), label)) in hits.iter().zip(&want).zip(&labels).enumerate() {
                t.compared += 1;
                let what = || format!("{cull} at {}: torus {torus:?} ray {:?}", d.isa(), rays[i]);
                match (got, want) {
                    (Some(g), Some(w)) => {
                        t.hits += 1;
                        let scale = w.t.abs().max(1.0);
                        if (g.t - w.t).abs() > 1e-6 * scale || (g.normal - w.normal).length() > 1e-5
                        {
                            t.value_mismatch += 1;
                            if t.examples.len() < 6 {
                                t.examples.push(format!("{}: {g:?} vs {w:?}", what()));
                            }
                        }
                    }
                    (None, None) => {}
                    _ => {
                        t.presence_mismatch += 1;
                        if t.examples.len() < 6 {
                            t.examples.push(format!("{}: {got:?} vs {want:?}", what()));
                        }
                    }
                }
                if got.is_none() && *label == OracleClass::Hit {
                    t.missed_hits += 1;
                    if t.examples.len() < 6 {
                        t.examples
                            .push(format!("{}: oracle hit, wavefront none", what()));
                    }
                }
            }
        }
    }
}

#[test]
fn wavefront_hits_are_the_scalar_hits_and_miss_no_oracle_hit() {
    let levels = crate::dispatch_levels();
    let nus = [1.01, 1.25, 2.0, 4.0, 16.0, 1000.0];
    let tallies = on_two_threads(&nus, |&nu| {
        let mut t = Tally::default();
        for &case in Case::ALL {
            for batch in family(case, nu, 3_000, 0xBA7E ^ nu.to_bits()) {
                check(&mut t, &batch.torus, &batch.rays, &levels);
                if case == Case::Grazing {
                    let far = 250.0 * batch.torus.outer_radius();
                    let rays: Vec<Ray> = batch.rays.iter().map(|r| pushed_back(r, far)).collect();
                    check(&mut t, &batch.torus, &rays, &levels);
                }
            }
        }
        (nu, t)
    });
    for (nu, t) in &tallies {
        println!(
            "nu={nu}: {} rays ({} oracle hits), {} results compared over {} culls x {:?}, \
             {} hits; presence mismatches {}, value mismatches {}, missed oracle hits {}",
            t.rays,
            t.oracle_hits,
            t.compared,
            BATCHED.len(),
            levels.iter().map(|d| d.isa().name()).collect::<Vec<_>>(),
            t.hits,
            t.presence_mismatch,
            t.value_mismatch,
            t.missed_hits
        );
        assert!(t.oracle_hits > 1_000, "nu={nu}: {t:?}");
        assert_eq!(
            (t.presence_mismatch, t.value_mismatch, t.missed_hits),
            (0, 0, 0),
            "nu={nu}:\n{}",
            t.examples.join("\n")
        );
    }
}

/// Stats add up, and a cull without a batch form has none to hand over.
#[test]
fn stats_count_the_stages() {
    let batch = family(Case::Uniform, 4.0, 1_000, 3).remove(0);
    let d = Dispatch::best();
    let mut w = Wavefront::new();
    let mut hits = Vec::new();
    let none = w.intersect(&d, BatchCull::NoCull, &batch.torus, &batch.rays, &mut hits);
    let skala = w.intersect(&d, BatchCull::Skala, &batch.torus, &batch.rays, &mut hits);
    assert_eq!(none.kept, none.rays);
    assert!(skala.kept < none.kept && skala.scalar_fallbacks <= skala.kept);
    assert_eq!(none.hits, skala.hits);
    assert_eq!(CullKind::DiscriminantF64.batched(), None);
    assert!(
        BatchCull::ALL
            .iter()
            .all(|c| c.kind() != CullKind::DiscriminantF64)
    );
}
