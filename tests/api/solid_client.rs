//! A client of the library's shape interface alone ([`Solid`] and [`RayCast`]): a generic
//! fn, the same fn through `dyn Solid`, and a scene of `Box<dyn RayCast>` holding a ring
//! torus, family members and pipe bends. Each answer (nearest hit and shadow of f32 and
//! f64 rays, every crossing iterated with `for`, the spans, the certified f32 answer, a
//! spawned ray and its hit, inside, signed distance, closest point) must equal the shape's
//! own method or free function, written out field by field, bit for bit (`{:?}` of an
//! f32/f64 tells every bit but a NaN's payload, and no answer here may be a NaN), on a
//! few hundred random and structured rays and points per shape.

use glam::{DVec3, Vec3};
use std::f64::consts::{PI, TAU};
use std::fmt::Debug;
use torus_cull::bend::PipeBend;
use torus_cull::family::{FamilyPointError, Toroid};
use torus_cull::{
    CullKind, DRay, Hit, NoFace, Passage, PointQueryError, Ray, RayCast, Solid, Torus, intersect,
    intersect_all, intersect_f32, occluded,
};

/// A small deterministic generator (SplitMix64): the rays need no statistics, only
/// variety and reproducibility.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `[lo, hi)`.
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn unit(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            if (0.01..=1.0).contains(&v.length_squared()) {
                return v.normalize();
            }
        }
    }
}

/// The rays: random lines near a solid of size ~5 (half aimed at it) (some with a finite `t_max` or a
/// positive `t_min`), and structured ones (down through the tube's top, through the
/// centre along the axis, in the equatorial plane, grazing the outer equator).
fn rays(seed: u64, center: DVec3) -> Vec<DRay> {
    let mut rng = Mix(seed);
    let mut out = Vec::new();
    for i in 0..240 {
        // From anywhere within 12, half of them aimed at a point within 5 of the centre.
        let o = center + rng.unit() * rng.range(0.0, 12.0);
        let d = if i % 2 == 0 {
            (center + rng.unit() * rng.range(0.0, 5.0) - o).normalize_or(DVec3::Y)
        } else {
            rng.unit()
        } * rng.range(0.5, 2.0);
        let ray = match i % 4 {
            0 => DRay::with_range(o, d, 0.0, rng.range(1.0, 10.0)),
            1 => DRay::with_range(o, d, rng.range(0.0, 3.0), f64::INFINITY),
            _ => DRay::new(o, d),
        };
        out.push(ray.unwrap());
    }
    for k in 0..16 {
        let a = TAU * f64::from(k) / 16.0;
        let radial = DVec3::new(a.cos(), 0.0, -a.sin());
        for (o, d) in [
            (radial * 4.0 + DVec3::Y * 10.0, DVec3::NEG_Y),
            (radial * 12.0, -radial),
            (radial * 5.0 + DVec3::Y * 3.0, DVec3::NEG_Y),
            (DVec3::Y * 9.0, DVec3::NEG_Y),
            (
                radial * 4.5 + radial.cross(DVec3::Y) * 9.0,
                -radial.cross(DVec3::Y),
            ),
        ] {
            out.push(DRay::new(center + o, d).unwrap());
        }
    }
    out
}

/// The f32 ray of an f64 one (the same range), for the f32 verbs.
fn f32_ray(ray: &DRay) -> Ray {
    Ray::with_range(
        ray.origin().as_vec3(),
        ray.dir().as_vec3(),
        ray.t_min() as f32,
        ray.t_max() as f32,
    )
    .unwrap()
}

/// The points: random in a box around the solid, the centre, points on the axis and on
/// the core circle.
fn points(seed: u64, center: DVec3) -> Vec<DVec3> {
    let mut rng = Mix(seed ^ 0x5EED);
    let mut out: Vec<DVec3> = (0..200)
        .map(|_| center + rng.unit() * rng.range(0.0, 8.0))
        .collect();
    for k in 0..8 {
        let a = TAU * f64::from(k) / 8.0;
        out.push(center + DVec3::new(4.0 * a.cos(), 0.0, -4.0 * a.sin()));
        out.push(center + DVec3::Y * f64::from(k));
    }
    out
}

/// Everything the client reads off one ray, as text: the interface's answers field by
/// field. The shape's own answers are written in the same words (`Own`).
fn client<S: Solid + ?Sized>(shape: &S, ray64: &DRay) -> Vec<String> {
    let ray = f32_ray(ray64);
    let mut out = Vec::new();
    let hit = shape.hit(&ray);
    out.push(match hit {
        Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, h.face),
        None => "miss".into(),
    });
    out.push(match shape.hit_f64(ray64) {
        Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, h.face),
        None => "miss".into(),
    });
    out.push(format!(
        "{} {}",
        shape.occluded(&ray),
        shape.occluded_f64(ray64)
    ));
    let all = shape.crossings(&ray);
    out.push(format!("inside {}", all.starts_inside()));
    for c in &all {
        out.push(crossing_row(c.t, c.normal, c.passage, c.face));
    }
    for s in &all.spans() {
        let ends = (s.enter.map(|c| c.t), s.exit.map(|c| c.t));
        out.push(format!("span {:?} {:?} {ends:?}", s.t_enter, s.t_exit));
    }
    let all64 = shape.crossings_f64(ray64);
    out.push(format!("inside {}", all64.starts_inside()));
    for c in &all64 {
        out.push(crossing_row(c.t, c.normal, c.passage, c.face));
    }
    let f32_answer = shape.hit_f32_certified(&ray);
    out.push(match f32_answer.hit {
        Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, h.face),
        None => "miss".into(),
    });
    out.push(format!("escalated {}", f32_answer.escalated));
    // Spawn at the first crossing, straight on; and the spawned ray's own nearest hit.
    if let Some(c) = all64.iter().next() {
        let on = shape.spawn_f64(ray64, c.t, ray64.dir()).unwrap();
        out.push(format!("{:?} {:?}", on.origin(), on.starts_on_surface()));
        out.push(match shape.hit_f64(&on) {
            Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, h.face),
            None => "miss".into(),
        });
    }
    if let Some(h) = hit {
        let on = shape.spawn(&ray, h.t, ray.dir()).unwrap();
        out.push(format!("{:?} {:?}", on.origin(), on.starts_on_surface()));
    }
    out
}

/// The point verbs, as text.
fn client_point<S: Solid + ?Sized>(shape: &S, p: DVec3) -> Vec<String> {
    vec![
        format!("{:?}", shape.contains(p).map_err(err_word)),
        format!("{:?}", shape.signed_distance(p).map_err(err_word)),
        match shape.project_point(p) {
            Ok(q) => projection_row(q.point, q.normal, q.signed_distance, q.face),
            Err(e) => err_word(e).into(),
        },
    ]
}

fn err_word(e: PointQueryError) -> &'static str {
    match e {
        PointQueryError::NonFinite(_) => "non-finite",
        PointQueryError::Unsupported(_) => "unsupported",
        _ => "other",
    }
}

fn hit_row<P: Debug, T: Debug, F: Debug>(t: T, n: P, p: P, front: bool, face: F) -> String {
    format!("hit {t:?} {n:?} {p:?} {front} {face:?}")
}

fn crossing_row<P: Debug, T: Debug, F: Debug>(t: T, n: P, passage: Passage, face: F) -> String {
    format!("crossing {t:?} {n:?} {passage:?} {face:?}")
}

fn projection_row<F: Debug>(p: DVec3, n: DVec3, d: f64, face: F) -> String {
    format!("projection {p:?} {n:?} {d:?} {face:?}")
}

/// Runs the client on a shape's rays and points against its own answers (`own` and
/// `own_point` write them in the client's words), through `S` and through `dyn Solid`.
fn check<S: Solid>(
    shape: &S,
    dyn_shape: &dyn Solid<Face = S::Face>,
    seed: u64,
    center: DVec3,
    own: impl Fn(&DRay) -> Vec<String>,
    own_point: impl Fn(DVec3) -> Vec<String>,
) {
    let rays = rays(seed, center);
    let mut crossed = 0;
    for ray in &rays {
        let want = own(ray);
        assert_eq!(client(shape, ray), want, "{ray:?}");
        assert_eq!(client(dyn_shape, ray), want, "dyn {ray:?}");
        crossed += usize::from(want.iter().any(|row| row.starts_with("crossing")));
    }
    // The rays are worth their name: a share meet the solid (a cut bend's segment is
    // small beside the sphere the rays start in: 15 % of them cross it).
    assert!(
        crossed * 10 > rays.len(),
        "{crossed} of {} cross",
        rays.len()
    );
    for p in points(seed, center).into_iter().chain([DVec3::NAN]) {
        assert_eq!(client_point(shape, p), own_point(p), "{p:?}");
        assert_eq!(client_point(dyn_shape, p), own_point(p), "dyn {p:?}");
    }
}

/// What every shape's own `spawn` and hits write, as the client writes them.
macro_rules! own_rows {
    ($ray64:ident, $hit:expr, $hit64:expr, $occl:expr, $all:expr, $spans:expr, $all64:expr,
     $f32:expr, $spawn64:expr, $spawn:expr, $face:expr) => {{
        let ray = f32_ray($ray64);
        let mut out = Vec::new();
        let face = $face;
        let hit = $hit(&ray);
        out.push(match hit {
            Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, face(&h)),
            None => "miss".into(),
        });
        out.push(match $hit64($ray64) {
            Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, face(&h)),
            None => "miss".into(),
        });
        out.push($occl(&ray, $ray64));
        let all = $all(&ray);
        out.push(format!("inside {}", all.starts_inside()));
        out.extend(
            all.iter()
                .map(|c| crossing_row(c.t, c.normal, c.passage, face(c))),
        );
        out.extend($spans(&all));
        let all64 = $all64($ray64);
        out.push(format!("inside {}", all64.starts_inside()));
        out.extend(
            all64
                .iter()
                .map(|c| crossing_row(c.t, c.normal, c.passage, face(c))),
        );
        let (f32_hit, escalated) = $f32(&ray);
        out.push(match f32_hit {
            Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, face(&h)),
            None => "miss".into(),
        });
        out.push(format!("escalated {escalated}"));
        if let Some(c) = all64.iter().next() {
            let on = $spawn64($ray64, c.t, $ray64.dir());
            out.push(format!("{:?} {:?}", on.origin(), on.starts_on_surface()));
            out.push(match $hit64(&on) {
                Some(h) => hit_row(h.t, h.normal, h.point, h.front_face, face(&h)),
                None => "miss".into(),
            });
        }
        if let Some(h) = hit {
            let on = $spawn(&ray, h.t, ray.dir());
            out.push(format!("{:?} {:?}", on.origin(), on.starts_on_surface()));
        }
        out
    }};
}

/// A span as the client writes it.
macro_rules! span_rows {
    ($spans:expr) => {
        $spans
            .iter()
            .map(|s| {
                let ends = (s.enter.map(|c| c.t), s.exit.map(|c| c.t));
                format!("span {:?} {:?} {ends:?}", s.t_enter, s.t_exit)
            })
            .collect::<Vec<_>>()
    };
}

fn family_err(e: FamilyPointError) -> &'static str {
    match e {
        FamilyPointError::NonFinite(_) => "non-finite",
        FamilyPointError::Unsupported => "unsupported",
        _ => "other",
    }
}

fn tori() -> Vec<Torus> {
    vec![
        Torus::canonical(4.0, 1.0).unwrap(),
        Torus::new(
            Vec3::new(1.0, -2.0, 0.5),
            Vec3::new(0.3, 1.0, -0.2),
            4.0,
            1.5,
        )
        .unwrap(),
    ]
}

#[test]
fn the_ring_torus_answers_through_the_interface_as_its_own_functions() {
    for (i, torus) in tori().iter().enumerate() {
        let own = |ray64: &DRay| {
            own_rows!(
                ray64,
                |r: &Ray| intersect(torus, r),
                |r: &DRay| intersect(torus, r),
                |r: &Ray, r64: &DRay| format!("{} {}", occluded(torus, r), occluded(torus, r64)),
                |r: &Ray| intersect_all(torus, r),
                |all: &torus_cull::Crossings| span_rows!(all.spans()),
                |r: &DRay| intersect_all(torus, r),
                |r: &Ray| {
                    let a = intersect_f32(torus, r);
                    (a.hit, a.escalated)
                },
                |r: &DRay, t, d| torus.spawn(r, t, d).unwrap(),
                |r: &Ray, t, d| torus.spawn(r, t, d).unwrap(),
                |_: &dyn Debug| NoFace
            )
        };
        let own_point = |p: DVec3| {
            vec![
                format!("{:?}", torus.contains(p).map_err(|_| "non-finite")),
                format!("{:?}", torus.signed_distance(p).map_err(|_| "non-finite")),
                match torus.project_point(p) {
                    Ok(q) => projection_row(q.point, q.normal, q.signed_distance, NoFace),
                    Err(_) => "non-finite".into(),
                },
            ]
        };
        let center = torus.center_f64();
        check(torus, torus, 11 + i as u64, center, own, own_point);
    }
}

fn toroids() -> Vec<Toroid> {
    vec![
        Toroid::canonical(4.0, 1.0, 1.0).unwrap(), // the circular ring
        Toroid::canonical(4.0, 1.0, 0.5).unwrap(), // elliptical ring
        Toroid::new_f64(
            DVec3::new(0.5, 1.0, 0.0),
            DVec3::new(1.0, 2.0, 0.5),
            4.0,
            1.5,
            2.0,
        )
        .unwrap(),
        Toroid::canonical(1.0, 1.0, 1.0).unwrap(), // circular horn
        Toroid::canonical(0.8, 1.0, 1.0).unwrap(), // circular spindle
        Toroid::canonical(1.0, 1.0, 1.5).unwrap(), // elliptical horn: no closest point
    ]
}

#[test]
fn the_family_answers_through_the_interface_as_its_own_methods() {
    for (i, toroid) in toroids().iter().enumerate() {
        let own = |ray64: &DRay| {
            own_rows!(
                ray64,
                |r: &Ray| toroid.intersect(r),
                |r: &DRay| toroid.intersect(r),
                |r: &Ray, r64: &DRay| format!("{} {}", toroid.occluded(r), toroid.occluded(r64)),
                |r: &Ray| toroid.intersect_all(r),
                |all: &torus_cull::Crossings| span_rows!(all.spans()),
                |r: &DRay| toroid.intersect_all(r),
                |r: &Ray| {
                    let a = toroid.intersect_f32(r);
                    (a.hit, a.escalated)
                },
                |r: &DRay, t, d| toroid.spawn(r, t, d).unwrap(),
                |r: &Ray, t, d| toroid.spawn(r, t, d).unwrap(),
                |_: &dyn Debug| NoFace
            )
        };
        let own_point = |p: DVec3| {
            vec![
                format!("{:?}", toroid.contains(p).map_err(|_| "non-finite")),
                format!("{:?}", toroid.signed_distance(p).map_err(family_err)),
                match toroid.project_point(p) {
                    Ok(q) => projection_row(q.point, q.normal, q.signed_distance, NoFace),
                    Err(e) => family_err(e).into(),
                },
            ]
        };
        let center = toroid.center_f64();
        check(toroid, toroid, 101 + i as u64, center, own, own_point);
    }
}

fn bends() -> Vec<PipeBend> {
    vec![
        PipeBend::canonical(4.0, 0.0, 1.0, 0.0, TAU).unwrap(), // the whole ring
        PipeBend::canonical(4.0, 0.5, 1.0, 0.3, 2.0).unwrap(), // a bore and a segment
        PipeBend::canonical(4.0, 0.0, 1.5, -PI / 4.0, PI).unwrap(), // a segment, no bore
        PipeBend::new_f64(
            DVec3::new(-1.0, 0.5, 2.0),
            DVec3::new(0.2, 1.0, 0.1),
            DVec3::X,
            4.0,
            0.8,
            1.2,
            1.0,
            4.0,
        )
        .unwrap(),
    ]
}

#[test]
fn the_pipe_bend_answers_through_the_interface_as_its_own_methods() {
    for (i, bend) in bends().iter().enumerate() {
        let own = |ray64: &DRay| {
            own_rows!(
                ray64,
                |r: &Ray| bend.intersect(r),
                |r: &DRay| bend.intersect(r),
                |r: &Ray, r64: &DRay| format!("{} {}", bend.occluded(r), bend.occluded(r64)),
                |r: &Ray| bend.intersect_all(r),
                |all: &torus_cull::bend::BendCrossings| span_rows!(all.spans()),
                |r: &DRay| bend.intersect_all(r),
                |r: &Ray| {
                    let a = bend.intersect_f32(r);
                    (a.hit, a.escalated)
                },
                |r: &DRay, t, d| bend.spawn(r, t, d).unwrap(),
                |r: &Ray, t, d| bend.spawn(r, t, d).unwrap(),
                |h: &dyn HasFace| h.face()
            )
        };
        let own_point = |p: DVec3| {
            vec![
                // The bend's own inside test answers `false` for a non-finite point; the
                // interface refuses it, as the other shapes do.
                if p.is_finite() {
                    format!("{:?}", Ok::<bool, &str>(bend.contains(p)))
                } else {
                    format!("{:?}", Err::<bool, &str>("non-finite"))
                },
                format!("{:?}", bend.signed_distance(p).map_err(|_| "non-finite")),
                match bend.project_point(p) {
                    Ok(q) => projection_row(q.point, q.normal, q.signed_distance, q.face),
                    Err(_) => "non-finite".into(),
                },
            ]
        };
        let center = bend.outer().center_f64();
        check(bend, bend, 1001 + i as u64, center, own, own_point);
    }
}

/// A bend's hit or crossing: its face, for the own-answer rows.
trait HasFace {
    fn face(&self) -> torus_cull::bend::BendFace;
}

impl<P: torus_cull::Precision> HasFace for torus_cull::bend::BendHit<P> {
    fn face(&self) -> torus_cull::bend::BendFace {
        self.face
    }
}

impl<P: torus_cull::Precision> HasFace for torus_cull::bend::BendCrossing<P> {
    fn face(&self) -> torus_cull::bend::BendFace {
        self.face
    }
}

fn hit_words<P: Debug, T: Debug>(hit: Option<(T, P, P, bool)>) -> String {
    match hit {
        Some((t, n, p, front)) => format!("{t:?} {n:?} {p:?} {front}"),
        None => "miss".into(),
    }
}

/// A scene of `Box<dyn RayCast>` holds a torus, a family member and a bend, bare and
/// behind a cull: each answers as its own `intersect` (the bend's face dropped) and
/// `occluded`, for f32 and f64 rays.
#[test]
fn a_scene_of_dyn_ray_cast_holds_every_shape() {
    let torus = Torus::canonical(4.0, 1.0).unwrap();
    let toroid = Toroid::canonical(4.0, 1.0, 0.5).unwrap();
    let bend = PipeBend::canonical(4.0, 0.5, 1.0, 0.3, 2.0).unwrap();
    let scene: Vec<Box<dyn RayCast + '_>> = vec![
        Box::new(torus),
        Box::new(toroid),
        Box::new(bend),
        Box::new(torus.with_cull(CullKind::Skala)),
        Box::new(toroid.with_cull(CullKind::Skala)),
        Box::new(bend.with_cull(bend.wedge_cull(CullKind::Skala))),
    ];
    let scene64: Vec<Box<dyn RayCast<DRay> + '_>> = vec![
        Box::new(torus),
        Box::new(toroid),
        Box::new(bend),
        Box::new(torus.with_cull(CullKind::Discriminant)),
        Box::new(toroid.with_cull(CullKind::Discriminant)),
        Box::new(bend.with_cull(CullKind::Discriminant)),
    ];
    let words = |h: Option<Hit>| hit_words(h.map(|h| (h.t, h.normal, h.point, h.front_face)));
    let words64 =
        |h: Option<torus_cull::DHit>| hit_words(h.map(|h| (h.t, h.normal, h.point, h.front_face)));
    let mut hits = 0;
    for ray64 in rays(7, DVec3::ZERO) {
        let ray = f32_ray(&ray64);
        let own = [
            (words(intersect(&torus, &ray)), occluded(&torus, &ray)),
            (words(toroid.intersect(&ray)), toroid.occluded(&ray)),
            (
                hit_words(
                    bend.intersect(&ray)
                        .map(|h| (h.t, h.normal, h.point, h.front_face)),
                ),
                bend.occluded(&ray),
            ),
        ];
        let own64 = [
            (words64(intersect(&torus, &ray64)), occluded(&torus, &ray64)),
            (words64(toroid.intersect(&ray64)), toroid.occluded(&ray64)),
            (
                hit_words(
                    bend.intersect(&ray64)
                        .map(|h| (h.t, h.normal, h.point, h.front_face)),
                ),
                bend.occluded(&ray64),
            ),
        ];
        for (i, object) in scene.iter().enumerate() {
            let (want, blocked) = &own[i % 3];
            let got = object.cast_ray_and_get_normal(&ray);
            assert_eq!(&words(got), want, "{i} {ray:?}");
            assert_eq!(object.cast_ray(&ray), got.map(|h| h.t), "{i} {ray:?}");
            assert_eq!(object.intersects_ray(&ray), *blocked, "{i} {ray:?}");
            hits += usize::from(got.is_some());
        }
        for (i, object) in scene64.iter().enumerate() {
            let (want, blocked) = &own64[i % 3];
            assert_eq!(
                &words64(object.cast_ray_and_get_normal(&ray64)),
                want,
                "{i}"
            );
            assert_eq!(object.intersects_ray(&ray64), *blocked, "{i} {ray64:?}");
        }
    }
    assert!(hits > 200, "{hits} hits");
}

/// The cull verb ([`Solid::kept_by`]) answers as each shape's own cull step, for every
/// timed cull, f32 and f64 rays (the torus's: the line in its frame against its bounds;
/// the toroid's and the bend's `kept_by`, the bend's also behind its wedge); it rejects
/// some rays, and never one the shape's own `intersect` hits.
#[test]
fn the_cull_verb_answers_as_each_shapes_own_cull_step() {
    /// Counts `verb` against `own` on every ray, f64 and f32; the rejected count.
    fn agree(
        rays: &[DRay],
        verb: impl Fn(&DRay, &Ray) -> (bool, bool),
        own: impl Fn(&DRay, &Ray) -> (bool, bool),
        hit: impl Fn(&DRay) -> bool,
    ) -> usize {
        let mut rejected = 0;
        for r64 in rays {
            let r = f32_ray(r64);
            let got = verb(r64, &r);
            assert_eq!(got, own(r64, &r), "{r64:?}");
            rejected += usize::from(!got.0);
            assert!(got.0 || !hit(r64), "a hit rejected: {r64:?}");
        }
        rejected
    }
    let mut rejected = 0;
    for cull in CullKind::TIMED {
        for (i, torus) in tori().iter().enumerate() {
            let line = |r: &Ray| {
                let l = torus.line_to_local(r);
                cull.keeps(torus.bounds(), l.origin, l.dir)
            };
            let line64 = |r: &DRay| {
                let l = torus.line_to_local(r);
                cull.keeps(torus.bounds(), l.origin, l.dir)
            };
            rejected += agree(
                &rays(11 + i as u64, torus.center_f64()),
                |r64, r| (torus.kept_by(&cull, r64), Solid::kept_by(torus, &cull, r)),
                |r64, r| (line64(r64), line(r)),
                |r64| intersect(torus, r64).is_some(),
            );
        }
        for (i, toroid) in toroids().iter().enumerate() {
            rejected += agree(
                &rays(101 + i as u64, toroid.center_f64()),
                |r64, r| {
                    (
                        Solid::kept_by(toroid, &cull, r64),
                        Solid::kept_by(toroid, &cull, r),
                    )
                },
                |r64, r| (toroid.kept_by(&cull, r64), toroid.kept_by(&cull, r)),
                |r64| toroid.intersect(r64).is_some(),
            );
        }
        for (i, bend) in bends().iter().enumerate() {
            let wedged = bend.wedge_cull(cull);
            for c in [&cull as &dyn torus_cull::Cull, &wedged] {
                rejected += agree(
                    &rays(1001 + i as u64, bend.outer().center_f64()),
                    |r64, r| (Solid::kept_by(bend, c, r64), Solid::kept_by(bend, c, r)),
                    |r64, r| (bend.kept_by(c, r64), bend.kept_by(c, r)),
                    |r64| bend.intersect(r64).is_some(),
                );
            }
        }
    }
    assert!(rejected > 0, "no cull rejected a ray");
}
