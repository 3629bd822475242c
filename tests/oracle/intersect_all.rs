//! `intersect_all` (every crossing, paired into spans) against the f64 oracle: no crossing
//! missed, none invented, entries and exits alternating with the oracle's inside and
//! outside, each crossing within a stated bound of the oracle's root, and the first one
//! `intersect`'s hit.
//!
//! Families: the workload's five cases (uniform, camera, grazing, outer band, hole) at
//! random poses, from their origins and from 100·(R + r) farther back, the adversarial hole-edge, tangent and tangent-limit lines (f32 rays, and
//! f64 rays exactly on the f64 line), rays from inside the tube, and rays from a surface
//! point (`Torus::spawn`); ν from 1.01 to 1000, R from 10⁻³ to 10³.
//!
//! **What counts.** The oracle's roots are sign changes of `D − r` (D the distance to the
//! core circle). A root is *robust* when the line is deeper than the ambiguity band
//! (`AMBIGUITY_REL·(R + r)`) inside the tube on its inside neighbour stretch and farther
//! than the band outside on its outside one; only those can be missed. A crossing of ours
//! that matches no oracle root is *invented* unless it lies on the surface where the line
//! comes within the band of a tangency (the oracle's class over its neighbourhood is
//! ambiguous, or an oracle root there is not robust): f64 cannot decide those.

use crate::common::{pairs, pushed_back};
use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::{Crossings, DRay, Passage, Precision, Ray, Torus, intersect, intersect_all};
use torus_cull_lab::oracle::{AMBIGUITY_REL, OracleClass, Query, on_surface_line, reference_roots};
use torus_cull_lab::workload::adversarial::{LineFamily, SpecialCircle, family_rays, tangent_line};
use torus_cull_lab::workload::{Case, Pose, generate, unit_vector};

const NUS: [f64; 7] = [1.01, 1.1, 2.0, 4.0, 16.0, 100.0, 1000.0];
const SCALES: [f64; 3] = [1e-3, 1.0, 1e3];

/// A crossing's `t` may differ from the oracle's root by this, × (R + r)/|d|, plus the
/// rounding of `t` to the ray's float (2⁻²³·|t| for f32, 4ε·|t| for f64), plus the root's
/// conditioning `ROOT_COND·ν·(R + r)/(|d|·|cos θ|)`, θ the angle between the ray and the
/// normal there: in the scaled frame the quartic's rounding is a few ε while its slope at
/// a crossing is `|∇F|·cos θ = 8(r/R)ρ·cos θ`, so a root moves by about ε·ν/|cos θ| (units
/// of R). The report prints the worst error as a fraction of this bound.
const T_TOL_REL: f64 = 1e-12;
/// See [`T_TOL_REL`]: about 450ε, for the solver's and the oracle's rounding together.
const ROOT_COND: f64 = 1e-13;
/// How far `intersect`'s nearest root (no final Newton step) may be from the first
/// crossing, × (R + r)/|d|.
const NEAREST_TOL_REL: f64 = 1e-8;

/// The answer of `intersect_all` in f64, whatever the ray's precision.
struct Answer {
    crossings: Vec<(f64, Passage)>,
    spans: Vec<(f64, f64)>,
    starts_inside: bool,
    first_hit: Option<f64>,
    /// Last-ulp slack of the ray's float at `t` (relative).
    t_rel: f64,
}

fn answer<P: Precision>(torus: &Torus, ray: &Ray<P>, to_f64: impl Fn(P::Float) -> f64) -> Answer
where
    Ray<P>: torus_cull::TorusRay<Hit = torus_cull::Hit<P>>,
{
    let all: Crossings<P> = intersect_all(torus, ray);
    let crossings = all
        .as_slice()
        .iter()
        .map(|c| (to_f64(c.t), c.passage))
        .collect();
    let spans = all
        .spans()
        .as_slice()
        .iter()
        .map(|s| (to_f64(s.t_enter), to_f64(s.t_exit)))
        .collect();
    Answer {
        crossings,
        spans,
        starts_inside: all.starts_inside(),
        first_hit: intersect(torus, ray).map(|h| to_f64(h.t)),
        t_rel: if std::mem::size_of::<P::Float>() == 4 {
            2.0 * f64::from(f32::EPSILON)
        } else {
            4.0 * f64::EPSILON
        },
    }
}

#[derive(Default)]
struct Tally {
    rays: usize,
    crossings: usize,
    robust_roots: usize,
    excused_roots: usize,
    excused_crossings: usize,
    touches: usize,
    spans: usize,
    surface_undecidable: usize,
    worst_t: f64,
    worst_vs_intersect: f64,
    missed: Vec<String>,
    invented: Vec<String>,
    wrong_side: Vec<String>,
    not_intersect: Vec<String>,
}

/// D − r at `t` on the query's line (negative inside the tube).
fn depth(q: &Query, t: f64) -> f64 {
    q.over(t, t).classify().margin
}

/// |cos θ| between the line and the surface normal near `t`, from D − r's slope (D is
/// 1-Lipschitz along a unit-speed line and |dD/ds| = |cos θ| on the surface).
fn cos_at(q: &Query, t: f64, size: f64) -> f64 {
    let h = 1e-7 * size;
    ((depth(q, t + h) - depth(q, t - h)) / (2.0 * h * q.d.length())).abs()
}

impl Tally {
    /// Checks `got` against the oracle for the query's range; `own` is the origin's own
    /// window for a ray from a surface point (oracle roots with `|t| ≤ own` are its own).
    fn check(&mut self, what: &str, q: &Query, got: &Answer, own: Option<f64>) {
        self.rays += 1;
        let band = AMBIGUITY_REL * (q.major + q.minor);
        let len = q.d.length();
        let size = (q.major + q.minor) / len;
        let nu = q.major / q.minor;
        let line = q.over(f64::NEG_INFINITY, f64::INFINITY);
        let all = reference_roots(&line);
        // A ray from a surface point: the origin's own root (the one nearest 0) is never
        // reported; another root within its window is undecidable.
        let mut own_root = None;
        if let Some(w) = own {
            let nearest = (0..all.len()).min_by(|&a, &b| all[a].abs().total_cmp(&all[b].abs()));
            match nearest {
                Some(k) if all[k].abs() <= w => own_root = Some(k),
                _ => {
                    self.surface_undecidable += 1;
                    return;
                }
            }
            if all
                .iter()
                .enumerate()
                .any(|(i, t)| Some(i) != own_root && t.abs() <= w)
            {
                self.surface_undecidable += 1;
                return;
            }
        }
        let (lo, hi) = (q.t_min, q.t_max);
        // Robust oracle roots: the stretches on either side are deep (inside) or high
        // (outside) beyond the band. The stretch before the first root is outside.
        let n = all.len();
        let stretch_clear = |i: usize| -> bool {
            // Stretch i lies between root i − 1 and root i (0: before the first).
            if i == 0 || i == n {
                return true;
            }
            let (a, b) = (all[i - 1], all[i]);
            if i % 2 == 1 {
                line.over(a, b).classify().margin < -band
            } else {
                depth(&line, 0.5 * (a + b)) > band
            }
        };
        let robust: Vec<bool> = (0..n)
            .map(|i| stretch_clear(i) && stretch_clear(i + 1))
            .collect();
        let tol = |t: f64| {
            T_TOL_REL * size
                + got.t_rel * t.abs()
                + ROOT_COND * nu * size / cos_at(&line, t, size).max(1e-300)
        };
        let mut matched = vec![false; got.crossings.len()];
        for (i, &t) in all.iter().enumerate() {
            if t < lo || t > hi {
                continue;
            }
            if own.is_some() && (Some(i) == own_root || t <= 0.0) {
                continue;
            }
            let reach = if robust[i] {
                tol(t)
            } else {
                tol(t).max(1e-6 * size)
            };
            let found = got
                .crossings
                .iter()
                .enumerate()
                .filter(|(_, (g, _))| (g - t).abs() <= reach)
                .min_by(|a, b| (a.1.0 - t).abs().total_cmp(&(b.1.0 - t).abs()));
            if let Some((k, &(g, passage))) = found {
                matched[k] = true;
                if robust[i] {
                    self.robust_roots += 1;
                    let err = (g - t).abs() / tol(t);
                    self.worst_t = self.worst_t.max(err);
                    // Entering at odd stretches' starts: root i opens stretch i + 1.
                    let want = if i % 2 == 0 {
                        Passage::Enter
                    } else {
                        Passage::Exit
                    };
                    if passage != want {
                        self.wrong_side.push(format!(
                            "{what}: root {t:e} is {want:?}, got {passage:?}: {:?}",
                            got.crossings
                        ));
                    }
                } else {
                    self.excused_roots += 1;
                }
            } else if robust[i] {
                let near = got
                    .crossings
                    .iter()
                    .map(|(g, _)| (g - t).abs() / size)
                    .fold(f64::INFINITY, f64::min);
                self.missed.push(format!(
                    "{what}: oracle root {t:e} (all {all:?}) unmatched, nearest of ours {near:e}·size: {:?}",
                    got.crossings
                ));
            } else {
                self.excused_roots += 1;
            }
        }
        for (k, &(g, passage)) in got.crossings.iter().enumerate() {
            self.crossings += 1;
            self.touches += usize::from(passage == Passage::Touch);
            if matched[k] {
                continue;
            }
            let on_surface = depth(&line, g).abs() <= 4.0 * band + got.t_rel * g.abs() * len;
            let w = 1e-2 * size;
            let ambiguous = line.over(g - w, g + w).classify().class == OracleClass::Ambiguous
                || all
                    .iter()
                    .zip(&robust)
                    .any(|(t, r)| !r && (t - g).abs() <= w);
            // A touch on the surface is a tangency (from outside or from inside the tube):
            // it changes no side, and the oracle reports only sign changes.
            if on_surface && (ambiguous || passage == Passage::Touch) {
                self.excused_crossings += 1;
            } else {
                self.invented.push(format!(
                    "{what}: crossing {g:e} {passage:?} matches no oracle root {all:?} (D − r = {:e})",
                    depth(&line, g)
                ));
            }
        }
        // The inside of every span is inside the tube (or within the band), and the
        // stretches between spans are outside.
        let mut edges = vec![if own.is_some() { lo.max(0.0) } else { lo }];
        for &(a, b) in &got.spans {
            edges.push(a);
            edges.push(b);
        }
        edges.push(hi);
        for (k, w) in edges.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            if b <= a {
                continue;
            }
            let mid = if b.is_finite() {
                0.5 * (a + b)
            } else {
                a + size
            };
            let d = depth(&line, mid);
            let inside = k % 2 == 1;
            if k % 2 == 1 {
                self.spans += 1;
            }
            if (inside && d > band) || (!inside && d < -band) {
                self.wrong_side.push(format!(
                    "{what}: [{a:e}, {b:e}] should be {} but D − r = {d:e} at its middle; spans {:?}, oracle {all:?}",
                    if inside { "inside" } else { "outside" },
                    got.spans
                ));
            }
        }
        // The side at the range's start.
        let start = if own.is_some() {
            lo.max(0.0) + 1e-3 * size
        } else {
            lo
        };
        let d0 = depth(&line, start);
        let clear_start = own.is_none() || all.iter().all(|&t| t <= 0.0 || t > start);
        if clear_start && d0.abs() > band && got.starts_inside != (d0 < 0.0) {
            self.wrong_side.push(format!(
                "{what}: starts_inside = {} but D − r = {d0:e} at the start",
                got.starts_inside
            ));
        }
        // The first crossing is intersect's hit.
        let first = got.crossings.first().map(|c| c.0);
        let agree = match (first, got.first_hit) {
            (None, None) => true,
            // intersect skips the last Newton step: on a line with a tangency elsewhere
            // (a near-double resolvent root) its root is off by up to 2e-9·size, within
            // its own stated accuracy (tests/oracle/intersect_vs_oracle.rs); the all-roots path
            // polishes it.
            (Some(a), Some(b)) => {
                self.worst_vs_intersect = self.worst_vs_intersect.max((a - b).abs() / size);
                (a - b).abs() <= 2.0 * tol(a) + NEAREST_TOL_REL * size
            }
            _ => false,
        };
        if !agree {
            self.not_intersect.push(format!(
                "{what}: first crossing {first:?}, intersect {:?}",
                got.first_hit
            ));
        }
    }

    fn report_and_assert(&self, name: &str) {
        println!(
            "{name}: {} rays, {} crossings ({} touches), {} spans; {} robust oracle roots \
             matched, worst error {:.3} of the bound; {} roots and {} crossings within the \
             band of a tangency; {} surface rays undecidable; missed {}, invented {}, \
             wrong side {}, first crossing ≠ intersect {} (worst |Δt| {:.1e}·size)",
            self.rays,
            self.crossings,
            self.touches,
            self.spans,
            self.robust_roots,
            self.worst_t,
            self.excused_roots,
            self.excused_crossings,
            self.surface_undecidable,
            self.missed.len(),
            self.invented.len(),
            self.wrong_side.len(),
            self.not_intersect.len(),
            self.worst_vs_intersect
        );
        let show = |v: &Vec<String>| v[..v.len().min(6)].join("\n");
        assert!(self.missed.is_empty(), "missed:\n{}", show(&self.missed));
        assert!(
            self.invented.is_empty(),
            "invented:\n{}",
            show(&self.invented)
        );
        assert!(
            self.wrong_side.is_empty(),
            "wrong side:\n{}",
            show(&self.wrong_side)
        );
        assert!(
            self.not_intersect.is_empty(),
            "first crossing ≠ intersect:\n{}",
            show(&self.not_intersect)
        );
    }
}

/// The same torus and ray scaled by `k` about the world origin (f32 values rounded).
fn scaled(torus: &Torus, ray: &Ray, k: f64) -> Option<(Torus, Ray)> {
    let kf = k as f32;
    let t = Torus::new(
        torus.center() * kf,
        torus.axis(),
        torus.major_radius() * kf,
        torus.minor_radius() * kf,
    )
    .ok()?;
    let r = Ray::with_range(ray.origin() * kf, ray.dir(), ray.t_min() * kf, ray.t_max()).ok()?;
    Some((t, r))
}

fn check_f32_and_f64(tally: &mut Tally, what: &str, torus: &Torus, ray: &Ray) {
    let q = Query::ray(torus, ray);
    tally.check(
        &format!("{what} f32 {ray:?}"),
        &q,
        &answer(torus, ray, f64::from),
        None,
    );
    let wide = DRay::from(*ray);
    let q = Query::dray(torus, &wide);
    tally.check(
        &format!("{what} f64 {wide:?}"),
        &q,
        &answer(torus, &wide, |t| t),
        None,
    );
}

#[test]
fn workload_cases_at_every_scale() {
    let mut tally = Tally::default();
    for nu in NUS {
        for &case in &[
            Case::Uniform,
            Case::Camera,
            Case::Grazing,
            Case::OuterBand,
            Case::Hole,
        ] {
            let batch = generate(case, nu, 150, 0xA11 ^ nu.to_bits(), Pose::Random).unwrap();
            for (torus, ray) in pairs(std::slice::from_ref(&batch)) {
                for k in SCALES {
                    let Some((t, r)) = scaled(torus, ray, k) else {
                        continue;
                    };
                    check_f32_and_f64(&mut tally, &format!("{case:?} nu={nu} k={k}"), &t, &r);
                    // The same line from 100·(R + r) farther back.
                    let far = pushed_back(&r, 100.0 * t.outer_radius());
                    check_f32_and_f64(&mut tally, &format!("{case:?} nu={nu} k={k} far"), &t, &far);
                }
            }
        }
    }
    tally.report_and_assert("workload cases");
    assert!(tally.robust_roots > 40_000, "{}", tally.robust_roots);
}

#[test]
fn adversarial_lines_hole_edge_and_tangents() {
    let mut tally = Tally::default();
    for nu in NUS {
        for family in [
            LineFamily::HoleEdge,
            LineFamily::Tangent,
            LineFamily::TangentLimit,
        ] {
            let mut rng = Pcg64::seed_from_u64(0xA12 ^ nu.to_bits());
            let (torus, rays) = family_rays(family, nu, 120, &mut rng);
            for ray in &rays {
                for k in SCALES {
                    let Some((t, r)) = scaled(&torus, ray, k) else {
                        continue;
                    };
                    check_f32_and_f64(&mut tally, &format!("{family:?} nu={nu} k={k}"), &t, &r);
                }
            }
        }
    }
    tally.report_and_assert("adversarial f32 lines");
    assert!(tally.robust_roots > 10_000, "{}", tally.robust_roots);
}

#[test]
fn exact_f64_tangents_on_an_f64_torus() {
    // The tangent lines in f64, offsets down to 1e-9·r, on Torus::new_f64: a touch or a
    // pair within the band, never a missed or invented crossing elsewhere.
    let mut tally = Tally::default();
    let mut rng = Pcg64::seed_from_u64(0xA13);
    for nu in NUS {
        for k in SCALES {
            let (major, minor) = (k, k / nu);
            let torus = Torus::new_f64(DVec3::ZERO, DVec3::Y, major, minor).unwrap();
            for i in 0..200 {
                let circle = SpecialCircle::ALL[i % 4];
                let delta = [1e-4, -1e-4, 1e-6, -1e-6, 1e-9, -1e-9, 0.0][(i / 4) % 7];
                let (p, d) = tangent_line(&mut rng, major, minor, circle, delta);
                let ray = DRay::new(p - d * 3.0 * (major + minor), d).unwrap();
                let q = Query::dray(&torus, &ray);
                let what = format!("tangent {circle:?} δ={delta} nu={nu} k={k} {ray:?}");
                tally.check(&what, &q, &answer(&torus, &ray, |t| t), None);
            }
        }
    }
    tally.report_and_assert("f64 tangents");
    assert!(tally.touches > 0);
}

/// A torus of major radius `k` and ν at a random pose, its centre `k` from the origin in a
/// random direction, with its f32 radii.
fn posed_torus(rng: &mut Pcg64, nu: f64, k: f64) -> (Torus, f32, f32) {
    let (major, minor) = (k as f32, (k / nu) as f32);
    let center = unit_vector(rng).as_vec3() * major;
    let torus = Torus::new(center, unit_vector(rng).as_vec3(), major, minor).unwrap();
    (torus, major, minor)
}

#[test]
fn rays_from_inside_the_tube() {
    let mut tally = Tally::default();
    let mut rng = Pcg64::seed_from_u64(0xA14);
    for nu in NUS {
        for k in SCALES {
            let (torus, major, minor) = posed_torus(&mut rng, nu, k);
            for _ in 0..150 {
                let phi = rng.random_range(0.0..std::f64::consts::TAU);
                let theta = rng.random_range(0.0..std::f64::consts::TAU);
                let depth = f64::from(minor) * rng.random_range(0.0..0.95);
                let radial = DVec3::new(phi.cos(), 0.0, phi.sin());
                let local = radial * f64::from(major)
                    + (radial * theta.cos() + DVec3::Y * theta.sin()) * depth;
                let world = torus.to_local_rotation_f64().transpose() * local + torus.center_f64();
                let d = unit_vector(&mut rng);
                let t_max = if rng.random_bool(0.5) {
                    f64::INFINITY
                } else {
                    rng.random_range(0.0..4.0) * k
                };
                let Ok(ray) = Ray::with_range(world.as_vec3(), d.as_vec3(), 0.0, t_max as f32)
                else {
                    continue;
                };
                check_f32_and_f64(&mut tally, &format!("inside nu={nu} k={k}"), &torus, &ray);
            }
        }
    }
    tally.report_and_assert("from inside");
    assert!(tally.spans > 2_000);
}

#[test]
fn rays_from_a_surface_point() {
    // Spawned from hits of rays aimed at the tube, in every direction (bounces, into the
    // tube, grazing); the origin's own root is never reported.
    let mut tally = Tally::default();
    let mut rng = Pcg64::seed_from_u64(0xA15);
    for nu in NUS {
        for k in SCALES {
            let (torus, major, _) = posed_torus(&mut rng, nu, k);
            let size = torus.outer_radius() as f64;
            for _ in 0..150 {
                let target = torus.center_f64() + unit_vector(&mut rng) * f64::from(major);
                let from = target + unit_vector(&mut rng) * 3.0 * size;
                let primary = DRay::new(from, target - from).unwrap();
                let Some(hit) = intersect(&torus, &primary) else {
                    continue;
                };
                let d = if rng.random_bool(0.3) {
                    // Grazing: nearly in the tangent plane.
                    let t1 = hit.normal.any_orthonormal_vector();
                    t1 + hit.normal * 10f64.powf(rng.random_range(-4.0..-1.0))
                } else {
                    unit_vector(&mut rng)
                };
                for f32_ray in [false, true] {
                    let what = format!("surface nu={nu} k={k} f32={f32_ray}");
                    if f32_ray {
                        let p32 = Ray::new(from.as_vec3(), (target - from).as_vec3()).unwrap();
                        let Some(h32) = intersect(&torus, &p32) else {
                            continue;
                        };
                        let Ok(ray) = torus.spawn(&p32, h32.t, d.as_vec3()) else {
                            continue;
                        };
                        // The on-surface rule: the line through the surface point.
                        let q = on_surface_line(&Query::ray(&torus, &ray));
                        let own = own_window(&torus, &q);
                        tally.check(&what, &q, &answer(&torus, &ray, f64::from), Some(own));
                    } else {
                        let Ok(ray) = torus.spawn(&primary, hit.t, d) else {
                            continue;
                        };
                        let q = on_surface_line(&Query::dray(&torus, &ray));
                        let own = own_window(&torus, &q);
                        tally.check(&what, &q, &answer(&torus, &ray, |t| t), Some(own));
                    }
                }
            }
        }
    }
    tally.report_and_assert("from a surface point");
    assert!(tally.robust_roots > 1_000);
}

/// The window around `t = 0` in which the origin's own root lies: δ/|cos θ₀| (δ the
/// distance from the surface of the query's origin, moved onto it), with 1e-11·(R + r) for
/// the oracle, and the band a tangency needs to clear (as tests/oracle/secondary_rays.rs).
fn own_window(torus: &Torus, q: &Query) -> f64 {
    let size = torus.outer_radius() as f64;
    let len = q.d.length();
    let to_local = torus.to_local_rotation_f64();
    let local = to_local * (q.o - torus.center_f64());
    let rho = local.x.hypot(local.z);
    let core = DVec3::new(local.x, 0.0, local.z) * (torus.major_radius_f64() / rho);
    let off = local - core;
    let delta = (off.length() - torus.minor_radius_f64()).abs();
    let n = to_local.transpose() * off.normalize();
    let cos0 = n.dot(q.d / len).abs().max(1e-12);
    4.0 * (delta + 1e-11 * size) / cos0 / len + 10.0 * AMBIGUITY_REL * size / cos0 / len
}

#[test]
fn fixed_capacity_and_bad_input() {
    // An origin near the float's largest value aimed at the torus with a short direction:
    // the crossings' t overflows and they are left out; never ∞ or NaN.
    let torus = Torus::canonical(1.0, 0.25).unwrap();
    let ray = Ray::new(Vec3::new(-3.0e38, 0.0, 0.0), Vec3::new(1e-18, 0.0, 0.0)).unwrap();
    let all = intersect_all(&torus, &ray);
    assert!(all.is_empty() && !all.starts_inside() && all.spans().is_empty());
    let ray = DRay::new(DVec3::new(-1e308, 0.0, 0.0), DVec3::new(1e-150, 0.0, 0.0)).unwrap();
    let all = intersect_all(&torus, &ray);
    assert!(all.is_empty() && all.spans().is_empty());
    // The same lines with a usable direction: four crossings, two spans.
    let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::new(1e-18, 0.0, 0.0)).unwrap();
    let all = intersect_all(&torus, &ray);
    assert_eq!(all.len(), 4);
    assert!(
        all.as_slice()
            .iter()
            .all(|c| c.t.is_finite() && c.normal.is_finite())
    );
    assert_eq!(all.spans().len(), 2);
    assert!(std::mem::size_of::<Crossings<Vec3>>() <= 128);
}

#[test]
fn wavefront_form_gives_the_scalar_answers_behind_every_cull() {
    // Every batched cull in front: every ray's answer equals intersect_all's, so a ray
    // the cull rejects (no crossing, outside all along) never had a crossing to lose.
    use torus_cull::batch::{BATCHED, Dispatch, Wavefront};
    let dispatch = Dispatch::best();
    let mut wavefront = Wavefront::new();
    let mut all = Vec::new();
    let (mut rays_checked, mut culled) = (0, 0);
    for nu in [1.01, 2.0, 32.0, 1000.0] {
        for &case in &[Case::Uniform, Case::Grazing, Case::Hole, Case::Camera] {
            let batch = generate(case, nu, 500, 0xA16 ^ nu.to_bits(), Pose::Random).unwrap();
            for cull in BATCHED {
                let stats =
                    wavefront.intersect_all(&dispatch, cull, &batch.torus, &batch.rays, &mut all);
                assert_eq!(all.len(), batch.rays.len());
                culled += stats.rays - stats.kept;
                for (ray, got) in batch.rays.iter().zip(&all) {
                    let want = intersect_all(&batch.torus, ray);
                    assert_eq!(got, &want, "{cull:?} {case:?} nu={nu}: {ray:?}");
                    rays_checked += 1;
                }
            }
        }
    }
    println!("wavefront: {rays_checked} ray answers equal to the scalar ones, {culled} culled");
    assert!(culled > 10_000);
}
