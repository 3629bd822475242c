//! Fat spindles (ν = R/a down to `MIN_FAMILY_NU` = 0.01) against the family oracle, on the
//! rays that find an apple's faults: the axis, the two cusps, tangents to the apple, rays
//! through the lemon (inside the apple: never a crossing), rays spawned from the apple near
//! its cusps, and random rays; each in f64 and as the f32 ray it rounds to (which the
//! certified f32 path hands to the f64 path, counted as escalated). Every member at
//! ν ∈ {0.01, 0.1, 0.3, 0.5} × b/a ∈ {¼, ½, 1, 2, 4}: 0 missed, 0 invented, `t` within
//! 10⁻⁹ of the size (f64 rays; 10⁻⁶ of size + t for the f32 `t`), every crossing equal,
//! 0 false rejects for every cull the member's shape does not decline.

use crate::family::{posed, query, rays, size};
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::cull::Shape;
use torus_cull::family::Toroid;
use torus_cull::{CullKind, DRay, Passage, Ray};
use torus_cull_lab::oracle::OracleClass;
use torus_cull_lab::oracle::family::Passage as OraclePassage;

const NUS: [f64; 4] = [0.01, 0.1, 0.3, 0.5];
const ASPECTS: [f64; 5] = [0.25, 0.5, 1.0, 2.0, 4.0];

/// The kinds of structured ray, for the counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Axis,
    Cusp,
    AppleTangent,
    Lemon,
    Random,
}

/// The member's frame: centre, axis, and two unit vectors across it.
fn frame(t: &Toroid) -> (DVec3, DVec3, DVec3, DVec3) {
    let axis = t.axis_f64();
    let (e0, e1) = axis.any_orthonormal_pair();
    (t.center_f64(), axis, e0, e1)
}

fn random_unit(rng: &mut Pcg64) -> DVec3 {
    loop {
        let v = DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        if (1e-2..=1.0).contains(&v.length_squared()) {
            return v.normalize();
        }
    }
}

/// The apple's point at tube angle θ (ρ = R + a cos θ ≥ 0) and azimuth φ, its outward
/// normal.
fn apple_point(t: &Toroid, theta: f64, phi: f64) -> (DVec3, DVec3) {
    let (c, axis, e0, e1) = frame(t);
    let (big, a, b) = (
        t.major_radius_f64(),
        t.radial_semi_axis_f64(),
        t.axial_semi_axis_f64(),
    );
    let radial = e0 * phi.cos() + e1 * phi.sin();
    let rho = (big + a * theta.cos()).max(0.0);
    let p = c + radial * rho + axis * (b * theta.sin());
    let n = (radial * (theta.cos() / a) + axis * (theta.sin() / b)).normalize();
    (p, n)
}

/// The tube angle of the upper cusp, where ρ = R + a cos θ = 0.
fn cusp_theta(t: &Toroid) -> f64 {
    (-t.nu()).acos()
}

/// The structured rays of one member (module docs), with their kind.
fn structured(t: &Toroid, rng: &mut Pcg64, n: usize) -> Vec<(DRay, Kind)> {
    let s = size(t);
    let (c, axis, e0, e1) = frame(t);
    let (big, a, b) = (
        t.major_radius_f64(),
        t.radial_semi_axis_f64(),
        t.axial_semi_axis_f64(),
    );
    let cusp_y = b * (1.0 - t.nu() * t.nu()).sqrt();
    let mut out = Vec::new();
    let mut push = |o: DVec3, d: DVec3, kind| out.push((DRay::new(o, d).unwrap(), kind));
    // The axis: exactly, both ways, from outside and from the centre; then parallel lines
    // 10⁻⁸…10⁻¹ of the size off it, and lines tilted by up to 10⁻².
    for sign in [1.0, -1.0] {
        push(c + axis * (sign * 3.0 * s), -axis * sign, Kind::Axis);
        push(c, axis * sign, Kind::Axis);
    }
    for _ in 0..n {
        let off = (e0 * rng.random_range(-1.0..1.0) + e1 * rng.random_range(-1.0..1.0))
            * (s * 10f64.powf(rng.random_range(-8.0..-1.0)));
        let tilt = (e0 * rng.random_range(-1.0..1.0) + e1 * rng.random_range(-1.0..1.0))
            * 10f64.powf(rng.random_range(-6.0..-2.0));
        let sign = if rng.random() { 1.0 } else { -1.0 };
        push(
            c + off + axis * (sign * 3.0 * s),
            tilt - axis * sign,
            Kind::Axis,
        );
    }
    // Through either cusp (exactly, or nudged by 10⁻¹²…10⁻⁴ of the size) from every side.
    for _ in 0..n {
        let y = if rng.random() { cusp_y } else { -cusp_y };
        let nudge = random_unit(rng) * (s * 10f64.powf(rng.random_range(-12.0..-4.0)));
        let at = c + axis * y + if rng.random() { nudge } else { DVec3::ZERO };
        let d = random_unit(rng);
        push(at - d * (2.0 * s), d, Kind::Cusp);
    }
    // Tangent to the apple (θ on the apple's arc), pushed ±10⁻⁸…10⁻³ of the size.
    let top = cusp_theta(t);
    for _ in 0..n {
        let theta = rng.random_range(-top..top);
        let (p, nrm) = apple_point(t, theta, rng.random_range(0.0..std::f64::consts::TAU));
        let tangent = nrm.any_orthonormal_vector();
        let spin = rng.random_range(0.0..std::f64::consts::TAU);
        let d = tangent * spin.cos() + nrm.cross(tangent) * spin.sin();
        let pushed =
            s * 10f64.powf(rng.random_range(-8.0..-3.0)) * if rng.random() { 1.0 } else { -1.0 };
        push(p + nrm * pushed - d * (2.0 * s), d, Kind::AppleTangent);
    }
    // Through the lemon: from a point inside it, any way; and lines tangent to the lemon
    // (its θ past the cusps, ρ = −(R + a cos θ)), which lie inside the apple there.
    for _ in 0..n {
        let phi = rng.random_range(0.0..std::f64::consts::TAU);
        let radial = e0 * phi.cos() + e1 * phi.sin();
        if rng.random() {
            // (ρ, y) inside the lemon ((ρ + R)/a)² + (y/b)² < 1, ρ ≥ 0.
            let rho = rng.random_range(0.0..(a - big));
            let ymax = b * (1.0 - ((rho + big) / a).powi(2)).max(0.0).sqrt();
            let y = rng.random_range(-1.0..1.0) * ymax;
            push(c + radial * rho + axis * y, random_unit(rng), Kind::Lemon);
        } else {
            let theta = rng.random_range(top..std::f64::consts::TAU - top);
            let rho = -(big + a * theta.cos());
            let p = c + radial * rho + axis * (b * theta.sin());
            // The lemon's normal in the meridian: the ellipse's, mirrored through the axis.
            let nrm = (radial * (-theta.cos() / a) + axis * (theta.sin() / b)).normalize();
            let tangent = nrm.any_orthonormal_vector();
            let spin = rng.random_range(0.0..std::f64::consts::TAU);
            let d = tangent * spin.cos() + nrm.cross(tangent) * spin.sin();
            push(p - d * (2.0 * s), d, Kind::Lemon);
        }
    }
    // Random: the box rays, grazing rays and near-axis rays of the family test.
    for (ray, _) in rays(t, rng, n) {
        out.push((ray, Kind::Random));
    }
    out
}

/// Whether the world point lies within 10⁻⁴ of the size of either cusp, where a crossing
/// is a double root of the quartic, found to about √ε of the size (not the 10⁻⁹ of a
/// simple one).
fn near_cusp(t: &Toroid, p: DVec3) -> bool {
    let (c, axis) = (t.center_f64(), t.axis_f64());
    let y = t.axial_semi_axis_f64() * (1.0 - t.nu() * t.nu()).sqrt();
    [y, -y]
        .iter()
        .any(|&y| (p - (c + axis * y)).length() <= 1e-4 * size(t))
}

/// The largest error allowed in a crossing's `t`, as a length: 10⁻⁹ of the size (f64)
/// or 10⁻⁶ of size + t (the f32 `t`), 2·10⁻⁷ of the size at a cusp.
fn allowed(t: &Toroid, o: DVec3, d: DVec3, want: f64, f64_ray: bool) -> f64 {
    let s = size(t);
    let base = if f64_ray {
        1e-9 * s
    } else {
        1e-6 * (s + want.abs() * d.length())
    };
    if near_cusp(t, o + d * want) {
        base.max(2e-7 * s)
    } else {
        base
    }
}

/// What a member's rays found.
#[derive(Default, Debug)]
struct Tally {
    judged: std::collections::BTreeMap<Kind, usize>,
    f32_judged: usize,
    missed: Vec<String>,
    invented: Vec<String>,
    far: Vec<String>,
    worst: f64,
    false_rejects: Vec<String>,
    crossings_compared: usize,
    crossings_wrong: Vec<String>,
}

/// One ray to judge: its f64 line and range, the library's `t` (widened to f64), and
/// which culls keep it.
struct Judged<'a> {
    o: DVec3,
    d: DVec3,
    range: (f64, f64),
    got: Option<f64>,
    kept: &'a dyn Fn(CullKind) -> bool,
    f64_ray: bool,
}

/// Judges one ray (f64, or the f32 ray it rounds to) against the oracle.
fn judge(t: &Toroid, r: &Judged, kind: Kind, tally: &mut Tally, ctx: &str) {
    let s = size(t);
    let q = query(t, r.o, r.d, r.range.0, r.range.1);
    let label = q.classify();
    if label.class == OracleClass::Ambiguous {
        return;
    }
    if r.f64_ray {
        *tally.judged.entry(kind).or_default() += 1;
    } else {
        tally.f32_judged += 1;
    }
    let what = || format!("{ctx} {kind:?} f64 {} o {:?} d {:?}", r.f64_ray, r.o, r.d);
    match (label.class, r.got) {
        (OracleClass::Hit, None) => tally.missed.push(what()),
        (OracleClass::Miss, Some(_)) => tally.invented.push(what()),
        (OracleClass::Hit, Some(got)) => {
            let want = q.first_crossing().unwrap();
            let err = (got - want).abs() * r.d.length();
            let allowed = allowed(t, r.o, r.d, want, r.f64_ray);
            tally.worst = tally.worst.max(err / s);
            if err > allowed {
                tally.far.push(format!("{}: {got} vs {want}", what()));
            }
        }
        _ => {}
    }
    if label.class == OracleClass::Hit {
        for cull in CullKind::TIMED {
            if !(r.kept)(cull) {
                tally.false_rejects.push(format!("{cull} {}", what()));
            }
        }
    }
}

/// Every crossing of `intersect_all` against the oracle's (f64 rays whose oracle crossings
/// are 10⁻⁶ of the size apart: a closer pair may come back as a touch).
fn judge_crossings(t: &Toroid, ray: &DRay, kind: Kind, tally: &mut Tally, ctx: &str) {
    let s = size(t);
    let q = query(t, ray.origin(), ray.dir(), ray.t_min(), ray.t_max());
    if q.classify().class == OracleClass::Ambiguous {
        return;
    }
    let len = ray.dir().length();
    let want: Vec<(f64, Passage)> = q
        .crossings()
        .iter()
        .filter_map(|c| match c.passage {
            OraclePassage::Entering => Some((c.t, Passage::Enter)),
            OraclePassage::Leaving => Some((c.t, Passage::Exit)),
            OraclePassage::Touching => None,
        })
        .collect();
    if want.windows(2).any(|w| (w[1].0 - w[0].0) * len < 1e-6 * s) {
        return;
    }
    let mut got: Vec<(f64, Passage)> = t
        .intersect_all(ray)
        .as_slice()
        .iter()
        .filter(|c| c.passage != Passage::Touch)
        .map(|c| (c.t, c.passage))
        .collect();
    // A line inside the apple on both sides of a cusp touches the surface there (the
    // oracle's touch); f64 may split that double root into an exit and an entry a few
    // ulps apart, a gap of no width: counted as the touch.
    let ray_point = |t_: f64| ray.origin() + ray.dir() * t_;
    if let Some(i) = got.windows(2).position(|w| {
        w[0].1 == Passage::Exit
            && w[1].1 == Passage::Enter
            && (w[1].0 - w[0].0) * len <= 1e-12 * s
            && near_cusp(t, ray_point(w[0].0))
    }) {
        got.drain(i..i + 2);
    }
    tally.crossings_compared += 1;
    let same = got.len() == want.len()
        && got.iter().zip(&want).all(|(g, w)| {
            let tol = (1e-8 * s).max(allowed(t, ray.origin(), ray.dir(), w.0, true));
            g.1 == w.1 && (g.0 - w.0).abs() * len <= tol
        });
    if !same {
        tally.crossings_wrong.push(format!(
            "{ctx} {kind:?} {ray:?}: got {got:?}, want {want:?}"
        ));
    }
}

#[test]
fn fat_spindles_on_structured_and_random_rays_against_the_oracle() {
    let mut rng = Pcg64::seed_from_u64(54_000);
    let mut tally = Tally::default();
    for nu in NUS {
        for aspect in ASPECTS {
            for scale in [1e-3, 1.0, 1e3] {
                let t = posed(&mut rng, (nu, 1.0, aspect), scale);
                assert_eq!(t.shape(), Shape::Spindle);
                let ctx = format!("nu {nu} b/a {aspect} ×{scale}");
                for (ray, kind) in structured(&t, &mut rng, 60) {
                    let kept = |c: CullKind| t.kept_by(&c, &ray);
                    let judged = Judged {
                        o: ray.origin(),
                        d: ray.dir(),
                        range: (ray.t_min(), ray.t_max()),
                        got: t.intersect(&ray).map(|h| h.t),
                        kept: &kept,
                        f64_ray: true,
                    };
                    judge(&t, &judged, kind, &mut tally, &ctx);
                    judge_crossings(&t, &ray, kind, &mut tally, &ctx);
                    // Never a NaN normal, at a cusp either (there: along the axis).
                    let hit = t.intersect(&ray);
                    assert!(hit.is_none_or(|h| h.normal.is_finite()), "{ctx} {ray:?}");
                    let all = t.intersect_all(&ray);
                    assert!(
                        all.as_slice().iter().all(|c| c.normal.is_finite()),
                        "{ray:?}"
                    );
                    if let Ok(r) = Ray::new(ray.origin().as_vec3(), ray.dir().as_vec3()) {
                        let kept = |c: CullKind| t.kept_by(&c, &r);
                        let judged = Judged {
                            o: r.origin().as_dvec3(),
                            d: r.dir().as_dvec3(),
                            range: (f64::from(r.t_min()), f64::from(r.t_max())),
                            got: t.intersect(&r).map(|h| f64::from(h.t)),
                            kept: &kept,
                            f64_ray: false,
                        };
                        judge(&t, &judged, kind, &mut tally, &ctx);
                        // The certified f32 path takes circular ring members alone: a
                        // spindle's f32 ray is the f64 path's answer, escalated.
                        let f = t.intersect_f32(&r);
                        assert!(f.escalated, "{ctx}");
                        assert_eq!(f.hit, t.intersect(&r), "{ctx}");
                    }
                }
            }
        }
    }
    eprintln!(
        "fat spindles: judged {:?} (f64), {} f32; missed {}, invented {}, far {}, worst t \
         error {:.2e} of the size; {} false rejects; crossings {} compared, {} wrong",
        tally.judged,
        tally.f32_judged,
        tally.missed.len(),
        tally.invented.len(),
        tally.far.len(),
        tally.worst,
        tally.false_rejects.len(),
        tally.crossings_compared,
        tally.crossings_wrong.len()
    );
    if let Ok(path) = std::env::var("SPINDLE_DUMP") {
        let all: Vec<String> = [
            &tally.missed,
            &tally.invented,
            &tally.far,
            &tally.false_rejects,
            &tally.crossings_wrong,
        ]
        .iter()
        .zip(["missed", "invented", "far", "reject", "crossings"])
        .flat_map(|(v, n)| v.iter().map(move |l| format!("{n} {l}")))
        .collect();
        std::fs::write(path, all.join("\n")).unwrap();
    }
    for kind in [
        Kind::Axis,
        Kind::Cusp,
        Kind::AppleTangent,
        Kind::Lemon,
        Kind::Random,
    ] {
        assert!(
            tally.judged.get(&kind).copied().unwrap_or(0) > 1_000,
            "{kind:?}"
        );
    }
    let first = |v: &Vec<String>| v.iter().take(3).cloned().collect::<Vec<_>>();
    assert!(tally.missed.is_empty(), "missed {:?}", first(&tally.missed));
    assert!(
        tally.invented.is_empty(),
        "invented {:?}",
        first(&tally.invented)
    );
    assert!(tally.far.is_empty(), "far {:?}", first(&tally.far));
    assert!(
        tally.false_rejects.is_empty(),
        "{} false rejects {:?}",
        tally.false_rejects.len(),
        first(&tally.false_rejects)
    );
    assert!(tally.crossings_compared > 10_000);
    assert!(
        tally.crossings_wrong.is_empty(),
        "{} crossings wrong {:?}",
        tally.crossings_wrong.len(),
        first(&tally.crossings_wrong)
    );
}

/// Rays spawned from the apple near its cusps (ρ from 10⁻⁶ to 10⁻¹ of a), f64 and f32:
/// 0 missed and 0 invented against the oracle's on-surface rule.
#[test]
fn rays_spawned_near_a_fat_spindle_s_cusps_against_the_oracle() {
    let mut rng = Pcg64::seed_from_u64(54_001);
    let (mut judged, mut wrong) = (0usize, Vec::new());
    for nu in NUS {
        for aspect in ASPECTS {
            let t = posed(&mut rng, (nu, 1.0, aspect), 1.0);
            let s = size(&t);
            let (a, top) = (t.radial_semi_axis_f64(), cusp_theta(&t));
            for _ in 0..60 {
                // The apple's point at ρ = 10⁻⁶…10⁻¹·a from the axis, near either cusp.
                let rho = a * 10f64.powf(rng.random_range(-6.0..-1.0));
                let theta = ((rho - t.major_radius_f64()) / a).clamp(-1.0, 1.0).acos();
                debug_assert!(theta <= top);
                let theta = if rng.random() { theta } else { -theta };
                let (p, n) = apple_point(&t, theta, rng.random_range(0.0..std::f64::consts::TAU));
                let incoming = (random_unit(&mut rng) - n * 1.5).normalize();
                let ray = DRay::new(p - incoming * s, incoming).unwrap();
                let f32_ray = Ray::new(ray.origin().as_vec3(), ray.dir().as_vec3()).unwrap();
                let Some(hit) = t.intersect(&ray) else {
                    continue;
                };
                let hit32 = t.intersect(&f32_ray);
                for _ in 0..4 {
                    let dir = random_unit(&mut rng);
                    let spawned = t.spawn(&ray, hit.t, dir).unwrap();
                    let mut check = |o: DVec3, d: DVec3, got: Option<f64>, tol: f64| {
                        let q = query(&t, o, d, 0.0, f64::INFINITY);
                        let label = q.classify_from_surface();
                        if label.class == OracleClass::Ambiguous {
                            return;
                        }
                        judged += 1;
                        let ok = match (label.class, got) {
                            (OracleClass::Hit, Some(g)) => {
                                let want = q.first_crossing_from_surface().unwrap();
                                (g - want).abs() * d.length() <= tol * s
                            }
                            (OracleClass::Miss, None) => true,
                            _ => false,
                        };
                        if !ok {
                            wrong.push(format!("nu {nu} b/a {aspect} {o:?} {d:?}: {got:?}"));
                        }
                    };
                    check(
                        spawned.origin(),
                        spawned.dir(),
                        t.intersect(&spawned).map(|h| h.t),
                        1e-9,
                    );
                    if let Some(h) = hit32 {
                        let sp = t.spawn(&f32_ray, h.t, dir.as_vec3()).unwrap();
                        check(
                            sp.origin().as_dvec3(),
                            sp.dir().as_dvec3(),
                            t.intersect(&sp).map(|h| f64::from(h.t)),
                            1e-6,
                        );
                    }
                }
            }
        }
    }
    eprintln!(
        "spawned near the cusps: {judged} judged, {} wrong",
        wrong.len()
    );
    assert!(judged > 4_000, "{judged}");
    assert!(
        wrong.is_empty(),
        "{}: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(3)]
    );
}
