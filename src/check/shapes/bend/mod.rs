pub mod exact;
pub mod rays;

use crate::check::record::{AnswerRecord, CaptureRecord, ClassRecord, CullRecord, KindRecord};
use crate::check::solid::count_culls;
use crate::check::{About, CheckShape, Job};
use crate::lab_shape::LabShape;
use crate::oracle::{OracleClass, OracleLabel};
use exact::Tally;
use rays::{RayKind, Spec};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
use torus_cull::bend::PipeBend;
use torus_cull::{Cull, CullKind, DRay, NoCull, Precision, Ray};

/// The seed `--seed` defaults to.
pub const SEED: u64 = 20261128;

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

/// A pipe bend with the parameters its oracle takes (the library's [`PipeBend`] keeps no
/// φ = 0 direction of its own): the lab's bend ([`LabShape`]).
#[derive(Debug, Clone)]
pub struct PosedBend {
    /// Its parameters, for the oracle.
    pub spec: Spec,
    /// The library's solid of `spec`.
    pub bend: PipeBend,
}

impl PosedBend {
    /// The bend of `spec`, or the library's reason for refusing it.
    ///
    /// # Errors
    ///
    /// The library's [`torus_cull::bend::BendError`].
    pub fn new(spec: Spec) -> Result<PosedBend, torus_cull::bend::BendError> {
        Ok(PosedBend {
            bend: spec.bend()?,
            spec,
        })
    }
}

/// The bend oracle (the on-surface rule for a ray from the surface), R + r_max, and the
/// segment's wedge as the guard in front of every cull (`PipeBend::wedge_cull`).
impl LabShape for PosedBend {
    type Solid = PipeBend;

    fn solid(&self) -> &PipeBend {
        &self.bend
    }

    fn label(&self, ray: &DRay) -> Result<OracleLabel, String> {
        let query = self.spec.query(ray);
        Ok(if ray.starts_on_surface() {
            query.classify_from_surface()
        } else {
            query.classify()
        })
    }

    fn size(&self) -> f64 {
        self.spec.size()
    }

    fn guard(&self) -> Option<&'static str> {
        Some("wedge")
    }

    fn guarded_kept<C: Cull, P: Precision>(&self, cull: C, rays: &[Ray<P>]) -> Vec<bool> {
        let wedged = self.bend.wedge_cull(cull);
        rays.iter().map(|r| self.bend.kept_by(&wedged, r)).collect()
    }
}

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

/// The pipe bend as a check's shape: its classes (ν, Δφ, r_min/r_max), each checked
/// already by [`refuse_class`]; f64 only.
pub struct BendShape {
    /// The classes, in order.
    pub classes: Vec<(f64, f64, f64)>,
}

impl CheckShape for BendShape {
    fn about(&self) -> About {
        About {
            name: "bend",
            precision: "f64",
            oracle: "oracle::bend (BendQuery; on-surface rule for spawned rays)",
            constants: vec![
                ("eta_rel", ETA_REL),
                ("capture_etas", CAPTURE_ETAS),
                ("exact_tol_rel", exact::TOL),
            ],
            chart: (
                "delta_phi_deg",
                "Δφ in degrees (log scale)",
                &["bore_ratio", "nu"],
            ),
            spec: format!("pose {POSE_RAYS} scales {SCALES:?}"),
        }
    }
    fn labels(&self) -> Vec<String> {
        self.classes.iter().map(|&c| class_label(c)).collect()
    }
    fn jobs(&self, rays: usize) -> usize {
        rays.div_ceil(POSE_RAYS)
    }
    fn check_job(&self, job: Job) -> Result<(ClassRecord, Vec<String>), String> {
        let first = job.job * POSE_RAYS;
        let count = POSE_RAYS.min(job.rays - first);
        let class = self.classes[job.index];
        check_pose(class, job.index, job.job, (first, count), job.seed)
    }
}

/// One cull record per timed cull, then each behind the wedge (`cychosz+wedge`).
fn cull_records() -> Vec<CullRecord> {
    let alone = CullKind::TIMED.iter().map(|c| c.name().to_string());
    let behind = CullKind::TIMED
        .iter()
        .map(|c| format!("{}+wedge", c.name()));
    alone
        .chain(behind)
        .map(|label| CullRecord::new(label, true))
        .collect()
}

/// The exact intersection's tally as its two answers, `intersect` (with the judge's
/// counts and the largest t error) and `intersect_all`.
fn answers(t: &Tally) -> Vec<AnswerRecord> {
    let kinds = ["missed", "invented", "wrong_face", "wrong_value"];
    let mut first = AnswerRecord::new("intersect", true, &kinds);
    let mut all = AnswerRecord::new("intersect_all", true, &kinds);
    let one = [t.missed, t.invented, t.wrong_face, t.wrong_value];
    let every = [
        t.all_missed,
        t.all_invented,
        t.all_wrong_face,
        t.all_wrong_value,
    ];
    for (k, (a, b)) in kinds.iter().zip(one.into_iter().zip(every)) {
        first.wrong.insert((*k).into(), a);
        all.wrong.insert((*k).into(), b);
    }
    for (k, v) in [
        ("judged_hits", t.hits),
        ("judged_misses", t.misses),
        ("ambiguous", t.ambiguous),
    ] {
        first.counts.insert(k.into(), v);
    }
    first.raise("max_t_error_rel", t.max_t_error_rel);
    vec![first, all]
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
) -> Result<(ClassRecord, Vec<String>), String> {
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
    let mut kinds = KindRecord::zeroed(RayKind::ALL.iter().map(|k| k.name()));
    let mut culls = cull_records();
    let mut cut_away = CaptureRecord {
        name: "cut-away".into(),
        by: "wedge".into(),
        ..CaptureRecord::default()
    };
    let mut exact = Tally::default();
    let mut shown = Vec::new();
    for i in first..first + count {
        let k = i % RayKind::ALL.len();
        let (ray, spawned) = rays::draw(&spec, &bend, RayKind::ALL[k], &mut rng);
        let q = spec.query(&ray);
        let label = if spawned {
            q.classify_from_surface()
        } else {
            q.classify()
        };
        kinds[k].count(label.class);
        let far_miss = !spawned && label.class == OracleClass::Miss && label.margin > far;
        let hit = label.class == OracleClass::Hit;
        let (alone, behind) = culls.split_at_mut(CullKind::TIMED.len());
        count_culls(&bend, &CullKind::TIMED, alone, &ray, (hit, far_miss));
        count_culls(&bend, &wedges, behind, &ray, (hit, far_miss));
        if !spawned && label.class == OracleClass::Miss && is_cut_away(&whole, &segment, &ray) {
            cut_away.misses += 1;
            cut_away.rejected += u64::from(!bend.kept_by(&alone_wedge, &ray));
        }
        let (tally, why) = if spawned {
            exact::compare_spawned(&spec, &bend, &ray, &label)
        } else {
            exact::compare(&spec, &bend, &ray, &label)
        };
        exact.add(&tally);
        if let Some(why) = why
            && shown.len() < 3
        {
            shown.push(why);
        }
    }
    let class = (nu, delta, ratio);
    let record = ClassRecord {
        label: class_label(class),
        params: [
            ("nu", nu),
            ("delta_phi", delta),
            ("delta_phi_deg", degrees(delta)),
            ("bore_ratio", ratio),
        ]
        .map(|(k, v)| (k.into(), v))
        .into(),
        words: Default::default(),
        rays: count as u64,
        kinds,
        culls,
        captures: vec![cut_away],
        answers: answers(&exact),
        ns_per_ray: None,
    };
    Ok((record, shown))
}

/// The whole outer torus is hit, its segment (without the bore) missed.
fn is_cut_away(whole: &Spec, segment: &Spec, ray: &DRay) -> bool {
    let class = |s: &Spec| -> OracleLabel { s.query(ray).classify() };
    class(whole).class == OracleClass::Hit && class(segment).class == OracleClass::Miss
}

/// The bend's classes from the check's options: the workload file's `bend` key (its
/// classes, rays per class and seed, returned with them), or `--nu`, `--delta-phi` and
/// `--bore-ratio` (their defaults where not given), each value checked against its range
/// and each class's bend built before any work ([`refuse_class`]).
///
/// # Errors
///
/// A value out of its range, or a class the library refuses, naming the flag (or the
/// workload file's field) and the allowed range.
pub fn build(options: &super::Options) -> Result<(BendShape, Option<(usize, u64)>), String> {
    use crate::number::Num;
    use crate::workload::bend_spec::{bore_ratio_ok, delta_phi_ok};
    use torus_cull::MAX_NU;
    if let Some(file) = &options.workload {
        let workload = crate::workload::spec::Workload::open(file).map_err(|e| e.to_string())?;
        let spec = workload.bend.ok_or_else(|| {
            format!(
                "--workload {}: no `bend` key (the classes: nu, delta_phi, bore_ratio, rays)",
                file.display()
            )
        })?;
        let classes = classes(&spec.nu, &spec.delta_phi, &spec.bore_ratio);
        for &class in &classes {
            refuse_class(class, ("bend.nu", "bend.delta_phi", "bend.bore_ratio"))
                .map_err(|e| format!("--workload {}: {e}", file.display()))?;
        }
        return Ok((BendShape { classes }, Some((spec.rays, workload.seed))));
    }
    let nus = if options.nu.is_empty() {
        vec![4.0]
    } else {
        options.nu.clone()
    };
    if let Some(nu) = nus
        .iter()
        .find(|nu| !(nu.is_finite() && **nu > 1.0 && **nu <= MAX_NU))
    {
        return Err(format!(
            "--nu {} is invalid (allowed: 1 < --nu <= {MAX_NU})",
            Num(*nu)
        ));
    }
    if let Some(d) = options.delta_phi.iter().find(|d| !delta_phi_ok(**d)) {
        return Err(format!(
            "--delta-phi {} is invalid (allowed: 0 < --delta-phi <= 2*pi = {TAU})",
            Num(*d)
        ));
    }
    if let Some(r) = options.bore_ratio.iter().find(|r| !bore_ratio_ok(**r)) {
        return Err(format!(
            "--bore-ratio {} is invalid (allowed: 0 <= --bore-ratio < 1)",
            Num(*r)
        ));
    }
    let or = |given: &[f64], default: &[f64]| {
        if given.is_empty() {
            default.to_vec()
        } else {
            given.to_vec()
        }
    };
    let classes = classes(
        &nus,
        &or(&options.delta_phi, &DELTAS),
        &or(&options.bore_ratio, &RATIOS),
    );
    // Each class's bend is built before any work: a bore ratio the library refuses at
    // some ν (the bore's own ν above 1000, a wall below the thinnest tested) names both.
    for &class in &classes {
        refuse_class(class, ("--nu", "--delta-phi", "--bore-ratio"))?;
    }
    Ok((BendShape { classes }, None))
}
