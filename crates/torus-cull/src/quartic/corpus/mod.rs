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

use super::{eval, nearest_root_depressed, solve_depressed_monic, solve_quartic};
use cases::{CASES, Case};

const EPS: f64 = f64::EPSILON;
/// The relative error allowed on a well-separated root (`κ ≤ 10⁴`).
const WELL_SEPARATED_REL: f64 = 1e-10;
const KAPPA_WELL: f64 = 1e4;
/// Beyond this `κε` a simple root is ill-conditioned.
const KAPPA_EPS_ILL: f64 = 1e-6;
/// A returned root with `|f(x)| ≤ BACKWARD·ε·Σ|cᵢ||x|ⁱ` is a root of a quartic within
/// rounding of the stored one.
const BACKWARD: f64 = 1e3;

#[derive(Debug, Default)]
struct Score {
    roots: usize,
    well: usize,
    ill: usize,
    /// The cases with an ill-conditioned root, once each.
    ill_cases: Vec<&'static str>,
    missed: Vec<String>,
    spurious: Vec<String>,
    worst_well_rel: f64,
}

/// The tolerance of the reference root `reference[i]` = `(x, multiplicity, κ)`, or `None`
/// when it is ill-conditioned: a multiple root, `κε > 10⁻⁶`, or a tolerance that reaches
/// half-way to the next real root (a pair the stored coefficients cannot separate).
fn tolerance(reference: &[(f64, u32, f64)], i: usize) -> Option<f64> {
    let (x, m, kappa) = reference[i];
    if m > 1 || kappa * EPS > KAPPA_EPS_ILL {
        return None;
    }
    let rel = if kappa <= KAPPA_WELL {
        WELL_SEPARATED_REL
    } else {
        64.0 * kappa * EPS
    };
    // κ is absolute for a root at 0.
    let tol = if x == 0.0 {
        rel.max(64.0 * kappa * EPS)
    } else {
        rel * x.abs()
    };
    let gap = reference
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != i)
        .map(|(_, y)| (y.0 - x).abs())
        .fold(f64::INFINITY, f64::min);
    (tol < 0.5 * gap).then_some(tol)
}

fn backward_error(c: &[f64; 5], x: f64) -> f64 {
    let mag = c.iter().fold(0.0, |acc, ci| acc * x.abs() + ci.abs());
    let f = eval(c, x).0.abs();
    if f == 0.0 { 0.0 } else { f / mag }
}

impl Score {
    /// Scores `got` (sorted) against the case's reference roots of the quartic `c`.
    fn all_roots(
        &mut self,
        name: &'static str,
        c: &[f64; 5],
        reference: &[(f64, u32, f64)],
        got: &[f64],
    ) {
        let mut used = vec![false; got.len()];
        // Well-separated roots matched: a second returned root there is a duplicate.
        let mut matched_simple = Vec::new();
        for (i, &root) in reference.iter().enumerate() {
            self.roots += 1;
            let Some(tol) = tolerance(reference, i) else {
                self.ill += 1;
                if self.ill_cases.last() != Some(&name) {
                    self.ill_cases.push(name);
                }
                continue;
            };
            let x = root.0;
            let well = root.2 <= KAPPA_WELL;
            self.well += usize::from(well);
            let best = (0..got.len())
                .filter(|&k| !used[k])
                .min_by(|&a, &b| (got[a] - x).abs().total_cmp(&(got[b] - x).abs()));
            match best {
                Some(k) if (got[k] - x).abs() <= tol => {
                    used[k] = true;
                    if well {
                        matched_simple.push((x, tol));
                        let rel = (got[k] - x).abs() / x.abs().max(f64::MIN_POSITIVE);
                        self.worst_well_rel = self.worst_well_rel.max(rel);
                    }
                }
                _ => self.missed.push(format!(
                    "{name}: root {x:e} (κ {:e}) not in {got:?}",
                    root.2
                )),
            }
        }
        for (k, &g) in got.iter().enumerate() {
            if used[k] {
                continue;
            }
            let duplicate = matched_simple.iter().any(|&(x, tol)| (g - x).abs() <= tol);
            let backward = backward_error(c, g);
            if duplicate || backward.is_nan() || backward > BACKWARD * EPS {
                self.spurious.push(format!(
                    "{name}: {g:e} (backward error {backward:e}{}) in {got:?}",
                    if duplicate { ", a duplicate" } else { "" }
                ));
            }
        }
    }

    /// Scores `nearest_root_depressed` from just past each reference root's predecessor.
    fn nearest(&mut self, name: &'static str, pqr: [f64; 3], reference: &[(f64, u32, f64)]) {
        let [p, q, r] = pqr;
        let c = [1.0, 0.0, p, q, r];
        for (i, &root) in reference.iter().enumerate() {
            self.roots += 1;
            let Some(tol) = tolerance(reference, i) else {
                self.ill += 1;
                if self.ill_cases.last() != Some(&name) {
                    self.ill_cases.push(name);
                }
                continue;
            };
            let x = root.0;
            let well = root.2 <= KAPPA_WELL;
            self.well += usize::from(well);
            // Half-way from the previous reference root: no other real root in [lo, x).
            let lo = if i == 0 {
                f64::NEG_INFINITY
            } else {
                0.5 * reference[i - 1].0 + 0.5 * x
            };
            let got = nearest_root_depressed(p, q, r, lo, f64::INFINITY);
            match got {
                Some(g) if (g - x).abs() <= tol => {
                    if well {
                        let rel = (g - x).abs() / x.abs().max(f64::MIN_POSITIVE);
                        self.worst_well_rel = self.worst_well_rel.max(rel);
                    }
                }
                Some(g) if g < x && backward_error(&c, g) <= BACKWARD * EPS => {}
                Some(g) if g < x => self.spurious.push(format!(
                    "{name}: nearest from {lo:e} is {g:e} (backward error {:e}), want {x:e}",
                    backward_error(&c, g)
                )),
                _ => self.missed.push(format!(
                    "{name}: nearest from {lo:e} is {got:?}, want {x:e} (κ {:e})",
                    root.2
                )),
            }
        }
    }

    fn report(&self, what: &str) -> String {
        format!(
            "{what}: {} reference roots ({} well separated, {} ill-conditioned): missed {}, \
             spurious {}, worst relative error on well-separated roots {:e}; ill-conditioned \
             in {:?}",
            self.roots,
            self.well,
            self.ill,
            self.missed.len(),
            self.spurious.len(),
            self.worst_well_rel,
            self.ill_cases
        )
    }

    fn assert_clean(&self, what: &str) {
        println!("{}", self.report(what));
        let show = |v: &Vec<String>| v.join("\n");
        assert!(
            self.missed.is_empty() && self.spurious.is_empty(),
            "{}\nmissed:\n{}\nspurious:\n{}",
            self.report(what),
            show(&self.missed),
            show(&self.spurious)
        );
        assert!(self.worst_well_rel <= WELL_SEPARATED_REL);
    }
}

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

#[test]
fn nearest_root_depressed_on_the_corpus() {
    let mut score = Score::default();
    for case in CASES {
        let Some(pqr) = depressed(case) else {
            continue;
        };
        score.nearest(case.name, pqr, case.depressed_roots);
    }
    score.assert_clean("nearest_root_depressed");
}
