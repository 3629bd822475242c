//! Batch mode's timed culls and the criterion benchmarks of one cull on one batch.

use criterion::{BenchmarkId, Criterion};
use std::hint::black_box;
use torus_cull::batch::{BatchCull, Dispatch, KeepMask, Lines, Wavefront, cull_batch};
use torus_cull::{Named, Ray, Torus};
use torus_cull_lab::workload::Case;

/// The culls timed in batch mode: the baseline and the five the wavefront model is
/// about (the branch-free classics and the three new quadric/discriminant culls).
pub const BATCH_TIMED: [BatchCull; 6] = [
    BatchCull::NoCull,
    BatchCull::Cychosz,
    BatchCull::Skala,
    BatchCull::Ellipsoid,
    BatchCull::Quadric,
    BatchCull::Discriminant,
];

/// The criterion groups of batch mode, each `<group>-<case>`, per cull of [`BATCH_TIMED`].
pub const BATCH_GROUPS: [&str; 3] = ["batch_cull_ns", "batch_total_ns", "batch_f32_total_ns"];

/// One case's batch at one ν, for batch mode.
pub struct BatchCase<'a> {
    pub case: Case,
    pub nu: f64,
    pub torus: &'a Torus,
    pub rays: &'a [Ray],
    pub lines: &'a Lines,
}

/// Times one cull on one batch in batch mode: `batch_cull_ns` (the SIMD cull over the
/// structure-of-arrays lines, into a keep mask), `batch_total_ns` (the wavefront on
/// world rays: lines, cull, compaction, exact intersection on lanes, hits) and
/// `batch_f32_total_ns` (the same through the certified f32 path).
pub fn time_batch_cull(c: &mut Criterion, dispatch: &Dispatch, cull: BatchCull, on: &BatchCase) {
    let BatchCase {
        case,
        nu,
        torus,
        rays,
        lines,
    } = *on;
    let bounds = torus.bounds();
    let id = BenchmarkId::new(cull.name(), nu);
    let mut keep = KeepMask::new();
    c.benchmark_group(format!("batch_cull_ns-{case}"))
        .bench_with_input(id.clone(), lines, |b, lines| {
            b.iter(|| {
                cull_batch(dispatch, cull, bounds, black_box(lines), &mut keep);
                black_box(&keep);
            })
        });
    let mut wavefront = Wavefront::new();
    let mut hits = Vec::new();
    c.benchmark_group(format!("batch_total_ns-{case}"))
        .bench_with_input(id.clone(), rays, |b, rays| {
            b.iter(|| {
                black_box(wavefront.intersect(dispatch, cull, torus, black_box(rays), &mut hits));
                black_box(&hits);
            })
        });
    c.benchmark_group(format!("batch_f32_total_ns-{case}"))
        .bench_with_input(id, rays, |b, rays| {
            b.iter(|| {
                black_box(wavefront.intersect_f32(
                    dispatch,
                    cull,
                    torus,
                    black_box(rays),
                    &mut hits,
                ));
                black_box(&hits);
            })
        });
}
