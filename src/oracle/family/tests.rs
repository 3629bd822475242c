//! The family oracle on hand-derived lines for every kind of shape, against its second
//! method on random lines, and against the ring oracle where a = b.

use super::line::Line;
use super::*;
pub(super) use crate::oracle::tests::unit;
use crate::oracle::tests::{
    Frame, GRAZING_PUSHES, axis_kind, far_kind, parallel_kind, random_back_and_reach, uniform_kind,
};
use crate::oracle::{AMBIGUITY_REL, reference_roots};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

const INF: f64 = f64::INFINITY;

/// (R, a, b): rings, a horn and its taller twin, spindles (down to ν = 0.01).
pub(super) const SHAPES: [(f64, f64, f64); 12] = [
    (4.0, 1.0, 1.0),
    (4.0, 1.0, 0.25),
    (4.0, 1.0, 4.0),
    (2.0, 1.0, 0.5),
    (1.0, 1.0, 1.0),
    (1.0, 1.0, 2.0),
    (0.75, 1.0, 1.0),
    (0.5, 1.0, 0.5),
    (0.5, 1.0, 2.0),
    (0.3, 1.0, 0.25),
    (0.1, 1.0, 4.0),
    (0.01, 1.0, 1.0),
];

pub(super) const SCALES: [f64; 3] = [1e-3, 1.0, 1e3];

/// Every shape at every scale, shape by shape.
pub(super) fn shapes_and_scales() -> impl Iterator<Item = ((f64, f64, f64), f64)> {
    SHAPES
        .into_iter()
        .flat_map(|shape| SCALES.map(|k| (shape, k)))
}

/// Every shape at every scale k, canonically posed and then randomly posed (the random
/// poses drawn from `seed`, one after the other): (pose, k, posed).
pub(super) fn poses_both_ways(seed: u64) -> impl Iterator<Item = (Pose, f64, bool)> {
    let mut rng = Pcg64::seed_from_u64(seed);
    shapes_and_scales()
        .flat_map(|(shape, k)| [false, true].map(|posed| (shape, k, posed)))
        .map(move |(shape, k, posed)| (Pose::posed_or_not(posed, &mut rng, shape, k), k, posed))
}

/// Every shape at every scale k, canonically posed: (pose, k).
pub(super) fn canonical_poses() -> impl Iterator<Item = (Pose, f64)> {
    shapes_and_scales().map(|(shape, k)| (Pose::canonical(shape, k), k))
}

/// A shape scaled by k, with a pose: its frame and its radii.
#[derive(Clone, Copy, Debug)]
pub(super) struct Pose {
    pub(super) frame: Frame,
    pub(super) big: f64,
    pub(super) ra: f64,
    pub(super) ax: f64,
}

impl Pose {
    pub(super) fn canonical((big, ra, ax): (f64, f64, f64), k: f64) -> Pose {
        Pose {
            frame: Frame::CANONICAL,
            big: big * k,
            ra: ra * k,
            ax: ax * k,
        }
    }
    /// [`Pose::random`] where `posed`, else [`Pose::canonical`] (drawing nothing).
    fn posed_or_not(posed: bool, rng: &mut Pcg64, shape: (f64, f64, f64), k: f64) -> Pose {
        if posed {
            Pose::random(rng, shape, k)
        } else {
            Pose::canonical(shape, k)
        }
    }
    pub(super) fn random(rng: &mut Pcg64, shape: (f64, f64, f64), k: f64) -> Pose {
        Pose {
            frame: Frame::random(rng, k),
            ..Pose::canonical(shape, k)
        }
    }
    /// The query for a line given in the torus frame.
    pub(super) fn q(&self, o: DVec3, d: DVec3) -> FamilyQuery {
        FamilyQuery::new(
            self.frame.c,
            self.frame.a,
            self.big,
            self.ra,
            self.ax,
            self.frame.point(o),
            self.frame.dir(d),
            -INF,
            INF,
        )
    }
    pub(super) fn size(&self) -> f64 {
        self.big + self.ra.max(self.ax)
    }
    pub(super) fn band(&self) -> f64 {
        AMBIGUITY_REL * self.size()
    }
    pub(super) fn min_ab(&self) -> f64 {
        self.ra.min(self.ax)
    }
    pub(super) fn is_ring(&self) -> bool {
        self.big > self.ra
    }
    pub(super) fn is_horn(&self) -> bool {
        self.big == self.ra
    }
    /// The surface point at tube angle θ, meridian φ (torus frame), with the unit outward
    /// normal; for a spindle θ must keep ρ = R + a cos θ ≥ 0.
    pub(super) fn surface(&self, phi: f64, theta: f64) -> (DVec3, DVec3) {
        let rho = self.big + self.ra * theta.cos();
        let y = self.ax * theta.sin();
        let er = DVec3::new(phi.cos(), 0.0, phi.sin());
        let n = er * (theta.cos() / self.ra) + DVec3::Y * (theta.sin() / self.ax);
        (er * rho + DVec3::Y * y, n.normalize())
    }
}

/// Asserts the crossings' passages and their t (each within `tol`).
#[track_caller]
fn assert_crossings(got: &[Crossing], want: &[(f64, Passage)], tol: f64, ctx: &str) {
    assert_eq!(got.len(), want.len(), "{ctx}: {got:?} want {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert_eq!(g.passage, w.1, "{ctx}: {got:?} want {want:?}");
        assert!((g.t - w.0).abs() <= tol, "{ctx}: {got:?} want {want:?}");
    }
}

use Passage::{Entering as In, Leaving as Out, Touching as Touch};

#[test]
fn rays_along_the_axis() {
    for (p, k, posed) in poses_both_ways(1) {
        let q = p.q(DVec3::new(0.0, 10.0 * k, 0.0), DVec3::NEG_Y);
        let ctx = format!("{p:?}");
        let l = q.classify();
        // On the axis ρ = 0: E = √((R/a)² + (y/b)²), least R/a at y = 0.
        let want = (p.big / p.ra - 1.0) * p.min_ab();
        let tol = 1e-14 * p.size();
        assert!((l.margin - want).abs() <= tol, "{ctx} {l:?}");
        let class = if p.is_ring() {
            OracleClass::Miss
        } else if p.is_horn() {
            OracleClass::Ambiguous
        } else {
            OracleClass::Hit
        };
        assert_eq!(l.class, class, "{ctx}");
        assert!(
            (q.margin_by_sampling() - want).abs() <= 1e-12 * p.size(),
            "{ctx}"
        );
        let got = q.crossings();
        if p.is_ring() {
            assert!(got.is_empty(), "{ctx} {got:?}");
        } else if p.is_horn() {
            // The centre, E = 1 exactly in the canonical frame.
            if !posed {
                assert_crossings(&got, &[(10.0 * k, Touch)], 0.0, &ctx);
            }
        } else {
            // The apple's dimples: y = ±b √(1 − (R/a)²).
            let y0 = p.ax * (1.0 - (p.big / p.ra).powi(2)).sqrt();
            let want = [(10.0 * k - y0, In), (10.0 * k + y0, Out)];
            assert_crossings(&got, &want, 1e-14 * 10.0 * k, &ctx);
        }
    }
}

#[test]
fn equatorial_rays_through_the_centre() {
    for (p, k, posed) in poses_both_ways(2) {
        let d = if posed {
            DVec3::new(0.6, 0.0, 0.8)
        } else {
            DVec3::X
        };
        let (big, ra) = (p.big, p.ra);
        let o = -10.0 * k * d;
        let q = p.q(o, d);
        let ctx = format!("{p:?}");
        let l = q.classify();
        assert_eq!(l.class, OracleClass::Hit, "{ctx}");
        let tol = 1e-14 * p.size();
        assert!((l.margin + p.min_ab()).abs() <= tol, "{ctx} {l:?}");
        let c = 10.0 * k;
        let want: Vec<(f64, Passage)> = if p.is_ring() {
            vec![
                (c - big - ra, In),
                (c - big + ra, Out),
                (c + big - ra, In),
                (c + big + ra, Out),
            ]
        } else if p.is_horn() {
            vec![(c - big - ra, In), (c, Touch), (c + big + ra, Out)]
        } else {
            // Only ρ = R + a: the lemon's ρ = a − R is inside the apple.
            vec![(c - big - ra, In), (c + big + ra, Out)]
        };
        let got = q.crossings();
        if posed && p.is_horn() {
            // Rounding of the pose decides whether the centre is touched.
            assert!(got.len() == 2 || got.len() == 3, "{ctx} {got:?}");
            continue;
        }
        assert_crossings(&got, &want, 1e-14 * c, &ctx);
        if p.big < p.ra {
            let lemon = ra - big;
            for t in [c - lemon, c + lemon] {
                assert!(got.iter().all(|x| (x.t - t).abs() > 1e-3 * k), "{ctx}");
            }
        }
    }
}

#[test]
fn rays_over_the_top_of_the_tube() {
    for (p, k) in canonical_poses() {
        let (big, ra, ax) = (p.big, p.ra, p.ax);
        for delta in [0.0, 1e-12, -1e-12, 1e-6, -1e-6, 1e-3, -1e-3] {
            let h = ax * (1.0 + delta);
            let ctx = format!("{p:?} delta {delta}");
            let want_margin = delta * p.min_ab();
            let class = if want_margin.abs() <= p.band() {
                OracleClass::Ambiguous
            } else if delta < 0.0 {
                OracleClass::Hit
            } else {
                OracleClass::Miss
            };
            // Across the hole (through the axis) and along the circle at ρ = R.
            let across = p.q(DVec3::new(-10.0 * k, h, 0.0), DVec3::X);
            let along = p.q(DVec3::new(big, h, -10.0 * k), DVec3::Z);
            for (name, q) in [("across", across), ("along", along)] {
                let l = q.classify();
                let tol = 1e-15 * p.size();
                assert!((l.margin - want_margin).abs() <= tol, "{ctx} {name} {l:?}");
                assert_eq!(l.class, class, "{ctx} {name}");
            }
            let c = 10.0 * k;
            // E = √(((ρ − R)/a)² + (1 + δ)²) = 1 at |ρ − R| = a √(1 − (1 + δ)²).
            let w = ra * (1.0 - (1.0 + delta).powi(2)).max(0.0).sqrt();
            let (want_across, want_along): (Vec<_>, Vec<_>) = if delta == 0.0 {
                (vec![(c - big, Touch), (c + big, Touch)], vec![(c, Touch)])
            } else if delta > 0.0 {
                (vec![], vec![])
            } else {
                let z = ((big + w).powi(2) - big * big).sqrt();
                // Where the chord's half-width w passes R (a fat spindle, near its top) the
                // two stretches meet at the axis: one, |x| < R + w.
                let across = if w > big {
                    vec![(c - big - w, In), (c + big + w, Out)]
                } else {
                    vec![
                        (c - big - w, In),
                        (c - big + w, Out),
                        (c + big - w, In),
                        (c + big + w, Out),
                    ]
                };
                (across, vec![(c - z, In), (c + z, Out)])
            };
            // A crossing near a tangency moves by rounding/√|δ|.
            let tol = 1e-15 * c / delta.abs().max(1e-6).sqrt() * 10.0;
            if delta.abs() != 1e-12 {
                assert_crossings(&across.crossings(), &want_across, tol, &ctx);
                assert_crossings(&along.crossings(), &want_along, tol, &ctx);
            }
        }
    }
}

#[test]
fn lines_parallel_to_the_axis() {
    for (p, k) in canonical_poses() {
        let (big, ra, ax) = (p.big, p.ra, p.ax);
        let mut cs = vec![
            big,
            big + 0.5 * ra,
            big + ra * (1.0 + 1e-3),
            2.0 * (big + ra),
        ];
        if p.is_ring() {
            // Through the hole.
            cs.push(0.5 * (big - ra));
        } else {
            cs.push(0.1 * big);
        }
        for c in cs {
            let q = p.q(DVec3::new(c, 10.0 * k, 0.0), DVec3::NEG_Y);
            let ctx = format!("{p:?} c {c}");
            let r = (c - big).abs() / ra;
            let l = q.classify();
            let want = (r - 1.0) * p.min_ab();
            assert!((l.margin - want).abs() <= 1e-14 * p.size(), "{ctx} {l:?}");
            let got = q.crossings();
            if r < 1.0 {
                let y0 = ax * ((1.0 - r) * (1.0 + r)).sqrt();
                let want = [(10.0 * k - y0, In), (10.0 * k + y0, Out)];
                assert_crossings(&got, &want, 1e-14 * 10.0 * k, &ctx);
            } else {
                assert!(got.is_empty(), "{ctx} {got:?}");
            }
        }
    }
}

#[test]
fn the_horns_centre_point() {
    for shape in SHAPES.into_iter().filter(|s| s.0 == s.1) {
        for k in SCALES {
            let p = Pose::canonical(shape, k);
            let (ra, ax) = (p.ra, p.ax);
            let ctx = format!("{p:?}");
            // From the centre outward in the equatorial plane: inside at once.
            let q = p.q(DVec3::ZERO, DVec3::X).over(0.0, INF);
            let l = q.classify();
            assert_eq!(l.class, OracleClass::Hit, "{ctx}");
            assert!((l.margin + p.min_ab()).abs() <= 1e-15 * p.size(), "{ctx}");
            assert_crossings(
                &q.crossings(),
                &[(0.0, Touch), (2.0 * ra, Out)],
                1e-15,
                &ctx,
            );
            assert_eq!(q.first_crossing(), Some(0.0));
            // Along the axis: only the centre, a touch; ambiguous.
            let q = p.q(DVec3::ZERO, DVec3::Y);
            assert_eq!(q.classify().class, OracleClass::Ambiguous, "{ctx}");
            assert_crossings(&q.crossings(), &[(0.0, Touch)], 0.0, &ctx);
            // The diagonal of a meridian plane: into both tubes through the centre, where
            // it touches; leaves where ((ρ − a)/a)² + (ρ/b)² = 1, ρ = 2/(a(1/a² + 1/b²)).
            let d = DVec3::new(1.0, 1.0, 0.0) / 2f64.sqrt();
            let q = p.q(DVec3::ZERO, d);
            let rho = 2.0 / (ra * (1.0 / (ra * ra) + 1.0 / (ax * ax)));
            let t = rho * 2f64.sqrt();
            assert_eq!(q.classify().class, OracleClass::Hit, "{ctx}");
            let want = [(-t, In), (0.0, Touch), (t, Out)];
            assert_crossings(&q.crossings(), &want, 1e-15 * t * 4.0, &ctx);
        }
    }
}

#[test]
fn far_origins_keep_their_lines() {
    let mut rng = Pcg64::seed_from_u64(3);
    for (p, k) in canonical_poses() {
        let far = 1e6 * p.big;
        // Exact: along the equator and down the axis from 10⁶ R.
        let q = p.q(DVec3::new(-far, 0.0, 0.0), DVec3::X);
        let near = p.q(DVec3::new(-10.0 * k, 0.0, 0.0), DVec3::X);
        let shift = far - 10.0 * k;
        let ctx = format!("{p:?}");
        let (lf, ln) = (q.classify(), near.classify());
        assert!((lf.margin - ln.margin).abs() <= 1e-15 * p.size(), "{ctx}");
        let (cf, cn) = (q.crossings(), near.crossings());
        assert_eq!(cf.len(), cn.len(), "{ctx} {cf:?} {cn:?}");
        for (a, b) in cf.iter().zip(&cn) {
            assert_eq!(a.passage, b.passage);
            assert!((a.t - shift - b.t).abs() <= 1e-15 * far * 4.0, "{ctx}");
        }
        let q = p.q(DVec3::new(0.0, far, 0.0), DVec3::NEG_Y);
        let want = (p.big / p.ra - 1.0) * p.min_ab();
        assert!(
            (q.classify().margin - want).abs() <= 1e-14 * p.size(),
            "{ctx}"
        );
        // Random lines through a point near the torus, from 10⁶ R away: the same
        // margin and crossings as from close by, within the far origin's rounding.
        for _ in 0..40 {
            let u = unit(&mut rng);
            let target = unit(&mut rng) * p.size() * rng.random::<f64>();
            let o_far = target - far * u;
            let o_near = target - 3.0 * p.size() * u;
            let (qf, qn) = (p.q(o_far, u), p.q(o_near, u));
            let (lf, ln) = (qf.classify(), qn.classify());
            let tol = 1e-15 * far * 8.0 * (p.ra.max(p.ax) / p.min_ab());
            assert!((lf.margin - ln.margin).abs() <= tol, "{ctx} {lf:?} {ln:?}");
            if lf.margin.abs() > tol + p.band() && ln.margin.abs() > tol + p.band() {
                assert_eq!(lf.class, ln.class, "{ctx}");
                let (cf, cn) = (qf.crossings(), qn.crossings());
                let ends = |c: &[Crossing]| c.iter().filter(|x| x.passage != Touch).count();
                assert_eq!(ends(&cf), ends(&cn), "{ctx} {cf:?} {cn:?}");
            }
            let mf = qf.margin_by_sampling();
            assert!(
                (mf - lf.margin).abs() <= 1e-9 * p.size(),
                "{ctx} {lf:?} {mf}"
            );
        }
    }
}

#[test]
fn margins_scale_with_the_torus() {
    let mut rng = Pcg64::seed_from_u64(4);
    for shape in SHAPES {
        for _ in 0..100 {
            let o = unit(&mut rng) * 3.0 * rng.random::<f64>() * (shape.0 + shape.2);
            let d = unit(&mut rng);
            let one = Pose::canonical(shape, 1.0).q(o, d);
            let l1 = one.classify();
            let c1 = one.crossings();
            for k in SCALES {
                let q = Pose::canonical(shape, k).q(o * k, d);
                let l = q.classify();
                assert!(
                    (l.margin - k * l1.margin).abs() <= 1e-13 * k,
                    "{shape:?} {k}"
                );
                if l1.class != OracleClass::Ambiguous {
                    assert_eq!(l.class, l1.class);
                    let ends = |c: &[Crossing]| -> Vec<f64> {
                        c.iter()
                            .filter(|x| x.passage != Touch)
                            .map(|x| x.t)
                            .collect()
                    };
                    let (c, c1) = (ends(&q.crossings()), ends(&c1));
                    assert_eq!(c.len(), c1.len(), "{shape:?} {k} {c:?} {c1:?}");
                    for (a, b) in c.iter().zip(&c1) {
                        assert!((a - k * b).abs() <= 1e-12 * k, "{shape:?} {k}");
                    }
                }
            }
        }
    }
}

/// A random test line in the torus frame: (o, d, t_min, t_max, kind).
fn random_line(rng: &mut Pcg64, p: &Pose, kind: usize) -> (DVec3, DVec3, f64, f64, &'static str) {
    let size = p.size();
    let tau = std::f64::consts::TAU;
    let (name, point, dir) = match kind {
        0 => uniform_kind(rng, size),
        1 => {
            // Near the centre: the hole, the horn's pinch, the apple's dimples.
            let rad = p.big * rng.random::<f64>().sqrt();
            let ang = rng.random_range(0.0..tau);
            let y = rng.random_range(-1.0..1.0) * p.ax;
            (
                "hole",
                DVec3::new(rad * ang.cos(), y, rad * ang.sin()),
                unit(rng),
            )
        }
        2 => {
            let phi = rng.random_range(0.0..tau);
            let theta = loop {
                let th: f64 = rng.random_range(0.0..tau);
                if p.big + p.ra * th.cos() > 1e-3 * p.ra {
                    break th;
                }
            };
            let (surf, n) = p.surface(phi, theta);
            let (t1, t2) = n.any_orthonormal_pair();
            let psi = rng.random_range(0.0..tau);
            let delta = GRAZING_PUSHES[rng.random_range(0..GRAZING_PUSHES.len())];
            let dir = psi.cos() * t1 + psi.sin() * t2;
            ("grazing", surf + delta * p.min_ab() * n, dir)
        }
        3 => axis_kind(rng, p.ax),
        4 => parallel_kind(rng, size + p.ra, p.ax),
        _ => far_kind(rng, 100.0 * size, size),
    };
    let (back, scale, t0, t1) = random_back_and_reach(rng, name, 100.0 * size, size);
    (point - back * dir, dir * scale, t0, t1, name)
}

#[test]
fn methods_agree_on_random_lines() {
    let mut rng = Pcg64::seed_from_u64(2026);
    let per = 60;
    let mut counts = [0usize; 3];
    let mut lines = 0;
    for shape in SHAPES {
        for kind in 0..6 {
            for i in 0..per {
                let k = SCALES[i % 3];
                let p = if i % 4 == 0 {
                    Pose::canonical(shape, k)
                } else {
                    Pose::random(&mut rng, shape, k)
                };
                let (o, d, t0, t1, name) = random_line(&mut rng, &p, kind);
                let q = p.q(o, d).over(t0, t1);
                lines += 1;
                let l = q.classify();
                let m2 = q.margin_by_sampling();
                let size = p.size();
                let ctx = format!("{p:?} {name} #{i}: {q:?} {l:?} sampled {m2}");
                // The primary method is the exact minimum; sampling an upper bound.
                assert!(l.margin <= m2 + 1e-12 * size, "{ctx}");
                assert!(m2 - l.margin <= 1e-9 * size, "{ctx}");
                if l.margin.abs() > 2.0 * p.band() {
                    let lm = OracleLabel::from_margin(m2, p.big, p.ra.max(p.ax));
                    assert_eq!(lm.class, l.class, "{ctx}");
                }
                counts[l.class as usize] += 1;
                check_crossings(&p, &q, l.class, &ctx);
            }
        }
    }
    assert_eq!(lines, SHAPES.len() * 6 * per);
    assert!(
        counts[0] > 300 && counts[1] > 300 && counts[2] > 20,
        "{counts:?}"
    );
}

/// Crossings lie on the surface, in the range, in order, alternate in and out, and fit
/// the class.
fn check_crossings(p: &Pose, q: &FamilyQuery, class: OracleClass, ctx: &str) {
    let got = q.crossings();
    let reach = (q.origin - q.center).length().min(1e3 * p.size());
    for c in &got {
        assert!(c.t >= q.t_min && c.t <= q.t_max, "{ctx} {got:?}");
        // |g| to rounding of the point, magnified by the slope of E − 1 ≤ 1/min(a, b).
        let tol = 1e-14 * (p.size() + reach) * (p.ra.max(p.ax) / p.min_ab());
        assert!(q.g(c.t).abs() <= tol, "{ctx} {c:?} g {}", q.g(c.t));
    }
    assert!(got.windows(2).all(|w| w[0].t < w[1].t), "{ctx} {got:?}");
    if class == OracleClass::Ambiguous {
        return;
    }
    let ends: Vec<Passage> = got
        .iter()
        .map(|c| c.passage)
        .filter(|&x| x != Touch)
        .collect();
    assert!(ends.windows(2).all(|w| w[0] != w[1]), "{ctx} {got:?}");
    let band = p.band();
    let clear = |t: f64| !t.is_finite() || q.g(t).abs() > band;
    if q.t_min == -INF && q.t_max == INF {
        match class {
            OracleClass::Hit => {
                assert!(!ends.is_empty() && ends.len() % 2 == 0, "{ctx} {got:?}");
                assert_eq!(ends[0], In, "{ctx} {got:?}");
            }
            _ => assert!(got.is_empty(), "{ctx} {got:?}"),
        }
    } else if clear(q.t_min) && clear(q.t_max) {
        let inside = |t: f64| t.is_finite() && q.g(t) < 0.0;
        assert_eq!(
            ends.len() % 2 == 1,
            inside(q.t_min) != inside(q.t_max),
            "{ctx} {got:?}"
        );
        if class == OracleClass::Miss {
            assert!(got.is_empty(), "{ctx} {got:?}");
        }
    }
}

#[test]
fn round_tubes_agree_with_the_ring_oracle() {
    let mut rng = Pcg64::seed_from_u64(77);
    let mut compared = 0;
    for (big, r) in [(4.0, 1.0), (2.0, 1.0), (1.1, 1.0), (32.0, 1.0)] {
        for i in 0..750 {
            let p = Pose::random(&mut rng, (big, r, r), 1.0);
            let (o, d, t0, t1, _) = random_line(&mut rng, &p, i % 6);
            let ring = Query {
                center: p.frame.c,
                axis: p.frame.a,
                major: big,
                minor: r,
                o: p.frame.point(o),
                d: p.frame.dir(d),
                t_min: t0,
                t_max: t1,
            };
            let q = FamilyQuery::from_ring(&ring);
            let (lf, lr) = (q.classify(), ring.classify());
            let ctx = format!("{q:?} family {lf:?} ring {lr:?}");
            assert!((lf.margin - lr.margin).abs() <= 1e-12 * p.size(), "{ctx}");
            if lr.margin.abs() <= 2.0 * p.band() {
                continue;
            }
            compared += 1;
            assert_eq!(lf.class, lr.class, "{ctx}");
            let roots = reference_roots(&ring);
            let ours: Vec<f64> = q
                .crossings()
                .iter()
                .filter(|c| c.passage != Touch)
                .map(|c| c.t)
                .collect();
            assert_eq!(ours.len(), roots.len(), "{ctx} {ours:?} {roots:?}");
            // Each method's crossings lie on the other's surface; a crossing near a
            // tangency moves by rounding over the slope, so positions agree more loosely.
            let scale = p.size() + (p.frame.point(o) - p.frame.c).length();
            let tol = 1e-9 * scale / p.frame.dir(d).length();
            for (a, b) in ours.iter().zip(&roots) {
                assert!((a - b).abs() <= tol, "{ctx} {ours:?} {roots:?}");
                assert!(q.g(*b).abs() <= 1e-14 * scale, "{ctx} {ours:?} {roots:?}");
                assert!(q.g(*a).abs() <= 1e-14 * scale, "{ctx} {ours:?} {roots:?}");
            }
            assert_eq!(q.first_crossing().is_some(), !roots.is_empty(), "{ctx}");
            if let (Some(a), Some(b)) = (q.first_crossing(), roots.first()) {
                assert!((a - b).abs() <= tol, "{ctx}");
            }
        }
    }
    assert!(compared > 2500, "{compared}");
}

#[test]
fn the_slope_is_monotone_between_its_breakpoints() {
    let mut rng = Pcg64::seed_from_u64(31);
    let mut pieces = 0;
    for shape in SHAPES {
        for i in 0..200 {
            let p = Pose::random(&mut rng, shape, SCALES[i % 3]);
            let (o, d, _, _, _) = random_line(&mut rng, &p, i % 6);
            let line = Line::new(&p.q(o, d));
            let cuts = line.breakpoints();
            let scale = p.size() * p.size();
            for w in cuts.windows(2) {
                let (a, b) = (w[0], w[1]);
                if b - a <= 1e-9 * p.size() {
                    continue;
                }
                pieces += 1;
                // Inside the cuts the slope falls; the samples keep off the ends.
                let hs: Vec<f64> = (1..200)
                    .map(|j| line.half_slope(a + (b - a) * f64::from(j) / 200.0, 0.0))
                    .collect();
                let ok = hs.windows(2).all(|x| x[1] <= x[0] + 1e-13 * scale);
                assert!(ok, "{p:?} {o} {d}: {cuts:?} {hs:?}");
            }
            // Outside them it rises.
            let (first, last) = (cuts.first().copied(), cuts.last().copied());
            let span = 10.0 * p.size();
            for (a, b) in [
                (first.map_or(-span, |c| c - span), first.unwrap_or(0.0)),
                (last.unwrap_or(0.0), last.map_or(span, |c| c + span)),
            ] {
                let hs: Vec<f64> = (1..200)
                    .map(|j| line.half_slope(a + (b - a) * f64::from(j) / 200.0, 0.0))
                    .collect();
                let ok = hs.windows(2).all(|x| x[1] >= x[0] - 1e-13 * scale);
                assert!(ok, "{p:?} {o} {d}: {cuts:?} {hs:?}");
            }
        }
    }
    assert!(pieces > 200, "{pieces}");
}
