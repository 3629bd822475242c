//! `torus-cull time`'s subcommands (issue 57): each run once at a tiny size with every
//! flag it offers, its file read back to see that each flag took effect; a flag a
//! subcommand does not offer is refused (exit 2), never accepted and ignored; the old
//! mode flags name the new command.

use crate::support::{arg, cli, read_json, refused, tiny_workload, torus_cull};
use serde_json::Value;
use std::path::Path;
use std::time::{Duration, Instant};

/// Runs `line` (`{}` filled from `fill`), which must succeed within `most` seconds and
/// take at least `least` (its `--seconds`: a shorter run ignored the flag); returns the
/// file `out` as JSON and the run's stderr.
fn timed(line: &str, fill: &[&str], (least, most): (f64, f64), out: &Path) -> (Value, String) {
    let start = Instant::now();
    let o = cli(line, fill);
    let took = start.elapsed();
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(o.status.success(), "{line}: {stderr}");
    assert!(
        took >= Duration::from_secs_f64(least) && took <= Duration::from_secs_f64(most),
        "{line}: took {took:?}, not {least} ..= {most} s"
    );
    (read_json(out), stderr)
}

/// The ratio records of a results file.
fn records(file: &Value) -> &Vec<Value> {
    file["ratio"].as_array().expect("a ratio section")
}

/// The SVG plots next to `out` (named after its stem).
fn plots(out: &Path) -> usize {
    let stem = out.file_stem().unwrap().to_str().unwrap().to_string();
    std::fs::read_dir(out.parent().unwrap())
        .unwrap()
        .filter_map(Result::ok)
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            name.starts_with(&format!("{stem}-")) && name.ends_with(".svg")
        })
        .count()
}

/// The runs a record's interval comes from, set aside ones included (`--runs`).
fn runs_made(r: &Value) -> u64 {
    r["runs"].as_u64().unwrap() + r["runs_set_aside"].as_u64().unwrap_or(0)
}

/// Every subcommand with each of its flags, at a tiny size, each flag's effect read from
/// the file it wrote.
#[test]
fn every_time_subcommand_honours_each_of_its_flags() {
    let (dir, workload) = tiny_workload();
    let w = arg(&workload);
    let path = |name: &str| dir.path().join(name);
    let culls_of = |file: &Value| -> std::collections::BTreeSet<String> {
        records(file)
            .iter()
            .map(|r| r["cull"].as_str().unwrap().to_string())
            .collect()
    };

    // ring: --culls, --nu, --cases, --batch, --mode both, --runs 2 (the workers'
    // --worker-run), --no-plots, --out, --workload, --seconds.
    let out = path("ring.json");
    let (file, stderr) = timed(
        "time ring --workload {} --culls skala --nu 2 --cases uniform --seconds 0.6 \
         --batch 64 --mode both --runs 2 --no-plots --out {}",
        &[w, arg(&out)],
        (0.6, 20.0),
        &out,
    );
    assert!(stderr.contains("run 2 of 2"), "{stderr}");
    assert_eq!(file["meta"]["workload"], "tiny");
    assert_eq!(file["meta"]["sizes"]["timing_rays"], 64);
    assert_eq!(plots(&out), 0, "--no-plots");
    let culls = culls_of(&file);
    assert!(
        culls.contains("skala")
            && culls
                .iter()
                .all(|c| ["skala", "none", "cychosz"].contains(&c.as_str())),
        "{culls:?}"
    );
    for r in records(&file) {
        assert_eq!(
            (r["case"].as_str(), r["nu"].as_f64()),
            (Some("uniform"), Some(2.0)),
            "{r}"
        );
        assert_eq!(r["rays"], 64, "{r}");
        assert_eq!(runs_made(r), 2, "{r}");
    }
    assert!(
        records(&file)
            .iter()
            .any(|r| r["metric"] == "batch_f32_total_ns"),
        "--mode both"
    );

    // secondary: the same flags, here --mode scalar, --runs 1, plots drawn.
    let out = path("secondary.json");
    let (file, _) = timed(
        "time secondary --workload {} --culls aabb --nu 8 --cases uniform --seconds 0.3 \
         --batch 128 --mode scalar --runs 1 --out {}",
        &[w, arg(&out)],
        (0.3, 20.0),
        &out,
    );
    assert!(plots(&out) > 0, "no plots drawn");
    assert!(culls_of(&file).contains("aabb"));
    for r in records(&file) {
        assert_eq!(
            (r["case"].as_str(), r["nu"].as_f64()),
            (Some("uniform_bounce"), Some(8.0)),
            "{r}"
        );
        // The bounces of 128 rays' hits: some, at most 128.
        assert!((16..=128).contains(&r["rays"].as_u64().unwrap()), "{r}");
        assert_eq!(runs_made(r), 1, "{r}");
        assert!(
            ["total_ns", "cull_ns"].contains(&r["metric"].as_str().unwrap()),
            "{r}"
        );
    }

    // family and bend: --runs, --batch, --seconds, --out, --no-plots (and plots drawn
    // without it), --workload (its name in the meta).
    let cull_count = torus_cull::CullKind::TIMED.len();
    for (name, runs, plotted, per_shape, shapes) in [
        ("family", 2, true, 2 + cull_count, 8),
        ("bend", 1, false, 4 * cull_count, 6),
    ] {
        let out = path(&format!("{name}.json"));
        let no_plots = if plotted { "" } else { "--no-plots" };
        let line = format!(
            "time {name} --workload {{}} --seconds 0.5 --batch 16 --runs {runs} {no_plots} --out {{}}"
        );
        let (file, stderr) = timed(&line, &[w, arg(&out)], (0.5, 20.0), &out);
        // Progress: the start and the end at least.
        assert!(
            stderr.contains(&format!("time {name}: 0/{shapes} shapes")),
            "{stderr}"
        );
        assert_eq!(file["meta"]["tool"], format!("time-{name}"));
        assert_eq!(file["meta"]["workload"], "tiny");
        assert_eq!(plots(&out) > 0, plotted, "{name}");
        assert_eq!(records(&file).len(), shapes * per_shape, "{name}");
        for r in records(&file) {
            assert_eq!(r["rays"], 16, "{name}: {r}");
            assert_eq!(r["runs"], runs, "{name}: {r}");
            assert_eq!(r["ratio_ci_between"].is_array(), runs > 1, "{name}: {r}");
            let ratio = r["ratio"].as_f64().unwrap();
            assert!(ratio.is_finite() && ratio > 0.0, "{name}: {r}");
        }
        // compare reads it and judges it clean against itself.
        let o = torus_cull(&["compare", arg(&out), arg(&out)]);
        assert_eq!(o.status.code(), Some(0), "{name}");
    }

    // bvh: --culls, --nu (any valid ν), --batch, --runs, plots, with the family's scene.
    let out = path("bvh.json");
    let (file, _) = timed(
        "time bvh --workload quick --culls skala --nu 3 --seconds 0.6 --runs 2 --batch 16 --out {}",
        &[arg(&out)],
        (0.6, 30.0),
        &out,
    );
    assert!(plots(&out) > 0, "no bvh plots");
    assert_eq!(file["meta"]["sizes"]["timing_rays"], 16);
    assert!(culls_of(&file).contains("skala"));
    for r in records(&file) {
        let nu = r["nu"].as_f64().unwrap();
        // The workload's scenes at --nu; the scenes it lacks (the family's, mixed ν,
        // dense) at ν = 4 whatever --nu says.
        let workloads =
            ["ring_field", "chain", "facing_grid"].contains(&r["case"].as_str().unwrap());
        assert_eq!(nu, if workloads { 3.0 } else { 4.0 }, "{r}");
        assert_eq!(runs_made(r), 2, "{r}");
    }
    assert!(records(&file).iter().any(|r| r["nu"] == 3.0));
    assert!(records(&file).iter().any(|r| r["case"] == "family"));
}

/// A flag that a subcommand does not read is not one of its flags: exit 2 naming it (no
/// timing starts); the old mode flags of a bare `time` name the command that replaced
/// them; a bare `time` is `time ring`.
#[test]
fn a_flag_a_subcommand_does_not_read_is_refused() {
    let (_dir, workload) = tiny_workload();
    let w = arg(&workload);
    for line in [
        "time family --culls skala",
        "time bend --nu 2",
        "time family --mode both",
        "time bend --cases uniform",
        "time family --bend",
        "time bvh --cases uniform",
        "time bvh --mode both",
        "time bvh --workgroup 32",
        "time ring --finish",
        "time secondary --workgroup 64",
        "time gpu --runs 2",
        "time gpu --mode both",
    ] {
        let (sub, flag) = line
            .rsplit_once(" --")
            .map(|(s, f)| (s, f.split(' ').next().unwrap()))
            .unwrap();
        let o = cli(&format!("{line} --workload {{}}"), &[w]);
        let err = refused(&o);
        assert!(err.contains(&format!("--{flag}")), "{sub}: {err}");
    }
    for (line, now) in [
        ("time --family", "time family"),
        ("time --bend --seconds 1", "time bend"),
        ("time --bvh", "time bvh"),
        ("time --secondary --mode both", "time secondary"),
        ("time --device gpu", "time gpu"),
        ("time --finish", "time gpu --finish"),
        ("time --workgroup 128", "time gpu --workgroup 128"),
    ] {
        let err = refused(&cli(line, &[]));
        assert!(err.contains(&format!("torus-cull {now}")), "{line}: {err}");
    }
    #[cfg(not(feature = "gpu"))]
    {
        let err = refused(&cli(
            "time gpu --workgroup 128 --finish --workload {}",
            &[w],
        ));
        assert!(err.contains("--features gpu"), "{err}");
    }
}
