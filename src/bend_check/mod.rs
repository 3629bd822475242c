//! `torus-cull bend`: every cull, alone and behind the wedge, and the exact intersection
//! of the pipe bend (`torus_cull::bend::PipeBend`) against the independent bend oracle
//! (`oracle::bend`), class by class: the run-scale check of issue 39.
//!
//! **Classes.** Δφ ∈ {2π, π, π/2, π/6} × r_min/r_max ∈ {0, 0.5, 0.9} at each ν = R/r_max
//! asked (`--nu`, default 4). Each class draws its rays in poses of [`POSE_RAYS`] rays: a
//! random pose (centre, axis, φ = 0, φ₀) and r_max ∈ {10⁻³, 1, 10³} in turn.
//!
//! **Rays** (f64; the culls see them rounded to f32 as always): `--rays N` per class,
//! cycling through [`rays::RayKind`] (random, cut-away arc, pipe axis through the caps and
//! the hollow core, hole, caps' edges, tangent to the bore, spawned from a face), seeded
//! from `--seed`, the class and the pose. Literal rays are labelled by
//! `BendQuery::classify`, spawned ones by its on-surface rule.
//!
//! **Counts**, per class and per cull of [`CullKind::TIMED`] applied to the outer torus,
//! alone and behind the wedge (`PipeBend::wedge_cull`; `none` + wedge is the wedge alone):
//! `false_rejects` (an oracle hit rejected: must be 0), `rejection_rate`, and `capture`,
//! the share rejected of the literal rays' oracle misses with margin > 1.25·η, η = 2⁻¹²·S
//! (S = R + r_max; a spawned ray's line passes through its own face point). The **cut-away
//! misses**: literal rays the oracle labels a miss that hit the whole outer torus and miss
//! its segment (no bore), and how many the wedge alone rejects. The **exact
//! intersection** ([`exact::compare`], [`exact::compare_spawned`]): missed, invented,
//! wrong-face and wrong-value answers of `intersect` and of `intersect_all`, and the
//! largest t error of `intersect` × |d|/S.

pub mod exact;
pub mod rays;
mod table;

use crate::check_counts::CullCounts;
pub use crate::check_counts::KindRecord;
use crate::oracle::{OracleClass, OracleLabel};
use exact::Tally;
use rays::{RayKind, Spec};
use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::fmt::Write as _;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use torus_cull::{CullKind, DRay, Named, NoCull};

pub use table::table;

/// The results file's schema.
pub const SCHEMA_VERSION: u32 = 1;

/// The culls' margin η = `ETA_REL`·(R + r_max); a miss counts for the capture when its
/// margin exceeds `CAPTURE_ETAS`·η.
pub const ETA_REL: f64 = 1.0 / 4096.0;

/// See [`ETA_REL`].
pub const CAPTURE_ETAS: f64 = 1.25;

/// The segments Δφ.
pub const DELTAS: [f64; 4] = [TAU, PI, FRAC_PI_2, PI / 6.0];

/// The bores r_min/r_max.
pub const RATIOS: [f64; 3] = [0.0, 0.5, 0.9];

/// The scales r_max, in turn per pose.
pub const SCALES: [f64; 3] = [1e-3, 1.0, 1e3];

/// Rays per pose.
pub const POSE_RAYS: usize = 1000;

/// Disagreements kept per class for the console.
const SHOWN: usize = 3;

/// The classes (ν, Δφ, r_min/r_max) of every ν of `nus`, Δφ of `deltas` and ratio of
/// `ratios`, ν outermost (the command's default: [`DELTAS`] × [`RATIOS`]).
pub fn classes(nus: &[f64], deltas: &[f64], ratios: &[f64]) -> Vec<(f64, f64, f64)> {
    let mut all = Vec::new();
    for &nu in nus {
        for &delta in deltas {
            for &ratio in ratios {
                all.push((nu, delta, ratio));
            }
        }
    }
    all
}

/// Δφ in degrees, rounded to 10⁻⁶ (30, not 30.000000000000004).
pub fn degrees(delta: f64) -> f64 {
    (delta.to_degrees() * 1e6).round() / 1e6
}

/// The class (ν, Δφ, r_min/r_max) as `dphi=90 rmin=0.5 nu=4`.
pub fn class_label((nu, delta, ratio): (f64, f64, f64)) -> String {
    format!("dphi={} rmin={ratio} nu={nu}", degrees(delta))
}

/// One cull, alone or behind the wedge, on one class.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CullRecord {
    /// The cull's stable name.
    pub cull: String,
    /// Behind the wedge.
    pub wedge: bool,
    /// Its counts (in the file, fields of the record).
    #[serde(flatten)]
    pub counts: CullCounts,
    /// rejected / rays.
    pub rejection_rate: f64,
    /// far_misses_rejected / far_misses (null without far misses).
    pub capture: Option<f64>,
}

impl CullRecord {
    /// `cychosz`, or `cychosz+wedge` (`none+wedge`: the wedge alone).
    pub fn label(&self) -> String {
        if self.wedge {
            format!("{}+wedge", self.cull)
        } else {
            self.cull.clone()
        }
    }
}

/// The cut-away misses of one class and the wedge alone's share of them.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct CutAwayRecord {
    /// Literal rays the oracle misses that hit the whole outer torus and miss its segment.
    pub misses: u64,
    /// Of those, rejected by the wedge alone.
    pub wedge_rejected: u64,
    /// wedge_rejected / misses (null without any).
    pub capture: Option<f64>,
}

/// The exact intersection on one class: [`Tally`]'s counts.
pub type ExactRecord = Tally;

/// One class.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ClassRecord {
    /// ν = R/r_max.
    pub nu: f64,
    /// Δφ in radians.
    pub delta_phi: f64,
    /// Δφ in degrees (rounded), for labels.
    pub delta_phi_deg: f64,
    /// r_min/r_max.
    pub bore_ratio: f64,
    /// Rays drawn.
    pub rays: u64,
    /// Per ray kind.
    pub kinds: Vec<KindRecord>,
    /// Per cull of [`CullKind::TIMED`] alone, then each behind the wedge.
    pub culls: Vec<CullRecord>,
    /// The cut-away misses.
    pub cut_away: CutAwayRecord,
    /// The exact intersection.
    pub exact: ExactRecord,
}

impl ClassRecord {
    /// `dphi=90 rmin=0.5 nu=4`.
    pub fn label(&self) -> String {
        class_label((self.nu, self.delta_phi, self.bore_ratio))
    }

    /// False rejects over every cull and combination.
    pub fn false_rejects(&self) -> u64 {
        self.culls.iter().map(|c| c.counts.false_rejects).sum()
    }
}

/// The results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BendFile {
    /// Always [`SCHEMA_VERSION`].
    pub schema_version: u32,
    /// Provenance, as in the other results files (`meta.tool` = `bend`).
    pub meta: crate::results::Meta,
    /// Rays per class.
    pub rays_per_class: u64,
    /// The seed.
    pub seed: u64,
    /// Which oracle labelled the rays.
    pub oracle: String,
    /// η / (R + r_max).
    pub eta_rel: f64,
    /// The capture's threshold in η.
    pub capture_etas: f64,
    /// The exact intersection's tolerance × S.
    pub exact_tol_rel: f64,
    /// One record per class, in [`classes`] order.
    pub classes: Vec<ClassRecord>,
}

impl BendFile {
    /// The file of `classes` ([`classes`]), drawn with `rays` per class from `seed`, with
    /// no records yet: its workload hash is over the parameters alone, so it is made
    /// before the work and the records filled in after.
    pub fn new(classes: &[(f64, f64, f64)], rays: usize, seed: u64) -> BendFile {
        use sha2::{Digest, Sha256};
        let mut spec = format!(
            "bend v{SCHEMA_VERSION} rays {rays} seed {seed} pose {POSE_RAYS} scales {SCALES:?}"
        );
        for &c in classes {
            let _ = write!(spec, " {}", class_label(c));
        }
        let sha256: String = Sha256::digest(spec.as_bytes())
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        let workload = crate::workload::spec::Workload {
            name: "bend".into(),
            seed,
            cases: Vec::new(),
            nu: classes.iter().map(|c| c.0).collect(),
            rays,
            pose: crate::workload::Pose::Random,
            bvh: None,
            bend: None,
            shapes: None,
            sha256,
        };
        let meta = crate::results::Results::new(&workload, "bend").meta;
        BendFile {
            schema_version: SCHEMA_VERSION,
            meta,
            rays_per_class: rays as u64,
            seed,
            oracle: "oracle::bend (BendQuery; on-surface rule for spawned rays)".into(),
            eta_rel: ETA_REL,
            capture_etas: CAPTURE_ETAS,
            exact_tol_rel: exact::TOL,
            classes: Vec::new(),
        }
    }
}

/// One pose's (or one class's) counts while rays are drawn.
#[derive(Debug, Clone, Default)]
struct Accum {
    kinds: Vec<KindRecord>,
    culls: Vec<CullRecord>,
    cut_away: CutAwayRecord,
    exact: Tally,
    why: Vec<String>,
}

impl Accum {
    fn new() -> Accum {
        let cull = |c: &CullKind, wedge| CullRecord {
            cull: c.name().into(),
            wedge,
            counts: CullCounts::default(),
            rejection_rate: 0.0,
            capture: None,
        };
        let mut culls: Vec<CullRecord> = CullKind::TIMED.iter().map(|c| cull(c, false)).collect();
        culls.extend(CullKind::TIMED.iter().map(|c| cull(c, true)));
        Accum {
            kinds: KindRecord::zeroed(RayKind::ALL.iter().map(|k| k.name())),
            culls,
            ..Accum::default()
        }
    }

    fn add(&mut self, o: Accum) {
        for (a, b) in self.kinds.iter_mut().zip(&o.kinds) {
            a.add(b);
        }
        for (a, b) in self.culls.iter_mut().zip(&o.culls) {
            a.counts.add(&b.counts);
        }
        self.cut_away.misses += o.cut_away.misses;
        self.cut_away.wedge_rejected += o.cut_away.wedge_rejected;
        self.exact.add(&o.exact);
        for w in o.why {
            if self.why.len() < SHOWN {
                self.why.push(w);
            }
        }
    }
}

/// The flags (or workload fields) that give a class's ν, Δφ and r_min/r_max, for
/// [`refuse_class`]'s messages: `("--nu", "--delta-phi", "--bore-ratio")`.
pub type ClassNames<'a> = (&'a str, &'a str, &'a str);

/// Why the class `(nu, delta, ratio)` is one the check cannot build, before any work:
/// its bend at every scale of [`SCALES`] is built (the library decides, at the poses'
/// own radii), and a refusal names the flags of `names` and the allowed range. ν is
/// `1 < nu <= MAX_NU`; with a bore, the bore's torus needs `R/r_min <= MAX_NU`, so
/// `ratio >= nu/MAX_NU`, and the wall needs `r_max − r_min >= MIN_WALL_REL·(R + r_max)`,
/// so `ratio <= 1 − MIN_WALL_REL·(nu + 1)`.
pub fn refuse_class((nu, delta, ratio): (f64, f64, f64), names: ClassNames) -> Result<(), String> {
    use torus_cull::MAX_NU;
    use torus_cull::bend::{BendError, MIN_WALL_REL};
    let (nu_name, delta_name, ratio_name) = names;
    if !(nu.is_finite() && nu > 1.0 && nu <= MAX_NU) {
        return Err(format!(
            "{nu_name} {nu} is invalid (allowed: 1 < {nu_name} <= {MAX_NU})"
        ));
    }
    let lo = nu / MAX_NU;
    let hi = 1.0 - MIN_WALL_REL * (nu + 1.0);
    let ratios = if lo <= hi {
        format!("0, or {lo} <= {ratio_name} <= 1 - {MIN_WALL_REL:e}*(nu + 1) = {hi}")
    } else {
        format!("0 only (a bore needs nu/1000 = {lo} <= {ratio_name}, which leaves no wall)")
    };
    for scale in SCALES {
        let spec = Spec::canonical(nu * scale, ratio * scale, scale, 0.0, delta);
        match spec.bend() {
            Ok(_) => {}
            Err(BendError::Segment { .. }) => {
                return Err(format!(
                    "{delta_name} {delta} is invalid (allowed: 0 < {delta_name} <= 2*pi = {TAU})"
                ));
            }
            Err(BendError::Bore { .. }) => {
                return Err(format!(
                    "{ratio_name} {ratio} is invalid (allowed: 0 <= {ratio_name} < 1)"
                ));
            }
            Err(BendError::ThinWall { .. }) => {
                return Err(format!(
                    "{ratio_name} {ratio} at {nu_name} {nu} leaves a wall r_max - r_min = \
                     {:e}*r_max, thinner than {MIN_WALL_REL:e}*(R + r_max), the thinnest the \
                     bend is tested at (allowed at {nu_name} {nu}: {ratio_name} {ratios})",
                    1.0 - ratio
                ));
            }
            Err(BendError::Torus { which: "bore", .. }) => {
                return Err(format!(
                    "{ratio_name} {ratio} at {nu_name} {nu} gives the bore's torus nu = R/r_min \
                     = {} (allowed: at most {MAX_NU}, so at {nu_name} {nu}: {ratio_name} {ratios})",
                    nu / ratio
                ));
            }
            Err(e) => {
                return Err(format!(
                    "{nu_name} {nu}, {delta_name} {delta}, {ratio_name} {ratio} at r_max = \
                     {scale}: {e}"
                ));
            }
        }
    }
    Ok(())
}

/// Rays `first..first + count` of class `(nu, delta, ratio)` in pose `pose`.
fn check_pose(
    (nu, delta, ratio): (f64, f64, f64),
    class: usize,
    pose: usize,
    (first, count): (usize, usize),
    seed: u64,
) -> Result<Accum, String> {
    let mut rng = rays::rng(
        seed ^ (class as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ (pose as u64 + 1).wrapping_mul(0xD1B5_4A32_D192_ED03),
    );
    let scale = SCALES[pose % SCALES.len()];
    let spec = Spec::canonical(nu * scale, ratio * scale, scale, 0.0, delta).posed(&mut rng);
    // The classes passed `refuse_class` at these radii; a pose moves and turns them only.
    let bend = spec
        .bend()
        .map_err(|e| format!("{}: {spec:?}: {e}", class_label((nu, delta, ratio))))?;
    let whole = Spec {
        bore: 0.0,
        delta: TAU,
        ..spec
    };
    let segment = Spec { bore: 0.0, ..spec };
    let far = CAPTURE_ETAS * ETA_REL * spec.size();
    let wedges: Vec<_> = CullKind::TIMED
        .iter()
        .map(|&c| bend.wedge_cull(c))
        .collect();
    let alone_wedge = bend.wedge_cull(NoCull);
    let mut acc = Accum::new();
    for i in first..first + count {
        let k = i % RayKind::ALL.len();
        let (ray, spawned) = rays::draw(&spec, &bend, RayKind::ALL[k], &mut rng);
        let q = spec.query(&ray);
        let label = if spawned {
            q.classify_from_surface()
        } else {
            q.classify()
        };
        acc.kinds[k].count(label.class);
        let n = CullKind::TIMED.len();
        let far_miss = !spawned && label.class == OracleClass::Miss && label.margin > far;
        for (j, record) in acc.culls.iter_mut().enumerate() {
            let kept = if j < n {
                bend.kept_by(&CullKind::TIMED[j], &ray)
            } else {
                bend.kept_by(&wedges[j - n], &ray)
            };
            let hit = label.class == OracleClass::Hit;
            record.counts.count(kept, hit, far_miss);
        }
        if !spawned && label.class == OracleClass::Miss && is_cut_away(&whole, &segment, &ray) {
            acc.cut_away.misses += 1;
            acc.cut_away.wedge_rejected += u64::from(!bend.kept_by(&alone_wedge, &ray));
        }
        let (tally, why) = if spawned {
            exact::compare_spawned(&spec, &bend, &ray, &label)
        } else {
            exact::compare(&spec, &bend, &ray, &label)
        };
        acc.exact.add(&tally);
        if let Some(why) = why
            && acc.why.len() < SHOWN
        {
            acc.why.push(why);
        }
    }
    Ok(acc)
}

/// The whole outer torus is hit, its segment (without the bore) missed.
fn is_cut_away(whole: &Spec, segment: &Spec, ray: &DRay) -> bool {
    let class = |s: &Spec| -> OracleLabel { s.query(ray).classify() };
    class(whole).class == OracleClass::Hit && class(segment).class == OracleClass::Miss
}

/// The outcome of [`check`]: the records, and per class up to three disagreements of the
/// exact intersection (for the console).
pub struct Checked {
    /// One record per class.
    pub records: Vec<ClassRecord>,
    /// (class label, description) of the first disagreements.
    pub disagreements: Vec<(String, String)>,
}

/// Every class of `all` ([`classes`]), `rays` rays each, on `threads` threads (the
/// counts do not depend on it: each pose draws from its own seed); `progress(done, all)`
/// in poses.
///
/// # Errors
///
/// A class whose bend the library refuses ([`refuse_class`] says which flag, before any
/// work; here, the first pose refused, should a pose's bend be refused all the same).
pub fn check(
    rays: usize,
    seed: u64,
    all: &[(f64, f64, f64)],
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Checked, String> {
    let refused: Mutex<Option<String>> = Mutex::new(None);
    let poses = rays.div_ceil(POSE_RAYS);
    let jobs: Vec<(usize, usize)> = (0..all.len())
        .flat_map(|c| (0..poses).map(move |p| (c, p)))
        .collect();
    let accums: Vec<Mutex<Accum>> = all.iter().map(|_| Mutex::new(Accum::new())).collect();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&(c, p)) = jobs.get(j) else { break };
                    let first = p * POSE_RAYS;
                    let count = POSE_RAYS.min(rays - first);
                    match check_pose(all[c], c, p, (first, count), seed) {
                        Ok(acc) => accums[c].lock().expect("no worker panicked").add(acc),
                        Err(e) => {
                            refused.lock().expect("no worker panicked").get_or_insert(e);
                        }
                    }
                    progress(done.fetch_add(1, Ordering::Relaxed) + 1, jobs.len());
                }
            });
        }
    });
    if let Some(e) = refused.into_inner().expect("no worker panicked") {
        return Err(e);
    }
    let mut records = Vec::with_capacity(all.len());
    let mut disagreements = Vec::new();
    for (&(nu, delta, ratio), acc) in all.iter().zip(accums) {
        let mut acc = acc.into_inner().expect("no worker panicked");
        for c in &mut acc.culls {
            c.rejection_rate = c.counts.rejection_rate(rays);
            c.capture = c.counts.capture();
        }
        let cut = &mut acc.cut_away;
        cut.capture = (cut.misses > 0).then(|| cut.wedge_rejected as f64 / cut.misses as f64);
        let record = ClassRecord {
            nu,
            delta_phi: delta,
            delta_phi_deg: degrees(delta),
            bore_ratio: ratio,
            rays: rays as u64,
            kinds: acc.kinds,
            culls: acc.culls,
            cut_away: acc.cut_away,
            exact: acc.exact,
        };
        disagreements.extend(acc.why.into_iter().map(|w| (record.label(), w)));
        records.push(record);
    }
    Ok(Checked {
        records,
        disagreements,
    })
}
