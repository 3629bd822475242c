//! The pipe bend: pose, radii, segment, validation, and the solid's inside test.

use super::wedge::Wedge;
use crate::{Torus, TorusError};
use glam::DVec3;
use std::f64::consts::TAU;
use std::fmt;

/// The thinnest wall a pipe bend takes, × (R + r_max): `r_max − r_min ≥ MIN_WALL_REL·(R +
/// r_max)` for a bend with a bore.
///
/// Why a floor, and why relative to S = R + r_max: every length the solid's answers and
/// their checks resolve scales with S. A marked origin's face is found within
/// 10⁻⁶·S (at most a quarter of the wall, so the other face of the wall is never the
/// origin's), the bend oracle marks faces within 10⁻⁸·S, holds answers to 10⁻⁹·S and its
/// own error to 10⁻¹¹·S. A wall of 10⁻⁷·S is ten times the oracle's reach and a hundred
/// times its tolerance, and the thin-wall tests (`tests/oracle/thin_wall.rs`) check every
/// wall from 10⁻² down to it; a thinner wall is one no test tells apart from a sheet.
/// At R/r_max = 4 that is r_min/r_max ≤ 1 − 5·10⁻⁷, at R/r_max = 1000 ≤ 1 − 1.001·10⁻⁴.
pub const MIN_WALL_REL: f64 = 1e-7;

/// A face of a pipe bend's boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BendFace {
    /// The outer torus, `D = r_max`.
    Outer,
    /// The bore's torus, `D = r_min` (concave: its outward normal points to the core).
    Inner,
    /// The end cap in the half-plane φ = φ₀.
    StartCap,
    /// The end cap in the half-plane φ = φ₀ + Δφ.
    EndCap,
}

/// A pipe bend in the world (module docs of [`crate::bend`]): centre, unit axis, the
/// direction of φ = 0, major radius R (`major_radius`, Geant4's Rtor), tube radius
/// r_max (`tube_radius`, Rmax), bore radius r_min (`bore_radius`, Rmin; 0 for none) and
/// the segment `[start_phi, start_phi + delta_phi]` (SPhi, DPhi; Δφ = 2π for the whole
/// ring). φ grows from `phi_zero` toward `axis × phi_zero`, right-handed about the axis
/// (Geant4's φ about z from x toward y).
///
/// ```
/// use glam::DVec3;
/// use torus_cull::DRay;
/// use torus_cull::bend::{BendFace, PipeBend};
/// // VecGeom's test solid: R = 30, r_min = 5, r_max = 10, φ from π/4 over 3π/4.
/// let pi = std::f64::consts::PI;
/// let bend = PipeBend::canonical(30.0, 5.0, 10.0, pi / 4.0, 3.0 * pi / 4.0)?;
/// // φ grows from +x toward y × x = −z (right-handed about +y). Down onto the bend at
/// // φ = π/2 (x = 0, z = −30): the outer face at y = 10.
/// let down = DRay::new(DVec3::new(0.0, 50.0, -30.0), DVec3::NEG_Y)?;
/// let hit = bend.intersect(&down).unwrap();
/// assert_eq!(hit.face, BendFace::Outer);
/// assert!((hit.t - 40.0).abs() < 1e-9);
/// // At φ = 0 (outside the segment) the same ray passes through the cut-away arc.
/// assert!(bend.intersect(&DRay::new(DVec3::new(30.0, 50.0, 0.0), DVec3::NEG_Y)?).is_none());
/// // Along the ring's direction of growing φ at φ = π/4, 7 from the core: the start cap.
/// let s = DVec3::new(1.0, 0.0, -1.0).normalize();
/// let t = DVec3::new(-1.0, 0.0, -1.0).normalize();
/// let into = DRay::new(s * 37.0 - t * 5.0, t)?;
/// let hit = bend.intersect(&into).unwrap();
/// assert_eq!(hit.face, BendFace::StartCap);
/// assert!((hit.t - 5.0).abs() < 1e-9 && hit.front_face);
/// assert!((hit.normal + t).length() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PipeBend {
    /// The outer torus (R, r_max) in the bend's pose.
    pub(super) outer: Torus,
    /// The bore's torus (R, r_min), or `None` for a solid tube.
    pub(super) inner: Option<Torus>,
    /// The segment in the outer torus's frame, or `None` for the whole ring.
    pub(super) wedge: Option<Wedge>,
    start_phi: f64,
    delta_phi: f64,
}

/// Why a pipe bend was refused.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum BendError {
    /// `bore_radius` is not finite, negative, or not below `tube_radius`.
    Bore {
        /// r_min as given.
        bore_radius: f64,
        /// r_max as given.
        tube_radius: f64,
    },
    /// The wall `r_max − r_min` is thinner than [`MIN_WALL_REL`]`·(R + r_max)`, the
    /// thinnest wall the tests hold the solid to (docs/bend.md, "Thin walls").
    ThinWall {
        /// r_min as given.
        bore_radius: f64,
        /// r_max as given.
        tube_radius: f64,
        /// The largest r_min accepted: `r_max − MIN_WALL_REL·(R + r_max)`.
        max_bore_radius: f64,
    },
    /// `start_phi` is not finite, or `delta_phi` is not in `(0, 2π]`.
    Segment {
        /// The parameter's name.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// `phi_zero` is zero, not finite, or along the axis.
    PhiZero(DVec3),
    /// The outer or the bore's torus, as [`crate::Torus`] refuses it (its name says which
    /// radius: `minor_radius` is r_max for the outer torus, r_min for the bore).
    Torus {
        /// `outer` or `bore`.
        which: &'static str,
        /// The torus's error.
        error: TorusError,
    },
    /// A path that takes a [`crate::Torus`] was asked for a bend with a bore or a segment.
    NotWhole,
}

impl fmt::Display for BendError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BendError::Bore {
                bore_radius,
                tube_radius,
            } => write!(
                f,
                "bore_radius = {bore_radius} is invalid (allowed: 0 <= bore_radius < tube_radius = {tube_radius})"
            ),
            BendError::ThinWall {
                bore_radius,
                tube_radius,
                max_bore_radius,
            } => write!(
                f,
                "bore_radius = {bore_radius} leaves a wall tube_radius - bore_radius = {} thinner \
                 than {MIN_WALL_REL:e}*(major_radius + tube_radius) (allowed: bore_radius = 0, \
                 or 0 < bore_radius <= {max_bore_radius})",
                tube_radius - bore_radius
            ),
            BendError::Segment { name, value } => write!(
                f,
                "{name} = {value} is invalid (start_phi finite; 0 < delta_phi <= 2*pi)"
            ),
            BendError::PhiZero(v) => write!(
                f,
                "phi_zero = {v} must be finite, non-zero and not along the axis"
            ),
            BendError::Torus { which, error } => write!(f, "the {which} torus: {error}"),
            BendError::NotWhole => write!(
                f,
                "a pipe bend with a bore or a segment is not a torus: this path (SIMD lanes, \
                 certified f32, GPU) takes whole tori only"
            ),
        }
    }
}

impl std::error::Error for BendError {}

impl PipeBend {
    /// A pipe bend from f64 geometry (type docs). `bore_radius = 0` and
    /// `delta_phi = 2π` give the whole torus.
    #[allow(clippy::too_many_arguments)]
    pub fn new_f64(
        center: DVec3,
        axis: DVec3,
        phi_zero: DVec3,
        major_radius: f64,
        bore_radius: f64,
        tube_radius: f64,
        start_phi: f64,
        delta_phi: f64,
    ) -> Result<PipeBend, BendError> {
        let outer = Torus::new_f64(center, axis, major_radius, tube_radius).map_err(|error| {
            BendError::Torus {
                which: "outer",
                error,
            }
        })?;
        if !(bore_radius.is_finite() && bore_radius >= 0.0 && bore_radius < tube_radius) {
            return Err(BendError::Bore {
                bore_radius,
                tube_radius,
            });
        }
        let max_bore_radius = tube_radius - MIN_WALL_REL * (major_radius + tube_radius);
        // The floor less a relative 10⁻⁶: the wall's difference and a caller's own
        // `r_max·(1 − MIN_WALL_REL·(ν + 1))` round, and the bound itself must pass.
        let floor = MIN_WALL_REL * (major_radius + tube_radius) * (1.0 - 1e-6);
        if bore_radius > 0.0 && tube_radius - bore_radius < floor {
            return Err(BendError::ThinWall {
                bore_radius,
                tube_radius,
                max_bore_radius,
            });
        }
        let inner = if bore_radius > 0.0 {
            Some(
                Torus::new_f64(center, axis, major_radius, bore_radius).map_err(|error| {
                    BendError::Torus {
                        which: "bore",
                        error,
                    }
                })?,
            )
        } else {
            None
        };
        if !start_phi.is_finite() {
            return Err(BendError::Segment {
                name: "start_phi",
                value: start_phi,
            });
        }
        if !(delta_phi > 0.0 && delta_phi <= TAU) {
            return Err(BendError::Segment {
                name: "delta_phi",
                value: delta_phi,
            });
        }
        let unit_axis = outer.axis_f64();
        let across = phi_zero - unit_axis * phi_zero.dot(unit_axis);
        if !(phi_zero.is_finite() && across.length() > 1e-9 * phi_zero.length()) {
            return Err(BendError::PhiZero(phi_zero));
        }
        let wedge = (delta_phi < TAU).then(|| {
            let rot = outer.to_local_rotation_f64();
            let e0 = (rot * across.normalize()).with_y(0.0).normalize();
            let e1 = DVec3::Y.cross(e0);
            Wedge::new(e0, e1, start_phi, delta_phi)
        });
        Ok(PipeBend {
            outer,
            inner,
            wedge,
            start_phi,
            delta_phi,
        })
    }

    /// The bend in its own frame: centre 0, axis +y, φ = 0 along +x (φ grows toward −z,
    /// which is `y × x`).
    pub fn canonical(
        major_radius: f64,
        bore_radius: f64,
        tube_radius: f64,
        start_phi: f64,
        delta_phi: f64,
    ) -> Result<PipeBend, BendError> {
        PipeBend::new_f64(
            DVec3::ZERO,
            DVec3::Y,
            DVec3::X,
            major_radius,
            bore_radius,
            tube_radius,
            start_phi,
            delta_phi,
        )
    }

    /// The outer torus (R, r_max): what the torus culls bound.
    #[inline]
    #[must_use]
    pub const fn outer(&self) -> &Torus {
        &self.outer
    }

    /// R.
    #[inline]
    #[must_use]
    pub const fn major_radius_f64(&self) -> f64 {
        self.outer.major_radius_f64()
    }

    /// r_max.
    #[inline]
    #[must_use]
    pub const fn tube_radius_f64(&self) -> f64 {
        self.outer.minor_radius_f64()
    }

    /// r_min (0 for a solid tube).
    #[inline]
    #[must_use]
    pub fn bore_radius_f64(&self) -> f64 {
        self.inner.map_or(0.0, |t| t.minor_radius_f64())
    }

    /// φ₀.
    #[inline]
    #[must_use]
    pub const fn start_phi(&self) -> f64 {
        self.start_phi
    }

    /// Δφ.
    #[inline]
    #[must_use]
    pub const fn delta_phi(&self) -> f64 {
        self.delta_phi
    }

    /// The outer torus (R, r_max), whole: what the culls and the lanes see of the solid.
    #[inline]
    pub(crate) fn outer_torus(&self) -> &Torus {
        &self.outer
    }

    /// The whole torus's [`Torus`], for the paths that take one.
    ///
    /// # Errors
    ///
    /// [`BendError::NotWhole`] for a bend with a bore or a segment.
    pub fn as_torus(&self) -> Result<&Torus, BendError> {
        if self.inner.is_none() && self.wedge.is_none() {
            Ok(&self.outer)
        } else {
            Err(BendError::NotWhole)
        }
    }

    /// Whether the world point `p` lies inside the solid (boundary included).
    #[must_use]
    pub fn contains(&self, p: DVec3) -> bool {
        self.contains_local(self.local_point(p), false)
    }

    /// The world point in the outer torus's frame.
    #[inline]
    pub(super) fn local_point(&self, p: DVec3) -> DVec3 {
        self.outer.to_local_rotation_f64() * (p - self.outer.center_f64())
    }

    /// The torus-frame point `x` lies in the solid: `r_min ≤ D ≤ r_max` and φ in the
    /// segment; `strict` leaves the boundary out (the interval test of `crossings`).
    pub(super) fn contains_local(&self, x: DVec3, strict: bool) -> bool {
        let d2 = (x.x.hypot(x.z) - self.major_radius_f64()).powi(2) + x.y * x.y;
        let (lo, hi) = (
            self.bore_radius_f64().powi(2),
            self.tube_radius_f64().powi(2),
        );
        // With no bore the core circle itself (D = 0) is interior: `d2 > 0` would drop a
        // ray whose interval midpoint lies on it (a ray down through the core circle).
        let radial = if strict {
            (self.inner.is_none() || d2 > lo) && d2 < hi
        } else {
            d2 >= lo && d2 <= hi
        };
        radial && self.wedge.is_none_or(|w| w.contains(x, strict))
    }
}
