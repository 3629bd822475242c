//! Paired timing for pipe bends (`torus_cull::bend::PipeBend`): each cull of the table
//! on the outer torus, and each with the segment's wedge in front
//! (`PipeBend::wedge_cull`), against `cychosz` and against no cull (`none`), on one ray
//! set ([`super::shapes`]).

use super::shapes::{Pair, ShapeRatio, time_contenders};
use crate::results::RatioRecord;
use crate::workload::box_rays::box_rays;
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::hint::black_box;
use std::time::{Duration, Instant};
use torus_cull::bend::PipeBend;
use torus_cull::{Cull, CullKind, CullVisitor, Ray};

/// The bends `time --bend` and `cargo bench` time, (Δφ, r_min/r_max) with R = 4,
/// r_max = 1, φ₀ = 0: Δφ = 2π, π, π/2, π/6 at a bore of half the tube, and no bore and
/// 0.9 at Δφ = π/2.
pub const BENDS: [(f64, f64); 6] = [
    (TAU, 0.5),
    (PI, 0.5),
    (FRAC_PI_2, 0.5),
    (PI / 6.0, 0.5),
    (FRAC_PI_2, 0.0),
    (FRAC_PI_2, 0.9),
];

/// A bend's case in a results file: `bend_dphi<degrees>_bore<r_min/r_max>`
/// (`bend_dphi90_bore0.5`); its ν field is R/r_max.
#[must_use]
pub fn case_name(bend: &PipeBend) -> String {
    let degrees = bend.delta_phi().to_degrees().round();
    let bore = bend.bore_radius_f64() / bend.tube_radius_f64();
    format!("bend_dphi{degrees}_bore{bore}")
}

/// Every bend of [`BENDS`] timed on `batch` uniform rays at the outer torus's box (seeded
/// per bend from `seed`), `runs` runs of `seconds` each, as `ratio` records of metric
/// `bend_total_ns`; `shown` sees each bend's ratios as they come.
///
/// # Errors
///
/// A bend without rounds (too short a time) or an invalid bend, named.
pub fn bend_records(
    seed: u64,
    batch: usize,
    (runs, seconds): (usize, f64),
    mut shown: impl FnMut(&PipeBend, &[ShapeRatio]),
) -> Result<Vec<RatioRecord>, String> {
    let mut records = Vec::new();
    for (i, &(delta_phi, bore)) in BENDS.iter().enumerate() {
        let bend =
            PipeBend::canonical(4.0, bore, 1.0, 0.0, delta_phi).map_err(|e| e.to_string())?;
        let rays = box_rays(4.0, 1.0, 1.0, batch, seed.wrapping_add(i as u64));
        let ratios = time_bend(&bend, &rays, runs, seconds, seed)
            .ok_or_else(|| format!("{}: no rounds (raise the time)", case_name(&bend)))?;
        shown(&bend, &ratios);
        let case = case_name(&bend);
        records.extend(
            ratios
                .iter()
                .map(|r| r.record(&case, 4.0, "bend_total_ns", rays.len())),
        );
    }
    Ok(records)
}

/// The bend's ratios on `rays`: each cull (`<name>`) and each cull with the wedge
/// (`wedge+<name>`), each against `cychosz` and against no cull (`none`), from
/// `runs` runs of about `seconds`. `None` for an empty ray set or a run without rounds.
pub fn time_bend(
    bend: &PipeBend,
    rays: &[Ray],
    runs: usize,
    seconds: f64,
    seed: u64,
) -> Option<Vec<ShapeRatio>> {
    // Contenders 0: no cull; 1 + i: cull i; 1 + n + i: cull i with the wedge.
    let culls = CullKind::TIMED;
    let n = culls.len();
    let cychosz = 1 + culls.iter().position(|&k| k == CullKind::Cychosz)?;
    let mut pairs: Vec<Pair> = Vec::new();
    let name = |s: &str| s.to_string();
    for (i, kind) in culls.iter().enumerate() {
        for (c, label) in [
            (1 + i, name(kind.name())),
            (1 + n + i, format!("wedge+{kind}")),
        ] {
            pairs.push((c, cychosz, label.clone(), name("cychosz")));
            pairs.push((c, 0, label, name("none")));
        }
    }
    time_contenders(1 + 2 * n, pairs, (runs, seconds, seed), rays.len(), |_| {
        let rays = rays.to_vec();
        move |i| {
            if i == 0 {
                return exact_pass(bend, &rays);
            }
            let (kind, wedge) = (culls[(i - 1) % n], i > n);
            kind.visit(Pass {
                bend,
                rays: &rays,
                wedge,
            })
        }
    })
}

#[inline(never)]
fn exact_pass(bend: &PipeBend, rays: &[Ray]) -> Duration {
    let start = Instant::now();
    let mut hits = 0usize;
    for ray in black_box(rays) {
        hits += usize::from(bend.intersect(ray).is_some());
    }
    black_box(hits);
    start.elapsed()
}

/// One timed pass behind a cull (with or without the wedge), monomorphized per cull.
struct Pass<'a> {
    bend: &'a PipeBend,
    rays: &'a [Ray],
    wedge: bool,
}

impl CullVisitor for Pass<'_> {
    type Output = Duration;

    #[inline(never)]
    fn visit<C: Cull>(self, cull: C) -> Duration {
        let start = Instant::now();
        let mut hits = 0usize;
        if self.wedge {
            let cull = self.bend.wedge_cull(cull);
            for ray in black_box(self.rays) {
                hits += usize::from(self.bend.intersect_culled(&cull, ray).is_some());
            }
        } else {
            for ray in black_box(self.rays) {
                hits += usize::from(self.bend.intersect_culled(&cull, ray).is_some());
            }
        }
        black_box(hits);
        start.elapsed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The records come out complete and finite at a tiny size (speed is `time --bend`'s).
    #[test]
    fn every_cull_with_and_without_the_wedge_is_reported() {
        let bend = PipeBend::canonical(4.0, 0.5, 1.0, 0.0, std::f64::consts::FRAC_PI_2).unwrap();
        let rays = crate::workload::box_rays::box_rays(4.0, 1.0, 1.0, 64, 9);
        let got = time_bend(&bend, &rays, 2, 0.1, 7).expect("rounds");
        assert_eq!(got.len(), 4 * CullKind::TIMED.len());
        for r in &got {
            assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
        }
    }
}
