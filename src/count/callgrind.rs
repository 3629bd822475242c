//! The parent side of the count channel: runs the worker under callgrind and reads the
//! dumps back (see [`super`] for the protocol).
//!
//! One valgrind process counts every region: `--dump-after` writes `cg.out.1`,
//! `cg.out.2`, … one per region in call order, each with a `totals:` line (the
//! instructions collected since the previous dump, and callgrind collects only inside a
//! region). The counts do not depend on the machine's load: callgrind counts the
//! instructions the guest executes, not time, and it runs the guest on one thread.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};

/// What a count run found: the dispatch level under valgrind, valgrind's version, the
/// worker's announcements (its stdout) and the dumps' totals in order.
#[derive(Debug, Clone)]
pub struct Dumps {
    /// `valgrind --version`.
    pub valgrind: String,
    /// The worker's stdout: the announcements.
    pub announced: String,
    /// Each dump's `totals:`, in dump order.
    pub totals: Vec<u64>,
}

/// The Debian (and Ubuntu) package that installs valgrind and callgrind.
pub const DEBIAN_PACKAGE: &str = "valgrind";

/// `valgrind --version`, or an error that names the package to install.
pub fn valgrind_version() -> Result<String, String> {
    let missing = |why: String| {
        format!(
            "valgrind is needed to count instructions ({why}): install the Debian/Ubuntu \
             package `{DEBIAN_PACKAGE}` (apt-get install {DEBIAN_PACKAGE}), which brings \
             callgrind"
        )
    };
    let out = Command::new("valgrind")
        .arg("--version")
        .output()
        .map_err(|e| missing(format!("`valgrind --version` did not run: {e}")))?;
    let version = String::from_utf8_lossy(&out.stdout).trim().to_string();
    if !out.status.success() || !version.starts_with("valgrind") {
        return Err(missing(format!(
            "`valgrind --version` said `{version}` with {}",
            out.status
        )));
    }
    Ok(version)
}

/// valgrind's full path, from `PATH` (the worker's environment is cleared).
fn which_valgrind() -> Result<std::path::PathBuf, String> {
    let path = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&path)
        .map(|d| d.join("valgrind"))
        .find(|p| p.is_file())
        .ok_or_else(|| "valgrind is on no directory of PATH".to_string())
}

/// Runs `exe count --worker PLAN` under callgrind, PLAN a file holding `plan_text`, collecting only inside the region function,
/// one dump per region. The worker's stderr (its progress) passes through; valgrind's own
/// messages go to a log whose tail an error quotes.
pub fn run(exe: &Path, plan_text: &str) -> Result<Dumps, String> {
    let valgrind = valgrind_version()?;
    let valgrind_path = which_valgrind()?;
    let dir = tempfile::tempdir().map_err(|e| format!("a temporary directory: {e}"))?;
    let out_file = dir.path().join("cg.out");
    let log = dir.path().join("valgrind.log");
    let pattern = super::region::REGION_PATTERN;
    // What the worker's process starts with must not vary from run to run: the sizes of
    // its environment, its path and its arguments place its stack and its first heap
    // blocks, and the SIMD code's copies take more or fewer instructions with their
    // alignment (an environment variable of 40 bytes more moved 9 of 26 wavefront
    // records by up to 0.02 %). So the worker gets an empty environment (but
    // `TORUS_CULL_ISA`), a path of fixed length (a link in the temporary directory), and
    // its plan in a file of that directory (one argument of fixed length).
    let worker = dir.path().join("worker");
    std::os::unix::fs::symlink(exe, &worker)
        .map_err(|e| format!("{}: linking the worker: {e}", worker.display()))?;
    let plan = dir.path().join("plan");
    std::fs::write(&plan, plan_text).map_err(|e| format!("{}: {e}", plan.display()))?;
    let mut command = Command::new(&valgrind_path);
    command.env_clear();
    if let Some(isa) = std::env::var_os("TORUS_CULL_ISA") {
        command.env("TORUS_CULL_ISA", isa);
    }
    let mut child = command
        .arg("--tool=callgrind")
        .arg("--collect-atstart=no")
        .arg(format!("--toggle-collect={pattern}"))
        .arg(format!("--dump-after={pattern}"))
        .arg(format!("--callgrind-out-file={}", out_file.display()))
        .arg(format!("--log-file={}", log.display()))
        .arg(&worker)
        .args(["count", "--worker"])
        .arg(&plan)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .map_err(|e| format!("valgrind did not start: {e}"))?;
    let mut announced = String::new();
    if let Some(mut stdout) = child.stdout.take() {
        stdout
            .read_to_string(&mut announced)
            .map_err(|e| format!("reading the count worker's output: {e}"))?;
    }
    let status = child
        .wait()
        .map_err(|e| format!("waiting for valgrind: {e}"))?;
    if !status.success() {
        let text = std::fs::read_to_string(&log).unwrap_or_default();
        let tail: Vec<&str> = text.lines().rev().take(12).collect();
        let tail: Vec<&str> = tail.into_iter().rev().collect();
        return Err(format!(
            "the count worker under callgrind failed ({status}); valgrind's log ends:\n{}",
            tail.join("\n")
        ));
    }
    let totals = read_dumps(dir.path(), "cg.out")?;
    Ok(Dumps {
        valgrind,
        announced,
        totals,
    })
}

/// The `totals:` of every numbered dump `<stem>.N` in `dir`, in order of N (the
/// program-termination dump `<stem>` itself, collected outside every region, is left
/// out).
pub fn read_dumps(dir: &Path, stem: &str) -> Result<Vec<u64>, String> {
    let mut numbered = Vec::new();
    let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for entry in entries {
        let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if let Some(n) = name
            .strip_prefix(stem)
            .and_then(|rest| rest.strip_prefix('.'))
            .and_then(|n| n.parse::<u64>().ok())
        {
            numbered.push((n, entry.path()));
        }
    }
    numbered.sort();
    numbered
        .iter()
        .map(|(_, path)| {
            let text =
                std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
            totals(&text).ok_or_else(|| format!("{}: no `totals:` line", path.display()))
        })
        .collect()
}

/// The instructions of one dump: its `totals:` line (the `summary:` line of older
/// callgrinds), the first event (Ir, the only one collected).
pub fn totals(dump: &str) -> Option<u64> {
    let line = dump
        .lines()
        .find(|l| l.starts_with("totals:"))
        .or_else(|| dump.lines().find(|l| l.starts_with("summary:")))?;
    line.split_once(':')?
        .1
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dump's total is its `totals:` line's first figure; the numbered dumps come in
    /// numeric order (10 after 9), the termination dump left out.
    #[test]
    fn dumps_are_read_in_order() {
        assert_eq!(totals("events: Ir\nsummary: 5\ntotals: 8012\n"), Some(8012));
        assert_eq!(totals("summary: 7\n"), Some(7));
        assert_eq!(totals("fn=x\n"), None);
        let dir = tempfile::tempdir().unwrap();
        for (name, n) in [
            ("cg.out", 0),
            ("cg.out.1", 1),
            ("cg.out.10", 10),
            ("cg.out.9", 9),
        ] {
            std::fs::write(dir.path().join(name), format!("totals: {n}\n")).unwrap();
        }
        assert_eq!(read_dumps(dir.path(), "cg.out").unwrap(), [1, 9, 10]);
    }
}
