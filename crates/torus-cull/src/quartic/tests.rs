//! Root sets with known answers: distinct, double, triple and quadruple roots, complex
//! pairs, wide ranges, random sets.

use super::*;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

/// Coefficients of k·(t − a)(t − b)(t − c)(t − d).
fn from_roots(k: f64, rs: [f64; 4]) -> [f64; 5] {
    let mut c = [k, 0.0, 0.0, 0.0, 0.0];
    // Multiply by (t − ρ) one factor at a time: c holds the polynomial, highest first.
    let mut deg = 0;
    for rho in rs {
        deg += 1;
        for j in (1..=deg).rev() {
            c[j] -= rho * c[j - 1];
        }
    }
    c
}

/// Coefficients of (t² + b t + c)(t − x)(t − y).
fn from_pair_and_roots(b: f64, cq: f64, x: f64, y: f64) -> [f64; 5] {
    let l = [1.0, -(x + y), x * y];
    let qd = [1.0, b, cq];
    let mut c = [0.0; 5];
    for i in 0..3 {
        for j in 0..3 {
            c[i + j] += l[i] * qd[j];
        }
    }
    c
}

/// A line far from the torus gives x⁴ + p x² + q x + r ≈ (x² + p/2)² with tiny q: the
/// resolvent's top two roots nearly merge, and rounding once returned the isolated
/// root −√r, whose factors had real, spurious double roots (found by the BVH bench).
#[test]
fn near_square_without_real_roots_gives_none() {
    let got = solve_depressed_monic(4563.646856842148, 0.001742656689884825, 5206718.203343114);
    assert!(got.is_empty(), "{:?}", got.as_slice());
    let mut rng = Pcg64::seed_from_u64(77);
    for _ in 0..20_000 {
        let a: f64 = 10f64.powf(rng.random_range(-2.0..5.0));
        let eps: f64 = a * a * 10f64.powf(rng.random_range(-12.0..-2.0));
        let q: f64 = a.sqrt() * 10f64.powf(rng.random_range(-9.0..-3.0));
        // (x² + a)² + eps + q x: positive for every real x when q is this small.
        let (p, r) = (2.0 * a, a * a + eps);
        let min_f = (0..200)
            .map(|i| {
                let x = (i as f64 - 100.0) * a.sqrt() / 20.0;
                ((x * x + p) * x + q) * x + r
            })
            .fold(f64::INFINITY, f64::min);
        if min_f <= 0.0 {
            continue;
        }
        let got = solve_depressed_monic(p, q, r);
        assert!(got.is_empty(), "p={p} q={q} r={r}: {:?}", got.as_slice());
    }
}

fn sorted(mut v: [f64; 4]) -> [f64; 4] {
    v.sort_by(f64::total_cmp);
    v
}

/// [`assert_roots`] on the quartic `k·∏(t − ρ)` of `roots`: the roots back, in order.
fn assert_recovers(k: f64, roots: [f64; 4], tol: f64) {
    assert_roots(from_roots(k, roots), &sorted(roots), tol);
}

/// Asserts the solver returns exactly `want` (sorted) with |err| ≤ tol·max(1, |root|).
fn assert_roots(c: [f64; 5], want: &[f64], tol: f64) {
    let got = solve_quartic(c);
    let got = got.as_slice();
    assert_eq!(
        got.len(),
        want.len(),
        "c = {c:?}: got {got:?}, want {want:?}"
    );
    for (g, w) in got.iter().zip(want) {
        assert!(
            (g - w).abs() <= tol * w.abs().max(1.0),
            "c = {c:?}: got {got:?}, want {want:?} (tol {tol})"
        );
    }
}

#[test]
fn distinct_roots() {
    assert_recovers(1.0, [1.0, 2.0, 3.0, 4.0], 1e-13);
    assert_recovers(-3.0, [-2.5, 0.5, 0.0, 7.0], 1e-13);
    assert_recovers(1.0, [-1.0, -2.0, 1.0, 2.0], 1e-14);
    // Large shift: roots clustered far from 0 (the depression cancels; polish repairs it).
    assert_recovers(1.0, [1000.0, 1001.0, 1002.0, 1003.0], 1e-11);
}

#[test]
fn double_roots() {
    // Double roots are ill-conditioned: error ~ √ε ≈ 1.5e-8, asserted at 1e-6.
    assert_recovers(1.0, [1.0, 1.0, 2.0, 3.0], 1e-6);
    assert_recovers(1.0, [-1.0, 0.5, 3.0, 3.0], 1e-6);
    assert_recovers(2.0, [-4.0, 0.0, 0.0, 5.0], 1e-6);
    // Two double pairs, symmetric (the tangent-on-top torus case, q = 0) and not.
    assert_recovers(1.0, [-1.0, -1.0, 1.0, 1.0], 1e-12);
    assert_recovers(1.0, [-2.0, -2.0, 3.0, 3.0], 1e-6);
    assert_recovers(1.0, [0.3, 0.3, 1.7, 1.7], 1e-6);
}

#[test]
fn triple_and_quadruple_roots() {
    // Triple root: error ~ ε^(1/3) ≈ 6e-6; asserted at 1e-4. The cluster may come back
    // as one or three real roots (both are within rounding of the truth), but every
    // returned root must be close to a true one and the simple root must be there.
    for (rs, simple) in [([2.0, 2.0, 2.0, -1.0], -1.0), ([-1.0, 0.5, 0.5, 0.5], -1.0)] {
        let got = solve_quartic(from_roots(1.0, rs));
        let got = got.as_slice();
        assert!(got.len() == 2 || got.len() == 4, "{rs:?}: {got:?}");
        assert!(
            got.iter().any(|g| (g - simple).abs() < 1e-10),
            "{rs:?}: {got:?}"
        );
        for g in got {
            assert!(
                rs.iter().any(|w| (g - w).abs() < 1e-4),
                "{rs:?}: spurious {g} in {got:?}"
            );
        }
    }
    // Quadruple root: error ~ ε^(1/4) ≈ 1.2e-4; asserted at 1e-3.
    for a in [0.0, 1.0, -2.5] {
        let got = solve_quartic(from_roots(1.0, [a; 4]));
        let got = got.as_slice();
        assert!(!got.is_empty(), "quadruple {a}: no root");
        assert!(got.len() % 2 == 0, "quadruple {a}: {got:?}");
        for g in got {
            assert!((g - a).abs() < 1e-3, "quadruple {a}: {got:?}");
        }
    }
    // Exactly t⁴ = 0 and (t−1)⁴ come back as four roots.
    assert_roots([1.0, 0.0, 0.0, 0.0, 0.0], &[0.0; 4], 0.0);
    assert_eq!(solve_quartic(from_roots(1.0, [1.0; 4])).len(), 4);
}

#[test]
fn complex_pairs() {
    // (t² + 1)(t − 1)(t − 3): two real roots.
    assert_roots(from_pair_and_roots(0.0, 1.0, 1.0, 3.0), &[1.0, 3.0], 1e-13);
    // (t² − 2t + 5)(t + 2)(t − 0.5): pair 1 ± 2i.
    assert_roots(
        from_pair_and_roots(-2.0, 5.0, -2.0, 0.5),
        &[-2.0, 0.5],
        1e-13,
    );
    // Two complex pairs: (t² + 1)(t² + 2t + 2): no real root.
    let c = [1.0, 2.0, 3.0, 2.0, 2.0];
    assert!(solve_quartic(c).is_empty(), "{:?}", solve_quartic(c));
    // t⁴ + 1 and t⁴ + t² + 1: none.
    assert!(solve_quartic([1.0, 0.0, 0.0, 0.0, 1.0]).is_empty());
    assert!(solve_quartic([1.0, 0.0, 1.0, 0.0, 1.0]).is_empty());
    // Near-tangent miss: (t² + 1e-6)(t − 2)(t − 5): the pair ±1e-3 i is far above rounding.
    assert_roots(from_pair_and_roots(0.0, 1e-6, 2.0, 5.0), &[2.0, 5.0], 1e-13);
    // Near-tangent hit: (t² − 1e-6)(t − 2)(t − 5): roots ±1e-3 stay real and distinct.
    assert_roots(
        from_pair_and_roots(0.0, -1e-6, 2.0, 5.0),
        &[-1e-3, 1e-3, 2.0, 5.0],
        1e-12,
    );
}

#[test]
fn wide_dynamic_range_and_scaling() {
    // Roots over nine decades: each relative error ≤ 1e-12.
    let rs = [1e-6, 1e-2, 1e1, 1e3];
    let got = solve_quartic(from_roots(1.0, rs));
    assert_eq!(got.len(), 4, "{got:?}");
    for (g, w) in got.as_slice().iter().zip(rs) {
        assert!(((g - w) / w).abs() < 1e-12, "{got:?}");
    }
    // Scaling every root by 2^k and the leading coefficient by anything: same relative roots.
    for k in [-40, -10, 0, 10, 40] {
        let s = 2f64.powi(k);
        let rs = [-1.5 * s, 0.25 * s, 0.75 * s, 2.0 * s];
        let got = solve_quartic(from_roots(1e-7, rs));
        assert_eq!(got.len(), 4, "k = {k}: {got:?}");
        for (g, w) in got.as_slice().iter().zip(rs) {
            assert!(((g - w) / w).abs() < 1e-12, "k = {k}: {got:?}");
        }
    }
}

#[test]
fn depressed_monic_matches_general() {
    // x⁴ − 5x² + 4 = (x² − 1)(x² − 4), and a q ≠ 0 case built from roots summing to 0.
    let r = solve_depressed_monic(-5.0, 0.0, 4.0);
    assert_eq!(r.as_slice(), &[-2.0, -1.0, 1.0, 2.0]);
    let c = from_roots(1.0, [-3.0, -0.5, 1.0, 2.5]);
    assert_eq!(c[1], 0.0);
    let r = solve_depressed_monic(c[2], c[3], c[4]);
    let want = [-3.0, -0.5, 1.0, 2.5];
    assert_eq!(r.len(), 4);
    for (g, w) in r.as_slice().iter().zip(want) {
        assert!((g - w).abs() < 1e-14, "{r:?}");
    }
    // Tangent pair of double roots with rounding-level q (a horizontal torus ray).
    let r = solve_depressed_monic(-2.0, 3e-16, 1.0);
    assert_eq!(r.len(), 4, "{r:?}");
    for (g, w) in r.as_slice().iter().zip([-1.0, -1.0, 1.0, 1.0]) {
        assert!((g - w).abs() < 1e-7, "{r:?}");
    }
}

#[test]
fn bad_input_gives_no_roots() {
    assert!(solve_quartic([0.0, 1.0, 2.0, 3.0, 4.0]).is_empty());
    assert!(solve_quartic([1.0, f64::NAN, 0.0, 0.0, -1.0]).is_empty());
    assert!(solve_depressed_monic(f64::INFINITY, 0.0, 0.0).is_empty());
}

/// Condition-aware tolerance for a simple root w: ε·Σ|cᵢ wⁱ| / |f'(w)|.
fn cond_tol(c: &[f64; 5], w: f64) -> f64 {
    let (_, df) = eval(c, w);
    let mag = c.iter().fold(0.0, |acc, ci| acc * w.abs() + ci.abs());
    EPS * mag / df.abs()
}

#[test]
fn random_real_root_sets() {
    // 20 000 sets of four real roots in [−10, 10]: exactly four found, each within
    // 64·(ε·Σ|cᵢwⁱ|/|f'(w)|) + 1e-14 of the truth (the root's own condition number).
    let mut rng = Pcg64::seed_from_u64(0x7051_0001);
    let mut worst = 0.0f64;
    for _ in 0..20_000 {
        let rs = sorted([(); 4].map(|_| rng.random_range(-10.0..10.0)));
        let k = rng.random_range(0.1..10.0);
        let c = from_roots(k, rs);
        let got = solve_quartic(c);
        assert_eq!(got.len(), 4, "roots {rs:?}: got {got:?}");
        for (g, w) in got.as_slice().iter().zip(rs) {
            let tol = 64.0 * cond_tol(&c, w) + 1e-14;
            worst = worst.max((g - w).abs() / tol);
            assert!((g - w).abs() <= tol, "roots {rs:?}: got {got:?}, tol {tol}");
        }
    }
    assert!(worst <= 1.0);
}

#[test]
fn random_sets_with_complex_pairs() {
    // Two real roots and a pair α ± iβ with β ≥ 0.05: exactly the two real roots,
    // and four complex roots: none.
    let mut rng = Pcg64::seed_from_u64(0x7051_0002);
    for _ in 0..10_000 {
        let x = rng.random_range(-10.0..10.0);
        let y = rng.random_range(-10.0..10.0);
        let (x, y) = if x < y { (x, y) } else { (y, x) };
        let alpha: f64 = rng.random_range(-10.0..10.0);
        let beta: f64 = rng.random_range(0.05..5.0);
        let c = from_pair_and_roots(-2.0 * alpha, alpha * alpha + beta * beta, x, y);
        let got = solve_quartic(c);
        assert_eq!(got.len(), 2, "{x} {y} {alpha}±{beta}i: {got:?}");
        for (g, w) in got.as_slice().iter().zip([x, y]) {
            let tol = 64.0 * cond_tol(&c, w) + 1e-14;
            assert!((g - w).abs() <= tol, "{x} {y} {alpha}±{beta}i: {got:?}");
        }
        // (t² − 2αt + α² + β²)(t² − 2γt + γ² + δ²): no real roots.
        let gamma: f64 = rng.random_range(-10.0..10.0);
        let delta: f64 = rng.random_range(0.05..5.0);
        let (b1, c1) = (-2.0 * alpha, alpha * alpha + beta * beta);
        let (b2, c2) = (-2.0 * gamma, gamma * gamma + delta * delta);
        let c = [1.0, b1 + b2, c1 + c2 + b1 * b2, b1 * c2 + b2 * c1, c1 * c2];
        assert!(solve_quartic(c).is_empty(), "{c:?}: {:?}", solve_quartic(c));
    }
}

#[test]
fn random_double_roots_are_kept() {
    // (t − a)²(t − b)(t − c) with random a, b, c: the double root must not be lost.
    // A double root is √-conditioned: rounding the coefficients moves it by up to
    // √(2ε·Σ|cᵢaⁱ|/|f''(a)|); asserted within 8× that (+1e-12). Simple roots as above.
    let mut rng = Pcg64::seed_from_u64(0x7051_0003);
    for _ in 0..10_000 {
        let a = rng.random_range(-5.0..5.0);
        let b = rng.random_range(-5.0..5.0);
        let cc = rng.random_range(-5.0..5.0);
        let want = sorted([a, a, b, cc]);
        let c = from_roots(1.0, want);
        let got = solve_quartic(c);
        assert_eq!(got.len(), 4, "{want:?}: {got:?}");
        let mag = c.iter().fold(0.0, |acc, ci| acc * a.abs() + ci.abs());
        let d2 = 2.0 * ((a - b) * (a - cc)).abs();
        let tol_double = 8.0 * (2.0 * EPS * mag / d2).sqrt() + 1e-12;
        for (g, w) in got.as_slice().iter().zip(want) {
            let tol = if w == a {
                tol_double
            } else {
                64.0 * cond_tol(&c, w) + 1e-14
            };
            assert!((g - w).abs() <= tol, "{want:?}: {got:?}, tol {tol}");
        }
    }
}

#[test]
fn pure_powers_with_negative_constant_take_the_quadratic_in_t_squared() {
    // x⁴ − 16 (p = q = 0, r < 0) once gave ±1.07·10⁸, x⁴ − 1 gave ±5.3·10⁷. With any
    // leading coefficient, and shifted so that the depression produces q = 0 exactly.
    for (c, want) in [
        ([1.0, 0.0, 0.0, 0.0, -16.0], [-2.0, 2.0]),
        ([1.0, 0.0, 0.0, 0.0, -1.0], [-1.0, 1.0]),
        ([-3.0, 0.0, 0.0, 0.0, 48.0], [-2.0, 2.0]),
        // (t − 1)⁴ − 16 = t⁴ − 4t³ + 6t² − 4t − 15: roots 1 ± 2.
        ([1.0, -4.0, 6.0, -4.0, -15.0], [-1.0, 3.0]),
        // x⁴ − 5x² + 4 = (x² − 1)(x² − 4).
        ([1.0, 0.0, -5.0, 0.0, 4.0], [-2.0, 2.0]),
    ] {
        let roots = solve_quartic(c);
        let got = roots.as_slice();
        assert!(got.len() == 2 || got.len() == 4, "{c:?}: {roots:?}");
        assert!(
            (got[0] - want[0]).abs() < 1e-14 && (got[got.len() - 1] - want[1]).abs() < 1e-14,
            "{c:?}: {roots:?}"
        );
    }
    // The proptest's shrunk case: −2.24t⁴ + 1.1·10⁻³⁰⁸t² + 1.049 = 0.
    let roots = solve_quartic([
        -2.2430208849158286,
        0.0,
        1.1125369292536007e-308,
        0.0,
        1.0489973467731717,
    ]);
    let x = (1.0489973467731717f64 / 2.2430208849158286).sqrt().sqrt();
    assert_eq!(roots.len(), 2, "{roots:?}");
    assert!((roots.as_slice()[1] - x).abs() < 1e-15 && (roots.as_slice()[0] + x).abs() < 1e-15);
}

#[test]
fn huge_leading_terms_beside_a_tiny_tail_give_finite_roots() {
    // A proptest case: t²(c₄t² + c₃t + c₂) with c₃/c₄ ≈ 2^25 (the rescale's border) and
    // c₃ ≈ 2^837, solved by monotone pieces since c₀ = 0. Their quadratic squared c₃ to ∞
    // and returned [−∞, 0, 0, −0]. Roots: 0 three times (c₂/c₃ underflows) and −c₃/c₄.
    let c = [
        4.7044202022028847e244,
        1.5785414777425239e252,
        1.1125369292536007e-308,
        0.0,
        0.0,
    ];
    let roots = solve_quartic(c);
    let got = roots.as_slice();
    assert!(got.iter().all(|t| t.is_finite()), "{roots:?}");
    let far = -c[1] / c[0];
    assert!(((got[0] - far) / far).abs() < 1e-15, "{roots:?}");
    assert!(got[1..].iter().all(|t| *t == 0.0), "{roots:?}");
    // The same shape at every coefficient size that stays in range, and each side of the
    // border: the far root to full accuracy, the zero roots exact.
    for lead_exp in [-900, -500, -100, 0, 100, 500, 800, 870] {
        for ratio_exp in [-30, -25, 24, 25, 26, 30] {
            let lead = 1.25 * 2f64.powi(lead_exp);
            let c3 = lead * 1.75 * 2f64.powi(ratio_exp);
            let roots = solve_quartic([lead, c3, 0.0, 0.0, 0.0]);
            let got = roots.as_slice();
            let far = -c3 / lead;
            assert_eq!(got.len(), 4, "2^{lead_exp}, 2^{ratio_exp}: {roots:?}");
            assert!(got.iter().all(|t| t.is_finite()), "{roots:?}");
            let (zeros, rest): (Vec<f64>, Vec<f64>) = got.iter().partition(|t| **t == 0.0);
            assert_eq!((zeros.len(), rest.len()), (3, 1), "{roots:?}");
            assert!(((rest[0] - far) / far).abs() < 1e-15, "{roots:?}");
        }
    }
    // b² beyond f64 in a quadratic piece with real roots: (t − 2^500)(t + 2^-500)·t².
    let (u, v) = (2f64.powi(500), 2f64.powi(-500));
    let roots = solve_quartic([1.0, v - u, -u * v, 0.0, 0.0]);
    let got = roots.as_slice();
    assert!(got.iter().all(|t| t.is_finite()), "{roots:?}");
    assert!(got.iter().any(|t| ((t - u) / u).abs() < 1e-15), "{roots:?}");
    assert!(got.iter().any(|t| ((t + v) / v).abs() < 1e-12), "{roots:?}");
}

#[test]
fn structured_coefficient_grid_gives_finite_sorted_backward_stable_roots() {
    // Every quartic whose coefficients are 0 or ±1.5·2^e, e from tiny to huge: the zero
    // patterns, exact powers and extreme ratios that bit-pattern fuzzing rarely draws.
    // Each returned root must be finite, the list sorted, and each root a root within
    // rounding of the caller's quartic (backward error ≤ 10⁴ε of Σ|cᵢ||t|ⁱ).
    let mut values = vec![0.0];
    for e in [-1000, -30, 0, 30, 1000] {
        let v = 1.5 * 2f64.powi(e);
        values.extend([v, -v]);
    }
    let n = values.len();
    let mut checked = 0;
    for code in 0..n.pow(5) {
        let mut k = code;
        let c: [f64; 5] = std::array::from_fn(|_| {
            let v = values[k % n];
            k /= n;
            v
        });
        let roots = solve_quartic(c);
        let got = roots.as_slice();
        assert!(got.iter().all(|t| t.is_finite()), "{c:?}: {roots:?}");
        assert!(got.windows(2).all(|w| w[0] <= w[1]), "{c:?}: {roots:?}");
        for &t in got {
            let f = eval(&c, t).0.abs();
            let mag = c.iter().fold(0.0, |acc, ci| acc * t.abs() + ci.abs());
            // Where Σ overflows, f cannot be evaluated in f64: not checked.
            assert!(
                !mag.is_finite() || f <= 1e4 * EPS * mag,
                "{c:?}: root {t} has |f| = {f:e}, Σ = {mag:e}"
            );
        }
        checked += usize::from(c[0] != 0.0);
    }
    assert_eq!(checked, (n - 1) * n.pow(4));
}

#[test]
fn structured_depressed_grid_agrees_between_the_solvers() {
    // x⁴ + p x² + q x + r with p, q, r each 0 or ±1.5·2^e, e from tiny to huge: every
    // root finite, sorted and a root within rounding; the nearest root in [0, ∞), in
    // (−∞, 0] and in [−1, 1] is the all-roots solve's first root there, to 10⁻⁹ of the
    // roots' scale, or differs by a near-double pair within the nearest path's contract.
    let mut values = vec![0.0];
    for e in [-1000, -500, -100, -30, 0, 30, 100, 500, 1000] {
        let v = 1.5 * 2f64.powi(e);
        values.extend([v, -v]);
    }
    for &p in &values {
        for &q in &values {
            for &r in &values {
                let all = solve_depressed_monic(p, q, r);
                let got = all.as_slice();
                let c = [1.0, 0.0, p, q, r];
                assert!(got.iter().all(|x| x.is_finite()), "{c:?}: {all:?}");
                assert!(got.windows(2).all(|w| w[0] <= w[1]), "{c:?}: {all:?}");
                for &x in got {
                    let (f, df) = eval(&c, x);
                    let mag = c.iter().fold(0.0, |acc, ci| acc * x.abs() + ci.abs());
                    let f = f.abs() - df.abs() * 2.0 * f64::from_bits(1);
                    // Where Σ overflows, f cannot be evaluated in f64: not checked.
                    assert!(
                        !mag.is_finite() || f <= 1e4 * EPS * mag,
                        "{c:?}: root {x:e}: |f| = {f:e}, Σ = {mag:e}"
                    );
                }
                let first_in = |lo: f64, hi: f64| got.iter().copied().find(|&x| x >= lo && x <= hi);
                for (lo, hi) in [(0.0, f64::INFINITY), (f64::NEG_INFINITY, 0.0), (-1.0, 1.0)] {
                    let want = first_in(lo, hi);
                    for near in [
                        nearest_root_depressed(p, q, r, lo, hi),
                        first_root_depressed(p, q, r, lo, hi),
                    ] {
                        // Accurate to a few ε of the roots' scale X, in absolute terms: a root
                        // within that of the interval's end may fall either side of it.
                        let x = p
                            .abs()
                            .sqrt()
                            .max(q.abs().cbrt())
                            .max(r.abs().sqrt().sqrt());
                        let tol = 1e-9 * x;
                        let near_end = |b: f64| (b - lo).abs() <= tol || (b - hi).abs() <= tol;
                        let a_root_at_the_end =
                            |a: f64| near_end(a) && got.iter().any(|g| (g - a).abs() <= tol);
                        // The nearest-root path decides near-double pairs at the quartic's scale
                        // X (its contract: a few ε·X in absolute terms): it may return a root of
                        // a quartic within ε·X⁴ of this one, or miss a pair that such a change
                        // makes complex (two roots within 10⁻⁶X).
                        let phantom = |a: f64| eval(&c, a).0.abs() <= 1e3 * EPS * x.powi(4);
                        let paired =
                            |b: f64| got.iter().filter(|g| (*g - b).abs() <= 1e-6 * x).count() >= 2;
                        let same = match (near, want) {
                            (Some(a), Some(b)) => {
                                (a - b).abs() <= tol
                                    || a_root_at_the_end(a)
                                    || (a < b && phantom(a))
                                    || (a > b && (paired(b) || near_end(b)))
                            }
                            (Some(a), None) => a_root_at_the_end(a) || phantom(a),
                            (None, Some(b)) => near_end(b) || paired(b),
                            (None, None) => true,
                        };
                        assert!(
                            same,
                            "{c:?} in [{lo}, {hi}]: nearest {near:?}, all roots {all:?}"
                        );
                    }
                }
            }
        }
    }
}
