//! `torus-cull bend` at a tiny size: a clean file, its charts, `plot` redrawing them, and
//! `compare` of two bend files; `eval` on a pipe bend's solid.

use super::support::{
    arg, assert_ok, cli, cli_ok, compare_clean_and_worse, eval_rows, read_json, refused,
    refused_at_once, stderr, svgs, temp_path, torus_cull,
};
use std::time::Instant;

#[test]
fn bend_check_at_a_tiny_size_is_clean() {
    let (dir, path) = temp_path("bend.json");
    let p = arg(&path);
    let out = torus_cull(&["bend", "--rays", "1400", "--out", p]);
    assert_ok(&out);
    let file = read_json(&path);
    assert_eq!(file["meta"]["tool"], "bend");
    let classes = file["classes"].as_array().unwrap();
    assert_eq!(classes.len(), 12);
    for c in classes {
        let culls = c["culls"].as_array().unwrap();
        assert_eq!(culls.len(), 2 * torus_cull::CullKind::TIMED.len());
        assert!(culls.iter().all(|k| k["false_rejects"] == 0), "{c}");
        for key in [
            "missed",
            "invented",
            "wrong_face",
            "wrong_value",
            "all_missed",
            "all_invented",
            "all_wrong_face",
            "all_wrong_value",
        ] {
            assert_eq!(c["exact"][key], 0, "{key}: {c}");
        }
        let kinds = c["kinds"].as_array().unwrap();
        let rays: u64 = kinds.iter().map(|k| k["rays"].as_u64().unwrap()).sum();
        assert_eq!(rays, 1400);
        // Every kind drawn, the spawned ones included.
        assert!(
            kinds.iter().all(|k| k["rays"].as_u64().unwrap() == 200),
            "{c}"
        );
        // A cut segment has cut-away misses, and the wedge alone rejects some of them.
        if c["delta_phi_deg"].as_f64().unwrap() < 360.0 {
            assert!(c["cut_away"]["wedge_rejected"].as_u64().unwrap() > 0, "{c}");
        }
    }
    // Its charts, next to it: capture and rejection per r_min/r_max (three, at ν = 4);
    // `plot` draws the same from the file.
    let written = svgs(dir.path());
    assert_eq!(written.len(), 6, "{written:?}");
    assert!(
        written.contains(&"bend-rmin0.5-nu4-capture.svg".to_string()),
        "{written:?}"
    );
    let chart = std::fs::read_to_string(dir.path().join("bend-rmin0.5-nu4-capture.svg")).unwrap();
    assert!(chart.contains("Δφ in degrees"), "the x axis is Δφ");
    assert!(chart.contains("cychosz+wedge"));
    let again = tempfile::tempdir().unwrap();
    let out = torus_cull(&["plot", p, "--out-dir", again.path().to_str().unwrap()]);
    assert_ok(&out);
    assert_eq!(svgs(again.path()), written);
    // `compare`: the same file is clean; a false reject added, a capture lowered or a
    // wrong face added is a regression (exit 1); files of other rays are refused (exit 2).
    let mut worse = file.clone();
    worse["classes"][4]["culls"][13]["false_rejects"] = 1.into();
    let cull = &mut worse["classes"][7]["culls"][3];
    let far = cull["far_misses"].as_u64().unwrap();
    cull["far_misses"] = (far + 1).into();
    worse["classes"][9]["exact"]["wrong_face"] = 1.into();
    let report = compare_clean_and_worse(p, &worse, again.path());
    assert!(report.contains("wrong-value answers 0 -> 1"), "{report}");
    let other = again.path().join("other.json");
    let o = arg(&other);
    cli_ok("bend --rays 7 --no-plots --seed 5 --out {}", &[o]);
    assert!(
        svgs(again.path()).len() == written.len(),
        "--no-plots wrote charts"
    );
    let out = torus_cull(&["compare", p, o]);
    refused(&out);
    assert!(stderr(&out).contains("workload_sha256"), "{}", stderr(&out));
    // A family file and a bend file are different records.
    let family = again.path().join("family.json");
    let f = arg(&family);
    let out = torus_cull(&["family", "--rays", "4", "--no-plots", "--out", f]);
    assert_ok(&out);
    let out = torus_cull(&["compare", f, p]);
    refused(&out);
}

#[test]
fn bad_bend_arguments_name_the_flag_and_the_range() {
    for (args, expect) in [
        (&["--rays", "0"][..], "--rays 0"),
        (&["--nu", "1"], "--nu 1"),
        (&["--nu", "nan"], "--nu NaN"),
        (&["--threads", "0"], "--threads 0"),
        (&["--delta-phi", "7"], "0 < --delta-phi <= 2*pi"),
        (&["--delta-phi", "0"], "--delta-phi 0"),
        (&["--bore-ratio", "1"], "0 <= --bore-ratio < 1"),
        (&["--bore-ratio", "-0.1"], "--bore-ratio -0.1"),
        (
            &["--workload", "quick", "--rays", "5"],
            "cannot be used with",
        ),
        (&["--workload", "quick"], "no `bend` key"),
    ] {
        let mut all = vec!["bend", "--no-plots", "--out", "/nonexistent/x.json"];
        all.extend_from_slice(args);
        let out = torus_cull(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(expect), "{args:?}: {}", stderr(&out));
    }
}

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

/// The classes a user names: `--delta-phi` and `--bore-ratio`, or a workload file's
/// `bend` key (its `seed` the seed); a bad value in the file names the file, the field and
/// the range.
#[test]
fn bend_takes_its_classes_from_flags_or_a_workload_file() {
    let (dir, path) = temp_path("flags.json");
    cli_ok(
        "bend --delta-phi 2 --bore-ratio 0.2 --rays 700 --no-plots --out {}",
        &[arg(&path)],
    );
    let file = read_json(&path);
    let classes = file["classes"].as_array().unwrap();
    assert_eq!(classes.len(), 1);
    assert_eq!(classes[0]["delta_phi"], 2.0);
    assert_eq!(classes[0]["bore_ratio"], 0.2);
    assert_eq!(classes[0]["rays"], 700);

    let workload = dir.path().join("bends.json");
    let text = |bend: &str| {
        format!(r#"{{"name":"bends","seed":9,"cases":["hole"],"nu":[2],"rays":1,"bend":{bend}}}"#)
    };
    std::fs::write(
        &workload,
        text(r#"{"nu":[2.5],"delta_phi":[1.0,3.0],"bore_ratio":[0.3],"rays":700}"#),
    )
    .unwrap();
    let from_file = dir.path().join("from-file.json");
    let run = || {
        cli(
            "bend --workload {} --no-plots --out {}",
            &[arg(&workload), arg(&from_file)],
        )
    };
    let out = run();
    assert_ok(&out);
    let file = read_json(&from_file);
    assert_eq!(file["seed"], 9);
    let classes = file["classes"].as_array().unwrap();
    let got: Vec<(f64, f64, f64)> = classes
        .iter()
        .map(|c| {
            (
                c["nu"].as_f64().unwrap(),
                c["delta_phi"].as_f64().unwrap(),
                c["bore_ratio"].as_f64().unwrap(),
            )
        })
        .collect();
    assert_eq!(got, [(2.5, 1.0, 0.3), (2.5, 3.0, 0.3)]);
    assert!(classes.iter().all(|c| c["rays"] == 700));

    for (bend, expect) in [
        (
            r#"{"nu":[4],"delta_phi":[7],"bore_ratio":[0],"rays":10}"#,
            "field `bend.delta_phi[0]`: 7 is invalid (allowed: 0 < delta_phi <= 2*pi",
        ),
        (
            r#"{"nu":[4],"delta_phi":[1],"bore_ratio":[0,1],"rays":10}"#,
            "field `bend.bore_ratio[1]`: 1 is invalid (allowed: 0 <= bore_ratio < 1)",
        ),
        (
            r#"{"nu":[4],"delta_phi":[1],"bore_ratio":[0],"rays":0}"#,
            "field `bend.rays`: 0 is invalid",
        ),
        (
            r#"{"nu":[],"delta_phi":[1],"bore_ratio":[0],"rays":10}"#,
            "field `bend.nu`: must list at least one value",
        ),
        (
            r#"{"nu":[4],"delta_phi":[1],"bore_ratio":[0],"rays":10,"bores":[1]}"#,
            "field `bend`: unknown field `bores`",
        ),
    ] {
        std::fs::write(&workload, text(bend)).unwrap();
        let err = refused(&run());
        assert!(
            err.contains("bends.json") && err.contains(expect),
            "{bend}: {err}"
        );
    }
}

/// Issue 52: classes whose bend the library refuses (the bore's torus's ν above 1000,
/// ν above 1000, a wall below 10⁻⁷·(R + r_max)) are refused before any work, exit 2,
/// naming the flags and the range (they panicked at `Spec::bend`, exit 101); a workload
/// file's names its fields. The issue's thin wall (10⁻⁶·r_max at ν = 4) is accepted and
/// clean.
#[test]
fn bend_refuses_classes_it_cannot_build_before_any_work() {
    let (dir, path) = temp_path("b.json");
    let p = arg(&path);
    for (args, needles) in [
        (
            &["--nu", "1000"][..],
            &[
                "--bore-ratio 0.5 at --nu 1000",
                "nu = R/r_min = 2000",
                "--bore-ratio 0 only",
            ][..],
        ),
        (
            &["--nu", "501"],
            &["--bore-ratio 0.5 at --nu 501", "0.501 <= --bore-ratio <= "],
        ),
        (
            &["--bore-ratio", "0.001"],
            &[
                "--bore-ratio 0.001 at --nu 4",
                "nu = R/r_min = 4000",
                "0.004 <= --bore-ratio",
            ],
        ),
        (&["--nu", "1001"], &["--nu 1001", "1 < --nu <= 1000"]),
        (
            &["--bore-ratio", "0.9999999"],
            &[
                "--bore-ratio 0.9999999 at --nu 4",
                "thinner than 1e-7*(R + r_max)",
                "<= 1 - 1e-7*(nu + 1) = 0.9999995",
            ],
        ),
    ] {
        let mut all = vec!["bend", "--rays", "100", "--no-plots", "--out", p];
        all.extend_from_slice(args);
        let started = Instant::now();
        let out = torus_cull(&all);
        refused_at_once(&out, started, needles);
        assert!(!path.exists(), "{args:?}: a file was written");
    }
    let workload = dir.path().join("bends.json");
    std::fs::write(
        &workload,
        r#"{"name":"b","seed":1,"cases":["hole"],"nu":[2],"rays":1,"bend":{"nu":[4],"delta_phi":[1.0],"bore_ratio":[0.001],"rays":100}}"#,
    )
    .unwrap();
    let started = Instant::now();
    let out = cli(
        "bend --workload {} --no-plots --out {}",
        &[arg(&workload), p],
    );
    refused_at_once(
        &out,
        started,
        &["bends.json", "bend.bore_ratio 0.001 at bend.nu 4"],
    );
    // The thin wall of the issue, and the thinnest at ν = 4, pass the check.
    for ratio in ["0.999999", "0.9999995"] {
        cli_ok(
            "bend --bore-ratio {} --delta-phi 1 --rays 700 --no-plots --out {}",
            &[ratio, p],
        );
        let file = read_json(&path);
        assert_eq!(file["classes"][0]["exact"]["missed"], 0);
        assert_eq!(file["classes"][0]["exact"]["wrong_value"], 0);
    }
}
