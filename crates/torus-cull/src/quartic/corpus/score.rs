//! How a solver's roots are scored against a corpus case's reference roots (see the
//! module docs of `super`). Self-contained (its own Horner), so that the lab's
//! `tests/solver/quartic_corpus_peers.rs` scores the peer crates with the same rules.

#![allow(
    dead_code,
    reason = "the library's tests and the lab's peer test each use a part"
)]

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
pub(crate) struct Score {
    pub(crate) roots: usize,
    pub(crate) well: usize,
    pub(crate) ill: usize,
    /// The cases with an ill-conditioned root, once each.
    pub(crate) ill_cases: Vec<&'static str>,
    pub(crate) missed: Vec<String>,
    pub(crate) spurious: Vec<String>,
    pub(crate) worst_well_rel: f64,
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

/// The index of the root of `got` nearest to `x` among those not `used` yet.
pub(crate) fn nearest_unused(got: &[f64], used: &[bool], x: f64) -> Option<usize> {
    (0..got.len())
        .filter(|&k| !used[k])
        .min_by(|&a, &b| (got[a] - x).abs().total_cmp(&(got[b] - x).abs()))
}

impl Score {
    /// Counts the reference root `reference[i]` of case `name`: its `(x, tol, well)`, or
    /// `None` for an ill-conditioned one, which is not scored.
    fn count(
        &mut self,
        name: &'static str,
        reference: &[(f64, u32, f64)],
        i: usize,
    ) -> Option<(f64, f64, bool)> {
        self.roots += 1;
        let Some(tol) = tolerance(reference, i) else {
            self.ill += 1;
            if self.ill_cases.last() != Some(&name) {
                self.ill_cases.push(name);
            }
            return None;
        };
        let (x, _, kappa) = reference[i];
        let well = kappa <= KAPPA_WELL;
        self.well += usize::from(well);
        Some((x, tol, well))
    }

    /// Scores `got` (sorted) against the case's reference roots of the quartic `c`.
    pub(crate) fn all_roots(
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
            let Some((x, tol, well)) = self.count(name, reference, i) else {
                continue;
            };
            match nearest_unused(got, &used, x) {
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
    pub(crate) fn nearest(
        &mut self,
        name: &'static str,
        pqr: [f64; 3],
        reference: &[(f64, u32, f64)],
        nearest_root: impl Fn(f64, f64, f64, f64, f64) -> Option<f64>,
    ) {
        let [p, q, r] = pqr;
        let c = [1.0, 0.0, p, q, r];
        for (i, &root) in reference.iter().enumerate() {
            let Some((x, tol, well)) = self.count(name, reference, i) else {
                continue;
            };
            // Half-way from the previous reference root: no other real root in [lo, x).
            let lo = if i == 0 {
                f64::NEG_INFINITY
            } else {
                0.5 * reference[i - 1].0 + 0.5 * x
            };
            let got = nearest_root(p, q, r, lo, f64::INFINITY);
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

    pub(crate) fn report(&self, what: &str) -> String {
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

    pub(crate) fn assert_clean(&self, what: &str) {
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

/// `f(x)` and `f′(x)` for `c = [c4, c3, c2, c1, c0]`, Horner.
fn eval(c: &[f64; 5], x: f64) -> (f64, f64) {
    let mut f = c[0];
    let mut df = 0.0;
    for &ci in &c[1..] {
        df = df * x + f;
        f = f * x + ci;
    }
    (f, df)
}
