//! `torus-cull time --family`: the torus family's paired ratios
//! ([`torus_cull_lab::paired::family`]) on uniform rays, at ν = R/a = 4 for the elliptical
//! tubes (b/a = 1/4, 1/2, 1, 2, 4) and at the horn and two spindles, written as the
//! `ratio` section of a results file (metric `family_total_ns`), which `compare` reads.

use super::shapes::{Records, Timed, show};
use torus_cull_lab::paired::family::{MEMBERS, members};
use torus_cull_lab::paired::shapes::shape_records;

/// Every member of [`MEMBERS`]; each prints its exact intersection's cost and its
/// fastest cull.
pub(super) const TIMED: Timed = Timed {
    name: "family",
    shapes: MEMBERS.len(),
    records,
};

fn records(seed: u64, batch: usize, timing: (usize, f64)) -> Records {
    shape_records(&members()?, seed, batch, timing, |member, ratios| {
        let best = ratios[2..]
            .iter()
            .min_by(|x, y| x.ratio.total_cmp(&y.ratio))
            .expect("every cull is timed");
        println!(
            "R = {}, a = {}, b = {} ({:?}): exact / circular exact = {}, on the images {}; \
             fastest cull: {} / cychosz = {}",
            member.major_radius_f64(),
            member.radial_semi_axis_f64(),
            member.axial_semi_axis_f64(),
            member.kind(),
            show(&ratios[0]),
            show(&ratios[1]),
            best.contender,
            show(best)
        );
    })
}
