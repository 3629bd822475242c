//! `torus-cull run`: a real sweep writes the results JSON and plots; a broken cull makes it
//! exit 1 and name the ray and seed; a bad workload exits 2 naming file and field.

// Every check here runs against the harness's oracle or CLI.

use crate::support::{arg, assert_ok, cli, cli_ok, refused, temp_path, torus_cull as run};
use std::process::Command;
use torus_cull_lab::results::Results;

#[test]
fn quick_workload_writes_results_and_plots() {
    let (dir, out) = temp_path("quick.json");
    let o = cli_ok("run --workload workloads/quick.json --out {}", &[arg(&out)]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("hole: miss capture") && stdout.contains("uniform: miss capture"));
    let r = Results::load(&out).unwrap();
    assert_eq!(r.meta.workload, "quick");
    assert_eq!(r.rejection.len(), 5 * 4 * torus_cull::CullKind::TIMED.len());
    assert!(r.rejection.iter().all(|x| x.false_rejects == 0));
    // The central claim is stated, with the number of rays behind it.
    let rays: u64 = r
        .rejection
        .iter()
        .filter(|x| x.cull == "none")
        .map(|x| x.rays)
        .sum();
    let culls = torus_cull::CullKind::TIMED.len();
    let claim = format!("0 false rejects in {rays} rays (each checked by {culls} culls");
    assert!(stdout.contains(&claim), "no '{claim}' in:\n{stdout}");
    // Hole rays are all misses: skala must capture most, cychosz none.
    let capture = |cull: &str| {
        r.rejection
            .iter()
            .find(|x| x.case == "hole" && x.nu == 8.0 && x.cull == cull)
            .and_then(|x| x.miss_capture)
            .unwrap()
    };
    assert_eq!(capture("cychosz"), 0.0);
    assert!(capture("skala") > 0.9);
    assert!(capture("discriminant") > 0.99 && capture("discriminant_f64") > 0.99);
    let svgs = std::fs::read_dir(dir.path())
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .is_some_and(|x| x == "svg")
        })
        .count();
    // The ring's 10; per b/a of the family (5) and per bore of the bends (3), 2 more.
    assert_eq!(svgs, 10 + 2 * (5 + 3));
    // Every member of the family and every bend has its records, with no false reject.
    assert_eq!(r.shapes.len(), 35 * culls + 12 * 2 * culls);
    assert!(r.shapes.iter().all(|x| x.counts.false_rejects == 0));
}

#[test]
fn a_broken_cull_fails_the_run_and_names_the_ray() {
    let (_dir, out) = temp_path("broken.json");
    let o = cli(
        "run --workload workloads/quick.json --out {} --no-plots --culls cychosz,cychosz_printed",
        &[arg(&out)],
    );
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("FALSE REJECT: cull cychosz_printed"), "{err}");
    assert!(
        err.contains("workload seed 7") && err.contains("stream seed 0x"),
        "{err}"
    );
    assert!(
        err.contains("ray #") && err.contains("origin") && err.contains("dir"),
        "{err}"
    );
    assert!(
        !err.contains("cull cychosz case"),
        "the real cychosz must not appear: {err}"
    );
    // The counts are still written, so the failure can be inspected.
    let r = Results::load(&out).unwrap();
    assert!(
        r.rejection
            .iter()
            .any(|x| x.cull == "cychosz_printed" && x.false_rejects > 0)
    );
}

#[test]
fn bad_inputs_exit_2_and_say_where() {
    let (_dir, bad) = temp_path("bad.json");
    std::fs::write(
        &bad,
        r#"{"name":"b","seed":1,"cases":["hole"],"nu":[0.8],"rays":10}"#,
    )
    .unwrap();
    let o = run(&["run", "--workload", arg(&bad)]);
    refused(&o);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("bad.json") && err.contains("field `nu[0]`") && err.contains("> 1"),
        "{err}"
    );

    let o = run(&["run", "--workload", "/no/such/workload.json"]);
    refused(&o);
    assert!(String::from_utf8_lossy(&o.stderr).contains("/no/such/workload.json"));

    let o = cli("run --workload workloads/quick.json --culls bogus", &[]);
    refused(&o);
    assert!(String::from_utf8_lossy(&o.stderr).contains("unknown cull 'bogus'"));

    let o = cli("render --scene facing_grid --nu 0.5 --out /tmp/x.png", &[]);
    refused(&o);
    assert!(String::from_utf8_lossy(&o.stderr).contains("--nu"));
}

/// `meta.commit` and the default file name describe the build, not the repository the
/// command runs in: run from inside another git repository, `run` still names the commit
/// it was built from.
#[test]
fn the_commit_is_the_builds_not_the_current_directorys() {
    let (built, _) = torus_cull_lab::results::git_state();
    let dir = tempfile::tempdir().unwrap();
    let git = |args: &[&str]| {
        let o = Command::new("git")
            .args(args)
            .current_dir(dir.path())
            .output()
            .expect("git");
        assert!(
            o.status.success(),
            "git {args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        String::from_utf8_lossy(&o.stdout).trim().to_string()
    };
    git(&["init", "-q"]);
    std::fs::write(dir.path().join("f"), "x").unwrap();
    git(&["add", "f"]);
    git(&[
        "-c",
        "user.name=t",
        "-c",
        "user.email=t@t.invalid",
        "commit",
        "-qm",
        "other",
    ]);
    let other = git(&["rev-parse", "--short", "HEAD"]);
    let workload = concat!(env!("CARGO_MANIFEST_DIR"), "/workloads/quick.json");
    let o = Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args(["run", "--no-plots", "--workload", workload])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_ok(&o);
    let written: Vec<String> = std::fs::read_dir(dir.path().join("results"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(written.len(), 1, "{written:?}");
    let name = &written[0];
    assert!(name.ends_with("-quick-run.json"), "{name}");
    assert!(
        !name.starts_with(&other),
        "named after the cwd's repository: {name}"
    );
    let r = Results::load(&dir.path().join("results").join(name)).unwrap();
    assert_eq!(r.meta.commit, built);
    assert_ne!(r.meta.commit.as_deref(), Some(other.as_str()));
    if let Some(c) = &built {
        assert!(
            name.starts_with(c.as_str()),
            "{name} is not named after {c}"
        );
    }
    // Built from a git checkout (as in CI), the build must have recorded its commit.
    if std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(".git")
        .exists()
    {
        assert!(built.is_some(), "build.rs recorded no commit");
    }
}

/// The installed command needs no clone: from a folder outside the repository the
/// built-in `quick` workload runs, and records the same workload (name and hash) as the
/// repository's file.
#[test]
fn a_built_in_workload_runs_from_any_folder() {
    let (dir, out) = temp_path("quick.json");
    let o = Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args(["run", "--workload", "quick", "--no-plots", "--out"])
        .arg(&out)
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_ok(&o);
    let r = Results::load(&out).unwrap();
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("workloads/quick.json");
    let want = torus_cull_lab::workload::spec::Workload::load(&file).unwrap();
    assert_eq!(r.meta.workload, "quick");
    assert_eq!(r.meta.workload_sha256, want.sha256);
}

/// Without `--workload`, `run` takes the built-in `default` workload, wherever it runs: an
/// unwritable `--out` is what stops it, not a missing `workloads/default.json`.
#[test]
fn the_default_workload_is_built_in() {
    let (dir, not_a_dir) = temp_path("file");
    std::fs::write(&not_a_dir, "").unwrap();
    let out = not_a_dir.join("results.json");
    let o = Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args(["run", "--out"])
        .arg(&out)
        .current_dir(dir.path())
        .output()
        .unwrap();
    let err = refused(&o);
    assert!(
        err.contains("--out") && !err.contains("cannot read"),
        "{err}"
    );
}
