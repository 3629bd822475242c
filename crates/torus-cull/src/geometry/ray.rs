//! The ray type shared by the culls, the exact intersection and the oracle, written once
//! for both precisions: [`Ray`] (`Ray<Vec3>`, f32, as a renderer shoots it) and [`DRay`]
//! (`Ray<DVec3>`, f64 geometry), with their errors [`RayError`] and [`DRayError`].

use glam::{DVec3, Vec3};
use sealed::Scalar;
use std::fmt;
use std::ops::{Add, Mul};

/// A ray's precision, named by its vector type: [`Vec3`] (f32) or [`DVec3`] (f64).
///
/// Sealed: the two are the whole list. It is the parameter of [`Ray`], [`RayError`] and
/// [`crate::Hit`]; a renderer names it only to write code generic over both.
pub trait Precision:
    sealed::Internals
    + Copy
    + PartialEq
    + fmt::Debug
    + fmt::Display
    + Add<Output = Self>
    + Mul<<Self as Precision>::Float, Output = Self>
{
    /// The float of `t` and of the components: `f32` for [`Vec3`], `f64` for [`DVec3`].
    type Float: sealed::Scalar + fmt::Debug + fmt::Display + fmt::LowerExp;
}

impl Precision for Vec3 {
    type Float = f32;
}

impl Precision for DVec3 {
    type Float = f64;
}

pub(crate) mod sealed {
    use super::Precision;
    use glam::{DVec3, Vec3};

    /// What answers for a ray of either precision, one method each: [`Internals::line_of`]
    /// calls the one of the ray's precision. (The torus's culled line is one; the trait
    /// keeps this file from naming the torus, which imports it.)
    pub trait PerPrecision {
        /// The answer.
        type Out;
        /// For an f32 ray.
        fn of_f32(&self, ray: &super::Ray) -> Self::Out;
        /// For an f64 ray.
        fn of_f64(&self, ray: &super::DRay) -> Self::Out;
    }

    /// What the crate needs of a ray's float ([`Precision::Float`]), out of the docs.
    pub trait Scalar: Copy + PartialOrd {
        /// +∞, `t_max` of [`Ray::new`].
        const INFINITY: Self;
        /// 0, `t_min` of [`Ray::new`].
        const ZERO: Self;
        /// The smallest normal float: `|d|²` must reach it.
        const MIN_POSITIVE: Self;
        /// The machine epsilon (2⁻²³ for f32, 2⁻⁵² for f64), widened to f64: a spawn's
        /// tolerance for the rounding of a hit's `t`.
        const EPSILON_F64: f64;
        fn finite(self) -> bool;
        fn nan(self) -> bool;
        fn min(self, other: Self) -> Self;
        fn max(self, other: Self) -> Self;
        /// Widened to f64 (exactly).
        fn to_f64(self) -> f64;
        /// An f64 rounded to this float.
        fn from_f64(x: f64) -> Self;
    }

    macro_rules! scalar {
        ($f:ty) => {
            impl Scalar for $f {
                const INFINITY: $f = <$f>::INFINITY;
                const ZERO: $f = 0.0;
                const MIN_POSITIVE: $f = <$f>::MIN_POSITIVE;
                const EPSILON_F64: f64 = <$f>::EPSILON as f64;
                #[inline(always)]
                fn finite(self) -> bool {
                    self.is_finite()
                }
                #[inline(always)]
                fn nan(self) -> bool {
                    self.is_nan()
                }
                #[inline(always)]
                fn min(self, other: $f) -> $f {
                    <$f>::min(self, other)
                }
                #[inline(always)]
                fn max(self, other: $f) -> $f {
                    <$f>::max(self, other)
                }
                #[inline(always)]
                fn to_f64(self) -> f64 {
                    f64::from(self)
                }
                #[inline(always)]
                #[allow(clippy::cast_possible_truncation)]
                fn from_f64(x: f64) -> $f {
                    x as $f
                }
            }
        };
    }
    scalar!(f32);
    scalar!(f64);

    /// What the crate needs of a [`Precision`]'s vector, out of the docs.
    pub trait Internals: Copy {
        /// The zero vector.
        const ZERO: Self;
        /// "f32" or "f64", for the messages.
        const NAME: &'static str;
        /// Why a direction is too long, as [`super::RayError`]'s message says it.
        const HUGE: &'static str;
        /// What a range must be, as [`super::RayError`]'s message says it.
        const RANGE: &'static str;
        fn finite(self) -> bool;
        fn length_sq(self) -> Self::Float
        where
            Self: Precision;
        fn components(self) -> [Self::Float; 3]
        where
            Self: Precision;
        /// Widened to f64 (exactly).
        fn to_dvec3(self) -> DVec3;
        /// An f64 vector rounded to this precision.
        fn from_dvec3(v: DVec3) -> Self;
        /// Rays of this precision as f32 rays, if they are.
        fn as_f32_rays(rays: &[super::Ray<Self>]) -> Option<&[super::Ray]>
        where
            Self: Precision;
        /// `target`'s answer for a ray of this precision ([`PerPrecision`]).
        fn line_of<T: PerPrecision>(target: &T, ray: &super::Ray<Self>) -> T::Out
        where
            Self: Precision;
    }

    /// The items of [`Internals`] that are the glam vector's own, alike in both precisions.
    macro_rules! internals_of_glam {
        ($v:ident, $f:ty) => {
            const ZERO: $v = $v::ZERO;
            #[inline(always)]
            fn finite(self) -> bool {
                self.is_finite()
            }
            #[inline(always)]
            fn length_sq(self) -> $f {
                self.length_squared()
            }
            fn components(self) -> [$f; 3] {
                self.to_array()
            }
        };
    }

    impl Internals for Vec3 {
        internals_of_glam!(Vec3, f32);
        const NAME: &'static str = "f32";
        const HUGE: &'static str = "|d|² must be finite in f32: |d| < 1.8e19";
        const RANGE: &'static str = "need 0 ≤ t_min ≤ t_max, t_min finite, t_max not NaN";
        #[inline(always)]
        fn to_dvec3(self) -> DVec3 {
            self.as_dvec3()
        }
        #[inline(always)]
        fn from_dvec3(v: DVec3) -> Vec3 {
            v.as_vec3()
        }
        fn as_f32_rays(rays: &[super::Ray]) -> Option<&[super::Ray]> {
            Some(rays)
        }
        #[inline(always)]
        fn line_of<T: PerPrecision>(target: &T, ray: &super::Ray) -> T::Out {
            target.of_f32(ray)
        }
    }

    impl Internals for DVec3 {
        internals_of_glam!(DVec3, f64);
        const NAME: &'static str = "f64";
        const HUGE: &'static str = "|d|² overflows f64";
        const RANGE: &'static str = "need 0 ≤ t_min ≤ t_max, t_min finite, t_max not NaN";
        #[inline(always)]
        fn to_dvec3(self) -> DVec3 {
            self
        }
        #[inline(always)]
        fn from_dvec3(v: DVec3) -> DVec3 {
            v
        }
        fn as_f32_rays(_: &[super::DRay]) -> Option<&[super::Ray]> {
            None
        }
        #[inline]
        fn line_of<T: PerPrecision>(target: &T, ray: &super::DRay) -> T::Out {
            target.of_f64(ray)
        }
    }
}

/// A ray `o + t·d` with `t ∈ [t_min, t_max]`, in f32 as a renderer shoots it ([`Ray`],
/// the default `Ray<Vec3>`) or in f64 for callers whose geometry is f64 ([`DRay`],
/// `Ray<DVec3>`: particle transport, CAD, another project's test suite).
///
/// The direction need not be unit length; every `t` in this crate is in units of the
/// given direction. The constructors reject zero, NaN and infinite directions, so every
/// ray is a valid line.
///
/// [`crate::intersect()`] takes a [`DRay`] without rounding anything to f32 and answers
/// in f64 ([`crate::DHit`]); the culls see its line rounded to f32 (direction normalized
/// first), which their margin covers.
///
/// ```
/// use glam::DVec3;
/// use torus_cull::DRay;
/// assert!(DRay::new(DVec3::ZERO, DVec3::X).is_ok());
/// assert!(DRay::new(DVec3::ZERO, DVec3::ZERO).is_err());
/// assert!(DRay::new(DVec3::ZERO, DVec3::splat(1e300)).is_err()); // |d|² overflows
/// // `at` and `with_t_max` are written once, for both precisions.
/// let ray = DRay::new(DVec3::ZERO, DVec3::X * 2.0)?.with_t_max(3.0)?;
/// assert_eq!((ray.at(1.5), ray.t_max()), (DVec3::new(3.0, 0.0, 0.0), 3.0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray<P: Precision = Vec3> {
    origin: P,
    dir: P,
    t_min: P::Float,
    t_max: P::Float,
    /// The origin is a point of the surface (a hit's), whose own root `t = 0` the
    /// intersection divides out ([`Ray::from_surface`]).
    on_surface: bool,
}

/// How far from the surface, relative to R + r, the origin of a ray from a surface point
/// ([`Ray::from_surface`]) may lie: 10⁻⁴.
///
/// A surface point rounded to f32 is off by at most 2⁻²⁴·|p|, within this bound for
/// |p| up to about 1 600·(R + r) from the world origin (and [`crate::Torus::spawn`]
/// rounds a point it first moved onto the surface in f64). The semantics hold for any
/// small offset δ, which moves the other crossings by about δ/|cos θ| (docs/math.md §9);
/// past this bound a point is not a surface point to the lab, whose `eval` refuses it.
pub const ON_SURFACE_REL: f64 = 1e-4;

/// A ray in f64: [`Ray`] over [`DVec3`], whose hits ([`crate::DHit`]) are f64.
pub type DRay = Ray<DVec3>;

/// Why a ray was refused (`RayError<DVec3>`, [`DRayError`], for a [`DRay`]).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum RayError<P: Precision = Vec3> {
    /// The origin has a NaN or infinite component.
    NonFiniteOrigin(P),
    /// The direction has a NaN or infinite component.
    NonFiniteDirection(P),
    /// |d|² is below the smallest normal float of the ray's precision (the zero vector
    /// included).
    ZeroDirection(P),
    /// |d|² overflows the ray's float.
    HugeDirection(P),
    /// `t_min` must be finite and ≥ 0 (the CLI's rule too: a ray starts at its origin),
    /// `t_max` may be +∞ but not NaN, and `t_min ≤ t_max`; also [`Ray::with_t_max`] of a
    /// NaN, so that a shadow ray with a NaN light distance is refused, not unbounded.
    BadRange {
        /// The lower end given.
        t_min: P::Float,
        /// The upper end given.
        t_max: P::Float,
    },
    /// A shape's `spawn` (`Torus::spawn`, `Toroid::spawn`, `PipeBend::spawn`) was given a
    /// `t` whose point is not on the surface: farther from it than the tolerance
    /// `ON_SURFACE_REL·size + 8·ε·|t|·|d|` ([`ON_SURFACE_REL`]; size = R + r, R + max(a, b)
    /// or R + r_max; ε the machine epsilon of the ray's float, for the rounding of a far
    /// hit's `t`). Such a `t` is not a hit's, and its point moved onto the surface would be
    /// another point than the one the caller meant.
    OffSurface {
        /// The `t` given.
        t: P::Float,
        /// The distance of the point at `t` from the surface (for an elliptical horn or
        /// spindle, a lower bound: `Toroid::spawn`).
        distance: f64,
        /// The tolerance it exceeds.
        tolerance: f64,
    },
}

/// Why a [`DRay`] was refused: [`RayError`]'s cases, in f64.
pub type DRayError = RayError<DVec3>;

/// A number in an error message, compact: its shortest round-trip text in positional
/// notation when `1e-5 <= |v| < 1e16` (or 0, or not finite), in scientific notation
/// otherwise, so that `1e200` is `1e200`, not 201 digits.
pub(crate) fn compact<T: fmt::Display + fmt::LowerExp>(v: T, as_f64: f64) -> String {
    if as_f64 == 0.0 || !as_f64.is_finite() || (1e-5..1e16).contains(&as_f64.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// An f64 in an error message, [`compact`]; one that is an f32 (a radius of
/// [`crate::Torus::new`], widened) as that f32's shortest text, as typed: `3e-9`, not
/// `3.000000026176508e-9`.
pub(crate) fn compact_value(v: f64) -> String {
    let narrow = v as f32;
    if f64::from(narrow) == v {
        compact(narrow, v)
    } else {
        compact(v, v)
    }
}

/// A vector in an error message, `[x, y, z]`, each component [`compact`].
pub(crate) fn compact3<P: Precision>(v: P) -> String {
    let [x, y, z] = v.components().map(|c| compact(c, c.to_f64()));
    format!("[{x}, {y}, {z}]")
}

impl<P: Precision> fmt::Display for RayError<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = P::NAME;
        match self {
            RayError::NonFiniteOrigin(o) => {
                write!(f, "ray origin {} is not finite", compact3(*o))
            }
            RayError::NonFiniteDirection(d) => {
                write!(f, "ray direction {} is not finite", compact3(*d))
            }
            RayError::ZeroDirection(d) if *d == P::ZERO => {
                write!(
                    f,
                    "ray direction {d} is zero (|d|² must be a normal {name} > 0)"
                )
            }
            RayError::ZeroDirection(d) => {
                let [x, y, z] = d.components();
                write!(
                    f,
                    "ray direction [{x:e}, {y:e}, {z:e}] is too short: |d|² = {:e} is below the \
                     smallest normal {name} {:e} (scale it up: only its direction matters)",
                    d.to_dvec3().length_squared(),
                    <P::Float as Scalar>::MIN_POSITIVE
                )
            }
            RayError::HugeDirection(d) => {
                write!(
                    f,
                    "ray direction {} is too long ({})",
                    compact3(*d),
                    P::HUGE
                )
            }
            RayError::BadRange { t_min, t_max } => {
                write!(
                    f,
                    "ray range [{}, {}] is invalid ({})",
                    compact(*t_min, t_min.to_f64()),
                    compact(*t_max, t_max.to_f64()),
                    P::RANGE
                )
            }
            RayError::OffSurface {
                t,
                distance,
                tolerance,
            } => {
                write!(
                    f,
                    "spawn at t = {}: the point there is {} from the surface, beyond the \
                     on-surface tolerance {} (ON_SURFACE_REL·size + 8·ε·|t|·|d|): t is not \
                     a hit of this shape",
                    compact(*t, t.to_f64()),
                    compact(*distance, *distance),
                    compact(*tolerance, *tolerance)
                )
            }
        }
    }
}

impl<P: Precision> std::error::Error for RayError<P> {}

impl<P: Precision> Ray<P> {
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
    pub fn new(origin: P, dir: P) -> Result<Ray<P>, RayError<P>> {
        Ray::with_range(origin, dir, P::Float::ZERO, P::Float::INFINITY)
    }

    /// A ray over `t ∈ [t_min, t_max]`.
    pub fn with_range(
        origin: P,
        dir: P,
        t_min: P::Float,
        t_max: P::Float,
    ) -> Result<Ray<P>, RayError<P>> {
        if !origin.finite() {
            return Err(RayError::NonFiniteOrigin(origin));
        }
        if !dir.finite() {
            return Err(RayError::NonFiniteDirection(dir));
        }
        // The culls divide by |d|²: below the smallest normal float it would overflow or
        // lose bits, and an infinite |d|² would make every 1/|d|² zero.
        let len_sq = dir.length_sq();
        if len_sq < <P::Float as Scalar>::MIN_POSITIVE {
            return Err(RayError::ZeroDirection(dir));
        }
        if !len_sq.finite() {
            return Err(RayError::HugeDirection(dir));
        }
        // A NaN t_min is not finite; −0 is 0, not below it.
        if !t_min.finite() || t_min < P::Float::ZERO || t_max.nan() || t_min > t_max {
            return Err(RayError::BadRange { t_min, t_max });
        }
        Ok(Ray {
            origin,
            dir,
            t_min,
            t_max,
            on_surface: false,
        })
    }

    /// A secondary ray over `t ∈ [0, +∞)` whose origin is a point **of the surface** (a
    /// hit point, as the renderer stored it), such as a shadow ray, a bounce or a
    /// refraction ray. [`Torus::spawn`](crate::Torus::spawn) makes one from a hit and
    /// projects the origin onto the surface first.
    ///
    /// The intersection treats the origin as lying on the torus: the quartic's root that
    /// belongs to it (`t = 0`) is divided out, and the nearest of the other crossings with
    /// `t > 0` (and in the range) is the hit. So the ray never hits its own origin, however
    /// the origin was rounded, and it finds a re-hit through the hole or across the tube
    /// however close, with no ε to choose. An origin off the surface by δ moves the other
    /// crossings by about δ/|cos θ| there, as it would move any hit (docs/math.md §9).
    /// An origin farther than 10⁻²·R from the surface is not a surface point, and such a
    /// ray is answered literally. A ray that is not from a surface point keeps
    /// [`Ray::new`]'s literal semantics.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::{Ray, Torus, intersect};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// // From the top of the tube, straight up: nothing above.
    /// let up = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::Y)?;
    /// assert_eq!(intersect(&torus, &up), None);
    /// // From the inner equator across the hole: the far side of the tube, at t = 6.
    /// let across = Ray::from_surface(Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_X)?;
    /// assert!((intersect(&torus, &across).unwrap().t - 6.0).abs() < 1e-5);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// **How near the surface.** The origin should lie within [`ON_SURFACE_REL`]·(R + r)
    /// of the surface: any surface point rounded to f32 within about 1 600·(R + r) of the
    /// world origin does (docs/math.md §9). The lab's `eval` refuses an `on_surface` row
    /// farther off; the library does not know the torus here and cannot.
    ///
    /// **Only for the surface it left.** The mark names no shape: a torus whose surface
    /// passes within 10⁻²·R of the origin takes the origin as its own point and divides
    /// its root out. In a scene, test the spawned ray on its own shape and its
    /// [`Ray::literal`] on every other one: a neighbour that touches the origin's shape
    /// (interlocked links) would otherwise report a crossing the line does not have.
    pub fn from_surface(origin: P, dir: P) -> Result<Ray<P>, RayError<P>> {
        Ray::from_surface_with_range(origin, dir, P::Float::ZERO, P::Float::INFINITY)
    }

    /// [`Ray::from_surface`] over `t ∈ [t_min, t_max]`: the nearest crossing in the range
    /// with `t > 0`, other than the origin's own. A shadow ray to a light at `t = 1` is
    /// `from_surface_with_range(p, light − p, 0.0, 1.0)` (or
    /// [`Ray::from_surface`]`(…)?.`[`with_t_max`](Ray::with_t_max)`(1.0)?`).
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::{Ray, Torus, occluded};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// // From the inner equator across the hole, to lights at x = −2 and x = −4.
    /// let near = Ray::from_surface_with_range(Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_X, 0.0, 5.0)?;
    /// let far = Ray::from_surface_with_range(Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_X, 0.0, 7.0)?;
    /// assert!(!occluded(&torus, &near) && occluded(&torus, &far));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn from_surface_with_range(
        origin: P,
        dir: P,
        t_min: P::Float,
        t_max: P::Float,
    ) -> Result<Ray<P>, RayError<P>> {
        Ok(Ray {
            on_surface: true,
            ..Ray::with_range(origin, dir, t_min, t_max)?
        })
    }

    /// The shapes' `spawn`: the point at `t`, formed in f64 and moved onto the surface by
    /// `onto` before it is rounded to `P`, as the origin of a [`Ray::from_surface`].
    ///
    /// First the point must be on the surface: `distance(at)` (the shape's distance, or a
    /// lower bound of it; +∞ where it has none) at most `ON_SURFACE_REL·size +
    /// 8·ε·|t|·|d|`, else [`RayError::OffSurface`]. The first term is
    /// [`Ray::from_surface`]'s own bound, which covers a hit rounded to f32 within about
    /// 1 600·size of the world origin; the second covers the rounding of a far hit's `t`
    /// to the ray's float (½ε·|t|·|d|) with a factor 16 of room for the solver's error,
    /// so that a renderer's hit on a small shape far from the camera is still a hit. A `t`
    /// that is not a hit moves the point by about |t − t_hit|·|d|·|cos θ| off the surface,
    /// far beyond it.
    pub(crate) fn spawn_onto(
        &self,
        t: P::Float,
        dir: P,
        size: f64,
        distance: impl Fn(DVec3) -> f64,
        onto: impl Fn(DVec3) -> DVec3,
    ) -> Result<Ray<P>, RayError<P>> {
        let at = self.origin.to_dvec3() + self.dir.to_dvec3() * t.to_f64();
        if !at.is_finite() {
            return Err(RayError::NonFiniteOrigin(P::from_dvec3(at)));
        }
        let travel = t.to_f64().abs() * self.dir.to_dvec3().length();
        let tolerance = ON_SURFACE_REL * size + 8.0 * <P::Float as Scalar>::EPSILON_F64 * travel;
        let distance = distance(at);
        if distance.is_nan() || distance > tolerance {
            return Err(RayError::OffSurface {
                t,
                distance,
                tolerance,
            });
        }
        Ray::from_surface(P::from_dvec3(onto(at)), dir)
    }

    /// The same ray, not marked as starting on a surface: what a spawned ray is for every
    /// shape but the one it left ([`Ray::from_surface`]).
    #[inline]
    #[must_use]
    pub const fn literal(&self) -> Ray<P> {
        Ray {
            on_surface: false,
            ..*self
        }
    }

    /// Whether the origin is a point of the surface ([`Ray::from_surface`]).
    #[inline]
    #[must_use]
    pub const fn starts_on_surface(&self) -> bool {
        self.on_surface
    }

    /// The origin `o`.
    #[inline]
    #[must_use]
    pub const fn origin(&self) -> P {
        self.origin
    }

    /// The direction `d` (as given; not normalized).
    #[inline]
    #[must_use]
    pub const fn dir(&self) -> P {
        self.dir
    }

    /// The lower end of the parameter range.
    #[inline]
    #[must_use]
    pub const fn t_min(&self) -> P::Float {
        self.t_min
    }

    /// The upper end of the parameter range (may be +∞).
    #[inline]
    #[must_use]
    pub const fn t_max(&self) -> P::Float {
        self.t_max
    }

    /// The same ray with its range cut to end at `t_max` (never widened, never below
    /// `t_min`): what a traversal passes on once a closer hit is known, or a shadow ray
    /// given its light's distance.
    ///
    /// # Errors
    ///
    /// [`RayError::BadRange`] for a NaN `t_max`: a shadow ray whose light distance is NaN
    /// would otherwise keep its range (+∞) and see every occluder behind the light.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::Ray;
    /// let ray = Ray::new(Vec3::ZERO, Vec3::X)?;
    /// assert_eq!(ray.with_t_max(2.0)?.t_max(), 2.0);
    /// assert_eq!(ray.with_t_max(2.0)?.with_t_max(5.0)?.t_max(), 2.0); // never widened
    /// assert!(ray.with_t_max(f32::NAN).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[inline]
    pub fn with_t_max(&self, t_max: P::Float) -> Result<Ray<P>, RayError<P>> {
        if t_max.nan() {
            return Err(RayError::BadRange {
                t_min: self.t_min,
                t_max,
            });
        }
        Ok(Ray {
            t_max: t_max.min(self.t_max).max(self.t_min),
            ..*self
        })
    }

    /// The point `o + t·d`.
    #[inline]
    #[must_use]
    pub fn at(&self, t: P::Float) -> P {
        self.origin + self.dir * t
    }

    /// `[t_min, t_max]` in f64 (exact).
    #[inline(always)]
    pub(crate) fn range_f64(&self) -> (f64, f64) {
        (self.t_min.to_f64(), self.t_max.to_f64())
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
            on_surface: ray.on_surface,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_their_precision() {
        let msg = |e: &dyn std::error::Error| e.to_string();
        let zero = Ray::new(Vec3::ZERO, Vec3::ZERO).unwrap_err();
        assert_eq!(
            msg(&zero),
            "ray direction [0, 0, 0] is zero (|d|² must be a normal f32 > 0)"
        );
        let huge = DRay::new(DVec3::ZERO, DVec3::splat(1e300)).unwrap_err();
        assert!(matches!(huge, DRayError::HugeDirection(_)));
        // Issue 36: compact numbers, not 301 digits each.
        assert_eq!(
            msg(&huge),
            "ray direction [1e300, 1e300, 1e300] is too long (|d|² overflows f64)"
        );
        let range = DRay::with_range(DVec3::ZERO, DVec3::X, 1e200, 1.0).unwrap_err();
        assert!(
            msg(&range).starts_with("ray range [1e200, 1] is invalid"),
            "{range}"
        );
        let huge = Ray::new(Vec3::ZERO, Vec3::splat(1e20)).unwrap_err();
        assert!(msg(&huge).ends_with("(|d|² must be finite in f32: |d| < 1.8e19)"));
        let tiny = Ray::new(Vec3::ZERO, Vec3::new(1e-20, 0.0, 0.0)).unwrap_err();
        assert_eq!(
            msg(&tiny),
            "ray direction [1e-20, 0e0, 0e0] is too short: |d|² = 9.99999936531046e-41 is \
             below the smallest normal f32 1.1754944e-38 (scale it up: only its direction \
             matters)"
        );
        let range = DRay::with_range(DVec3::ZERO, DVec3::X, 2.0, 1.0).unwrap_err();
        assert_eq!(
            msg(&range),
            "ray range [2, 1] is invalid (need 0 ≤ t_min ≤ t_max, t_min finite, t_max not NaN)"
        );
        let range = Ray::with_range(Vec3::ZERO, Vec3::X, 2.0, 1.0).unwrap_err();
        assert_eq!(
            msg(&range),
            "ray range [2, 1] is invalid (need 0 ≤ t_min ≤ t_max, t_min finite, t_max not NaN)"
        );
    }
}
