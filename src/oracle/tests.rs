//! The oracle against its second method, closed forms and the crate's own geometry.

use super::interval::{cubic_real_roots, quadratic_real_roots};
use super::*;
use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;

const NUS: [f64; 4] = [1.1, 2.0, 10.0, 32.0];
const INF: f64 = f64::INFINITY;

/// A torus pose in f64: its frame and its radii.
#[derive(Clone, Copy)]
struct Pose {
    frame: Frame,
    big: f64,
    small: f64,
}

impl Pose {
    fn canonical(big: f64, small: f64) -> Pose {
        Pose {
            frame: Frame::CANONICAL,
            big,
            small,
        }
    }
    fn random(rng: &mut Pcg64, big: f64, small: f64) -> Pose {
        Pose {
            frame: Frame::random(rng, big),
            big,
            small,
        }
    }
    fn query(&self, o: DVec3, d: DVec3, t_min: f64, t_max: f64) -> Query {
        Query {
            center: self.frame.c,
            axis: self.frame.a,
            major: self.big,
            minor: self.small,
            o,
            d,
            t_min,
            t_max,
        }
    }
    fn label(&self, o: DVec3, d: DVec3, t0: f64, t1: f64) -> OracleLabel {
        self.query(o, d, t0, t1).classify()
    }
    fn sampled(&self, o: DVec3, d: DVec3, t0: f64, t1: f64) -> f64 {
        margin_by_sampling(&self.query(o, d, t0, t1))
    }
    fn roots(&self, o: DVec3, d: DVec3, t0: f64, t1: f64) -> Vec<f64> {
        reference_roots(&self.query(o, d, t0, t1))
    }
    /// g = D − r at o + t d, straight from the definition in world coordinates.
    fn g(&self, o: DVec3, d: DVec3, t: f64) -> f64 {
        let (c, a) = (self.frame.c, self.frame.a);
        let x = o + t * d - c;
        let y = x.dot(a);
        ((x - y * a).length() - self.big).hypot(y) - self.small
    }
    fn band(&self) -> f64 {
        AMBIGUITY_REL * (self.big + self.small)
    }
    /// A point on the surface (torus frame) with its outward normal, at angles φ, θ.
    fn surface(&self, phi: f64, theta: f64) -> (DVec3, DVec3) {
        let n = DVec3::new(
            theta.cos() * phi.cos(),
            theta.sin(),
            theta.cos() * phi.sin(),
        );
        let core = DVec3::new(self.big * phi.cos(), 0.0, self.big * phi.sin());
        (core + self.small * n, n)
    }
}

pub(super) fn unit(rng: &mut Pcg64) -> DVec3 {
    crate::random::ball_direction(rng, 1e-4)
}

/// A test pose's frame: its centre `c`, unit axis `a` and two unit vectors `x`, `z`
/// completing it; the ring's and the family's tests give their lines in it (the torus
/// frame) and place them in the world with it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame {
    pub(super) c: DVec3,
    pub(super) a: DVec3,
    pub(super) x: DVec3,
    pub(super) z: DVec3,
}

impl Frame {
    /// Centred at the origin, the axis +y.
    pub(super) const CANONICAL: Frame = Frame {
        c: DVec3::ZERO,
        a: DVec3::Y,
        x: DVec3::X,
        z: DVec3::Z,
    };

    /// A centre within ±5 `scale` on each axis and a random unit axis.
    pub(super) fn random(rng: &mut Pcg64, scale: f64) -> Frame {
        let a = unit(rng);
        let (x, z) = a.any_orthonormal_pair();
        let c = DVec3::new(
            rng.random_range(-5.0..5.0),
            rng.random_range(-5.0..5.0),
            rng.random_range(-5.0..5.0),
        ) * scale;
        Frame { c, a, x, z }
    }

    /// The world point of the torus-frame point `l`.
    pub(super) fn point(&self, l: DVec3) -> DVec3 {
        self.c + l.x * self.x + l.y * self.a + l.z * self.z
    }

    /// The world direction of the torus-frame direction `l`.
    pub(super) fn dir(&self, l: DVec3) -> DVec3 {
        l.x * self.x + l.y * self.a + l.z * self.z
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Asserts that the line through `o` along +x hits `p` with `margin` (to 1e-15) and
/// crosses it at exactly the `t`s of `want` (each to 1e-14).
#[track_caller]
fn assert_hit_along_x(p: &Pose, o: DVec3, margin: f64, want: &[f64]) {
    let l = p.label(o, DVec3::X, -INF, INF);
    assert_eq!(l.class, OracleClass::Hit);
    assert!(close(l.margin, margin, 1e-15), "{l:?}");
    let roots = p.roots(o, DVec3::X, -INF, INF);
    assert_eq!(roots.len(), want.len(), "{roots:?}");
    for (t, w) in roots.iter().zip(want) {
        assert!(close(*t, *w, 1e-14), "{roots:?}");
    }
}

#[test]
fn hand_computed_lines_on_the_canonical_torus() {
    let p = Pose::canonical(2.0, 1.0);
    let x = DVec3::X;
    // Along the x axis: through both tube centres (D = 0 at x = ±2), margin −r.
    assert_hit_along_x(&p, DVec3::new(-5.0, 0.0, 0.0), -1.0, &[2.0, 4.0, 6.0, 8.0]);
    // Vertical line at ρ = 0.5 through the hole: margin |0.5 − 2| − 1.
    let o = DVec3::new(0.3, 3.0, 0.4);
    let l = p.label(o, -DVec3::Y, -INF, INF);
    assert_eq!(l.class, OracleClass::Miss);
    assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
    assert!(p.roots(o, -DVec3::Y, -INF, INF).is_empty());
    // Horizontal line at height 1.5 over both tubes: margin 0.5.
    let l = p.label(DVec3::new(-5.0, 1.5, 0.0), x, -INF, INF);
    assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
    // In the plane z = 2.5 (R ≤ a < R + r), y = 0: ρ ≥ 2.5, so min D = 0.5.
    let l = p.label(DVec3::new(-5.0, 0.0, 2.5), x, -INF, INF);
    assert!(close(l.margin, -0.5, 1e-15), "{l:?}");
    // Inner-equator point, circle-tangent direction: the saddle side, it dips to the core.
    let l = p.label(DVec3::new(1.0, 0.0, -5.0), DVec3::Z, -INF, INF);
    assert!(close(l.margin, -1.0, 1e-15), "{l:?}");
}

#[test]
fn ray_mode_counts_only_the_range() {
    let p = Pose::canonical(2.0, 1.0);
    // The torus is behind the origin: the ray starts at D = 3 and moves away.
    let (o, d) = (DVec3::new(5.0, 0.0, 0.0), DVec3::X);
    let l = p.label(o, d, 0.0, INF);
    assert_eq!(l.class, OracleClass::Miss);
    assert!(close(l.margin, 2.0, 1e-15), "{l:?}");
    assert!(p.roots(o, d, 0.0, INF).is_empty());
    assert_eq!(p.label(o, d, -INF, INF).class, OracleClass::Hit);
    // A non-unit direction and a t_max that stops before the tube: ends at x = −3.5.
    let (o, d) = (DVec3::new(-5.0, 0.0, 0.0), DVec3::new(2.0, 0.0, 0.0));
    let l = p.label(o, d, 0.0, 0.75);
    assert_eq!(l.class, OracleClass::Miss);
    assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
    // Stopping at x = −2.5, inside the tube: one crossing, at x = −3 (t = 1).
    let l = p.label(o, d, 0.0, 1.25);
    assert_eq!(l.class, OracleClass::Hit);
    assert!(close(l.margin, -0.5, 1e-15), "{l:?}");
    assert_eq!(p.roots(o, d, 0.0, 1.25), vec![1.0]);
    // Starting on the core circle: margin −r, one exit at t = 1.
    let (o, d) = (DVec3::new(2.0, 0.0, 0.0), DVec3::Y);
    let l = p.label(o, d, 0.0, INF);
    assert!(close(l.margin, -1.0, 1e-15), "{l:?}");
    let roots = p.roots(o, d, 0.0, INF);
    assert_eq!(roots.len(), 1);
    assert!(close(roots[0], 1.0, 1e-15), "{roots:?}");
}

#[test]
fn f32_wrappers_use_the_ray_range_and_the_line() {
    let torus = Torus::canonical(2.0, 1.0).unwrap();
    let behind = Ray::new(Vec3::new(5.0, 0.0, 0.0), Vec3::X).unwrap();
    assert_eq!(classify(&torus, &behind).class, OracleClass::Miss);
    let line = classify_line(&torus, &behind);
    assert_eq!(line.class, OracleClass::Hit);
    assert!(close(line.margin, -1.0, 1e-15));
    let short = Ray::with_range(Vec3::new(-5.0, 0.0, 0.0), Vec3::X, 0.0, 1.5).unwrap();
    let l = classify(&torus, &short);
    assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
}

#[test]
fn design_section7_counterexamples_are_hits() {
    let p = Pose::canonical(2.0, 1.0);
    // Eq. 35: y = 0.5 through both tubes; crossings at x = ±2 ± √0.75.
    let h = 0.75f64.sqrt();
    let want = [6.0 - 2.0 - h, 6.0 - 2.0 + h, 6.0 + 2.0 - h, 6.0 + 2.0 + h];
    assert_hit_along_x(&p, DVec3::new(-6.0, 0.5, 0.0), -0.5, &want);
    // Eq. 105: the plane z = 2, y = 0.5; crossings at x = ±√((2 + √0.75)² − 4) ≈ ±2.0528.
    let xr = ((2.0 + h).powi(2) - 4.0).sqrt();
    assert!(close(xr, 2.0528, 1e-4));
    assert_hit_along_x(&p, DVec3::new(-5.0, 0.5, 2.0), -0.5, &[5.0 - xr, 5.0 + xr]);
    // Eq. 102: steep line through the hole's edge; at t = 3 it is at ρ ≈ 1.056, y = 0.
    let (o, d) = (DVec3::new(0.9, -3.0, 0.5), DVec3::new(0.01, 1.0, 0.0));
    let l = p.label(o, d, -INF, INF);
    assert_eq!(l.class, OracleClass::Hit);
    assert!(l.margin <= p.g(o, d, 3.0) + 1e-15 && p.g(o, d, 3.0) < -0.05);
    assert!(close(l.margin, p.sampled(o, d, -INF, INF), 1e-12));
    assert_eq!(p.roots(o, d, -INF, INF).len(), 2);
}

/// Tangent lines whose minimum distance to the core circle is known exactly:
/// (point, direction) in the torus frame, pushed out by δ along the normal.
fn exact_tangents(big: f64, small: f64, push: f64) -> [(DVec3, DVec3); 5] {
    let out = big + small + push;
    let top = small + push;
    let inner = big - small - push;
    [
        // Outer equator, vertical: ρ is constant, D ≥ ρ − R.
        (DVec3::new(out, 0.0, 0.0), DVec3::Y),
        // Outer equator, along the circle: ρ only grows, y = 0.
        (DVec3::new(out, 0.0, 0.0), DVec3::Z),
        // Top, across the hole: y is constant, D ≥ |y|, equality at ρ = R.
        (DVec3::new(big, top, 0.0), DVec3::X),
        // Top, along the circle: y constant, equality at the touching point.
        (DVec3::new(big, top, 0.0), DVec3::Z),
        // Inner equator, vertical: ρ constant, D ≥ R − ρ.
        (DVec3::new(inner, 0.0, 0.0), DVec3::Y),
    ]
}

#[test]
fn exact_grazing_lines_have_margin_equal_to_the_push() {
    let mut rng = Pcg64::seed_from_u64(7);
    for nu in NUS {
        let small = 1.0;
        let big = nu * small;
        for pose in [
            Pose::canonical(big, small),
            Pose::random(&mut rng, big, small),
        ] {
            for delta in [1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6] {
                for (pt, dir) in exact_tangents(big, small, delta * small) {
                    let (o, d) = (pose.frame.point(pt - 3.0 * dir), pose.frame.dir(dir) * 0.7);
                    let l = pose.label(o, d, -INF, INF);
                    // Rounding of the pose: ~1e-16 of |c| ≤ 9R.
                    let tol = 1e-13 * (big + small);
                    assert!(
                        close(l.margin, delta * small, tol),
                        "nu {nu} delta {delta} {pt} {dir}: {l:?}"
                    );
                    let want = if delta < 0.0 {
                        OracleClass::Hit
                    } else {
                        OracleClass::Miss
                    };
                    assert_eq!(l.class, want);
                    let n = pose.roots(o, d, -INF, INF).len();
                    if delta < 0.0 {
                        assert!(n == 2 || n == 4, "{n}");
                    } else {
                        assert_eq!(n, 0);
                    }
                }
            }
        }
    }
}

#[test]
fn ambiguity_band_is_relative_to_the_outer_radius() {
    let p = Pose::canonical(2.0, 1.0);
    let band = p.band();
    for (push, want) in [
        (0.5 * band, OracleClass::Ambiguous),
        (-0.5 * band, OracleClass::Ambiguous),
        (4.0 * band, OracleClass::Miss),
        (-4.0 * band, OracleClass::Hit),
    ] {
        for (pt, dir) in exact_tangents(2.0, 1.0, push) {
            let l = p.label(pt, dir, -INF, INF);
            assert_eq!(l.class, want, "push {push} {pt} {dir}: {l:?}");
            assert!(close(l.margin, push, 1e-15));
        }
    }
}

#[test]
fn random_grazing_lines_touch_at_the_push() {
    let mut rng = Pcg64::seed_from_u64(11);
    let mut windowed = 0;
    for nu in NUS {
        let small = 1.0 / nu.sqrt();
        let big = nu * small;
        for _ in 0..200 {
            let pose = Pose::random(&mut rng, big, small);
            let phi = rng.random_range(0.0..std::f64::consts::TAU);
            let theta = rng.random_range(0.0..std::f64::consts::TAU);
            let (surf, n) = pose.surface(phi, theta);
            let e_phi = DVec3::new(-phi.sin(), 0.0, phi.cos());
            let e_m = n.cross(e_phi);
            let psi = rng.random_range(0.0..std::f64::consts::TAU);
            let dir = psi.cos() * e_m + psi.sin() * e_phi;
            let delta = [1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6][rng.random_range(0..6)];
            let push = delta * small;
            let (o, d) = (pose.frame.point(surf + push * n), pose.frame.dir(dir));
            let tol = 1e-13 * (big + small);
            // The pushed point is at D = r + push and D′ = n·u = 0 there.
            assert!(close(pose.g(o, d, 0.0), push, tol));
            let line = pose.label(o, d, -INF, INF);
            assert!(line.margin <= push + tol, "{line:?} push {push}");
            if delta < 0.0 {
                assert_eq!(line.class, OracleClass::Hit);
            }
            // Where both curvatures are positive, D″ = cos²ψ/D + sin²ψ·cosθ/ρ > 0: the
            // pushed point is the minimum over a short window around it.
            if theta.cos() > 0.3 {
                windowed += 1;
                let w = 0.05 * small;
                let l = pose.label(o, d, -w, w);
                assert!(close(l.margin, push, tol), "{l:?} push {push}");
            }
        }
    }
    assert!(windowed > 100);
}

/// One random test line in world coordinates: (o, d, t_min, t_max).
fn random_line(
    rng: &mut Pcg64,
    pose: &Pose,
    kind: usize,
) -> (DVec3, DVec3, f64, f64, &'static str) {
    let (big, small) = (pose.big, pose.small);
    let outer = big + small;
    let tau = std::f64::consts::TAU;
    let (name, point, dir) = match kind {
        // Isotropic through the bounding sphere (a little beyond it).
        0 => uniform_kind(rng, outer),
        1 => {
            // Through the hole disk, any direction.
            let rad = (big - small) * rng.random::<f64>().sqrt();
            let ang = rng.random_range(0.0..tau);
            let pt = DVec3::new(rad * ang.cos(), 0.0, rad * ang.sin());
            ("hole", pt, unit(rng))
        }
        2 => {
            let (surf, n) = pose.surface(rng.random_range(0.0..tau), rng.random_range(0.0..tau));
            let t = n.any_orthonormal_pair();
            let psi = rng.random_range(0.0..tau);
            let delta = GRAZING_PUSHES[rng.random_range(0..GRAZING_PUSHES.len())];
            let dir = psi.cos() * t.0 + psi.sin() * t.1;
            ("grazing", surf + delta * small * n, dir)
        }
        // Through a point of the axis: D has a kink there.
        3 => axis_kind(rng, small),
        // Parallel to the axis: ρ is constant.
        4 => parallel_kind(rng, outer + small, 1.0),
        // From 100·R away, aimed into the bounding sphere.
        _ => far_kind(rng, 100.0 * big, outer),
    };
    let (back, scale, t0, t1) = random_back_and_reach(rng, name, 100.0 * big, outer);
    let o = pose.frame.point(point - back * dir);
    let d = pose.frame.dir(dir) * scale;
    (o, d, t0, t1, name)
}

/// For a random line whose point of interest is `back` from its origin: the direction's
/// scale, and the range (the whole line, the ray, or a window of a few `size` at the point).
pub(super) fn random_reach(rng: &mut Pcg64, back: f64, size: f64) -> (f64, f64, f64) {
    let scale = 10f64.powf(rng.random_range(-1.0..1.0));
    let t_near = back / scale;
    let (t0, t1) = match rng.random_range(0..4) {
        0 | 1 => (-INF, INF),
        2 => (0.0, INF),
        _ => {
            let a = t_near + rng.random_range(-2.0..2.0) * size / scale;
            let b = a + rng.random_range(0.0..3.0) * size / scale;
            (a, b)
        }
    };
    (scale, t0, t1)
}

/// The grazing kind's pushes off the surface, in units of the tube's (least) radius: ±1e-8
/// sits just outside the oracle's band, ±1e-11 inside it.
pub(super) const GRAZING_PUSHES: [f64; 10] = [
    1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6, 1e-8, -1e-8, 1e-11, -1e-11,
];

/// The `uniform` kind: an isotropic line through the sphere of radius `1.05·size`.
pub(super) fn uniform_kind(rng: &mut Pcg64, size: f64) -> (&'static str, DVec3, DVec3) {
    let u = unit(rng);
    let (e1, e2) = u.any_orthonormal_pair();
    let rad = 1.05 * size * rng.random::<f64>().sqrt();
    let ang = rng.random_range(0.0..std::f64::consts::TAU);
    ("uniform", rad * (ang.cos() * e1 + ang.sin() * e2), u)
}

/// The `axis` kind: any direction through a point of the axis within ±2 `y_scale`.
pub(super) fn axis_kind(rng: &mut Pcg64, y_scale: f64) -> (&'static str, DVec3, DVec3) {
    let pt = DVec3::new(0.0, rng.random_range(-2.0..2.0) * y_scale, 0.0);
    ("axis", pt, unit(rng))
}

/// The `parallel` kind: a line parallel to the axis, at a distance below `rad_max` from it
/// and a height within ±3 `y_scale`.
pub(super) fn parallel_kind(
    rng: &mut Pcg64,
    rad_max: f64,
    y_scale: f64,
) -> (&'static str, DVec3, DVec3) {
    let rad = rng.random_range(0.0..rad_max);
    let ang = rng.random_range(0.0..std::f64::consts::TAU);
    let y = rng.random_range(-3.0..3.0) * y_scale;
    let pt = DVec3::new(rad * ang.cos(), y, rad * ang.sin());
    let s = if rng.random::<bool>() { 1.0 } else { -1.0 };
    ("parallel", pt, DVec3::Y * s)
}

/// The `far` kind: from `far` away, aimed into the ball of radius `size`.
pub(super) fn far_kind(rng: &mut Pcg64, far: f64, size: f64) -> (&'static str, DVec3, DVec3) {
    let from = far * unit(rng);
    let to = unit(rng) * size * rng.random::<f64>().cbrt();
    ("far", to, (to - from).normalize())
}

/// How far back from its point a line of kind `name` starts (`far` for the `far` kind, else
/// up to 3 `size`), with [`random_reach`]'s scale and range: (back, scale, t0, t1).
pub(super) fn random_back_and_reach(
    rng: &mut Pcg64,
    name: &str,
    far: f64,
    size: f64,
) -> (f64, f64, f64, f64) {
    let back = if name == "far" {
        far
    } else {
        rng.random_range(0.0..3.0 * size)
    };
    let (scale, t0, t1) = random_reach(rng, back, size);
    (back, scale, t0, t1)
}

#[test]
fn methods_agree_on_random_lines() {
    let mut rng = Pcg64::seed_from_u64(2024);
    let per = 500;
    let mut counts = [0usize; 3];
    let mut lines = 0;
    for nu in NUS {
        let small = 1.0 / nu;
        let big = nu * small;
        for kind in 0..6 {
            for i in 0..per {
                let pose = if i % 4 == 0 {
                    Pose::canonical(big, small)
                } else {
                    Pose::random(&mut rng, big, small)
                };
                let (o, d, t0, t1, name) = random_line(&mut rng, &pose, kind);
                lines += 1;
                let l = pose.label(o, d, t0, t1);
                let m2 = pose.sampled(o, d, t0, t1);
                let band = pose.band();
                let ctx =
                    format!("nu {nu} {name} #{i}: o {o} d {d} [{t0}, {t1}] {l:?} sampled {m2}");
                // The primary method is the exact minimum; sampling is an upper bound.
                assert!(l.margin <= m2 + 1e-12 * (big + small), "{ctx}");
                assert!(m2 - l.margin <= 1e-9 * (big + small), "{ctx}");
                if l.margin.abs() > 2.0 * band {
                    assert_eq!(
                        OracleLabel::from_margin(m2, big, small).class,
                        l.class,
                        "{ctx}"
                    );
                }
                counts[l.class as usize] += 1;
                // Roots lie on the surface and their count fits the class.
                let roots = pose.roots(o, d, t0, t1);
                let scale = big + small + (o - pose.frame.c).length().min(1e3 * big);
                for &t in &roots {
                    assert!(pose.g(o, d, t).abs() <= 1e-13 * scale, "{ctx} root {t}");
                    assert!(t >= t0 && t <= t1);
                }
                assert!(roots.windows(2).all(|w| w[0] < w[1]), "{ctx} {roots:?}");
                if l.class == OracleClass::Ambiguous {
                    continue;
                }
                if t0 == -INF {
                    let ok = match l.class {
                        OracleClass::Hit => roots.len() == 2 || roots.len() == 4,
                        _ => roots.is_empty(),
                    };
                    assert!(ok, "{ctx} {roots:?}");
                } else {
                    let inside = |t: f64| t.is_finite() && pose.g(o, d, t) < 0.0;
                    let end_clear = |t: f64| !t.is_finite() || pose.g(o, d, t).abs() > band;
                    if end_clear(t0) && end_clear(t1) {
                        assert_eq!(
                            roots.len() % 2 == 1,
                            inside(t0) != inside(t1),
                            "{ctx} {roots:?}"
                        );
                    }
                    if l.class == OracleClass::Miss {
                        assert!(roots.is_empty(), "{ctx} {roots:?}");
                    }
                }
            }
        }
    }
    assert_eq!(lines, NUS.len() * 6 * per);
    // The workload must exercise all three classes, or the test proves little.
    assert!(
        counts[0] > 500 && counts[1] > 500 && counts[2] > 20,
        "{counts:?}"
    );
}

#[test]
fn f_prime_candidates_give_the_same_class() {
    let mut rng = Pcg64::seed_from_u64(99);
    for nu in NUS {
        let (big, small) = (nu, 1.0);
        for i in 0..2000 {
            let pose = Pose::random(&mut rng, big, small);
            let (o, d, _, _, _) = random_line(&mut rng, &pose, i % 6);
            let l = pose.label(o, d, -INF, INF);
            let frame = LineFrame::new(&pose.query(o, d, -INF, INF));
            let by_f = frame
                .f_prime_roots()
                .into_iter()
                .map(|s| frame.dist(s) - small)
                .fold(INF, f64::min);
            assert!(by_f >= l.margin - 1e-13 * (big + small));
            if l.margin.abs() > pose.band() {
                assert_eq!((by_f < 0.0), (l.margin < 0.0), "{l:?} by F′ {by_f}");
            }
        }
    }
}

/// `classify_unless` stops early only where the full label would be thrown away, and
/// otherwise gives that label bit for bit: for a threshold at the band (the `hole`
/// sampler's) and at a grazing push's lower edge, on every kind of random line.
#[test]
fn classify_unless_is_classify_where_it_does_not_stop() {
    let mut rng = Pcg64::seed_from_u64(7);
    let (mut stopped, mut kept) = (0, 0);
    for nu in NUS {
        let (big, small) = (nu, 1.0);
        for i in 0..1200 {
            let pose = Pose::random(&mut rng, big, small);
            let (o, d, t0, t1, name) = random_line(&mut rng, &pose, i % 6);
            let query = pose.query(o, d, t0, t1);
            let label = query.classify();
            for floor in [pose.band(), -1e-4 * small - 1e-6 * (big + small)] {
                let rejects = |m: f64| m <= floor;
                match query.classify_unless(rejects) {
                    None => {
                        assert!(rejects(label.margin), "nu {nu} {name} #{i}: {label:?}");
                        stopped += 1;
                    }
                    Some(l) => {
                        assert_eq!(l.class, label.class, "nu {nu} {name} #{i}");
                        assert_eq!(l.margin.to_bits(), label.margin.to_bits(), "{name} #{i}");
                        assert!(!rejects(l.margin), "nu {nu} {name} #{i}: {l:?}");
                        kept += 1;
                    }
                }
            }
        }
    }
    // Both ways are exercised.
    assert!(
        stopped > 1000 && kept > 1000,
        "stopped {stopped}, kept {kept}"
    );
}

#[test]
fn f32_wrappers_agree_with_sampling_on_random_rays() {
    let mut rng = Pcg64::seed_from_u64(5);
    for nu in [1.1f32, 4.0, 32.0] {
        for _ in 0..300 {
            let axis = unit(&mut rng).as_vec3();
            let center = (unit(&mut rng) * 3.0).as_vec3();
            let torus = Torus::new(center, axis, nu, 1.0).unwrap();
            let target = center + (unit(&mut rng) * f64::from(nu + 1.0)).as_vec3();
            let origin = center + (unit(&mut rng) * f64::from(4.0 * nu)).as_vec3();
            let ray = Ray::new(origin, target - origin).unwrap();
            let query = Query::ray(&torus, &ray);
            let (big, small) = (query.major, query.minor);
            let ray_m = classify(&torus, &ray).margin;
            let line_m = classify_line(&torus, &ray).margin;
            assert!(close(
                ray_m,
                margin_by_sampling(&query.over(0.0, INF)),
                1e-9 * (big + small)
            ));
            assert!(close(
                line_m,
                margin_by_sampling(&query.over(-INF, INF)),
                1e-9 * (big + small)
            ));
            assert!(line_m <= ray_m);
        }
    }
}

#[test]
fn cubic_and_quadratic_solvers() {
    let r = cubic_real_roots(1.0, 0.0, -7.0, 6.0); // (s − 1)(s − 2)(s + 3)
    assert_eq!(r.len(), 3);
    for (x, w) in r.iter().zip([-3.0, 1.0, 2.0]) {
        assert!(close(*x, w, 1e-15), "{r:?}");
    }
    assert_eq!(cubic_real_roots(1.0, -3.0, 3.0, -1.0), vec![1.0]); // (s − 1)³
    let r = cubic_real_roots(2.0, 0.0, 2.0, -4.0); // 2(s − 1)(s² + s + 2)
    assert_eq!(r.len(), 1);
    assert!(close(r[0], 1.0, 1e-15));
    // Close roots 1 ± 1e-6 and a far one at −1e4.
    let (a, b, c) = (1.0 - 1e-6, 1.0 + 1e-6, -1e4);
    let r = cubic_real_roots(1.0, -(a + b + c), a * b + a * c + b * c, -a * b * c);
    assert_eq!(r.len(), 3, "{r:?}");
    // The rounded coefficients move the close pair by ~1e-10: that is conditioning.
    assert!(
        close(r[0], c, 1e-10) && close(r[1], a, 1e-9) && close(r[2], b, 1e-9),
        "{r:?}"
    );
    let f = |s: f64| ((s - (a + b + c)) * s + (a * b + a * c + b * c)) * s - a * b * c;
    let (lo, hi) = (f(r[1]).abs(), f(r[2]).abs());
    assert!(lo < 1e-9 && hi < 1e-9, "{lo} {hi}");
    assert_eq!(quadratic_real_roots(1.0, 0.0, 1.0), Vec::<f64>::new());
    assert_eq!(quadratic_real_roots(1.0, -3.0, 2.0), vec![1.0, 2.0]);
}
