//! A torus placed by an instance transform (glam's `DAffine3` / `Affine3A`): a rigid
//! motion with a uniform scale, anything else refused.

use super::{Torus, TorusError};
use glam::{DMat3, DVec3, Vec3};

impl Torus {
    /// The torus in its own frame (centre 0, axis +y, radii R = `major_radius`, r =
    /// `minor_radius`) placed by an instance transform: its centre is the translation, its
    /// axis the image of +y, its radii scaled by the transform's scale. Only a rigid motion
    /// with a uniform scale keeps a torus a torus; any other linear part (shear, a
    /// non-uniform scale, a reflection) is refused.
    ///
    /// ```
    /// use glam::{DAffine3, DQuat, DVec3};
    /// use torus_cull::Torus;
    /// let placed = DAffine3::from_scale_rotation_translation(
    ///     DVec3::splat(2.0),
    ///     DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2),
    ///     DVec3::new(1.0, 2.0, 3.0),
    /// );
    /// let torus = Torus::from_affine(placed, 4.0, 1.0)?;
    /// assert_eq!(torus.major_radius_f64(), 8.0);
    /// assert!((torus.axis_f64() - DVec3::Z).length() < 1e-15);
    /// let squashed = DAffine3::from_scale(DVec3::new(1.0, 0.5, 1.0));
    /// assert!(Torus::from_affine(squashed, 4.0, 1.0).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`TorusError::NotSimilarity`] for a transform that is not a rotation with a uniform
    /// positive scale (to 10⁻⁹ relative), or the errors of [`Torus::new_f64`].
    pub fn from_affine(
        transform: glam::DAffine3,
        major_radius: f64,
        minor_radius: f64,
    ) -> Result<Torus, TorusError> {
        let (rigid, scale) = similarity(transform.matrix3, 1e-9)?;
        Torus::new_f64(
            transform.translation,
            rigid * DVec3::Y,
            major_radius * scale,
            minor_radius * scale,
        )
    }

    /// [`Torus::from_affine`] from glam's f32 `Affine3A`, widened exactly.
    ///
    /// # Errors
    ///
    /// As [`Torus::from_affine`].
    pub fn from_affine_f32(
        transform: glam::Affine3A,
        major_radius: f32,
        minor_radius: f32,
    ) -> Result<Torus, TorusError> {
        let m = glam::DMat3::from_cols(
            transform.matrix3.x_axis.as_dvec3(),
            transform.matrix3.y_axis.as_dvec3(),
            transform.matrix3.z_axis.as_dvec3(),
        );
        // f32 entries are off by 2⁻²⁴ relative: allow that, not more.
        let (rigid, scale) = similarity(m, 1e-6)?;
        let unit = rigid * DVec3::Y;
        Torus::new(
            Vec3::from(transform.translation),
            unit.as_vec3(),
            (f64::from(major_radius) * scale) as f32,
            (f64::from(minor_radius) * scale) as f32,
        )
    }
}

/// The linear part `m` of an instance transform as a rotation and a uniform positive
/// scale, `m = scale·rigid`, each entry of `rigidᵀ·rigid − I` within `tolerance`.
fn similarity(m: DMat3, tolerance: f64) -> Result<(DMat3, f64), TorusError> {
    let scale = m.determinant().cbrt();
    let rigid = m * (1.0 / scale);
    let off = (rigid.transpose() * rigid - DMat3::IDENTITY).to_cols_array();
    if scale.is_finite() && scale > 0.0 && off.iter().all(|e| e.abs() <= tolerance) {
        Ok((rigid, scale))
    } else {
        Err(TorusError::NotSimilarity)
    }
}
