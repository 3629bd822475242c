//! Plain-text tables of a results file, as `run` and `cargo bench` print them.

mod shapes;

use crate::results::{CPU_DEVICE, F64_REFERENCE, RatioRecord, Results, TimingRecord};
use std::fmt::Write;

/// One table per case: rows ν, columns culls, cells `value(record)` formatted by `fmt`.
fn table<R>(
    records: &[R],
    key: impl Fn(&R) -> (&str, f64, &str),
    cell: impl Fn(&R) -> String,
    title: impl Fn(&str) -> String,
) -> String {
    grid(records, "nu", key, cell, title)
}

/// [`table`] with rows named `row` (`nu`, `bore`): one table per group, rows the key's
/// number, columns its name.
fn grid<R>(
    records: &[R],
    row: &str,
    key: impl Fn(&R) -> (&str, f64, &str),
    cell: impl Fn(&R) -> String,
    title: impl Fn(&str) -> String,
) -> String {
    let mut cases: Vec<&str> = Vec::new();
    let mut culls: Vec<&str> = Vec::new();
    for r in records {
        let (case, _, cull) = key(r);
        if !cases.contains(&case) {
            cases.push(case);
        }
        if !culls.contains(&cull) {
            culls.push(cull);
        }
    }
    let mut out = String::new();
    for case in cases {
        let _ = writeln!(out, "{}", title(case));
        let mut nus: Vec<f64> = records
            .iter()
            .filter(|r| key(r).0 == case)
            .map(|r| key(r).1)
            .collect();
        nus.sort_by(f64::total_cmp);
        nus.dedup();
        let cells: Vec<Vec<String>> = nus
            .iter()
            .map(|&nu| {
                culls
                    .iter()
                    .map(|c| {
                        records
                            .iter()
                            .find(|r| key(r) == (case, nu, c))
                            .map(&cell)
                            .unwrap_or_else(|| "-".into())
                    })
                    .collect()
            })
            .collect();
        // Each column as wide as its name or its widest cell: ten culls stay readable.
        let widths: Vec<usize> = culls
            .iter()
            .enumerate()
            .map(|(i, c)| {
                cells
                    .iter()
                    .map(|row| row[i].chars().count())
                    .chain([c.len(), 5])
                    .max()
                    .unwrap_or(5)
            })
            .collect();
        let _ = write!(out, "{row:>7}");
        for (c, width) in culls.iter().zip(&widths) {
            let _ = write!(out, " {c:>width$}");
        }
        let _ = writeln!(out);
        for (nu, row) in nus.iter().zip(&cells) {
            let _ = write!(out, "{nu:>7}");
            for (text, width) in row.iter().zip(&widths) {
                let _ = write!(out, " {text:>width$}");
            }
            let _ = writeln!(out);
        }
        let _ = writeln!(out);
    }
    out
}

/// Miss capture per case (rows ν, columns culls); `n/a` where a batch has no misses.
pub fn miss_capture_tables(results: &Results) -> String {
    table(
        &results.rejection,
        |r| (r.case.as_str(), r.nu, r.cull.as_str()),
        |r| r.miss_capture.map_or("n/a".into(), |c| format!("{c:.3}")),
        |case| format!("{case}: miss capture (rejected / misses)"),
    )
}

/// The other shapes' miss capture (`results.shapes`): per b/a of the family, rows ν
/// (ring, horn, spindle alike), columns culls, `-` where the cull declines the shape; per
/// bend ν and segment, rows the bore, columns culls, each cell the cull alone and behind
/// the segment's wedge (`none`'s: the wedge alone).
pub fn shape_tables(results: &Results) -> String {
    shapes::tables(&results.shapes, |cells, row, title| {
        grid(
            cells,
            row,
            |c: &shapes::Cell| (c.group.as_str(), c.row, c.column.as_str()),
            |c| c.text.clone(),
            title,
        )
    })
}

/// The scalar-mode timing records (one ray at a time, f64).
fn scalar_timings(results: &Results) -> Vec<TimingRecord> {
    results
        .timing
        .iter()
        .filter(|r| !r.is_batch() && !r.is_f32())
        .cloned()
        .collect()
}

/// Total ns per ray with the speedup over `none`, per case (scalar mode).
pub fn timing_tables(results: &Results) -> String {
    table(
        &scalar_timings(results),
        |r| (r.case.as_str(), r.nu, r.cull.as_str()),
        |r| format!("{:.1} ({:.2}x)", r.total_ns, r.speedup_vs_none),
        |case| format!("{case}: total ns per ray, cull + exact intersection (speedup vs none)"),
    )
}

/// Cull-alone ns per ray, per case (scalar mode).
pub fn cull_ns_tables(results: &Results) -> String {
    table(
        &scalar_timings(results),
        |r| (r.case.as_str(), r.nu, r.cull.as_str()),
        |r| format!("{:.2}", r.cull_ns),
        |case| format!("{case}: cull alone, ns per ray"),
    )
}

/// BVH figures: Mrays/s and quartic solves per ray, per scene.
pub fn bvh_tables(results: &Results) -> String {
    let keyed: Vec<(String, &crate::results::BvhRecord)> = results
        .bvh
        .iter()
        .map(|r| (format!("{} {} rays", r.scene, r.ray_set), r))
        .collect();
    table(
        &keyed,
        |(k, r)| (k.as_str(), r.nu, r.cull.as_str()),
        |(_, r)| format!("{:.2} / {:.3}", r.mrays_per_s, r.quartic_solves_per_ray),
        |scene| format!("BVH {scene}: Mrays/s / quartic solves per ray"),
    )
}

/// Paired ratios per case, metric and reference (rows ν, columns culls): the median
/// per-round `t(cull) / t(reference)` and its bootstrap 95 % interval (of several runs,
/// their geometric mean and the between-run interval, see [`crate::paired::runs`]). Below 1 the cull
/// is faster than the reference. The f32 wavefront's ratios against the same cull's f64
/// wavefront (reference `f64`) are the f32 / f64 speed ratio; after them, the f32
/// path's escalation rates.
pub fn ratio_tables(results: &Results) -> String {
    let keyed: Vec<(String, &RatioRecord)> = results
        .ratio
        .iter()
        .map(|r| {
            let what = match r.metric.as_str() {
                "total_ns" => "total (cull + exact intersection)",
                "cull_ns" => "cull alone",
                "batch_total_ns" => "batch total (wavefront: SIMD cull + lane intersection)",
                "batch_cull_ns" => "batch cull alone (SIMD)",
                "batch_f32_total_ns" => "batch f32 total (certified f32 wavefront)",
                "batch_f32_uncertified_ns" => "batch f32 total, uncertified (no proof)",
                "family_total_ns" => "family member total (cull + exact intersection)",
                "bend_total_ns" => "pipe bend total (cull or wedge + exact intersection)",
                "bvh_closest_ns" => "BVH closest-hit (camera rays, cull at the leaves)",
                "bvh_anyhit_ns" => "BVH any-hit (shadow rays, cull at the leaves)",
                "bvh_bounce_ns" => "BVH closest-hit of bounce rays (diffuse, from the camera hits)",
                "bvh_batched_ns" => "BVH batched leaves (wavefront per torus)",
                other => other,
            };
            let device = if r.device == CPU_DEVICE {
                String::new()
            } else {
                format!(" on {}", r.device)
            };
            let reference = if r.reference == F64_REFERENCE {
                "the same cull's f64 wavefront"
            } else if r.reference == crate::paired::bvh::SCALAR_REFERENCE {
                "the same cull's scalar closest-hit"
            } else {
                r.reference.as_str()
            };
            (format!("{}: {what}{device} / {reference}", r.case), r)
        })
        .collect();
    // Of several runs, the interval shown is the between-run one: how far the next run
    // may land, not only how well this one's rounds pinned it down. The title says how
    // many runs the interval comes from: "within 1 run" where every record kept one run
    // (with how many were made), else "between N runs", N the runs made whether or not
    // some were set aside as run in a slow state of the machine (`runs_set_aside`, see
    // `paired::runs::SLOW_STATE`: the header's shape does not depend on the machine's
    // state), and, per ν, how many were, and where that left one run, that its interval
    // is that run's own.
    let header = |title: &str| {
        let of: Vec<&RatioRecord> = keyed
            .iter()
            .filter(|(k, _)| k == title)
            .map(|(_, r)| *r)
            .collect();
        runs_header(title, &of)
    };
    let mut out = table(
        &keyed,
        |(k, r)| (k.as_str(), r.nu, r.cull.as_str()),
        |(_, r)| {
            let [lo, hi] = r.ratio_ci_between.unwrap_or(r.ratio_ci);
            format!("{:.3} [{lo:.3}, {hi:.3}]", r.ratio)
        },
        header,
    );
    // One escalation rate per cull and (case, ν): the certified records all carry it.
    let escalation: Vec<&RatioRecord> = results
        .ratio
        .iter()
        .filter(|r| r.metric == "batch_f32_total_ns" && r.reference == F64_REFERENCE)
        .collect();
    out += &table(
        &escalation,
        |r| (r.case.as_str(), r.nu, r.cull.as_str()),
        |r| {
            r.escalation_rate
                .map_or("-".into(), |e| format!("{:.3}%", 100.0 * e))
        },
        |case| format!("{case}: certified f32 wavefront, rays escalated to f64 / rays"),
    );
    out
}

/// A paired-ratio table's title, `{title}, paired ratio [95% CI]` and how many runs its
/// intervals come from (see [`ratio_tables`]), for the table's records `of`.
fn runs_header(title: &str, of: &[&RatioRecord]) -> String {
    let made = of
        .iter()
        .map(|r| r.runs + r.runs_set_aside)
        .max()
        .unwrap_or(1);
    // Per ν with runs set aside: how many, and whether one run was left there.
    let mut aside: Vec<(f64, u64, bool)> = of
        .iter()
        .filter(|r| r.runs_set_aside > 0)
        .map(|r| (r.nu, r.runs_set_aside, r.ratio_ci_between.is_none()))
        .collect();
    aside.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    aside.dedup();
    let single = of.iter().all(|r| r.ratio_ci_between.is_none());
    let head = format!("{title}, paired ratio [95% CI]");
    if made <= 1 {
        return format!("{head} within 1 run");
    }
    let at: Vec<String> = aside
        .iter()
        .map(|&(nu, n, one_left)| {
            let left = if one_left && !single {
                ", there within the 1 run left"
            } else {
                ""
            };
            format!("{n} at ν = {}{left}", crate::number::Num(nu))
        })
        .collect();
    let set_aside = if at.is_empty() {
        String::new()
    } else {
        format!(
            "set aside as run in a slow state of the machine: {}",
            at.join(", ")
        )
    };
    match (single, set_aside.is_empty()) {
        (true, true) => format!("{head} within 1 run ({made} made)"),
        (true, false) => format!("{head} within 1 run ({made} made; {set_aside})"),
        (false, true) => format!("{head} between {made} runs"),
        (false, false) => format!("{head} between {made} runs ({set_aside})"),
    }
}

/// Scalar against batch mode per case (rows ν, columns the culls timed both ways): each
/// cell is `cull_ns scalar → batch | total_ns scalar → batch`, ns per ray. Empty when the
/// file has no batch records.
pub fn scalar_vs_batch_tables(results: &Results) -> String {
    let f64_cpu = |r: &TimingRecord| !r.is_f32() && r.device == CPU_DEVICE;
    let pairs: Vec<(&TimingRecord, &TimingRecord)> = results
        .timing
        .iter()
        .filter(|b| b.is_batch() && f64_cpu(b))
        .filter_map(|b| {
            results
                .timing
                .iter()
                .find(|s| {
                    !s.is_batch()
                        && f64_cpu(s)
                        && s.case == b.case
                        && s.nu == b.nu
                        && s.cull == b.cull
                })
                .map(|s| (s, b))
        })
        .collect();
    let isa = results.meta.isa.as_deref().unwrap_or("unknown");
    table(
        &pairs,
        |(s, _)| (s.case.as_str(), s.nu, s.cull.as_str()),
        |(s, b)| {
            format!(
                "{:.2}→{:.2} | {:.1}→{:.1}",
                s.cull_ns, b.cull_ns, s.total_ns, b.total_ns
            )
        },
        |case| {
            format!(
                "{case}: scalar → batch ({isa}), ns per ray: cull alone | cull + exact intersection"
            )
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workload::spec::Workload;

    /// A `hole` total-time record of skala against cychosz at ν, of `runs` kept and
    /// `aside` set aside.
    fn record(nu: f64, runs: u64, aside: u64) -> RatioRecord {
        RatioRecord {
            case: "hole".into(),
            nu,
            cull: "skala".into(),
            reference: "cychosz".into(),
            metric: "total_ns".into(),
            ratio: 0.2,
            ratio_ci: [0.19, 0.21],
            rounds: 40,
            rounds_measured: 80,
            rays: 200,
            ns_per_ray: 20.0,
            reference_ns_per_ray: 100.0,
            precision: "f64".into(),
            device: CPU_DEVICE.into(),
            escalation_rate: None,
            runs,
            runs_set_aside: aside,
            run_ratios: Vec::new(),
            // Of two runs or more kept, the between-run interval.
            ratio_ci_between: (runs > 1).then_some([0.18, 0.22]),
            run_spread: None,
        }
    }

    fn tables(records: Vec<RatioRecord>) -> String {
        let workload = Workload::open(std::path::Path::new("quick")).unwrap();
        let mut results = Results::new(&workload, "time");
        results.ratio = records;
        ratio_tables(&results)
    }

    /// Issue 36: a run set aside as slow no longer drops "between 2 runs" from the header
    /// (which made `time_cli` fail by chance); the header says where runs were set aside.
    #[test]
    fn the_header_counts_the_runs_made_whether_or_not_one_was_set_aside() {
        let title = "hole: total (cull + exact intersection) / cychosz, paired ratio [95% CI]";
        let kept = tables(vec![record(2.0, 2, 0), record(8.0, 2, 0)]);
        assert!(
            kept.contains(&format!("{title} between 2 runs\n")),
            "{kept}"
        );
        // Every batch lost a run: the intervals are one run's own, and the header says
        // so, with the runs made (the bug: it said "between 2 runs" over them).
        let aside = tables(vec![record(2.0, 1, 1), record(8.0, 1, 1)]);
        assert!(
            aside.contains(&format!(
                "{title} within 1 run (2 made; set aside as run in a slow state of the \
                 machine: 1 at ν = 2, 1 at ν = 8)\n"
            )),
            "{aside}"
        );
        let one = tables(vec![record(2.0, 2, 0), record(8.0, 1, 1)]);
        assert!(
            one.contains(&format!(
                "{title} between 2 runs (set aside as run in a slow state of the machine: \
                 1 at ν = 8, there within the 1 run left)\n"
            )),
            "{one}"
        );
        let three = tables(vec![record(2.0, 5, 0), record(8.0, 3, 2)]);
        assert!(
            three.contains(&format!(
                "{title} between 5 runs (set aside as run in a slow state of the machine: \
                 2 at ν = 8)\n"
            )),
            "{three}"
        );
        // One run (--runs 1).
        let single = tables(vec![record(2.0, 1, 0)]);
        assert!(
            single.contains(&format!("{title} within 1 run\n")),
            "{single}"
        );
    }
}
