//! What `eval` asks of the shape it answers for ([`EvalShape`]): written once for the
//! lab's [`LabShape`] (every shape through the interface: its oracle, the exact `t` of
//! [`Solid::hit`], the certified answer, the cull forms and the on-surface distance) and
//! by [`super::Target`], which keeps the flags' shapes' own refusals and messages and
//! answers its columns through the same functions ([`form_keeps`]).

use super::EvalError;
use crate::lab_shape::{self, LabShape};
use crate::measure::CountedCull;
use crate::oracle::OracleLabel;
use glam::DVec3;
use torus_cull::{CullKind, DRay, ON_SURFACE_REL, Precision, Ray, Solid, Torus};

/// A shape `eval` answers rows for.
pub trait EvalShape {
    /// Refuses a mode the shape cannot take (`--exact f32`, `--exact gpu`), naming it.
    ///
    /// # Errors
    ///
    /// [`EvalError::Mode`], or the shape's own error.
    fn check_mode(&self, precision: super::Precision) -> Result<(), EvalError>;
    /// The torus the GPU answers for.
    ///
    /// # Errors
    ///
    /// A shape the GPU does not take.
    fn gpu_torus(&self) -> Result<&Torus, EvalError>;
    /// The oracle's label of the ray (the on-surface rule for a ray from the surface).
    ///
    /// # Errors
    ///
    /// A line the oracle cannot answer, for its row.
    fn oracle(&self, ray: &DRay) -> Result<OracleLabel, String>;
    /// The exact intersection's nearest `t` of an f32 ray.
    fn t_hit_f32(&self, ray: &Ray) -> Option<f32>;
    /// The exact intersection's nearest `t` of an f64 ray.
    fn t_hit_f64(&self, ray: &DRay) -> Option<f64>;
    /// The certified f32 path's `t` and whether it escalated.
    ///
    /// # Errors
    ///
    /// A shape the certified path does not take.
    fn certified_f32(&self, ray: &Ray) -> Result<(Option<f32>, bool), EvalError>;
    /// Each cull form's verdict (true keeps): [`CullKind::TIMED`]'s, then the guard's.
    fn keeps<P: Precision>(&self, ray: &Ray<P>) -> Vec<bool>;
    /// The columns after the culls' (the guard's forms), empty without a guard.
    fn guard_columns(&self) -> Vec<String>;
    /// Refuses an `on_surface` row whose origin is not a surface point.
    ///
    /// # Errors
    ///
    /// The distance and the allowed bound.
    fn check_on_surface(&self, origin: DVec3) -> Result<(), String>;
}

/// [`CullKind::TIMED`] as counted culls.
fn timed() -> Vec<CountedCull> {
    CullKind::TIMED.iter().map(|&c| c.into()).collect()
}

/// Each form's verdict on one ray ([`lab_shape::forms`] of [`CullKind::TIMED`]): the
/// columns' bits, every shape's through [`Solid::kept_by`].
pub fn form_keeps<S: LabShape, P: Precision>(shape: &S, ray: &Ray<P>) -> Vec<bool> {
    lab_shape::forms(shape, &timed())
        .iter()
        .map(|form| form.kept(shape, std::slice::from_ref(ray))[0])
        .collect()
}

/// The names of the forms after [`CullKind::TIMED`]'s (the guard's).
pub fn guard_columns<S: LabShape>(shape: &S) -> Vec<String> {
    lab_shape::forms(shape, &timed())
        .into_iter()
        .skip(CullKind::TIMED.len())
        .map(|f| f.name)
        .collect()
}

/// Any lab shape: the certified f32 path through [`Solid::hit_f32_certified`], the GPU
/// refused (it takes the ring torus alone), an `on_surface` origin within
/// [`ON_SURFACE_REL`]·size of the surface ([`Solid::signed_distance`]).
impl<S: LabShape> EvalShape for S {
    fn check_mode(&self, precision: super::Precision) -> Result<(), EvalError> {
        match precision {
            super::Precision::CertifiedGpu => self.gpu_torus().map(|_| ()),
            _ => Ok(()),
        }
    }

    fn gpu_torus(&self) -> Result<&Torus, EvalError> {
        Err(EvalError::Mode {
            mode: "--exact gpu",
            message: "the GPU answers for the ring torus alone; use --exact f64".into(),
        })
    }

    fn oracle(&self, ray: &DRay) -> Result<OracleLabel, String> {
        self.label(ray)
    }

    fn t_hit_f32(&self, ray: &Ray) -> Option<f32> {
        self.solid().hit(ray).map(|h| h.t)
    }

    fn t_hit_f64(&self, ray: &DRay) -> Option<f64> {
        self.solid().hit_f64(ray).map(|h| h.t)
    }

    fn certified_f32(&self, ray: &Ray) -> Result<(Option<f32>, bool), EvalError> {
        let answer = self.solid().hit_f32_certified(ray);
        Ok((answer.hit.map(|h| h.t), answer.escalated))
    }

    fn keeps<P: Precision>(&self, ray: &Ray<P>) -> Vec<bool> {
        form_keeps(self, ray)
    }

    fn guard_columns(&self) -> Vec<String> {
        guard_columns(self)
    }

    fn check_on_surface(&self, origin: DVec3) -> Result<(), String> {
        let off = self
            .solid()
            .signed_distance(origin)
            .map_err(|e| e.to_string())?
            .abs();
        on_surface_bound(off, self.size(), "size")
    }
}

/// Refuses a distance `off` from the surface above [`ON_SURFACE_REL`]·`size`, naming
/// the size as `words`.
pub fn on_surface_bound(off: f64, size: f64, words: &str) -> Result<(), String> {
    let bound = ON_SURFACE_REL * size;
    if off > bound {
        return Err(format!(
            "column on_surface: 1, but the origin is {off:.3e} from the surface (allowed: ≤ \
             {ON_SURFACE_REL:e}·{words} = {bound:e}, docs/math.md §9): not a surface point; \
             give 0 for a literal ray"
        ));
    }
    Ok(())
}
