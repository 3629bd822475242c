//! A structured grid of depressed quartics with a **close pair of large roots** (issue 36,
//! item 4): roots `X` and `X + δ` with `X` from 1 to 10⁶ and `δ/X` from 10⁻³ to 10⁻⁷,
//! beside a complex pair or a second real pair centred at `−(X + δ/2)` (so that the roots
//! sum to 0), and the mirror image `x → −x` of each. `|p|` reaches 10¹⁴.
//!
//! **Reference.** Each quartic is built from its roots in double-double arithmetic and
//! rounded to f64 (`p`, `q`, `r` as stored); its reference roots are those of the
//! **stored** quartic, found by Newton's method in double-double from the constructed
//! roots (≈ 10⁻³⁰ relative, independent of the solver under test), and kept only where
//! the stored quartic still has the constructed number of real roots near them (each
//! reference root a sign change of `f`, evaluated in double-double).
//!
//! **Tolerance, from conditioning.** f64's Horner evaluation of `f` at `x` is off by at
//! most `γ₈·Σ|cᵢ||x|ⁱ ≈ 4ε·Σ|cᵢ||x|ⁱ`, so an f64 method that decides on `f` can only
//! be sure of a simple root to `4κε|x|`, `κ = Σ|cᵢ||x|ⁱ/(|x|·|f′(x)|)`; the tolerance is
//! four times that, `16κε|x|`, plus `8ε·X` (the nearest-root query's absolute accuracy at the
//! roots' scale `X = max(√|p|, ∛|q|, ∜|r|)`). A root whose tolerance reaches half-way to
//! its neighbour is **unresolved** (the f64 evaluation cannot tell the pair from a double
//! root or a complex pair) and is not scored. The example of the issue (`p, q, r =
//! −59369260987.89166, −5803400893965144.0, 1.9440159814205568e21`, roots 192 889.336 65
//! and 192 889.363 90, `κ = 7.7·10⁶`, half gap 41κε|x|) is resolved.
//!
//! **Scoring** (as `corpus/score.rs` scores the nearest root): for each reference root
//! `xᵢ`, the nearest root in `[lo, ∞)` with `lo` half-way from `xᵢ₋₁` (`−∞` for the
//! first). *Missed*: none, or one beyond `xᵢ + tol`; *spurious*: one below `xᵢ − tol`
//! (there is no root in `[lo, xᵢ)`). The all-roots solvers are scored on the same roots.
//!
//! **Counts** (docs/solver.md): before the fix of issue 36 (23698ab),
//! `nearest_root_depressed` missed 64 of the 926 scored roots and returned 22 spurious
//! ones, all at `δ/X = 10⁻⁷` or the example, at every `X` from 1 to 10⁶ (the failure was
//! the near-double decision, not the coefficients' size); now 0 and 0, as the all-roots
//! solvers were before and are now.

use super::corpus::score::nearest_unused;
use super::{first_root_depressed, nearest_root_depressed, solve_depressed_monic, solve_quartic};

const EPS: f64 = f64::EPSILON;

/// A double-double number `hi + lo`, `|lo| ≤ ulp(hi)/2`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Dd(f64, f64);

fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    Dd(s, (a - (s - bb)) + (b - bb))
}

impl Dd {
    fn from(x: f64) -> Dd {
        Dd(x, 0.0)
    }
    fn add(self, o: Dd) -> Dd {
        let s = two_sum(self.0, o.0);
        let t = two_sum(self.1, o.1);
        let s = two_sum(s.0, s.1 + t.0);
        two_sum(s.0, s.1 + t.1)
    }
    fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    fn sub(self, o: Dd) -> Dd {
        self.add(o.neg())
    }
    fn mul(self, o: Dd) -> Dd {
        let p = self.0 * o.0;
        let e = self.0.mul_add(o.0, -p);
        two_sum(p, e + (self.0 * o.1 + self.1 * o.0))
    }
    fn div(self, o: Dd) -> Dd {
        let q1 = self.0 / o.0;
        let r = self.sub(o.mul(Dd::from(q1)));
        let q2 = r.0 / o.0;
        let r = r.sub(o.mul(Dd::from(q2)));
        let q3 = r.0 / o.0;
        two_sum(q1, q2).add(Dd::from(q3))
    }
    fn f64(self) -> f64 {
        self.0 + self.1
    }
}

/// `f(x)` and `f′(x)` of `x⁴ + p x² + q x + r` in double-double.
fn eval_dd(p: f64, q: f64, r: f64, x: Dd) -> (Dd, Dd) {
    let mut f = Dd::from(1.0);
    let mut df = Dd::from(0.0);
    for c in [0.0, p, q, r] {
        df = df.mul(x).add(f);
        f = f.mul(x).add(Dd::from(c));
    }
    (f, df)
}

/// `Σ|cᵢ||x|ⁱ` in f64 (for the tolerance only).
fn magnitude(p: f64, q: f64, r: f64, x: f64) -> f64 {
    let ax = x.abs();
    ((ax * ax + p.abs()) * ax + q.abs()) * ax + r.abs()
}

/// One grid quartic: the stored `p, q, r`, its reference real roots (sorted) and the
/// roots' scale.
pub(super) struct Quartic {
    pub name: String,
    pub p: f64,
    pub q: f64,
    pub r: f64,
    pub roots: Vec<f64>,
    pub scale: f64,
}

/// The second pair around `c = −(X + δ/2)`.
#[derive(Debug, Clone, Copy)]
enum Second {
    /// `c ± i·η·X`.
    Complex(f64),
    /// `c ± ω·X`.
    Real(f64),
}

/// `x⁴ + p x² + q x + r` with roots `a`, `b`, `c ± w` (`w² = w2`, negative for a
/// complex pair), `c = −(a + b)/2`, exact in double-double, rounded once.
fn build(a: f64, b: f64, w2: Dd) -> (f64, f64, f64, Dd) {
    let (a, b) = (Dd::from(a), Dd::from(b));
    let c = a.add(b).mul(Dd::from(-0.5));
    // (x² − (a + b)x + ab)(x² − 2c x + c² − w²), with a + b = −2c.
    let (s1, p1) = (a.add(b), a.mul(b));
    let (s2, p2) = (c.mul(Dd::from(2.0)), c.mul(c).sub(w2));
    // x⁴ − (s1 + s2)x³ + (p1 + p2 + s1 s2)x² − (s1 p2 + s2 p1)x + p1 p2; s1 + s2 = 0.
    let p = p1.add(p2).add(s1.mul(s2));
    let q = s1.mul(p2).add(s2.mul(p1)).neg();
    let r = p1.mul(p2);
    (p.f64(), q.f64(), r.f64(), c)
}

/// Newton in double-double on the stored quartic from `x0`: the root it converges to
/// (to far below f64's resolution), or `None` if it does not settle.
fn newton_dd(p: f64, q: f64, r: f64, x0: Dd) -> Option<Dd> {
    let mut x = x0;
    let mut last = f64::INFINITY;
    for _ in 0..100 {
        let (f, df) = eval_dd(p, q, r, x);
        if f.0 == 0.0 {
            return Some(x);
        }
        let step = f.div(df);
        x = x.sub(step);
        let size = step.0.abs();
        // Converged to double-double's resolution, or stalled there (the evaluation's
        // rounding, 10⁻³²·Σ|cᵢ||x|ⁱ, over f′: far below f64's ulp of x).
        if size <= 1e-30 * x.0.abs() || (size <= 1e-22 * x.0.abs() && size >= 0.5 * last) {
            return Some(x);
        }
        last = size;
    }
    None
}

/// The sign of `f` in double-double at `x` (0 where it cannot tell).
fn sign_dd(p: f64, q: f64, r: f64, x: f64) -> f64 {
    let (f, _) = eval_dd(p, q, r, Dd::from(x));
    if f.0 == 0.0 { 0.0 } else { f.0.signum() }
}

/// The grid, with the example first.
pub(super) fn grid() -> Vec<Quartic> {
    let mut out = Vec::new();
    // The example: its reference roots are the two real ones (the other pair is
    // complex), found from the roots the issue quotes.
    let (p, q, r) = (
        -59369260987.89166,
        -5803400893965144.0,
        1.9440159814205568e21,
    );
    let roots = [192_889.336_66, 192_889.363_89]
        .map(|x| newton_dd(p, q, r, Dd::from(x)).expect("converges").f64());
    out.push(Quartic {
        name: "issue36_example".into(),
        p,
        q,
        r,
        roots: roots.to_vec(),
        scale: scale(p, q, r),
    });
    let seconds = [
        Second::Complex(0.01),
        Second::Complex(0.6),
        Second::Complex(10.0),
        Second::Real(0.5),
        Second::Real(3.0),
    ];
    for x_exp in 0..=6 {
        let big = 10f64.powi(x_exp);
        for rho_exp in 3..=7 {
            let delta = big * 10f64.powi(-rho_exp);
            for second in seconds {
                for mirror in [false, true] {
                    if let Some(quartic) = case(big, delta, second, mirror) {
                        out.push(quartic);
                    }
                }
            }
        }
    }
    out
}

fn scale(p: f64, q: f64, r: f64) -> f64 {
    p.abs()
        .sqrt()
        .max(q.abs().cbrt())
        .max(r.abs().sqrt().sqrt())
}

fn case(big: f64, delta: f64, second: Second, mirror: bool) -> Option<Quartic> {
    let (a, b) = (big, big + delta);
    let w2 = match second {
        Second::Complex(eta) => Dd::from(eta * big).mul(Dd::from(eta * big)).neg(),
        Second::Real(omega) => Dd::from(omega * big).mul(Dd::from(omega * big)),
    };
    let (p, q, r, c) = build(a, b, w2);
    let mut starts = vec![Dd::from(a), Dd::from(b)];
    if let Second::Real(omega) = second {
        let w = Dd::from(omega * big);
        starts.extend([c.sub(w), c.add(w)]);
    }
    let mut roots = Vec::new();
    for x0 in starts {
        roots.push(newton_dd(p, q, r, x0)?.f64());
    }
    roots.sort_by(f64::total_cmp);
    // The stored quartic must keep the constructed real roots apart: each a sign change,
    // alternating, of f in double-double (a pair that rounding made complex or merged is
    // left out of the grid).
    let sep_ok = roots.windows(2).all(|w| w[0] < w[1]);
    let signs_ok = roots.iter().enumerate().all(|(i, &x)| {
        let before = sign_dd(p, q, r, x.next_down());
        let after = sign_dd(p, q, r, x.next_up());
        // f > 0 left of the first root, alternating after each simple root.
        let want_before = if (roots.len() - i) % 2 == 0 {
            1.0
        } else {
            -1.0
        };
        before == want_before && after == -want_before
    });
    if !(sep_ok && signs_ok) {
        return None;
    }
    let (q, roots) = if mirror {
        (-q, roots.iter().rev().map(|x| -x).collect())
    } else {
        (q, roots)
    };
    let what = match second {
        Second::Complex(eta) => format!("complex {eta}X"),
        Second::Real(omega) => format!("real ±{omega}X"),
    };
    Some(Quartic {
        name: format!(
            "X={big:e} δ/X={:e} {what}{}",
            delta / big,
            if mirror { " mirrored" } else { "" }
        ),
        p,
        q,
        r,
        roots,
        scale: scale(p, q, r),
    })
}

/// The tolerance of `roots[i]` (see the module docs), or `None` where it is unresolved.
pub(super) fn tolerance(quartic: &Quartic, i: usize) -> Option<f64> {
    let Quartic { p, q, r, .. } = *quartic;
    let x = quartic.roots[i];
    let (_, df) = eval_dd(p, q, r, Dd::from(x));
    let kappa_eps_x = EPS * magnitude(p, q, r, x) / df.f64().abs();
    let tol = 16.0 * kappa_eps_x + 8.0 * EPS * quartic.scale;
    let gap = quartic
        .roots
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != i)
        .map(|(_, y)| (y - x).abs())
        .fold(f64::INFINITY, f64::min);
    (tol < 0.5 * gap).then_some(tol)
}

/// Missed and spurious roots of a solver over the grid, with a line for each.
#[derive(Debug, Default)]
pub(super) struct Tally {
    pub quartics: usize,
    pub scored: usize,
    pub unresolved: usize,
    pub missed: Vec<String>,
    pub spurious: Vec<String>,
    /// The largest error of a root found, over its tolerance.
    pub worst: f64,
}

impl Tally {
    pub(super) fn summary(&self, what: &str) -> String {
        format!(
            "{what}: {} quartics, {} roots scored ({} unresolved): {} missed, {} spurious; \
             the largest error of a root found {:.3} of its tolerance",
            self.quartics,
            self.scored,
            self.unresolved,
            self.missed.len(),
            self.spurious.len(),
            self.worst
        )
    }
}

/// Scores a nearest-root query (`nearest_root_depressed`, `first_root_depressed`) on the
/// grid.
pub(super) fn score_nearest(
    grid: &[Quartic],
    nearest: impl Fn(f64, f64, f64, f64, f64) -> Option<f64>,
) -> Tally {
    let mut tally = Tally::default();
    for quartic in grid {
        tally.quartics += 1;
        let Quartic { p, q, r, .. } = *quartic;
        for (i, &x) in quartic.roots.iter().enumerate() {
            let Some(tol) = tolerance(quartic, i) else {
                tally.unresolved += 1;
                continue;
            };
            tally.scored += 1;
            let lo = if i == 0 {
                f64::NEG_INFINITY
            } else {
                0.5 * quartic.roots[i - 1] + 0.5 * x
            };
            let got = nearest(p, q, r, lo, f64::INFINITY);
            let line = || {
                format!(
                    "{} (p, q, r = {p:?}, {q:?}, {r:?}): from {lo:e}: {got:?}, want {x:?} ± {tol:e}",
                    quartic.name
                )
            };
            match got {
                Some(g) if (g - x).abs() <= tol => {
                    tally.worst = tally.worst.max((g - x).abs() / tol)
                }
                Some(g) if g < x => tally.spurious.push(line()),
                _ => tally.missed.push(line()),
            }
        }
    }
    tally
}

/// Scores an all-roots solver on the grid: each scored root matched by a returned root
/// within its tolerance (each returned root used once); a returned root that matches no
/// reference root, resolved or not, is spurious.
pub(super) fn score_all(grid: &[Quartic], solve: impl Fn(&Quartic) -> Vec<f64>) -> Tally {
    let mut tally = Tally::default();
    for quartic in grid {
        tally.quartics += 1;
        let got = solve(quartic);
        let mut used = vec![false; got.len()];
        let line = |what: String| format!("{}: {what} in {got:?}", quartic.name);
        for (i, &x) in quartic.roots.iter().enumerate() {
            let Some(tol) = tolerance(quartic, i) else {
                tally.unresolved += 1;
                continue;
            };
            tally.scored += 1;
            match nearest_unused(&got, &used, x) {
                Some(k) if (got[k] - x).abs() <= tol => {
                    used[k] = true;
                    tally.worst = tally.worst.max((got[k] - x).abs() / tol);
                }
                _ => tally.missed.push(line(format!("root {x:?} ± {tol:e}"))),
            }
        }
        // An unresolved pair may come back as two roots or a double one anywhere near it.
        for (k, &g) in got.iter().enumerate() {
            if used[k] {
                continue;
            }
            let near_unresolved = quartic.roots.iter().enumerate().any(|(i, &x)| {
                tolerance(quartic, i).is_none()
                    && (g - x).abs() <= 1e-6 * quartic.scale.max(x.abs())
            });
            if !near_unresolved {
                tally.spurious.push(line(format!("{g:?}")));
            }
        }
    }
    tally
}

#[test]
fn close_pairs_of_large_roots_are_found_by_every_solver() {
    let grid = grid();
    let nearest = score_nearest(&grid, nearest_root_depressed);
    let first = score_nearest(&grid, first_root_depressed);
    let depressed = score_all(&grid, |c| {
        solve_depressed_monic(c.p, c.q, c.r).as_slice().to_vec()
    });
    let general = score_all(&grid, |c| {
        solve_quartic([1.0, 0.0, c.p, c.q, c.r]).as_slice().to_vec()
    });
    let largest_p = grid.iter().map(|c| c.p.abs()).fold(0.0, f64::max);
    println!("close-pair grid: |p| up to {largest_p:e}");
    for (what, tally) in [
        ("nearest_root_depressed", &nearest),
        ("first_root_depressed", &first),
        ("solve_depressed_monic", &depressed),
        ("solve_quartic", &general),
    ] {
        println!("{}", tally.summary(what));
        for l in tally.missed.iter().chain(&tally.spurious).take(40) {
            println!("  {l}");
        }
    }
    // Every constructed quartic kept its real roots apart through the rounding of p, q, r.
    assert_eq!(grid.len(), 1 + 7 * 5 * 5 * 2);
    assert!(largest_p > 1e11);
    for tally in [&nearest, &first, &depressed, &general] {
        assert!(
            tally.missed.is_empty() && tally.spurious.is_empty(),
            "{}",
            tally.summary("")
        );
    }
}
