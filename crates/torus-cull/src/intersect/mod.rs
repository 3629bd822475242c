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
            let t_p = <P::Float as Scalar>::from_f64(t);
            t_p.finite().then(|| Hit {
                t: t_p,
                normal: P::from_dvec3(normal),
                point: P::from_dvec3(origin + dir * t),
                front_face: dir.dot(normal) < 0.0,
            })
        }

        #[inline(always)]
        fn from_proved(t: f64, normal: DVec3, origin: DVec3, dir: DVec3) -> Option<Hit<P>> {
            let t_p = <P::Float as Scalar>::from_f64(t);
            t_p.finite().then(|| Hit {
                t: t_p,
                normal: P::from_dvec3(normal),
                point: P::from_dvec3(origin + dir * t_p.to_f64()),
                front_face: true,
            })
        }
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
/// assert!(!occluded(&torus, &to_light.with_t_max(8.5))); // the light is above the tube
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
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_pcg::Pcg64;

    fn canonical() -> Torus {
        Torus::canonical(2.0, 1.0).unwrap()
    }

    /// The geometric outward normal at a local point near the surface: (x − c)/|x − c| with
    /// c = R·(x, 0, z)/ρ the nearest point of the tube's centre circle.
    fn geometric_normal(major: f64, x: DVec3) -> DVec3 {
        let rho = (x.x * x.x + x.z * x.z).sqrt();
        let c = DVec3::new(x.x, 0.0, x.z) * (major / rho);
        (x - c).normalize()
    }

    /// Distance from a local point to the torus surface: |‖x − c‖ − r|.
    fn surface_distance(major: f64, minor: f64, x: DVec3) -> f64 {
        let rho = (x.x * x.x + x.z * x.z).sqrt();
        ((rho - major).hypot(x.y) - minor).abs()
    }

    #[test]
    fn hand_computed_hit_along_x() {
        let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X).unwrap();
        let hit = intersect(&canonical(), &ray).expect("hits the outer equator");
        assert!((hit.t - 2.0).abs() < 1e-6, "{hit:?}");
        assert!(
            (hit.normal - Vec3::new(-1.0, 0.0, 0.0)).length() < 1e-6,
            "{hit:?}"
        );
        // All four crossings: x = −3, −1, 1, 3 → t = 2, 4, 6, 8.
        let roots = line_roots_local(
            2.0,
            1.0,
            DVec3::new(-5.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
        );
        let want = [2.0, 4.0, 6.0, 8.0];
        assert_eq!(roots.len(), 4, "{roots:?}");
        for (g, w) in roots.as_slice().iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{roots:?}");
        }
        // A non-unit direction: t in units of d.
        let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::new(4.0, 0.0, 0.0)).unwrap();
        let hit = intersect(&canonical(), &ray).unwrap();
        assert!((hit.t - 0.5).abs() < 1e-7, "{hit:?}");
        // Skala's Eq. 35 counterexample (docs/math.md, errata): hits at x = ±1.134, ±2.866.
        let roots = line_roots_local(
            2.0,
            1.0,
            DVec3::new(-6.0, 0.5, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
        );
        let h = 0.75f64.sqrt();
        let want = [-2.0 - h, -2.0 + h, 2.0 - h, 2.0 + h].map(|x| x + 6.0);
        assert_eq!(roots.len(), 4, "{roots:?}");
        for (g, w) in roots.as_slice().iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{roots:?} vs {want:?}");
        }
    }

    #[test]
    fn tangent_ray_on_top_is_a_double_root() {
        // y = r touches the top circle ρ = R at x = ±2: two double roots.
        let o = DVec3::new(-5.0, 1.0, 0.0);
        let roots = line_roots_local(2.0, 1.0, o, DVec3::X);
        assert_eq!(roots.len(), 4, "{roots:?}");
        for (g, w) in roots.as_slice().iter().zip([3.0, 3.0, 7.0, 7.0]) {
            assert!((g - w).abs() < 1e-7, "{roots:?}");
        }
        let ray = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X).unwrap();
        let hit = intersect(&canonical(), &ray).expect("tangent ray grazes the top");
        assert!((hit.t - 3.0).abs() < 1e-6, "{hit:?}");
        assert!((hit.normal - Vec3::Y).length() < 1e-6, "{hit:?}");
        // Tangent to the outer equator from above: x = R + r, along −y; double root at y = 0.
        let roots = line_roots_local(2.0, 1.0, DVec3::new(3.0, 5.0, 0.0), -DVec3::Y);
        assert_eq!(roots.len(), 2, "{roots:?}");
        for g in roots.as_slice() {
            assert!((g - 5.0).abs() < 1e-7, "{roots:?}");
        }
        // Slightly above the top: a miss.
        let ray = Ray::new(Vec3::new(-5.0, 1.0001, 0.0), Vec3::X).unwrap();
        assert!(intersect(&canonical(), &ray).is_none());
    }

    #[test]
    fn tangent_rays_in_random_poses_are_found() {
        // A radial line at height y = r touches the top circle (ρ = R) twice: double roots.
        // In a random world pose the f32 ray is tangent only up to rounding, so the line is
        // nudged by 1e-5·r: inward it must hit near the tangent point (the chord half-length
        // is √(2r·δ) ≈ 2.2e-3), outward it must miss.
        // Along the top circle instead (its tangent direction), the contact is of order
        // four (ρ − R ≈ s²/2R), so the inward-nudged hit is ⁴√-far: |t − 10| ≈ 0.095.
        let mut rng = Pcg64::seed_from_u64(0x7051_0010);
        for _ in 0..2000 {
            let axis = Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            if axis.length() < 0.1 {
                continue;
            }
            let center = Vec3::new(
                rng.random_range(-5.0..5.0),
                rng.random_range(-5.0..5.0),
                rng.random_range(-5.0..5.0),
            );
            let torus = Torus::new(center, axis, 2.0, 0.5).unwrap();
            let phi = rng.random_range(0.0..std::f32::consts::TAU);
            let (sn, cs) = phi.sin_cos();
            let radial = Vec3::new(cs, 0.0, sn);
            let along = Vec3::new(-sn, 0.0, cs);
            // Radial: the origin is at −8·radial, so the first touch is the far side's top,
            // ρ = R at −2·radial, t = 6.
            for (dir, t_hit, t_tol) in [(radial, 6.0, 3e-3), (along, 10.0, 0.12)] {
                for (nudge, hits) in [(-1e-5f32, true), (1e-5, false)] {
                    let touch = Vec3::new(2.0 * cs, 0.5 * (1.0 + nudge), 2.0 * sn);
                    let o_local = touch - 10.0 * dir;
                    let ray =
                        Ray::new(torus.point_to_world(o_local), torus.dir_to_world(dir)).unwrap();
                    let hit = intersect(&torus, &ray);
                    assert_eq!(hit.is_some(), hits, "{dir} nudge {nudge}: {hit:?}");
                    if let Some(hit) = hit {
                        assert!((hit.t - t_hit).abs() < t_tol, "{dir}: {hit:?}");
                        assert!(
                            (hit.normal - torus.axis()).length() < 2e-2,
                            "{dir}: {hit:?}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn ray_through_the_hole_along_the_axis_misses() {
        let ray = Ray::new(Vec3::new(0.0, 10.0, 0.0), -Vec3::Y).unwrap();
        assert!(intersect(&canonical(), &ray).is_none());
        assert!(line_roots_local(2.0, 1.0, DVec3::new(0.0, 10.0, 0.0), -DVec3::Y).is_empty());
        // Also the lib.rs doc example: a vertical ray onto the top of the tube at t = 9.
        let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0).unwrap();
        let ray = Ray::new(Vec3::new(4.0, 10.0, 0.0), -Vec3::Y).unwrap();
        let hit = intersect(&torus, &ray).unwrap();
        assert!((hit.t - 9.0).abs() < 1e-6);
    }

    #[test]
    fn range_is_respected() {
        let torus = canonical();
        let o = Vec3::new(-5.0, 0.0, 0.0);
        let at = |t_min: f32, t_max: f32| {
            intersect(&torus, &Ray::with_range(o, Vec3::X, t_min, t_max).unwrap()).map(|h| h.t)
        };
        let close = |a: Option<f32>, b: f32| a.is_some_and(|a| (a - b).abs() < 1e-6);
        assert!(close(at(0.0, f32::INFINITY), 2.0));
        assert!(close(at(2.5, 100.0), 4.0));
        assert!(close(at(4.5, 100.0), 6.0));
        assert!(close(at(7.0, 8.5), 8.0));
        assert!(close(at(-100.0, 100.0), 2.0));
        assert_eq!(at(8.5, 100.0), None);
        assert_eq!(at(0.0, 1.9), None);
        assert_eq!(at(2.1, 3.9), None);
        // Origin inside the tube (x = −2.5): the nearest forward hit is the exit at t = 1.5,
        // with the normal pointing out of the tube, i.e. towards +x here.
        let ray = Ray::new(Vec3::new(-2.5, 0.0, 0.0), Vec3::X).unwrap();
        let hit = intersect(&torus, &ray).unwrap();
        assert!((hit.t - 1.5).abs() < 1e-6 && (hit.normal - Vec3::X).length() < 1e-6);
        // Behind the origin only: miss.
        let ray = Ray::new(Vec3::new(5.0, 0.0, 0.0), Vec3::X).unwrap();
        assert!(intersect(&torus, &ray).is_none());
    }

    /// A random pose, R in [1e-3, 1e3] log-uniform, ν in (1.2, 10).
    fn random_torus(rng: &mut Pcg64) -> Torus {
        let major = 10f32.powf(rng.random_range(-3.0..3.0));
        let nu = rng.random_range(1.2..10.0);
        // A uniform axis by rejection from the unit ball (the harness's generators are not
        // part of the renderer build).
        let mut cube = || {
            Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
        };
        let axis = loop {
            let v = cube();
            if (0.01..=1.0).contains(&v.length_squared()) {
                break v.normalize();
            }
        };
        let center = cube() * 3.0 * major;
        Torus::new(center, axis, major, major / nu).expect("valid radii at any pose")
    }

    /// An origin in the box ±`reach`·R around the centre, and the direction from it to a
    /// point near the tube (|x|, |z| ≤ 1.5R, |y| ≤ 0.5R), unnormalized.
    fn aimed_at_the_tube(rng: &mut Pcg64, torus: &Torus, reach: f32) -> (Vec3, Vec3) {
        let big = torus.major_radius();
        let mut offset = |x: f32, y: f32| {
            Vec3::new(
                rng.random_range(-x..x),
                rng.random_range(-y..y),
                rng.random_range(-x..x),
            ) * big
        };
        let o = torus.center() + offset(reach, reach);
        let target = torus.center() + offset(1.5, 0.5);
        (o, target - o)
    }

    #[test]
    fn random_poses_hits_lie_on_the_surface_with_correct_normals() {
        // Rays from a box of ±4R aimed at random points near the torus. For each hit:
        // the local hit point is within 1e-9·R of the surface (relative to the f64 line), the
        // normal is unit to 1e-6 and within 1e-6 of the geometric normal, the hit is the
        // nearest root in range, and the f32 world hit is within 1e-5·R of the surface.
        let mut rng = Pcg64::seed_from_u64(0x7051_0011);
        let mut hits = 0;
        for _ in 0..5000 {
            let torus = random_torus(&mut rng);
            let (o, dir) = aimed_at_the_tube(&mut rng, &torus, 4.0);
            let dir = dir * rng.random_range(0.01..100.0);
            let Ok(ray) = Ray::new(o, dir) else { continue };
            let (lo, ld) = torus.line_to_local_f64(&ray);
            let (major, minor) = (
                f64::from(torus.major_radius()),
                f64::from(torus.minor_radius()),
            );
            let all = line_roots_local(major, minor, lo, ld);
            for &t in all.as_slice() {
                let dist = surface_distance(major, minor, lo + t * ld);
                assert!(
                    dist < 1e-9 * major,
                    "root off the surface by {dist}: {all:?}"
                );
            }
            let Some(hit) = intersect(&torus, &ray) else {
                assert!(all.as_slice().iter().all(|&t| t < 0.0), "missed {all:?}");
                continue;
            };
            hits += 1;
            let first = all.as_slice().iter().copied().find(|&t| t >= 0.0).unwrap();
            assert!((f64::from(hit.t) - first).abs() <= 1e-6 * first.abs().max(1e-30));
            let (t_loc, n_loc) = intersect_local(major, minor, lo, ld, 0.0, f64::INFINITY).unwrap();
            let x = lo + t_loc * ld;
            let geo = geometric_normal(major, x);
            assert!((n_loc.length() - 1.0).abs() < 1e-12);
            assert!((n_loc - geo).length() < 1e-6, "{n_loc} vs {geo}");
            assert!((hit.normal.length() - 1.0).abs() < 1e-6, "{hit:?}");
            let n_world = torus.dir_to_world(geo.as_vec3());
            assert!(
                (hit.normal - n_world).length() < 1e-5,
                "{hit:?} vs {n_world}"
            );
            let p_world = ray.at(hit.t);
            let p_loc = torus.point_to_local(p_world).as_dvec3();
            let dist = surface_distance(major, minor, p_loc);
            let tol = 1e-5 * (major + (o - torus.center()).length() as f64);
            assert!(
                dist < tol,
                "world hit off the surface by {dist} (tol {tol})"
            );
        }
        assert!(hits > 1000, "only {hits} hits");
    }

    #[test]
    fn roots_scale_with_the_torus() {
        // The same configuration at scale k: every root t scales by k (rel. 1e-6; the f32
        // world data round differently at each scale) and normals are unchanged.
        let base = Torus::new(
            Vec3::new(0.3, -0.2, 0.1),
            Vec3::new(0.2, 1.0, -0.4),
            2.0,
            0.7,
        )
        .unwrap();
        let o = Vec3::new(-6.0, 1.3, 0.4);
        let dir = Vec3::new(1.0, -0.25, 0.05);
        let ray = Ray::new(o, dir).unwrap();
        let h1 = intersect(&base, &ray).unwrap();
        let (lo, ld) = base.line_to_local_f64(&ray);
        let r1 = line_roots_local(2.0, 0.7, lo, ld);
        assert_eq!(r1.len(), 4, "{r1:?}");
        for k in [1e-3f32, 0.5e-3 * 3.0, 1.0, 37.0, 1e3] {
            let torus = Torus::new(base.center() * k, base.axis(), 2.0 * k, 0.7 * k).unwrap();
            let ray = Ray::new(o * k, dir).unwrap();
            let h = intersect(&torus, &ray).unwrap();
            assert!(
                ((h.t / k - h1.t) / h1.t).abs() < 1e-5,
                "k = {k}: {h:?} vs {h1:?}"
            );
            assert!((h.normal - h1.normal).length() < 1e-5, "k = {k}");
            // In f64 from the exact scaled line, all four roots scale to 1e-12.
            let kd = f64::from(k);
            let rk = line_roots_local(2.0 * kd, 0.7 * kd, lo * kd, ld);
            assert_eq!(rk.len(), 4);
            for (a, b) in rk.as_slice().iter().zip(r1.as_slice()) {
                assert!(
                    (a / kd - b).abs() < 1e-12 * b.abs(),
                    "k = {k}: {rk:?} vs {r1:?}"
                );
            }
        }
    }

    #[test]
    fn far_origin_finds_the_same_hit() {
        // Move the origin back by 100·R (and 1000·R) along the ray: the hit is found and
        // t_far − shift agrees with the near t to relative 1e-5.
        let mut rng = Pcg64::seed_from_u64(0x7051_0012);
        let mut checked = 0;
        for _ in 0..3000 {
            let torus = random_torus(&mut rng);
            let big = torus.major_radius();
            let (o, dir) = aimed_at_the_tube(&mut rng, &torus, 3.0);
            let dir = dir.normalize();
            let Ok(near) = Ray::new(o, dir) else { continue };
            let Some(hn) = intersect(&torus, &near) else {
                continue;
            };
            // Only origins with the whole torus in front (no root behind), so that moving the
            // origin back along the line cannot add an earlier hit.
            let (lo, ld) = torus.line_to_local_f64(&near);
            let all = line_roots_local(f64::from(big), f64::from(torus.minor_radius()), lo, ld);
            if all.as_slice().iter().any(|&t| t < 0.0) {
                continue;
            }
            // Skip grazing hits, whose position is ill-conditioned in f32 itself.
            let (_, n) = intersect_local(
                f64::from(big),
                f64::from(torus.minor_radius()),
                lo,
                ld,
                0.0,
                f64::INFINITY,
            )
            .unwrap();
            let cos = n.dot(ld.normalize()).abs();
            if cos < 0.1 {
                continue;
            }
            for back in [100.0f32, 1000.0] {
                let shift = back * big;
                let far = Ray::new(o - dir * shift, dir).unwrap();
                let hf = intersect(&torus, &far).expect("far ray must still hit");
                let t_far = f64::from(hf.t);
                let expect = f64::from(hn.t) + f64::from(shift);
                assert!(
                    ((t_far - expect) / expect).abs() < 1e-5,
                    "back {back}: {t_far} vs {expect}"
                );
                // The far f32 origin is rounded by ~6e-8·back·R; on a tube of radius r = R/ν
                // hit at incidence cos, the normal moves by about that / (r·cos).
                let n_tol = 2e-6 * f64::from(back) * f64::from(torus.nu()) / cos;
                let dn = f64::from((hf.normal - hn.normal).length());
                assert!(dn < n_tol, "back {back}: normal moved {dn} (tol {n_tol})");
            }
            checked += 1;
        }
        assert!(checked > 500, "only {checked}");
    }

    #[test]
    fn coefficients_match_the_documented_substitution() {
        // F(t) from the unscaled coefficients of docs/math.md equals R⁴·Q(u) (|d| = 1 here) at
        // u = (t|d| + o·d̂)/R, for a few t.
        let (major, minor) = (3.0, 1.25);
        let o = DVec3::new(-7.0, 0.8, 2.0);
        let d = DVec3::new(0.9, -0.1, -0.3).normalize();
        let c = quartic_coefficients_local(major, minor, o, d);
        assert_eq!((c[0], c[1]), (1.0, 0.0));
        let k = o.length_squared() + major * major - minor * minor;
        let od = o.dot(d);
        let big = [
            1.0,
            4.0 * od,
            2.0 * k + 4.0 * od * od - 4.0 * major * major * (d.x * d.x + d.z * d.z),
            4.0 * od * k - 8.0 * major * major * (o.x * d.x + o.z * d.z),
            k * k - 4.0 * major * major * (o.x * o.x + o.z * o.z),
        ];
        let ev = |c: &[f64; 5], x: f64| c.iter().fold(0.0, |a, ci| a * x + ci);
        for t in [-1.0, 0.0, 3.5, 8.0, 12.0] {
            let u = (t + od) / major;
            let lhs = ev(&big, t);
            let rhs = major.powi(4) * ev(&c, u);
            assert!(
                (lhs - rhs).abs() < 1e-9 * lhs.abs().max(1e3),
                "t = {t}: {lhs} vs {rhs}"
            );
        }
    }
}
