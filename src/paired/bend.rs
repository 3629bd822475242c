//! Paired timing for pipe bends (`torus_cull::bend::PipeBend`): each cull of the table
//! on the outer torus, and each with the segment's wedge in front
//! (`PipeBend::wedge_cull`), against `cychosz` and against no cull (`none`), on one ray
//! set ([`super::shapes`]).

use super::engine::timed_pass;
use super::shapes::{CulledPass, Pair, ShapeRatio, TimedShape, time_contenders};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::time::Duration;
use torus_cull::bend::PipeBend;
use torus_cull::{Cull, CullKind, CullVisitor, Ray};

/// The bends `time bend` and `cargo bench` time, (Δφ, r_min/r_max) with R = 4,
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

/// The bends of [`BENDS`], as [`super::shapes::shape_records`] times them.
///
/// # Errors
///
/// An invalid bend, named.
pub fn bends() -> Result<Vec<PipeBend>, String> {
    BENDS
        .iter()
        .map(|&(delta_phi, bore)| PipeBend::canonical(4.0, bore, 1.0, 0.0, delta_phi))
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())
}

/// The bend's ratios on `rays`: each cull (`<name>`) and each cull with the wedge
/// (`wedge+<name>`), each against `cychosz` and against no cull (`none`), from
/// `runs` runs of about `seconds`. `None` for an empty ray set or a run without rounds.
impl TimedShape for PipeBend {
    const METRIC: &'static str = "bend_total_ns";

    #[inline(always)]
    fn hit_culled<C: Cull>(&self, cull: &C, ray: &Ray) -> bool {
        self.intersect_culled(cull, ray).is_some()
    }

    fn box_radii(&self) -> (f64, f64, f64) {
        let (big, tube) = (self.major_radius_f64(), self.tube_radius_f64());
        (big, tube, tube)
    }

    /// A bend's case in a results file: `bend_dphi<degrees>_bore<r_min/r_max>`
    /// (`bend_dphi90_bore0.5`); its ν field is R/r_max.
    fn case_name(&self) -> String {
        let degrees = self.delta_phi().to_degrees().round();
        let bore = self.bore_radius_f64() / self.tube_radius_f64();
        format!("bend_dphi{degrees}_bore{bore}")
    }

    fn ratios(&self, rays: &[Ray], timing: (usize, f64, u64)) -> Option<Vec<ShapeRatio>> {
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
        time_contenders(1 + 2 * n, pairs, timing, rays.len(), |_| {
            let rays = rays.to_vec();
            move |i| {
                if i == 0 {
                    return exact_pass(self, &rays);
                }
                let (kind, wedge) = (culls[(i - 1) % n], i > n);
                kind.visit(Pass {
                    bend: self,
                    rays: &rays,
                    wedge,
                })
            }
        })
    }
}

#[inline(never)]
fn exact_pass(bend: &PipeBend, rays: &[Ray]) -> Duration {
    timed_pass(rays, |ray, (): &mut ()| bend.intersect(ray).is_some())
}

/// One timed pass behind a cull (with or without the wedge), monomorphized per cull:
/// [`CulledPass`] behind the cull or behind its wedge cull.
struct Pass<'a> {
    bend: &'a PipeBend,
    rays: &'a [Ray],
    wedge: bool,
}

impl CullVisitor for Pass<'_> {
    type Output = Duration;

    fn visit<C: Cull>(self, cull: C) -> Duration {
        let pass = CulledPass {
            shape: self.bend,
            rays: self.rays,
        };
        if self.wedge {
            // Made before the clock starts, as the pass it replaced made it just after:
            // a few multiplications, beside a pass of hundreds of rays.
            pass.visit(self.bend.wedge_cull(cull))
        } else {
            pass.visit(cull)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The records come out complete and finite at a tiny size (speed is `time bend`'s).
    #[test]
    fn every_cull_with_and_without_the_wedge_is_reported() {
        let bend = PipeBend::canonical(4.0, 0.5, 1.0, 0.0, std::f64::consts::FRAC_PI_2).unwrap();
        let rays = crate::workload::box_rays::box_rays(4.0, 1.0, 1.0, 64, 9);
        let got = bend.ratios(&rays, (2, 0.1, 7)).expect("rounds");
        assert_eq!(got.len(), 4 * CullKind::TIMED.len());
        for r in &got {
            assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
        }
    }
}
