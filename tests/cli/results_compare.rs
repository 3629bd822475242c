//! Results JSON: schema round trip, version check, atomic write; `compare` flags and exit codes.

// Every check here runs against the harness's oracle or CLI.

use crate::support::{arg, assert_ok, read_json, stderr, stdout, temp_path, torus_cull};
use std::path::{Path, PathBuf};
use torus_cull_lab::compare::compare;
use torus_cull_lab::results::{
    BvhRecord, Meta, RatioRecord, RejectionRecord, Results, ResultsError, SCHEMA_VERSION,
    TimingRecord, write_atomic,
};

pub(crate) fn sample() -> Results {
    Results {
        schema_version: SCHEMA_VERSION,
        meta: Meta {
            commit: Some("abc1234".into()),
            dirty: false,
            created: "2026-11-21T12:00:00Z".into(),
            rustc: "rustc 1.95.0".into(),
            cpu: "test cpu".into(),
            workload: "quick".into(),
            workload_sha256: "00".repeat(32),
            seed: Some(7),
            torus_cull_version: Some("0.1.0".into()),
            tool: Some("run".into()),
            partial: false,
            preset: None,
            sizes: None,
            isa: None,
            cores: None,
            threads: None,
            os: None,
            device: None,
            summary_of: None,
            counts: None,
        },
        rejection: vec![
            RejectionRecord {
                case: "hole".into(),
                nu: 2.0,
                cull: "skala".into(),
                rays: 1000,
                hits: 0,
                misses: 1000,
                ambiguous: 0,
                rejected: 940,
                false_rejects: 0,
                rejection_rate: 0.94,
                miss_capture: Some(0.94),
            },
            RejectionRecord {
                case: "grazing".into(),
                nu: 2.0,
                cull: "none".into(),
                rays: 1000,
                hits: 1000,
                misses: 0,
                ambiguous: 0,
                rejected: 0,
                false_rejects: 0,
                rejection_rate: 0.0,
                miss_capture: None,
            },
        ],
        timing: vec![TimingRecord {
            case: "hole".into(),
            nu: 2.0,
            cull: "skala".into(),
            cull_ns: 6.0,
            total_ns: 20.0,
            total_ns_ci: [19.0, 21.0],
            speedup_vs_none: 5.0,
            ideal_total_ns: 6.0,
            solve_hit_ns: None,
            ideal_total_ns_at_hit_cost: None,
            source: "criterion".into(),
            mode: "scalar".into(),
            precision: "f64".into(),
            device: "cpu".into(),
            escalation_rate: None,
        }],
        bvh: vec![BvhRecord {
            scene: "facing_grid".into(),
            nu: 4.0,
            cull: "skala".into(),
            ray_set: "camera".into(),
            rays: 100,
            hits: 40,
            leaf_visits_per_ray: 2.0,
            cull_rejects_per_ray: 1.0,
            quartic_solves_per_ray: 1.0,
            mrays_per_s: 3.0,
            matches_brute_force: true,
        }],
        solver: Vec::new(),
        estimates: Vec::new(),
        ratio: Vec::new(),
        shapes: Vec::new(),
        counts: Vec::new(),
    }
}

#[test]
fn schema_round_trips_and_keeps_field_names() {
    let (_dir, path) = temp_path("r.json");
    let r = sample();
    r.save(&path).unwrap();
    assert_eq!(Results::load(&path).unwrap(), r);
    let text = std::fs::read_to_string(&path).unwrap();
    // Written compact: one line of JSON and its newline (issue 53: the committed files).
    assert_eq!(text.lines().count(), 1, "not compact: {text}");
    assert!(text.ends_with("}\n"), "no final newline");
    for field in [
        "\"schema_version\":1",
        "\"commit\"",
        "\"dirty\"",
        "\"created\"",
        "\"rustc\"",
        "\"cpu\"",
        "\"workload\"",
        "\"workload_sha256\"",
        "\"rejection_rate\"",
        "\"miss_capture\":null",
        "\"false_rejects\"",
        "\"total_ns_ci\"",
        "\"speedup_vs_none\"",
        "\"ideal_total_ns\"",
        "\"leaf_visits_per_ray\"",
        "\"matches_brute_force\"",
    ] {
        assert!(text.contains(field), "missing {field}");
    }
}

/// `precision`, `device` and `escalation_rate` (issue 19): written on every timing and
/// ratio record (`escalation_rate` only on f32 ones) and read back; a record without them
/// reads as f64 on the CPU with no escalation rate, so files from before them load.
#[test]
fn precision_device_and_escalation_round_trip_and_default_when_absent() {
    let mut r = sample();
    let f64_timing = r.timing[0].clone();
    r.timing.push(TimingRecord {
        mode: "batch".into(),
        precision: "f32".into(),
        escalation_rate: Some(2.5e-4),
        ..f64_timing.clone()
    });
    let ratio = RatioRecord {
        case: "uniform".into(),
        nu: 4.0,
        cull: "skala".into(),
        reference: "cychosz".into(),
        metric: "batch_total_ns".into(),
        ratio: 0.85,
        ratio_ci: [0.84, 0.86],
        rounds: 100,
        rounds_measured: 400,
        rays: 1024,
        ns_per_ray: 20.0,
        reference_ns_per_ray: 23.5,
        precision: "f64".into(),
        device: "cpu".into(),
        ..RatioRecord::default()
    };
    r.ratio = vec![
        ratio.clone(),
        RatioRecord {
            reference: "f64".into(),
            metric: "batch_f32_total_ns".into(),
            precision: "f32".into(),
            escalation_rate: Some(2.5e-4),
            ..ratio.clone()
        },
    ];
    let (dir, path) = temp_path("r.json");
    r.save(&path).unwrap();
    assert_eq!(Results::load(&path).unwrap(), r);
    let value = read_json(&path);
    for section in ["timing", "ratio"] {
        let records = value[section].as_array().unwrap();
        assert_eq!(records[0]["precision"], "f64", "{section}");
        assert_eq!(records[0]["device"], "cpu", "{section}");
        assert!(records[0].get("escalation_rate").is_none(), "{section}");
        assert_eq!(records[1]["precision"], "f32", "{section}");
        assert_eq!(records[1]["escalation_rate"], 2.5e-4, "{section}");
    }

    // Without the fields (as files written before them): f64, cpu, no rate.
    let mut old = value.clone();
    for section in ["timing", "ratio"] {
        for record in old[section].as_array_mut().unwrap() {
            let record = record.as_object_mut().unwrap();
            for field in ["precision", "device", "escalation_rate"] {
                record.remove(field);
            }
        }
    }
    let old_path = dir.path().join("old.json");
    std::fs::write(&old_path, serde_json::to_string_pretty(&old).unwrap()).unwrap();
    let loaded = Results::load(&old_path).unwrap();
    let batch_f64 = TimingRecord {
        mode: "batch".into(),
        ..f64_timing.clone()
    };
    assert_eq!(loaded.timing, vec![f64_timing, batch_f64]);
    assert_eq!(
        loaded.ratio[1],
        RatioRecord {
            reference: "f64".into(),
            metric: "batch_f32_total_ns".into(),
            ..ratio.clone()
        }
    );
    assert!(
        loaded
            .ratio
            .iter()
            .all(|x| x.precision == "f64" && x.device == "cpu" && x.escalation_rate.is_none())
    );
}

/// The committed `time` and bench files, written before `precision` existed, load as f64
/// CPU records and still compare with each other (issue 19 keeps the schema backward
/// compatible).
#[test]
fn committed_results_from_before_precision_load_and_compare() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("results");
    for name in ["230696a-time.json", "1ac18eb-time.json", "1ac18eb.json"] {
        let r = Results::load(&root.join(name)).unwrap();
        assert!(!r.ratio.is_empty(), "{name}");
        assert!(
            r.ratio
                .iter()
                .all(|x| x.precision == "f64" && x.device == "cpu" && x.escalation_rate.is_none()),
            "{name}"
        );
        assert!(
            r.timing
                .iter()
                .all(|x| x.precision == "f64" && x.device == "cpu" && x.escalation_rate.is_none()),
            "{name}"
        );
    }
    let (code, out) = cli_compare(
        &root.join("230696a-time.json"),
        &root.join("1ac18eb-time.json"),
    );
    assert!(code == 0 || code == 1, "{out}");
    assert!(out.contains("skala/cychosz total_ns"), "{out}");
    assert!(!out.contains("[f32]"), "{out}");
}

#[test]
fn other_versions_and_non_json_are_refused() {
    let (dir, v2) = temp_path("v2.json");
    let text = serde_json::to_string(&sample())
        .unwrap()
        .replace("\"schema_version\":1", "\"schema_version\":2");
    std::fs::write(&v2, text).unwrap();
    let e = Results::load(&v2).unwrap_err();
    assert!(matches!(e, ResultsError::Version(..)));
    assert!(
        e.to_string().contains("v2.json") && e.to_string().contains("schema_version"),
        "{e}"
    );
    let junk = dir.path().join("junk.json");
    std::fs::write(&junk, "{ not json").unwrap();
    let e = Results::load(&junk).unwrap_err().to_string();
    assert!(
        e.contains("junk.json") && e.contains("not a torus-cull results file"),
        "{e}"
    );
}

#[test]
fn atomic_write_leaves_no_partial_file() {
    let (dir, path) = temp_path("r.json");
    write_atomic(&path, b"old contents").unwrap();
    // A write that fails at the rename (target is a non-empty directory) keeps nothing half-done.
    let blocked = dir.path().join("blocked");
    std::fs::create_dir_all(blocked.join("inside")).unwrap();
    assert!(write_atomic(&blocked, b"new").is_err());
    assert_eq!(std::fs::read(&path).unwrap(), b"old contents");
    write_atomic(&path, b"new contents").unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"new contents");
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
}

/// The sample with its first record's rejected count and miss capture changed.
fn with_capture(rejected: u64, capture: f64) -> Results {
    let mut r = sample();
    r.rejection[0].rejected = rejected;
    r.rejection[0].miss_capture = Some(capture);
    r
}

#[test]
fn compare_flags_regressions() {
    let old = sample();
    assert_eq!(compare(&old, &old, 0.1).regressions(), 0);

    let r = compare(&old, &with_capture(900, 0.9), 0.1);
    assert_eq!(r.regressions(), 1);
    assert!(
        r.rows[0]
            .flags
            .iter()
            .any(|f| f.contains("rejected 940->900"))
    );

    let mut false_reject = sample();
    false_reject.rejection[1].false_rejects = 1;
    false_reject.rejection[1].rejected = 1;
    assert_eq!(compare(&old, &false_reject, 0.1).regressions(), 1);

    // Better capture is flagged as a change but is no regression.
    let r = compare(&old, &with_capture(990, 0.99), 0.1);
    assert_eq!(r.regressions(), 0);
    assert!(!r.rows[0].flags.is_empty());

    // Slower by 50 % with overlapping intervals: noise. Disjoint: regression.
    let mut noisy = sample();
    noisy.timing[0].total_ns = 30.0;
    noisy.timing[0].total_ns_ci = [15.0, 45.0];
    assert_eq!(compare(&old, &noisy, 0.1).regressions(), 0);
    let mut slow = sample();
    slow.timing[0].total_ns = 30.0;
    slow.timing[0].total_ns_ci = [29.0, 31.0];
    assert_eq!(compare(&old, &slow, 0.1).regressions(), 1);
    // ... but not past a 60 % threshold.
    assert_eq!(compare(&old, &slow, 0.6).regressions(), 0);

    let mut bvh = sample();
    bvh.bvh[0].matches_brute_force = false;
    assert_eq!(compare(&old, &bvh, 0.1).regressions(), 1);
    let mut bvh = sample();
    bvh.bvh[0].hits = 41;
    assert_eq!(compare(&old, &bvh, 0.1).regressions(), 1);

    let mut fewer = sample();
    fewer.rejection.pop();
    let r = compare(&old, &fewer, 0.1);
    assert_eq!(r.only_old, vec!["rejection grazing 2 none".to_string()]);
    assert_eq!(r.regressions(), 0);
}

/// A new folder with the sample saved as `a.json`, and the path `b.json` beside it.
fn sample_and_b() -> (tempfile::TempDir, PathBuf, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.json"), dir.path().join("b.json"));
    sample().save(&a).unwrap();
    (dir, a, b)
}

/// `compare old new`: its exit code, and its standard output followed by its error.
fn cli_compare(old: &Path, new: &Path) -> (i32, String) {
    let (code, out, err) = compare_cli(&[arg(old), arg(new)]);
    (code, out + &err)
}

#[test]
fn compare_exit_codes() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b, c) = (
        dir.path().join("a.json"),
        dir.path().join("b.json"),
        dir.path().join("c.json"),
    );
    sample().save(&a).unwrap();
    sample().save(&b).unwrap();
    let mut worse = sample();
    worse.rejection[0].miss_capture = Some(0.5);
    worse.rejection[0].rejected = 500;
    worse.save(&c).unwrap();
    let (code, text) = cli_compare(&a, &b);
    assert_eq!(code, 0, "{text}");
    assert!(text.contains("0 regressions"));
    let (code, text) = cli_compare(&a, &c);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("REGRESSION: lower miss capture"), "{text}");
    let junk = dir.path().join("junk.json");
    std::fs::write(&junk, "[]").unwrap();
    let (code, text) = cli_compare(&a, &junk);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("junk.json"), "{text}");

    // No record in common: a vacuous comparison is an error, not a pass.
    let disjoint = dir.path().join("disjoint.json");
    let mut other = sample();
    for r in &mut other.rejection {
        r.nu = 3.0;
    }
    other.timing[0].nu = 3.0;
    other.bvh[0].nu = 8.0;
    other.save(&disjoint).unwrap();
    let (code, text) = cli_compare(&a, &disjoint);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("share no record"), "{text}");

    // Another workload: refused, naming the field, and no regression verdict is given.
    let other_workload = dir.path().join("w.json");
    let mut w = worse_of(sample());
    w.meta.workload_sha256 = "11".repeat(32);
    w.save(&other_workload).unwrap();
    let (code, text) = cli_compare(&a, &other_workload);
    assert_eq!(code, 2, "{text}");
    assert!(
        text.contains("workloads differ") && text.contains("meta.workload_sha256"),
        "{text}"
    );
    assert!(!text.contains("REGRESSION"), "{text}");

    // The same workload at another size (a smoke sweep against a full one): refused too.
    let (full, smoke) = (dir.path().join("full.json"), dir.path().join("smoke.json"));
    let mut f = sample();
    f.meta.sizes = Some(torus_cull_lab::results::Sizes::rejection_only(100_000));
    f.save(&full).unwrap();
    let mut s = worse_of(sample());
    s.meta.sizes = Some(torus_cull_lab::results::Sizes::rejection_only(1_000));
    s.meta.preset = Some("smoke".into());
    s.save(&smoke).unwrap();
    let (code, text) = cli_compare(&full, &smoke);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("meta.sizes.rejection_rays"), "{text}");
}

fn worse_of(mut r: Results) -> Results {
    r.rejection[0].miss_capture = Some(0.5);
    r.rejection[0].rejected = 500;
    r
}

/// Issue 17: a BVH Mrays/s figure is one criterion median with no interval, so a change
/// (−18.5 % on unchanged code once) is shown as "no verdict", never a regression; a changed
/// hit count still is.
#[test]
fn bvh_throughput_without_an_interval_gets_no_verdict() {
    let old = sample();
    let mut slower = sample();
    slower.bvh[0].mrays_per_s = old.bvh[0].mrays_per_s * 0.815;
    let r = compare(&old, &slower, 0.1);
    assert_eq!(r.regressions(), 0, "{:?}", r.rows);
    let row = r.rows.iter().find(|r| r.section == "bvh").unwrap();
    assert!(
        row.flags
            .iter()
            .any(|f| f.contains("no verdict (no interval)")),
        "{row:?}"
    );
    slower.bvh[0].hits += 1;
    assert_eq!(compare(&old, &slower, 0.1).regressions(), 1);
}

/// Issue 17: a new file that lost records fails the comparison (exit 1, naming the flag
/// that only warns); with `--allow-missing` it passes with a warning. Records only in the
/// new file are fine.
#[test]
fn records_missing_from_the_new_file_fail_unless_allowed() {
    let (_dir, a, b) = sample_and_b();
    let mut fewer = sample();
    fewer.rejection.pop();
    fewer.bvh.clear();
    fewer.save(&b).unwrap();
    let (code, text) = cli_compare(&a, &b);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("2 records of")
            && text.contains("missing")
            && text.contains("--allow-missing"),
        "{text}"
    );
    let (code, _, err) = compare_cli(&[arg(&a), arg(&b), "--allow-missing"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("warning") && err.contains("missing"), "{err}");
    // The other way round (new records) is no failure.
    let (code, text) = cli_compare(&b, &a);
    assert_eq!(code, 0, "{text}");
}

/// `compare args…`: its exit code, standard output and standard error.
fn compare_cli(args: &[&str]) -> (i32, String, String) {
    let out = torus_cull(&[&["compare"], args].concat());
    (out.status.code().unwrap(), stdout(&out), stderr(&out))
}

/// Issue 29: a file with one record twice is refused (exit 2), naming the file and the
/// record, instead of one of the two being compared silently.
#[test]
fn duplicate_records_are_refused_naming_the_record() {
    let (_dir, a, b) = sample_and_b();
    let mut twice = sample();
    let mut copy = twice.rejection[0].clone();
    copy.rejected = 10;
    twice.rejection.push(copy);
    twice.save(&b).unwrap();
    let (code, out, err) = compare_cli(&[arg(&a), arg(&b)]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(
        err.contains(arg(&b))
            && err.contains("record `rejection hole 2 skala` appears more than once"),
        "{err}"
    );
    assert!(out.is_empty(), "{out}");
}

/// Issue 29: the miss capture is recomputed from the counts. A record whose counts fell
/// while its stored capture did not is a regression, and the stale value is named.
#[test]
fn miss_capture_is_recomputed_from_the_counts() {
    let old = sample();
    let mut stale = sample();
    stale.rejection[0].rejected = 900; // 0.90 by the counts, still 0.94 as stored
    let r = compare(&old, &stale, 0.1);
    assert_eq!(r.regressions(), 1, "{:?}", r.rows[0]);
    let row = &r.rows[0];
    assert!((row.new - 0.9).abs() < 1e-12, "{row:?}");
    assert!(
        row.flags
            .iter()
            .any(|f| f.contains("new: stored miss_capture 0.940000 disagrees with its counts")),
        "{row:?}"
    );
    // Counts unchanged, only the stored value edited: no regression, but it is said.
    let mut edited = sample();
    edited.rejection[0].miss_capture = Some(0.5);
    let r = compare(&old, &edited, 0.1);
    assert_eq!(r.regressions(), 0);
    assert!(r.rows[0].flags.iter().any(|f| f.contains("disagrees")));
}

/// Issue 29: files from different machines (here AVX-512 against AVX2, and two CPU models)
/// say so on the report's first line, in its summary and on stderr; a timing regression
/// between them is labelled not comparable and does not fail, unless `--across-machines`.
/// Rejection verdicts stay.
#[test]
fn different_machines_are_said_first_and_their_timings_decide_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("old.json"), dir.path().join("new.json"));
    let mut old = sample();
    old.meta.isa = Some("avx512".into());
    old.meta.cpu = "Intel Xeon Platinum 8480".into();
    old.save(&a).unwrap();
    let mut slow = sample();
    slow.meta.isa = Some("avx2".into());
    slow.meta.cpu = "AMD EPYC 7763".into();
    slow.timing[0].total_ns = 30.0;
    slow.timing[0].total_ns_ci = [29.0, 31.0];
    slow.save(&b).unwrap();
    let (a, b) = (arg(&a), arg(&b));
    let (code, out, err) = compare_cli(&[a, b]);
    assert_eq!(code, 0, "{out}{err}");
    let first = out.lines().next().unwrap();
    assert!(
        first.starts_with("WARNING: old and new were measured on different machines")
            && first.contains("meta.isa: avx512 vs avx2")
            && first.contains("AMD EPYC 7763"),
        "{first}"
    );
    assert!(
        out.contains("not comparable (different machines): +50.0% slower"),
        "{out}"
    );
    assert!(
        out.trim_end()
            .ends_with("different machines: 1 timing regressions not counted"),
        "{out}"
    );
    assert!(err.contains("different machines"), "{err}");
    let (code, out, _) = compare_cli(&[a, b, "--across-machines"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("REGRESSION: +50.0% slower, intervals disjoint (across machines)"));
    // A count regression is a regression on any machine.
    let mut worse = worse_of(sample());
    worse.meta.isa = Some("avx2".into());
    worse.save(Path::new(b)).unwrap();
    let (code, out, _) = compare_cli(&[a, b]);
    assert_eq!(code, 1, "{out}");
    // Same machine: no warning line.
    let (_, out, _) = compare_cli(&[a, a]);
    assert!(!out.contains("WARNING"), "{out}");
}

/// The comparison of other kinds of files (f32-check, estimate-only) and of between-run
/// intervals: in a module of its own, to keep each file short.
#[path = "results_compare/kinds_and_intervals.rs"]
mod kinds_and_intervals;
