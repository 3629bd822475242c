//! `torus-cull count` (issue 58) at smoke size under valgrind: positive records, identical
//! from run to run, and `compare` judging a planted count change with its direction; its
//! refusals. Where valgrind is missing the count tests print SKIPPED, except under
//! `CI=true`, where they fail (CI installs the `valgrind` package).

use crate::common::under_ci;
use crate::support::{arg, refused, stdout, temp_path, torus_cull};
use std::process::Command;
use torus_cull_lab::results::Results;

/// Whether valgrind runs here; a loud SKIPPED line where it does not, a failure under CI.
fn have_valgrind() -> bool {
    let ok = Command::new("valgrind")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        assert!(
            !under_ci(),
            "valgrind is missing under CI=true: install the Debian package valgrind"
        );
        use std::io::Write;
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED: no valgrind (install the Debian package valgrind)"
        );
    }
    ok
}

/// The smoke plan: two cases at one ν, 16 rays, one cull besides the references.
const SMOKE: [&str; 10] = [
    "count",
    "--rays",
    "16",
    "--cases",
    "hole,uniform",
    "--nu",
    "2",
    "--culls",
    "skala",
    "--out",
];

#[test]
fn counts_repeat_exactly_and_compare_judges_a_planted_change() {
    if !have_valgrind() {
        return;
    }
    let (dir, a) = temp_path("a.json");
    let b = dir.path().join("b.json");
    for path in [&a, &b] {
        let mut args = SMOKE.to_vec();
        args.push(arg(path));
        let o = torus_cull(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(stdout(&o).contains("count records"), "{}", stdout(&o));
    }
    let (ra, rb) = (Results::load(&a).unwrap(), Results::load(&b).unwrap());
    let meta = ra.meta.counts.as_ref().expect("meta.counts");
    assert!(meta.valgrind.starts_with("valgrind-"), "{meta:?}");
    assert!(!meta.isa.is_empty() && meta.rays == 16, "{meta:?}");
    // Every region ran some instructions; ring records for each of the three culls.
    assert!(
        ra.counts
            .iter()
            .all(|r| r.instructions > 0 && r.per_ray > 0.0)
    );
    for cull in ["none", "cychosz", "skala"] {
        assert!(
            ra.counts
                .iter()
                .any(|r| r.cull == cull && r.metric == "total")
        );
    }
    let skala = |r: &Results| {
        r.counts
            .iter()
            .position(|c| c.cull == "skala" && c.metric == "cull")
            .unwrap()
    };
    assert!(ra.counts[skala(&ra)].ratio.is_some_and(|x| x > 0.0));
    assert_eq!(ra.counts, rb.counts, "two runs of one build differ");
    let o = torus_cull(&["compare", arg(&a), arg(&b)]);
    assert!(o.status.success(), "{}", stdout(&o));
    assert!(stdout(&o).contains(" 0 regressions"), "{}", stdout(&o));

    // Planted: one record 0.5 % more instructions, another 0.5 % fewer.
    let mut planted = rb.clone();
    let i = skala(&planted);
    planted.counts[i].per_ray *= 1.005;
    planted.counts[0].per_ray *= 0.995;
    planted.save(&b).unwrap();
    let o = torus_cull(&["compare", arg(&a), arg(&b), "--only-changes"]);
    let text = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(
        text.contains("REGRESSION: count +0.50% (more instructions)"),
        "{text}"
    );
    assert!(text.contains("count -0.50% (fewer instructions)"), "{text}");
    assert!(text.contains(" 1 regressions"), "{text}");
    // Above a 1 % threshold neither is a change.
    let o = torus_cull(&["compare", arg(&a), arg(&b), "--count-threshold", "1"]);
    assert!(o.status.success(), "{}", stdout(&o));
}

#[test]
fn bad_count_flags_are_refused_naming_the_flag() {
    let (_dir, out) = temp_path("x.json");
    let cases: [(&[&str], &str); 4] = [
        (
            &["--rays", "2"],
            "--rays 2 is invalid (allowed: 4 ..= 65536",
        ),
        (
            &["--culls", "bogus"],
            "--culls: 'bogus' is not a timed cull",
        ),
        (
            &["--paths", "gpu"],
            "--paths: 'gpu' is not a path (allowed: scalar, batch, solver, bvh, family, bend",
        ),
        (&["--nu", "3"], "--nu 3 is not in workload quick"),
    ];
    for (flags, needle) in cases {
        let mut args = vec!["count", "--out", arg(&out)];
        args.extend_from_slice(flags);
        let err = refused(&torus_cull(&args));
        assert!(err.contains(needle), "{flags:?}: {err}");
    }
    assert!(!out.exists());
    // A missing valgrind names the package to install.
    let empty = tempfile::tempdir().unwrap();
    let o = Command::new(crate::support::BIN)
        .args(["count", "--rays", "4", "--out", arg(&out)])
        .env("PATH", empty.path())
        .output()
        .unwrap();
    let err = refused(&o);
    assert!(err.contains("package `valgrind`"), "{err}");
    // Counts added to a file of another workload would pair with other rays' records.
    let bench = concat!(env!("CARGO_MANIFEST_DIR"), "/results/1ac18eb.json");
    let err = refused(&torus_cull(&["count", "--add-to", bench]));
    assert!(err.contains("is not --workload quick"), "{err}");
    let err = refused(&torus_cull(&[
        "compare",
        arg(&out),
        arg(&out),
        "--count-threshold",
        "-1",
    ]));
    assert!(err.contains("--count-threshold -1 is invalid"), "{err}");
}
