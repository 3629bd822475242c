//! `torus-cull eval`: bad input gives the documented error, good input round-trips.

use std::path::Path;
use std::process::{Command, Output};
use torus_cull::oracle::{OracleClass, classify};
use torus_cull::{CullBounds, CullKind, Ray, Torus, intersect};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_torus-cull"))
        .args(args)
        .output()
        .expect("run torus-cull")
}

fn eval_file(dir: &Path, csv: &str, major: &str, minor: &str) -> Output {
    let input = dir.join("rays.csv");
    std::fs::write(&input, csv).unwrap();
    run(&[
        "eval",
        "--major",
        major,
        "--minor",
        minor,
        "--rays",
        input.to_str().unwrap(),
    ])
}

#[test]
fn bad_rows_stop_with_the_line_number() {
    let dir = tempfile::tempdir().unwrap();
    let header = "ox,oy,oz,dx,dy,dz\n";
    let good = "-5,0,0,1,0,0\n";
    for (row, expect) in [
        ("1,2,3,4,5\n", "expected 6 columns"),
        ("1,2,3,4,5,6,7\n", "expected 6 columns"),
        ("1,2,x,1,0,0\n", "column oz: 'x' is not a number"),
        ("1,2,3,0,0,0\n", "zero"),
        ("1,2,3,NaN,0,1\n", "column dx: NaN is not finite"),
        ("1,2,3,inf,0,1\n", "column dx: inf is not finite"),
    ] {
        let out = eval_file(dir.path(), &format!("{header}{good}{row}"), "2", "1");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{row:?} accepted");
        assert!(
            err.contains("rays.csv:3:"),
            "{row:?}: no line number in {err}"
        );
        assert!(err.contains(expect), "{row:?}: {err}");
    }
    let out = eval_file(dir.path(), "x,y,z\n1,2,3\n", "2", "1");
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("rays.csv:1: header"));
    // r ≥ R: no hole.
    let out = eval_file(dir.path(), &format!("{header}{good}"), "1", "2");
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("must be > 1"));
    // --out is written atomically: a bad row leaves no partial output behind.
    let input = dir.path().join("rays.csv");
    std::fs::write(&input, format!("{header}{good}{good}1,2\n")).unwrap();
    let out_path = dir.path().join("out.csv");
    let out = run(&[
        "eval",
        "--major",
        "2",
        "--minor",
        "1",
        "--rays",
        input.to_str().unwrap(),
        "--out",
        out_path.to_str().unwrap(),
    ]);
    assert!(!out.status.success());
    assert!(
        !out_path.exists(),
        "a failed eval left {}",
        out_path.display()
    );
    // A missing file is named.
    let out = run(&[
        "eval",
        "--major",
        "2",
        "--minor",
        "1",
        "--rays",
        "/no/such.csv",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/no/such.csv"));
}

#[test]
fn good_input_round_trips() {
    let dir = tempfile::tempdir().unwrap();
    let rows = [
        [-5.0f32, 0.0, 0.0, 2.0, 0.0, 0.0], // through both tubes, non-unit direction
        [0.5, 10.0, 0.0, 0.0, -1.0, 0.0],   // down the hole
        [-6.0, 0.5, 0.0, 1.0, 0.0, 0.0],    // Eq. 35 counterexample
        [-5.0, 0.5, 2.0, 1.0, 0.0, 0.0],    // Eq. 105 counterexample
        [0.9, -3.0, 0.5, 0.01, 1.0, 0.0],   // Eq. 102 counterexample
        [5.0, 0.0, 0.0, 1.0, 0.0, 0.0],     // torus behind the ray
        [0.0, 5.0, 9.0, 0.3, -1.0, 0.2],    // far outside
    ];
    let mut csv = String::from("ox,oy,oz,dx,dy,dz\n");
    for r in &rows {
        csv.push_str(&format!(
            "{},{},{},{},{},{}\n",
            r[0], r[1], r[2], r[3], r[4], r[5]
        ));
    }
    let input = dir.path().join("rays.csv");
    let output = dir.path().join("out.csv");
    std::fs::write(&input, csv).unwrap();
    let out = run(&[
        "eval",
        "--major",
        "2",
        "--minor",
        "1",
        "--rays",
        input.to_str().unwrap(),
        "--out",
        output.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&output).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "index,oracle,margin,t_hit,none,sphere,aabb,cychosz,thick_cylinder,skala,\
         ellipsoid,quadric,discriminant,discriminant_f64"
    );
    let torus = Torus::canonical(2.0, 1.0).unwrap();
    let bounds = CullBounds::of(&torus);
    let mut n = 0;
    for (i, (line, r)) in lines.zip(&rows).enumerate() {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 4 + CullKind::TIMED.len(), "{line}");
        assert_eq!(f[0], i.to_string());
        let ray = Ray::new(
            r[..3].try_into().map(glam::Vec3::from_array).unwrap(),
            glam::Vec3::new(r[3], r[4], r[5]),
        )
        .unwrap();
        let label = classify(&torus, &ray);
        let class = match label.class {
            OracleClass::Hit => "hit",
            OracleClass::Miss => "miss",
            OracleClass::Ambiguous => "ambiguous",
        };
        assert_eq!(f[1], class, "{line}");
        assert_eq!(f[2].parse::<f64>().unwrap(), label.margin);
        match intersect(&torus, &ray) {
            Some(hit) => assert_eq!(f[3].parse::<f32>().unwrap(), hit.t),
            None => assert_eq!(f[3], ""),
        }
        for (j, cull) in CullKind::TIMED.iter().enumerate() {
            let keep = cull.keeps(&bounds, ray.origin(), ray.dir());
            assert_eq!(f[4 + j], if keep { "1" } else { "0" }, "{cull} on {line}");
        }
        n += 1;
    }
    assert_eq!(n, rows.len());
    // The first row hits the outer wall at x = −3: t = 1 in units of d = (2, 0, 0).
    let first: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(first[1], "hit");
    assert!((first[3].parse::<f32>().unwrap() - 1.0).abs() < 1e-5);
    // The hole row: skala rejects it, cychosz keeps it.
    let hole: Vec<&str> = text.lines().nth(2).unwrap().split(',').collect();
    assert_eq!((hole[1], hole[7], hole[9]), ("miss", "1", "0"));
    // quadric's hyperboloid and the discriminant reject it too.
    assert_eq!((hole[11], hole[12], hole[13]), ("0", "0", "0"));
}
