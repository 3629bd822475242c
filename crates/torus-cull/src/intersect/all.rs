//! Every crossing of a ray with the torus, paired into the spans where the ray is inside
//! the solid: the query CSG, transport and CAD need (BRL-CAD's `tor.c` returns the same
//! segments).
//!
//! **Method.** The same line as the nearest hit (module docs of [`super`]): the foot-point
//! frame scaled by 1/R, the bounding sphere's chord test, and the depressed quartic, here
//! solved for all its real roots ([`solve_depressed_monic`]: Ferrari with near-double
//! factors decided on the quartic itself, then Newton-polished). For a ray from a surface
//! point ([`Ray::from_surface`](crate::Ray::from_surface)) the origin's root is divided
//! out as in `from_surface.rs` and the other roots are the cubic's ([`cubic_roots`]).
//!
//! **Entering or leaving** is not read off the sign of `d·n`, which rounding decides at a
//! grazing crossing. The whole line's roots are sorted, and the line is outside the solid
//! at `u → −∞`; each simple root flips inside/outside and a double root (a tangent) does
//! not. So the side at `t_min` is the parity of the simple roots before it, and the
//! crossings in range alternate, entering first, by construction: a span can only be
//! wrong where a root is missed, which the tests check against the oracle.

use super::from_surface::{SurfaceCubic, cubic_roots, starts_on_the_surface};
use super::reduce::{coefficients, foot_line, normal};
use crate::geometry::ray::sealed::Scalar;
use crate::geometry::{SpanOf, Tube, pair_spans};
use crate::num::{Sc, V3, fixed_list, sc};
use crate::quartic::solve_depressed_monic;
use crate::{Precision, Ray, Torus};
use glam::{DVec3, Vec3};
use std::cmp::Ordering;

/// How a ray meets the surface at a [`Crossing`] (the solids' one passage type).
pub use crate::geometry::Passage;

/// One crossing of a ray with the torus surface, in the ray's precision.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Crossing<P: Precision = Vec3> {
    /// Ray parameter, in units of the ray's direction.
    pub t: P::Float,
    /// Unit outward surface normal, world space.
    pub normal: P,
    /// Whether the ray enters, leaves or touches the solid here.
    pub passage: Passage,
}

/// A stretch `[t_enter, t_exit]` of the ray's range inside the solid torus ([`SpanOf`],
/// the one span type of every solid, over the torus's [`Crossing`]).
pub type Span<P = Vec3> = SpanOf<<P as Precision>::Float, Crossing<P>>;

/// Every crossing of a ray with the torus in `[t_min, t_max]`, sorted by `t` (at most
/// four: a quartic's roots), and the ray's side at `t_min`: what [`intersect_all`]
/// returns. Fixed capacity, no allocation.
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use]
pub struct Crossings<P: Precision = Vec3> {
    crossings: [Crossing<P>; 4],
    len: usize,
    starts_inside: bool,
    t_min: P::Float,
    t_max: P::Float,
}

/// The spans of a [`Crossings`] (at most two: a line crosses the surface at most four
/// times). Fixed capacity, no allocation.
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use]
pub struct Spans<P: Precision = Vec3> {
    spans: [Span<P>; 2],
    len: usize,
}

impl<P: Precision> Crossings<P> {
    /// No crossing, outside at `t_min`, over the ray's range.
    pub(crate) fn none(ray: &Ray<P>) -> Crossings<P> {
        Crossings {
            crossings: [Crossing {
                t: <P::Float as Scalar>::ZERO,
                normal: P::ZERO,
                passage: Passage::Touch,
            }; 4],
            len: 0,
            starts_inside: false,
            t_min: ray.t_min(),
            t_max: ray.t_max(),
        }
    }

    /// Whether the ray is inside the solid torus at `t_min` (for a ray from a surface
    /// point: just past its origin).
    #[inline]
    #[must_use]
    pub fn starts_inside(&self) -> bool {
        self.starts_inside
    }

    /// The crossings paired into the stretches of the range inside the solid, ascending
    /// (`pair_spans`, as every solid's). Touches open no span.
    pub fn spans(&self) -> Spans<P> {
        let mut spans = [SpanOf::EMPTY; 2];
        let crossings = self.iter().map(|&c| (c.t, c.passage, c));
        let len = pair_spans(crossings, self.starts_inside, self.range(), &mut spans);
        Spans { spans, len }
    }

    /// The ray's range `[t_min, t_max]` the crossings were found in.
    #[inline]
    #[must_use]
    pub fn range(&self) -> (P::Float, P::Float) {
        (self.t_min, self.t_max)
    }
}

fixed_list! {
    /// The crossings, ascending in `t`: entries and exits alternate (an entry first unless
    /// [`Crossings::starts_inside`]), with touches anywhere between them (0 to 4; a touch
    /// counts once).
    impl[P: Precision] Crossings<P>, crossings: [Crossing<P>], "crossings"
}

fixed_list! {
    /// The spans, ascending (0 to 2).
    impl[P: Precision] Spans<P>, spans: [Span<P>], "spans"
}

/// A root of the whole line's quartic in the foot-point frame, at `key`: `u`, or for a ray
/// from a surface point `v = u − own root`.
#[derive(Debug, Clone, Copy)]
struct LineRoot {
    key: f64,
    double: bool,
    /// The origin's own root of a ray from a surface point: counted for the side, never
    /// reported.
    origin: bool,
    /// A spindle's cusp where the line passes it ([`with_cusps`]): reported only where
    /// the side changes there, never as a touch.
    cusp: bool,
}

/// Every crossing of `ray` with the torus in `[t_min, t_max]`, sorted, each with its `t`,
/// its world normal and whether the ray enters or leaves the solid there, in the ray's
/// precision ([`Ray`]: f32, [`DRay`](crate::DRay): f64); [`Crossings::spans`] pairs them
/// into the stretches inside the solid.
///
/// - A ray that starts inside begins with a span opened at `t_min`
///   ([`Crossings::starts_inside`]); one that ends inside, with a span closed at `t_max`.
/// - A tangent (a double root, decided within rounding on the quartic itself, as
///   [`crate::quartic::solve_depressed_monic`] decides it) is one [`Passage::Touch`]
///   crossing, not a span of zero length. A line that dips in by less than rounding can
///   as well come back as a touch or as a pair of crossings a few ulps apart: that is as
///   far as f64 resolves it.
/// - A ray from a surface point ([`Ray::from_surface`](crate::Ray::from_surface)) has its
///   origin's root divided out, as in [`crate::intersect()`]: the crossings are those with
///   `t > 0`, and [`Crossings::starts_inside`] is the side just past the origin (an
///   origin farther than 10⁻²·R from the surface is no surface point: that ray is
///   answered literally, as there).
/// - A crossing whose `t` overflows the ray's float is left out (it lies past every finite
///   `t`, so a span it would close runs to `t_max`): never ∞ or NaN.
///
/// Its first crossing is [`crate::intersect()`]'s hit, up to the last Newton step (the
/// nearest-root query skips it).
///
/// ```
/// use glam::Vec3;
/// use torus_cull::{Passage, Ray, Torus, intersect_all};
/// let torus = Torus::canonical(2.0, 1.0)?;
/// // Along the x axis from x = −5: through the tube at x = −3 … −1, then at 1 … 3.
/// let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X)?;
/// let all = intersect_all(&torus, &ray);
/// let ts: Vec<f32> = all.as_slice().iter().map(|c| c.t).collect();
/// assert_eq!(ts, [2.0, 4.0, 6.0, 8.0]);
/// assert_eq!(all.as_slice()[0].passage, Passage::Enter);
/// assert_eq!(all.as_slice()[0].normal, Vec3::NEG_X);
/// let spans = all.spans();
/// assert_eq!(spans.len(), 2);
/// assert_eq!((spans.as_slice()[1].t_enter, spans.as_slice()[1].t_exit), (6.0, 8.0));
/// // From inside the tube (x = −2), with the range cut at t = 4.5: a span open at t_min,
/// // then one cut at t_max.
/// let inside = Ray::with_range(Vec3::new(-2.0, 0.0, 0.0), Vec3::X, 0.0, 4.5)?;
/// let all = intersect_all(&torus, &inside);
/// assert!(all.starts_inside());
/// let spans = all.spans();
/// let ends: Vec<(f32, f32)> = spans.as_slice().iter().map(|s| (s.t_enter, s.t_exit)).collect();
/// assert_eq!(ends, [(0.0, 1.0), (3.0, 4.5)]);
/// assert!(spans.as_slice()[0].enter.is_none() && spans.as_slice()[1].exit.is_none());
/// // Over the top of the tube, y = r: two touches, no span.
/// let over = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X)?;
/// let all = intersect_all(&torus, &over);
/// assert_eq!(all.len(), 2);
/// assert!(all.as_slice().iter().all(|c| c.passage == Passage::Touch));
/// assert!(all.spans().is_empty());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn intersect_all<P: Precision>(torus: &Torus, ray: &Ray<P>) -> Crossings<P> {
    let to_world = torus.to_local_rotation_f64().transpose();
    let line = torus.line_to_local_f64(ray);
    crossings_in_frame(ray, torus.tube(), line, Roots::All, |n| to_world * n)
}

/// Which of the quartic's roots are crossings of the surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Roots {
    /// Every root: a ring torus (R > r), whose quartic is its surface.
    All,
    /// The apple's roots alone: a horn or spindle (R ≤ r), whose quartic also holds the
    /// inner lemon `(ρ + R)² + y² = r²`, no surface of the solid ([`apple`]).
    Apple,
}

/// [`intersect_all`] of `ray` on the torus-frame line `line` (f64) of the circular torus
/// `tube`, its range the ray's; `to_world` takes a torus-frame outward normal to the
/// world (a family member's image frame adds its y scale there: `crate::family`).
pub(crate) fn crossings_in_frame<P: Precision>(
    ray: &Ray<P>,
    tube: &Tube,
    line: (DVec3, DVec3),
    roots_kept: Roots,
    to_world: impl Fn(DVec3) -> DVec3,
) -> Crossings<P> {
    let (t_min, t_max) = ray.range_f64();
    let mut out = Crossings::none(ray);
    let mut emit = |t: f64, n: DVec3, passage: Passage| {
        let t = <P::Float as Scalar>::from_f64(t);
        if t.finite() && out.len < 4 {
            out.crossings[out.len] = Crossing {
                t,
                normal: P::from_dvec3(to_world(n)),
                passage,
            };
            out.len += 1;
        }
    };
    out.starts_inside = line_crossings(
        tube,
        line,
        (t_min, t_max),
        ray.starts_on_surface(),
        roots_kept,
        &mut emit,
    );
    out
}

/// The crossings of the torus-frame line `line` (f64) of the circular torus `tube` within
/// `(t_min, t_max)`, in order, each handed to `emit` with its `t`, its torus-frame outward
/// normal and its passage; returns whether the range starts inside the solid.
/// `on_surface`: the ray is marked as starting on the surface (its own root divided out
/// where its origin is one).
pub(crate) fn line_crossings(
    tube: &Tube,
    line: (DVec3, DVec3),
    (t_min, t_max): (f64, f64),
    on_surface: bool,
    roots_kept: Roots,
    mut emit: impl FnMut(f64, DVec3, Passage),
) -> bool {
    if on_surface && starts_on_the_surface(tube, line.0) {
        let g = SurfaceCubic::new(tube, line);
        let (lo, hi) = g.v_range(t_min, t_max);
        let (cubic, n) = cubic_roots(g.a3, g.a2, g.a1);
        let mut roots = [LineRoot {
            key: 0.0,
            double: false,
            origin: true,
            cusp: false,
        }; 4];
        for (slot, &(v, double)) in roots[1..].iter_mut().zip(&cubic[..n]) {
            *slot = LineRoot {
                key: v,
                double,
                origin: false,
                cusp: false,
            };
        }
        let mut n = n + 1;
        if roots_kept == Roots::Apple {
            let at = |v: f64| g.line.p + g.line.dh * sc(g.own + v);
            n = keep_apple(&mut roots[..n], |r| at(r.key), tube.k);
        }
        let roots = &mut roots[..n];
        roots.sort_by(|a, b| a.key.total_cmp(&b.key));
        let point = |v: f64| g.line.p + g.line.dh * sc(g.own + v);
        // Past the origin only: v > 0, and v ≥ lo.
        let range = |v: f64| {
            if v <= 0.0 || v < lo {
                Place::Before
            } else if v <= hi {
                Place::Within
            } else {
                Place::After
            }
        };
        let emit = |r: &LineRoot, passage| emit(g.t_at(r.key), g.normal(tube, r.key), passage);
        match roots_kept {
            Roots::All => walk(roots, range, emit),
            Roots::Apple => walk_by_side(roots, range, |v| in_apple(point(v), tube), emit),
        }
    } else {
        let (o, d) = line;
        let line = foot_line(V3::from_dvec3(o), V3::from_dvec3(d), sc(tube.inv_major));
        // A line that misses the bounding sphere has no root: no solve.
        if line.chord_sq(sc(tube.outer)).v < 0.0 {
            return false;
        }
        let (lo, hi) = line.u_range(sc(t_min), sc(t_max), sc(tube.inv_major));
        let (lo, hi) = (lo.v, hi.v);
        let [c2, c1, c0] = coefficients(line.p, line.dh, sc(tube.minor_rel));
        let found = solve_depressed_monic(c2.v, c1.v, c0.v);
        let (mut roots, mut n) = pair_doubles(found.as_slice());
        let apple = if roots_kept == Roots::Apple {
            n = keep_apple(&mut roots[..n], |r| line.p + line.dh * sc(r.key), tube.k);
            let at = |u: f64| (line.p + line.dh * sc(u)).to_dvec3();
            with_cusps(&roots[..n], line.dh.to_dvec3(), at, tube)
        } else {
            ([CUSP_FREE; 6], 0)
        };
        let range = |u: f64| {
            if u < lo {
                Place::Before
            } else if u <= hi {
                Place::Within
            } else {
                Place::After
            }
        };
        let emit = |r: &LineRoot, passage| {
            let u = sc(r.key);
            let t = line.t_at(u, sc(tube.major)).v;
            // At a cusp the surface has no normal (∇F = 0): the bisector of the two arcs'
            // normals, along the axis (as the point queries give it).
            // (A solver's root right at a cusp has ∇F = 0 too: the same.)
            let n = normal(line.p, line.dh, u, sc(tube.k)).to_dvec3();
            let n = if r.cusp || !n.is_finite() {
                DVec3::new(0.0, (line.p + line.dh * u).y.v.signum(), 0.0)
            } else {
                n
            };
            emit(t, n, passage);
        };
        match roots_kept {
            Roots::All => walk(&roots[..n], range, emit),
            Roots::Apple => walk_by_side(
                &apple.0[..apple.1],
                range,
                |u| in_apple(line.p + line.dh * sc(u), tube),
                emit,
            ),
        }
    }
}

/// The sorted roots of the whole line (a double root given twice, as the solver gives
/// it) with each exactly repeated pair merged into one double root.
fn pair_doubles(sorted: &[f64]) -> ([LineRoot; 4], usize) {
    let mut out = [LineRoot {
        key: 0.0,
        double: false,
        origin: false,
        cusp: false,
    }; 4];
    let (mut n, mut i) = (0, 0);
    while i < sorted.len() {
        let u = sorted[i];
        let double = i + 1 < sorted.len() && sorted[i + 1] == u;
        out[n] = LineRoot {
            key: u,
            double,
            origin: false,
            cusp: false,
        };
        n += 1;
        i += if double { 2 } else { 1 };
    }
    (out, n)
}

/// Keeps the apple's roots of `roots` in place, in order, and returns how many: a root at
/// the scaled point `x` (units of R) is the apple's where `s = |x|² + 1 − (r/R)² ≥ 0`.
///
/// On the quartic `s² = 4ρ²` (R = 1), and `s = 2ρ` on the apple `(ρ − 1)² + y² = rr²`,
/// `s = −2ρ` on the lemon `(ρ + 1)² + y² = rr²`: the two meet only on the axis (ρ = 0),
/// at the spindle's cusps. A double root there (`|s|` within [`CUSP`]) is an apple root
/// and a lemon root merged: it is kept as one simple root, the apple's crossing.
/// (OpenMC's sign test on its squared side is this `s`: docs/family.md.)
fn keep_apple(roots: &mut [LineRoot], at: impl Fn(&LineRoot) -> V3<Sc>, k: f64) -> usize {
    let mut n = 0;
    for i in 0..roots.len() {
        let mut r = roots[i];
        let s = at(&r).to_dvec3().length_squared() + k;
        if r.double && s.abs() <= CUSP {
            r.double = false;
        } else if s < 0.0 && !r.origin {
            continue;
        }
        roots[n] = r;
        n += 1;
    }
    n
}

/// No root, for the arrays [`with_cusps`] fills.
const CUSP_FREE: LineRoot = LineRoot {
    key: 0.0,
    double: false,
    origin: false,
    cusp: false,
};

/// How near the axis (units of R, times r/R) the line must pass a cusp's height for
/// [`with_cusps`] to add the cusp: 10⁻⁴. Near a cusp the apple's root and the lemon's are
/// a pair `y − y_c ≈ ±ρ/y_c` apart (a line parallel to the axis at ρ), which f64 loses
/// (a complex pair) once 2ρ is below the quartic's rounding, `√ε·(r/R)²` ≈ 10⁻⁸·(r/R)²:
/// inside this reach for every accepted ν ≥ 1/100 (r/R ≤ 100).
const CUSP_REACH: f64 = 1e-4;

/// The apple's roots `kept` (sorted) and the line's points at the cusps' heights
/// `y = ±√((r/R)² − 1)` where it passes within [`CUSP_REACH`]·(r/R) of the axis there and
/// no kept root lies within as much of that point along the line, sorted: `at(u)` is the
/// scaled point at `u`, `dh` the unit direction.
///
/// A line through a spindle's cusp (the axis, for one) meets the apple and the lemon in a
/// double root there, which f64 may return as a complex pair: both lost, and with them a
/// crossing of the solid (a line down the axis from the centre, deep inside, was reported
/// as a miss). [`walk_by_side`] reads the side off the solid on either hand of each cusp
/// added, so a cusp added where the line only touches the surface changes nothing (the
/// same side on both hands: not reported), and one where the solver lost the crossing is
/// that crossing, within the pair's `ρ/y_c` of it.
fn with_cusps(
    kept: &[LineRoot],
    dh: DVec3,
    at: impl Fn(f64) -> DVec3,
    tube: &Tube,
) -> ([LineRoot; 6], usize) {
    let mut out = [CUSP_FREE; 6];
    out[..kept.len()].copy_from_slice(kept);
    let mut n = kept.len();
    let height = (tube.minor_rel * tube.minor_rel - 1.0).max(0.0).sqrt();
    if dh.y != 0.0 && height > 0.0 {
        let p = at(0.0);
        for y in [-height, height] {
            let u = (y - p.y) / dh.y;
            let x = at(u);
            // A kept root this near is the cusp's own (its double root split by rounding):
            // the solver's answer stands.
            let kept_here = kept
                .iter()
                .any(|r| (r.key - u).abs() <= CUSP_REACH * tube.minor_rel);
            if u.is_finite() && !kept_here && x.x.hypot(x.z) <= CUSP_REACH * tube.minor_rel {
                out[n] = LineRoot {
                    key: u,
                    double: false,
                    origin: false,
                    cusp: true,
                };
                n += 1;
            }
        }
    }
    if n > kept.len() {
        // Stable, and −0 = +0: the solver's roots keep their order (and their t its sign).
        out[..n].sort_by(|a, b| a.key.partial_cmp(&b.key).unwrap_or(Ordering::Equal));
    }
    (out, n)
}

/// [`walk`] for the apple's roots: the side between two consecutive roots is read off the
/// solid itself, at the midpoint (`inside(key)`), not off the roots' parity, which the
/// apple's singular points break (the horn's centre and the spindle's cusps are roots of
/// any multiplicity the solver happens to resolve). A root with the same side on both
/// hands is a touch. The line is outside before its first root (beyond the bounding
/// sphere) and after its last.
fn walk_by_side(
    roots: &[LineRoot],
    place: impl Fn(f64) -> Place,
    inside: impl Fn(f64) -> bool,
    mut emit: impl FnMut(&LineRoot, Passage),
) -> bool {
    let mut side = false;
    let mut at_start = None;
    for (i, r) in roots.iter().enumerate() {
        // A root repeated exactly (a singular point's multiple root) is one root.
        if i > 0 && roots[i - 1].key == r.key {
            continue;
        }
        // The side up to the next root at another point (a cusp added where the solver
        // kept its root repeats that root's key).
        let after = roots[i + 1..]
            .iter()
            .find(|next| next.key != r.key)
            .is_some_and(|next| inside(0.5 * (r.key + next.key)));
        let at = if r.origin {
            Place::Before
        } else {
            place(r.key)
        };
        if at != Place::Before {
            at_start.get_or_insert(side);
        }
        if at == Place::Within {
            let passage = match (side, after) {
                (false, true) => Passage::Enter,
                (true, false) => Passage::Exit,
                _ => Passage::Touch,
            };
            // A cusp with the same side on both hands is no point of the line's: only
            // where the side changes there is it a crossing the solver lost.
            if !(r.cusp && passage == Passage::Touch) {
                emit(r, passage);
            }
        }
        side = after;
    }
    at_start.unwrap_or(side)
}

/// The scaled image point `x` (units of R) lies inside the apple: `(ρ − 1)² + y² < (r/R)²`
/// (strictly: between two roots that rounding left apart at a singular point, the
/// midpoint is on the surface, and the pair is a touch).
fn in_apple(x: V3<Sc>, tube: &Tube) -> bool {
    let x = x.to_dvec3();
    (x.x.hypot(x.z) - 1.0).powi(2) + x.y * x.y < tube.minor_rel * tube.minor_rel
}

/// How close to 0 `s` of a double root must be for the root to be a spindle's cusp
/// ([`keep_apple`]), in units of R²: `|s| = 2ρ`, and a double root's point is found to
/// about √ε of its line, so 10⁻⁶ keeps every cusp and no tangent farther than 5·10⁻⁷·R
/// from the axis.
const CUSP: f64 = 1e-6;

/// Where a root lies against the ray's range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Place {
    Before,
    Within,
    After,
}

/// Walks the whole line's sorted roots from `−∞` (outside), flipping the side at each
/// simple root; calls `emit` for each root in range (never the origin's own) with its
/// passage, and returns the side at the start of the range: the side before the first
/// root not before it.
fn walk(
    roots: &[LineRoot],
    place: impl Fn(f64) -> Place,
    mut emit: impl FnMut(&LineRoot, Passage),
) -> bool {
    let mut inside = false;
    let mut at_start = None;
    for r in roots {
        let at = if r.origin {
            Place::Before
        } else {
            place(r.key)
        };
        if at != Place::Before {
            at_start.get_or_insert(inside);
        }
        if at == Place::Within {
            let passage = match (r.double, inside) {
                (true, _) => Passage::Touch,
                (false, false) => Passage::Enter,
                (false, true) => Passage::Exit,
            };
            emit(r, passage);
        }
        if !r.double {
            inside = !inside;
        }
    }
    at_start.unwrap_or(inside)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::DRay;

    #[test]
    fn surface_ray_across_the_hole_and_through_the_tube() {
        let torus = Torus::canonical(4.0, 1.0).unwrap();
        // From the inner equator (3, 0, 0) across the hole: enters the far side at x = −3
        // (t = 6), leaves it at x = −5 (t = 8). The origin's own root is not reported.
        let across = DRay::from_surface(DVec3::new(3.0, 0.0, 0.0), DVec3::NEG_X).unwrap();
        let all = intersect_all(&torus, &across);
        assert!(!all.starts_inside());
        let got: Vec<(f64, Passage)> = all.as_slice().iter().map(|c| (c.t, c.passage)).collect();
        assert_eq!(got.len(), 2, "{got:?}");
        assert!((got[0].0 - 6.0).abs() < 1e-12 && got[0].1 == Passage::Enter);
        assert!((got[1].0 - 8.0).abs() < 1e-12 && got[1].1 == Passage::Exit);
        // Into the tube from the outer equator (5, 0, 0): inside at once, out at x = 3,
        // then across the hole.
        let into = DRay::from_surface(DVec3::new(5.0, 0.0, 0.0), DVec3::NEG_X).unwrap();
        let all = intersect_all(&torus, &into);
        assert!(all.starts_inside());
        let spans = all.spans();
        let ends: Vec<(f64, f64)> = spans
            .as_slice()
            .iter()
            .map(|s| (s.t_enter, s.t_exit))
            .collect();
        assert_eq!(ends.len(), 2, "{ends:?}");
        assert_eq!(ends[0].0, 0.0);
        for (got, want) in [ends[0].1, ends[1].0, ends[1].1]
            .iter()
            .zip([2.0, 8.0, 10.0])
        {
            assert!((got - want).abs() < 1e-12, "{ends:?}");
        }
        // The first crossing is intersect's hit (the cubic's bracket may differ by an ulp).
        let hit = crate::intersect(&torus, &into).unwrap().t;
        assert!((all.as_slice()[0].t - hit).abs() < 1e-15, "{hit}");
    }

    #[test]
    fn cubic_roots_simple_and_double() {
        // (v − 1)(v − 2)(v − 3).
        let (r, n) = cubic_roots(-6.0, 11.0, -6.0);
        assert_eq!(n, 3);
        for ((v, double), want) in r.iter().zip([1.0, 2.0, 3.0]) {
            assert!((v - want).abs() < 1e-14 && !double, "{r:?}");
        }
        // (v − 1)²(v + 2) = v³ − 3v + 2: −2 simple, 1 double.
        let (r, n) = cubic_roots(0.0, -3.0, 2.0);
        assert_eq!(n, 2, "{r:?}");
        assert!((r[0].0 + 2.0).abs() < 1e-14 && !r[0].1);
        assert!((r[1].0 - 1.0).abs() < 1e-7 && r[1].1);
        // v³ + v: only 0.
        let (r, n) = cubic_roots(0.0, 1.0, 0.0);
        assert_eq!((n, r[0]), (1, (0.0, false)));
        // Non-finite: none.
        assert_eq!(cubic_roots(f64::NAN, 1.0, 0.0).1, 0);
    }
}
