//! The torus's constants on the exact (f64) path, in the foot-point frame scaled by 1/R.

/// A torus's constants on the exact path, each computed once in f64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tube {
    /// R.
    pub(crate) major: f64,
    /// 1/R: the scale of the foot-point frame.
    pub(crate) inv_major: f64,
    /// r/R: the tube radius at R = 1.
    pub(crate) minor_rel: f64,
    /// 1 − (r/R)², of the normal's gradient.
    pub(crate) k: f64,
    /// 1 + r/R: the bounding sphere's radius at R = 1.
    pub(crate) outer: f64,
}

impl Tube {
    /// The constants of R = `major`, r = `minor`.
    #[inline(always)]
    pub(crate) fn new(major: f64, minor: f64) -> Tube {
        let inv_major = 1.0 / major;
        let minor_rel = minor * inv_major;
        Tube {
            major,
            inv_major,
            minor_rel,
            k: 1.0 - minor_rel * minor_rel,
            outer: 1.0 + minor / major,
        }
    }
}
