//! Paired timing for the torus family (`torus_cull::family::Toroid`): what an elliptical
//! tube or a spindle costs against the circular torus, and each cull's `total_ns` against
//! `cychosz` on the member, in the module's interleaved rounds (docs of [`super`]).
//!
//! Contenders, one pass each over the same rays per round, in a shuffled order:
//! the circular member (R, a, a)'s exact intersection on the same rays, the same on the
//! rays' images (y scaled by a/b: the lines the member's own solve sees, so the ratio
//! to it is the family path's overhead alone, the geometry factored out), the member's
//! exact intersection, and the member behind each cull of the table ([`CullKind::TIMED`]; a
//! cull that does not accept the member's shape is declined, so it costs the exact
//! intersection alone). Each of `runs` runs keeps its quietest quarter of rounds
//! ([`super::stats::quiet_rounds`]) and gives a median ratio with its bootstrap interval;
//! the runs' ratios give the between-run interval ([`super::runs::between_run_interval`]).

use super::engine::{Schedule, interleave};
use super::runs::between_run_interval;
use super::stats::{QUIET_FRACTION, quiet_rounds, ratio_estimate};
use std::hint::black_box;
use std::time::{Duration, Instant};
use torus_cull::family::Toroid;
use torus_cull::{Cull, CullKind, CullVisitor, Ray};

/// One paired ratio of the family's timing.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FamilyRatio {
    /// What is timed: `exact` (the member, no cull) or a cull's name (its `total_ns`).
    pub contender: String,
    /// Against what: `circular_exact` (the circular torus (R, a) on the same rays),
    /// `circular_exact_on_images` (the same on the rays' images) or `cychosz`.
    pub reference: String,
    /// The geometric mean of the runs' median ratios.
    pub ratio: f64,
    /// Each run's median ratio.
    pub run_ratios: Vec<f64>,
    /// The first run's bootstrap 95 % interval (within-run).
    pub within: [f64; 2],
    /// The 95 % interval over the runs; `None` for a single run.
    pub between: Option<[f64; 2]>,
    /// The contender's median ns per ray (first run).
    pub ns_per_ray: f64,
}

/// The family's ratios for `member` (in its own frame: centre 0, axis +y) on `rays`:
/// its exact intersection over the circular member (R, a, a)'s on the same rays and on
/// their images, and each cull's total over `cychosz`'s, from `runs` runs of about
/// `seconds` each. `None` for an empty ray set, a posed member or a run without rounds.
pub fn time_family(
    member: &Toroid,
    rays: &[Ray],
    runs: usize,
    seconds: f64,
    seed: u64,
) -> Option<Vec<FamilyRatio>> {
    let own_frame = member.center_f64() == glam::DVec3::ZERO && member.axis_f64() == glam::DVec3::Y;
    if rays.is_empty() || runs == 0 || !own_frame {
        return None;
    }
    let a = member.radial_semi_axis_f64();
    let circular = Toroid::canonical(member.major_radius_f64(), a, a).ok()?;
    let scale = glam::Vec3::new(1.0, (a / member.axial_semi_axis_f64()) as f32, 1.0);
    let images: Vec<Ray> = rays
        .iter()
        .map(|r| Ray::with_range(r.origin() * scale, r.dir() * scale, r.t_min(), r.t_max()))
        .collect::<Result<_, _>>()
        .ok()?;
    // Contenders 0: the circular exact; 1: the same on the images; 2: the member's
    // exact; 3..: each cull's total on the member.
    let culls = CullKind::TIMED;
    let cychosz = 3 + culls.iter().position(|&k| k == CullKind::Cychosz)?;
    let mut pairs: Vec<(usize, usize, String, String)> = vec![
        (2, 0, "exact".to_string(), "circular_exact".to_string()),
        (
            2,
            1,
            "exact".to_string(),
            "circular_exact_on_images".to_string(),
        ),
    ];
    for (i, kind) in culls.iter().enumerate() {
        pairs.push((
            3 + i,
            cychosz,
            kind.name().to_string(),
            "cychosz".to_string(),
        ));
    }
    let mut per_run: Vec<Vec<(f64, [f64; 2], f64)>> = vec![Vec::new(); pairs.len()];
    for run in 0..runs {
        // A fresh copy per run: a run's layout is its own (module docs of `super::runs`).
        let (rays, images): (Vec<Ray>, Vec<Ray>) = (rays.to_vec(), images.clone());
        let schedule = Schedule {
            warm_up: Duration::from_secs_f64(0.1 * seconds),
            budget: Duration::from_secs_f64(0.9 * seconds),
            min_rounds: 20,
            max_rounds: 100_000,
            seed: seed.wrapping_add(run as u64),
        };
        let rounds = interleave(3 + culls.len(), &schedule, |i| match i {
            0 => exact_pass(&circular, &rays),
            1 => exact_pass(&circular, &images),
            2 => exact_pass(member, &rays),
            _ => culls[i - 3].visit(CulledPass {
                member,
                rays: &rays,
            }),
        });
        let eligible: Vec<bool> = rounds.disturbed.iter().map(|d| !d).collect();
        let kept = quiet_rounds(&rounds.ns, &eligible, QUIET_FRACTION);
        let pick = |c: usize| -> Vec<f64> { kept.iter().map(|&k| rounds.ns[c][k]).collect() };
        for (slot, &(c, r, _, _)) in per_run.iter_mut().zip(&pairs) {
            let est = ratio_estimate(&pick(c), &pick(r), rays.len() as f64, seed ^ c as u64)?;
            slot.push((est.ratio, est.ratio_ci, est.ns_per_ray));
        }
    }
    Some(
        pairs
            .into_iter()
            .zip(per_run)
            .map(|((_, _, contender, reference), runs)| {
                let run_ratios: Vec<f64> = runs.iter().map(|r| r.0).collect();
                let log_mean =
                    run_ratios.iter().map(|r| r.ln()).sum::<f64>() / run_ratios.len() as f64;
                FamilyRatio {
                    contender,
                    reference,
                    ratio: log_mean.exp(),
                    between: between_run_interval(&run_ratios),
                    run_ratios,
                    within: runs[0].1,
                    ns_per_ray: runs[0].2,
                }
            })
            .collect(),
    )
}

/// One timed pass of the member's exact intersection over the rays.
#[inline(never)]
fn exact_pass(member: &Toroid, rays: &[Ray]) -> Duration {
    let start = Instant::now();
    let mut hits = 0usize;
    for ray in black_box(rays) {
        hits += usize::from(member.intersect(ray).is_some());
    }
    black_box(hits);
    start.elapsed()
}

/// One timed pass of the member behind a cull, monomorphized per cull.
struct CulledPass<'a> {
    member: &'a Toroid,
    rays: &'a [Ray],
}

impl CullVisitor for CulledPass<'_> {
    type Output = Duration;

    #[inline(never)]
    fn visit<C: Cull>(self, cull: C) -> Duration {
        let start = Instant::now();
        let mut hits = 0usize;
        for ray in black_box(self.rays) {
            hits += usize::from(self.member.intersect_culled(&cull, ray).is_some());
        }
        black_box(hits);
        start.elapsed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// The records come out complete and finite at a tiny size (speed is the bench's).
    #[test]
    fn every_cull_and_the_exact_ratio_are_reported() {
        let member = Toroid::canonical(4.0, 1.0, 0.5).unwrap();
        let rays: Vec<Ray> = (0..64)
            .map(|i| {
                let a = i as f32 * 0.1;
                Ray::new(
                    Vec3::new(10.0 * a.cos(), 2.0, 10.0 * a.sin()),
                    Vec3::new(-a.cos(), -0.2, -a.sin()),
                )
                .unwrap()
            })
            .collect();
        let got = time_family(&member, &rays, 2, 0.05, 7).unwrap();
        assert_eq!(got.len(), 2 + CullKind::TIMED.len());
        assert_eq!(
            (got[0].contender.as_str(), got[0].reference.as_str()),
            ("exact", "circular_exact")
        );
        for r in &got {
            assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
            assert_eq!(r.run_ratios.len(), 2);
            assert!(r.between.is_some(), "{r:?}");
        }
    }
}
