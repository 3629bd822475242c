//! `torus-cull time --bend`: pipe bends' paired ratios ([`torus_cull_lab::paired::bend`])
//! on uniform rays at the outer torus's box, ν = R/r_max = 4: Δφ = 2π, π, π/2, π/6 at
//! r_min/r_max = 0.5, and r_min/r_max = 0 and 0.9 at Δφ = π/2, written as the `ratio`
//! section of a results file (metric `bend_total_ns`), which `compare` reads.

use super::shapes::{Records, Timed, show};
use torus_cull_lab::paired::bend::{BENDS, bends};
use torus_cull_lab::paired::shapes::shape_records;

/// Every bend of [`BENDS`]; each prints the best cull with and without the wedge.
pub(super) const TIMED: Timed = Timed {
    name: "bend",
    shapes: BENDS.len(),
    records,
};

fn records(seed: u64, batch: usize, timing: (usize, f64)) -> Records {
    shape_records(&bends()?, seed, batch, timing, |bend, ratios| {
        let best = |wedge: bool| {
            ratios
                .iter()
                .filter(|r| r.reference == "none" && r.contender.starts_with("wedge+") == wedge)
                .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
                .expect("every cull is timed")
        };
        let (plain, wedged) = (best(false), best(true));
        println!(
            "dphi = {:.4}, r_min/r_max = {}: over no cull, best {} {}, best with the wedge {} {}",
            bend.delta_phi(),
            bend.bore_radius_f64() / bend.tube_radius_f64(),
            plain.contender,
            show(plain),
            wedged.contender,
            show(wedged)
        );
    })
}
