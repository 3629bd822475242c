//! What the command's tests share: the binary, the repository root, running it there or
//! elsewhere, a small workload, and the checks every error test makes.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// The `torus-cull` binary cargo built for these tests.
pub const BIN: &str = env!("CARGO_BIN_EXE_torus-cull");
/// The repository root, where every test runs the binary.
pub const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Runs `torus-cull args…` in the repository root and waits for it.
pub fn torus_cull(args: &[&str]) -> Output {
    torus_cull_in(Path::new(ROOT), args)
}

/// Runs `torus-cull args…` in `cwd` (where a default `results/` would go) and waits for it.
pub fn torus_cull_in(cwd: &Path, args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("run torus-cull")
}

/// `torus-cull eval` of the rays in `rays` on the torus R = 2, r = 1, written to `out`.
pub fn eval_to(rays: &Path, out: &Path) -> Output {
    torus_cull(&[
        "eval",
        "--major",
        "2",
        "--minor",
        "1",
        "--rays",
        arg(rays),
        "--out",
        arg(out),
    ])
}

/// A path as an argument: the tests' temporary paths are UTF-8.
pub fn arg(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// The run's standard error, as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The run's standard output, as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Asserts that the run succeeded, showing its standard error where it did not.
pub fn assert_ok(o: &Output) {
    assert!(o.status.success(), "{}", stderr(o));
}

/// Asserts that the run exited 2 (refused its input) and returns its standard error.
pub fn refused(o: &Output) -> String {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    err
}

/// Writes `dir/name.json`, a workload of two cases at two ν with `rays` rays each (200: a
/// second to run, a few to time), and returns its path.
pub fn workload(dir: &Path, name: &str, rays: usize) -> PathBuf {
    let path = dir.join(format!("{name}.json"));
    std::fs::write(
        &path,
        format!(
            r#"{{ "name": "{name}", "seed": 3, "cases": ["hole", "uniform"], "nu": [2, 8],
                 "rays": {rays}, "pose": "random" }}"#
        ),
    )
    .unwrap();
    path
}

/// A new temporary folder holding the workload `tiny` of [`workload`] (200 rays), and the
/// workload's path; the folder lives as long as the caller keeps it.
pub fn tiny_workload() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = workload(dir.path(), "tiny", 200);
    (dir, path)
}

/// Exit 2, one line on stderr naming every needle, nothing on stdout, and fast (begun at
/// `started`): the work never started.
pub fn refused_at_once(o: &Output, started: Instant, needles: &[&str]) {
    let err = refused(o);
    for needle in needles {
        assert!(err.contains(needle), "no '{needle}' in: {err}");
    }
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(o.stdout.is_empty(), "the work ran: {}", stdout(o));
    assert!(
        started.elapsed() < Duration::from_secs(10),
        "it worked first"
    );
}

/// Runs `torus-cull` in the repository root with the arguments [`words`] makes of `line`
/// and `fill`, and waits for it.
pub fn cli(line: &str, fill: &[&str]) -> Output {
    torus_cull(&words(line, fill))
}

/// The words of a command line, split as a shell would split `line`, each `{}` replaced by
/// the next of `fill` whole (a path may hold spaces).
pub fn words<'a>(line: &'a str, fill: &[&'a str]) -> Vec<&'a str> {
    let mut fill = fill.iter();
    let words = line
        .split_whitespace()
        .map(|word| match word {
            "{}" => *fill
                .next()
                .unwrap_or_else(|| panic!("too few values for {line}")),
            _ => word,
        })
        .collect();
    assert!(fill.next().is_none(), "too many values for {line}");
    words
}
