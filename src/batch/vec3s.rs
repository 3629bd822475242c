//! glam's `Vec3` over lanes: the same formulas, in the same operation order, so that each
//! lane rounds exactly as the scalar cull does.

use super::lanes::F32s;
use pulp::Simd;
use std::ops::{Add, Mul, Sub};

/// One 3-vector per lane, structure of arrays.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Vec3s<S: Simd> {
    pub(crate) x: F32s<S>,
    pub(crate) y: F32s<S>,
    pub(crate) z: F32s<S>,
}

impl<S: Simd> Vec3s<S> {
    /// From three lane registers.
    #[inline(always)]
    pub(crate) fn new(x: F32s<S>, y: F32s<S>, z: F32s<S>) -> Self {
        Vec3s { x, y, z }
    }

    /// Every lane `v`.
    #[inline(always)]
    pub(crate) fn splat(s: S, v: glam::Vec3) -> Self {
        Vec3s {
            x: F32s::splat(s, v.x),
            y: F32s::splat(s, v.y),
            z: F32s::splat(s, v.z),
        }
    }

    /// `Vec3::dot`: `(x·x′ + y·y′) + z·z′`.
    #[inline(always)]
    pub(crate) fn dot(self, o: Self) -> F32s<S> {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// `Vec3::length_squared`, i.e. `self.dot(self)`.
    #[inline(always)]
    pub(crate) fn length_squared(self) -> F32s<S> {
        self.dot(self)
    }

    /// `Vec3::cross`.
    #[inline(always)]
    pub(crate) fn cross(self, o: Self) -> Self {
        Vec3s {
            x: self.y * o.z - o.y * self.z,
            y: self.z * o.x - o.z * self.x,
            z: self.x * o.y - o.x * self.y,
        }
    }

    /// `Vec3::abs`.
    #[inline(always)]
    pub(crate) fn abs(self) -> Self {
        Vec3s {
            x: self.x.abs(),
            y: self.y.abs(),
            z: self.z.abs(),
        }
    }

    /// `Vec3::max_element`: `max(x, max(y, z))` with glam's `a > b` selection.
    #[inline(always)]
    pub(crate) fn max_element(self) -> F32s<S> {
        self.x.max_cmp(self.y.max_cmp(self.z))
    }

    /// `Vec3::min_element`: `min(x, min(y, z))` with glam's `a < b` selection.
    #[inline(always)]
    pub(crate) fn min_element(self) -> F32s<S> {
        self.x.min_cmp(self.y.min_cmp(self.z))
    }

    /// `Vec3::min` (glam's selection, per component).
    #[inline(always)]
    pub(crate) fn min_cmp(self, o: Self) -> Self {
        Vec3s {
            x: self.x.min_cmp(o.x),
            y: self.y.min_cmp(o.y),
            z: self.z.min_cmp(o.z),
        }
    }

    /// `Vec3::max` (glam's selection, per component).
    #[inline(always)]
    pub(crate) fn max_cmp(self, o: Self) -> Self {
        Vec3s {
            x: self.x.max_cmp(o.x),
            y: self.y.max_cmp(o.y),
            z: self.z.max_cmp(o.z),
        }
    }

    /// Per-component product, `Vec3 * Vec3`.
    #[inline(always)]
    pub(crate) fn mul_elem(self, o: Self) -> Self {
        Vec3s {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }
}

impl<S: Simd> Add for Vec3s<S> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Vec3s {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl<S: Simd> Sub for Vec3s<S> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Vec3s {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

/// `Vec3 * f32`: every component times the same lane value.
impl<S: Simd> Mul<F32s<S>> for Vec3s<S> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, k: F32s<S>) -> Self {
        Vec3s {
            x: self.x * k,
            y: self.y * k,
            z: self.z * k,
        }
    }
}
