//! glam's `Vec3` and `DVec3` over lanes: one 3-vector type, [`V3`], generic over the
//! number trait [`Real`], with glam's formulas in glam's operation order, so that each
//! lane rounds exactly as the scalar code does. [`Vec3s`] (f32 lanes: the culls) and
//! [`DVec3s`] (f64 lanes: the exact intersection) are its two lane instantiations; the
//! certified f32 path uses it at width 1 and on lanes alike.

use super::lanes::{F32s, F64s};
use super::real::{Real, Sc, sc};
use pulp::Simd;
use std::ops::{Add, Mul, Sub};

/// One 3-vector per lane, structure of arrays.
#[derive(Debug, Clone, Copy)]
pub struct V3<R> {
    pub x: R,
    pub y: R,
    pub z: R,
}

/// glam's `Vec3` over f32 lanes.
pub type Vec3s<S> = V3<F32s<S>>;
/// glam's `DVec3` over f64 lanes.
pub type DVec3s<S> = V3<F64s<S>>;

impl<R: Real> V3<R> {
    /// From three lane registers.
    #[inline(always)]
    pub fn new(x: R, y: R, z: R) -> Self {
        V3 { x, y, z }
    }

    /// `Vec3::dot`: `(x·x′ + y·y′) + z·z′`.
    #[inline(always)]
    pub fn dot(self, o: Self) -> R {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// `Vec3::length_squared`, i.e. `self.dot(self)`.
    #[inline(always)]
    pub fn length_squared(self) -> R {
        self.dot(self)
    }

    /// `Vec3::cross`.
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        V3 {
            x: self.y * o.z - o.y * self.z,
            y: self.z * o.x - o.z * self.x,
            z: self.x * o.y - o.x * self.y,
        }
    }

    /// `Vec3::abs`.
    #[inline(always)]
    pub fn abs(self) -> Self {
        V3 {
            x: self.x.abs(),
            y: self.y.abs(),
            z: self.z.abs(),
        }
    }

    /// `v` in every lane, with `like`'s SIMD token (rounded to the lane type).
    #[inline(always)]
    pub fn of(like: R, v: glam::DVec3) -> Self {
        V3::new(like.k(v.x), like.k(v.y), like.k(v.z))
    }

    /// `DMat3 * DVec3` (or, from an f32 matrix, `Mat3 * Vec3`) as glam computes it:
    /// `(x_axis·v.x + y_axis·v.y) + z_axis·v.z`.
    #[inline(always)]
    pub fn rotated(self, m: &glam::DMat3) -> Self {
        let like = self.x;
        V3::of(like, m.x_axis) * self.x
            + V3::of(like, m.y_axis) * self.y
            + V3::of(like, m.z_axis) * self.z
    }

    /// `Vec3::max_element`: `max(x, max(y, z))` with glam's `a > b` selection.
    #[inline(always)]
    pub fn max_element(self) -> R {
        self.x.max_cmp(self.y.max_cmp(self.z))
    }

    /// `Vec3::min_element`: `min(x, min(y, z))` with glam's `a < b` selection.
    #[inline(always)]
    pub fn min_element(self) -> R {
        self.x.min_cmp(self.y.min_cmp(self.z))
    }

    /// `Vec3::min` (glam's selection, per component).
    #[inline(always)]
    pub fn min_cmp(self, o: Self) -> Self {
        V3 {
            x: self.x.min_cmp(o.x),
            y: self.y.min_cmp(o.y),
            z: self.z.min_cmp(o.z),
        }
    }

    /// `Vec3::max` (glam's selection, per component).
    #[inline(always)]
    pub fn max_cmp(self, o: Self) -> Self {
        V3 {
            x: self.x.max_cmp(o.x),
            y: self.y.max_cmp(o.y),
            z: self.z.max_cmp(o.z),
        }
    }

    /// `-self` per component (exact: flips the sign bits).
    #[inline(always)]
    pub fn negate(self) -> Self {
        V3::new(self.x.negate(), self.y.negate(), self.z.negate())
    }

    /// Per-component product, `Vec3 * Vec3`.
    #[inline(always)]
    pub fn mul_elem(self, o: Self) -> Self {
        V3 {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }
}

impl<S: Simd> Vec3s<S> {
    /// Every lane `v`.
    #[inline(always)]
    pub fn splat(s: S, v: glam::Vec3) -> Self {
        V3 {
            x: F32s::splat(s, v.x),
            y: F32s::splat(s, v.y),
            z: F32s::splat(s, v.z),
        }
    }
}

impl V3<Sc> {
    /// glam's `DVec3` as the scalar instantiation.
    #[inline(always)]
    pub fn from_dvec3(x: glam::DVec3) -> Self {
        V3::new(sc(x.x), sc(x.y), sc(x.z))
    }

    /// The scalar instantiation as glam's `DVec3`.
    #[inline(always)]
    pub fn to_dvec3(self) -> glam::DVec3 {
        glam::DVec3::new(self.x.v, self.y.v, self.z.v)
    }
}

impl<S: Simd> DVec3s<S> {
    /// Every lane `v`.
    #[inline(always)]
    pub fn splat(s: S, v: glam::DVec3) -> Self {
        V3 {
            x: F64s::splat(s, v.x),
            y: F64s::splat(s, v.y),
            z: F64s::splat(s, v.z),
        }
    }
}

impl<R: Real> Add for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        V3 {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl<R: Real> Sub for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        V3 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

/// `Vec3 * f32`: every component times the same lane value.
impl<R: Real> Mul<R> for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, k: R) -> Self {
        V3 {
            x: self.x * k,
            y: self.y * k,
            z: self.z * k,
        }
    }
}
