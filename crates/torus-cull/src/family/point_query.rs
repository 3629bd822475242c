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
//! - **an elliptical ring tube**: the ellipse's nearest point, with no closed form (a
//!   quartic): Eberly's method ("Distance from a point to an ellipse", 2011), the root of
//!   a function monotone on a bracket, bisected to adjacent floats, so the point is exact
//!   but for a few ulps of (R + max(a, b)). An elliptical horn or spindle is refused
//!   ([`FamilyPointError::Unsupported`]): its arc's nearest point may be an interior
//!   minimum other than the ellipse's, which this method does not enumerate.
//!
//! On the axis the meridian is the torus frame's x axis; on the core circle (`q = 0`)
//! the closest point is the nearer end of the ellipse's minor axis (the outer equator for
//! a circle), as the ring torus's point queries choose ([`crate::Torus::project_point`]).

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
    /// The closest point of an elliptical horn or spindle (module docs).
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
    /// [`FamilyPointError::NonFinite`] for a NaN or infinite coordinate;
    /// [`FamilyPointError::Unsupported`] for an elliptical horn or spindle.
    pub fn project_point(&self, p: DVec3) -> Result<SurfaceProjection, FamilyPointError> {
        let x = self.image().point_to_local_f64(p)?;
        let (big, a, b) = (
            self.major_radius_f64(),
            self.radial_semi_axis_f64(),
            self.axial_semi_axis_f64(),
        );
        let elliptical = a != b;
        if elliptical && self.kind() != ToroidKind::Ring {
            return Err(FamilyPointError::Unsupported);
        }
        let rho = x.x.hypot(x.z);
        let radial = if rho > 0.0 {
            DVec3::new(x.x / rho, 0.0, x.z / rho)
        } else {
            DVec3::X
        };
        let q = DVec2::new(rho - big, x.y);
        let inside = (q.x / a).powi(2) + (q.y / b).powi(2) <= 1.0;
        let on = if elliptical {
            nearest_on_ellipse(a, b, q)
        } else {
            nearest_on_apple(big, a, q)
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
    if big + on.x >= 0.0 {
        return on;
    }
    let cusp = (a * a - big * big).max(0.0).sqrt();
    DVec2::new(-big, if q.y >= 0.0 { cusp } else { -cusp })
}

/// The nearest point of the ellipse `(u/a)² + (v/b)² = 1` to `q` (module docs: Eberly's
/// bisection, in the first quadrant with the longer semi-axis first, then mapped back).
fn nearest_on_ellipse(a: f64, b: f64, q: DVec2) -> DVec2 {
    let swap = a < b;
    let (e0, e1) = if swap { (b, a) } else { (a, b) };
    let (y0, y1) = if swap {
        (q.y.abs(), q.x.abs())
    } else {
        (q.x.abs(), q.y.abs())
    };
    let (x0, x1) = first_quadrant(e0, e1, y0, y1);
    let (x0, x1) = (
        x0.copysign(if swap { q.y } else { q.x }),
        x1.copysign(if swap { q.x } else { q.y }),
    );
    if swap {
        DVec2::new(x1, x0)
    } else {
        DVec2::new(x0, x1)
    }
}

/// Eberly's nearest point for `e0 ≥ e1 > 0`, `y0, y1 ≥ 0`.
fn first_quadrant(e0: f64, e1: f64, y0: f64, y1: f64) -> (f64, f64) {
    if y1 > 0.0 {
        if y0 > 0.0 {
            let (z0, z1) = (y0 / e0, y1 / e1);
            let g = z0 * z0 + z1 * z1 - 1.0;
            if g == 0.0 {
                return (y0, y1);
            }
            let r0 = (e0 / e1) * (e0 / e1);
            let s = bisect(r0, z0, z1, g);
            return (r0 * y0 / (s + r0), y1 / (s + 1.0));
        }
        return (0.0, e1);
    }
    let numer = e0 * y0;
    let denom = e0 * e0 - e1 * e1;
    if numer < denom {
        let xde0 = numer / denom;
        return (e0 * xde0, e1 * (1.0 - xde0 * xde0).max(0.0).sqrt());
    }
    (e0, 0.0)
}

/// The root `s` of `(r0 z0/(s + r0))² + (z1/(s + 1))² = 1` on its bracket, bisected to
/// adjacent floats (the function decreases in `s` there).
fn bisect(r0: f64, z0: f64, z1: f64, g: f64) -> f64 {
    let n0 = r0 * z0;
    let mut s0 = z1 - 1.0;
    let mut s1 = if g < 0.0 { 0.0 } else { n0.hypot(z1) - 1.0 };
    let mut s = 0.0;
    for _ in 0..2200 {
        s = 0.5 * (s0 + s1);
        if s == s0 || s == s1 {
            break;
        }
        let (t0, t1) = (n0 / (s + r0), z1 / (s + 1.0));
        let h = t0 * t0 + t1 * t1 - 1.0;
        if h > 0.0 {
            s0 = s;
        } else if h < 0.0 {
            s1 = s;
        } else {
            break;
        }
    }
    s
}
