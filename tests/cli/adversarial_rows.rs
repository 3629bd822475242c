//! Nothing lost, pinned: `eval` on the ≥ 50 000 adversarial rows of every member
//! (`data/adversarial_rows.py`: rings at three ν and scales, elliptical rings, horns,
//! spindles down to ν = 0.02, pipe bends) in `--exact f64`, `--precision f32` and
//! `--exact f32` gives the outputs whose SHA-256 and exit codes
//! `data/adversarial_rows.sha256` holds. Those were checked byte for byte against the
//! commit before the shape interface (7a4c61d) with `data/nothing_lost_compare.sh`; blessed
//! again when a bend's rows gained the `wedge` and `wedge+<cull>` columns (every other
//! column byte-identical, no wedge form rejecting an oracle hit) and when the refusal of
//! `--exact f32` for a non-circular member lost its "(shape Spindle" for a horn.
//! A cull added to the table after the pins adds columns the digests leave out
//! (`support::pinned_columns`). A change that moves an answer fails here; one that means to (a new solver's last
//! digits, say) compares the two binaries with that script first, then writes the new
//! digests with `TORUS_CULL_BLESS=1`.

use crate::support::{BIN, ROOT, pinned_columns};
use sha2::{Digest, Sha256};
use std::fmt::Write as _;
use std::process::Command;

const MODES: [&str; 3] = ["--exact f64", "--precision f32", "--exact f32"];

#[test]
fn eval_on_the_adversarial_rows_of_every_member_is_pinned() {
    let dir = tempfile::tempdir().unwrap();
    let rows = dir.path().join("rows");
    let made = Command::new("python3")
        .arg(format!("{ROOT}/tests/cli/data/adversarial_rows.py"))
        .arg(&rows)
        .output()
        .expect("python3 runs the generator");
    assert!(
        made.status.success(),
        "{}",
        String::from_utf8_lossy(&made.stderr)
    );
    let manifest = std::fs::read_to_string(rows.join("members.tsv")).unwrap();
    let (mut got, mut total) = (String::new(), 0usize);
    for line in manifest.lines() {
        let (name, flags) = line.split_once('\t').unwrap();
        let csv = rows.join(format!("{name}.csv"));
        total += std::fs::read_to_string(&csv).unwrap().lines().count() - 1;
        for mode in MODES {
            let o = Command::new(BIN)
                .arg("eval")
                .args(flags.split(' '))
                .args(mode.split(' '))
                .arg("--rays")
                .arg(&csv)
                .output()
                .unwrap();
            let mut h = Sha256::new();
            h.update(pinned_columns(&o.stdout));
            h.update(&o.stderr);
            let digest: String = h.finalize().iter().map(|b| format!("{b:02x}")).collect();
            let code = o.status.code().unwrap_or(-1);
            writeln!(got, "{name}\t{mode}\t{code}\t{digest}").unwrap();
        }
    }
    assert!(total >= 50_000, "only {total} rows");
    let path = format!("{ROOT}/tests/cli/data/adversarial_rows.sha256");
    if std::env::var_os("TORUS_CULL_BLESS").is_some() {
        std::fs::write(&path, &got).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap();
    let moved: Vec<_> = got
        .lines()
        .zip(want.lines())
        .filter(|(g, w)| g != w)
        .map(|(g, _)| g.split('\t').take(2).collect::<Vec<_>>().join(" "))
        .collect();
    assert!(
        moved.is_empty() && got.lines().count() == want.lines().count(),
        "eval's answers moved on {} of {} member × mode: {moved:?} (compare two binaries with \
         tests/cli/data/nothing_lost_compare.sh; bless with TORUS_CULL_BLESS=1)",
        moved.len(),
        got.lines().count()
    );
}
