//! The torus's constants on the exact (f64) path, in the foot-point frame scaled by 1/R.

use glam::DVec3;

/// A torus's constants on the exact path, each computed once in f64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tube {
    /// R.
    pub(crate) major: f64,
    /// r.
    pub(crate) minor: f64,
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
            minor,
            inv_major,
            minor_rel,
            k: 1.0 - minor_rel * minor_rel,
            outer: 1.0 + minor / major,
        }
    }

    /// The surface point nearest to the torus-frame point `o` (f64): `c + r·(o − c)/|o − c|`
    /// with `c = R·(o_x, 0, o_z)/ρ` the nearest point of the core circle. Closed form, off
    /// the surface by a few ulps of `|o|`. `None` on the axis or the core circle (no unique
    /// nearest point) and for a non-finite `o`.
    #[inline]
    pub(crate) fn nearest_surface_point(&self, o: DVec3) -> Option<DVec3> {
        let rho = o.x.hypot(o.z);
        if !(rho > 0.0 && rho.is_finite()) {
            return None;
        }
        let core = DVec3::new(o.x, 0.0, o.z) * (self.major / rho);
        let off = o - core;
        let len = off.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        Some(core + off * (self.minor / len))
    }
}
