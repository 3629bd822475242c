//! One torus-family member of `run`'s sweep: its rays (the family check's literal kinds),
//! the family oracle's labels and each cull's verdicts.

use super::{Member, Params, Unit, sweep_shape};
use crate::check::shapes::family::posed_member;
use crate::check::shapes::family::rays::{self, RayKind};
use crate::measure::CountedCull;
use rand::SeedableRng;
use rand_pcg::Pcg64;
use torus_cull::DRay;
use torus_cull::family::{Toroid, ToroidKind};

/// A stream of its own for the run's member `index` (not the family check's rays).
const SALT: u64 = 0x5EED_F00D_0000_0001;

/// The member (ν = R/a, b/a), a = 1, in a random pose from `rng`: the check's
/// [`posed_member`], any axis (made unit, |v|² > 0.03 as drawn).
fn posed((nu, aspect): (f64, f64), rng: &mut Pcg64) -> Result<Toroid, String> {
    posed_member((nu, aspect), rng, |rng| {
        crate::random::ball_direction(rng, 0.03)
    })
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
    let member = Member {
        pose: format!(
            "Toroid::new_f64(center {:?}, axis {:?}, R {nu}, a 1, b {aspect})",
            toroid.center_f64(),
            toroid.axis_f64()
        ),
        label: label_of,
        first: 0,
    };
    let params = Params {
        shape: shape_name(&toroid, aspect).into(),
        aspect: Some(aspect),
        ..Params::default()
    };
    sweep_shape(&toroid, &drawn, culls, (&member, nu, params))
}
