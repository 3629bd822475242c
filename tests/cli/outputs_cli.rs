//! Every output behaves like a Unix tool's: symlinks are followed, FIFOs and devices are
//! written in place (and their errors reported), regular files are replaced atomically
//! with the umask's mode, an interrupted `eval --out` leaves no temp file, a closed pipe
//! ends `eval` quietly, and an unwritable `--out` fails before the work.

// Every check here runs against the harness's oracle or CLI.
#![cfg(unix)]

use crate::support::{
    BIN, arg, assert_ok, cli, eval_to, read_json, refused, svgs, temp_path, torus_cull, words,
};
use std::io::{Read, Write};
use std::os::unix::fs::{FileTypeExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const HEADER: &str = "ox,oy,oz,dx,dy,dz\n";

fn rays_csv(dir: &Path, rows: usize) -> PathBuf {
    let path = dir.join("rays.csv");
    let mut text = String::from(HEADER);
    for i in 0..rows {
        text.push_str(&format!("-5,{},0,1,0,0\n", (i % 100) as f32 * 0.01));
    }
    std::fs::write(&path, text).unwrap();
    path
}

/// Runs the quick workload without plots into `dir/q.json` and returns that file.
fn quick_results(dir: &Path) -> PathBuf {
    let json = dir.join("q.json");
    assert_ok(&cli(
        "run --workload workloads/quick.json --no-plots --out {}",
        &[arg(&json)],
    ));
    json
}

/// `render` of a small chain scene (two tori, 8 pixels) to `out`.
fn render_chain(out: &Path) -> Output {
    cli(
        "render --scene chain --nu 4 --size 8 --tori 2 --out {}",
        &[arg(out)],
    )
}

/// Runs `args` under `umask`, through the shell (the test process's umask is not touched).
fn with_umask(umask: &str, args: &[&str]) -> Output {
    let quoted: Vec<String> = args.iter().map(|a| format!("'{a}'")).collect();
    Command::new("sh")
        .arg("-c")
        .arg(format!(
            "umask {umask} && exec '{BIN}' {}",
            quoted.join(" ")
        ))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap()
}

fn mode(path: &Path) -> u32 {
    std::fs::metadata(path).unwrap().permissions().mode() & 0o777
}

fn temp_files(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".torus-cull-"))
        .collect()
}

#[test]
fn out_follows_symlinks_and_writes_fifos_and_devices_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let rays = rays_csv(dir.path(), 3);

    // A symlink: the file it names is written, the link stays a link.
    let real = dir.path().join("real.csv");
    let link = dir.path().join("link.csv");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let o = eval_to(&rays, &link);
    assert_ok(&o);
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(std::fs::read_to_string(&real).unwrap().lines().count(), 4);

    // A FIFO: its reader gets the CSV, and it is still a FIFO afterwards.
    let fifo = dir.path().join("fifo");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    let o = eval_to(&rays, &fifo);
    assert_ok(&o);
    assert_eq!(reader.join().unwrap().lines().count(), 4);
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );

    // The process's own stdout, through /proc/self/fd/1 (what /dev/stdout links to).
    let to_stdout = dir.path().join("stdout");
    std::os::unix::fs::symlink("/proc/self/fd/1", &to_stdout).unwrap();
    let o = eval_to(&rays, &to_stdout);
    assert_ok(&o);
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("index,oracle"));
    assert!(
        std::fs::symlink_metadata(&to_stdout)
            .unwrap()
            .file_type()
            .is_symlink()
    );

    // A full device: the write error is reported, naming the path, and the device stays.
    // (Through a link in the temp dir, so that a broken build can only break the link.)
    if Path::new("/dev/full").exists() {
        let full = dir.path().join("full");
        std::os::unix::fs::symlink("/dev/full", &full).unwrap();
        let big = rays_csv(dir.path(), 20_000);
        let o = eval_to(&big, &full);
        let err = refused(&o);
        assert!(err.contains("full") && err.contains("No space"), "{err}");
        assert!(
            std::fs::symlink_metadata(&full)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert!(
            std::fs::metadata("/dev/full")
                .unwrap()
                .file_type()
                .is_char_device()
        );
    }
    assert!(temp_files(dir.path()).is_empty());
}

#[test]
fn new_files_get_the_umask_mode() {
    let dir = tempfile::tempdir().unwrap();
    let rays = rays_csv(dir.path(), 3);
    for (umask, want) in [("022", 0o644), ("077", 0o600), ("002", 0o664)] {
        let out = dir.path().join(format!("eval-{umask}.csv"));
        let o = with_umask(
            umask,
            &words(
                "eval --major 2 --minor 1 --rays {} --out {}",
                &[arg(&rays), arg(&out)],
            ),
        );
        assert_ok(&o);
        assert_eq!(mode(&out), want, "eval --out under umask {umask}");
    }
    // The results JSON and its SVGs.
    let json = dir.path().join("q.json");
    let o = with_umask(
        "022",
        &words(
            "run --workload workloads/quick.json --out {}",
            &[arg(&json)],
        ),
    );
    assert_ok(&o);
    assert_eq!(mode(&json), 0o644);
    let svg = dir.path().join("q-hole-miss_capture.svg");
    assert_eq!(mode(&svg), 0o644);
}

/// Waits until `dir` holds a temp file of this crate (the output has been started).
fn wait_for_temp(dir: &Path) {
    let start = Instant::now();
    while temp_files(dir).is_empty() {
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "eval never started its output"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn an_interrupted_eval_leaves_no_temp_file() {
    for signal in ["TERM", "INT", "HUP"] {
        let (dir, out) = temp_path("out.csv");
        let mut child = Command::new(BIN)
            .args([
                "eval", "--major", "2", "--minor", "1", "--rays", "-", "--out",
            ])
            .arg(&out)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Some rows, then the input stays open: eval is mid-run when the signal comes.
        let mut stdin = child.stdin.take().unwrap();
        stdin.write_all(HEADER.as_bytes()).unwrap();
        for _ in 0..1000 {
            stdin.write_all(b"-5,0.5,0,1,0,0\n").unwrap();
        }
        stdin.flush().unwrap();
        wait_for_temp(dir.path());
        let killed = Command::new("kill")
            .arg(format!("-{signal}"))
            .arg(child.id().to_string())
            .status()
            .unwrap();
        assert!(killed.success());
        let mut stderr = child.stderr.take().unwrap();
        let status = child.wait().unwrap();
        drop(stdin);
        assert!(!status.success(), "SIG{signal}: {status:?}");
        // Issue 29: one line says what happened (an exit status alone said nothing).
        let mut err = String::new();
        stderr.read_to_string(&mut err).unwrap();
        assert!(
            err.contains(&format!("interrupted by SIG{signal}"))
                && err.contains("no partial output"),
            "SIG{signal}: {err}"
        );
        assert_eq!(temp_files(dir.path()), Vec::<String>::new(), "SIG{signal}");
        assert!(
            !out.exists(),
            "SIG{signal} left a partial {}",
            out.display()
        );
    }
}

#[test]
fn a_byte_order_mark_before_the_header_is_accepted() {
    let (_dir, rays) = temp_path("bom.csv");
    std::fs::write(&rays, format!("\u{feff}{HEADER}-5,0,0,2,0,0\n")).unwrap();
    let o = torus_cull(&["eval", "--major", "2", "--minor", "1", "--rays", arg(&rays)]);
    assert_ok(&o);
    assert!(String::from_utf8_lossy(&o.stdout).contains("0,hit,"));
}

#[test]
fn a_closed_pipe_ends_eval_quietly() {
    let dir = tempfile::tempdir().unwrap();
    // Far more output than a pipe buffers, so eval is still writing when the reader leaves.
    let rays = rays_csv(dir.path(), 50_000);
    let mut child = Command::new(BIN)
        .args(["eval", "--major", "2", "--minor", "1", "--rays"])
        .arg(&rays)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut head = [0u8; 100];
    stdout.read_exact(&mut head).unwrap();
    drop(stdout); // what `head` does after its lines
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(0), "{err}");
    assert!(err.is_empty(), "stderr: {err}");
}

#[test]
fn run_refuses_an_unwritable_out_before_the_sweep() {
    let (_dir, not_a_dir) = temp_path("file");
    std::fs::write(&not_a_dir, "").unwrap();
    let out = not_a_dir.join("results.json");
    let start = Instant::now();
    let o = cli(
        "run --workload workloads/default.json --out {}",
        &[arg(&out)],
    );
    let err = refused(&o);
    assert!(err.contains("--out") && err.contains(arg(&out)), "{err}");
    // No table means the sweep never ran (the default workload takes half a minute).
    assert!(
        o.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    assert!(start.elapsed() < Duration::from_secs(20));
}

#[test]
fn plots_are_replaced_atomically_and_errors_name_the_path() {
    let dir = tempfile::tempdir().unwrap();
    let json = quick_results(dir.path());

    // An old chart with a second hard link: a rename leaves the link's bytes alone,
    // writing in place (truncate, then draw) would change them.
    let svg = dir.path().join("q-hole-miss_capture.svg");
    std::fs::write(&svg, "old chart").unwrap();
    let kept = dir.path().join("kept.svg");
    std::fs::hard_link(&svg, &kept).unwrap();
    let o = torus_cull(&["plot", arg(&json)]);
    assert_ok(&o);
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    assert_eq!(std::fs::read_to_string(&kept).unwrap(), "old chart");
    assert!(temp_files(dir.path()).is_empty());

    // An output directory that cannot exist: the error names it.
    let blocked = dir.path().join("kept.svg").join("charts");
    let o = torus_cull(&["plot", arg(&json), "--out-dir", arg(&blocked)]);
    let err = refused(&o);
    assert!(err.contains(arg(&blocked)), "{err}");

    // A chart path that is a directory: the error names the chart.
    let dir_chart = dir.path().join("charts2");
    std::fs::create_dir_all(dir_chart.join("q-hole-miss_capture.svg")).unwrap();
    let o = torus_cull(&["plot", arg(&json), "--out-dir", arg(&dir_chart)]);
    let err = refused(&o);
    assert!(err.contains("q-hole-miss_capture.svg"), "{err}");
}

/// Issue 29: `plot --out-dir` treats its directory as every `--out` does (a missing one
/// is an error, not created); a file there is named as a file, not "File exists".
#[test]
fn plot_out_dir_must_be_an_existing_directory() {
    let dir = tempfile::tempdir().unwrap();
    let json = quick_results(dir.path());
    let missing = dir.path().join("no").join("such");
    let file = dir.path().join("a-file");
    std::fs::write(&file, "x").unwrap();
    for (out_dir, needle) in [
        (&missing, "no such directory (it is not created"),
        (&file, "is a file, not a directory"),
    ] {
        let o = torus_cull(&["plot", arg(&json), "--out-dir", arg(out_dir)]);
        let err = refused(&o);
        assert!(
            err.contains("--out-dir") && err.contains(arg(out_dir)) && err.contains(needle),
            "{err}"
        );
        assert!(!err.contains("os error 17"), "{err}");
    }
    assert!(!dir.path().join("no").exists(), "the directory was created");
}

/// Issue 29: `render --out x.svg` is refused before drawing (it wrote PNG bytes into it).
#[test]
fn render_refuses_a_name_that_is_not_png() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["x.svg", "x.jpg", "x"] {
        let out = dir.path().join(name);
        let o = render_chain(&out);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains("a file name ending in .png"), "{name}: {err}");
        assert!(!out.exists(), "{name} was written");
    }
    let out = dir.path().join("x.PNG");
    let o = render_chain(&out);
    assert_ok(&o);
    assert!(std::fs::read(&out).unwrap().starts_with(b"\x89PNG"));
}

/// Issue 29: `f32-check` (`check --shape ring --precision f32`) writes its plots, and its
/// file goes through `plot` and `compare` (both refused it: "missing field
/// `rejection`"); one ray per family keeps its ν as one value, not "3.145-3", and the f64
/// time has a line of its own beside the f32 path's.
#[test]
fn f32_check_files_are_plotted_and_compared() {
    let (dir, json) = temp_path("f.json");
    let o = cli("f32-check --rays 1 --rounds 1 --out {}", &[arg(&json)]);
    let table = String::from_utf8_lossy(&o.stdout).into_owned();
    assert_ok(&o);
    assert_eq!(
        svgs(dir.path()),
        [
            "f-escalation.svg",
            "f-ns_per_ray.svg",
            "f-t_error.svg",
            "f-wrong.svg"
        ]
    );
    let file = read_json(&json);
    let inner = file["classes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["label"] == "tangent_1e-6_inner_equator")
        .unwrap();
    assert_eq!(
        inner["params"]["nu_lo"], inner["params"]["nu_hi"],
        "{inner}"
    );
    // Each family's f32 line carries its time, and the f64 intersection a line of its own.
    let mut hole_edge = table.lines().skip_while(|l| !l.starts_with("hole_edge"));
    let lines: Vec<&str> = hole_edge.by_ref().take(4).collect();
    assert!(lines[1].trim_start().starts_with("f32"), "{lines:?}");
    assert!(!lines[1].trim_end().ends_with(" -"), "{lines:?}");
    assert!(
        lines[3].trim_start().starts_with("f64_intersect"),
        "{lines:?}"
    );
    let again = dir.path().join("again");
    std::fs::create_dir(&again).unwrap();
    let o = torus_cull(&["plot", arg(&json), "--out-dir", arg(&again)]);
    assert_ok(&o);
    assert_eq!(svgs(&again), svgs(dir.path()));
    let o = torus_cull(&["compare", arg(&json), arg(&json)]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_ok(&o);
    assert!(out.contains("0 regressions"), "{out}");
}
