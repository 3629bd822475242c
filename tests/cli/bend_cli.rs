//! `eval` on a pipe bend's solid (the bend's check: check_cli.rs).

use super::support::eval_rows;

/// `eval --bore --phi-start --delta-phi`: the quarter bend R = 4, r_min = 0.5, r_max = 1,
/// φ from 0 (+x) to π/2 (−z), rows whose first crossings are known in closed form.
#[test]
fn eval_answers_the_pipe_bends_solid() {
    let (c, s) = (
        std::f64::consts::FRAC_1_SQRT_2,
        std::f64::consts::FRAC_1_SQRT_2,
    );
    let at = |rho: f64| (rho * c, -rho * s); // φ = π/4
    let (x1, z1) = at(4.75);
    let (x2, z2) = at(4.0);
    let csv = format!(
        "ox,oy,oz,dx,dy,dz\n\
         {x1},3,{z1},0,-1,0\n\
         {x2},3,{z2},0,-1,0\n\
         -4.75,3,0,0,-1,0\n\
         4.75,0,10,0,0,-1\n\
         4,0,10,0,0,-1\n"
    );
    let flags = [
        "--major",
        "4",
        "--minor",
        "1",
        "--bore",
        "0.5",
        "--delta-phi",
        "1.5707963267948966",
    ];
    let rows = eval_rows(&csv, &flags).unwrap();
    let t = |row: usize| rows[row][3].parse::<f64>().unwrap();
    // The outer tube's top at ρ = 4.75: y = √(1 − 0.75²).
    assert_eq!(rows[0][1], "hit", "{:?}", rows[0]);
    assert!(
        (t(0) - (3.0 - 0.4375f64.sqrt())).abs() < 1e-9,
        "{:?}",
        rows[0]
    );
    // Over the bore: the outer tube's top first, y = 1.
    assert_eq!(rows[1][1], "hit");
    assert!((t(1) - 2.0).abs() < 1e-9, "{:?}", rows[1]);
    // Through the cut-away arc (φ = π): a miss the whole torus would hit, which every
    // torus cull keeps (they bound the outer torus); the wedge columns after them reject it.
    assert_eq!(rows[2][1], "miss");
    assert_eq!(rows[2][3], "");
    let culls = torus_cull::CullKind::TIMED.len();
    assert!(
        rows[2][4..4 + culls].iter().all(|k| k == "1"),
        "{:?}",
        rows[2]
    );
    assert!(
        rows[2][4 + culls..].iter().all(|k| k == "0"),
        "{:?}",
        rows[2]
    );
    // Onto the start cap (the half-plane φ = 0, z = 0) at ρ = 4.75, in the annulus.
    assert_eq!(rows[3][1], "hit");
    assert!((t(3) - 10.0).abs() < 1e-9, "{:?}", rows[3]);
    // Into the bore's open end at ρ = 4: on through the hollow to the bore's wall, where
    // √(16 + z²) = 4.5.
    assert_eq!(rows[4][1], "hit");
    assert!(
        (t(4) - (10.0 + 4.25f64.sqrt())).abs() < 1e-9,
        "{:?}",
        rows[4]
    );
    // Every cull keeps every hit.
    for row in rows.iter().filter(|r| r[1] == "hit") {
        assert!(row[4..].iter().all(|k| k == "1"), "{row:?}");
    }
    // A whole bend is the ring torus: the same bytes as without the flags.
    let whole = [
        "--bore",
        "0",
        "--phi-start",
        "0",
        "--delta-phi",
        "6.283185307179586",
    ];
    let ring = eval_rows(&csv, &["--major", "4", "--minor", "1"]).unwrap();
    let mut args = vec!["--major", "4", "--minor", "1"];
    args.extend_from_slice(&whole);
    assert_eq!(eval_rows(&csv, &args).unwrap(), ring);
    // `--exact f32` (PipeBend::intersect_f32): a line that misses the outer torus, from
    // outside it, is proved in f32 (escalated 0); every other row escalates to the f64
    // solid (escalated 1), its t the f64 answer on the row's f32 ray.
    let csv32 = format!("{csv}0,10,0,1,0,0\n");
    let mut args32 = flags.to_vec();
    args32.extend(["--exact", "f32"]);
    let rows32 = eval_rows(&csv32, &args32).unwrap();
    assert_eq!((rows32[5][3].as_str(), rows32[5][4].as_str()), ("", "0"));
    for (r32, r64) in rows32.iter().zip(&rows) {
        assert_eq!(r32[4], "1", "{r32:?}");
        assert_eq!(r32[3].is_empty(), r64[3].is_empty(), "{r32:?} {r64:?}");
        if let (Ok(a), Ok(b)) = (r32[3].parse::<f64>(), r64[3].parse::<f64>()) {
            assert!((a - b).abs() <= 1e-6 * b, "{r32:?} {r64:?}");
        }
    }
}

#[test]
fn bad_bend_values_name_the_flag_and_the_range() {
    let csv = "ox,oy,oz,dx,dy,dz\n-3,0,0,1,0,0\n";
    for (extra, expect) in [
        (&["--bore", "1"][..], ["--bore 1", "0 <= --bore < --minor"]),
        (&["--bore", "-0.5"], ["--bore -0.5", "0 <= --bore"]),
        (
            &["--delta-phi", "0"],
            ["--delta-phi 0", "0 < --delta-phi <= 2*pi"],
        ),
        (
            &["--delta-phi", "7"],
            ["--delta-phi 7", "0 < --delta-phi <= 2*pi"],
        ),
        (&["--phi-start", "nan"], ["--phi-start", "finite"]),
        (
            &["--bore", "0.5", "--axial", "0.5"],
            ["--axial", "circular"],
        ),
        (
            &["--bore", "0.5", "--exact", "gpu"],
            ["--exact gpu", "pipe bend"],
        ),
        // Issue 52: the bore's own ν above 1000, and a wall below 10⁻⁷·(R + r_max).
        (
            &["--bore", "0.001"],
            ["--bore 0.001", "0.004 <= --bore <= --minor"],
        ),
        (
            &["--bore", "0.9999999"],
            ["--bore 0.9999999", "0 < --bore <= 0.9999995"],
        ),
    ] {
        let mut args = vec!["--major", "4", "--minor", "1"];
        args.extend_from_slice(extra);
        let err = eval_rows(csv, &args).expect_err("refused");
        for part in expect {
            assert!(err.contains(part), "{args:?}: {err}");
        }
    }
    // A row marked on the surface must lie on a face of the solid.
    let off = "ox,oy,oz,dx,dy,dz,on_surface\n4.2,1.5,-0.5,0,1,0,1\n";
    let err =
        eval_rows(off, &["--major", "4", "--minor", "1", "--delta-phi", "1"]).expect_err("refused");
    assert!(
        err.contains(":2:") && err.contains("not a surface point"),
        "{err}"
    );
}
