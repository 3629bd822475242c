//! `torus-cull run` over a workload's `shapes` key: a record per family member or bend and
//! cull with the shape's parameters, declined culls said so, a bend's wedge forms, 0 false
//! rejects against the shapes' oracles, tables and charts; a broken cull fails the run
//! naming the member; a bend the library does not build is refused before the work.

use crate::support::{arg, assert_ok, cli, read_json, refused, stdout, svgs, temp_path};
use torus_cull::CullKind;
use torus_cull_lab::results::Results;

/// A workload in `dir`: one ring batch of 200 rays, six family members (a ring, an
/// elliptical ring, the horn, a spindle below ν = ½; b/a 0.5 and 1) and two bends (a
/// quarter, with and without a bore), 600 rays each: under a second.
fn shapes_workload(dir: &std::path::Path) -> std::path::PathBuf {
    let path = dir.join("shapes.json");
    std::fs::write(
        &path,
        r#"{"name":"shapes","seed":7,"cases":["uniform"],"nu":[4],"rays":200,
            "shapes":{"rays":600,"family":{"nu":[4,1,0.3],"aspects":[0.5,1]},
            "bends":{"nu":[4],"segments_deg":[90],"bores":[0,0.5]}}}"#,
    )
    .unwrap();
    path
}

#[test]
fn every_member_has_a_record_per_cull_with_its_parameters_and_no_false_reject() {
    let (dir, out) = temp_path("r.json");
    let workload = shapes_workload(dir.path());
    let o = cli("run --workload {} --out {}", &[arg(&workload), arg(&out)]);
    assert_ok(&o);
    let text = stdout(&o);
    let r = Results::load(&out).unwrap();
    let culls = CullKind::TIMED.len();
    // Six members × every cull; two bends × (every cull, `wedge`, `wedge+<cull>` but none).
    assert_eq!(r.shapes.len(), 6 * culls + 2 * (2 * culls), "{text}");
    assert!(r.shapes.iter().all(|s| s.counts.false_rejects == 0));
    assert!(r.shapes.iter().all(|s| s.counts.rays == 600));
    let kinds: Vec<&str> = r.shapes.iter().map(|s| s.shape.as_str()).collect();
    for kind in ["ring", "elliptic", "horn", "spindle", "bend"] {
        assert!(kinds.contains(&kind), "no {kind} in {kinds:?}");
    }
    // The discriminant culls decline the horn and the spindle: kept every ray, no capture.
    let find = |shape: &str, nu: f64, cull: &str| {
        r.shapes
            .iter()
            .find(|s| s.shape == shape && s.counts.nu == nu && s.counts.cull == cull)
            .unwrap_or_else(|| panic!("no {shape} {nu} {cull}"))
    };
    let declined = find("spindle", 0.3, "discriminant");
    assert!(!declined.accepts && declined.counts.rejected == 0);
    assert_eq!(declined.counts.miss_capture, None);
    assert!(find("horn", 1.0, "skala").accepts && find("horn", 1.0, "skala").counts.rejected > 0);
    // A bend: its parameters, the wedge alone and behind a cull, which rejects at least as
    // much as the cull alone.
    let bend = |cull: &str| {
        r.shapes
            .iter()
            .find(|s| s.shape == "bend" && s.bore == Some(0.5) && s.counts.cull == cull)
            .unwrap_or_else(|| panic!("no bend {cull}"))
    };
    assert_eq!(bend("skala").segment_deg, Some(90.0));
    assert!(bend("wedge").counts.rejected > 0);
    assert!(bend("wedge+skala").counts.rejected >= bend("skala").counts.rejected);
    assert!(r.shapes.iter().all(|s| s.counts.cull != "wedge+none"));
    // The ring's records are as they were: no shape field in the file.
    let json = read_json(&out);
    let ring = json["rejection"][0].as_object().unwrap();
    for field in ["shape", "aspect", "bore", "segment_deg", "accepts"] {
        assert!(!ring.contains_key(field), "{ring:?}");
    }
    // The claim, the tables and the charts.
    assert!(
        text.contains("0 false rejects in 4800 rays of 8 family members and bends"),
        "{text}"
    );
    assert!(
        text.contains("family b/a=0.5 (") && text.contains("bend nu=4 dphi=90:"),
        "{text}"
    );
    let charts = svgs(dir.path());
    for name in [
        "r-shapes-b0.5-miss_capture.svg",
        "r-shapes-bend-bore0.5-nu4-rejection_rate.svg",
    ] {
        assert!(charts.iter().any(|c| c == name), "no {name} in {charts:?}");
    }
    // `plot` of the file draws them too.
    let again = tempfile::tempdir().unwrap();
    let o = cli("plot {} --out-dir {}", &[arg(&out), arg(again.path())]);
    assert_ok(&o);
    assert_eq!(svgs(again.path()).len(), charts.len());
}

#[test]
fn a_broken_cull_on_a_shape_fails_the_run_and_names_the_member() {
    let (dir, out) = temp_path("broken.json");
    let workload = shapes_workload(dir.path());
    let o = cli(
        "run --workload {} --out {} --no-plots --culls cychosz,cychosz_printed",
        &[arg(&workload), arg(&out)],
    );
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("FALSE REJECT: cull cychosz_printed on "),
        "{err}"
    );
    assert!(
        err.contains("Toroid::new_f64(center") && err.contains("ray #"),
        "{err}"
    );
    assert!(
        !err.contains("cull cychosz on"),
        "the real cychosz must not appear: {err}"
    );
    let r = Results::load(&out).unwrap();
    assert!(
        r.shapes
            .iter()
            .any(|s| s.counts.cull == "cychosz_printed" && s.counts.false_rejects > 0)
    );
    assert!(
        r.shapes
            .iter()
            .filter(|s| s.counts.cull == "cychosz")
            .all(|s| s.counts.false_rejects == 0)
    );
}

#[test]
fn a_bend_the_library_does_not_build_is_refused_before_the_work() {
    let (dir, out) = temp_path("r.json");
    let workload = dir.path().join("thin.json");
    std::fs::write(
        &workload,
        r#"{"name":"thin","seed":7,"cases":["uniform"],"nu":[4],"rays":10,
            "shapes":{"rays":10,"bends":{"nu":[4],"segments_deg":[90],"bores":[0.9999999]}}}"#,
    )
    .unwrap();
    let err = refused(&cli(
        "run --workload {} --out {}",
        &[arg(&workload), arg(&out)],
    ));
    assert!(
        err.contains("thin.json") && err.contains("shapes.bends") && err.contains("allowed"),
        "{err}"
    );
    assert!(!out.exists());
}

#[test]
fn compare_pairs_the_shape_records_and_flags_a_new_false_reject() {
    let (dir, out) = temp_path("old.json");
    let workload = shapes_workload(dir.path());
    assert_ok(&cli(
        "run --workload {} --out {} --no-plots",
        &[arg(&workload), arg(&out)],
    ));
    // The same file against itself: every shape record paired, nothing flagged.
    let o = cli("compare {} {}", &[arg(&out), arg(&out)]);
    assert_ok(&o);
    let same = stdout(&o);
    assert!(
        !same.contains("REGRESSION") && !same.contains("disagrees"),
        "{same}"
    );
    // A false reject on the horn: a regression, named by member and cull.
    let mut worse = Results::load(&out).unwrap();
    let horn = worse
        .shapes
        .iter_mut()
        .find(|s| s.shape == "horn" && s.counts.cull == "skala")
        .unwrap();
    horn.counts.false_rejects = 1;
    let new = dir.path().join("new.json");
    std::fs::write(&new, serde_json::to_string(&worse).unwrap()).unwrap();
    let o = cli("compare {} {}", &[arg(&out), arg(&new)]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let text = stdout(&o);
    assert!(
        text.contains("horn nu=1 b/a=0.5 skala")
            && text.contains("REGRESSION: false rejects 0 -> 1"),
        "{text}"
    );
}
