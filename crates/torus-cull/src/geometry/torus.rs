//! The torus: pose, validation and the rigid world→torus-frame transform.

use super::bounds::CullBounds;
use super::ray::sealed::PerPrecision;
use super::ray::{DRay, Precision, Ray, RayError, compact_value as num};
use super::tube::Tube;
use glam::{DMat3, DVec3, Mat3, Vec3};
use std::fmt;

/// A ring torus in the world: centre, unit rotation axis, `major_radius` R and
/// `minor_radius` r, with R > r > 0 (ν = R/r > 1).
///
/// In the torus frame the centre is the origin and the axis is +y, so the surface is
/// `(ρ − R)² + y² = r²` with `ρ = √(x² + z²)`. The world→torus transform is rigid
/// (translate, then rotate the axis onto +y), so `t` is the same in both frames.
///
/// **ν ≤ 1 is refused.** A horn or spindle torus has no hole, and the quartic's second
/// factor `(ρ + R)² + y² − r²` is no longer positive there, so "sign F = inside the tube",
/// which the oracle and the hole test rely on, would fail silently. [`Torus::new`]
/// returns [`TorusError::NoHole`] instead.
///
/// **ν is limited to [`MAX_NU`] (1000).** The tests check the exact intersection against
/// the oracle, and every cull's conservativeness, up to ν = 1000 and no further; far
/// thinner tubes are not only untested but known wrong (at ν ≈ 3.3·10⁸ `intersect`
/// reported a hit half a tube radius outside the surface). [`Torus::new`] returns
/// [`TorusError::TooThin`] above it.
///
/// **The size is limited to [`MIN_OUTER_RADIUS`] ≤ R + r ≤ [`MAX_OUTER_RADIUS`]**
/// (10⁻¹⁵ to 10¹⁵). The culls run in f32 and square lengths and products of lengths:
/// past about 10¹⁹ the squares overflow (`cychosz` and `skala` then reject real hits) and
/// below about 10⁻¹⁹ they fall into subnormals (`thick_cylinder` and `skala` then do).
/// The limits leave a factor of about 10³ of room on each side, and the tests check every timed
/// cull against the oracle at both limits. Larger or smaller scenes should be rescaled
/// before they reach the culls; [`TorusError::OutOfRange`] says so.
///
/// **f64 geometry: [`Torus::new_f64`].** A torus built from f64 centre, axis and radii
/// keeps them in f64 for everything that runs in f64: [`crate::intersect()`],
/// [`crate::occluded()`] and [`crate::intersect_culled`]'s exact step (for a [`Ray`] and a
/// [`DRay`] alike), the f64 lines the culls of a [`DRay`] start from, the batch f64
/// intersection and the certified f32 path's line. Only what is f32 by nature is
/// rounded: the getters without `_f64` ([`Torus::center`], [`Torus::axis`],
/// [`Torus::major_radius`], [`Torus::minor_radius`], and what derives from them:
/// [`Torus::nu`], [`Torus::outer_radius`], [`Torus::world_aabb`], the f32 rotation and
/// transforms) are rounded to nearest, and the culls' [`CullBounds`] are built for a
/// slightly fatter tube (R rounded to nearest, r rounded up by R's rounding error too),
/// which holds the f64 one, so the culls stay conservative. An f32 [`Ray`] whose torus
/// centre f32 cannot hold reaches the culls through the f64 foot-point path
/// ([`Torus::line_to_local`]), never through the rounded centre.
///
/// ```
/// use torus_cull::Torus;
/// use glam::Vec3;
/// let t = Torus::new(Vec3::new(1.0, 2.0, 3.0), Vec3::Z, 2.0, 0.5).unwrap();
/// assert_eq!(t.nu(), 4.0);
/// assert!(Torus::canonical(1.0, 1.0).is_err()); // horn torus: no hole
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Torus {
    center: Vec3,
    axis: Vec3,
    major_radius: f32,
    minor_radius: f32,
    /// Rows are the world directions of the torus frame's x, y (= axis) and z.
    to_local: Mat3,
    /// The same rotation built in f64 (from the f32 axis, or for [`Torus::new_f64`] from
    /// the f64 one), for the f64 exact intersection; its middle row is the unit axis.
    to_local_f64: DMat3,
    /// The centre in f64: `center` widened, or [`Torus::new_f64`]'s own.
    center_f64: DVec3,
    /// R in f64: `major_radius` widened, or [`Torus::new_f64`]'s own.
    major_f64: f64,
    /// r in f64: `minor_radius` widened, or [`Torus::new_f64`]'s own.
    minor_f64: f64,
    /// (NEAR_ORIGIN_REL·(R + r))²: origins beyond it take the f64 path to the culls; −1
    /// (every origin) when `center` is not `center_f64`.
    near_origin_sq: f32,
    /// The culls' constants, derived once here from the validated radii: a cull can only
    /// be given the bounds of the torus it tests.
    bounds: CullBounds,
    /// The exact path's constants (1/R, r/R, …), likewise derived once.
    tube: Tube,
}

/// Why a torus was refused.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TorusError {
    /// A radius is NaN, infinite, zero or negative.
    BadRadius {
        /// Which radius.
        name: &'static str,
        /// The value given (an f32 radius widened exactly).
        value: f64,
    },
    /// ν = R/r ≤ 1: a horn or spindle torus, which has no hole.
    NoHole {
        /// R as given.
        major_radius: f64,
        /// r as given.
        minor_radius: f64,
    },
    /// ν = R/r > [`MAX_NU`]: a tube thinner than the tests prove the intersection and
    /// the culls right for.
    TooThin {
        /// R as given.
        major_radius: f64,
        /// r as given.
        minor_radius: f64,
    },
    /// The centre has a NaN or infinite component.
    NonFiniteCenter(Vec3),
    /// [`Torus::from_affine`]: the transform is not a rotation with a uniform positive
    /// scale (a shear, a non-uniform scale or a reflection does not keep a torus a torus).
    NotSimilarity,
    /// The axis is zero, NaN or infinite.
    BadAxis(Vec3),
    /// R + r is outside [`MIN_OUTER_RADIUS`, `MAX_OUTER_RADIUS`], where the f32 culls are no
    /// longer conservative.
    OutOfRange {
        /// R as given.
        major_radius: f64,
        /// r as given.
        minor_radius: f64,
    },
}

/// The largest supported ν = R/r, 1000: the edge of what the tests prove (the exact
/// intersection against the f64 oracle, and every cull's conservativeness, are checked up
/// to ν = 1000 at R from 10⁻³ to 10³). ν is taken in f64 from the f32 radii, and a
/// radius rounded to f32 may put a requested ν = 1000 a few parts in 10⁸ above it, so
/// [`Torus::new`] allows ν ≤ `MAX_NU`·(1 + 10⁻⁶).
pub const MAX_NU: f64 = 1000.0;

/// The relative slack [`Torus::new`] allows above [`MAX_NU`] for the f32 rounding of the
/// radii.
const MAX_NU_SLACK: f64 = 1e-6;

/// The smallest supported R + r, 10⁻¹⁵: below about 10⁻¹⁹ the culls' squared lengths
/// become subnormal f32 and lose the bits the safety margin relies on.
pub const MIN_OUTER_RADIUS: f32 = 1e-15;

/// The largest supported R + r, 10¹⁵: above about 10¹⁹ the culls' squared lengths
/// overflow f32.
pub const MAX_OUTER_RADIUS: f32 = 1e15;

/// Origins farther than this many (R + r) from the centre are first moved to the line's
/// foot point, in f64 (see [`Torus::line_to_local`]). The culls' margin covers f32
/// rounding up to 256·(R + r); 64 leaves a factor 4 of room.
pub const NEAR_ORIGIN_REL: f32 = 64.0;

/// Origins farther than this many (R + r) from the centre (2⁴⁰) are beyond where f64 places
/// a line to within the culls' margin: the culls then keep the ray (see
/// [`Torus::line_to_local`]), and the exact intersection answers with an error of about
/// 2⁻⁵³ of the distance.
pub const FAR_LIMIT_REL: f64 = 1_099_511_627_776.0;

impl fmt::Display for TorusError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TorusError::BadRadius { name, value } => {
                write!(
                    f,
                    "{name} = {} is invalid (must be finite and > 0)",
                    num(*value)
                )
            }
            TorusError::NoHole {
                major_radius,
                minor_radius,
            } => write!(
                f,
                "major_radius = {}, minor_radius = {}: nu = R/r = {} must be > 1 \
                 (a horn or spindle torus has no hole; torus-cull supports ring tori only)",
                num(*major_radius),
                num(*minor_radius),
                num(major_radius / minor_radius)
            ),
            TorusError::TooThin {
                major_radius,
                minor_radius,
            } => write!(
                f,
                "major_radius = {}, minor_radius = {}: nu = R/r = {:e} \
                 is above the supported range (allowed: 1 < nu <= {MAX_NU}, where the \
                 intersection and the culls are tested; scale r up or split the scene)",
                num(*major_radius),
                num(*minor_radius),
                major_radius / minor_radius
            ),
            TorusError::NotSimilarity => write!(
                f,
                "the transform is not a rotation with a uniform positive scale (allowed: rigid \
                 motion times a uniform scale; a shear, a non-uniform scale or a reflection \
                 does not keep a torus a torus)"
            ),
            TorusError::NonFiniteCenter(c) => {
                write!(f, "torus centre {} is not finite", super::ray::compact3(*c))
            }
            TorusError::BadAxis(a) => write!(
                f,
                "torus axis {} must be finite and non-zero",
                super::ray::compact3(*a)
            ),
            TorusError::OutOfRange {
                major_radius,
                minor_radius,
            } => write!(
                f,
                "major_radius = {}, minor_radius = {}: R + r = {} is outside \
                 the supported range {MIN_OUTER_RADIUS:e} ..= {MAX_OUTER_RADIUS:e} (the f32 culls are \
                 not conservative beyond it; rescale the scene)",
                num(*major_radius),
                num(*minor_radius),
                num(major_radius + minor_radius)
            ),
        }
    }
}

impl std::error::Error for TorusError {}

/// A line in the torus frame: `origin + t·dir`, f32, `dir` non-zero but of any length.
///
/// It is the ray's *line*, for the culls: `origin` is the ray's origin, or the line's foot
/// point when the origin is far (see [`Torus::line_to_local`]), so `t` along it is not the
/// ray's `t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalLine {
    /// A point of the line in the torus frame.
    pub origin: Vec3,
    /// The direction in the torus frame (same length as the world direction).
    pub dir: Vec3,
}

impl Torus {
    /// A torus at `center` with rotation `axis` (normalized here), R = `major_radius`,
    /// r = `minor_radius`.
    pub fn new(
        center: Vec3,
        axis: Vec3,
        major_radius: f32,
        minor_radius: f32,
    ) -> Result<Torus, TorusError> {
        let (major, minor) = (f64::from(major_radius), f64::from(minor_radius));
        check_hole(major, minor)?;
        Torus::image(center.as_dvec3(), axis.as_dvec3(), major, minor, false)
    }

    /// A torus from f64 geometry, kept in f64 for the exact intersection (see the type's
    /// docs for what is exact and what is rounded to f32): centre `center`, rotation
    /// `axis` (normalized here, in f64), R = `major_radius`, r = `minor_radius`.
    ///
    /// The same rules as [`Torus::new`], checked on the f64 values, with the same errors;
    /// the radii an error carries are the f64 values given, the centre and axis are
    /// rounded to f32. A centre beyond f32's range is refused as
    /// [`TorusError::NonFiniteCenter`] (it is infinite where the culls and f32 rays work).
    ///
    /// ```
    /// use glam::DVec3;
    /// use torus_cull::{DRay, Torus, intersect};
    /// // R = 2 + 10⁻⁹ and a centre at x = 0.1: neither is an f32.
    /// let torus = Torus::new_f64(DVec3::new(0.1, 0.0, 0.0), DVec3::Y, 2.0 + 1e-9, 1.0)?;
    /// assert_eq!(torus.major_radius_f64(), 2.0 + 1e-9);
    /// assert_eq!(torus.major_radius(), 2.0); // the f32 view, rounded
    /// let ray = DRay::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X)?;
    /// // The outer equator at x = 0.1 − (3 + 10⁻⁹): t = 7.1 − 10⁻⁹, to f64 precision.
    /// let hit = intersect(&torus, &ray).expect("the outer equator");
    /// assert!((hit.t - (7.1 - 1e-9)).abs() < 1e-12);
    /// // The same torus built from f32 values is off by their rounding (about 10⁻⁹ here).
    /// let rounded = Torus::new(glam::Vec3::new(0.1, 0.0, 0.0), glam::Vec3::Y, 2.0, 1.0)?;
    /// let off = intersect(&rounded, &ray).expect("the outer equator");
    /// assert!((off.t - (7.1 - 1e-9)).abs() > 1e-10);
    /// assert!(Torus::new_f64(DVec3::ZERO, DVec3::Y, 1.0, 1.0).is_err()); // no hole
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn new_f64(
        center: DVec3,
        axis: DVec3,
        major_radius: f64,
        minor_radius: f64,
    ) -> Result<Torus, TorusError> {
        check_hole(major_radius, minor_radius)?;
        Torus::image(center, axis, major_radius, minor_radius, true)
    }

    /// [`Torus::new`] (`f64_geometry` false: the values are f32's, widened) or
    /// [`Torus::new_f64`] without the hole's rule, so R ≤ r (a horn or spindle) is built
    /// too: the circular image of a torus-family member (`crate::family::Toroid`). Only
    /// the family, which answers R ≤ r with the apple's roots alone, may hold such a torus.
    pub(crate) fn image(
        center: DVec3,
        axis: DVec3,
        major_radius: f64,
        minor_radius: f64,
        f64_geometry: bool,
    ) -> Result<Torus, TorusError> {
        validate_image(center, axis, major_radius, minor_radius)?;
        if !f64_geometry {
            let (center, axis) = (center.as_vec3(), axis.as_vec3());
            // The stored f32 axis *is* the torus: the f64 rotation (and the oracle) start
            // from it, so both paths agree on the same surface to f64 precision.
            let axis = axis.as_dvec3().normalize().as_vec3();
            let (major, minor) = (major_radius as f32, minor_radius as f32);
            return Ok(Torus::build(
                (center, center.as_dvec3()),
                (axis, axis.as_dvec3().normalize()),
                (major, f64::from(major)),
                (minor, f64::from(minor)),
                minor,
            ));
        }
        let center_f32 = center.as_vec3();
        if !center_f32.is_finite() {
            return Err(TorusError::NonFiniteCenter(center_f32));
        }
        // Scaled to its largest component first, so that |axis|² neither overflows nor
        // underflows.
        let unit = (axis / axis.abs().max_element()).normalize();
        let major_f32 = major_radius as f32;
        // The culls' tube: around the circle of radius R rounded, it must hold the f64
        // tube, whose points are within r + |R − R_f32| of that circle.
        let minor_cull =
            crate::num::round::up(minor_radius + (major_radius - f64::from(major_f32)).abs());
        Ok(Torus::build(
            (center_f32, center),
            (unit.as_vec3(), unit),
            (major_f32, major_radius),
            (minor_radius as f32, minor_radius),
            minor_cull,
        ))
    }

    /// The torus of validated values, each given as (f32 view, f64 value); `minor_cull`
    /// is the r the culls' bounds are built for.
    fn build(
        (center, center_f64): (Vec3, DVec3),
        (axis, unit_axis): (Vec3, DVec3),
        (major_radius, major_f64): (f32, f64),
        (minor_radius, minor_f64): (f32, f64),
        minor_cull: f32,
    ) -> Torus {
        let to_local_f64 = rotation_axis_to_y(unit_axis);
        let near = NEAR_ORIGIN_REL * (major_radius + minor_radius);
        // A centre f32 cannot hold: the f32 `ray.origin() − center` of the near path would
        // be off by the centre's rounding, so every f32 ray takes the f64 path.
        let near_origin_sq = if center.as_dvec3() == center_f64 {
            near * near
        } else {
            -1.0
        };
        Torus {
            center,
            axis,
            major_radius,
            minor_radius,
            to_local: to_local_f64.as_mat3(),
            to_local_f64,
            center_f64,
            major_f64,
            minor_f64,
            near_origin_sq,
            bounds: CullBounds::new(major_radius, minor_cull),
            tube: Tube::new(major_f64, minor_f64),
        }
    }

    /// The torus in its own frame: centre at the origin, axis +y.
    pub fn canonical(major_radius: f32, minor_radius: f32) -> Result<Torus, TorusError> {
        Torus::new(Vec3::ZERO, Vec3::Y, major_radius, minor_radius)
    }

    /// The centre in world space.
    #[inline]
    #[must_use]
    pub const fn center(&self) -> Vec3 {
        self.center
    }

    /// The unit rotation axis in world space.
    #[inline]
    #[must_use]
    pub const fn axis(&self) -> Vec3 {
        self.axis
    }

    /// R: distance from the axis to the tube centre.
    #[inline]
    #[must_use]
    pub const fn major_radius(&self) -> f32 {
        self.major_radius
    }

    /// r: the tube radius.
    #[inline]
    #[must_use]
    pub const fn minor_radius(&self) -> f32 {
        self.minor_radius
    }

    /// The centre in f64: [`Torus::center`] widened, or [`Torus::new_f64`]'s as given.
    #[inline]
    #[must_use]
    pub const fn center_f64(&self) -> DVec3 {
        self.center_f64
    }

    /// The unit rotation axis in f64, that of the f64 rotation: [`Torus::axis`] widened
    /// and normalized in f64, or [`Torus::new_f64`]'s normalized in f64.
    #[inline]
    #[must_use]
    pub fn axis_f64(&self) -> DVec3 {
        self.to_local_f64.row(1)
    }

    /// R in f64: [`Torus::major_radius`] widened, or [`Torus::new_f64`]'s as given.
    #[inline]
    #[must_use]
    pub const fn major_radius_f64(&self) -> f64 {
        self.major_f64
    }

    /// r in f64: [`Torus::minor_radius`] widened, or [`Torus::new_f64`]'s as given.
    #[inline]
    #[must_use]
    pub const fn minor_radius_f64(&self) -> f64 {
        self.minor_f64
    }

    /// ν = R/r, > 1 for every `Torus`.
    #[inline]
    #[must_use]
    pub const fn nu(&self) -> f32 {
        self.major_radius / self.minor_radius
    }

    /// The radius R + r of the bounding sphere.
    #[inline]
    #[must_use]
    pub const fn outer_radius(&self) -> f32 {
        self.major_radius + self.minor_radius
    }

    /// The culls' per-torus constants (R, r and the padded radii of the safety margin),
    /// computed once by [`Torus::new`]: what [`crate::Cull::keeps`] and
    /// [`crate::batch::cull_batch`] take with a line already in this torus's frame.
    #[inline]
    #[must_use]
    pub const fn bounds(&self) -> &CullBounds {
        &self.bounds
    }

    /// The exact intersection's per-torus constants.
    #[inline(always)]
    pub(crate) const fn tube(&self) -> &Tube {
        &self.tube
    }

    /// The rotation world→torus frame (axis → +y), f32.
    #[inline]
    #[must_use]
    pub const fn to_local_rotation(&self) -> Mat3 {
        self.to_local
    }

    /// The rotation world→torus frame (axis → +y), built in f64.
    #[inline]
    #[must_use]
    pub const fn to_local_rotation_f64(&self) -> DMat3 {
        self.to_local_f64
    }

    /// A world point in the torus frame (f32).
    #[inline]
    #[must_use]
    pub fn point_to_local(&self, p: Vec3) -> Vec3 {
        self.to_local * (p - self.center)
    }

    /// A torus-frame point in the world (f32).
    #[inline]
    #[must_use]
    pub fn point_to_world(&self, p: Vec3) -> Vec3 {
        self.to_local.transpose() * p + self.center
    }

    /// A torus-frame direction in the world (f32); lengths are kept.
    #[inline]
    #[must_use]
    pub fn dir_to_world(&self, d: Vec3) -> Vec3 {
        self.to_local.transpose() * d
    }

    /// (`NEAR_ORIGIN_REL`·(R + r))²: origins farther than this from the centre take
    /// [`Torus::line_to_local`]'s f64 foot-point path.
    #[inline]
    pub(crate) const fn near_origin_sq(&self) -> f32 {
        self.near_origin_sq
    }

    /// The ray's line in the torus frame, in f32, as the culls see it.
    ///
    /// The f32 transform errs by about 4·2⁻²⁴·|o − c|, which the culls' margin absorbs for
    /// |o − c| ≤ 256·(R + r). An origin farther than [`NEAR_ORIGIN_REL`]·(R + r) is
    /// therefore replaced by the line's foot point p = o − d (o·d)/|d|², the point closest
    /// to the centre, computed in f64: the same line, now with an origin the margin
    /// covers, whatever the distance. The near case, which is every ray a camera near
    /// the torus shoots, costs one compare.
    ///
    /// For a [`DRay`] the line is formed in f64 with a unit direction (the culls' verdicts
    /// do not depend on its length, and f32 holds a unit vector whatever the ray's
    /// scale), a far origin moves to the foot point the same way, and rounding the origin
    /// (then within 64·(R + r)) and the direction to f32 moves the line by at most about
    /// 2⁻¹⁷·(R + r) inside the bounding sphere, below the culls' margin η = 2⁻¹²·(R + r).
    /// A foot point farther than 4·(R + r) (a line that misses the torus by far, and
    /// whose foot f32 may not even hold) is pulled in to 4·(R + r) along itself: still a
    /// line that misses.
    #[inline(always)]
    #[must_use]
    pub fn line_to_local<P: Precision>(&self, ray: &Ray<P>) -> LocalLine {
        P::line_of(self, ray)
    }

    /// [`Torus::line_to_local`] of an f32 [`Ray`].
    #[inline]
    pub(super) fn ray_line(&self, ray: &Ray) -> LocalLine {
        let relative = ray.origin() - self.center;
        // An overflowed (infinite) square fails the test too and takes the f64 path.
        if relative.length_squared() <= self.near_origin_sq {
            LocalLine {
                origin: self.to_local * relative,
                dir: self.to_local * ray.dir(),
            }
        } else {
            self.far_ray_line(ray)
        }
    }

    /// [`Torus::line_to_local`] for a far origin: the foot point, in f64.
    #[cold]
    #[inline(never)]
    fn far_ray_line(&self, ray: &Ray) -> LocalLine {
        let (o, d) = self.line_to_local_f64(ray);
        if !self.placeable(o) {
            return self.unplaceable(d);
        }
        let foot = o - d * (o.dot(d) / d.length_squared());
        LocalLine {
            origin: foot.as_vec3(),
            dir: d.as_vec3(),
        }
    }

    /// Whether f64 places the line through `o` (torus frame) to within the culls' margin:
    /// the foot point's rounding, about 2⁻⁵³·|o|, must stay below η = 2⁻¹²·(R + r), so
    /// |o| ≤ 2⁴⁰·(R + r).
    fn placeable(&self, o: DVec3) -> bool {
        let limit = FAR_LIMIT_REL * (self.major_f64 + self.minor_f64);
        o.length_squared() <= limit * limit
    }

    /// The line the culls get for a ray f64 cannot place: one with the ray's direction
    /// through the tube's core circle at (R, 0, 0), which every conservative cull keeps
    /// (it runs inside the tube), so the exact intersection decides.
    #[cold]
    fn unplaceable(&self, d: DVec3) -> LocalLine {
        LocalLine {
            origin: Vec3::new(self.major_radius(), 0.0, 0.0),
            dir: (d / d.length()).as_vec3(),
        }
    }

    /// The ray's origin and direction in the torus frame, in f64 (for the exact path);
    /// an f32 [`Ray`] is widened exactly first.
    #[inline]
    #[must_use]
    pub fn line_to_local_f64<P: Precision>(&self, ray: &Ray<P>) -> (DVec3, DVec3) {
        let o = ray.origin().to_dvec3() - self.center_f64;
        (
            self.to_local_f64 * o,
            self.to_local_f64 * ray.dir().to_dvec3(),
        )
    }

    /// The point of the surface nearest to `p` (world space, f64): the tube's core circle's
    /// nearest point `c` (at distance R from the axis, in the plane through `p` and the
    /// axis), then `c + r·(p − c)/|p − c|`. Closed form, exact but for rounding. A point on
    /// the axis, or on the core circle itself, has no unique nearest point and is
    /// returned unchanged.
    #[must_use]
    pub fn nearest_surface_point(&self, p: DVec3) -> DVec3 {
        let local = self.to_local_f64 * (p - self.center_f64);
        match self.tube().nearest_surface_point(local) {
            Some(on) => self.to_local_f64.transpose() * on + self.center_f64,
            None => p,
        }
    }

    /// The secondary ray that leaves the hit at `t` on `ray` (its `Hit::t`) in direction
    /// `dir`: its origin is `ray`'s point at `t`, formed in f64 and moved onto the surface
    /// ([`Torus::nearest_surface_point`]) before it is rounded to the ray's precision, and
    /// it is marked as starting there ([`Ray::from_surface`]), so it cannot hit its own
    /// origin and needs no ε. A shadow ray takes [`Ray::with_t_max`] after.
    ///
    /// `dir` may point to either side of the surface: outward (reflection, a shadow ray
    /// to a light above the surface) or into the tube (refraction), where the hit is the
    /// ray's exit (`Hit::front_face` false, the outward normal along the ray). Nothing
    /// is assumed about the side: the origin's own root is divided out either way, and a
    /// direction in the tangent plane is a grazing ray (docs/math.md §9).
    ///
    /// # Errors
    ///
    /// A [`RayError`], never a panic or a NaN ray: `NonFiniteDirection` for a NaN or
    /// infinite component of `dir`, `ZeroDirection` / `HugeDirection` for a `dir` whose
    /// `|d|²` is not a normal finite float, `NonFiniteOrigin` when the point at `t` is not
    /// finite (a NaN or infinite `t`, or a hit too far along for the ray's float),
    /// `OffSurface` when it lies farther from the surface than
    /// [`ON_SURFACE_REL`](crate::ON_SURFACE_REL)·(R + r) + 8·ε·|t|·|d| (ε the machine
    /// epsilon of the ray's float): `t` is not a hit's.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::{Ray, Torus, intersect};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// // Along the x axis from outside: the outer equator, x = 5, at t = 5.
    /// let ray = Ray::new(Vec3::new(10.0, 0.0, 0.0), Vec3::NEG_X)?;
    /// let hit = intersect(&torus, &ray).expect("hits the outer equator first");
    /// // Straight through the tube instead: the refraction ray exits at x = 3.
    /// let through = torus.spawn(&ray, hit.t, Vec3::NEG_X)?;
    /// assert!(through.starts_on_surface());
    /// assert!((intersect(&torus, &through).unwrap().t - 2.0).abs() < 1e-5);
    /// // Back the way it came: nothing.
    /// assert_eq!(intersect(&torus, &torus.spawn(&ray, hit.t, Vec3::X)?), None);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn spawn<P: Precision>(
        &self,
        ray: &Ray<P>,
        t: P::Float,
        dir: P,
    ) -> Result<Ray<P>, RayError<P>> {
        let distance = |at| self.signed_distance(at).map_or(f64::INFINITY, f64::abs);
        let size = self.major_f64 + self.minor_f64;
        ray.spawn_onto(t, dir, size, distance, |at| self.nearest_surface_point(at))
    }

    /// [`Torus::spawn`] from a hit's point (`Hit::point`, in the ray's precision), for a
    /// renderer that kept the hit and not the ray: the point is moved onto the surface in
    /// f64 and the ray marked as starting there.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::{Ray, Torus, intersect};
    /// let torus = Torus::canonical(4.0, 1.0)?;
    /// let ray = Ray::new(Vec3::new(10.0, 0.0, 0.0), Vec3::NEG_X)?;
    /// let hit = intersect(&torus, &ray).unwrap();
    /// let through = torus.spawn_from_point(hit.point, Vec3::NEG_X)?;
    /// assert!((intersect(&torus, &through).unwrap().t - 2.0).abs() < 1e-5);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// A [`RayError`], as [`Torus::spawn`]'s.
    pub fn spawn_from_point<P: Precision>(&self, point: P, dir: P) -> Result<Ray<P>, RayError<P>> {
        Ray::from_surface(
            P::from_dvec3(self.nearest_surface_point(point.to_dvec3())),
            dir,
        )
    }

    /// [`Torus::line_to_local`] of an f64 [`DRay`].
    pub(super) fn dray_line(&self, ray: &DRay) -> LocalLine {
        let (o, d) = self.line_to_local_f64(ray);
        if !self.placeable(o) {
            return self.unplaceable(d);
        }
        let d = d / d.length();
        let outer = self.major_f64 + self.minor_f64;
        let near = f64::from(NEAR_ORIGIN_REL) * outer;
        let origin = if o.length_squared() <= near * near {
            o
        } else {
            let foot = o - d * o.dot(d);
            let far = 4.0 * outer;
            let dist = foot.length();
            if dist > far {
                foot * (far / dist)
            } else {
                foot
            }
        };
        LocalLine {
            origin: origin.as_vec3(),
            dir: d.as_vec3(),
        }
    }

    /// The world-space axis-aligned bounding box of the torus, `(min, max)`.
    ///
    /// Exact for any axis: along world axis i the half-extent is `R·√(1 − a_i²) + r`,
    /// computed in f64 from the torus's f64 geometry and rounded outward to f32, so the
    /// box holds the torus.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::Torus;
    /// // Lying flat (axis +y): 2(R + r) wide in x and z, 2r high.
    /// let flat = Torus::new(Vec3::new(1.0, 2.0, 3.0), Vec3::Y, 4.0, 1.0)?;
    /// assert_eq!(flat.world_aabb(), (Vec3::new(-4.0, 1.0, -2.0), Vec3::new(6.0, 3.0, 8.0)));
    /// // Standing on edge (axis +x): now thin in x.
    /// let (lo, hi) = Torus::new(Vec3::ZERO, Vec3::X, 4.0, 1.0)?.world_aabb();
    /// assert_eq!((lo, hi), (Vec3::new(-1.0, -5.0, -5.0), Vec3::new(1.0, 5.0, 5.0)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn world_aabb(&self) -> (Vec3, Vec3) {
        let a = self.to_local_f64.row(1);
        let ring = (DVec3::ONE - a * a).max(DVec3::ZERO).sqrt() * self.major_f64;
        let half = ring + DVec3::splat(self.minor_f64);
        let (lo, hi) = (self.center_f64 - half, self.center_f64 + half);
        use crate::num::round::{down, up};
        (
            Vec3::new(down(lo.x), down(lo.y), down(lo.z)),
            Vec3::new(up(hi.x), up(hi.y), up(hi.z)),
        )
    }
}

/// The hole's rule of [`Torus::new`]: R > r, checked on positive finite radii only (the
/// others are [`validate_image`]'s to refuse, as `BadRadius`, which comes first).
fn check_hole(major: f64, minor: f64) -> Result<(), TorusError> {
    let positive = |v: f64| v.is_finite() && v > 0.0;
    if positive(major) && positive(minor) && major <= minor {
        return Err(TorusError::NoHole {
            major_radius: major,
            minor_radius: minor,
        });
    }
    Ok(())
}

/// [`Torus::new`]'s rules on f64 values (f32 ones widened exactly) but the hole's
/// ([`check_hole`]): also those of a torus-family member's circular image
/// (`crate::family`), which refuses its own ratios.
fn validate_image(center: DVec3, axis: DVec3, major: f64, minor: f64) -> Result<(), TorusError> {
    for (name, value) in [("major_radius", major), ("minor_radius", minor)] {
        if !(value.is_finite() && value > 0.0) {
            return Err(TorusError::BadRadius { name, value });
        }
    }
    // The values as given, f64 (an f32 radius widened exactly): rounded to f32, 10³⁰⁰
    // would be reported as inf.
    let (major_radius, minor_radius) = (major, minor);
    // In f64: R + r may overflow f32 while both radii are finite.
    if !(f64::from(MIN_OUTER_RADIUS)..=f64::from(MAX_OUTER_RADIUS)).contains(&(major + minor)) {
        return Err(TorusError::OutOfRange {
            major_radius,
            minor_radius,
        });
    }
    // After the size: a torus out of range says so first.
    if major / minor > MAX_NU * (1.0 + MAX_NU_SLACK) {
        return Err(TorusError::TooThin {
            major_radius,
            minor_radius,
        });
    }
    if !center.is_finite() {
        return Err(TorusError::NonFiniteCenter(center.as_vec3()));
    }
    if !axis.is_finite() || axis == DVec3::ZERO {
        return Err(TorusError::BadAxis(axis.as_vec3()));
    }
    Ok(())
}

/// The culls' line of a ray of either precision ([`Torus::line_to_local`]).
impl PerPrecision for Torus {
    type Out = LocalLine;
    #[inline(always)]
    fn of_f32(&self, ray: &Ray) -> LocalLine {
        self.ray_line(ray)
    }
    #[inline]
    fn of_f64(&self, ray: &DRay) -> LocalLine {
        self.dray_line(ray)
    }
}

/// A proper rotation taking the unit vector `axis` to +y.
///
/// Rows are (x̂, axis, ẑ) with x̂ ⊥ axis and ẑ = x̂ × axis, so the frame is right-handed.
fn rotation_axis_to_y(axis: DVec3) -> DMat3 {
    let (x_hat, _) = axis.any_orthonormal_pair();
    let z_hat = x_hat.cross(axis);
    DMat3::from_cols(x_hat, axis, z_hat).transpose()
}

mod affine;
#[cfg(test)]
mod tests;
