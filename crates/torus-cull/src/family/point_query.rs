//! Where a point is, for a family member: inside or not, and its closest surface point
//! and signed distance.
//!
//! The closest point lies in the point's meridian half-plane, where the tube is the
//! ellipse `(u/a)² + (v/b)² = 1` in `(u, v) = (ρ − R, y)`:
//! - **a circular tube** (a = b): the circle's radial projection, `a·q/|q|`; for a horn
//!   or spindle, whose surface is the apple (the arc with ρ ≥ 0), the nearer cusp
//!   `(−R, ±√(a² − R²))` where the projection falls past the axis (the distance to a
//!   circle's points grows with the angle from `q`, so the arc's nearest point is the
//!   projection or an end);
//! - **an elliptical ring or horn tube**: the ellipse's nearest point (its whole ellipse
//!   is the surface: u ≥ −R = −a holds on a horn's), with no closed form (a quartic):
//!   Eberly's method ("Distance from a point to an ellipse", 2011), the root of a function
//!   monotone on a bracket, bisected to adjacent floats;
//! - **an elliptical spindle**: the apple's arc `u ≥ −R`, whose nearest point may be an
//!   interior minimum other than the ellipse's: the nearest of every foot of a normal from
//!   `q` on the arc (each bisected to adjacent floats) and the two cusps (`ellipse.rs`).
//!
//! **Error bound.** The point is on the surface to rounding and the signed distance within
//! 10⁻¹³·(R + max(a, b) + |q|) of the exact one, q the point's offset from the tube's
//! centre in its meridian (measured: tests/oracle/family_points.rs, against a brute-force
//! reference on 10⁶ points).
//!
//! On the axis the meridian is the torus frame's x axis; on the core circle (`q = 0`)
//! the closest point is the nearer end of the ellipse's minor axis (the outer equator for
//! a circle), as the ring torus's point queries choose ([`crate::Torus::project_point`]).

use super::ellipse::{nearest_on_arc, nearest_on_ellipse};
use super::{Toroid, ToroidKind};
use crate::{NonFinitePoint, SurfaceProjection};
use glam::{DVec2, DVec3};
use std::fmt;

/// Why a family point query was refused.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum FamilyPointError {
    /// A NaN or infinite coordinate.
    NonFinite(NonFinitePoint),
    /// No longer returned: every accepted member answers (elliptical horns and spindles
    /// since issue 54). Kept so that code matching on it still compiles.
    Unsupported,
}

impl fmt::Display for FamilyPointError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FamilyPointError::NonFinite(e) => write!(f, "{e}"),
            FamilyPointError::Unsupported => write!(
                f,
                "the closest point of an elliptical horn or spindle torus is not supported \
                 (circular tubes and elliptical ring tori are)"
            ),
        }
    }
}

impl std::error::Error for FamilyPointError {}

impl From<NonFinitePoint> for FamilyPointError {
    fn from(e: NonFinitePoint) -> FamilyPointError {
        FamilyPointError::NonFinite(e)
    }
}

impl Toroid {
    /// Whether `p` lies in the solid, `((ρ − R)/a)² + (y/b)² ≤ 1` (the apple for a horn or
    /// spindle; the surface included).
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn contains(&self, p: DVec3) -> Result<bool, NonFinitePoint> {
        let x = self.image().point_to_local_f64(p)?;
        let (u, v) = (x.x.hypot(x.z) - self.major_radius_f64(), x.y);
        let (a, b) = (self.radial_semi_axis_f64(), self.axial_semi_axis_f64());
        Ok((u / a).powi(2) + (v / b).powi(2) <= 1.0)
    }

    /// The signed distance from `p` to the surface: negative inside.
    ///
    /// # Errors
    ///
    /// As [`Toroid::project_point`].
    pub fn signed_distance(&self, p: DVec3) -> Result<f64, FamilyPointError> {
        Ok(self.project_point(p)?.signed_distance)
    }

    /// The closest surface point to `p`, its outward normal and `p`'s signed distance
    /// (module docs).
    ///
    /// ```
    /// use glam::DVec3;
    /// use torus_cull::family::Toroid;
    /// let flat = Toroid::canonical(4.0, 1.0, 0.5)?; // b = 0.5 along the axis
    /// let above = flat.project_point(DVec3::new(4.0, 2.0, 0.0))?;
    /// assert!((above.signed_distance - 1.5).abs() < 1e-15);
    /// assert!((above.point - DVec3::new(4.0, 0.5, 0.0)).length() < 1e-15);
    /// // A spindle's centre: the apple is 0.25 away along the equator… and √(1 − 0.75²)
    /// // = 0.661 away at its cusps, which are nearer.
    /// let spindle = Toroid::canonical(0.75, 1.0, 1.0)?;
    /// let d = spindle.signed_distance(DVec3::ZERO)?;
    /// assert!((d + (1.0f64 - 0.75 * 0.75).sqrt()).abs() < 1e-15, "{d}");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`FamilyPointError::NonFinite`] for a NaN or infinite coordinate (every accepted
    /// member answers).
    pub fn project_point(&self, p: DVec3) -> Result<SurfaceProjection, FamilyPointError> {
        let x = self.image().point_to_local_f64(p)?;
        let (big, a, b) = (
            self.major_radius_f64(),
            self.radial_semi_axis_f64(),
            self.axial_semi_axis_f64(),
        );
        let elliptical = a != b;
        let rho = x.x.hypot(x.z);
        let radial = if rho > 0.0 {
            DVec3::new(x.x / rho, 0.0, x.z / rho)
        } else {
            DVec3::X
        };
        let q = DVec2::new(rho - big, x.y);
        let inside = (q.x / a).powi(2) + (q.y / b).powi(2) <= 1.0;
        let on = match (elliptical, self.kind()) {
            (false, _) => nearest_on_apple(big, a, q),
            (true, ToroidKind::Spindle) => nearest_on_arc(big, a, b, q),
            // A ring's or a horn's surface is the whole ellipse (u ≥ −R = −a holds on it).
            (true, _) => nearest_on_ellipse(a, b, q),
        };
        // The outward normal: the ellipse's gradient at the point (at a cusp, the
        // bisector of the two arcs' normals: along ±y).
        let grad = DVec2::new(on.x / (a * a), on.y / (b * b));
        let cusp = big + on.x <= 0.0;
        let n2 = if cusp {
            DVec2::new(0.0, on.y.signum())
        } else {
            grad.normalize()
        };
        let dist = (q - on).length();
        let rot = self.image().to_local_rotation_f64().transpose();
        let local = radial * (big + on.x) + DVec3::Y * on.y;
        Ok(SurfaceProjection {
            point: self.image().point_to_world_f64(local),
            normal: rot * (radial * n2.x + DVec3::Y * n2.y),
            signed_distance: if inside { -dist } else { dist },
        })
    }
}

impl Toroid {
    /// The distance from `p` to the surface, for [`Toroid::spawn`]'s on-surface check: the
    /// distance itself, but for an elliptical horn or spindle (whose closest point this
    /// module does not compute) the distance to the whole ellipse in `p`'s meridian, a
    /// lower bound (the apple's arc is part of that ellipse, and the nearest surface point
    /// lies in `p`'s own meridian half-plane). +∞ for a non-finite point.
    pub(super) fn distance_at_least(&self, p: DVec3) -> f64 {
        match self.signed_distance(p) {
            Ok(d) => d.abs(),
            Err(FamilyPointError::Unsupported) => {
                let Ok(x) = self.image().point_to_local_f64(p) else {
                    return f64::INFINITY;
                };
                let q = DVec2::new(x.x.hypot(x.z) - self.major_radius_f64(), x.y);
                let (a, b) = (self.radial_semi_axis_f64(), self.axial_semi_axis_f64());
                (q - nearest_on_ellipse(a, b, q)).length()
            }
            Err(FamilyPointError::NonFinite(_)) => f64::INFINITY,
        }
    }
}

/// The nearest point of the circle of radius `a` about `(0, 0)` in `(u, v)`, limited to
/// `u ≥ −R` (the apple) with its cusps as ends; `q = 0` gives the outer equator.
fn nearest_on_apple(big: f64, a: f64, q: DVec2) -> DVec2 {
    let len = q.length();
    let on = if len > 0.0 {
        q * (a / len)
    } else {
        DVec2::new(a, 0.0)
    };
    // A horn's arc is the whole circle (its "cusp" (−R, 0) is on it, between arcs): the
    // projection stands even where rounding puts it a hair past the axis.
    if big + on.x >= 0.0 || big >= a {
        return on;
    }
    let cusp = (a * a - big * big).max(0.0).sqrt();
    DVec2::new(-big, if q.y >= 0.0 { cusp } else { -cusp })
}
