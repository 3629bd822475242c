//! The ray type shared by the culls, the exact intersection and the oracle.

use glam::{DVec3, Vec3};
use std::fmt;

/// A ray `o + t·d` with `t ∈ [t_min, t_max]`, in f32 as a renderer shoots it.
///
/// The direction need not be unit length; every `t` in this crate is in units of the
/// given direction. The constructors reject zero, NaN and infinite directions, so every
/// `Ray` is a valid line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    origin: Vec3,
    dir: Vec3,
    t_min: f32,
    t_max: f32,
}

/// Why a ray was refused.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum RayError {
    /// The origin has a NaN or infinite component.
    NonFiniteOrigin(Vec3),
    /// The direction has a NaN or infinite component.
    NonFiniteDirection(Vec3),
    /// The direction is the zero vector (or so small that its squared length underflows).
    ZeroDirection(Vec3),
    /// The direction is so long that its squared length overflows f32.
    HugeDirection(Vec3),
    /// `t_min` must be finite, `t_max` may be +∞, and `t_min ≤ t_max`.
    BadRange {
        /// The lower end given.
        t_min: f32,
        /// The upper end given.
        t_max: f32,
    },
}

impl fmt::Display for RayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RayError::NonFiniteOrigin(o) => write!(f, "ray origin {o} is not finite"),
            RayError::NonFiniteDirection(d) => write!(f, "ray direction {d} is not finite"),
            RayError::ZeroDirection(d) if *d == Vec3::ZERO => {
                write!(
                    f,
                    "ray direction {d} is zero (|d|² must be a normal f32 > 0)"
                )
            }
            RayError::ZeroDirection(d) => write!(
                f,
                "ray direction [{:e}, {:e}, {:e}] is too short: |d|² = {:e} is below the \
                 smallest normal f32 {:e} (scale it up: only its direction matters)",
                d.x,
                d.y,
                d.z,
                (d.as_dvec3()).length_squared(),
                f32::MIN_POSITIVE
            ),
            RayError::HugeDirection(d) => write!(
                f,
                "ray direction {d} is too long (|d|² must be finite in f32: |d| < 1.8e19)"
            ),
            RayError::BadRange { t_min, t_max } => write!(
                f,
                "ray range [{t_min}, {t_max}] is invalid (need finite t_min ≤ t_max)"
            ),
        }
    }
}

impl std::error::Error for RayError {}

impl Ray {
    /// A ray over `t ∈ [0, +∞)`.
    ///
    /// ```
    /// use torus_cull::Ray;
    /// use glam::Vec3;
    /// assert!(Ray::new(Vec3::ZERO, Vec3::X).is_ok());
    /// assert!(Ray::new(Vec3::ZERO, Vec3::ZERO).is_err());
    /// assert!(Ray::new(Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 1.0)).is_err());
    /// assert!(Ray::new(Vec3::ZERO, Vec3::splat(1e20)).is_err()); // |d|² overflows
    /// ```
    pub fn new(origin: Vec3, dir: Vec3) -> Result<Ray, RayError> {
        Ray::with_range(origin, dir, 0.0, f32::INFINITY)
    }

    /// A ray over `t ∈ [t_min, t_max]`.
    pub fn with_range(origin: Vec3, dir: Vec3, t_min: f32, t_max: f32) -> Result<Ray, RayError> {
        if !origin.is_finite() {
            return Err(RayError::NonFiniteOrigin(origin));
        }
        if !dir.is_finite() {
            return Err(RayError::NonFiniteDirection(dir));
        }
        // The culls divide by |d|²: below the smallest normal f32 it would overflow or lose
        // bits, and an infinite |d|² would make every 1/|d|² zero.
        let len_sq = dir.length_squared();
        if len_sq < f32::MIN_POSITIVE {
            return Err(RayError::ZeroDirection(dir));
        }
        if !len_sq.is_finite() {
            return Err(RayError::HugeDirection(dir));
        }
        if !t_min.is_finite() || t_max.is_nan() || t_min > t_max {
            return Err(RayError::BadRange { t_min, t_max });
        }
        Ok(Ray {
            origin,
            dir,
            t_min,
            t_max,
        })
    }

    /// The origin `o`.
    #[inline]
    pub fn origin(&self) -> Vec3 {
        self.origin
    }

    /// The direction `d` (as given; not normalized).
    #[inline]
    pub fn dir(&self) -> Vec3 {
        self.dir
    }

    /// The lower end of the parameter range.
    #[inline]
    pub fn t_min(&self) -> f32 {
        self.t_min
    }

    /// The upper end of the parameter range (may be +∞).
    #[inline]
    pub fn t_max(&self) -> f32 {
        self.t_max
    }

    /// The same ray with its range cut to end at `t_max` (never widened, never below
    /// `t_min`): what a traversal passes on once a closer hit is known.
    #[inline]
    pub fn with_t_max(&self, t_max: f32) -> Ray {
        Ray {
            t_max: t_max.min(self.t_max).max(self.t_min),
            ..*self
        }
    }

    /// The point `o + t·d`.
    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + self.dir * t
    }
}

/// A ray `o + t·d` with `t ∈ [t_min, t_max]` in f64, for callers whose geometry is f64
/// (particle transport, CAD, another project's test suite).
///
/// [`crate::intersect()`] takes it without rounding anything to f32 and answers in f64
/// ([`crate::DHit`]); the culls see its line rounded to f32 (direction normalized
/// first), which their margin covers. The constructors reject zero, NaN and infinite
/// directions, so every `DRay` is a valid line.
///
/// ```
/// use glam::DVec3;
/// use torus_cull::DRay;
/// assert!(DRay::new(DVec3::ZERO, DVec3::X).is_ok());
/// assert!(DRay::new(DVec3::ZERO, DVec3::ZERO).is_err());
/// assert!(DRay::new(DVec3::ZERO, DVec3::splat(1e300)).is_err()); // |d|² overflows
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DRay {
    origin: DVec3,
    dir: DVec3,
    t_min: f64,
    t_max: f64,
}

/// Why a [`DRay`] was refused: [`RayError`]'s cases, in f64.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum DRayError {
    /// The origin has a NaN or infinite component.
    NonFiniteOrigin(DVec3),
    /// The direction has a NaN or infinite component.
    NonFiniteDirection(DVec3),
    /// |d|² is below the smallest normal f64 (the zero vector included).
    ZeroDirection(DVec3),
    /// |d|² overflows f64.
    HugeDirection(DVec3),
    /// `t_min` must be finite, `t_max` may be +∞, and `t_min ≤ t_max`.
    BadRange {
        /// The lower end given.
        t_min: f64,
        /// The upper end given.
        t_max: f64,
    },
}

impl fmt::Display for DRayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DRayError::NonFiniteOrigin(o) => write!(f, "ray origin {o} is not finite"),
            DRayError::NonFiniteDirection(d) => write!(f, "ray direction {d} is not finite"),
            DRayError::ZeroDirection(d) if *d == DVec3::ZERO => {
                write!(
                    f,
                    "ray direction {d} is zero (|d|² must be a normal f64 > 0)"
                )
            }
            DRayError::ZeroDirection(d) => write!(
                f,
                "ray direction [{:e}, {:e}, {:e}] is too short: |d|² = {:e} is below the \
                 smallest normal f64 {:e} (scale it up: only its direction matters)",
                d.x,
                d.y,
                d.z,
                d.length_squared(),
                f64::MIN_POSITIVE
            ),
            DRayError::HugeDirection(d) => {
                write!(f, "ray direction {d} is too long (|d|² overflows f64)")
            }
            DRayError::BadRange { t_min, t_max } => write!(
                f,
                "ray range [{t_min}, {t_max}] is invalid (t_min finite, t_min ≤ t_max)"
            ),
        }
    }
}

impl std::error::Error for DRayError {}

impl DRay {
    /// A ray over `t ∈ [0, +∞)`.
    pub fn new(origin: DVec3, dir: DVec3) -> Result<DRay, DRayError> {
        DRay::with_range(origin, dir, 0.0, f64::INFINITY)
    }

    /// A ray over `t ∈ [t_min, t_max]`.
    pub fn with_range(
        origin: DVec3,
        dir: DVec3,
        t_min: f64,
        t_max: f64,
    ) -> Result<DRay, DRayError> {
        if !origin.is_finite() {
            return Err(DRayError::NonFiniteOrigin(origin));
        }
        if !dir.is_finite() {
            return Err(DRayError::NonFiniteDirection(dir));
        }
        let len_sq = dir.length_squared();
        if len_sq < f64::MIN_POSITIVE {
            return Err(DRayError::ZeroDirection(dir));
        }
        if !len_sq.is_finite() {
            return Err(DRayError::HugeDirection(dir));
        }
        if !t_min.is_finite() || t_max.is_nan() || t_min > t_max {
            return Err(DRayError::BadRange { t_min, t_max });
        }
        Ok(DRay {
            origin,
            dir,
            t_min,
            t_max,
        })
    }

    /// The origin `o`.
    #[inline]
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The direction `d` (as given; not normalized).
    #[inline]
    pub fn dir(&self) -> DVec3 {
        self.dir
    }

    /// The lower end of the parameter range.
    #[inline]
    pub fn t_min(&self) -> f64 {
        self.t_min
    }

    /// The upper end of the parameter range (may be +∞).
    #[inline]
    pub fn t_max(&self) -> f64 {
        self.t_max
    }
}

impl From<Ray> for DRay {
    /// The same ray, widened exactly.
    fn from(ray: Ray) -> DRay {
        DRay {
            origin: ray.origin().as_dvec3(),
            dir: ray.dir().as_dvec3(),
            t_min: f64::from(ray.t_min()),
            t_max: f64::from(ray.t_max()),
        }
    }
}
