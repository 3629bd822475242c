//! The pipe bends of `run`'s sweep: each bend's rays (the bend check's literal kinds) in
//! poses of `check::shapes::bend::POSE_RAYS` rays, at the check's scales r_max ∈ {10⁻³, 1, 10³} in
//! turn, the bend oracle's labels and each cull's verdicts, alone, with the wedge alone,
//! and behind the wedge.

use super::{Params, ShapeFalseReject, Tally, Unit, name};
use crate::check::shapes::bend::rays::{self, RayKind, Spec};
use crate::check::shapes::bend::{POSE_RAYS, SCALES, refuse_class};
use crate::measure::CountedCull;
use crate::oracle::OracleLabel;
use crate::workload::shapes_spec::{ShapesSpec, segment_radians};
use torus_cull::bend::PipeBend;
use torus_cull::{Cull, CullKind, CullVisitor, DRay, NoCull};

/// A stream of its own for the run's bends (not the bend check's rays).
const SALT: u64 = 0x5EED_BE4D_0000_0002;

/// Why a bend of `spec` is one the library does not build, before any work: the bend
/// check's own test (every scale, the library's refusal), naming the workload's fields.
///
/// # Errors
///
/// The first refused bend, its fields and the allowed range.
pub fn refuse_bends(spec: &ShapesSpec) -> Result<(), String> {
    for &(nu, deg, bore) in &spec.bends {
        refuse_class(
            (nu, segment_radians(deg), bore),
            (
                "shapes.bends.nu",
                "shapes.bends.segments_deg (in radians here)",
                "shapes.bends.bores",
            ),
        )?;
    }
    Ok(())
}

/// One pose's work: the bend's index, its pose, its rays' first index and count.
pub(super) struct PoseUnit {
    pub(super) class: usize,
    pose: usize,
    first: usize,
    count: usize,
}

/// Every pose of every bend of `spec`, bend by bend.
pub(super) fn units(spec: &ShapesSpec) -> Vec<PoseUnit> {
    let mut all = Vec::new();
    for class in 0..spec.bends.len() {
        for (pose, first) in (0..spec.rays).step_by(POSE_RAYS).enumerate() {
            let count = POSE_RAYS.min(spec.rays - first);
            all.push(PoseUnit {
                class,
                pose,
                first,
                count,
            });
        }
    }
    all
}

/// The names of a bend's cull forms: each cull, `wedge`, then `wedge+<cull>` for each
/// cull but `none` (whose wedge form is `wedge`).
fn forms(culls: &[CountedCull]) -> Vec<(String, bool)> {
    let mut all: Vec<(String, bool)> = culls.iter().map(|&c| (name(c), true)).collect();
    all.push(("wedge".into(), true));
    for &c in culls
        .iter()
        .filter(|&&c| c != CountedCull::Timed(CullKind::NoCull))
    {
        all.push((format!("wedge+{}", name(c)), true));
    }
    all
}

/// One pose of one bend.
pub(super) fn pose(
    unit: &PoseUnit,
    spec: &ShapesSpec,
    seed: u64,
    culls: &[CountedCull],
) -> Result<Unit, String> {
    let (nu, deg, ratio) = spec.bends[unit.class];
    let mut rng = rays::rng(
        seed ^ SALT
            ^ (unit.class as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ (unit.pose as u64 + 1).wrapping_mul(0xD1B5_4A32_D192_ED03),
    );
    let scale = SCALES[unit.pose % SCALES.len()];
    let delta = segment_radians(deg);
    let shape = Spec::canonical(nu * scale, ratio * scale, scale, 0.0, delta).posed(&mut rng);
    let member = format!("bend nu={nu} dphi={deg} bore={ratio}");
    // `refuse_bends` passed these radii; a pose moves and turns them only.
    let bend = shape
        .bend()
        .map_err(|e| format!("{member}: {shape:?}: {e}"))?;
    // The check's kinds but the spawned rays (module docs of `shape_sweep`).
    let kinds: Vec<RayKind> = RayKind::ALL
        .into_iter()
        .filter(|&k| k != RayKind::Spawned)
        .collect();
    let drawn: Vec<DRay> = (unit.first..unit.first + unit.count)
        .map(|i| rays::draw(&shape, &bend, kinds[i % kinds.len()], &mut rng).0)
        .collect();
    let labels: Vec<OracleLabel> = drawn.iter().map(|r| shape.query(r).classify()).collect();
    let forms = forms(culls);
    let mut tally = Tally::new(forms.len());
    tally.label(&labels);
    let mut verdicts: Vec<Vec<bool>> = culls
        .iter()
        .map(|&c| c.visit(Verdicts(&bend, &drawn, false)))
        .collect();
    verdicts.push(Verdicts(&bend, &drawn, true).visit(NoCull));
    for &c in culls
        .iter()
        .filter(|&&c| c != CountedCull::Timed(CullKind::NoCull))
    {
        verdicts.push(c.visit(Verdicts(&bend, &drawn, true)));
    }
    let mut false_rejects = Vec::new();
    for (j, kept) in verdicts.iter().enumerate() {
        for i in tally.verdicts(j, &labels, kept) {
            false_rejects.push(ShapeFalseReject {
                member: member.clone(),
                pose: format!("{shape:?}"),
                cull: forms[j].0.clone(),
                index: unit.first + i,
                origin: drawn[i].origin(),
                dir: drawn[i].dir(),
                margin: labels[i].margin,
            });
        }
    }
    Ok(Unit {
        nu,
        params: Params {
            shape: "bend".into(),
            bore: Some(ratio),
            segment_deg: Some(deg),
            ..Params::default()
        },
        forms,
        tally,
        false_rejects,
    })
}

/// The cull's verdict on each ray against the bend's outer torus (`true` keeps), behind
/// the segment's wedge if asked.
struct Verdicts<'a>(&'a PipeBend, &'a [DRay], bool);

impl CullVisitor for Verdicts<'_> {
    type Output = Vec<bool>;
    fn visit<C: Cull>(self, cull: C) -> Vec<bool> {
        let Verdicts(bend, rays, wedge) = self;
        if wedge {
            let cull = bend.wedge_cull(cull);
            rays.iter().map(|r| bend.kept_by(&cull, r)).collect()
        } else {
            rays.iter().map(|r| bend.kept_by(&cull, r)).collect()
        }
    }
}
