//! `compare` on other kinds of files (f32-check, estimate-only, mixed) and on records
//! with between-run intervals.

use super::*;

/// Issue 29: the report's first line is never blank (`compare | head -1`), and a key longer
/// than the default column keeps the columns aligned.
/// Asserts that one of `notes` says every one of `parts`.
fn assert_note(notes: &[String], parts: &[&str]) {
    assert!(
        notes.iter().any(|n| parts.iter().all(|p| n.contains(p))),
        "no note with {parts:?} in {notes:?}"
    );
}

#[test]
fn first_line_is_not_blank_and_long_keys_stay_aligned() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.json"), dir.path().join("b.json"));
    let mut r = sample();
    r.rejection[1].case = "a_case_with_a_very_long_name_indeed".into();
    r.rejection[1].cull = "discriminant_f64".into();
    r.save(&a).unwrap();
    r.save(&b).unwrap();
    let (code, out, _) = compare_cli(&[arg(&a), arg(&b)]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.lines().next().is_some_and(|l| !l.trim().is_empty()),
        "{out}"
    );
    let rejection: Vec<&str> = out
        .lines()
        .skip_while(|l| !l.starts_with("rejection"))
        .take(3)
        .collect();
    // The `change` column ends at the same place on every line of the section.
    let ends: Vec<usize> = rejection
        .iter()
        .map(|l| {
            l.find("  flags")
                .or_else(|| l.rfind('%').map(|i| i + 1))
                .or_else(|| l.rfind('-').map(|i| i + 1))
                .unwrap()
        })
        .collect();
    assert!(ends.windows(2).all(|w| w[0] == w[1]), "{rejection:#?}");
}

/// Issue 29: two check files compare class by class; more missed hits of ours is a
/// regression; a check file against a results file is refused, naming both tools.
#[test]
fn check_files_compare_and_mixed_kinds_are_refused() {
    use torus_cull_lab::check::record::{AnswerRecord, ChartAxes, CheckFile, ClassRecord};
    let answer = |who: &str, ours: bool, missed: u64| {
        let mut a = AnswerRecord::new(who, ours, &["far", "missed", "spurious"]);
        a.wrong.insert("missed".into(), missed);
        a.counts.insert("escalated".into(), 1);
        a.counts.insert("hits_answered".into(), 50);
        a
    };
    let family = |missed: u64| ClassRecord {
        label: "hole 2".into(),
        rays: 100,
        answers: vec![
            answer("cert", true, missed),
            answer("f32", true, missed),
            answer("peer", false, 3),
        ],
        ..ClassRecord::default()
    };
    let file = |classes| CheckFile {
        schema_version: torus_cull_lab::check::record::SCHEMA_VERSION,
        meta: sample().meta,
        shape: "ring".into(),
        precision: "f32".into(),
        rays_per_class: 100,
        seed: 1,
        oracle: "oracle".into(),
        constants: Default::default(),
        chart: ChartAxes {
            x: "nu".into(),
            x_title: "nu".into(),
            group_by: Vec::new(),
        },
        classes,
    };
    let mut good = file(vec![family(0)]);
    good.meta.tool = Some("check".into());
    let dir = tempfile::tempdir().unwrap();
    let (a, b, c) = (
        dir.path().join("a.json"),
        dir.path().join("b.json"),
        dir.path().join("c.json"),
    );
    let write = |path: &Path, f: &CheckFile| {
        write_atomic(path, serde_json::to_string(f).unwrap().as_bytes()).unwrap();
    };
    write(&a, &good);
    let mut bad = good.clone();
    bad.classes[0] = family(2);
    write(&b, &bad);
    let (code, out, err) = compare_cli(&[arg(&a), arg(&a)]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("hole 2 cert"), "{out}");
    let (code, out, _) = compare_cli(&[arg(&a), arg(&b)]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("REGRESSION: far/missed/spurious answers 0 -> 2"),
        "{out}"
    );
    sample().save(&c).unwrap();
    let (code, _, err) = compare_cli(&[arg(&a), arg(&c)]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("`check`") && err.contains("`run`"), "{err}");
}

/// Issue 29: a file with only `estimates` (`time gpu`, a filtered bench) is
/// plotted and compared by them (it was "nothing to plot" and "share no record"); an
/// adapter change is a machine change.
#[test]
fn estimate_only_files_are_plotted_and_compared() {
    use torus_cull_lab::results::EstimateRecord;
    let gpu = |ns: f64, device: &str| {
        let mut r = sample();
        r.rejection.clear();
        r.timing.clear();
        r.bvh.clear();
        r.meta.tool = Some("time".into());
        r.meta.device = Some(device.into());
        r.estimates = [2.0, 8.0]
            .iter()
            .flat_map(|nu| {
                ["none", "cychosz"].map(|cull| EstimateRecord {
                    benchmark: format!("gpu_ns-hole/{cull}/{nu}"),
                    elements: 1024,
                    ns_per_element: ns,
                    ns_per_element_ci: [ns * 0.99, ns * 1.01],
                })
            })
            .collect();
        r
    };
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.json"), dir.path().join("b.json"));
    gpu(2.0, "RTX").save(&a).unwrap();
    gpu(3.0, "RTX").save(&b).unwrap();
    let (a, b) = (arg(&a), arg(&b));
    let (code, out, _) = compare_cli(&[a, b]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("gpu_ns-hole/cychosz/2") && out.contains("4 regressions"),
        "{out}"
    );
    gpu(3.0, "lavapipe").save(Path::new(b)).unwrap();
    let (code, out, _) = compare_cli(&[a, b]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("meta.device: RTX vs lavapipe"), "{out}");
    assert_ok(&torus_cull(&["plot", a]));
    let svg = dir.path().join("a-estimates-gpu_ns-hole.svg");
    let text = std::fs::read_to_string(&svg).expect("an estimates chart");
    assert!(
        text.contains("cychosz") && text.contains("ns per element"),
        "{text}"
    );
}

/// `sample()` with one `total_ns` ratio record of skala against cychosz.
fn with_ratio(ratio: f64, ci: [f64; 2], between: Option<[f64; 2]>, runs: u64) -> Results {
    let mut r = sample();
    r.ratio = vec![RatioRecord {
        case: "hole".into(),
        nu: 8.0,
        cull: "skala".into(),
        reference: "cychosz".into(),
        metric: "total_ns".into(),
        ratio,
        ratio_ci: ci,
        rounds: 300,
        rounds_measured: 1200,
        rays: 1024,
        ns_per_ray: 10.0 * ratio,
        reference_ns_per_ray: 10.0,
        precision: "f64".into(),
        device: "cpu".into(),
        escalation_rate: None,
        runs,
        runs_set_aside: 0,
        run_ratios: if runs > 1 {
            vec![ratio; runs as usize]
        } else {
            Vec::new()
        },
        ratio_ci_between: between,
        run_spread: None,
    }];
    r
}

/// Issue 29: where both files have between-run intervals, `compare` judges by them. A
/// ratio 15 % slower whose within-run intervals are disjoint but whose between-run
/// intervals overlap is noise, not a regression; disjoint between-run intervals are one.
/// A file without them (one run, or from before `--runs`) falls back to the within-run
/// intervals, and the report says how many runs stood behind each side.
#[test]
fn between_run_intervals_decide_where_both_files_have_them() {
    let old = with_ratio(1.0, [0.99, 1.01], Some([0.90, 1.11]), 3);
    let new = with_ratio(1.15, [1.14, 1.16], Some([1.05, 1.26]), 3);
    let r = compare(&old, &new, 0.1);
    assert_eq!(r.regressions(), 0, "{r:?}");
    let row = r.rows.iter().find(|x| x.section == "ratio").unwrap();
    assert_eq!(row.flags, ["slower, intervals overlap (noise)"], "{row:?}");
    assert_note(
        &r.notes,
        &[
            "old file 3 runs, new file 3 runs",
            "by the between-run intervals",
        ],
    );

    // The same change with between-run intervals apart: a regression, saying which.
    let apart = with_ratio(1.15, [1.14, 1.16], Some([1.12, 1.18]), 3);
    let r = compare(&old, &apart, 0.1);
    assert_eq!(r.regressions(), 1, "{r:?}");
    let row = r.rows.iter().find(|x| x.section == "ratio").unwrap();
    assert!(
        row.flags[0].contains("between-run intervals disjoint (3 vs 3 runs)"),
        "{row:?}"
    );

    // An old file of one run: the within-run intervals decide, and the note says why.
    let single = with_ratio(1.0, [0.99, 1.01], None, 1);
    let r = compare(&single, &new, 0.1);
    assert_eq!(r.regressions(), 1, "{r:?}");
    assert_note(
        &r.notes,
        &[
            "old file 1 run, new file 3 runs",
            "the old file lacks between-run intervals",
        ],
    );

    // A record written before the fields existed reads as one run with no between-run
    // interval; a single-run record writes neither the run ratios nor the interval.
    let mut json = serde_json::to_value(&single.ratio[0]).unwrap();
    assert!(json.get("run_ratios").is_none() && json.get("ratio_ci_between").is_none());
    json.as_object_mut().unwrap().remove("runs");
    let back: RatioRecord = serde_json::from_value(json).unwrap();
    assert_eq!(back, single.ratio[0]);

    // Through the CLI: the note is printed.
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.json"), dir.path().join("b.json"));
    old.save(&a).unwrap();
    new.save(&b).unwrap();
    let (code, stdout) = cli_compare(&a, &b);
    assert_eq!(code, 0, "{stdout}");
    assert!(
        stdout.contains("old file 3 runs, new file 3 runs"),
        "{stdout}"
    );
}
