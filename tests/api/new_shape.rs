//! The recipe for a new shape (docs/layout.md, "Adding a shape"), proved by a shape that
//! lives in this file alone: a ball (a sphere) of radius ρ threaded on the core circle of
//! a host ring torus, inside its tube (ρ < r), so that the torus culls, applied to the
//! host, are conservative for it. It implements the library's [`Solid`] (every verb; its
//! cull verb is the host torus's) and the lab's [`LabShape`] (its own exact oracle), and
//! goes through the lab's own code paths, the ones `run`, `check` and `eval` take for the
//! library's shapes: [`shape_sweep::sweep_shape`], [`check::check`] (with
//! [`SolidCheck`]) and [`eval::eval_shape_csv`]. No lab file outside this test names it.
//!
//! Asserted: 0 false rejects by every cull row against the ball's exact oracle (a hit
//! rejected would fail), rows that do reject (the culls work on it), the check's counts
//! (rays, hits + misses + ambiguous, our exact hit against the oracle), and eval's header
//! and columns (every cull keeps an oracle hit; `t_hit` where the oracle says hit).

use glam::{DVec3, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::{
    Cull, CullKind, DRay, DRayError, NoFace, NonFinitePoint, Passage, PointQueryError, Precision,
    Ray, RayError, Solid, SolidCrossing, SolidCrossings, SolidF32Hit, SolidHit, SolidProjection,
    Torus,
};
use torus_cull_lab::check::solid::SolidCheck;
use torus_cull_lab::check::{self, CheckShape};
use torus_cull_lab::eval::{self, EvalError, Precision as EvalPrecision};
use torus_cull_lab::lab_shape::LabShape;
use torus_cull_lab::measure::CountedCull;
use torus_cull_lab::oracle::{OracleClass, OracleLabel};
use torus_cull_lab::shape_sweep::{self, Member, Params};

/// A ball of radius `radius` about `center`, a point of the host torus's core circle.
#[derive(Debug, Clone)]
struct Ball {
    center: DVec3,
    radius: f64,
    /// The ring torus whose tube holds the ball: the culls' bounding torus.
    host: Torus,
}

impl Ball {
    /// The ball on the host's core circle at angle `phi`, its radius `share` of the tube's.
    fn on(host: Torus, phi: f64, share: f64) -> Ball {
        let axis = host.axis_f64().normalize();
        let (x, z) = axis.any_orthonormal_pair();
        let r = host.major_radius_f64();
        Ball {
            center: host.center_f64() + (x * phi.cos() + z * phi.sin()) * r,
            radius: share * host.minor_radius_f64(),
            host,
        }
    }

    /// Both roots of |o + t·d − c|² = ρ², ascending, in f64.
    fn roots(&self, o: DVec3, d: DVec3) -> Option<(f64, f64)> {
        let oc = o - self.center;
        let (a, b, c) = (d.dot(d), oc.dot(d), oc.dot(oc) - self.radius * self.radius);
        let disc = b * b - a * c;
        if disc < 0.0 {
            return None;
        }
        // The root of larger magnitude first (no cancellation), the other by Vieta.
        let q = -(b + b.signum() * disc.sqrt());
        if q == 0.0 {
            return Some((0.0, 0.0));
        }
        let (t1, t2) = (q / a, c / q);
        Some((t1.min(t2), t1.max(t2)))
    }

    /// The crossings `(t, entering)` of the line in `[t_min, t_max]`, the origin's own
    /// root skipped for a ray from the surface.
    fn crossings_of(&self, o: DVec3, d: DVec3, range: (f64, f64), on: bool) -> Vec<(f64, bool)> {
        let Some((t1, t2)) = self.roots(o, d) else {
            return Vec::new();
        };
        let own = match on {
            true if t1.abs() <= t2.abs() => t1,
            true => t2,
            false => f64::NAN,
        };
        [(t1, true), (t2, false)]
            .into_iter()
            .filter(|&(t, _)| t >= range.0 && t <= range.1 && t != own)
            .collect()
    }

    fn normal(&self, p: DVec3) -> DVec3 {
        (p - self.center).normalize()
    }

    fn hit_in<P: Precision>(
        &self,
        (o, d): (DVec3, DVec3),
        range: (f64, f64),
        on: bool,
        cast: impl Fn(f64, DVec3, DVec3) -> SolidHit<P, NoFace>,
    ) -> Option<SolidHit<P, NoFace>> {
        let &(t, _) = self.crossings_of(o, d, range, on).first()?;
        let p = o + d * t;
        Some(cast(t, self.normal(p), p))
    }

    /// The world point nearest `p` on the sphere (the centre itself: any direction).
    fn onto(&self, p: DVec3) -> DVec3 {
        let v = p - self.center;
        let n = if v.length_squared() > 0.0 {
            v.normalize()
        } else {
            DVec3::Y
        };
        self.center + n * self.radius
    }
}

fn f32_line(ray: &Ray) -> ((DVec3, DVec3), (f64, f64)) {
    (
        (ray.origin().as_dvec3(), ray.dir().as_dvec3()),
        (f64::from(ray.t_min()), f64::from(ray.t_max())),
    )
}

fn f64_line(ray: &DRay) -> ((DVec3, DVec3), (f64, f64)) {
    ((ray.origin(), ray.dir()), (ray.t_min(), ray.t_max()))
}

/// Step 1 of the recipe: the library's interface, every verb in f64 and rounded once.
impl Solid for Ball {
    type Face = NoFace;

    fn world_aabb(&self) -> (Vec3, Vec3) {
        let r = DVec3::splat(self.radius);
        let lo = (self.center - r).as_vec3();
        let hi = (self.center + r).as_vec3();
        // Outward by an f32 ulp's worth of the largest coordinate.
        let pad = Vec3::splat(f32::EPSILON * lo.abs().max(hi.abs()).max_element().max(1.0));
        (lo - pad, hi + pad)
    }

    fn hit(&self, ray: &Ray) -> Option<SolidHit<Vec3, NoFace>> {
        let (line, range) = f32_line(ray);
        self.hit_in(line, range, ray.starts_on_surface(), |t, n, p| {
            SolidHit::new(
                t as f32,
                n.as_vec3(),
                p.as_vec3(),
                n.dot(line.1) < 0.0,
                NoFace,
            )
        })
    }

    fn hit_f64(&self, ray: &DRay) -> Option<SolidHit<DVec3, NoFace>> {
        let (line, range) = f64_line(ray);
        self.hit_in(line, range, ray.starts_on_surface(), |t, n, p| {
            SolidHit::new(t, n, p, n.dot(line.1) < 0.0, NoFace)
        })
    }

    fn occluded(&self, ray: &Ray) -> bool {
        self.hit(ray).is_some()
    }

    fn occluded_f64(&self, ray: &DRay) -> bool {
        self.hit_f64(ray).is_some()
    }

    fn crossings(&self, ray: &Ray) -> SolidCrossings<Vec3, NoFace> {
        let (line, range) = f32_line(ray);
        let inside = self.contains(line.0 + line.1 * range.0).unwrap_or(false);
        let mut all = SolidCrossings::new(ray.t_min(), ray.t_max(), inside);
        for (t, enter) in self.crossings_of(line.0, line.1, range, ray.starts_on_surface()) {
            let passage = if enter { Passage::Enter } else { Passage::Exit };
            let n = self.normal(line.0 + line.1 * t).as_vec3();
            all.push(SolidCrossing::new(t as f32, n, passage, NoFace));
        }
        all
    }

    fn crossings_f64(&self, ray: &DRay) -> SolidCrossings<DVec3, NoFace> {
        let (line, range) = f64_line(ray);
        let inside = self.contains(line.0 + line.1 * range.0).unwrap_or(false);
        let mut all = SolidCrossings::new(ray.t_min(), ray.t_max(), inside);
        for (t, enter) in self.crossings_of(line.0, line.1, range, ray.starts_on_surface()) {
            let passage = if enter { Passage::Enter } else { Passage::Exit };
            let n = self.normal(line.0 + line.1 * t);
            all.push(SolidCrossing::new(t, n, passage, NoFace));
        }
        all
    }

    /// The ball proves nothing in f32: every ray is the f64 path's, escalated.
    fn hit_f32_certified(&self, ray: &Ray) -> SolidF32Hit<NoFace> {
        SolidF32Hit::new(self.hit(ray), true)
    }

    /// Step 2: the cull verb. The ball lies in the host's solid tube, so the host's
    /// verdict is conservative for it.
    fn kept_by<C: Cull + ?Sized, P: Precision>(&self, cull: &C, ray: &Ray<P>) -> bool {
        self.host.kept_by(cull, ray)
    }

    fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Result<Ray, RayError> {
        let p = self.onto(ray.at(t).as_dvec3());
        Ray::from_surface(p.as_vec3(), dir)
    }

    fn spawn_f64(&self, ray: &DRay, t: f64, dir: DVec3) -> Result<DRay, DRayError> {
        DRay::from_surface(self.onto(ray.at(t)), dir)
    }

    fn contains(&self, p: DVec3) -> Result<bool, PointQueryError> {
        Ok(self.signed_distance(p)? <= 0.0)
    }

    fn signed_distance(&self, p: DVec3) -> Result<f64, PointQueryError> {
        if !p.is_finite() {
            return Err(NonFinitePoint(p).into());
        }
        Ok((p - self.center).length() - self.radius)
    }

    fn project_point(&self, p: DVec3) -> Result<SolidProjection<NoFace>, PointQueryError> {
        let d = self.signed_distance(p)?;
        let q = self.onto(p);
        Ok(SolidProjection::new(q, self.normal(q), d, NoFace))
    }
}

/// Step 3 of the recipe: the lab's questions. The oracle is the ball's own, exact and
/// independent of the roots above: the line's distance from the centre over the ray's
/// range, min and max; it crosses the sphere iff `min ≤ ρ ≤ max`.
impl LabShape for Ball {
    type Solid = Ball;

    fn solid(&self) -> &Ball {
        self
    }

    fn label(&self, ray: &DRay) -> Result<OracleLabel, String> {
        if ray.starts_on_surface() {
            return Err("the ball's oracle labels literal rays only".into());
        }
        let (o, d) = (ray.origin() - self.center, ray.dir());
        let dist = |t: f64| (o + d * t).length();
        let (t0, t1) = (ray.t_min(), ray.t_max());
        let nearest = (-o.dot(d) / d.dot(d)).clamp(t0, t1);
        let (min, max) = (dist(nearest), dist(t0).max(dist(t1)));
        let rho = self.radius;
        let margin = if min <= rho && rho <= max {
            -(rho - min).min(max - rho)
        } else if min > rho {
            min - rho
        } else {
            rho - max
        };
        Ok(OracleLabel::from_margin(margin, rho, 0.0))
    }

    fn size(&self) -> f64 {
        self.radius
    }
}

/// Rays of class `index`: from a sphere of radius 4·(R + r) about the host's centre,
/// aimed at the ball's box (doubled) for the even ones, at the host's box for the odd
/// ones (most of which miss the ball, and some the host: the culls' matter).
fn draw(ball: &Ball, i: usize, rng: &mut Pcg64) -> DRay {
    let unit = |rng: &mut Pcg64| loop {
        let v = DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        if v.length_squared() > 1e-3 && v.length_squared() <= 1.0 {
            break v.normalize();
        }
    };
    let host = &ball.host;
    let size = host.major_radius_f64() + host.minor_radius_f64();
    let origin = host.center_f64() + unit(rng) * 4.0 * size;
    let (center, reach) = if i % 2 == 0 {
        (ball.center, 2.0 * ball.radius)
    } else {
        (host.center_f64(), size)
    };
    let target = center + unit(rng) * reach * rng.random_range(0.0..1.0);
    DRay::new(origin, target - origin).expect("a finite non-zero direction")
}

/// The test's balls: a canonical host and a posed one.
fn balls() -> Vec<Ball> {
    let posed = Torus::new(
        Vec3::new(1.0, -2.0, 0.5),
        Vec3::new(0.3, 1.0, -0.2),
        4.0,
        1.5,
    );
    vec![
        Ball::on(Torus::canonical(4.0, 1.0).unwrap(), 0.7, 0.8),
        Ball::on(posed.unwrap(), 2.0, 0.5),
    ]
}

fn timed() -> Vec<CountedCull> {
    CullKind::TIMED.iter().map(|&c| c.into()).collect()
}

const RAYS: usize = 2000;

#[test]
fn a_new_shape_runs_through_the_shape_sweep_with_no_false_reject() {
    for (k, ball) in balls().iter().enumerate() {
        let mut rng = Pcg64::seed_from_u64(7 + k as u64);
        let rays: Vec<DRay> = (0..RAYS).map(|i| draw(ball, i, &mut rng)).collect();
        let member = Member {
            label: format!("ball {k}"),
            pose: format!("{ball:?}"),
            first: 0,
        };
        let params = Params::named("ball");
        let unit = shape_sweep::sweep_shape(ball, &rays, &timed(), (&member, 4.0, params))
            .expect("the ball's oracle labels every literal ray");
        assert!(unit.false_rejects.is_empty(), "{:?}", unit.false_rejects);
        let records: Vec<_> = unit.records().collect();
        // One record per timed cull (no guard), each accepting the ball.
        assert_eq!(records.len(), CullKind::TIMED.len());
        let mut rejecting = 0;
        for r in &records {
            let c = &r.counts;
            assert_eq!((r.shape.as_str(), r.accepts), ("ball", true));
            assert_eq!(c.rays, RAYS as u64, "{}", c.cull);
            assert_eq!(c.hits + c.misses + c.ambiguous, c.rays, "{}", c.cull);
            assert!(
                c.hits > RAYS as u64 / 10 && c.misses > RAYS as u64 / 10,
                "{c:?}"
            );
            assert_eq!(c.false_rejects, 0, "{}", c.cull);
            assert!(c.rejected <= c.misses + c.ambiguous, "{}", c.cull);
            if c.cull == "none" {
                assert_eq!(c.rejected, 0);
            }
            rejecting += usize::from(c.rejected > 0);
        }
        assert!(rejecting >= 3, "only {rejecting} culls reject a ray");
    }
}

#[test]
fn a_new_shape_runs_through_the_check_pipeline() {
    let shape = SolidCheck {
        name: "ball",
        classes: balls()
            .into_iter()
            .enumerate()
            .map(|(k, b)| (format!("ball {k}"), b))
            .collect(),
        draw,
    };
    assert_eq!(shape.labels(), ["ball 0", "ball 1"]);
    let checked = check::check(&shape, &[0, 1], (RAYS, 2026), 2, &|_, _| {}).unwrap();
    assert_eq!(checked.records.len(), 2);
    for record in &checked.records {
        assert_eq!(record.rays, RAYS as u64);
        let kind = &record.kinds[0];
        assert_eq!(kind.rays, RAYS as u64);
        assert_eq!(kind.hits + kind.misses + kind.ambiguous, kind.rays);
        assert!(kind.hits > 0 && kind.misses > 0, "{kind:?}");
        assert_eq!(record.culls.len(), CullKind::TIMED.len());
        for cull in &record.culls {
            assert_eq!(cull.counts.false_rejects, 0, "{}", cull.cull);
            assert!(cull.accepts);
        }
        assert!(record.culls.iter().any(|c| c.counts.rejected > 0));
        let hit = &record.answers[0];
        assert_eq!((hit.count("missed"), hit.count("invented")), (0, 0));
    }
    // The same rays for a class alone, as for the whole check.
    let alone = check::check(&shape, &[1], (RAYS, 2026), 1, &|_, _| {}).unwrap();
    assert_eq!(
        format!("{:?}", alone.records[0]),
        format!("{:?}", checked.records[1])
    );
}

#[test]
fn a_new_shape_answers_eval_rows() {
    let ball = &balls()[1];
    let mut rng = Pcg64::seed_from_u64(99);
    let rays: Vec<DRay> = (0..400).map(|i| draw(ball, i, &mut rng)).collect();
    let mut input = String::from("ox,oy,oz,dx,dy,dz\n");
    for r in &rays {
        let (o, d) = (r.origin(), r.dir());
        input += &format!("{},{},{},{},{},{}\n", o.x, o.y, o.z, d.x, d.y, d.z);
    }
    let mut out = Vec::new();
    let rows = eval::eval_shape_csv(
        ball,
        EvalPrecision::F64,
        input.as_bytes(),
        "ball.csv",
        &mut out,
    )
    .unwrap();
    assert_eq!(rows, rays.len());
    let text = String::from_utf8(out).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(eval::output_header().as_str()));
    let (mut hits, mut rejected) = (0, 0);
    for (i, line) in lines.enumerate() {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 4 + CullKind::TIMED.len(), "{line}");
        assert_eq!(f[0], i.to_string());
        let label = ball.label(&rays[i]).unwrap();
        let oracle = match label.class {
            OracleClass::Hit => "hit",
            OracleClass::Miss => "miss",
            OracleClass::Ambiguous => "ambiguous",
        };
        assert_eq!(f[1], oracle, "{line}");
        if label.class != OracleClass::Ambiguous {
            assert_eq!(!f[3].is_empty(), label.class == OracleClass::Hit, "{line}");
        }
        if label.class == OracleClass::Hit {
            hits += 1;
            assert!(
                f[4..].iter().all(|&bit| bit == "1"),
                "a hit rejected: {line}"
            );
        }
        rejected += f[4..].iter().filter(|&&bit| bit == "0").count();
    }
    assert!(
        hits > 0 && rejected > 0,
        "{hits} hits, {rejected} rejections"
    );
    // The certified mode answers through the interface (escalated: the ball proves
    // nothing in f32); the GPU, which takes the ring torus alone, is refused.
    let mut out = Vec::new();
    eval::eval_shape_csv(
        ball,
        EvalPrecision::CertifiedF32,
        input.as_bytes(),
        "ball.csv",
        &mut out,
    )
    .unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.lines()
            .skip(1)
            .all(|l| l.split(',').nth(4) == Some("1"))
    );
    let gpu = eval::eval_shape_csv(
        ball,
        EvalPrecision::CertifiedGpu,
        input.as_bytes(),
        "ball.csv",
        Vec::new(),
    );
    assert!(matches!(gpu, Err(EvalError::Mode { .. })), "{gpu:?}");
}
