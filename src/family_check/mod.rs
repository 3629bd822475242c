//! `torus-cull family`: every cull and the exact intersection of the torus family
//! (`torus_cull::family::Toroid`) against the oracle, member class by member class.
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
//! and for the exact intersection: `missed` (an oracle hit without a hit) and `invented`
//! (an oracle miss with one), for `Toroid::intersect` and for `Toroid::intersect_all`'s
//! first crossing, on rows the oracle does not call ambiguous; and the largest distance
//! between the hit's `t` and the oracle's first crossing (and `intersect_all`'s first),
//! × |d|/(R + max(a, b)).

pub mod rays;

pub use crate::check_counts::KindRecord;
use crate::check_counts::{CullCounts, cull_columns, rate_and_capture};
use crate::family_label;
use crate::oracle::OracleClass;
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use rays::RayKind;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use torus_cull::family::{Toroid, ToroidError};
use torus_cull::{CullKind, Named};

/// The results file's schema.
pub const SCHEMA_VERSION: u32 = 1;

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

/// One cull on one member.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CullRecord {
    /// The cull's stable name.
    pub cull: String,
    /// Whether the cull accepts the member's shape (false: declined, keeps every ray).
    pub accepts: bool,
    /// Its counts (in the file, fields of the record).
    #[serde(flatten)]
    pub counts: CullCounts,
    /// rejected / rays.
    pub rejection_rate: f64,
    /// far_misses_rejected / far_misses (null without far misses).
    pub capture: Option<f64>,
}

/// The exact intersection on one member, against the oracle.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ExactRecord {
    /// Non-ambiguous oracle hits where `intersect` found none.
    pub intersect_missed: u64,
    /// Non-ambiguous oracle misses where `intersect` found a hit.
    pub intersect_invented: u64,
    /// As `intersect_missed`, for `intersect_all`'s first crossing.
    pub all_missed: u64,
    /// As `intersect_invented`, for `intersect_all`'s first crossing.
    pub all_invented: u64,
    /// The largest |t − t_all|·|d|/(R + max(a, b)) between `intersect`'s `t` and
    /// `intersect_all`'s first crossing, over rays both hit.
    pub intersect_vs_all_rel: f64,
    /// The largest |t − t_oracle|·|d|/(R + max(a, b)) over hits both found.
    pub max_t_error_rel: f64,
}

/// One member class.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MemberRecord {
    /// `ring`, `horn` or `spindle`.
    pub kind: String,
    /// The cull table's shape: `Ring`, `Elliptic` or `Spindle`.
    pub shape: String,
    /// ν = R/a.
    pub nu: f64,
    /// b/a.
    pub aspect: f64,
    /// Rays drawn.
    pub rays: u64,
    /// Per ray kind.
    pub kinds: Vec<KindRecord>,
    /// Per cull, in [`CullKind::TIMED`] order.
    pub culls: Vec<CullRecord>,
    /// The exact intersection.
    pub exact: ExactRecord,
}

impl MemberRecord {
    /// `ring ν=4 b/a=0.25`.
    pub fn label(&self) -> String {
        format!("{} nu={} b/a={}", self.kind, self.nu, self.aspect)
    }

    /// False rejects over every cull.
    pub fn false_rejects(&self) -> u64 {
        self.culls.iter().map(|c| c.counts.false_rejects).sum()
    }

    /// Missed and invented hits of the exact intersection (both forms).
    pub fn exact_wrong(&self) -> u64 {
        let e = &self.exact;
        e.intersect_missed + e.intersect_invented + e.all_missed + e.all_invented
    }
}

/// The results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FamilyFile {
    /// Always [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// Provenance, as in the other results files (`meta.tool` = `family`).
    pub meta: crate::results::Meta,
    /// Rays per member.
    pub rays_per_member: u64,
    /// The seed.
    pub seed: u64,
    /// Which oracle labelled the rays.
    pub oracle: String,
    /// η / (R + max(a, b)).
    pub eta_rel: f64,
    /// The capture's threshold in η.
    pub capture_etas: f64,
    /// One record per member class, in [`members`] order.
    pub members: Vec<MemberRecord>,
}

impl FamilyFile {
    /// The file for `members`, drawn with `rays` per member from `seed`.
    pub fn new(members: Vec<MemberRecord>, rays: usize, seed: u64) -> FamilyFile {
        let mut spec = format!("family v{SCHEMA_VERSION} rays {rays} seed {seed}");
        for m in &members {
            let _ = write!(spec, " {}@{}x{}", m.kind, m.nu, m.aspect);
        }
        let workload = crate::workload::spec::Workload::drawn("family", seed, rays, &spec);
        let meta = crate::results::Results::new(&workload, "family").meta;
        FamilyFile {
            schema_version: SCHEMA_VERSION,
            meta,
            rays_per_member: rays as u64,
            seed,
            oracle: "oracle::family (FamilyQuery; on-surface rule for spawned rays)".into(),
            eta_rel: ETA_REL,
            capture_etas: CAPTURE_ETAS,
            members,
        }
    }
}

/// The member (ν, b/a) with a = 1 in a random pose drawn from `rng`.
fn member(nu: f64, aspect: f64, rng: &mut Pcg64) -> Result<Toroid, ToroidError> {
    let size = nu + aspect.max(1.0);
    let center = DVec3::new(
        rng.random_range(-2.0..2.0),
        rng.random_range(-2.0..2.0),
        rng.random_range(-2.0..2.0),
    ) * size;
    let axis = loop {
        let v = DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        if v.length_squared() > 1e-3 && v.length_squared() <= 1.0 {
            break v;
        }
    };
    Toroid::new_f64(center, axis, nu, 1.0, aspect)
}

/// Checks one member class with `rays` rays.
pub fn check_member(
    (nu, aspect): (f64, f64),
    index: usize,
    rays: usize,
    seed: u64,
) -> Result<MemberRecord, String> {
    let mut rng = Pcg64::seed_from_u64(seed ^ (index as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    let toroid =
        member(nu, aspect, &mut rng).map_err(|e| format!("member nu={nu} b/a={aspect}: {e}"))?;
    let size = rays::size(&toroid);
    let far = CAPTURE_ETAS * ETA_REL * size;
    let mut kinds = KindRecord::zeroed(RayKind::ALL.iter().map(|k| k.name()));
    let mut culls: Vec<CullRecord> = CullKind::TIMED
        .iter()
        .map(|c| CullRecord {
            cull: c.name().into(),
            accepts: c.accepts(toroid.shape()),
            counts: CullCounts::default(),
            rejection_rate: 0.0,
            capture: None,
        })
        .collect();
    let mut exact = ExactRecord::default();
    for i in 0..rays {
        let k = i % RayKind::ALL.len();
        let ray = rays::draw(&toroid, RayKind::ALL[k], &mut rng);
        let label = family_label::label(&toroid, &ray)
            .map_err(|e| format!("member nu={nu} b/a={aspect}, ray {i}: {e}"))?;
        kinds[k].count(label.class);
        for (cull, record) in CullKind::TIMED.iter().zip(&mut culls) {
            // A spawned ray's line passes through its own surface point: no line cull can
            // reject it, so its misses are left out of the capture.
            let literal = RayKind::ALL[k] != RayKind::Spawned;
            let far_miss = literal && label.class == OracleClass::Miss && label.margin > far;
            let hit = label.class == OracleClass::Hit;
            record
                .counts
                .count(toroid.kept_by(cull, &ray), hit, far_miss);
        }
        if label.class == OracleClass::Ambiguous {
            continue;
        }
        let hit = toroid.intersect(&ray).map(|h| h.t);
        let all = toroid.intersect_all(&ray);
        let first = all.as_slice().first().map(|c| c.t);
        let oracle_hit = label.class == OracleClass::Hit;
        exact.intersect_missed += u64::from(oracle_hit && hit.is_none());
        exact.intersect_invented += u64::from(!oracle_hit && hit.is_some());
        exact.all_missed += u64::from(oracle_hit && first.is_none());
        exact.all_invented += u64::from(!oracle_hit && first.is_some());
        if let (Some(t), Some(f)) = (hit, first) {
            let gap = (t - f).abs() * ray.dir().length() / size;
            exact.intersect_vs_all_rel = exact.intersect_vs_all_rel.max(gap);
        }
        if let (true, Some(t), Some(reference)) =
            (oracle_hit, hit, family_label::first_crossing(&toroid, &ray))
        {
            let error = (t - reference).abs() * ray.dir().length() / size;
            exact.max_t_error_rel = exact.max_t_error_rel.max(error);
        }
    }
    for record in &mut culls {
        record.rejection_rate = record.counts.rejection_rate(rays);
        record.capture = record.counts.capture();
    }
    Ok(MemberRecord {
        kind: format!("{:?}", toroid.kind()).to_lowercase(),
        shape: format!("{:?}", toroid.shape()),
        nu,
        aspect,
        rays: rays as u64,
        kinds,
        culls,
        exact,
    })
}

/// Every member class, `rays` rays each; `progress(done, all)` after each.
pub fn check(
    rays: usize,
    seed: u64,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<MemberRecord>, String> {
    let all = members();
    let mut records = Vec::with_capacity(all.len());
    for (index, m) in all.iter().enumerate() {
        records.push(check_member(*m, index, rays, seed)?);
        progress(index + 1, all.len());
    }
    Ok(records)
}

/// The short table: one line per member (rays, ambiguous, false rejects, exact wrong),
/// then per cull the rejection rate and capture (accepted shapes), `—` where declined.
pub fn table(records: &[MemberRecord]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<24} {:>6} {:>5} {:>6} {:>6} {:>6} {:>6} {:>9}",
        "member", "rays", "ambig", "falseR", "i.miss", "i.inv", "all.w", "t err"
    );
    for r in records {
        let e = &r.exact;
        let ambiguous: u64 = r.kinds.iter().map(|k| k.ambiguous).sum();
        let _ = writeln!(
            out,
            "{:<24} {:>6} {:>5} {:>6} {:>6} {:>6} {:>6} {:>9.1e}",
            r.label(),
            r.rays,
            ambiguous,
            r.false_rejects(),
            e.intersect_missed,
            e.intersect_invented,
            e.all_missed + e.all_invented,
            e.max_t_error_rel
        );
    }
    let _ = writeln!(
        out,
        "\nrejection rate / capture of misses > {CAPTURE_ETAS}·η, per cull ('-': declined)"
    );
    let rows = records.iter().map(|r| {
        let cell = |c: &CullRecord| match c.accepts {
            true => rate_and_capture(c.rejection_rate, c.capture, "%"),
            false => "-".into(),
        };
        (r.label(), r.culls.iter().map(cell).collect())
    });
    cull_columns(&mut out, ("member", 24), 13, rows);
    out
}
