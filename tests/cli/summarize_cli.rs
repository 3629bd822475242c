//! `torus-cull summarize` (issue 53): the summary of a full bench file holds the quoted
//! records of the full file and no others, `compare` reads it against the full file, and
//! bad input is refused naming the file.

use crate::support::{arg, assert_ok, refused, stdout, torus_cull};
use std::path::Path;
use torus_cull_lab::results::Results;

#[test]
fn a_bench_summary_keeps_quoted_records_and_compares_clean_against_its_full_file() {
    let full_path = Path::new(env!("CARGO_MANIFEST_DIR")).join("results/1ac18eb.json");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.json");
    let o = torus_cull(&["summarize", arg(&full_path), "--out", arg(&out)]);
    assert_ok(&o);
    assert!(stdout(&o).contains("ratio records"), "{}", stdout(&o));

    let (full, summary) = (
        Results::load(&full_path).unwrap(),
        Results::load(&out).unwrap(),
    );
    assert!(
        summary
            .meta
            .summary_of
            .as_deref()
            .unwrap()
            .ends_with("1ac18eb.json")
    );
    assert!(summary.estimates.is_empty() && !full.estimates.is_empty());
    assert!(!summary.ratio.is_empty() && summary.ratio.len() < full.ratio.len());
    assert!(summary.ratio.iter().all(|r| full.ratio.contains(r)));
    assert!(
        summary
            .ratio
            .iter()
            .all(|r| torus_cull_lab::summary::is_quoted(&r.metric, &r.reference))
    );
    assert_eq!(
        (
            &summary.rejection,
            &summary.timing,
            &summary.bvh,
            &summary.solver
        ),
        (&full.rejection, &full.timing, &full.bvh, &full.solver)
    );
    // Compact: one line.
    assert_eq!(std::fs::read_to_string(&out).unwrap().lines().count(), 1);

    // The full file against its summary: the full file summarized, nothing lost.
    let o = torus_cull(&["compare", arg(&full_path), arg(&out), "--only-changes"]);
    assert_ok(&o);
    let text = stdout(&o);
    assert!(text.contains("one file is a summary"), "{text}");
    assert!(
        text.contains("0 regressions, 0 only in old, 0 only in new"),
        "{text}"
    );
}

#[test]
fn summarize_refuses_check_files_and_its_own_input_as_output() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("results");
    let check = root.join("4be09a0-f32-check.json");
    let err = refused(&torus_cull(&["summarize", arg(&check)]));
    assert!(
        err.contains("4be09a0-f32-check.json") && err.contains("f32-check"),
        "{err}"
    );

    let dir = tempfile::tempdir().unwrap();
    let copy = dir.path().join("full.json");
    std::fs::copy(root.join("1ac18eb.json"), &copy).unwrap();
    let err = refused(&torus_cull(&["summarize", arg(&copy), "--out", arg(&copy)]));
    assert!(err.contains("--out"), "{err}");
    // Nothing was written over it.
    assert_eq!(
        std::fs::read(&copy).unwrap(),
        std::fs::read(root.join("1ac18eb.json")).unwrap()
    );
}
