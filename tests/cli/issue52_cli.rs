//! Issue 52.4: the messages a new user's bad inputs got. Each repro runs the binary on
//! input it refuses at once (no work starts), so the whole module takes about a second.

use crate::results_compare::sample;
use crate::support::{
    arg, assert_ok, refused, stdout, temp_path, tiny_workload, torus_cull, torus_cull_in,
};
use torus_cull_lab::results::RatioRecord;

/// Every numeric flag of `run`, `time`, `compare`, `render`, `f32-check`, `family` and
/// `bend --rays/--seed/--threads/--nu` given `-1`: the flag's own range, not clap's
/// "unexpected argument '-1' found".
#[test]
fn a_negative_value_gets_the_flags_range() {
    let png = "--scene chain --nu 2 --out x.png";
    for (line, answer) in [
        (
            "run --threads -1",
            "--threads -1 is invalid (allowed: 1 ..= 1024",
        ),
        (
            "time --nu -1",
            "--nu -1 is not in workload quick (allowed: ",
        ),
        (
            "time gpu --workgroup -1",
            "--workgroup -1 is invalid (allowed: 32 ..= 256",
        ),
        (
            "time --seconds -1",
            "--seconds -1 is invalid (allowed: 0 < seconds <= ",
        ),
        ("time --batch -1", "--batch -1 is invalid (allowed: 16 ..= "),
        (
            "time --runs -1",
            "--runs -1 is invalid (allowed: 1 ..= 100)",
        ),
        (
            "time family --runs -1",
            "--runs -1 is invalid (allowed: 1 ..= 100)",
        ),
        (
            "compare a.json b.json --threshold -1",
            "--threshold -1 is invalid (allowed: a percentage >= 0)",
        ),
        (
            "render --scene chain --nu -1 --out x.png",
            "--nu: nu = -1 is invalid (allowed: 1 < nu <= 1000)",
        ),
        (
            &format!("render {png} --size -1"),
            "--size -1 is invalid (allowed: 1 ..= 8192)",
        ),
        (
            &format!("render {png} --tori -1"),
            "--tori -1 is invalid (allowed: 1 ..= 1000000)",
        ),
        (
            &format!("render {png} --seed -1"),
            "--seed -1 is invalid (allowed: 0 ..= 18446744073709551615)",
        ),
        (
            "f32-check --rays -1",
            "--rays -1 is invalid (allowed: 1 ..= 1000000)",
        ),
        (
            "f32-check --seed -1",
            "--seed -1 is invalid (allowed: 0 ..= ",
        ),
        (
            "f32-check --threads -1",
            "--threads -1 is invalid (allowed: 1 ..= 1024",
        ),
        (
            "f32-check --rounds -1",
            "--rounds -1 is invalid (allowed: 0 ..= 1000)",
        ),
        (
            "family --rays -1",
            "--rays -1 is invalid (allowed: 1 ..= 1000000)",
        ),
        ("family --seed -1", "--seed -1 is invalid (allowed: 0 ..= "),
        (
            "bend --rays -1",
            "--rays -1 is invalid (allowed: 1 ..= 10000000)",
        ),
        ("bend --seed -1", "--seed -1 is invalid (allowed: 0 ..= "),
        (
            "bend --threads -1",
            "--threads -1 is invalid (allowed: 1 ..= 1024",
        ),
        (
            "bend --nu -1",
            "--nu -1 is invalid (allowed: 1 < --nu <= 1000)",
        ),
    ] {
        let (_dir, out) = temp_path("x.json");
        let mut words: Vec<&str> = line.split_whitespace().collect();
        // Nothing may be written anywhere but the temporary folder.
        if ["run", "time", "f32-check", "family", "bend"].contains(&words[0]) {
            words.extend(["--out", arg(&out)]);
        }
        let o = torus_cull(&words);
        let err = refused(&o);
        assert!(err.contains(answer), "{line}: {err}");
        assert!(!err.contains("unexpected argument"), "{line}: {err}");
    }
}

/// Huge values are written with significant digits, a long field is cut.
#[test]
fn huge_values_are_shortened() {
    let (_dir, out) = temp_path("x.json");
    let err = refused(&torus_cull(&[
        "time",
        "--seconds",
        "1e300",
        "--out",
        arg(&out),
    ]));
    assert!(err.contains("--seconds 1e300 is invalid"), "{err}");
    // A CSV field of 100 000 digits: its first 40 and the length.
    let (dir, rays) = temp_path("rays.csv");
    let digits = "9".repeat(100_000);
    std::fs::write(&rays, format!("ox,oy,oz,dx,dy,dz\n{digits},0,0,1,0,0\n")).unwrap();
    let o = torus_cull(&[
        "eval",
        "--major",
        "2",
        "--minor",
        "1",
        "--rays",
        arg(&rays),
        "--out",
        arg(&dir.path().join("o.csv")),
    ]);
    let err = refused(&o);
    assert!(
        err.contains(&format!("{}… (100000 characters)", &digits[..40])),
        "{err}"
    );
    assert!(err.len() < 400, "{} bytes: {}", err.len(), &err[..400]);
}

/// `--out` a bare file name: the plots are in `.`, not `/`.
#[test]
fn plots_of_a_bare_out_name_are_in_the_working_directory() {
    let (dir, workload) = tiny_workload();
    let o = torus_cull_in(
        dir.path(),
        &[
            "run",
            "--workload",
            arg(&workload),
            "--out",
            "bare.json",
            "--threads",
            "1",
        ],
    );
    assert_ok(&o);
    let said = stdout(&o);
    assert!(said.contains("plots to ./bare-*.svg"), "{said}");
    let svgs = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.starts_with("bare-") && name.ends_with(".svg"))
        .count();
    assert!(svgs > 0, "no bare-*.svg beside bare.json: {said}");
}

/// eval's bend messages: one space where 22 were, and R > r_max instead of "ring tori
/// only" (eval takes spindles).
#[test]
fn eval_bend_messages() {
    let (dir, rays) = temp_path("rays.csv");
    std::fs::write(&rays, "ox,oy,oz,dx,dy,dz\n0,0,-9,0,0,1\n").unwrap();
    let out = dir.path().join("o.csv");
    let eval = |extra: &[&str]| {
        let mut words = vec!["eval", "--rays", arg(&rays), "--out", arg(&out)];
        words.extend(extra);
        refused(&torus_cull(&words))
    };
    let err = eval(&[
        "--major", "4", "--minor", "1", "--axial", "2", "--bore", "0.5",
    ]);
    assert!(err.contains("a pipe bend's tube is circular"), "{err}");
    assert!(!err.contains("  "), "a run of spaces: {err:?}");
    let err = eval(&["--major", "0.8", "--minor", "1", "--bore", "0.5"]);
    assert!(
        err.contains("--major 0.8 --minor 1: a pipe bend needs R > r_max"),
        "{err}"
    );
    assert!(!err.contains("ring tori only"), "{err}");
}

/// `compare`: a ratio ≤ 0 is refused naming the file and the field, a `NaN` in the JSON
/// is named, and a 1e308 ratio keeps the table a table.
#[test]
fn compare_refuses_bad_ratios_and_names_nan() {
    let record = |ratio: f64| RatioRecord {
        case: "uniform".into(),
        nu: 2.0,
        cull: "skala".into(),
        reference: "cychosz".into(),
        metric: "total_ns".into(),
        ratio,
        ratio_ci: [ratio * 0.99, ratio * 1.01],
        rounds: 100,
        rounds_measured: 400,
        rays: 1024,
        ns_per_ray: 20.0,
        reference_ns_per_ray: 23.5,
        ..RatioRecord::default()
    };
    let (dir, a) = temp_path("a.json");
    let b = dir.path().join("b.json");
    let mut good = sample();
    good.ratio = vec![record(1.0)];
    good.save(&a).unwrap();
    let mut bad = sample();
    bad.ratio = vec![RatioRecord {
        ratio: -1.0,
        ..record(1.0)
    }];
    bad.save(&b).unwrap();
    let o = torus_cull(&["compare", arg(&a), arg(&b)]);
    let err = refused(&o);
    assert!(
        err.contains(arg(&b))
            && err.contains("field `ratio` = -1 is invalid (allowed: a finite ratio > 0"),
        "{err}"
    );
    // A NaN, as Python's json.dump writes it (results files are compact JSON).
    let text = std::fs::read_to_string(&a)
        .unwrap()
        .replace("\"ratio\":1.0", "\"ratio\":NaN");
    assert!(text.contains("NaN"));
    std::fs::write(&b, text).unwrap();
    let err = refused(&torus_cull(&["compare", arg(&a), arg(&b)]));
    assert!(
        err.contains("`NaN` is not a JSON number (JSON has no NaN or Infinity"),
        "{err}"
    );
    // 1e308: scientific, and the change too.
    let mut huge = sample();
    huge.ratio = vec![record(1e308)];
    huge.save(&b).unwrap();
    let o = torus_cull(&["compare", arg(&a), arg(&b)]);
    let table = stdout(&o);
    assert!(table.contains("1.0000e308"), "{table}");
    assert!(table.lines().all(|l| l.len() < 400), "{table}");
}
