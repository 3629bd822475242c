//! The torus family on the command line: `eval --axial` and horn/spindle tori, the
//! circular ring torus's rows unchanged (the family's check: check_cli.rs).

use super::support::{arg, eval_rows, stderr, torus_cull};
use std::path::Path;

#[test]
fn spindle_rows_cross_the_apple_only() {
    // R = 0.5, r = 1 (a spindle): the apple is (ρ − 0.5)² + y² = 1 with ρ ≥ 0; the lemon
    // (ρ + 0.5)² + y² = 1 bounds nothing.
    // Row 0: along x through the centre from x = −3: the apple at x = −1.5 (t = 1.5);
    // the lemon's x = −0.5 is no surface.
    // Row 1: down, parallel to the axis at ρ = 0.2: y = √(1 − 0.3²) = √0.91, t = 3 − √0.91.
    // Row 2: above the apple's top (y = 1 at ρ = 0.5): a miss.
    let csv = "ox,oy,oz,dx,dy,dz\n-3,0,0,1,0,0\n0.2,3,0,0,-1,0\n-3,1.2,0,1,0,0\n";
    for precision in ["f64", "f32"] {
        let rows = eval_rows(
            csv,
            &["--major", "0.5", "--minor", "1", "--precision", precision],
        )
        .unwrap();
        let t = |row: usize| rows[row][3].parse::<f64>().unwrap();
        let tol = if precision == "f64" { 1e-12 } else { 1e-6 };
        assert_eq!(rows[0][1], "hit");
        assert!((t(0) - 1.5).abs() < tol, "{precision}: {:?}", rows[0]);
        assert_eq!(rows[1][1], "hit");
        assert!(
            (t(1) - (3.0 - 0.91f64.sqrt())).abs() < tol,
            "{precision}: {:?}",
            rows[1]
        );
        assert_eq!(rows[2][1], "miss");
        assert_eq!(rows[2][3], "", "{precision}: {:?}", rows[2]);
        // Every cull keeps both hits.
        for row in &rows[..2] {
            assert!(row[4..].iter().all(|k| k == "1"), "{precision}: {row:?}");
        }
    }
    // An elliptical ring (R = 4, a = 1, b = 0.5), straight down onto the tube's top:
    // y = b, t = 3 − 0.5.
    let rows = eval_rows(
        "ox,oy,oz,dx,dy,dz\n4,3,0,0,-1,0\n",
        &["--major", "4", "--minor", "1", "--axial", "0.5"],
    )
    .unwrap();
    assert_eq!(rows[0][1], "hit");
    assert_eq!(rows[0][3], "2.5");
}

#[test]
fn bad_family_values_name_the_flag_and_the_range() {
    let csv = "ox,oy,oz,dx,dy,dz\n-3,0,0,1,0,0\n";
    for (args, expect) in [
        (
            &["--major", "4", "--minor", "1", "--axial", "5"][..],
            ["--axial 5", "0.25 ..= 4"],
        ),
        (
            &["--major", "4", "--minor", "1", "--axial", "0.2"],
            ["--axial 0.2", "0.25 ..= 4"],
        ),
        (
            &["--major", "4", "--minor", "1", "--axial", "0"],
            ["--axial 0", "> 0"],
        ),
        (
            &["--major", "4", "--minor", "1", "--axial", "-1"],
            ["--axial -1", "> 0"],
        ),
        (
            &["--major", "4", "--minor", "1", "--axial", "nan"],
            ["--axial", "finite"],
        ),
        (
            &["--major", "0.009", "--minor", "1"],
            ["--major 0.009", "0.01 <= --major / --minor"],
        ),
        (
            &["--major", "0.5", "--minor", "1", "--exact", "f32"],
            ["--exact f32", "a spindle torus"],
        ),
        (
            &[
                "--major", "4", "--minor", "1", "--axial", "2", "--exact", "f32",
            ],
            ["--exact f32", "an elliptical ring torus"],
        ),
    ] {
        let err = eval_rows(csv, args).expect_err("refused");
        for part in expect {
            assert!(err.contains(part), "{args:?}: {err}");
        }
    }
}

#[test]
fn circular_ring_rows_are_unchanged() {
    // tests/cli/data/ring_rays.csv: 120 rows (literal rays, ranges, surface points) of
    // the torus R = 3, r = 1; the expected outputs were written by the binary of 7fece07,
    // before eval knew the family. `--axial 1` (= r) must answer the same bytes.
    let data = Path::new(super::support::ROOT).join("tests/cli/data");
    let input = data.join("ring_rays.csv");
    for (mode, expected) in [
        (&[][..], "ring_rays.f64.expected"),
        (&["--precision", "f32"], "ring_rays.f32.expected"),
        (&["--exact", "f32"], "ring_rays.certified-f32.expected"),
    ] {
        let expected = std::fs::read_to_string(data.join(expected)).unwrap();
        for axial in [&[][..], &["--axial", "1"]] {
            let mut args = vec!["eval", "--major", "3", "--minor", "1"];
            args.extend_from_slice(axial);
            args.extend_from_slice(&["--rays", arg(&input)]);
            args.extend_from_slice(mode);
            let out = torus_cull(&args);
            assert!(out.status.success(), "{args:?}: {}", stderr(&out));
            // A cull newer than the pins adds a column they leave out.
            assert!(
                super::support::pinned_columns(&out.stdout) == expected.as_bytes(),
                "{args:?}: the rows changed"
            );
        }
    }
}
