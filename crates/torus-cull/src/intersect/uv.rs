//! Texturing a hit: its surface coordinates (θ, φ) and the surface's unit tangents there.
//!
//! The coordinates are [`Torus::point_at`]'s and [`Torus::surface_coords`]': θ around the
//! tube (0 on the outer equator, π/2 on the top circle, toward +axis), φ around the axis
//! (0 on the torus frame's x axis, growing right-handed about the axis, toward its −z axis:
//! the one φ of every shape, docs/math.md §1), each in `(−π, π]`. In the torus frame the
//! surface is `P(θ, φ) = ((R + r cos θ) cos φ, r sin θ, −(R + r cos θ) sin φ)`.

use super::Hit;
use crate::{Precision, Torus};
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// A surface point's coordinates (module docs): θ around the tube, φ around the axis,
/// each in `(−π, π]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceCoords {
    /// The angle around the tube: 0 on the outer equator, π/2 on the top circle.
    pub theta: f64,
    /// The angle around the axis: 0 on the torus frame's x axis, growing right-handed
    /// about the axis (toward its −z axis).
    pub phi: f64,
}

impl SurfaceCoords {
    /// The texture coordinates `(u, v) = ((φ + π)/2π, (θ + π)/2π)`, each in `(0, 1]`: `u`
    /// along the ring, `v` around the tube (`v = 1/2` on the outer equator).
    #[must_use]
    pub fn texture_uv(&self) -> DVec2 {
        DVec2::new((self.phi + PI) / TAU, (self.theta + PI) / TAU)
    }
}

/// The surface's unit tangents at a point, world space: `along_ring` is `∂P/∂φ` (length
/// R + r cos θ > 0 for a ring torus), `around_tube` is `∂P/∂θ` (length r), both
/// normalized. They are orthogonal, and `along_ring × around_tube` is the outward normal:
/// `(along_ring, around_tube, normal)` is a right-handed frame, a normal map's tangent,
/// bitangent and normal (N = T × B) with u along φ and v along θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceTangents {
    /// `∂P/∂φ / |∂P/∂φ|`: along the ring, toward growing φ.
    pub along_ring: DVec3,
    /// `∂P/∂θ / |∂P/∂θ|`: around the tube, toward growing θ.
    pub around_tube: DVec3,
}

/// `atan2` with −π taken as π, so an angle lies in `(−π, π]`.
fn wrap(a: f64) -> f64 {
    if a == -PI { PI } else { a }
}

impl Torus {
    /// The surface coordinates of a hit on this torus (module docs), for texturing: φ
    /// from the hit point (`atan2(−z, x)` in the torus frame, well conditioned since
    /// ρ ≥ R − r there), θ from the hit's normal (`atan2(n·y, n·ρ̂)`, whose rounding is
    /// the normal's alone, where the point's would be scaled by (R + r)/r). `Hit` stays as
    /// small as it is: the coordinates are asked for, not carried.
    ///
    /// A hand-made hit on the axis gets φ = 0 and one with a zero normal θ = 0, as
    /// [`Torus::surface_coords`] chooses; a non-finite one gives NaN coordinates.
    ///
    /// ```
    /// use glam::DVec3;
    /// use torus_cull::{DRay, Torus, intersect};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// // Down onto the top of the tube at φ = π/2 (the −z side: φ grows right-handed
    /// // about +y): θ = π/2.
    /// let hit = intersect(&torus, &DRay::new(DVec3::new(0.0, 10.0, -4.0), DVec3::NEG_Y)?).unwrap();
    /// let uv = torus.hit_uv(&hit);
    /// assert!((uv.theta - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    /// assert!((uv.phi - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    /// assert!((torus.point_at(uv.theta, uv.phi) - hit.point).length() < 1e-12);
    /// let frame = torus.tangents(uv);
    /// assert!((frame.along_ring - DVec3::NEG_X).length() < 1e-12);
    /// assert!((frame.around_tube - DVec3::Z).length() < 1e-12);
    /// // N = T × B: the outward normal, +y on the top circle.
    /// assert!((frame.along_ring.cross(frame.around_tube) - DVec3::Y).length() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn hit_uv<P: Precision>(&self, hit: &Hit<P>) -> SurfaceCoords {
        let rot = self.to_local_rotation_f64();
        let x = rot * (hit.point.to_dvec3() - self.center_f64());
        let n = rot * hit.normal.to_dvec3();
        let rho = x.x.hypot(x.z);
        let (phi, radial) = if rho > 0.0 {
            // `-x.z`: φ grows right-handed about +y, from +x toward −z.
            ((-x.z).atan2(x.x), DVec2::new(x.x / rho, x.z / rho))
        } else {
            (0.0, DVec2::X)
        };
        let across = n.x * radial.x + n.z * radial.y;
        let theta = if across == 0.0 && n.y == 0.0 {
            0.0
        } else {
            n.y.atan2(across)
        };
        SurfaceCoords {
            theta: wrap(theta),
            phi: wrap(phi),
        }
    }

    /// The unit tangents at the surface point `(θ, φ)` ([`SurfaceTangents`]), world
    /// space: in the torus frame `∂P/∂φ ∝ (−sin φ, 0, −cos φ)` and
    /// `∂P/∂θ ∝ (−sin θ cos φ, cos θ, sin θ sin φ)`, exact unit vectors but for rounding.
    #[must_use]
    pub fn tangents(&self, coords: SurfaceCoords) -> SurfaceTangents {
        let to_world = self.to_local_rotation_f64().transpose();
        let (st, ct) = coords.theta.sin_cos();
        let (sp, cp) = coords.phi.sin_cos();
        SurfaceTangents {
            along_ring: to_world * DVec3::new(-sp, 0.0, -cp),
            around_tube: to_world * DVec3::new(-st * cp, ct, st * sp),
        }
    }
}

#[cfg(test)]
mod tests;
