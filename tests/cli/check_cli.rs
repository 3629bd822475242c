//! `torus-cull check` for every shape, at a tiny size, through its aliases `family` and
//! `bend` (moved from family_cli.rs and bend_cli.rs): a clean file, its charts, `plot`
//! redrawing them, `compare` of two check files; the bend's classes from flags or a
//! workload file, and refusals naming the flag; then the one command itself: its
//! spellings count the same rays, options of another shape are refused, old check files
//! are refused naming the new kind.

use super::support::{
    arg, assert_ok, cli, cli_ok, compare_clean_and_worse, read_json, refused, refused_at_once,
    stderr, svgs, temp_path, torus_cull,
};
use std::time::Instant;

#[test]
fn family_check_at_a_tiny_size_is_clean() {
    let (dir, path) = temp_path("family.json");
    let out = torus_cull(&["family", "--rays", "48", "--out", arg(&path)]);
    assert_ok(&out);
    let file = read_json(&path);
    assert_eq!(file["meta"]["tool"], "check");
    assert_eq!(file["shape"], "family");
    let members = file["classes"].as_array().unwrap();
    assert_eq!(members.len(), 33);
    for m in members {
        let culls = m["culls"].as_array().unwrap();
        assert_eq!(culls.len(), torus_cull::CullKind::TIMED.len());
        for c in culls {
            assert_eq!(c["false_rejects"], 0, "{m}");
        }
        for answer in m["answers"].as_array().unwrap() {
            for key in ["missed", "invented"] {
                assert_eq!(answer["wrong"][key], 0, "{key}: {m}");
            }
        }
        let rays: u64 = m["kinds"]
            .as_array()
            .unwrap()
            .iter()
            .map(|k| k["rays"].as_u64().unwrap())
            .sum();
        assert_eq!(rays, 48);
    }
    // Its charts, next to it: capture and rejection rate per aspect b/a (five aspects);
    // `plot` draws the same from the file, and `--no-plots` writes none.
    let written = svgs(dir.path());
    assert_eq!(written.len(), 10, "{written:?}");
    assert!(
        written.contains(&"family-aspect0.25-capture.svg".to_string()),
        "{written:?}"
    );
    let again = tempfile::tempdir().unwrap();
    cli_ok(
        "plot {} --out-dir {}",
        &[arg(&path), again.path().to_str().unwrap()],
    );
    assert_eq!(svgs(again.path()), written);
    // `compare` reads two family files: the same file is clean; a false reject added, or a
    // capture lowered, is a regression (exit 1); files of other rays are refused (exit 2).
    let p = arg(&path);
    let mut worse: serde_json::Value = file.clone();
    worse["classes"][3]["culls"][5]["false_rejects"] = 1.into();
    let cull = &mut worse["classes"][7]["culls"][8];
    let far = cull["far_misses"].as_u64().unwrap();
    cull["far_misses"] = (far + 1).into();
    compare_clean_and_worse(p, &worse, again.path());
    let other = again.path().join("other.json");
    cli_ok(
        "family --rays 8 --no-plots --seed 5 --out {}",
        &[arg(&other)],
    );
    let out = torus_cull(&["compare", p, arg(&other)]);
    refused(&out);
    assert!(stderr(&out).contains("workload_sha256"), "{}", stderr(&out));
    let bare = tempfile::tempdir().unwrap();
    let quiet = bare.path().join("family.json");
    let out = torus_cull(&["family", "--rays", "8", "--no-plots", "--out", arg(&quiet)]);
    assert_ok(&out);
    assert!(svgs(bare.path()).is_empty());
}

#[test]
fn bend_check_at_a_tiny_size_is_clean() {
    let (dir, path) = temp_path("bend.json");
    let p = arg(&path);
    let out = torus_cull(&["bend", "--rays", "1400", "--out", p]);
    assert_ok(&out);
    let file = read_json(&path);
    assert_eq!(file["meta"]["tool"], "check");
    assert_eq!(file["shape"], "bend");
    let classes = file["classes"].as_array().unwrap();
    assert_eq!(classes.len(), 12);
    for c in classes {
        let culls = c["culls"].as_array().unwrap();
        assert_eq!(culls.len(), 2 * torus_cull::CullKind::TIMED.len());
        assert!(culls.iter().all(|k| k["false_rejects"] == 0), "{c}");
        let answers = c["answers"].as_array().unwrap();
        assert_eq!(answers.len(), 2, "intersect and intersect_all: {c}");
        for answer in answers {
            for key in ["missed", "invented", "wrong_face", "wrong_value"] {
                assert_eq!(answer["wrong"][key], 0, "{key}: {c}");
            }
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
        if c["params"]["delta_phi_deg"].as_f64().unwrap() < 360.0 {
            assert_eq!(c["captures"][0]["name"], "cut-away");
            assert!(c["captures"][0]["rejected"].as_u64().unwrap() > 0, "{c}");
        }
    }
    // Its charts, next to it: capture and rejection per r_min/r_max (three, at ν = 4);
    // `plot` draws the same from the file.
    let written = svgs(dir.path());
    assert_eq!(written.len(), 6, "{written:?}");
    assert!(
        written.contains(&"bend-bore_ratio0.5-nu4-capture.svg".to_string()),
        "{written:?}"
    );
    let chart =
        std::fs::read_to_string(dir.path().join("bend-bore_ratio0.5-nu4-capture.svg")).unwrap();
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
    worse["classes"][9]["answers"][0]["wrong"]["wrong_face"] = 1.into();
    let report = compare_clean_and_worse(p, &worse, again.path());
    assert!(report.contains("wrong_value answers 0 -> 1"), "{report}");
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
    assert_eq!(classes[0]["params"]["delta_phi"], 2.0);
    assert_eq!(classes[0]["params"]["bore_ratio"], 0.2);
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
                c["params"]["nu"].as_f64().unwrap(),
                c["params"]["delta_phi"].as_f64().unwrap(),
                c["params"]["bore_ratio"].as_f64().unwrap(),
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
        let first = &file["classes"][0]["answers"][0]["wrong"];
        assert_eq!(first["missed"], 0);
        assert_eq!(first["wrong_value"], 0);
    }
}

/// The one command: `check --shape bend` is `bend` (the same rays, the same file but its
/// path), `f32-check --family TEXT` is `check --shape ring --precision f32 --class TEXT`;
/// a shape's options are refused on another shape, a precision a shape is not checked at
/// is refused, and so is an old check file, naming the new kind.
#[test]
fn one_check_command_for_every_shape() {
    let (dir, path) = temp_path("a.json");
    let other = dir.path().join("b.json");
    let (a, b) = (arg(&path), arg(&other));
    cli_ok("bend --rays 300 --delta-phi 1 --no-plots --out {}", &[a]);
    cli_ok(
        "check --shape bend --rays 300 --delta-phi 1 --no-plots --threads 1 --out {}",
        &[b],
    );
    let (x, y) = (read_json(&path), read_json(&other));
    assert_eq!(x["classes"], y["classes"]);
    assert_eq!(x["meta"]["workload_sha256"], y["meta"]["workload_sha256"]);
    cli_ok(
        "f32-check --family bitangent --rays 50 --rounds 0 --no-plots --out {}",
        &[a],
    );
    cli_ok(
        "check --shape ring --precision f32 --class bitangent --rays 50 --rounds 0 --no-plots --out {}",
        &[b],
    );
    let (x, y) = (read_json(&path), read_json(&other));
    assert_eq!(x["classes"], y["classes"]);
    assert_eq!(x["classes"].as_array().unwrap().len(), 1);
    assert_eq!(x["precision"], "f32");
    for (args, needles) in [
        (
            &["family", "--nu", "4"][..],
            &["--nu", "--shape family", "--shape bend"][..],
        ),
        (&["bend", "--rounds", "1"], &["--rounds", "--shape bend"]),
        (
            &["check", "--shape", "ring", "--precision", "f64"],
            &["--precision f64", "ring at f32"],
        ),
        (
            &["check", "--shape", "family", "--precision", "f32"],
            &["--precision f32", "family at f64"],
        ),
        (
            &["check", "--shape", "cone"],
            &["--shape cone", "family, bend, ring"],
        ),
        (
            &["check", "--class", "nothing-like-it"],
            &["--class nothing-like-it"],
        ),
    ] {
        let mut all = args.to_vec();
        all.extend_from_slice(&["--rays", "10", "--no-plots", "--out", a]);
        let _ = std::fs::remove_file(&path);
        let started = Instant::now();
        refused_at_once(&torus_cull(&all), started, needles);
        assert!(!path.exists(), "{args:?}: a file was written");
    }
    // A check file of the old kinds (meta.tool `family`, `bend`, `f32-check`) is refused by
    // `compare` and `plot`, naming the new kind and the command.
    let old = std::path::Path::new(super::support::ROOT).join("results/bafc576-family.json");
    let out = torus_cull(&["compare", arg(&old), arg(&old)]);
    let err = refused(&out);
    assert!(
        err.contains("meta.tool `check`") && err.contains("check --shape family"),
        "{err}"
    );
}
