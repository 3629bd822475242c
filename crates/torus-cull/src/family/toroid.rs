//! The family member: pose, semi-axes, validation, and its circular image.

use crate::cull::Shape;
use crate::{LocalLine, Precision, Ray, RayError, Torus, TorusError};
use glam::{DVec3, Vec3};
use std::fmt;

/// The smallest tube aspect `b/a` accepted, 1/4: the edge of what the tests prove
/// (the exact intersection and every cull against the family oracle).
pub const MIN_ASPECT: f64 = 0.25;

/// The largest tube aspect `b/a` accepted, 4.
pub const MAX_ASPECT: f64 = 4.0;

/// The smallest `ν = R/a` accepted, 1/100: the fattest spindle the tests prove (the exact
/// intersection and every cull that takes a spindle against the family oracle, at
/// ν = 0.01, 0.1, 0.3 and 0.5, docs/family.md). Bevy and POV-Ray take any 0 < R < a; below 1/100 the apple and the lemon
/// inside it are within 2R < a/50 of each other everywhere, and the library refuses
/// rather than answers untested. (Ring members keep [`crate::MAX_NU`] as their thinnest.)
pub const MIN_FAMILY_NU: f64 = 0.01;

/// Which member of the family: Bevy's `TorusKind` without `Invalid` (refused instead).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ToroidKind {
    /// R > a: a hole through the middle.
    Ring,
    /// R = a: the tube meets itself at the centre.
    Horn,
    /// R < a: the tube overlaps itself; the surface is the outer "apple".
    Spindle,
}

/// A torus of the family in the world: centre, unit rotation axis, major radius R and an
/// elliptical tube with semi-axes `a` = `radial_semi_axis` (in the equatorial plane) and
/// `b` = `axial_semi_axis` (along the axis). The solid is `((ρ − R)/a)² + (y/b)² ≤ 1` in
/// the torus frame (centre at the origin, axis +y, ρ ≥ 0 the distance from the axis).
///
/// A ring member has R > a; R = a is the horn and R < a the spindle, whose surface is the
/// apple (module docs of [`crate::family`]). Accepted: `MIN_FAMILY_NU` ≤ R/a ≤
/// [`crate::MAX_NU`], [`MIN_ASPECT`] ≤ b/a ≤ [`MAX_ASPECT`], and R + a within
/// [`crate::Torus`]'s size range.
///
/// ```
/// use glam::{DVec3, Vec3};
/// use torus_cull::family::{Toroid, ToroidKind};
/// use torus_cull::{DRay, Passage};
/// // An OpenMC z-torus A = 4, B = 0.5 (along the axis), C = 1 (radial).
/// let flat = Toroid::canonical(4.0, 1.0, 0.5)?;
/// let down = DRay::new(DVec3::new(4.0, 3.0, 0.0), DVec3::NEG_Y)?;
/// assert!((flat.intersect(&down).unwrap().t - 2.5).abs() < 1e-12); // y = b
/// // A spindle (R < a): through the centre along x, only the apple is crossed.
/// let spindle = Toroid::canonical(0.5, 1.0, 1.0)?;
/// assert_eq!(spindle.kind(), ToroidKind::Spindle);
/// let across = DRay::new(DVec3::new(-3.0, 0.0, 0.0), DVec3::X)?;
/// let all = spindle.intersect_all(&across);
/// let ts: Vec<f64> = all.as_slice().iter().map(|c| c.t).collect();
/// assert_eq!(ts.len(), 2); // x = ∓1.5; the lemon's x = ∓0.5 is no surface
/// assert!((ts[0] - 1.5).abs() < 1e-12 && (ts[1] - 4.5).abs() < 1e-12);
/// assert_eq!(all.as_slice()[0].passage, Passage::Enter);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Toroid {
    /// The circular torus (R, a) in the same pose: the image under `y ↦ y·a/b`.
    image: Torus,
    /// b.
    axial: f64,
    /// a/b: the image's y per member's y; exactly 1 for a circular tube.
    y_scale: f64,
    kind: ToroidKind,
}

/// Why a family member was refused.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ToroidError {
    /// A radius or semi-axis is NaN, infinite, zero or negative.
    BadRadius {
        /// `major_radius`, `radial_semi_axis` or `axial_semi_axis`.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// `b/a` outside [`MIN_ASPECT`] ..= [`MAX_ASPECT`].
    Aspect {
        /// a as given.
        radial_semi_axis: f64,
        /// b as given.
        axial_semi_axis: f64,
    },
    /// `R/a` below [`MIN_FAMILY_NU`]: a spindle fatter than the tests prove.
    TooFat {
        /// R as given.
        major_radius: f64,
        /// a as given.
        radial_semi_axis: f64,
    },
    /// The pose or the size, as [`crate::Torus`] refuses them for the circular image
    /// (R, a): a bad centre or axis, R + a out of range, R/a above [`crate::MAX_NU`].
    Torus(TorusError),
    /// A path that takes a [`crate::Torus`] (SIMD lanes, certified f32, the GPU) was asked
    /// for a member that is not a circular ring torus.
    NotCircular {
        /// The member's kind.
        kind: ToroidKind,
        /// b/a.
        aspect: f64,
    },
}

impl fmt::Display for ToroidError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ToroidError::BadRadius { name, value } => {
                write!(f, "{name} = {value} is invalid (must be finite and > 0)")
            }
            ToroidError::Aspect {
                radial_semi_axis,
                axial_semi_axis,
            } => write!(
                f,
                "axial_semi_axis / radial_semi_axis = {axial_semi_axis} / {radial_semi_axis} = {} \
                 is outside the supported range {MIN_ASPECT} ..= {MAX_ASPECT}",
                axial_semi_axis / radial_semi_axis
            ),
            ToroidError::TooFat {
                major_radius,
                radial_semi_axis,
            } => write!(
                f,
                "major_radius / radial_semi_axis = {major_radius} / {radial_semi_axis} = {} is \
                 below the supported {MIN_FAMILY_NU} (allowed: {MIN_FAMILY_NU} <= nu <= {})",
                major_radius / radial_semi_axis,
                crate::MAX_NU
            ),
            ToroidError::Torus(e) => write!(f, "{e}"),
            ToroidError::NotCircular { kind, aspect } => write!(
                f,
                "a {} torus with tube aspect b/a = {aspect} is not a circular ring torus: \
                 this path (SIMD lanes, certified f32, GPU) takes ring tori with a = b only",
                match kind {
                    ToroidKind::Ring => "ring",
                    ToroidKind::Horn => "horn",
                    ToroidKind::Spindle => "spindle",
                }
            ),
        }
    }
}

impl std::error::Error for ToroidError {}

impl From<TorusError> for ToroidError {
    fn from(e: TorusError) -> ToroidError {
        ToroidError::Torus(e)
    }
}

/// A ring torus is the family's circular member: the same answers, bit for bit.
impl From<Torus> for Toroid {
    fn from(image: Torus) -> Toroid {
        Toroid {
            axial: image.minor_radius_f64(),
            image,
            y_scale: 1.0,
            kind: ToroidKind::Ring,
        }
    }
}

impl Toroid {
    /// A member at `center` with rotation `axis` (normalized here), R = `major_radius`,
    /// a = `radial_semi_axis`, b = `axial_semi_axis`, all f32 (the circular ring member
    /// is [`crate::Torus::new`]'s torus).
    pub fn new(
        center: Vec3,
        axis: Vec3,
        major_radius: f32,
        radial_semi_axis: f32,
        axial_semi_axis: f32,
    ) -> Result<Toroid, ToroidError> {
        Toroid::build(
            (center.as_dvec3(), axis.as_dvec3()),
            f64::from(major_radius),
            f64::from(radial_semi_axis),
            f64::from(axial_semi_axis),
            false,
        )
    }

    /// [`Toroid::new`] from f64 geometry, kept in f64 (as [`crate::Torus::new_f64`]).
    pub fn new_f64(
        center: DVec3,
        axis: DVec3,
        major_radius: f64,
        radial_semi_axis: f64,
        axial_semi_axis: f64,
    ) -> Result<Toroid, ToroidError> {
        Toroid::build(
            (center, axis),
            major_radius,
            radial_semi_axis,
            axial_semi_axis,
            true,
        )
    }

    /// The member in its own frame (centre at the origin, axis +y), from f64 values.
    pub fn canonical(
        major_radius: f64,
        radial_semi_axis: f64,
        axial_semi_axis: f64,
    ) -> Result<Toroid, ToroidError> {
        Toroid::new_f64(
            DVec3::ZERO,
            DVec3::Y,
            major_radius,
            radial_semi_axis,
            axial_semi_axis,
        )
    }

    fn build(
        (center, axis): (DVec3, DVec3),
        major: f64,
        radial: f64,
        axial: f64,
        f64_geometry: bool,
    ) -> Result<Toroid, ToroidError> {
        for (name, value) in [
            ("major_radius", major),
            ("radial_semi_axis", radial),
            ("axial_semi_axis", axial),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ToroidError::BadRadius { name, value });
            }
        }
        let aspect = axial / radial;
        if !(MIN_ASPECT..=MAX_ASPECT).contains(&aspect) {
            return Err(ToroidError::Aspect {
                radial_semi_axis: radial,
                axial_semi_axis: axial,
            });
        }
        // From f32 radii, ν as f32 divides it: 0.01 typed in f32 (0.0099999998) is 1/100.
        let too_fat = if f64_geometry {
            major / radial < MIN_FAMILY_NU
        } else {
            (major as f32) / (radial as f32) < MIN_FAMILY_NU as f32
        };
        if too_fat {
            return Err(ToroidError::TooFat {
                major_radius: major,
                radial_semi_axis: radial,
            });
        }
        let image = Torus::image(center, axis, major, radial, f64_geometry)?;
        // The kind of the member as stored (an f32 member's radii rounded).
        let (major, radial) = (image.major_radius_f64(), image.minor_radius_f64());
        let axial = if f64_geometry {
            axial
        } else {
            f64::from(axial as f32)
        };
        let kind = if major > radial {
            ToroidKind::Ring
        } else if major == radial {
            ToroidKind::Horn
        } else {
            ToroidKind::Spindle
        };
        Ok(Toroid {
            image,
            axial,
            y_scale: if axial == radial { 1.0 } else { radial / axial },
            kind,
        })
    }

    /// Ring, horn or spindle.
    #[inline]
    #[must_use]
    pub const fn kind(&self) -> ToroidKind {
        self.kind
    }

    /// The row of the cull table's `shapes` column this member needs.
    #[inline]
    #[must_use]
    pub const fn shape(&self) -> Shape {
        match self.kind {
            ToroidKind::Ring if self.y_scale == 1.0 => Shape::Ring,
            ToroidKind::Ring => Shape::Elliptic,
            ToroidKind::Horn | ToroidKind::Spindle => Shape::Spindle,
        }
    }

    /// R.
    #[inline]
    #[must_use]
    pub const fn major_radius_f64(&self) -> f64 {
        self.image.major_radius_f64()
    }

    /// a, the tube's semi-axis in the equatorial plane.
    #[inline]
    #[must_use]
    pub const fn radial_semi_axis_f64(&self) -> f64 {
        self.image.minor_radius_f64()
    }

    /// b, the tube's semi-axis along the axis.
    #[inline]
    #[must_use]
    pub const fn axial_semi_axis_f64(&self) -> f64 {
        self.axial
    }

    /// ν = R/a.
    #[inline]
    #[must_use]
    pub fn nu(&self) -> f64 {
        self.major_radius_f64() / self.radial_semi_axis_f64()
    }

    /// The tube's aspect b/a.
    #[inline]
    #[must_use]
    pub fn aspect(&self) -> f64 {
        self.axial / self.radial_semi_axis_f64()
    }

    /// The centre in world space, f64.
    #[inline]
    #[must_use]
    pub const fn center_f64(&self) -> DVec3 {
        self.image.center_f64()
    }

    /// The unit axis in world space, f64.
    #[inline]
    #[must_use]
    pub fn axis_f64(&self) -> DVec3 {
        self.image.axis_f64()
    }

    /// The world box `(min, max)` that holds the solid. It lies in the Minkowski sum of
    /// the core circle (radius R, across the unit axis n) and the spheroid with semi-axes
    /// a, a across n and b along n (each meridian ellipse lies in the spheroid centred at
    /// its core point), whose half-width along the world axis e_i is `R·√(1 − n_i²) +
    /// √(a²·(1 − n_i²) + b²·n_i²)` (support functions add; for a = b,
    /// [`Torus::world_aabb`]'s `R·√(1 − n_i²) + r`). Formed in f64, widened by 10⁻¹⁵ of
    /// the coordinates' size for f64's rounding, and rounded outward to f32.
    #[must_use]
    pub fn world_aabb(&self) -> (Vec3, Vec3) {
        use crate::num::round::{down, up};
        let (c, n) = (self.center_f64(), self.axis_f64());
        let (major, a, b) = (
            self.major_radius_f64(),
            self.radial_semi_axis_f64(),
            self.axial_semi_axis_f64(),
        );
        let across = (DVec3::ONE - n * n).max(DVec3::ZERO);
        let tube = (across * (a * a) + n * n * (b * b)).sqrt();
        let half = across.sqrt() * major + tube;
        let slack = (c.abs() + half) * 1e-15;
        let (lo, hi) = (c - half - slack, c + half + slack);
        (
            Vec3::new(down(lo.x), down(lo.y), down(lo.z)),
            Vec3::new(up(hi.x), up(hi.y), up(hi.z)),
        )
    }

    /// The member as a [`crate::Torus`], for the paths that take one (SIMD lanes,
    /// certified f32, the GPU): only a circular ring member is one.
    ///
    /// # Errors
    ///
    /// [`ToroidError::NotCircular`] for an elliptical tube or a horn or spindle.
    pub fn as_torus(&self) -> Result<&Torus, ToroidError> {
        if self.shape() == Shape::Ring {
            Ok(&self.image)
        } else {
            Err(ToroidError::NotCircular {
                kind: self.kind,
                aspect: self.aspect(),
            })
        }
    }

    /// The circular image (R, a) in the same pose (module docs of [`crate::family`]).
    #[inline(always)]
    pub(crate) const fn image(&self) -> &Torus {
        &self.image
    }

    /// The ray's line in the image frame, f64: the torus frame with y scaled by a/b.
    #[inline(always)]
    pub(crate) fn image_line_f64<P: Precision>(&self, ray: &Ray<P>) -> (DVec3, DVec3) {
        let (o, d) = self.image.line_to_local_f64(ray);
        if self.y_scale == 1.0 {
            return (o, d);
        }
        let s = DVec3::new(1.0, self.y_scale, 1.0);
        (o * s, d * s)
    }

    /// The member's outward world normal from the image's torus-frame one: `Sᵀ n`,
    /// normalized, then rotated to the world.
    #[inline(always)]
    pub(crate) fn normal_to_world(&self, n: DVec3) -> DVec3 {
        let n = if self.y_scale == 1.0 {
            n
        } else {
            DVec3::new(n.x, n.y * self.y_scale, n.z).normalize()
        };
        self.image.to_local_rotation_f64().transpose() * n
    }

    /// The ray's line as the culls see it: the image's line in the torus frame
    /// ([`crate::Torus::line_to_local`]) with y scaled by a/b in f32. The scaling's extra
    /// rounding, at most 2⁻²⁴ of the line's coordinates (within 64·(R + a) of the centre,
    /// or the foot point), is below 2⁻¹⁷·(R + a), far inside the culls' margin
    /// η = 2⁻¹²·(R + a) of the image torus.
    #[inline(always)]
    #[must_use]
    pub fn line_to_local<P: Precision>(&self, ray: &Ray<P>) -> LocalLine {
        let line = self.image.line_to_local(ray);
        if self.y_scale == 1.0 {
            return line;
        }
        let s = Vec3::new(1.0, self.y_scale as f32, 1.0);
        LocalLine {
            origin: line.origin * s,
            dir: line.dir * s,
        }
    }

    /// A surface point near `p` (world, f64): the image torus's nearest surface point
    /// mapped back. For a circular tube it is the nearest point
    /// ([`crate::Torus::nearest_surface_point`]); for an elliptical one (whose nearest
    /// point solves a quartic) it is a point of the surface within
    /// `max(a/b, b/a)·dist(p, surface)` of `p`, as the map scales lengths by at most
    /// `max(1, a/b)` one way and `max(1, b/a)` back. A point on the axis or the core
    /// circle is returned unchanged.
    #[must_use]
    pub fn surface_point_near(&self, p: DVec3) -> DVec3 {
        if self.y_scale == 1.0 {
            return self.image.nearest_surface_point(p);
        }
        let Ok(local) = self.image.point_to_local_f64(p) else {
            return p;
        };
        let image = DVec3::new(local.x, local.y * self.y_scale, local.z);
        match self.image.tube().nearest_surface_point(image) {
            Some(on) => self
                .image
                .point_to_world_f64(DVec3::new(on.x, on.y / self.y_scale, on.z)),
            None => p,
        }
    }

    /// The secondary ray leaving the hit at `t` on `ray` in direction `dir`, marked as
    /// starting on the surface (as [`crate::Torus::spawn`]): its origin is the point at
    /// `t` moved onto the surface ([`Toroid::surface_point_near`]).
    ///
    /// # Errors
    ///
    /// A [`RayError`] as [`crate::Torus::spawn`]'s, never a panic or a NaN ray; size is
    /// R + max(a, b) in `OffSurface`'s tolerance, the distance [`Toroid::signed_distance`]'s
    /// (every member has one).
    pub fn spawn<P: Precision>(
        &self,
        ray: &Ray<P>,
        t: P::Float,
        dir: P,
    ) -> Result<Ray<P>, RayError<P>> {
        let size =
            self.major_radius_f64() + self.radial_semi_axis_f64().max(self.axial_semi_axis_f64());
        ray.spawn_onto(
            t,
            dir,
            size,
            |at| self.distance_at_least(at),
            |at| self.surface_point_near(at),
        )
    }
}
