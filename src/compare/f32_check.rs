//! `torus-cull compare` on two f32-check files, family by family.
//!
//! * **f32-check** rows (`<family>[ ν] cert` and `<family>[ ν] f32`, the certified verdict and
//!   the whole f32 path): the escalation rate, recomputed from `escalated / rays`. A
//!   changed count is flagged `changed`; more missed, spurious or far answers than before
//!   is a **regression** (ours must have none). The peer's row (`<family> peer`) shows its
//!   changes and decides nothing: its speckles are what f32-check measures, not ours.
//! * **f32-check timing** rows (`<family> f32 path`): ns per ray, the minimum over a few
//!   rounds with no interval, so a change is shown as `no verdict (no interval)`.
//!
//! Two files of different families, rays or seed (`meta.workload_sha256`) are refused by
//! [`comparable`], as results files of different workloads are.

use super::counted::{self, CountedFile};
use super::rows::{Report, Row, TIMED_SECTIONS, changed_counts, counts, judged_row, pair_up};
use crate::f32_check::{CheckFile, FamilyRecord, Tally};

/// A family's key: its name, and its ν when it has one (the workload generators' families
/// share a name across ν).
fn family_key(f: &FamilyRecord) -> String {
    match f.nu {
        Some(nu) => format!("{} {nu}", f.family),
        None => f.family.clone(),
    }
}

/// The file as [`counted`] sees it.
fn counted(file: &CheckFile) -> CountedFile<'_, FamilyRecord> {
    CountedFile {
        kind: "f32-check",
        class: "family",
        meta: &file.meta,
        classes: &file.families,
        rays: file.rays_per_family,
        seed: format!("{:?}", file.meta.seed),
    }
}

/// Refuses files whose rays differ, and a file that holds a family twice.
pub fn comparable(old: &CheckFile, new: &CheckFile) -> Result<(), String> {
    counted::comparable(&counted(old), &counted(new), family_key)
}

/// The rows of two f32-check files; `threshold` is a fraction (0.10 for 10 %). Timing
/// verdicts across machines are handled as for results files.
pub fn compare(old: &CheckFile, new: &CheckFile, threshold: f64, across_machines: bool) -> Report {
    let mut report = Report {
        meta: super::machine::differences(&old.meta, &new.meta),
        across_machines,
        ..Report::default()
    };
    let pairs = pair_up(
        &old.families,
        &new.families,
        family_key,
        &mut report,
        "f32-check",
    );
    for (key, o, n) in &pairs {
        let oracle = changed_counts(&counts!(o, n; rays, hits, misses, ambiguous));
        for (who, a, b, ours) in [
            ("cert", &o.certified, &n.certified, true),
            ("f32", &o.f32_path, &n.f32_path, true),
            ("peer", &o.peer, &n.peer, false),
        ] {
            let mut row = tally_row(format!("{key} {who}"), (a, o.rays), (b, n.rays), ours);
            if who == "cert" && !oracle.is_empty() {
                row.flags
                    .insert(0, format!("oracle counts changed: {}", oracle.join(", ")));
            }
            report.rows.push(row);
        }
    }
    for (key, o, n) in &pairs {
        if let (Some(a), Some(b)) = (o.ns_per_ray, n.ns_per_ray) {
            let change = b.f32_path / a.f32_path - 1.0;
            let flags = if change.abs() > threshold {
                vec![format!(
                    "{} {:+.1}%: no verdict (no interval)",
                    if change > 0.0 { "slower" } else { "faster" },
                    change * 100.0
                )]
            } else {
                Vec::new()
            };
            report.rows.push(Row {
                section: TIMED_SECTIONS[2],
                key: format!("{key} f32 path"),
                metric: "ns_per_ray (min of rounds)",
                old: a.f32_path,
                new: b.f32_path,
                flags,
                regression: false,
            });
        }
    }
    super::judge_across_machines(&mut report);
    report
}

/// One intersector on one family: its escalation rate from its counts, its changed
/// counts, and (for ours) a regression when it got more answers wrong.
fn tally_row(
    key: String,
    (o, o_rays): (&Tally, u64),
    (n, n_rays): (&Tally, u64),
    ours: bool,
) -> Row {
    let rate = |t: &Tally, rays: u64| {
        if rays > 0 {
            t.escalated as f64 / rays as f64
        } else {
            f64::NAN
        }
    };
    let counts = counts!(o, n; escalated, missed, spurious, far, hits_answered);
    let wrong = |t: &Tally| t.missed + t.spurious + t.far;
    let worse = (ours && wrong(n) > wrong(o)).then(|| {
        format!(
            "REGRESSION: missed/spurious/far {}/{}/{} -> {}/{}/{}",
            o.missed, o.spurious, o.far, n.missed, n.spurious, n.far
        )
    });
    let rates = (rate(o, o_rays), rate(n, n_rays));
    judged_row(("f32-check", key, "escalation_rate"), rates, &counts, worse)
}
