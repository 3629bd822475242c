//! `torus-cull check --shape family`: every cull and the exact intersection of the torus
//! family (`torus_cull::family::Toroid`) against the oracle, member class by member class.
//!
//! **Members.** Elliptical (and circular) ring tori with ν = R/a ∈ {1.25, 4, 16} and
//! b/a ∈ {0.25, 0.5, 1, 2, 4}; horn and spindle tori with ν ∈ {1, 0.75, 0.5, 0.3, 0.1,
//! 0.01} (down to `MIN_FAMILY_NU`) and b/a ∈ {0.25, 1, 4}. a = 1; each member in a random pose (f64 centre and axis).
//!
//! **Rays** (f64, [`torus_cull::DRay`]; the culls see them rounded to f32 as always):
//! `--rays N` per member, cycling through the kinds of [`rays::RayKind`] (uniform,
//! grazing, axis/hole, spawned), seeded from `--seed` and the member's index.
//!
//! **Labels** from the family oracle ([`crate::family_label`], `oracle::family`), with
//! its margin `(E − 1)·min(a, b)`; ambiguous rows are counted apart. Spawned rays are
//! labelled by its on-surface rule.
//!
//! **Counts**, per member and per cull of [`CullKind::TIMED`] (a cull that does not
//! accept the member's shape is *declined* and keeps every ray):
//! - `false_rejects`: a hit of the oracle the cull rejects (must be 0);
//! - `rejection_rate`: rejected / rays;
//! - `capture`: the share of the oracle's misses with margin > 1.25·η, η = 2⁻¹²·(R +
//!   max(a, b)), that the cull rejects, over the literal rays (uniform, grazing,
//!   axis/hole: their lines behind the origin run away from the member, so the ray's
//!   margin is the line's); a spawned ray's line passes through its surface point, which
//!   no line cull can reject;
//!
//! and for the exact intersection (answers `intersect` and `intersect_all`, its first
//! crossing): `missed` (an oracle hit without a hit) and `invented` (an oracle miss with
//! one), on rows the oracle does not call ambiguous; `intersect`'s largest distance
//! between its `t` and the oracle's first crossing (`max_t_error_rel`) and
//! `intersect_all`'s first (`intersect_vs_all_rel`), × |d|/(R + max(a, b)).

pub mod rays;

use crate::check::record::{AnswerRecord, ClassRecord, CullRecord, KindRecord};
use crate::check::solid::count_culls;
use crate::check::{About, CheckShape, Job};
use crate::family_label;
use crate::oracle::OracleClass;
use glam::DVec3;
use rand::SeedableRng;
use rand_pcg::Pcg64;
use rays::RayKind;
use torus_cull::family::{Toroid, ToroidError};
use torus_cull::{CullKind, Named};

/// The seed `--seed` defaults to.
pub const SEED: u64 = 20261127;

/// The culls' margin η = `ETA_REL`·(R + max(a, b)); a miss counts for the capture when
/// its margin exceeds `CAPTURE_ETAS`·η.
pub const ETA_REL: f64 = 1.0 / 4096.0;

/// See [`ETA_REL`].
pub const CAPTURE_ETAS: f64 = 1.25;

/// The member classes: (ν, b/a), the ring tori first.
pub fn members() -> Vec<(f64, f64)> {
    let mut all = Vec::new();
    for nu in [1.25, 4.0, 16.0] {
        for aspect in [0.25, 0.5, 1.0, 2.0, 4.0] {
            all.push((nu, aspect));
        }
    }
    for nu in [1.0, 0.75, 0.5, 0.3, 0.1, 0.01] {
        for aspect in [0.25, 1.0, 4.0] {
            all.push((nu, aspect));
        }
    }
    all
}

/// The member's kind (`ring`, `horn`, `spindle`) by ν.
fn kind_name(nu: f64) -> &'static str {
    if nu > 1.0 {
        "ring"
    } else if nu == 1.0 {
        "horn"
    } else {
        "spindle"
    }
}

/// `ring nu=4 b/a=0.25`.
pub fn label((nu, aspect): (f64, f64)) -> String {
    format!("{} nu={nu} b/a={aspect}", kind_name(nu))
}

/// The torus family as a check's shape: its [`members`], f64 only.
pub struct FamilyShape;

impl CheckShape for FamilyShape {
    fn about(&self) -> About {
        About {
            name: "family",
            precision: "f64",
            oracle: "oracle::family (FamilyQuery; on-surface rule for spawned rays)",
            constants: vec![("eta_rel", ETA_REL), ("capture_etas", CAPTURE_ETAS)],
            chart: ("nu", "ν = R/a (log scale)", &["aspect"]),
            spec: String::new(),
        }
    }
    fn labels(&self) -> Vec<String> {
        members().into_iter().map(label).collect()
    }
    fn jobs(&self, _rays: usize) -> usize {
        1
    }
    fn check_job(&self, job: Job) -> Result<(ClassRecord, Vec<String>), String> {
        let m = members()[job.index];
        Ok((check_member(m, job.index, job.rays, job.seed)?, Vec::new()))
    }
}

/// The member (ν, b/a) with a = 1 in a random pose drawn from `rng`: its centre uniform
/// in the cube of half-side 2·(R + max(a, b)) about the origin, then its axis by `axis`
/// (the check's and `run`'s sweep's each draw it their own way: each keeps its stream).
///
/// # Errors
///
/// The library's refusal of the member.
pub fn posed_member(
    (nu, aspect): (f64, f64),
    rng: &mut Pcg64,
    axis: impl FnOnce(&mut Pcg64) -> DVec3,
) -> Result<Toroid, ToroidError> {
    let center = crate::random::cube_point(rng, 2.0) * (nu + aspect.max(1.0));
    Toroid::new_f64(center, axis(rng), nu, 1.0, aspect)
}

/// The check's member: [`posed_member`] with any axis of the unit ball longer than
/// 10⁻³ in square, as drawn (not made unit).
fn member(nu: f64, aspect: f64, rng: &mut Pcg64) -> Result<Toroid, ToroidError> {
    posed_member((nu, aspect), rng, |rng| {
        crate::random::ball_point(rng, 1e-3)
    })
}

/// Checks one member class with `rays` rays: its record, labelled as [`label`].
pub fn check_member(
    (nu, aspect): (f64, f64),
    index: usize,
    rays: usize,
    seed: u64,
) -> Result<ClassRecord, String> {
    let mut rng = Pcg64::seed_from_u64(seed ^ (index as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    let toroid =
        member(nu, aspect, &mut rng).map_err(|e| format!("member nu={nu} b/a={aspect}: {e}"))?;
    let size = rays::size(&toroid);
    let far = CAPTURE_ETAS * ETA_REL * size;
    let mut kinds = KindRecord::zeroed(RayKind::ALL.iter().map(|k| k.name()));
    let mut culls: Vec<CullRecord> = CullKind::TIMED
        .iter()
        .map(|c| CullRecord::new(c.name().into(), c.accepts(toroid.shape())))
        .collect();
    let mut first_hit = AnswerRecord::new("intersect", true, &["missed", "invented"]);
    let mut all_first = AnswerRecord::new("intersect_all", true, &["missed", "invented"]);
    first_hit.raise("max_t_error_rel", 0.0);
    first_hit.raise("intersect_vs_all_rel", 0.0);
    for i in 0..rays {
        let k = i % RayKind::ALL.len();
        let ray = rays::draw(&toroid, RayKind::ALL[k], &mut rng);
        let label = family_label::label(&toroid, &ray)
            .map_err(|e| format!("member nu={nu} b/a={aspect}, ray {i}: {e}"))?;
        kinds[k].count(label.class);
        // A spawned ray's line passes through its own surface point: no line cull can
        // reject it, so its misses are left out of the capture.
        let literal = RayKind::ALL[k] != RayKind::Spawned;
        let far_miss = literal && label.class == OracleClass::Miss && label.margin > far;
        let hit = label.class == OracleClass::Hit;
        count_culls(&toroid, &CullKind::TIMED, &mut culls, &ray, (hit, far_miss));
        if label.class == OracleClass::Ambiguous {
            continue;
        }
        let hit = toroid.intersect(&ray).map(|h| h.t);
        let all = toroid.intersect_all(&ray);
        let first = all.as_slice().first().map(|c| c.t);
        let oracle_hit = label.class == OracleClass::Hit;
        for (answer, t) in [(&mut first_hit, hit), (&mut all_first, first)] {
            let wrong = &mut answer.wrong;
            *wrong.entry("missed".into()).or_default() += u64::from(oracle_hit && t.is_none());
            *wrong.entry("invented".into()).or_default() += u64::from(!oracle_hit && t.is_some());
        }
        if let (Some(t), Some(f)) = (hit, first) {
            let gap = (t - f).abs() * ray.dir().length() / size;
            first_hit.raise("intersect_vs_all_rel", gap);
        }
        if let (true, Some(t), Some(reference)) =
            (oracle_hit, hit, family_label::first_crossing(&toroid, &ray))
        {
            let error = (t - reference).abs() * ray.dir().length() / size;
            first_hit.raise("max_t_error_rel", error);
        }
    }
    let words = [
        ("kind", format!("{:?}", toroid.kind()).to_lowercase()),
        ("cull_shape", format!("{:?}", toroid.shape())),
    ];
    Ok(ClassRecord {
        label: label((nu, aspect)),
        params: [("nu", nu), ("aspect", aspect)]
            .map(|(k, v)| (k.into(), v))
            .into(),
        words: words.map(|(k, v)| (k.into(), v)).into(),
        rays: rays as u64,
        kinds,
        culls,
        captures: Vec::new(),
        answers: vec![first_hit, all_first],
        ns_per_ray: None,
    })
}

/// A family member to the lab: its oracle ([`family_label::label`]), its size
/// R + max(a, b), and the culls whose table row names its shape.
impl crate::lab_shape::LabShape for Toroid {
    type Solid = Toroid;

    fn solid(&self) -> &Toroid {
        self
    }

    fn label(&self, ray: &torus_cull::DRay) -> Result<crate::oracle::OracleLabel, String> {
        family_label::label(self, ray)
    }

    fn size(&self) -> f64 {
        rays::size(self)
    }

    fn accepts<C: torus_cull::Cull + ?Sized>(&self, cull: &C) -> bool {
        cull.shapes().contains(&self.shape())
    }
}
