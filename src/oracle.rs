//! The f64 ground truth: hit / miss / ambiguous with a signed margin. Never timed.

use crate::{Ray, Torus};

/// The oracle's class for a line or ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OracleClass {
    /// Enters the tube by more than the ambiguity band.
    Hit,
    /// Stays outside the tube by more than the ambiguity band.
    Miss,
    /// |margin| ≤ AMBIGUITY_REL·(R + r).
    Ambiguous,
}

/// The oracle's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OracleLabel {
    /// The class.
    pub class: OracleClass,
    /// min over t of dist(P(t), core circle) − r, in length units; negative enters the tube.
    pub margin: f64,
}

/// Classify the ray over `t ∈ [t_min, t_max]`.
pub fn classify(_torus: &Torus, _ray: &Ray) -> OracleLabel {
    todo!("oracle helper")
}
