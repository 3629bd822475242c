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

/// Asserts that the run succeeded, showing its standard output and error where it did not.
pub fn assert_ok(o: &Output) {
    assert!(o.status.success(), "{}{}", stdout(o), stderr(o));
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

/// A new temporary folder and the path `name` in it (nothing made there yet); the folder
/// lives as long as the caller keeps it.
pub fn temp_path(name: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    (dir, path)
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

/// [`cli`], asserting that the run succeeded.
pub fn cli_ok(line: &str, fill: &[&str]) -> Output {
    let o = cli(line, fill);
    assert_ok(&o);
    o
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

/// `compare` of the results file `old` with itself is clean (exit 0, records compared);
/// with `worse` (written to `dir/worse.json`), where a false reject was added and a capture
/// lowered, it is a regression (exit 1) that names both. Returns that report.
pub fn compare_clean_and_worse(old: &str, worse: &serde_json::Value, dir: &Path) -> String {
    let out = torus_cull(&["compare", old, old]);
    assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
    assert!(
        stdout(&out).contains("records compared"),
        "{}",
        stdout(&out)
    );
    let worse_path = dir.join("worse.json");
    std::fs::write(&worse_path, worse.to_string()).unwrap();
    let out = torus_cull(&["compare", old, arg(&worse_path)]);
    assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
    let report = stdout(&out);
    assert!(
        report.contains("REGRESSION: false rejects 0 -> 1"),
        "{report}"
    );
    assert!(report.contains("REGRESSION: lower capture"), "{report}");
    report
}

/// The names of the SVG files in `dir`, sorted.
pub fn svgs(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".svg"))
        .collect();
    names.sort();
    names
}

/// The JSON file at `path`, parsed.
pub fn read_json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `eval` rows of `csv` (written to a temp file) as columns, or the error text.
pub fn eval_rows(csv: &str, args: &[&str]) -> Result<Vec<Vec<String>>, String> {
    let (_dir, input) = temp_path("rays.csv");
    std::fs::write(&input, csv).unwrap();
    let mut all = vec!["eval", "--rays", arg(&input)];
    all.extend_from_slice(args);
    let out = torus_cull(&all);
    if !out.status.success() {
        return Err(stderr(&out));
    }
    Ok(String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect())
}

/// The culls whose columns the pinned `eval` outputs hold (`data/ring_rays.*.expected`,
/// `data/adversarial_rows.sha256`): the table's rows when they were blessed.
pub const PINNED_CULLS: [&str; 10] = [
    "none",
    "sphere",
    "aabb",
    "cychosz",
    "thick_cylinder",
    "skala",
    "ellipsoid",
    "quadric",
    "discriminant",
    "discriminant_f64",
];

/// `eval`'s stdout as the pins hold it: without the columns (`<cull>`, `wedge+<cull>`,
/// `gpu_<cull>`) of a cull added to the table after [`PINNED_CULLS`], so that a new row
/// leaves every pinned answer to be checked byte for byte (its own column is checked
/// by the oracle's conservativeness tests, which take every cull of the table). With no
/// newer cull, the text itself.
pub fn pinned_columns(out: &[u8]) -> Vec<u8> {
    use torus_cull::{CullKind, Named};
    for cull in PINNED_CULLS {
        assert!(
            CullKind::TIMED.iter().any(|&c| c.name() == cull),
            "the pinned cull {cull} is no longer in the table: bless the pins again"
        );
    }
    let newer: Vec<&str> = CullKind::TIMED
        .iter()
        .map(|&c| c.name())
        .filter(|n| !PINNED_CULLS.contains(n))
        .collect();
    let text = String::from_utf8_lossy(out);
    let Some(header) = text.lines().next().filter(|_| !newer.is_empty()) else {
        return out.to_vec();
    };
    let keep: Vec<bool> = header
        .split(',')
        .map(|c| {
            let cull = c
                .strip_prefix("wedge+")
                .or_else(|| c.strip_prefix("gpu_"))
                .unwrap_or(c);
            !newer.contains(&cull)
        })
        .collect();
    let mut kept = String::new();
    for line in text.split_inclusive('\n') {
        let (body, end) = match line.strip_suffix('\n') {
            Some(body) => (body, "\n"),
            None => (line, ""),
        };
        let fields: Vec<&str> = body
            .split(',')
            .zip(keep.iter().chain(std::iter::repeat(&true)))
            .filter(|&(_, &k)| k)
            .map(|(f, _)| f)
            .collect();
        kept.push_str(&fields.join(","));
        kept.push_str(end);
    }
    kept.into_bytes()
}
