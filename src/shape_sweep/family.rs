//! One torus-family member of `run`'s sweep: its rays (the family check's literal kinds),
//! the family oracle's labels and each cull's verdicts.

use super::{Params, ShapeFalseReject, Tally, Unit, name};
use crate::check::shapes::family::rays::{self, RayKind};
use crate::family_label;
use crate::measure::CountedCull;
use crate::oracle::OracleLabel;
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use torus_cull::family::{Toroid, ToroidKind};
use torus_cull::{Cull, CullVisitor, DRay};

/// A stream of its own for the run's member `index` (not the family check's rays).
const SALT: u64 = 0x5EED_F00D_0000_0001;

/// The member (ν = R/a, b/a), a = 1, in a random pose from `rng`: centre within 2·(R +
/// max(a, b)) of the origin, any axis.
fn posed((nu, aspect): (f64, f64), rng: &mut Pcg64) -> Result<Toroid, String> {
    let size = nu + aspect.max(1.0);
    let center = DVec3::new(
        rng.random_range(-2.0..2.0),
        rng.random_range(-2.0..2.0),
        rng.random_range(-2.0..2.0),
    ) * size;
    let axis = crate::random::ball_direction(rng, 0.03);
    Toroid::new_f64(center, axis, nu, 1.0, aspect)
        .map_err(|e| format!("shapes.family member nu={nu} b/a={aspect}: {e}"))
}

/// `ring`, `elliptic`, `horn` or `spindle`.
fn shape_name(toroid: &Toroid, aspect: f64) -> &'static str {
    match toroid.kind() {
        ToroidKind::Ring if aspect == 1.0 => "ring",
        ToroidKind::Ring => "elliptic",
        ToroidKind::Horn => "horn",
        ToroidKind::Spindle => "spindle",
    }
}

/// Member `index` of the sweep, `(nu, aspect)`, with `rays` rays from `seed`.
pub(super) fn member(
    (nu, aspect): (f64, f64),
    index: usize,
    rays: usize,
    seed: u64,
    culls: &[CountedCull],
) -> Result<Unit, String> {
    let mut rng =
        Pcg64::seed_from_u64(seed ^ SALT ^ (index as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    let toroid = posed((nu, aspect), &mut rng)?;
    let label_of = format!("{} nu={nu} b/a={aspect}", shape_name(&toroid, aspect));
    // The check's kinds but the spawned rays (module docs of `shape_sweep`).
    let kinds: Vec<RayKind> = RayKind::ALL
        .into_iter()
        .filter(|&k| k != RayKind::Spawned)
        .collect();
    let drawn: Vec<DRay> = (0..rays)
        .map(|i| rays::draw(&toroid, kinds[i % kinds.len()], &mut rng))
        .collect();
    let labels = drawn
        .iter()
        .enumerate()
        .map(|(i, ray)| {
            family_label::label(&toroid, ray).map_err(|e| format!("{label_of}, ray {i}: {e}"))
        })
        .collect::<Result<Vec<OracleLabel>, String>>()?;
    let mut tally = Tally::new(culls.len());
    tally.label(&labels);
    let mut forms = Vec::new();
    let mut false_rejects = Vec::new();
    for (j, &cull) in culls.iter().enumerate() {
        let (accepts, kept) = cull.visit(Verdicts(&toroid, &drawn));
        for i in tally.verdicts(j, &labels, &kept) {
            false_rejects.push(ShapeFalseReject {
                member: label_of.clone(),
                pose: format!(
                    "Toroid::new_f64(center {:?}, axis {:?}, R {nu}, a 1, b {aspect})",
                    toroid.center_f64(),
                    toroid.axis_f64()
                ),
                cull: name(cull),
                index: i,
                origin: drawn[i].origin(),
                dir: drawn[i].dir(),
                margin: labels[i].margin,
            });
        }
        forms.push((name(cull), accepts));
    }
    Ok(Unit {
        nu,
        params: Params {
            shape: shape_name(&toroid, aspect).into(),
            aspect: Some(aspect),
            ..Params::default()
        },
        forms,
        tally,
        false_rejects,
    })
}

/// Whether the cull accepts the member's shape, and its verdict on each ray (`true`
/// keeps; a declined cull keeps every ray).
struct Verdicts<'a>(&'a Toroid, &'a [DRay]);

impl CullVisitor for Verdicts<'_> {
    type Output = (bool, Vec<bool>);
    fn visit<C: Cull>(self, cull: C) -> (bool, Vec<bool>) {
        let accepts = cull.shapes().contains(&self.0.shape());
        (
            accepts,
            self.1.iter().map(|r| self.0.kept_by(&cull, r)).collect(),
        )
    }
}
