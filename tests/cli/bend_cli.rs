//! `torus-cull bend` at a tiny size: a clean file, its charts, `plot` redrawing them, and
//! `compare` of two bend files.

use super::support::{
    arg, assert_ok, cli_ok, compare_clean_and_worse, read_json, refused, stderr, svgs, temp_path,
    torus_cull,
};

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
    ] {
        let mut all = vec!["bend", "--no-plots", "--out", "/nonexistent/x.json"];
        all.extend_from_slice(args);
        let out = torus_cull(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(expect), "{args:?}: {}", stderr(&out));
    }
}
