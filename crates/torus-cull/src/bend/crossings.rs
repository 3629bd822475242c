//! A pipe bend's crossings: candidates from each face, sides read off the solid
//! (module docs of [`crate::bend`]).

use super::{BendFace, PipeBend};
use crate::geometry::ray::sealed::Scalar;
use crate::intersect::sealed::Sealed;
use crate::intersect::{Roots, line_crossings};
use crate::{Cull, Passage, Precision, Ray, TorusRay};
use glam::DVec3;

/// How far from a face (in units of R + r_max) a marked origin may lie and still be that
/// face's point; the ring torus's own reach (`OWN_ROOT_REACH`, 10⁻²·R) is wider, this one
/// also decides between faces that meet at a cap's edge.
const FACE_REACH: f64 = 1e-6;

/// One crossing of a pipe bend's boundary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BendCrossing<P: Precision = glam::Vec3> {
    /// Ray parameter, in units of the ray's direction.
    pub t: P::Float,
    /// The face's unit outward normal (out of the solid), world space.
    pub normal: P,
    /// Entering or leaving the solid, or a tangent touch.
    pub passage: Passage,
    /// Which face.
    pub face: BendFace,
}

/// The nearest hit on a pipe bend: [`crate::Hit`]'s fields and the face.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct BendHit<P: Precision = glam::Vec3> {
    /// Ray parameter, in units of the ray's direction.
    pub t: P::Float,
    /// The face's unit outward normal, world space.
    pub normal: P,
    /// The hit point `o + t·d`, formed in f64.
    pub point: P,
    /// The ray enters the solid here.
    pub front_face: bool,
    /// Which face.
    pub face: BendFace,
}

impl<P: Precision> BendHit<P> {
    /// A ring torus's hit as the whole bend's: the same fields, on the face `Outer` (a
    /// whole bend is its outer torus, on every path).
    pub(crate) fn on_outer(hit: crate::Hit<P>) -> BendHit<P> {
        BendHit {
            t: hit.t,
            normal: hit.normal,
            point: hit.point,
            front_face: hit.front_face,
            face: BendFace::Outer,
        }
    }
}

/// Every crossing of a ray with a pipe bend in its range, sorted (at most ten).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BendCrossings<P: Precision = glam::Vec3> {
    crossings: [BendCrossing<P>; 10],
    len: usize,
    starts_inside: bool,
    t_min: P::Float,
    t_max: P::Float,
}

impl<P: Precision> BendCrossings<P> {
    /// None yet, over the ray's range.
    fn empty(ray: &Ray<P>, starts_inside: bool) -> BendCrossings<P> {
        BendCrossings {
            crossings: [BendCrossing {
                t: <P::Float as Scalar>::ZERO,
                normal: P::ZERO,
                passage: Passage::Touch,
                face: BendFace::Outer,
            }; 10],
            len: 0,
            starts_inside,
            t_min: ray.t_min(),
            t_max: ray.t_max(),
        }
    }

    /// The crossings, ascending in `t`, copied into a `Vec`.
    #[deprecated(
        since = "0.1.0",
        note = "allocates: use `crossings()` (a slice), `iter()` or `for c in &crossings`"
    )]
    #[must_use]
    pub fn as_slice(&self) -> Vec<BendCrossing<P>> {
        self.crossings().to_vec()
    }

    /// The crossings, ascending in `t`, without allocating.
    #[inline]
    #[must_use]
    pub fn crossings(&self) -> &[BendCrossing<P>] {
        &self.crossings[..self.len]
    }

    /// The crossings by reference, ascending (`for c in &crossings` says the same).
    #[inline]
    pub fn iter(&self) -> std::slice::Iter<'_, BendCrossing<P>> {
        self.crossings().iter()
    }

    /// The ray's range `[t_min, t_max]` the crossings were found in.
    #[inline]
    #[must_use]
    pub fn range(&self) -> (P::Float, P::Float) {
        (self.t_min, self.t_max)
    }

    /// How many.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// None in range.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The range starts inside the solid (for a ray from a surface point: just past it).
    #[must_use]
    pub fn starts_inside(&self) -> bool {
        self.starts_inside
    }
}

/// A candidate: `t`, the face, the torus-frame outward normal of the solid there, and
/// whether it is a tangent of its torus.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    t: f64,
    face: BendFace,
    normal: DVec3,
    touch: bool,
}

/// The faces a marked origin lies on, and the origin moved onto them.
pub(super) struct OwnFaces {
    pub(super) point: DVec3,
    pub(super) faces: [bool; 4],
}

/// The faces within [`FACE_REACH`] of the torus-frame point `x`, nearest first, and `x`
/// moved onto them: a torus face along its meridian (the core circle's nearest point
/// out by r), a cap along its plane's normal; a point near a cap's edge onto both.
pub(super) fn own_faces(bend: &PipeBend, x: DVec3) -> OwnFaces {
    let size = bend.major_radius_f64() + bend.tube_radius_f64();
    let reach = FACE_REACH * size;
    // A torus face's reach is at most a quarter of the wall: a point of one face of a
    // thin wall lies a wall's thickness from the other, and taking both as its own would
    // divide out the other face's root too (a ray from the bore across a wall of
    // 10⁻⁶·r_max then missed its exit at t ≈ 10⁻⁶). With the wall at least
    // `MIN_WALL_REL`·S (10⁻⁷·S) the reach stays above 2.5·10⁻⁸·S, far above a hit
    // point's rounding.
    let torus_reach = match bend.inner {
        Some(_) => reach.min(0.25 * (bend.tube_radius_f64() - bend.bore_radius_f64())),
        None => reach,
    };
    let mut faces = [false; 4];
    let mut point = x;
    // A point within reach of a torus face is off the axis and the core circle (R > r),
    // where the projection is the unique closest point. Of the two tori, the nearer (the
    // reach already keeps them apart; the nearer is the one a rounding leaves it by).
    let mut nearest = f64::INFINITY;
    for (i, torus) in [(0, Some(bend.outer)), (1, bend.inner)] {
        let Some(torus) = torus else { continue };
        let (on, _, signed_distance) = torus.tube().project(x);
        if signed_distance.abs() <= torus_reach && signed_distance.abs() < nearest {
            nearest = signed_distance.abs();
            faces = [false; 4];
            faces[i] = true;
            point = on;
        }
    }
    if let Some(w) = bend.wedge {
        for (i, end) in [(2, false), (3, true)] {
            let (dir, normal) = w.cap(end);
            let h = point.dot(normal);
            if h.abs() <= reach && point.dot(dir) > 0.0 {
                let d = (point.dot(dir) - bend.major_radius_f64()).hypot(point.y);
                let on_annulus =
                    d >= bend.bore_radius_f64() - reach && d <= bend.tube_radius_f64() + reach;
                if on_annulus {
                    faces[i] = true;
                    point -= normal * h;
                }
            }
        }
    }
    OwnFaces { point, faces }
}

impl PipeBend {
    /// The nearest crossing in range: the face, `t`, its normal, and whether the ray
    /// enters there. The whole torus answers as [`crate::intersect()`] does.
    #[must_use]
    pub fn intersect<P: Precision>(&self, ray: &Ray<P>) -> Option<BendHit<P>> {
        if let Ok(torus) = self.as_torus() {
            return crate::intersect(torus, ray).map(BendHit::on_outer);
        }
        let (first, _) = self.walk(ray, true);
        let c = first[0]?;
        let (o, d) = (ray.origin().to_dvec3(), ray.dir().to_dvec3());
        let t = <P::Float as Scalar>::from_f64(c.t);
        t.finite().then(|| BendHit {
            t,
            normal: P::from_dvec3(self.normal_to_world(c.normal)),
            point: P::from_dvec3(o + d * c.t),
            front_face: c.passage == Passage::Enter,
            face: c.face,
        })
    }

    /// `cull` on the outer torus, then [`PipeBend::intersect`] if it keeps the ray.
    #[must_use]
    pub fn intersect_culled<C: Cull + ?Sized, P: Precision>(
        &self,
        cull: &C,
        ray: &Ray<P>,
    ) -> Option<BendHit<P>> {
        if self.kept_by(cull, ray) {
            self.intersect(ray)
        } else {
            None
        }
    }

    /// Every crossing in range, sorted, each with its face, outward normal and passage
    /// (CSG intervals: each entry is followed by its exit).
    #[must_use]
    pub fn intersect_all<P: Precision>(&self, ray: &Ray<P>) -> BendCrossings<P> {
        if let Ok(torus) = self.as_torus() {
            let all = crate::intersect_all(torus, ray);
            let mut out = BendCrossings::empty(ray, all.starts_inside());
            out.len = all.len();
            for (slot, c) in out.crossings.iter_mut().zip(all.as_slice()) {
                *slot = BendCrossing {
                    t: c.t,
                    normal: c.normal,
                    passage: c.passage,
                    face: BendFace::Outer,
                };
            }
            return out;
        }
        let (all, starts_inside) = self.walk(ray, false);
        let mut out = BendCrossings::empty(ray, starts_inside);
        for c in all.iter().flatten() {
            let t = <P::Float as Scalar>::from_f64(c.t);
            if t.finite() {
                out.crossings[out.len] = BendCrossing {
                    t,
                    normal: P::from_dvec3(self.normal_to_world(c.normal)),
                    passage: c.passage,
                    face: c.face,
                };
                out.len += 1;
            }
        }
        out
    }

    fn normal_to_world(&self, n: DVec3) -> DVec3 {
        self.outer.to_local_rotation_f64().transpose() * n
    }

    /// The crossings in range (the first alone with `first_only`), f64, and whether the
    /// range starts inside.
    fn walk<P: Precision>(&self, ray: &Ray<P>, first_only: bool) -> ([Option<Found>; 10], bool) {
        let (o, d) = self.outer.line_to_local_f64(ray);
        let (t_min, t_max) = ray.as_ray().range_f64();
        let on_surface = ray.starts_on_surface();
        let own = if on_surface {
            own_faces(self, o)
        } else {
            OwnFaces {
                point: o,
                faces: [false; 4],
            }
        };
        let mut cands = [Candidate {
            t: 0.0,
            face: BendFace::Outer,
            normal: DVec3::ZERO,
            touch: false,
        }; 10];
        let mut n = 0;
        let mut push = |c: Candidate| {
            if n < 10 {
                cands[n] = c;
                n += 1;
            }
        };
        // A marked origin's own faces lose their own root; the others are solved from
        // the moved origin, past it.
        let (lo, hi) = if on_surface {
            (t_min.max(0.0), t_max)
        } else {
            (t_min, t_max)
        };
        let line = (own.point, d);
        let tori = [
            (BendFace::Outer, Some(self.outer)),
            (BendFace::Inner, self.inner),
        ];
        for (i, (face, torus)) in tori.into_iter().enumerate() {
            let Some(torus) = torus else { continue };
            let sign = if face == BendFace::Inner { -1.0 } else { 1.0 };
            line_crossings(
                torus.tube(),
                line,
                (lo, hi),
                own.faces[i],
                Roots::All,
                |t, normal, passage| {
                    if !(on_surface && t <= 0.0) {
                        push(Candidate {
                            t,
                            face,
                            normal: normal * sign,
                            touch: passage == Passage::Touch,
                        });
                    }
                },
            );
        }
        if let Some(w) = self.wedge {
            for (i, face, end) in [(2, BendFace::StartCap, false), (3, BendFace::EndCap, true)] {
                if own.faces[i] {
                    continue;
                }
                let (dir, growing) = w.cap(end);
                let t = -line.0.dot(growing) / d.dot(growing);
                // On the cap's own half-plane: for Δφ = π the two caps share a plane.
                let on_half = (line.0 + d * t).dot(dir) > 0.0;
                let in_range = t.is_finite() && t >= lo && t <= hi;
                if in_range && on_half && !(on_surface && t <= 0.0) {
                    let outward = if end { growing } else { -growing };
                    push(Candidate {
                        t,
                        face,
                        normal: outward,
                        touch: false,
                    });
                }
            }
        }
        let cands = &mut cands[..n];
        cands.sort_by(|a, b| a.t.total_cmp(&b.t));
        let size = (self.major_radius_f64() + self.tube_radius_f64()) / d.length();
        let inside_at = |t: f64| self.contains_local(line.0 + d * t, true);
        // The side of each interval, at its midpoint (or a step past an open end).
        let side = |k: usize| -> bool {
            let a = if k == 0 { lo } else { cands[k - 1].t };
            let b = if k == cands.len() { hi } else { cands[k].t };
            let t = match (a.is_finite(), b.is_finite()) {
                (true, true) => 0.5 * (a + b),
                (true, false) => a + size,
                (false, true) => b - size,
                (false, false) => 0.0,
            };
            inside_at(t)
        };
        let starts_inside = side(0);
        let mut out = [None; 10];
        let mut m = 0;
        let mut before = starts_inside;
        for (k, &c) in cands.iter().enumerate() {
            let after = side(k + 1);
            let passage = match (before, after) {
                (false, true) => Some(Passage::Enter),
                (true, false) => Some(Passage::Exit),
                // A tangent of a torus face that touches the solid from outside.
                (false, false) if c.touch && self.contains_local(line.0 + d * c.t, false) => {
                    Some(Passage::Touch)
                }
                _ => None,
            };
            if let Some(passage) = passage {
                out[m] = Some(Found {
                    t: c.t,
                    face: c.face,
                    normal: c.normal,
                    passage,
                });
                m += 1;
                if first_only {
                    break;
                }
            }
            before = after;
        }
        (out, starts_inside)
    }
}

/// A crossing found, f64, torus frame.
#[derive(Debug, Clone, Copy)]
struct Found {
    t: f64,
    face: BendFace,
    normal: DVec3,
    passage: Passage,
}

impl PipeBend {
    /// Whether the ray meets the solid in its range (a shadow ray's question).
    #[must_use]
    pub fn occluded<R: TorusRay>(&self, ray: &R) -> bool {
        self.intersect(ray.as_ray()).is_some()
    }
}
