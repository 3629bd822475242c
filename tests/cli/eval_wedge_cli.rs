//! `eval` on a pipe bend: after the culls' columns, the wedge's (`wedge` alone, then
//! `wedge+<cull>`), named in the header; a row the wedge rejects is never an oracle hit,
//! the wedge adds rejections to every cull, and `--exact f32` keeps the columns.

use crate::support::{arg, stdout, temp_path, torus_cull};
use torus_cull::{CullKind, Named};
use torus_cull_lab::eval::{bend_wedge_columns, output_header};

/// The quarter bend R = 4, r_min = 0.5, r_max = 1, φ from 0 to π/2.
const BEND: [&str; 8] = [
    "--major",
    "4",
    "--minor",
    "1",
    "--bore",
    "0.5",
    "--delta-phi",
    "1.5707963267948966",
];

/// `n` rays from the sphere of radius 12 about the centre toward random points of the
/// outer torus's box, from a fixed xorshift stream.
fn rays_csv(n: usize) -> String {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut csv = String::from("ox,oy,oz,dx,dy,dz\n");
    for _ in 0..n {
        let o = loop {
            let v = [next(), next(), next()];
            let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if len > 0.1 && len <= 1.0 {
                break v.map(|c| 12.0 * c / len);
            }
        };
        let target = [5.0 * next(), next(), 5.0 * next()];
        let d = [target[0] - o[0], target[1] - o[1], target[2] - o[2]];
        csv += &format!("{},{},{},{},{},{}\n", o[0], o[1], o[2], d[0], d[1], d[2]);
    }
    csv
}

/// `eval` of `csv` with `args`: its header and its rows, split.
fn eval(csv: &str, args: &[&str]) -> (String, Vec<Vec<String>>) {
    let (_dir, input) = temp_path("rays.csv");
    std::fs::write(&input, csv).unwrap();
    let mut all = vec!["eval", "--rays", arg(&input)];
    all.extend_from_slice(args);
    let o = torus_cull(&all);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = stdout(&o);
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_string();
    let rows = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    (header, rows)
}

#[test]
fn a_bends_rows_carry_the_wedge_and_a_wedge_rejected_ray_is_a_miss() {
    let wedge = bend_wedge_columns();
    assert_eq!(wedge[0], "wedge");
    assert_eq!(wedge[5], "wedge+skala");
    assert_eq!(wedge.len(), CullKind::TIMED.len());
    let (header, rows) = eval(&rays_csv(3000), &BEND);
    assert_eq!(header, format!("{},{}", output_header(), wedge.join(",")));
    let culls = CullKind::TIMED.len();
    let (mut hits, mut wedge_only) = (0, 0);
    for row in &rows {
        assert_eq!(row.len(), 4 + 2 * culls, "{row:?}");
        let keep = |col: usize| row[4 + col] == "1";
        for (j, (form, cull)) in wedge.iter().zip(CullKind::TIMED).enumerate() {
            // Conservative: behind the wedge too, a rejected row is not an oracle hit.
            if !keep(culls + j) {
                assert_ne!(row[1], "hit", "wedge form {form} rejected a hit: {row:?}");
            }
            // The wedge only adds rejections to a cull (`wedge` is `none` behind it).
            if !keep(j) {
                let name = cull.name();
                assert!(
                    !keep(culls + j),
                    "{form} kept what {name} rejected: {row:?}"
                );
            }
        }
        hits += usize::from(row[1] == "hit");
        let skala = CullKind::TIMED
            .iter()
            .position(|&c| c == CullKind::Skala)
            .unwrap();
        wedge_only += usize::from(keep(skala) && !keep(culls + skala));
    }
    // The rays test something: hits, and misses of the segment that only the wedge rejects.
    assert!(
        hits > 100 && wedge_only > 100,
        "hits {hits}, wedge only {wedge_only}"
    );
    // `--exact f32` keeps the columns, after `escalated`.
    let mut f32_args = BEND.to_vec();
    f32_args.extend(["--exact", "f32"]);
    let (header32, rows32) = eval(&rays_csv(50), &f32_args);
    assert!(header32.ends_with(&wedge.join(",")) && header32.contains(",t_hit,escalated,"));
    assert!(rows32.iter().all(|r| r.len() == 5 + 2 * culls));
}
