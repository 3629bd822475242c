//! The published quartic corpus (Algorithm 1010's accuracy cases, which include Flocke's
//! and Strobach's) and structured edge cases, scored against the real roots of each
//! quartic **as stored in f64**, derived exactly (`cases.py`, rational arithmetic and
//! Sturm sequences).
//!
//! **Well separated** means a relative condition number `κ = Σ|cᵢ||x|ⁱ/(|x|·|f′(x)|) ≤ 10⁴`:
//! rounding the coefficients by ε moves such a root by at most about κε ≈ 2·10⁻¹², and the
//! goal there is a relative error ≤ 10⁻¹⁰. A simple root with `κε ≤ 10⁻⁶` must still be
//! found, within `64κε`. A multiple root, one with `κε > 10⁻⁶`, or one whose tolerance
//! reaches half-way to its neighbour (a cluster: Strobach's triple and quadruple roots,
//! the double root 10⁷ of cases 20 and 21 split by rounding, roots 10⁻⁷ apart seen through
//! a depression), is **ill-conditioned**: the stored coefficients do not determine whether it is one real
//! root, several, or a complex pair, so the solver may return it either way; what it
//! returns there must still be a root within rounding (backward error ≤ 10³ε, relative to
//! `Σ|cᵢ||x|ⁱ`).
//!
//! *Missed*: a well-separated or moderately conditioned root with no returned root within
//! its tolerance. *Spurious*: a returned root that matches no reference root and is not a
//! root within rounding, or that duplicates a simple root already matched.

mod cases;
pub(super) mod score;

use super::{first_root_depressed, nearest_root_depressed, solve_depressed_monic, solve_quartic};
use cases::{CASES, Case};
use score::Score;

fn depressed(case: &Case) -> Option<[f64; 3]> {
    case.depressed
}

#[test]
fn solve_quartic_on_the_corpus() {
    let mut score = Score::default();
    for case in CASES {
        let got = solve_quartic(case.c);
        score.all_roots(case.name, &case.c, case.roots, got.as_slice());
    }
    score.assert_clean("solve_quartic");
    assert!(score.well >= 60, "{}", score.well);
}

#[test]
fn solve_depressed_monic_on_the_corpus() {
    let mut score = Score::default();
    for case in CASES {
        let Some([p, q, r]) = depressed(case) else {
            continue;
        };
        let got = solve_depressed_monic(p, q, r);
        score.all_roots(
            case.name,
            &[1.0, 0.0, p, q, r],
            case.depressed_roots,
            got.as_slice(),
        );
    }
    score.assert_clean("solve_depressed_monic");
}

/// Both nearest-root queries, each scored on its own: `nearest_root_depressed`, and the
/// bracketed walk `first_root_depressed` (issue 61) held to the same score.
#[test]
fn nearest_root_queries_on_the_corpus() {
    type Query = fn(f64, f64, f64, f64, f64) -> Option<f64>;
    let queries: [(&str, Query); 2] = [
        ("nearest_root_depressed", nearest_root_depressed),
        ("first_root_depressed", first_root_depressed),
    ];
    for (query_name, query) in queries {
        let mut score = Score::default();
        for case in CASES {
            let Some(pqr) = depressed(case) else {
                continue;
            };
            score.nearest(case.name, pqr, case.depressed_roots, query);
        }
        score.assert_clean(query_name);
    }
}
