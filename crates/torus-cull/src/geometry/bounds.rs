//! The per-torus constants of the culls with their safety margin ([`CullBounds`]): owned
//! by the [`super::Torus`] they were computed for.

use crate::num::round::down;

/// The relative safety margin: `η = SAFETY_REL · (R + r)`, 2⁻¹² ≈ 2.4e-4.
///
/// About 4000 f32 ulps of the torus size: large enough to absorb the transform and
/// foot-point rounding for origins within 256·(R + r), small enough to cost nothing
/// measurable in rejection rate (it only keeps lines that pass within η of the surface).
pub const SAFETY_REL: f32 = 1.0 / 4096.0;

/// **The one table of the culls' per-torus constants.** Calls `$then! { rows }`: every
/// list of them comes from these rows: the fields of [`CullBounds`] (here), the lanes'
/// `LaneBounds` (`cull/kernel.rs`), the GPU's parameter rows and the WGSL `TcBounds`
/// (`gpu/bounds.rs`). A row is `field: type [forms], "doc";`, its value computed in
/// [`CullBounds::with_margin`] (the struct literal there fails to compile without it):
/// - `lanes`: an f32 the lane kernels read, `LaneBounds::field`;
/// - `lanes gpu name`: also packed for the kernel, in row order, read in WGSL as
///   `TcBounds::name` (three `vec4<f32>` of `TorusParams` hold at most 10 of them).
///
/// Adding a per-torus constant is a row here and its line in `with_margin`.
macro_rules! cull_bounds_table {
    ($then:ident) => {
        $then! {
            major_radius: f32 [lanes], "R.";
            minor_radius: f32 [lanes], "r (unpadded, for the paper-as-printed variants).";
            outer_safe: f32 [lanes gpu outer], "R + r_η.";
            outer_safe_sq: f32 [lanes gpu outer_sq], "(R + r_η)²: the padded bounding sphere.";
            minor_safe: f32 [lanes gpu minor],
                "r_η = r + η: the padded tube radius used by every timed cull.";
            minor_safe_sq: f32 [lanes gpu minor_sq], "r_η².";
            inner_safe: f32 [],
                "R − r_η: the padded hole radius (≥ 0 is not guaranteed for ν near 1).";
            inner_safe_sq: f32 [lanes gpu inner_sq], "(R − r_η)², or 0 when the padded hole closes.";
            ellipsoid_y_scale: f32 [lanes gpu y_scale],
                "s = √(ν_η + 1) with ν_η = R/r_η, rounded down: scaling y by s turns the padded \
                 outer ellipsoid ρ² + (ν_η + 1)·y² ≤ (R + r_η)² into the sphere of radius R + r_η. \
                 Rounding s down only widens the ellipsoid.";
            ellipsoid_slab: f32 [lanes gpu slab], "s·r_η: the slab |y| ≤ r_η in the y-scaled coordinates.";
            hyperboloid_y_coef: f32 [lanes gpu hyperboloid],
                "(ν_η − 1)/(ν_η + 1) = (R − r_η)/(R + r_η), rounded down, or 0 when the padded \
                 hole closes: the inner hyperboloid ρ² − (ν_η − 1)·y² ≥ (R − r_η)² in the \
                 y-scaled coordinates is ρ² − this·y′² ≥ (R − r_η)². Rounding down only widens it.";
            inv_major_sq: f32 [lanes], "1/R²: the discriminant works at R = 1.";
            minor_rel_sq: f32 [lanes gpu minor_rel_sq], "(r_η/R)²: the padded tube radius at R = 1.";
            inv_major_sq_f64: f64 [], "1/R² in f64, for `discriminant_f64`.";
            minor_rel_sq_f64: f64 [],
                "(r_η/R)² in f64, from the f32 r_η and R, for `discriminant_f64`.";
        }
    };
}
pub(crate) use cull_bounds_table;

/// [`CullBounds`] from the rows of [`cull_bounds_table`].
macro_rules! define_cull_bounds {
    ($($field:ident: $ty:ty [$($forms:tt)*], $doc:literal;)*) => {
        /// Per-torus constants for the culls, in f32, with the safety margin folded in.
        ///
        /// Owned by its [`crate::Torus`] (computed once in [`crate::Torus::new`], read with
        /// [`crate::Torus::bounds`]): bounds exist only for a torus the constructor accepted, so a
        /// cull can be handed neither another torus's constants nor those of a torus without a
        /// hole (R ≤ r, where the padded hole test would reject lines that hit).
        ///
        /// ```compile_fail
        /// // Not constructible outside the crate: R < r has no bounds, only a `TorusError`.
        /// let bounds = torus_cull::CullBounds::new(1.0, 2.0);
        /// ```
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct CullBounds {
            $(#[doc = $doc] pub(crate) $field: $ty,)*
        }
    };
}
cull_bounds_table!(define_cull_bounds);

impl CullBounds {
    /// Bounds for R = `major_radius`, r = `minor_radius`: only [`crate::Torus::new`]'s
    /// validated radii come here (and the unit tests').
    pub(crate) fn new(major_radius: f32, minor_radius: f32) -> CullBounds {
        CullBounds::with_margin(
            major_radius,
            minor_radius,
            SAFETY_REL * (major_radius + minor_radius),
        )
    }

    /// Bounds for R, r with the tube padded by `eta` instead of
    /// [`SAFETY_REL`]·(R + r): the GPU kernel's culls, whose margin also covers the
    /// kernel's own line error (`crate::gpu`).
    pub(crate) fn with_margin(major_radius: f32, minor_radius: f32, eta: f32) -> CullBounds {
        let minor_safe = minor_radius + eta;
        let outer_safe = major_radius + minor_safe;
        let inner_safe = major_radius - minor_safe;
        let (big, small) = (f64::from(major_radius), f64::from(minor_safe));
        let hyperboloid_y_coef = if inner_safe > 0.0 {
            down((big - small) / (big + small))
        } else {
            0.0
        };
        let ellipsoid_y_scale = down(((big + small) / small).sqrt());
        CullBounds {
            major_radius,
            minor_radius,
            minor_safe,
            minor_safe_sq: minor_safe * minor_safe,
            outer_safe_sq: outer_safe * outer_safe,
            outer_safe,
            inner_safe,
            inner_safe_sq: if inner_safe > 0.0 {
                inner_safe * inner_safe
            } else {
                0.0
            },
            ellipsoid_y_scale,
            ellipsoid_slab: ellipsoid_y_scale * minor_safe,
            hyperboloid_y_coef,
            inv_major_sq: (1.0 / (big * big)) as f32,
            minor_rel_sq: ((small / big) * (small / big)) as f32,
            inv_major_sq_f64: 1.0 / (big * big),
            minor_rel_sq_f64: (small / big) * (small / big),
        }
    }

    /// r_η = r + η: the padded tube radius every timed cull tests against (η =
    /// [`SAFETY_REL`]·(R + r), rounded in f32), for code that checks a cull's margin.
    #[must_use]
    #[inline]
    pub const fn minor_safe(&self) -> f32 {
        self.minor_safe
    }

    /// R, the major radius these bounds were made for.
    #[must_use]
    #[inline]
    pub const fn major_radius(&self) -> f32 {
        self.major_radius
    }

    /// r, the minor (tube) radius these bounds were made for.
    #[must_use]
    #[inline]
    pub const fn minor_radius(&self) -> f32 {
        self.minor_radius
    }

    /// (R + r + η)²: the padded bounding sphere's squared radius.
    #[doc(hidden)]
    #[must_use]
    #[inline]
    pub const fn outer_safe_sq(&self) -> f32 {
        self.outer_safe_sq
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn margin_is_small_and_positive() {
        let b = CullBounds::new(2.0, 1.0);
        assert!(b.minor_safe > 1.0 && b.minor_safe < 1.001);
        assert!(b.outer_safe > 3.0 && b.outer_safe < 3.001);
        assert!(b.inner_safe < 1.0 && b.inner_safe > 0.999);
    }
}
