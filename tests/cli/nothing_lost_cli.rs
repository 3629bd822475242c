//! Issue 17's reproducers, each now a one-line error before any work or a correct answer:
//! outputs checked first (an existing directory, a missing parent, an input, a workload
//! name escaping `results/`), a closed pipe ends every command quietly after its files, ν
//! beyond the tested range and workloads whose generators cannot succeed are refused at
//! once, `time`'s default file carries the workload, and messages name the value typed,
//! the file and the option.

// Every check here runs against the harness's CLI.
#![cfg(unix)]

use crate::support::{
    BIN, ROOT, arg, assert_ok, cli, cli_ok, refused, refused_at_once, stderr, temp_path,
    tiny_workload, torus_cull, torus_cull_in, words, workload,
};
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::Instant;

#[test]
fn an_existing_directory_as_out_is_refused_before_the_work() {
    let (dir, workload) = tiny_workload();
    let target = dir.path().to_str().unwrap();
    for command in ["run", "time"] {
        let start = Instant::now();
        let o = torus_cull(&[command, "--workload", arg(&workload), "--out", target]);
        refused_at_once(&o, start, &["--out", target, "is a directory"]);
    }
}

#[test]
fn a_missing_parent_directory_is_an_error_not_created() {
    let (dir, workload) = tiny_workload();
    let out = dir.path().join("no").join("such").join("r.json");
    for command in ["run", "time"] {
        let start = Instant::now();
        let o = torus_cull(&[command, "--workload", arg(&workload), "--out", arg(&out)]);
        refused_at_once(&o, start, &["--out", "does not exist"]);
        assert!(
            !dir.path().join("no").exists(),
            "{command} made the directory"
        );
    }
    let rays = dir.path().join("rays.csv");
    std::fs::write(&rays, "ox,oy,oz,dx,dy,dz\n-5,0,0,1,0,0\n").unwrap();
    let o = cli(
        "eval --major 2 --minor 1 --rays {} --out {}",
        &[arg(&rays), arg(&out)],
    );
    refused(&o);
    assert!(stderr(&o).contains("--out"), "{}", stderr(&o));
    assert!(!dir.path().join("no").exists());
}

#[test]
fn an_output_that_is_an_input_is_refused_and_the_input_kept() {
    let (dir, rays) = temp_path("a.csv");
    let csv = "ox,oy,oz,dx,dy,dz\n-5,0,0,1,0,0\n";
    std::fs::write(&rays, csv).unwrap();
    // The same path, a symlink to it and a hard link to it are all the same file.
    let sym = dir.path().join("sym.csv");
    std::os::unix::fs::symlink(&rays, &sym).unwrap();
    let hard = dir.path().join("hard.csv");
    std::fs::hard_link(&rays, &hard).unwrap();
    for out in [&rays, &sym, &hard] {
        let o = cli(
            "eval --major 2 --minor 1 --rays {} --out {}",
            &[arg(&rays), arg(out)],
        );
        let err = refused(&o);
        assert!(
            err.contains("--out") && err.contains("--rays") && err.contains("same file"),
            "{err}"
        );
        assert_eq!(std::fs::read_to_string(&rays).unwrap(), csv);
    }

    let workload = workload(dir.path(), "tiny", 200);
    let text = std::fs::read_to_string(&workload).unwrap();
    for command in ["run", "time"] {
        let start = Instant::now();
        let o = cli(
            "{} --workload {} --out {}",
            &[command, arg(&workload), arg(&workload)],
        );
        refused_at_once(&o, start, &["--out", "--workload", "same file"]);
        assert_eq!(std::fs::read_to_string(&workload).unwrap(), text);
    }
}

#[test]
fn a_workload_name_that_escapes_results_is_refused_at_load() {
    let (dir, workload) = tiny_workload();
    let text = std::fs::read_to_string(&workload)
        .unwrap()
        .replace("\"tiny\"", "\"../../evil\"");
    std::fs::write(&workload, text).unwrap();
    for command in ["run", "time"] {
        let start = Instant::now();
        let o = torus_cull_in(dir.path(), &[command, "--workload", arg(&workload)]);
        refused_at_once(&o, start, &[arg(&workload), "field `name`", "../../evil"]);
    }
    assert!(!dir.path().join("results").exists());
}

#[test]
fn time_names_its_default_file_after_the_workload() {
    let (dir, cwd) = temp_path("cwd");
    std::fs::create_dir(&cwd).unwrap();
    for name in ["tiny", "small"] {
        let workload = workload(dir.path(), name, 200);
        let o = torus_cull_in(
            &cwd,
            &words(
                "time --workload {} --seconds 0.5 --no-plots",
                &[arg(&workload)],
            ),
        );
        assert_ok(&o);
    }
    // The tool's own results/ is made (one level) for a default name; both files are kept.
    let mut names: Vec<String> = std::fs::read_dir(cwd.join("results"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 2, "{names:?}");
    assert!(names[0].ends_with("-small-time.json"), "{names:?}");
    assert!(names[1].ends_with("-tiny-time.json"), "{names:?}");
}

/// Runs `args` with stdout a pipe whose reader has already gone.
fn with_closed_stdout(args: &[&str]) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(ROOT)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

#[test]
fn a_closed_pipe_ends_every_command_quietly_after_its_files() {
    let (dir, workload) = tiny_workload();
    let json = dir.path().join("r.json");
    let o = with_closed_stdout(&["run", "--workload", arg(&workload), "--out", arg(&json)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
    let svgs = |d: &Path| {
        std::fs::read_dir(d)
            .unwrap()
            .filter(|e| e.as_ref().unwrap().path().extension() == Some("svg".as_ref()))
            .count()
    };
    let written = svgs(dir.path());
    assert!(json.exists());
    // Every plot of the file: the same count as `plot` writes.
    let again = dir.path().join("again");
    std::fs::create_dir(&again).unwrap();
    let o = with_closed_stdout(&["plot", arg(&json), "--out-dir", arg(&again)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        written > 0 && written == svgs(&again),
        "{written} vs {}",
        svgs(&again)
    );

    // compare keeps its documented exit code (0: no regression).
    let o = with_closed_stdout(&["compare", arg(&json), arg(&json)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));

    let timed = dir.path().join("t.json");
    let o = with_closed_stdout(&words(
        "time --workload {} --seconds 0.5 --out {}",
        &[arg(&workload), arg(&timed)],
    ));
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(timed.exists());

    let png = dir.path().join("scene.png");
    let o = with_closed_stdout(&words(
        "render --scene chain --nu 4 --size 16 --tori 4 --out {}",
        &[arg(&png)],
    ));
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(png.exists() && dir.path().join("scene-cullmap.png").exists());
}

#[test]
fn nu_beyond_the_tested_range_is_a_one_line_error() {
    // The reproducer: R = 1, r = 3e-9 (nu = 3.3e8) once answered a hit for a miss.
    let (dir, rays) = temp_path("rays.csv");
    std::fs::write(&rays, "ox,oy,oz,dx,dy,dz\n-5,4.5e-9,0,1,0,0\n").unwrap();
    let o = cli("eval --major 1 --minor 3e-9 --rays {}", &[arg(&rays)]);
    let err = refused(&o);
    assert!(
        err.contains("--major/--minor") && err.contains("3.33") && err.contains("<= 1000"),
        "{err}"
    );
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        o.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let png = dir.path().join("thin.png");
    let o = cli("render --scene chain --nu 2000 --out {}", &[arg(&png)]);
    refused(&o);
    assert!(stderr(&o).contains("--nu") && stderr(&o).contains("1000"));
}

#[test]
fn a_workload_its_generators_cannot_fill_is_refused_at_load() {
    let (dir, workload) = temp_path("thin.json");
    std::fs::write(
        &workload,
        r#"{ "name": "thin", "seed": 1, "cases": ["hole"], "nu": [1.0000001],
             "rays": 20000 }"#,
    )
    .unwrap();
    let start = Instant::now();
    let o = cli(
        "run --workload {} --out {}",
        &[arg(&workload), arg(&dir.path().join("r.json"))],
    );
    refused_at_once(
        &o,
        start,
        &[arg(&workload), "field `nu[0]`", "1.0000001", "case hole"],
    );
}

#[test]
fn eval_messages_name_the_value_typed_and_the_option() {
    let (dir, rays) = temp_path("rays.csv");
    std::fs::write(&rays, "ox,oy,oz,dx,dy,dz\n-5,0,0,1,0,0\n").unwrap();
    let rays = arg(&rays);
    for (major, minor, needles) in [
        ("1e300", "1", vec!["--major", "1e300"]),
        ("1e-300", "1e-301", vec!["--major", "1e-300"]),
        ("2", "-1", vec!["minor_radius = -1"]),
        ("2", "-1e-300", vec!["--minor", "-1e-300"]),
    ] {
        let o = torus_cull(&["eval", "--major", major, "--minor", minor, "--rays", rays]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{major} {minor}: {err}");
        for n in needles {
            assert!(err.contains(n), "{major} {minor}: no '{n}' in {err}");
        }
        assert!(
            !err.contains("= inf") && !err.contains("= 0 ") && !err.contains("unexpected"),
            "{err}"
        );
    }
    // A tiny direction is not "zero", and the row says what was typed: 1e-20 is too short
    // for an f32 ray (|d|² underflows), 1e-170 for an f64 one (the default precision).
    for (precision, tiny_dx) in [("f32", "1e-20"), ("f64", "1e-170")] {
        let tiny = dir.path().join("tiny.csv");
        std::fs::write(&tiny, format!("ox,oy,oz,dx,dy,dz\n-5,0,0,{tiny_dx},0,0\n")).unwrap();
        let o = cli(
            "eval --major 2 --minor 1 --rays {} --precision {}",
            &[arg(&tiny), precision],
        );
        let err = refused(&o);
        assert!(
            err.contains(":2:") && err.contains(tiny_dx) && err.contains("too short"),
            "{err}"
        );
        assert!(!err.contains("is zero"), "{err}");
    }
    // A directory as --rays names the option and the path.
    let d = dir.path().to_str().unwrap();
    let o = torus_cull(&["eval", "--major", "2", "--minor", "1", "--rays", d]);
    let err = refused(&o);
    assert!(
        err.contains("--rays") && err.contains(d) && err.contains("is a directory"),
        "{err}"
    );
}

#[test]
fn time_lists_only_what_it_times_and_checks_the_isa_in_every_mode() {
    let o = torus_cull(&["time", "--culls", "bogus"]);
    let err = refused(&o);
    assert!(
        err.contains("'bogus'") && err.contains("discriminant_f64"),
        "{err}"
    );
    assert!(!err.contains("printed") && !err.contains("eq102"), "{err}");

    let (dir, workload) = tiny_workload();
    let start = Instant::now();
    let o = Command::new(BIN)
        .args([
            "time",
            "--workload",
            arg(&workload),
            "--seconds",
            "5",
            "--out",
            arg(&dir.path().join("t.json")),
        ])
        .env("TORUS_CULL_ISA", "avx3")
        .output()
        .unwrap();
    refused_at_once(&o, start, &["TORUS_CULL_ISA", "avx3"]);
}

#[test]
fn help_texts_state_the_real_defaults() {
    let run = String::from_utf8_lossy(&torus_cull(&["run", "--help"]).stdout).into_owned();
    assert!(run.contains("-run.json"), "{run}");
    let time = String::from_utf8_lossy(&torus_cull(&["time", "--help"]).stdout).into_owned();
    assert!(!time.contains("six") && time.contains("ten"), "{time}");
    assert!(time.contains("<workload>-time.json"), "{time}");
}

/// The command's stderr holds every one of `needles`.
fn says(o: &std::process::Output, needles: &[&str]) {
    let err = stderr(o);
    for needle in needles {
        assert!(err.contains(needle), "no {needle:?} in:\n{err}");
    }
}

/// With stderr not a terminal (a log, a CI job) `run` and `time` say what they are doing
/// as they go; their files record cores, threads and OS, and `time`'s its sizes; `plot`
/// draws a `time` file's paired ratios with their intervals, titled with the workload and
/// commit, and says so when a file has nothing to plot.
#[test]
fn progress_meta_and_plots_of_time_files() {
    let (dir, workload) = tiny_workload();
    let run_json = dir.path().join("r.json");
    let o = cli_ok(
        "run --workload {} --threads 2 --no-plots --out {}",
        &[arg(&workload), arg(&run_json)],
    );
    says(&o, &["run tiny", "800/800 rays (100%)"]);
    let r = torus_cull_lab::results::Results::load(&run_json).unwrap();
    assert_eq!(r.meta.threads, Some(2));
    assert!(r.meta.cores.is_some_and(|c| c >= 1));
    assert!(
        r.meta
            .os
            .as_deref()
            .is_some_and(|os| os.starts_with(std::env::consts::OS))
    );

    let time_json = dir.path().join("t.json");
    let o = cli_ok(
        "time --workload {} --seconds 0.5 --out {}",
        &[arg(&workload), arg(&time_json)],
    );
    says(&o, &["time tiny", "(100%)"]);
    let t = torus_cull_lab::results::Results::load(&time_json).unwrap();
    let sizes = t.meta.sizes.clone().expect("time records its sizes");
    assert_eq!(sizes.timing_rays, Some(200));
    assert_eq!(sizes.timed_nu, vec![2.0, 8.0]);
    assert_eq!(t.meta.threads, Some(1));
    // Issue 29: `time` draws its own plots, as the README says every command does.
    let svg = dir.path().join("t-ratio-hole-total_ns-vs-cychosz.svg");
    assert!(svg.is_file(), "time wrote no plot");
    assert!(
        String::from_utf8_lossy(&o.stdout).contains("plots to"),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    std::fs::remove_file(&svg).unwrap();

    let o = torus_cull(&["plot", arg(&time_json)]);
    assert_ok(&o);
    let svg = dir.path().join("t-ratio-hole-total_ns-vs-cychosz.svg");
    let text = std::fs::read_to_string(&svg).expect("a ratio chart");
    assert!(
        text.contains("paired ratio [95% CI]") && text.contains("tiny, "),
        "{svg:?}"
    );
    let charts = std::fs::read_dir(dir.path())
        .unwrap()
        .filter(|e| {
            let name = e.as_ref().unwrap().file_name();
            let name = name.to_string_lossy();
            name.starts_with("t-ratio-") && name.ends_with(".svg")
        })
        .count();
    // Per case: the total against both references, the cull alone against cychosz.
    assert_eq!(charts, 2 * 3);

    let empty = dir.path().join("empty.json");
    let mut e = t.clone();
    e.ratio.clear();
    e.save(&empty).unwrap();
    let o = torus_cull(&["plot", arg(&empty)]);
    refused(&o);
    assert!(stderr(&o).contains("nothing to plot"), "{}", stderr(&o));
}

/// Issue 29: `--major NaN`/`inf`/`-inf` are not finite (not "too small"); a CSV value
/// beyond f32 with f32 rays is out of f32 range (not "not finite"), with the range; huge
/// values are written in scientific notation, not as 300 digits.
#[test]
fn non_finite_radii_f32_range_and_huge_values_are_said_plainly() {
    let (dir, rays) = temp_path("rays.csv");
    std::fs::write(&rays, "ox,oy,oz,dx,dy,dz\n-5,0,0,1,0,0\n").unwrap();
    let rays = arg(&rays);
    for bad in ["NaN", "inf", "-inf"] {
        let o = torus_cull(&["eval", "--major", bad, "--minor", "1", "--rays", rays]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{bad}: {err}");
        assert!(
            err.contains("--major") && err.contains(&format!("{bad} is not a finite number")),
            "{bad}: {err}"
        );
        assert!(err.contains("3.4028235e38"), "{bad}: no range in {err}");
        assert!(!err.contains("too small"), "{bad}: {err}");
    }
    let big = dir.path().join("big.csv");
    std::fs::write(&big, "ox,oy,oz,dx,dy,dz\n1e39,0,0,-1,0,0\n").unwrap();
    let o = cli(
        "eval --major 3 --minor 1 --rays {} --precision f32",
        &[arg(&big)],
    );
    let err = refused(&o);
    assert!(
        err.contains("column ox: 1e39 is out of f32 range (allowed: |value| <= 3.4028235e38)"),
        "{err}"
    );
    assert!(!err.contains("not finite"), "{err}");
    // The same row in f64 is read, and its t_hit (about 1e39) is one short word.
    let o = torus_cull(&["eval", "--major", "3", "--minor", "1", "--rays", arg(&big)]);
    assert_ok(&o);
    let csv = String::from_utf8_lossy(&o.stdout).into_owned();
    let row = csv.lines().nth(1).unwrap();
    let t_hit = row.split(',').nth(3).unwrap();
    assert!(t_hit.contains('e') && t_hit.len() < 30, "{row}");
    assert!(
        (t_hit.parse::<f64>().unwrap() / 1e39 - 1.0).abs() < 1e-9,
        "{row}"
    );
    // `inf` typed in a CSV is still "not finite".
    std::fs::write(&big, "ox,oy,oz,dx,dy,dz\ninf,0,0,-1,0,0\n").unwrap();
    let o = torus_cull(&["eval", "--major", "3", "--minor", "1", "--rays", arg(&big)]);
    assert!(
        stderr(&o).contains("column ox: inf is not finite"),
        "{}",
        stderr(&o)
    );
    // ν typed as 1e300 is named as typed, not as 301 digits.
    for args in [
        &[
            "render", "--scene", "chain", "--nu", "1e300", "--out", "x.png",
        ][..],
        &["time", "--nu", "1e300"][..],
    ] {
        let o = torus_cull(args);
        let err = refused(&o);
        assert!(
            err.contains("1e300") && !err.contains("0000000000"),
            "{err}"
        );
    }
}

/// Issue 29: `--threads 0` is refused before any work, naming the option and the range.
#[test]
fn zero_threads_is_refused_with_the_range() {
    for command in [
        &["run", "--workload", "quick", "--no-plots"][..],
        &["f32-check"][..],
    ] {
        let started = Instant::now();
        let mut args = command.to_vec();
        args.extend(["--threads", "0", "--out", "/nonexistent-dir-h29/x.json"]);
        let o = torus_cull(&args);
        refused_at_once(
            &o,
            started,
            &["--threads 0 is invalid", "allowed: 1 ..= 1024"],
        );
    }
}

/// Issue 29: `time --mode both` with a cull that has no batch form says on stderr why its
/// batch tables are missing, instead of dropping them without a word.
#[test]
fn time_says_why_a_cull_has_no_batch_table() {
    let (dir, workload) = tiny_workload();
    let o = cli_ok(
        "time --workload {} --mode both --culls discriminant_f64 --seconds 0.3 --no-plots --out {}",
        &[arg(&workload), arg(&dir.path().join("t.json"))],
    );
    assert!(
        stderr(&o).contains(
            "discriminant_f64 has no batch form and is timed one ray at a time only, so no \
             batch table is printed"
        ),
        "{}",
        stderr(&o)
    );
    // --no-plots: the results file alone.
    let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(files.len(), 2, "{files:?}");
}
