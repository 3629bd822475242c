//! Paired timing for pipe bends (`torus_cull::bend::PipeBend`): each cull of the table
//! on the outer torus, and each with the segment's wedge in front
//! (`PipeBend::wedge_cull`), against `cychosz` and against no cull (`exact`), on one ray
//! set ([`super::shapes`]).

use super::shapes::{Pair, ShapeRatio, time_contenders};
use std::hint::black_box;
use std::time::{Duration, Instant};
use torus_cull::bend::PipeBend;
use torus_cull::{Cull, CullKind, CullVisitor, Ray};

/// The bend's ratios on `rays`: `exact` (no cull), each cull (`<name>`) and each cull
/// with the wedge (`wedge+<name>`), each against `cychosz` and against `exact`, from
/// `runs` runs of about `seconds`. `None` for an empty ray set or a run without rounds.
pub fn time_bend(
    bend: &PipeBend,
    rays: &[Ray],
    runs: usize,
    seconds: f64,
    seed: u64,
) -> Option<Vec<ShapeRatio>> {
    // Contenders 0: exact; 1 + i: cull i; 1 + n + i: cull i with the wedge.
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
            pairs.push((c, 0, label, name("exact")));
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
