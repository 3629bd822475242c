//! Exact ray–torus intersection: the expensive path a cull saves (timed).
//!
//! Precision practice (BRL-CAD, POV-Ray; see docs/math.md): the f32 ray goes to the torus frame in f64, the direction
//! is normalized, the origin moves to the foot point `p = o − (o·d̂)d̂` (closest to the
//! centre; this removes the cubic term) and lengths are scaled by `1/R`. Along the line
//! `x = p/R + u·d̂` the torus quartic is then depressed and monic:
//!
//! `u⁴ + c2 u² + c1 u + c0`, with `K = |p/R|² + 1 − (r/R)²`,
//! `c2 = 2K − 4(d̂x² + d̂z²)`, `c1 = −8(px d̂x + pz d̂z)/R`, `c0 = K² − 4(px² + pz²)/R²`
//! (c2 and c0 evaluated in forms that do not cancel near the surface: see `reduce`),
//!
//! and the ray parameter in units of the given direction is `t = (u·R − o·d̂)/|d|`
//! (the point is `o + t·d = p + (o·d̂ + t|d|)·d̂`).
//! Far origins cost nothing in accuracy: `u` is O(1) for every hit wherever the ray starts.

use crate::cull::Cull;
use crate::geometry::Tube;
use crate::num::V3;
use crate::num::{Sc, sc};
use crate::quartic::{RealRoots, solve_depressed_monic};
use crate::{Precision, Ray, Torus};
use nearest_hit::{Careful, nearest_hit};
use reduce::{FootLine, coefficients, foot_line};
use sealed::{FromExact, Steps};

mod all;
pub(crate) mod from_surface;
pub(crate) mod nearest_hit;
mod ray_cast;
pub(crate) mod reduce;
mod uv;
pub use all::{Crossing, Crossings, Passage, Span, Spans, intersect_all};
pub(crate) use all::{Roots, crossings_in_frame, line_crossings};
use glam::{DVec3, Vec3};
pub use ray_cast::{Culled, RayCast};
pub use uv::{SurfaceCoords, SurfaceTangents};

/// The nearest hit of a ray, in the ray's precision: [`Hit`] (`Hit<Vec3>`, f32) for a
/// [`Ray`], [`DHit`] (`Hit<DVec3>`, f64) for a [`DRay`](crate::DRay).
///
/// What a renderer shades and spawns from: where ([`Hit::point`]), which way the surface
/// faces ([`Hit::normal`], always the *outward* normal), and from which side the ray came
/// ([`Hit::front_face`]).
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, Torus, intersect};
/// let torus = Torus::canonical(4.0, 1.0)?;
/// // Down onto the top of the tube: the outside, at (4, 1, 0).
/// let down = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?;
/// let hit = intersect(&torus, &down).expect("the top of the tube");
/// assert!(hit.front_face && (hit.point - Vec3::new(4.0, 1.0, 0.0)).length() < 1e-5);
/// // From the tube's centre outwards: the inside of the tube, where the ray leaves it.
/// let out = Ray::new(Vec3::new(4.0, 0.0, 0.0), Vec3::X)?;
/// let hit = intersect(&torus, &out).expect("the outer equator, from inside");
/// assert!(!hit.front_face && (hit.normal - Vec3::X).length() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Hit<P: Precision = Vec3> {
    /// Ray parameter, in units of the ray's direction.
    pub t: P::Float,
    /// Unit outward surface normal, world space.
    pub normal: P,
    /// The hit point `o + t·d`, world space, formed in f64 from the solver's f64 `t` and
    /// rounded once to the ray's precision (so more accurate than `ray.at(hit.t)` in f32).
    /// To start a secondary ray here, call [`Torus::spawn`] with the ray and `t`, or
    /// [`Torus::spawn_from_point`] with this point: each projects it onto the surface and
    /// marks the ray as starting on it.
    pub point: P,
    /// The ray struck the outside of the tube: `d·n < 0` with `n` the outward normal (it
    /// enters the solid torus here). `false` where it leaves the solid (an origin inside
    /// the tube, or a ray spawned into it); a renderer flips the normal for shading then.
    /// On an exactly tangent hit (`d·n = 0`) it is `false`.
    pub front_face: bool,
}

/// The nearest hit of an f64 ray ([`crate::DRay`]): `t` and the normal in f64.
pub type DHit = Hit<DVec3>;

/// A ray the exact intersection and [`crate::intersect_culled`] take: [`Ray`] (f32, as a
/// renderer shoots it; hits in f32) or [`DRay`](crate::DRay) (f64 geometry; hits in f64). Sealed: the
/// two are the whole list (it is `Ray<P>` for either [`Precision`]).
pub trait TorusRay: sealed::Sealed {
    /// What a hit reports: [`Hit`] for [`Ray`], [`DHit`] for [`DRay`](crate::DRay).
    type Hit: sealed::FromExact + Copy + std::fmt::Debug + PartialEq;
    /// The ray's float type, that of a hit's `t`: `f32` for [`Ray`], `f64` for [`DRay`](crate::DRay).
    type Float;
    /// A hit's `t` ([`RayCast::cast_ray`]'s answer).
    #[must_use]
    fn hit_t(hit: &Self::Hit) -> Self::Float;
}

/// What the crate needs of a [`TorusRay`], out of the public docs.
pub(crate) mod sealed {
    use super::Hit;
    use crate::geometry::ray::sealed::Internals;
    use crate::geometry::ray::sealed::Scalar;
    use crate::{LocalLine, Precision, Ray, Torus};
    use glam::DVec3;

    /// A hit made from the exact intersection's answer.
    pub trait FromExact: Sized {
        /// The hit from the exact intersection's f64 `t` and world normal on the world
        /// line `origin + t·dir` (f64), rounded to the ray's precision; `None` when `t`
        /// does not fit its float (a hit farther along than f32, or f64, can count).
        fn from_exact(t: f64, normal: DVec3, origin: DVec3, dir: DVec3) -> Option<Self>;
        /// The hit of a root the certified f32 path proved: `t` rounded to the ray's
        /// float, the point at that `t`, and `front_face` true (the proof is a crossing
        /// from outside to inside: `crate::certified`'s `proved_hit`).
        fn from_proved(t: f64, normal: DVec3, origin: DVec3, dir: DVec3) -> Option<Self>;
    }

    impl<P: Precision> FromExact for Hit<P> {
        #[inline(always)]
        fn from_exact(t: f64, normal: DVec3, origin: DVec3, dir: DVec3) -> Option<Hit<P>> {
            rounded(t, normal, |_| origin + dir * t, dir.dot(normal) < 0.0)
        }

        #[inline(always)]
        fn from_proved(t: f64, normal: DVec3, origin: DVec3, dir: DVec3) -> Option<Hit<P>> {
            rounded(t, normal, |t_p| origin + dir * t_p, true)
        }
    }

    /// The hit at `t` rounded to the ray's float (`None` when it does not fit), with the
    /// normal and `point(t rounded, back in f64)` rounded too. The two ways of making a
    /// hit differ only in the point (at the exact `t`, or at the rounded `t` the proof
    /// is about) and in how `front_face` is known.
    #[inline(always)]
    fn rounded<P: Precision>(
        t: f64,
        normal: DVec3,
        point: impl FnOnce(f64) -> DVec3,
        front_face: bool,
    ) -> Option<Hit<P>> {
        let t_p = <P::Float as Scalar>::from_f64(t);
        t_p.finite().then(|| Hit {
            t: t_p,
            normal: P::from_dvec3(normal),
            point: P::from_dvec3(point(t_p.to_f64())),
            front_face,
        })
    }

    pub trait Sealed {
        /// The ray as a `Ray` of its precision.
        type Precision: Precision;
        fn as_ray(&self) -> &Ray<Self::Precision>;
        /// Whether an f64 `t` is finite once rounded to the ray's float (a hit the ray
        /// can report).
        fn fits(t: f64) -> bool;
        /// The slice as f32 [`Ray`]s, if that is what it is (the wavefront's lane
        /// transform to the culls' frame is written for them).
        fn as_f32_rays(rays: &[Self]) -> Option<&[Ray]>
        where
            Self: Sized;
    }

    impl<P: Precision> Sealed for Ray<P> {
        type Precision = P;
        #[inline(always)]
        fn as_ray(&self) -> &Ray<P> {
            self
        }
        #[inline(always)]
        fn fits(t: f64) -> bool {
            <P::Float as Scalar>::from_f64(t).finite()
        }
        #[inline(always)]
        fn as_f32_rays(rays: &[Ray<P>]) -> Option<&[Ray]> {
            P::as_f32_rays(rays)
        }
    }

    /// The steps of the exact intersection and of the culls, on any ray.
    pub(crate) trait Steps: Sealed {
        /// The line in the torus frame in f32, as the culls see it.
        #[inline(always)]
        fn cull_line(&self, torus: &Torus) -> LocalLine {
            torus.line_to_local(self.as_ray())
        }
        /// Origin and direction in the torus frame, in f64.
        #[inline(always)]
        fn local_f64(&self, torus: &Torus) -> (DVec3, DVec3) {
            torus.line_to_local_f64(self.as_ray())
        }
        /// `[t_min, t_max]` in f64.
        #[inline(always)]
        fn range_f64(&self) -> (f64, f64) {
            self.as_ray().range_f64()
        }
        /// The origin is a surface point ([`Ray::from_surface`]).
        #[inline(always)]
        fn on_surface(&self) -> bool {
            self.as_ray().starts_on_surface()
        }
        /// World origin and direction, in f64 (exact).
        #[inline(always)]
        fn world_f64(&self) -> (DVec3, DVec3) {
            let ray = self.as_ray();
            (ray.origin().to_dvec3(), ray.dir().to_dvec3())
        }
    }

    impl<R: Sealed + ?Sized> Steps for R {}
}

impl<P: Precision> TorusRay for Ray<P> {
    type Hit = Hit<P>;
    type Float = P::Float;
    #[inline(always)]
    fn hit_t(hit: &Hit<P>) -> P::Float {
        hit.t
    }
}

/// The foot-point line of `o + t·d` (scaled by 1/R) and its quartic's `[c2, c1, c0]`.
#[inline(always)]
fn reduce(tube: &Tube, o: DVec3, d: DVec3) -> (FootLine<Sc>, [Sc; 3]) {
    let line = foot_line(V3::from_dvec3(o), V3::from_dvec3(d), sc(tube.inv_major));
    (line, coefficients(line.p, line.dh, sc(tube.minor_rel)))
}

/// The depressed monic quartic `[1, 0, c2, c1, c0]` actually solved for a torus-frame line
/// `o + t·d` (torus of radii `major` = R, `minor` = r, axis +y, centred at 0).
///
/// Its variable `u` is the signed distance along `d̂ = d/|d|` from the foot point
/// `o − (o·d̂)d̂`, **in units of R**: `t = (u·R − o·d̂)/|d|`. Feed it to
/// [`crate::quartic::solve_quartic`] (or `solve_depressed_monic(c[2], c[3], c[4])`).
#[must_use]
pub fn quartic_coefficients_local(major: f64, minor: f64, o: DVec3, d: DVec3) -> [f64; 5] {
    let (_, [c2, c1, c0]) = reduce(&Tube::new(major, minor), o, d);
    [1.0, 0.0, c2.v, c1.v, c0.v]
}

/// Every real `t` (units of `d`, sorted, double roots twice) where the whole line
/// `o + t·d` meets the torus; torus-frame input, no range restriction.
///
/// ```
/// use glam::DVec3;
/// use torus_cull::intersect::line_roots_local;
/// // R = 2, r = 1: along the x axis from x = −5 the line crosses x = −3, −1, 1, 3.
/// let roots = line_roots_local(2.0, 1.0, DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
/// assert_eq!(roots.len(), 4);
/// for (got, want) in roots.as_slice().iter().zip([2.0, 4.0, 6.0, 8.0]) {
///     assert!((got - want).abs() < 1e-12);
/// }
/// // Roots behind the origin count too (no range), in units of the direction given.
/// let back = line_roots_local(2.0, 1.0, DVec3::new(5.0, 0.0, 0.0), DVec3::X * 2.0);
/// assert!((back.as_slice()[0] + 4.0).abs() < 1e-12); // x = −3
/// // Down the axis, through the hole: no root.
/// assert!(line_roots_local(2.0, 1.0, DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y).is_empty());
/// ```
#[must_use]
pub fn line_roots_local(major: f64, minor: f64, o: DVec3, d: DVec3) -> RealRoots {
    let (line, [c2, c1, c0]) = reduce(&Tube::new(major, minor), o, d);
    // t is increasing in u (R > 0, |d| > 0), so the order is kept.
    solve_depressed_monic(c2.v, c1.v, c0.v).map_increasing(|u| line.t_at(sc(u), sc(major)).v)
}

/// The nearest intersection with `t ∈ [t_min, t_max]` of the torus-frame line `o + t·d`
/// with the torus (R = `major`, r = `minor`, axis +y): `t` in units of `d` and the unit
/// outward normal in the torus frame.
///
/// Every root lies on the chord of the bounding sphere, `u² ≤ (1 + r/R)² − |p/R|²`, so a
/// line that misses the sphere, or whose chord lies outside the range, returns before
/// the quartic; otherwise [`crate::quartic::nearest_root_depressed`] solves for the nearest root in range.
#[inline]
#[must_use]
pub fn intersect_local(
    major: f64,
    minor: f64,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) -> Option<(f64, DVec3)> {
    intersect_reduced::<true>(&Tube::new(major, minor), o, d, t_min, t_max)
}

/// [`intersect_local`]; `CHECKED = false` skips the solver's coefficient range check,
/// for a [`Torus`] (validated: 1 < ν ≤ 1000, so past the chord test the coefficients are
/// O(1)), where the check can never fire and would only put three absolute values, two
/// maxima and a range compare in front of every solve.
#[inline(always)]
fn intersect_reduced<const CHECKED: bool>(
    tube: &Tube,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) -> Option<(f64, DVec3)> {
    let (o, d) = (V3::from_dvec3(o), V3::from_dvec3(d));
    let found = nearest_hit::<Sc, Careful<CHECKED>>(tube, o, d, sc(t_min), sc(t_max))?;
    found.hit.m.then(|| (found.t.v, found.normal.to_dvec3()))
}

/// The nearest hit with `t ∈ [t_min, t_max]`, or `None`: for a [`Ray`] a [`Hit`] in f32,
/// for a [`DRay`](crate::DRay) a [`DHit`] in f64 (nothing rounded to f32 on the way). A hit whose `t`
/// overflows the ray's float type (an origin near f32's, or f64's, largest value, aimed
/// back at the torus) is not reported: no finite `t` of that type reaches it.
///
/// Always solves the quartic in f64 (see the module docs); the normal is the unit outward
/// normal in world space.
///
/// **An origin inside the tube** (a ray that starts in the solid, or a secondary ray whose
/// origin rounded to the inside): the nearest root at or after `t_min` is where the ray
/// *leaves* the solid, and that is the hit, with the outward normal there (pointing along
/// the ray). A renderer that wants to skip the surface its ray starts on sets `t_min` to a
/// small ε. `tests/oracle/intersect_vs_oracle.rs` checks it.
///
/// ```
/// use glam::DVec3;
/// use torus_cull::{DRay, Torus, intersect};
/// // Another project's near-tangent test ray: R = 2, r = 1, the line y = 0.999999 along z.
/// let torus = Torus::canonical(2.0, 1.0)?;
/// let ray = DRay::new(DVec3::new(0.0, 0.999999, -4.0), DVec3::Z)?;
/// let hit = intersect(&torus, &ray).expect("grazes the top of the tube");
/// assert!((hit.t - 1.99858578679).abs() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[inline]
#[must_use]
pub fn intersect<R: TorusRay>(torus: &Torus, ray: &R) -> Option<R::Hit> {
    let (t, n) = exact(torus, ray)?;
    let (o, d) = ray.world_f64();
    // The rotation is orthonormal: its transpose is its inverse.
    R::Hit::from_exact(t, torus.to_local_rotation_f64().transpose() * n, o, d)
}

/// Whether the ray meets the torus at some `t ∈ [t_min, t_max]`: a shadow ray's question.
/// The same solve as [`intersect()`] (so never a different answer), with the hit's normal
/// and world transform left out.
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Ray, Torus, occluded};
/// let torus = Torus::canonical(4.0, 1.0)?;
/// let to_light = Ray::with_range(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y, 0.0, 20.0)?;
/// assert!(occluded(&torus, &to_light));
/// assert!(!occluded(&torus, &to_light.with_t_max(8.5)?)); // the light is above the tube
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[inline]
#[must_use]
pub fn occluded<R: TorusRay>(torus: &Torus, ray: &R) -> bool {
    // The same test as `FromExact`: the hit's `t` fits the ray's float.
    exact(torus, ray).is_some_and(|(t, _)| R::fits(t))
}

/// The nearest root in range and the torus-frame normal there, for either kind of ray:
/// the literal range, or from a surface point with its own root divided out
/// ([`from_surface`]).
#[inline(always)]
fn exact<R: TorusRay>(torus: &Torus, ray: &R) -> Option<(f64, DVec3)> {
    exact_in_frame(
        torus.tube(),
        ray.local_f64(torus),
        ray.range_f64(),
        ray.on_surface(),
    )
}

/// [`exact`] on the torus-frame line `line` (f64) of the ring torus `tube`, over `range`;
/// `on_surface`: the ray is marked as starting on the surface. The family's elliptical
/// ring tori come here with their image line (`crate::family`).
#[inline(always)]
pub(crate) fn exact_in_frame(
    tube: &Tube,
    line: (DVec3, DVec3),
    range: (f64, f64),
    on_surface: bool,
) -> Option<(f64, DVec3)> {
    if on_surface && from_surface::starts_on_the_surface(tube, line.0) {
        return from_surface::intersect_from_surface(tube, line, range);
    }
    let ((o, d), (t_min, t_max)) = (line, range);
    intersect_reduced::<false>(tube, o, d, t_min, t_max)
}

/// What a renderer does per torus: `cull` in the torus frame (f32), then the exact
/// intersection only if the cull keeps the ray. This is the timed `total_ns` path.
///
/// ```
/// use torus_cull::{CychoszCull, NoCull, Ray, SkalaCull, Torus, intersect_culled};
/// use glam::Vec3;
/// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?; // its cull bounds, once
/// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::new(0.1, -1.0, 0.0))?;
/// // Every conservative cull gives the same answer; skala just gets there without the quartic.
/// assert_eq!(intersect_culled(&SkalaCull, &torus, &hole), None);
/// assert_eq!(intersect_culled(&CychoszCull, &torus, &hole), None);
/// assert_eq!(intersect_culled(&NoCull, &torus, &hole), None);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[inline(always)]
#[must_use]
pub fn intersect_culled<C: Cull + ?Sized, R: TorusRay>(
    cull: &C,
    torus: &Torus,
    ray: &R,
) -> Option<R::Hit> {
    if kept_by(cull, torus, ray) {
        intersect(torus, ray)
    } else {
        None
    }
}

/// The cull step of [`intersect_culled`] (and of [`Culled`]'s queries): the ray's line in
/// the torus frame, as the culls see it, against the torus's own bounds.
#[inline(always)]
pub(crate) fn kept_by<C: Cull + ?Sized, R: TorusRay>(cull: &C, torus: &Torus, ray: &R) -> bool {
    let line = Steps::cull_line(ray, torus);
    cull.keeps(torus.bounds(), line.origin, line.dir)
}

#[cfg(test)]
mod tests;
