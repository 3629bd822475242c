//! The peer crates of the solver bench on the library's quartic corpus
//! (`crates/torus-cull/src/quartic/corpus/`: Algorithm 1010's accuracy cases and the
//! structured edge cases, reference roots of the stored f64 quartics derived exactly),
//! scored with the library's own rules (`corpus/score.rs`): where `kurbo` and `polycool`
//! stand beside ours. Printed with `--nocapture`; ours must be clean (as the library's
//! tests assert), the peers' counts are reported, not asserted.

#[path = "../../crates/torus-cull/src/quartic/corpus/cases.rs"]
mod cases;
#[path = "../../crates/torus-cull/src/quartic/corpus/score.rs"]
mod score;

use cases::CASES;
use score::Score;
use torus_cull::quartic::{nearest_root_depressed, solve_depressed_monic, solve_quartic};

/// `kurbo::common::solve_quartic` (Algorithm 1010) on `[c4, c3, c2, c1, c0]`: its
/// arguments run from the constant up; its roots sorted.
fn kurbo_all(c: &[f64; 5]) -> Vec<f64> {
    let mut r: Vec<f64> = kurbo::common::solve_quartic(c[4], c[3], c[2], c[1], c[0]).to_vec();
    r.sort_by(f64::total_cmp);
    r
}

/// `polycool` 0.4's roots in `[−B, B]` (B = 1 + max|cᵢ/c₄|, Cauchy's bound: every root)
/// to the last bit (x_error = 0: it stops at adjacent floats).
fn polycool_all(c: &[f64; 5]) -> Vec<f64> {
    let bound = 1.0 + c[1..].iter().map(|x| (x / c[0]).abs()).fold(0.0, f64::max);
    polycool::Quartic::new([c[4], c[3], c[2], c[1], c[0]])
        .roots_between(-bound, bound, 0.0)
        .to_vec()
}

fn nearest_of(roots: &[f64], lo: f64, hi: f64) -> Option<f64> {
    roots
        .iter()
        .copied()
        .filter(|&x| x >= lo && x <= hi)
        .min_by(f64::total_cmp)
}

#[test]
fn peers_on_the_quartic_corpus() {
    type All = fn(&[f64; 5]) -> Vec<f64>;
    let solvers: [(&str, All); 3] = [
        ("torus_cull", |c| solve_quartic(*c).as_slice().to_vec()),
        ("kurbo_0.13", kurbo_all),
        ("polycool_0.4", polycool_all),
    ];
    let mut lines = Vec::new();
    for (name, solve) in solvers {
        // The general form.
        let mut general = Score::default();
        for case in CASES {
            general.all_roots(case.name, &case.c, case.roots, &solve(&case.c));
        }
        // The depressed form, all roots and the nearest root (picked from all roots for
        // the peers).
        let (mut depressed, mut nearest) = (Score::default(), Score::default());
        for case in CASES {
            let Some([p, q, r]) = case.depressed else {
                continue;
            };
            let c = [1.0, 0.0, p, q, r];
            let all = if name == "torus_cull" {
                solve_depressed_monic(p, q, r).as_slice().to_vec()
            } else {
                solve(&c)
            };
            depressed.all_roots(case.name, &c, case.depressed_roots, &all);
            if name == "torus_cull" {
                nearest.nearest(
                    case.name,
                    [p, q, r],
                    case.depressed_roots,
                    nearest_root_depressed,
                );
            } else {
                nearest.nearest(
                    case.name,
                    [p, q, r],
                    case.depressed_roots,
                    |_, _, _, lo, hi| nearest_of(&all, lo, hi),
                );
            }
        }
        for (form, score) in [
            ("general", &general),
            ("depressed", &depressed),
            ("nearest", &nearest),
        ] {
            lines.push(format!(
                "| {name} | {form} | {} | {} | {} | {} | {} | {:.1e} |",
                score.roots,
                score.well,
                score.ill,
                score.missed.len(),
                score.spurious.len(),
                score.worst_well_rel
            ));
            if name != "torus_cull" && !(score.missed.is_empty() && score.spurious.is_empty()) {
                println!(
                    "{name} {form}:\n  {}\n  {}",
                    score.missed.join("\n  "),
                    score.spurious.join("\n  ")
                );
            }
            if name == "torus_cull" {
                score.assert_clean(form);
            }
        }
    }
    println!(
        "| solver | form | roots | well separated | ill | missed | spurious | worst rel. error (well sep.) |\n|---|---|---|---|---|---|---|---|\n{}",
        lines.join("\n")
    );
}
