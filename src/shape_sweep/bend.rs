//! The pipe bends of `run`'s sweep: each bend's rays (the bend check's literal kinds) in
//! poses of `check::shapes::bend::POSE_RAYS` rays, at the check's scales r_max ∈ {10⁻³, 1, 10³} in
//! turn, the bend oracle's labels and each cull's verdicts, alone, with the wedge alone,
//! and behind the wedge.

use super::{Member, Params, Unit, sweep_shape};
use crate::check::shapes::bend::rays::{self, RayKind, Spec};
use crate::check::shapes::bend::{POSE_RAYS, PosedBend, SCALES, refuse_class};
use crate::measure::CountedCull;
use crate::workload::shapes_spec::{ShapesSpec, segment_radians};
use torus_cull::DRay;

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
    let posed = PosedBend::new(shape).map_err(|e| format!("{member}: {shape:?}: {e}"))?;
    // The check's kinds but the spawned rays (module docs of `shape_sweep`).
    let kinds: Vec<RayKind> = RayKind::ALL
        .into_iter()
        .filter(|&k| k != RayKind::Spawned)
        .collect();
    let drawn: Vec<DRay> = (unit.first..unit.first + unit.count)
        .map(|i| rays::draw(&shape, &posed.bend, kinds[i % kinds.len()], &mut rng).0)
        .collect();
    let member = Member {
        label: member,
        pose: format!("{shape:?}"),
        first: unit.first,
    };
    let params = Params {
        shape: "bend".into(),
        bore: Some(ratio),
        segment_deg: Some(deg),
        ..Params::default()
    };
    sweep_shape(&posed, &drawn, culls, (&member, nu, params))
}
