//! `torus-cull time`: a short run writes a `ratio` section that loads and compares; a
//! worse ratio fails `compare`; bad arguments exit 2 naming the flag and what is allowed;
//! results files from before the `ratio` section still load.

// Every check here runs against the harness's oracle or CLI.

use crate::support::{arg, assert_ok, cli, cli_ok, refused, temp_path, tiny_workload, torus_cull};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::process::Output;
use std::time::{Duration, Instant};
use torus_cull_lab::results::Results;

/// `time` of the tiny workload with `options` into `a.json` in a new folder, which must
/// succeed: the folder (kept alive by the caller), that file and the run.
fn time_tiny(options: &str) -> (tempfile::TempDir, PathBuf, Output) {
    let (dir, workload) = tiny_workload();
    let a = dir.path().join("a.json");
    let line = format!("time --workload {{}} {options} --out {{}}");
    let o = cli_ok(&line, &[arg(&workload), arg(&a)]);
    (dir, a, o)
}

#[test]
fn a_short_run_writes_ratios_that_load_and_compare() {
    let (dir, a, o) = time_tiny("--seconds 1");
    let stdout = String::from_utf8_lossy(&o.stdout);
    for title in [
        "hole: total (cull + exact intersection) / cychosz, paired ratio [95% CI]",
        "uniform: cull alone / cychosz, paired ratio [95% CI]",
    ] {
        assert!(stdout.contains(title), "{stdout}");
    }

    let r = Results::load(&a).unwrap();
    assert_eq!(r.meta.tool.as_deref(), Some("time"));
    assert!(r.rejection.is_empty() && r.timing.is_empty());
    // Per case × ν: for the total, none and cychosz against each other and every other
    // cull against both; for the cull alone, every other cull against cychosz (`none`'s
    // cull alone is an empty loop, not timed).
    let others = torus_cull::CullKind::TIMED.len() - 2;
    assert_eq!(r.ratio.len(), 2 * 2 * ((1 + 1 + others * 2) + others));
    for x in &r.ratio {
        assert!(x.ratio.is_finite() && x.ratio > 0.0, "{x:?}");
        assert!(
            x.ratio_ci[0] <= x.ratio && x.ratio <= x.ratio_ci[1],
            "{x:?}"
        );
        assert!(x.rounds >= 5 && x.rounds <= x.rounds_measured, "{x:?}");
        assert_eq!(x.rays, 200, "the batch is the workload's 200 rays");
        assert!(x.ns_per_ray > 0.0 && x.reference_ns_per_ray > 0.0, "{x:?}");
        assert!(x.metric == "total_ns" || x.metric == "cull_ns");
        assert!(x.reference == "cychosz" || x.reference == "none");
        assert_ne!(x.cull, x.reference);
    }
    // The physics shows through any load: on hole rays skala skips the quartic for most
    // lines and cychosz for none (about 0.2 on an idle machine).
    let skala = r
        .ratio
        .iter()
        .find(|x| {
            (
                x.case.as_str(),
                x.nu,
                x.cull.as_str(),
                x.reference.as_str(),
                x.metric.as_str(),
            ) == ("hole", 8.0, "skala", "cychosz", "total_ns")
        })
        .unwrap();
    assert!(skala.ratio < 0.6, "{skala:?}");

    // A file against itself: every ratio row compared, nothing flagged.
    let o = torus_cull(&["compare", arg(&a), arg(&a)]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains("hole 8 skala/cychosz total_ns"), "{stdout}");
    assert!(stdout.contains("0 regressions"), "{stdout}");

    // The same file with skala's hole total 50 % worse and its interval moved along: a
    // regression, exit 1.
    let mut worse = r.clone();
    for x in worse.ratio.iter_mut().filter(|x| {
        x.case == "hole" && x.cull == "skala" && x.metric == "total_ns" && x.reference == "cychosz"
    }) {
        x.ratio *= 1.5;
        x.ratio_ci = [x.ratio_ci[1] * 1.4, x.ratio_ci[1] * 1.6];
        // The default is several runs: compare judges by the between-run interval (none
        // where all runs but one were set aside as slow: then by the within-run one).
        if let Some([_, hi]) = x.ratio_ci_between {
            x.ratio_ci_between = Some([hi * 1.4, hi * 1.6]);
        }
    }
    let b = dir.path().join("b.json");
    worse.save(&b).unwrap();
    let o = torus_cull(&["compare", arg(&a), arg(&b)]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains("2 regressions"), "{stdout}");
    assert!(
        stdout.contains("REGRESSION: +50.0% against cychosz"),
        "{stdout}"
    );
}

/// Issue 29: `--runs 2` times the workload in two worker processes and writes, for every
/// record, the within-run interval, the between-run interval over the two run ratios,
/// `runs = 2` and the run ratios themselves; the console says how many runs.
#[test]
fn runs_2_writes_both_intervals() {
    let (dir, workload) = tiny_workload();
    let a = dir.path().join("a.json");
    let o = cli_ok(
        "time --workload {} --seconds 1 --culls skala,aabb --runs 2 --no-plots --out {}",
        &[arg(&workload), arg(&a)],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("run 1 of 2") && err.contains("run 2 of 2"),
        "{err}"
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    // Two runs were made whether or not one was set aside as slow (issue 36: the count
    // used to vanish then, and this test failed by chance); the header says where.
    let header = stdout
        .lines()
        .find(|l| {
            l.starts_with(
                "hole: total (cull + exact intersection) / cychosz, paired ratio [95% CI]",
            )
        })
        .unwrap_or_else(|| panic!("no hole total table: {stdout}"));
    assert!(
        header.starts_with(
            "hole: total (cull + exact intersection) / cychosz, paired ratio [95% CI] between 2 runs"
        ),
        "{header}"
    );
    let r = Results::load(&a).unwrap();
    let hole_total = r
        .ratio
        .iter()
        .filter(|x| x.case == "hole" && x.metric == "total_ns" && x.reference == "cychosz");
    let mut aside: Vec<(f64, u64)> = hole_total
        .filter(|x| x.runs_set_aside > 0)
        .map(|x| (x.nu, x.runs_set_aside))
        .collect();
    aside.sort_by(|a, b| a.0.total_cmp(&b.0));
    aside.dedup();
    let aside: Vec<String> = aside
        .iter()
        .map(|(nu, n)| format!("{n} at ν = {nu}"))
        .collect();
    if aside.is_empty() {
        assert!(!header.contains("set aside"), "{header}");
    } else {
        assert!(
            header.ends_with(&format!(
                " (set aside as run in a slow state of the machine: {})",
                aside.join(", ")
            )),
            "{header}"
        );
    }
    // Per case × ν (2 × 2): skala and aabb against both references for the total, against
    // cychosz for the cull alone.
    assert_eq!(r.ratio.len(), 4 * (2 * 2 + 2));
    for x in &r.ratio {
        // A run in a slow state of the machine is set aside (paired::runs::SLOW_STATE).
        assert_eq!(x.runs + x.runs_set_aside, 2, "{x:?}");
        if let Some([blo, bhi]) = x.ratio_ci_between {
            let spread = x.run_spread.expect("a between-run interval has its spread");
            assert!(spread.log_sd.is_finite() && spread.log_sd >= 0.0, "{x:?}");
            assert!(blo <= x.ratio_ci[0] && x.ratio_ci[1] <= bhi, "{x:?}");
        }
        if x.runs == 1 {
            // One run kept: no run ratios; an interval only from the comparison's pool.
            assert!(x.run_ratios.is_empty(), "{x:?}");
            assert!(x.run_spread.is_none_or(|s| s.pooled), "{x:?}");
            assert!(
                x.ratio_ci[0] <= x.ratio && x.ratio <= x.ratio_ci[1],
                "{x:?}"
            );
            continue;
        }
        assert_eq!(x.run_ratios.len(), 2, "{x:?}");
        assert!(x.run_ratios.iter().all(|q| q.is_finite() && *q > 0.0));
        // The ratio is the geometric mean of the run ratios.
        let gm = (x.run_ratios[0] * x.run_ratios[1]).sqrt();
        assert!((x.ratio - gm).abs() <= 1e-12 * gm, "{x:?}");
        let [lo, hi] = x.ratio_ci;
        let [blo, bhi] = x
            .ratio_ci_between
            .expect("two runs: a between-run interval");
        assert!(lo <= x.ratio && x.ratio <= hi, "{x:?}");
        assert!(
            blo <= lo && hi <= bhi,
            "the between-run interval holds the within: {x:?}"
        );
        // Two runs: at least t(0.975, 1) = 12.706 times the half-difference of the logs
        // (the comparison's pooled spread may widen it).
        let half = 12.706 * (x.run_ratios[0] / x.run_ratios[1]).ln().abs() / 2.0;
        assert!(
            bhi.ln() >= x.ratio.ln() + half - 1e-9 && blo.ln() <= x.ratio.ln() - half + 1e-9,
            "{x:?}"
        );
        // Each run took its own rounds (40 at least per (case, ν)).
        assert!(x.rounds_measured >= 2 * 40, "{x:?}");
    }

    // Too many runs for the time, or none: exit 2 naming the option, nothing written.
    let b = dir.path().join("b.json");
    for (args, want) in [
        (
            ["--runs", "3", "--seconds", "0.5"],
            &["--seconds 0.5 is too short for --runs 3", "0.75"][..],
        ),
        (
            ["--runs", "0", "--seconds", "1"],
            &["--runs 0", "1 ..= 100"][..],
        ),
    ] {
        let mut all = vec!["time", "--workload", arg(&workload), "--out", arg(&b)];
        all.extend_from_slice(&args);
        let o = torus_cull(&all);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        for w in want {
            assert!(err.contains(w), "{args:?}: missing '{w}' in: {err}");
        }
        assert!(!b.exists());
    }
}

#[test]
fn bad_arguments_exit_2_naming_the_flag_and_the_allowed_values() {
    let (dir, workload) = tiny_workload();
    let out = dir.path().join("never.json");
    let out = arg(&out);
    let cases: [(&[&str], &[&str]); 9] = [
        (
            &["--culls", "bogus"],
            &["--culls", "'bogus' is not a timed cull", "skala"],
        ),
        (
            &["--culls", "skala,cychosz_printed"],
            &[
                "--culls",
                "cychosz_printed",
                "not conservative",
                "thick_cylinder",
            ],
        ),
        (&["--seconds", "0"], &["--seconds 0", "0 < seconds <= 3600"]),
        (&["--seconds=-1"], &["--seconds -1", "0 < seconds <= 3600"]),
        (
            &["--seconds", "NaN"],
            &["--seconds NaN", "0 < seconds <= 3600"],
        ),
        (
            &["--seconds", "1e9"],
            &["--seconds 1000000000", "0 < seconds <= 3600"],
        ),
        (&["--nu", "5"], &["--nu 5", "tiny.json", "allowed: 2, 8"]),
        (&["--batch", "5"], &["--batch 5", "16 ..= 200"]),
        (&["--batch", "201"], &["--batch 201", "16 ..= 200"]),
    ];
    for (args, want) in cases {
        let mut all = vec!["time", "--workload", arg(&workload), "--out", out];
        all.extend_from_slice(args);
        let o = torus_cull(&all);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        for w in want {
            assert!(err.contains(w), "{args:?}: missing '{w}' in: {err}");
        }
        assert!(!Path::new(out).exists());
    }
    let o = torus_cull(&["time", "--workload", "no/such/workload.json", "--out", out]);
    refused(&o);
    assert!(String::from_utf8_lossy(&o.stderr).contains("no/such/workload.json"));
}

/// An output that cannot be written is found before the measurement, not after it.
#[test]
fn an_unwritable_out_fails_before_measuring() {
    let (dir, workload) = tiny_workload();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "not a directory").unwrap();
    let out = file.join("r.json");
    let start = Instant::now();
    let o = cli(
        "time --workload {} --seconds 20 --out {}",
        &[arg(&workload), arg(&out)],
    );
    refused(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--out") && err.contains("r.json"), "{err}");
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "it measured first"
    );
}

/// Results files written before the `ratio` section existed load, with no ratios, and
/// round-trip.
#[test]
fn results_without_a_ratio_section_still_load() {
    let old = Path::new(env!("CARGO_MANIFEST_DIR")).join("results/a13357e.json");
    let text = std::fs::read_to_string(&old).unwrap();
    assert!(
        !text.contains("\"ratio\""),
        "the fixture must predate the section"
    );
    let r = Results::load(&old).unwrap();
    assert!(r.ratio.is_empty());
    assert!(!r.timing.is_empty() && !r.rejection.is_empty());
    let (_dir, copy) = temp_path("copy.json");
    r.save(&copy).unwrap();
    assert_eq!(Results::load(&copy).unwrap(), r);
}

/// `--mode both` adds the batch-mode ratios in the same rounds and records the
/// instruction set; `TORUS_CULL_ISA` picks it, and a bad value exits 2 naming it.
#[test]
fn mode_both_adds_batch_ratios_at_the_chosen_isa() {
    let (dir, workload) = tiny_workload();
    let a = dir.path().join("a.json");
    let run = |isa: &str, out: &Path| {
        Command::new(env!("CARGO_BIN_EXE_torus-cull"))
            .args([
                "time",
                "--workload",
                arg(&workload),
                "--seconds",
                "1",
                "--culls",
                "skala,discriminant_f64",
                "--mode",
                "both",
                "--out",
                arg(out),
            ])
            .env("TORUS_CULL_ISA", isa)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .expect("run torus-cull")
    };
    let o = run("scalar", &a);
    assert_ok(&o);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("hole: batch total (wavefront: SIMD cull + lane intersection) / none"),
        "{stdout}"
    );
    let r = Results::load(&a).unwrap();
    assert_eq!(r.meta.isa.as_deref(), Some("scalar"));
    let count = |metric: &str, cull: &str| {
        r.ratio
            .iter()
            .filter(|x| x.metric == metric && x.cull == cull)
            .count()
    };
    // Per case × ν (2 × 2), against both references; the cull alone against cychosz.
    for metric in ["total_ns", "batch_total_ns"] {
        assert_eq!(count(metric, "skala"), 8, "{metric}");
    }
    for metric in ["cull_ns", "batch_cull_ns"] {
        assert_eq!(count(metric, "skala"), 4, "{metric}");
    }
    // The f32 wavefront, certified and not: against both references and against skala's
    // own f64 wavefront (reference `f64`).
    for metric in ["batch_f32_total_ns", "batch_f32_uncertified_ns"] {
        assert_eq!(count(metric, "skala"), 12, "{metric}");
        assert_eq!(count(metric, "discriminant_f64"), 0, "{metric}");
    }
    // discriminant_f64 has no batch form: scalar ratios only.
    assert_eq!(count("total_ns", "discriminant_f64"), 8);
    assert_eq!(count("batch_total_ns", "discriminant_f64"), 0);

    let b = dir.path().join("b.json");
    let o = run("sse9", &b);
    refused(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("TORUS_CULL_ISA") && err.contains("sse9") && err.contains("avx2"),
        "{err}"
    );
    assert!(!b.exists());
}

/// Issue 19: `--mode both` times the certified f32 wavefront and the uncertified one
/// beside the f64 wavefront; its records say `"precision": "f32"` and carry the
/// escalation rate, the headline f32 / f64 ratio shows in the console, and `compare`
/// never pairs an f32 record with an f64 one.
#[test]
fn mode_both_times_the_f32_wavefront_with_escalation_rates() {
    let (dir, a, o) = time_tiny("--seconds 1 --culls none,discriminant --mode both");
    let stdout = String::from_utf8_lossy(&o.stdout);
    for title in [
        "uniform: batch f32 total (certified f32 wavefront) / the same cull's f64 wavefront, \
         paired ratio [95% CI]",
        "uniform: batch f32 total, uncertified (no proof) / cychosz",
        "uniform: certified f32 wavefront, rays escalated to f64 / rays",
    ] {
        assert!(stdout.contains(title), "missing '{title}' in: {stdout}");
    }

    let r = Results::load(&a).unwrap();
    let f32: Vec<_> = r.ratio.iter().filter(|x| x.precision == "f32").collect();
    // Per case × ν (2 × 2), both f32 metrics: none against cychosz and f64, discriminant
    // against cychosz, none and f64.
    assert_eq!(f32.len(), 4 * 2 * (2 + 3));
    for x in &f32 {
        assert!(x.metric.starts_with("batch_f32_"), "{x:?}");
        assert_eq!(x.device, "cpu");
        let e = x.escalation_rate.expect("every f32 record has its rate");
        assert!((0.0..=1.0).contains(&e), "{x:?}");
        assert!(x.ratio.is_finite() && x.ratio > 0.0, "{x:?}");
    }
    for x in r.ratio.iter().filter(|x| x.precision != "f32") {
        assert_eq!(x.precision, "f64", "{x:?}");
        assert!(
            !x.metric.contains("f32") && x.escalation_rate.is_none(),
            "{x:?}"
        );
    }
    // The headline: each cull's f32 wavefront against its own f64 wavefront, whose time
    // is the f64 record's in the same rounds.
    for case in ["hole", "uniform"] {
        for nu in [2.0, 8.0] {
            let find = |metric: &str, reference: &str| {
                r.ratio
                    .iter()
                    .find(|x| {
                        (x.case.as_str(), x.nu, x.cull.as_str(), x.metric.as_str())
                            == (case, nu, "discriminant", metric)
                            && x.reference == reference
                    })
                    .unwrap_or_else(|| panic!("{case} {nu} {metric}/{reference}"))
            };
            let headline = find("batch_f32_total_ns", "f64");
            assert_eq!(
                headline.reference_ns_per_ray,
                find("batch_total_ns", "none").ns_per_ray
            );
        }
    }
    // Hole rays are all misses that discriminant rejects: nothing reaches the f32 solve.
    assert!(
        r.ratio
            .iter()
            .filter(|x| x.case == "hole" && x.cull == "discriminant" && x.precision == "f32")
            .all(|x| x.escalation_rate.unwrap() < 0.01)
    );

    // compare: the f32 records pair with themselves under their own keys ...
    let o = torus_cull(&["compare", arg(&a), arg(&a)]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{stdout}");
    assert!(
        stdout.contains("uniform 8 discriminant/f64 batch_f32_total_ns [f32]"),
        "{stdout}"
    );
    // ... and never with an f64 record: relabelled f64, the same records match nothing.
    let mut as_f64 = r.clone();
    as_f64.ratio.retain(|x| x.precision == "f32");
    for x in &mut as_f64.ratio {
        x.precision = "f64".into();
        x.escalation_rate = None;
    }
    let mut only_f32 = r.clone();
    only_f32.ratio.retain(|x| x.precision == "f32");
    let (b, c) = (dir.path().join("b.json"), dir.path().join("c.json"));
    as_f64.save(&b).unwrap();
    only_f32.save(&c).unwrap();
    let o = torus_cull(&["compare", arg(&b), arg(&c), "--allow-missing"]);
    let text =
        String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
    // No record in common: a vacuous comparison, refused.
    assert_eq!(o.status.code(), Some(2), "{text}");
    assert!(text.contains("share no record"), "{text}");
}

/// `--secondary` times the bounces spawned from each batch's hits (issue 26's cost goal):
/// every record's case is `<case>_bounce`, the f32 wavefront is paired against the f64 one
/// on the same rays, and a case without hits (the hole) is skipped with a note.
#[test]
fn secondary_times_spawned_bounces_in_both_paths() {
    let (_dir, a) = temp_path("a.json");
    let o = cli(
        "time secondary --workload quick --nu 2 --seconds 1 --culls skala --mode both --no-plots --out {}",
        &[arg(&a)],
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(
        stderr.contains("rays of hole at nu = 2 hit the torus"),
        "{stderr}"
    );
    let r = Results::load(&a).unwrap();
    assert!(!r.ratio.is_empty());
    assert!(r.ratio.iter().all(|x| x.case.ends_with("_bounce")));
    assert!(!r.ratio.iter().any(|x| x.case == "hole_bounce"));
    let f32_vs_f64: Vec<_> = r
        .ratio
        .iter()
        .filter(|x| x.reference == "f64" && x.metric == "batch_f32_total_ns")
        .collect();
    // outer_band, grazing, uniform, camera at ν = 2.
    assert_eq!(f32_vs_f64.len(), 4, "{f32_vs_f64:?}");
    for x in f32_vs_f64 {
        let e = x.escalation_rate.expect("f32 records carry their rate");
        // Bounces leave into the outside: almost all are proved in f32.
        assert!(e < 0.05, "{x:?}");
        assert!(x.ratio.is_finite() && x.ratio > 0.0, "{x:?}");
    }
}

/// Issue 29: a worker process that dies fails the whole timing, naming the run and how it
/// ended, and no results file is written.
#[test]
#[cfg(target_os = "linux")]
fn a_dead_worker_fails_the_timing_and_writes_nothing() {
    let (dir, workload) = tiny_workload();
    let out = dir.path().join("a.json");
    let parent = Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args([
            "time",
            "--workload",
            arg(&workload),
            "--seconds",
            "20",
            "--runs",
            "2",
            "--no-plots",
            "--out",
            arg(&out),
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run torus-cull");
    // The first worker, as soon as it is started.
    let children = format!("/proc/{0}/task/{0}/children", parent.id());
    let start = Instant::now();
    let worker = loop {
        let text = std::fs::read_to_string(&children).unwrap_or_default();
        if let Some(pid) = text.split_whitespace().next() {
            break pid.to_string();
        }
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "no worker started"
        );
        std::thread::sleep(Duration::from_millis(20));
    };
    let killed = Command::new("kill").args(["-9", &worker]).status().unwrap();
    assert!(killed.success());
    let o = parent.wait_with_output().unwrap();
    let err = refused(&o);
    assert!(
        err.contains("worker run 1 of 2 failed") && err.contains("no results written"),
        "{err}"
    );
    assert!(
        start.elapsed() < Duration::from_secs(15),
        "it went on measuring"
    );
    assert!(!out.exists());
}

/// `--cases` keeps the workload's cases named and refuses any other, naming the allowed
/// ones.
#[test]
fn cases_are_the_workloads() {
    let (dir, workload) = tiny_workload();
    let stderr = refused(&torus_cull(&[
        "time",
        "--workload",
        arg(&workload),
        "--cases",
        "camera",
    ]));
    assert!(
        stderr.contains("--cases camera") && stderr.contains("allowed: hole, uniform"),
        "{stderr}"
    );
    let out = dir.path().join("a.json");
    cli_ok(
        "time --workload {} --cases uniform --culls cychosz --seconds 0.3 --runs 1 --no-plots --out {}",
        &[arg(&workload), arg(&out)],
    );
    let r = Results::load(&out).unwrap();
    assert!(!r.ratio.is_empty());
    assert!(r.ratio.iter().all(|x| x.case == "uniform"), "{:?}", r.ratio);
}

/// `gpu-info` in a binary without the feature says how to build one, exit 2.
#[test]
#[cfg(not(feature = "gpu"))]
fn gpu_info_needs_the_feature() {
    let o = torus_cull(&["gpu-info"]);
    refused(&o);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.contains("--features gpu"), "{stderr}");
}
