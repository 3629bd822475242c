//! Pipe bends for the oracle tests: the bend, its rays and the judge of the exact
//! intersection live in the lab (`torus_cull_lab::check::shapes::bend`), one home shared with
//! `torus-cull bend`; the wedge-alone shorthand and the ambiguity band stay here.
#![allow(
    unused_imports,
    reason = "re-exported for every test crate that includes common/, each using a part"
)]

use torus_cull::bend::PipeBend;
use torus_cull::{DRay, NoCull};
use torus_cull_lab::oracle::AMBIGUITY_REL;

pub use torus_cull_lab::check::shapes::bend::exact::{TOL, Tally, face, from_surface_reference};
pub use torus_cull_lab::check::shapes::bend::rays::{Spec, rng, unit};

/// Compares `intersect` and `intersect_all` on the literal `ray` with the oracle
/// (`check::shapes::bend::exact::compare`, labelling the ray itself).
pub fn compare(spec: &Spec, bend: &PipeBend, ray: &DRay) -> (Tally, Option<String>) {
    let label = spec.query(ray).classify();
    torus_cull_lab::check::shapes::bend::exact::compare(spec, bend, ray, &label)
}

/// The wedge alone, for capture counts.
pub fn wedge_alone_keeps(bend: &PipeBend, ray: &DRay) -> bool {
    bend.kept_by(&bend.wedge_cull(NoCull), ray)
}

/// The ambiguity band, for reference.
pub fn band(spec: &Spec) -> f64 {
    AMBIGUITY_REL * spec.size()
}
