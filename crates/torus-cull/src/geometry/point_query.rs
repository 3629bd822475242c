//! Where a point is, for a ring torus: inside or not, its signed distance and closest
//! surface point, the normal and surface coordinates (θ, φ), and the torus's size.
//!
//! Closed forms in f64: with `x` the point in the torus frame, ρ its distance from the
//! axis and `c = R·(x, 0, z)/ρ` the nearest point of the core circle, the distance to the
//! core circle is `D = |x − c| = √((ρ − R)² + y²)`, the signed distance `D − r`, and the
//! closest surface point `c + r·(x − c)/D`. Each is off by rounding only: at most a few
//! ulps of `|p − centre| + R + r` (the transform's and the square root's).
//!
//! Where the closest point is not unique the queries choose one and say which: on the
//! axis (ρ = 0, a whole circle of closest points) the meridian of the torus frame's x
//! axis (`to_local_rotation_f64().row(0)`); on the core circle (D = 0, a whole tube
//! circle) the outer equator's point. [`Torus::nearest_surface_point`] keeps its own
//! convention there (the point returned unchanged), which the spawn path relies on.

use super::{Torus, Tube};
use glam::DVec3;
use std::f64::consts::PI;
use std::fmt;

/// A point query's refusal: a point with a NaN or infinite coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonFinitePoint(pub DVec3);

impl fmt::Display for NonFinitePoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "point {} is not finite", self.0)
    }
}

impl std::error::Error for NonFinitePoint {}

/// The closest surface point to a query point, with its outward normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceProjection {
    /// The closest surface point, world space.
    pub point: DVec3,
    /// The unit outward normal there, world space.
    pub normal: DVec3,
    /// The query point's signed distance to the surface: negative inside the solid.
    pub signed_distance: f64,
}

impl Tube {
    /// The closest surface point to the torus-frame point `x`, its outward normal and the
    /// signed distance (module docs; the axis and the core circle as chosen there).
    pub(crate) fn project(&self, x: DVec3) -> (DVec3, DVec3, f64) {
        let rho = x.x.hypot(x.z);
        let radial = if rho > 0.0 {
            DVec3::new(x.x / rho, 0.0, x.z / rho)
        } else {
            DVec3::X
        };
        // The offset from the core circle in the meridian's own coordinates (ρ − R, y):
        // formed from x − R·radial instead, its rounding leaves the meridian, and on the
        // core circle (where it is only rounding) would point anywhere.
        let (across, up) = (rho - self.major, x.y);
        let dist = across.hypot(up);
        let out = if dist > 0.0 {
            radial * (across / dist) + DVec3::Y * (up / dist)
        } else {
            radial
        };
        (
            radial * self.major + out * self.minor,
            out,
            dist - self.minor,
        )
    }
}

impl Torus {
    /// The torus-frame point of the world point `p`, in f64 (the world→torus transform of
    /// the exact path: translate, then rotate the axis onto +y).
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn point_to_local_f64(&self, p: DVec3) -> Result<DVec3, NonFinitePoint> {
        if !p.is_finite() {
            return Err(NonFinitePoint(p));
        }
        Ok(self.to_local_rotation_f64() * (p - self.center_f64()))
    }

    /// The world point of the torus-frame point `x` (f64).
    #[must_use]
    pub fn point_to_world_f64(&self, x: DVec3) -> DVec3 {
        self.to_local_rotation_f64().transpose() * x + self.center_f64()
    }

    /// Whether `p` lies in the solid torus (`D ≤ r`, the surface included).
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn contains(&self, p: DVec3) -> Result<bool, NonFinitePoint> {
        Ok(self.signed_distance(p)? <= 0.0)
    }

    /// The signed distance from `p` to the surface, `D − r`: negative inside.
    ///
    /// ```
    /// use glam::DVec3;
    /// use torus_cull::Torus;
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// assert_eq!(torus.signed_distance(DVec3::new(4.0, 0.0, 0.0))?, -1.0); // the core
    /// assert_eq!(torus.signed_distance(DVec3::new(7.0, 0.0, 0.0))?, 2.0);
    /// assert_eq!(torus.signed_distance(DVec3::new(0.0, 3.0, 0.0))?, 4.0); // on the axis
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn signed_distance(&self, p: DVec3) -> Result<f64, NonFinitePoint> {
        Ok(self.tube().project(self.point_to_local_f64(p)?).2)
    }

    /// The closest surface point to `p`, its outward normal and `p`'s signed distance
    /// (module docs: a choice on the axis and on the core circle, never a NaN).
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn project_point(&self, p: DVec3) -> Result<SurfaceProjection, NonFinitePoint> {
        let (point, normal, signed_distance) = self.tube().project(self.point_to_local_f64(p)?);
        let rot = self.to_local_rotation_f64().transpose();
        Ok(SurfaceProjection {
            point: self.point_to_world_f64(point),
            normal: rot * normal,
            signed_distance,
        })
    }

    /// The surface point at tube angle θ (0 on the outer equator, π/2 on the top circle,
    /// toward +axis) and angle φ about the axis (0 on the torus frame's x axis, growing
    /// right-handed about the axis, toward its −z axis: the one φ of every shape,
    /// docs/math.md §1): `((R + r cos θ) cos φ, r sin θ, −(R + r cos θ) sin φ)` in the
    /// torus frame, world space. The inverse of [`Torus::surface_coords`].
    #[must_use]
    pub fn point_at(&self, theta: f64, phi: f64) -> DVec3 {
        let (big, small) = (self.major_radius_f64(), self.minor_radius_f64());
        let rho = big + small * theta.cos();
        self.point_to_world_f64(DVec3::new(
            rho * phi.cos(),
            small * theta.sin(),
            -rho * phi.sin(),
        ))
    }

    /// The surface coordinates `(θ, φ)`, each in `(−π, π]`, of the closest surface point to
    /// `p` (as [`Torus::point_at`] names them; θ = 0 on the core circle, φ = 0 on the axis:
    /// the choices of the module docs; φ = atan2(−z, x)). A texture's `(u, v)` is
    /// `(φ + π, θ + π)/2π`.
    ///
    /// # Errors
    ///
    /// [`NonFinitePoint`] for a NaN or infinite coordinate.
    pub fn surface_coords(&self, p: DVec3) -> Result<(f64, f64), NonFinitePoint> {
        let x = self.point_to_local_f64(p)?;
        let rho = x.x.hypot(x.z);
        // `-x.z`, not `x.z`: φ grows right-handed about +y, from +x toward −z.
        let phi = if rho > 0.0 { (-x.z).atan2(x.x) } else { 0.0 };
        let (off, y) = (rho - self.major_radius_f64(), x.y);
        let theta = if off == 0.0 && y == 0.0 {
            0.0
        } else {
            y.atan2(off)
        };
        // atan2 gives [−π, π]: −π is π.
        let wrap = |a: f64| if a == -PI { PI } else { a };
        Ok((wrap(theta), wrap(phi)))
    }

    /// The smallest sphere holding the torus: its centre and radius R + r.
    #[must_use]
    pub fn bounding_sphere(&self) -> (DVec3, f64) {
        (
            self.center_f64(),
            self.major_radius_f64() + self.minor_radius_f64(),
        )
    }

    /// The surface's area, 4π²·R·r.
    #[must_use]
    pub fn area(&self) -> f64 {
        4.0 * PI * PI * self.major_radius_f64() * self.minor_radius_f64()
    }

    /// The solid's volume, 2π²·R·r².
    #[must_use]
    pub fn volume(&self) -> f64 {
        let r = self.minor_radius_f64();
        2.0 * PI * PI * self.major_radius_f64() * r * r
    }
}
