//! The f64 ground truth for a pipe bend (Geant4's `G4Torus`, the library's
//! `torus_cull::bend::PipeBend`): a torus solid with a hollow core and a φ segment closed by
//! flat end caps. Independent of the library's bend: no code of it, no quartic; the torus
//! crossings are the family oracle's ([`super::family`]), by monotone pieces and bisection.
//!
//! **Definition.** Centre `c`, unit axis `â`, `e0` the unit part of `phi_zero` across the
//! axis and `e1 = â × e0` (φ grows from e0 toward e1, right-handed about â; in the
//! canonical frame, axis +y and φ = 0 along +x, φ = atan2(−z, x)). For a point x, with
//! `q = ((x − c)·e0, (x − c)·e1)`, `y = (x − c)·â`, `ρ = |q|`:
//! `D(x) = √((ρ − R)² + y²)` (the distance to the core circle), φ = atan2(q₁, q₀). The
//! solid: `r_min ≤ D ≤ r_max` and `(φ − φ₀) mod 2π ≤ Δφ`.
//!
//! **The signed function** (distance-like, negative inside):
//! `F = max(f_rad, f_w)`, `f_rad = |D − (r_min + r_max)/2| − (r_max − r_min)/2` (with no
//! bore `D − r_max`), and `f_w` the signed distance in the plane of q to the segment's
//! cone, `± min(d_s, d_e)` (d_s, d_e the distances to the cone's two edge rays, `−` strictly
//! inside the segment by the angle test); no `f_w` for Δφ = 2π.
//! `margin = min over t ∈ [t_min, t_max] of F(o + t d)`; the label is ambiguous iff
//! `|margin| ≤ AMBIGUITY_REL·(R + r_max)`, a hit if the margin is negative.
//!
//! **The margin, exactly.** Along the line: D is monotone between the family oracle's
//! critical points of E ([`FamilyQuery::critical_ts`]), so f_rad is monotone between those
//! and the roots of D = (r_min + r_max)/2 (the family oracle's crossings of that torus).
//! d_s is the distance to a convex set, convex along the line, with its minimum where the
//! projected line crosses the edge ray or else at its closest point to the axis; between
//! those two minima d_s and d_e are monotone, and where they run opposite ways their
//! difference is monotone and its sign change (bisected to adjacent floats) is where
//! `min(d_s, d_e)` turns: f_w is monotone between all these points. On each piece between
//! consecutive points both f_rad and f_w are monotone, so the minimum of their max is at an
//! end or where they cross (bisected again); the maximum at an end. The pieces are taken
//! on the chord of the ball of radius 2·(R + r_max) around the centre; beyond it F ≥ R +
//! r_max, and the margin reported there (a range that misses the chord) is F at the
//! range's point nearest the centre, a miss either way.
//!
//! **The crossings.** Candidates on the whole line: the family oracle's crossings of the
//! outer torus (R, r_max) and of the bore's (R, r_min), and the line's meeting with each
//! cap's half-plane (`q × s = 0` with `q·s > 0`). Candidates closer than rounding
//! (`64 ε (S + |o − c| + |t d|)`, S = R + r_max) form one group; the side of each gap
//! between groups is the sign of F at its midpoint (the line is outside at ±∞). A group
//! where the side changes is a crossing (entering or leaving) of its first candidate's
//! face; one where it does not is a touching if it holds a touching of a torus inside the
//! segment, else nothing (a torus root outside the segment, a plane point off its
//! annulus). [`BendQuery::faces_at`] names every face within a distance of a point, for
//! judging faces where they meet (a cap's edge).
//!
//! [`BendQuery::margin_by_sampling`] is the second method (dense samples, golden-section
//! refinement); [`BendQuery::classify_from_surface`] the rule for rays from a face
//! (`bend/surface.rs`).

mod pieces;
mod surface;
#[cfg(test)]
mod tests;

use super::family::FamilyQuery;
use super::{OracleLabel, interval::bisect};
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

pub use super::family::Passage;
pub use surface::onto_face;

/// A face of the bend's boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Face {
    /// D = r_max.
    Outer,
    /// D = r_min (the bore).
    Inner,
    /// The annulus in the half-plane φ = φ₀.
    StartCap,
    /// The annulus in the half-plane φ = φ₀ + Δφ.
    EndCap,
}

/// A pipe bend in the world, f64: centre `center`, axis `axis`, φ = 0 along `phi_zero`
/// (its part across the axis), R = `major`, r_min = `bore` (0: none), r_max = `tube`,
/// segment `[start, start + delta]` (the library's argument order). The bend part of a
/// [`BendQuery`], and the check's bend (`check::shapes::bend::rays`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spec {
    /// The centre.
    pub center: DVec3,
    /// The axis (any length).
    pub axis: DVec3,
    /// The direction of φ = 0 (its part across the axis).
    pub phi_zero: DVec3,
    /// R.
    pub major: f64,
    /// r_min (0: no bore).
    pub bore: f64,
    /// r_max.
    pub tube: f64,
    /// φ₀.
    pub start: f64,
    /// Δφ.
    pub delta: f64,
}

/// One question to the bend oracle: the line `origin + t dir`, `t ∈ [t_min, t_max]` (either
/// end may be infinite), against the bend `bend`; all f64, world frame. The bend's
/// parameters read through it (`query.major`: [`std::ops::Deref`] to [`Spec`]).
///
/// Methods panic on a zero or non-finite direction or axis, `phi_zero` along the axis,
/// radii not `0 ≤ bore < tube`, R > 0, Δφ not in (0, 2π], or a bad range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BendQuery {
    /// The bend.
    pub bend: Spec,
    /// The line's origin.
    pub origin: DVec3,
    /// The line's direction.
    pub dir: DVec3,
    /// The range's start.
    pub t_min: f64,
    /// The range's end.
    pub t_max: f64,
}

impl std::ops::Deref for BendQuery {
    type Target = Spec;
    fn deref(&self) -> &Spec {
        &self.bend
    }
}

impl std::ops::DerefMut for BendQuery {
    fn deref_mut(&mut self) -> &mut Spec {
        &mut self.bend
    }
}

/// The bend's frame and the line's projection, computed once per question.
#[derive(Debug, Clone, Copy)]
pub(super) struct Frame {
    c: DVec3,
    a: DVec3,
    e0: DVec3,
    e1: DVec3,
    /// The edge rays' unit directions in the plane (φ₀, φ₀ + Δφ).
    s: DVec2,
    e: DVec2,
    wedge: bool,
    major: f64,
    bore: f64,
    tube: f64,
    start_phi: f64,
    delta_phi: f64,
}

fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The distance from the plane point `q` to the ray `{λ u, λ ≥ 0}` (u unit).
fn ray_distance(q: DVec2, u: DVec2) -> f64 {
    if q.dot(u) > 0.0 {
        cross(q, u).abs()
    } else {
        q.length()
    }
}

impl Frame {
    pub(super) fn new(q: &BendQuery) -> Frame {
        assert!(
            q.axis.is_finite() && q.axis.length_squared() > 0.0,
            "bad axis"
        );
        assert!(q.dir.is_finite() && q.dir.length_squared() > 0.0, "bad dir");
        assert!(q.center.is_finite() && q.origin.is_finite(), "bad point");
        assert!(
            q.major > 0.0 && q.bore >= 0.0 && q.bore < q.tube && q.tube.is_finite(),
            "bad radii R = {}, r_min = {}, r_max = {}",
            q.major,
            q.bore,
            q.tube
        );
        assert!(
            q.start.is_finite() && q.delta > 0.0 && q.delta <= TAU,
            "bad segment"
        );
        assert!(q.t_min <= q.t_max, "bad range [{}, {}]", q.t_min, q.t_max);
        let a = q.axis.normalize();
        let across = q.phi_zero - a * q.phi_zero.dot(a);
        assert!(across.length() > 0.0, "phi_zero along the axis");
        let e0 = across.normalize();
        let e1 = a.cross(e0);
        let end = q.start + q.delta;
        Frame {
            c: q.center,
            a,
            e0,
            e1,
            s: DVec2::new(q.start.cos(), q.start.sin()),
            e: DVec2::new(end.cos(), end.sin()),
            wedge: q.delta < TAU,
            major: q.major,
            bore: q.bore,
            tube: q.tube,
            start_phi: q.start,
            delta_phi: q.delta,
        }
    }

    /// (q, y) of a world point.
    pub(super) fn local(&self, x: DVec3) -> (DVec2, f64) {
        let r = x - self.c;
        (DVec2::new(r.dot(self.e0), r.dot(self.e1)), r.dot(self.a))
    }

    /// The plane part of a world direction.
    pub(super) fn plane_dir(&self, d: DVec3) -> DVec2 {
        DVec2::new(d.dot(self.e0), d.dot(self.e1))
    }

    /// The world point of local (q, y).
    pub(super) fn world(&self, q: DVec2, y: f64) -> DVec3 {
        self.c + self.e0 * q.x + self.e1 * q.y + self.a * y
    }

    /// D, the distance to the core circle.
    pub(super) fn d_core(&self, q: DVec2, y: f64) -> f64 {
        (q.length() - self.major).hypot(y)
    }

    pub(super) fn f_rad(&self, d: f64) -> f64 {
        if self.bore > 0.0 {
            (d - 0.5 * (self.bore + self.tube)).abs() - 0.5 * (self.tube - self.bore)
        } else {
            d - self.tube
        }
    }

    /// φ strictly inside the segment, by the angle.
    pub(super) fn in_segment(&self, q: DVec2) -> bool {
        if !self.wedge {
            return true;
        }
        let rel = (q.y.atan2(q.x) - self.start_phi).rem_euclid(TAU);
        rel > 0.0 && rel < self.delta_phi
    }

    /// (d_s, d_e): the distances to the two edge rays.
    pub(super) fn edge_distances(&self, q: DVec2) -> (f64, f64) {
        (ray_distance(q, self.s), ray_distance(q, self.e))
    }

    /// The signed distance to the segment's cone (−∞ for the whole ring).
    pub(super) fn f_w(&self, q: DVec2) -> f64 {
        if !self.wedge {
            return f64::NEG_INFINITY;
        }
        let (ds, de) = self.edge_distances(q);
        let m = ds.min(de);
        if self.in_segment(q) { -m } else { m }
    }

    /// F at a world point.
    pub(super) fn f(&self, x: DVec3) -> f64 {
        let (q, y) = self.local(x);
        self.f_rad(self.d_core(q, y)).max(self.f_w(q))
    }
}

impl BendQuery {
    /// A query from plain values (see the fields), grouped: the pose, the radii (R,
    /// r_min, r_max), the segment (φ₀, Δφ), the line and its range.
    pub fn new(
        (center, axis, phi_zero): (DVec3, DVec3, DVec3),
        (major, bore, tube): (f64, f64, f64),
        (start, delta): (f64, f64),
        origin: DVec3,
        dir: DVec3,
        (t_min, t_max): (f64, f64),
    ) -> BendQuery {
        BendQuery {
            bend: Spec {
                center,
                axis,
                phi_zero,
                major,
                bore,
                tube,
                start,
                delta,
            },
            origin,
            dir,
            t_min,
            t_max,
        }
    }

    /// The bend in its canonical frame (centre 0, axis +y, φ = 0 along +x), the whole line.
    pub fn canonical(
        (major, bore, tube): (f64, f64, f64),
        (start_phi, delta_phi): (f64, f64),
        origin: DVec3,
        dir: DVec3,
    ) -> BendQuery {
        BendQuery::new(
            (DVec3::ZERO, DVec3::Y, DVec3::X),
            (major, bore, tube),
            (start_phi, delta_phi),
            origin,
            dir,
            (f64::NEG_INFINITY, f64::INFINITY),
        )
    }

    /// The same line over `[t_min, t_max]`.
    pub fn over(self, t_min: f64, t_max: f64) -> BendQuery {
        BendQuery {
            t_min,
            t_max,
            ..self
        }
    }

    /// R + r_max: the size the ambiguity band is relative to.
    pub fn size(&self) -> f64 {
        self.major + self.tube
    }

    /// F at t (module docs), from the point itself.
    pub fn f(&self, t: f64) -> f64 {
        Frame::new(self).f(self.origin + self.dir * t)
    }

    /// The family query of the torus (R, r) on this line, the whole line.
    fn torus(&self, r: f64) -> FamilyQuery {
        FamilyQuery::new(
            self.center,
            self.axis.normalize(),
            self.major,
            r,
            r,
            self.origin,
            self.dir,
            f64::NEG_INFINITY,
            f64::INFINITY,
        )
    }

    /// The oracle's class and margin (module docs).
    pub fn classify(&self) -> OracleLabel {
        let frame = Frame::new(self);
        let margin = self.margin_over(&frame, self.t_min, self.t_max);
        OracleLabel::from_margin(margin, self.major, self.tube)
    }

    /// The crossings in `[t_min, t_max]`, ascending: `(t, passage, face)`.
    pub fn crossings(&self) -> Vec<(f64, Passage, Face)> {
        self.walk()
            .into_iter()
            .filter_map(|ev| ev.passage.map(|p| (ev.t, p, ev.face)))
            .filter(|c| c.0 >= self.t_min && c.0 <= self.t_max)
            .collect()
    }

    /// The first of [`BendQuery::crossings`].
    pub fn first_crossing(&self) -> Option<(f64, Passage, Face)> {
        self.crossings().first().copied()
    }

    /// Whether the range starts inside the solid (past a crossing at `t_min` itself).
    pub fn starts_inside(&self) -> bool {
        if self.t_min == f64::NEG_INFINITY {
            return false;
        }
        self.walk()
            .iter()
            .rev()
            .find(|ev| ev.t <= self.t_min)
            .is_some_and(|ev| ev.inside_after)
    }

    /// The smallest gap between two crossings of the whole line (in length units), ∞ for
    /// fewer than two: below the test tolerance the order of two faces at a corner is not
    /// determined.
    pub fn closest_crossings(&self) -> f64 {
        let ts: Vec<f64> = self
            .walk()
            .iter()
            .filter(|e| e.passage.is_some())
            .map(|e| e.t)
            .collect();
        ts.windows(2)
            .map(|w| (w[1] - w[0]) * self.dir.length())
            .fold(f64::INFINITY, f64::min)
    }

    /// How close the line comes to touching a torus face inside the segment: the least
    /// `|D − r_max|` (and `|D − r_min|`) at D's critical points in range where the point is
    /// in the segment (within `tol`), in length units; ∞ where there is none. Below the
    /// test tolerance a tangent's crossings (none, a touch, or two) are not determined.
    pub fn tangency(&self, tol: f64) -> f64 {
        let frame = Frame::new(self);
        self.torus(self.tube)
            .critical_ts()
            .into_iter()
            .filter(|&t| t >= self.t_min && t <= self.t_max)
            .filter_map(|t| {
                let (q, y) = frame.local(self.origin + self.dir * t);
                if frame.f_w(q) > tol {
                    return None;
                }
                let d = frame.d_core(q, y);
                let inner = if self.bore > 0.0 {
                    (d - self.bore).abs()
                } else {
                    f64::INFINITY
                };
                Some((d - self.tube).abs().min(inner))
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// Every face whose surface passes within `tol` (a length) of the world point `p`.
    pub fn faces_at(&self, p: DVec3, tol: f64) -> Vec<Face> {
        let frame = Frame::new(self);
        let (q, y) = frame.local(p);
        let d = frame.d_core(q, y);
        let fw = frame.f_w(q);
        let mut out = Vec::new();
        if (d - self.tube).abs() <= tol && fw <= tol {
            out.push(Face::Outer);
        }
        if self.bore > 0.0 && (d - self.bore).abs() <= tol && fw <= tol {
            out.push(Face::Inner);
        }
        if frame.wedge {
            for (face, u) in [(Face::StartCap, frame.s), (Face::EndCap, frame.e)] {
                let along = q.dot(u);
                if along <= 0.0 {
                    continue;
                }
                let off = cross(q, u).abs();
                let dc = (along - self.major).hypot(y);
                let radial = (dc - self.tube).max(self.bore - dc).max(0.0);
                if off.hypot(radial) <= tol {
                    out.push(face);
                }
            }
        }
        out
    }

    /// The unit outward normal (out of the solid) of `face` at the world point `p`.
    pub fn normal(&self, face: Face, p: DVec3) -> DVec3 {
        let frame = Frame::new(self);
        let (q, _) = frame.local(p);
        let core = frame.world(q * (self.major / q.length()), 0.0);
        let growing = |u: DVec2| frame.e1 * u.x - frame.e0 * u.y;
        match face {
            Face::Outer => (p - core).normalize(),
            Face::Inner => (core - p).normalize(),
            Face::StartCap => -growing(frame.s),
            Face::EndCap => growing(frame.e),
        }
        .normalize()
    }

    /// The chord `[t0, t1]` of the ball of radius 2·(R + r_max) around the centre.
    fn chord(&self) -> Option<(f64, f64)> {
        let p = self.origin - self.center;
        let dd = self.dir.length_squared();
        let half = p.dot(self.dir) / dd;
        let reach = 2.0 * self.size();
        let disc = half * half - (p.length_squared() - reach * reach) / dd;
        (disc >= 0.0).then(|| {
            let root = disc.sqrt();
            (-half - root, -half + root)
        })
    }

    /// min F over `[lo, hi]` (module docs).
    pub(super) fn margin_over(&self, frame: &Frame, lo: f64, hi: f64) -> f64 {
        let at = |t: f64| frame.f(self.origin + self.dir * t);
        let clipped = self
            .chord()
            .map(|(c0, c1)| (lo.max(c0), hi.min(c1)))
            .filter(|(a, b)| a <= b);
        let Some((a, b)) = clipped else {
            let p = self.origin - self.center;
            let nearest = (-p.dot(self.dir) / self.dir.length_squared()).clamp(lo, hi);
            return at(nearest);
        };
        self.candidates(frame, a, b)
            .into_iter()
            .map(at)
            .fold(f64::INFINITY, f64::min)
    }

    /// The whole line's events: each group of candidates, its passage (if it is a
    /// crossing) and face, and the side after it.
    fn walk(&self) -> Vec<Event> {
        let frame = Frame::new(self);
        let mut cands: Vec<(f64, Option<Passage>, Face)> = Vec::new();
        let mut radii = vec![(self.tube, Face::Outer)];
        if self.bore > 0.0 {
            radii.push((self.bore, Face::Inner));
        }
        for (r, face) in radii {
            for c in self.torus(r).crossings() {
                cands.push((c.t, Some(c.passage), face));
            }
        }
        if frame.wedge {
            let (q0, _) = frame.local(self.origin);
            let v = frame.plane_dir(self.dir);
            for (face, u) in [(Face::StartCap, frame.s), (Face::EndCap, frame.e)] {
                let cr = cross(v, u);
                if cr != 0.0 {
                    let t = -cross(q0, u) / cr;
                    if t.is_finite() && (q0 + v * t).dot(u) > 0.0 {
                        cands.push((t, None, face));
                    }
                }
            }
        }
        cands.sort_by(|a, b| a.0.total_cmp(&b.0));
        let len = self.dir.length();
        let base = self.size() + (self.origin - self.center).length();
        let tol = |t: f64| 64.0 * f64::EPSILON * (base + t.abs() * len) / len;
        let mut groups: Vec<&[(f64, Option<Passage>, Face)]> = Vec::new();
        let mut i = 0;
        while i < cands.len() {
            let mut j = i + 1;
            while j < cands.len() && cands[j].0 - cands[j - 1].0 <= tol(cands[j].0) {
                j += 1;
            }
            groups.push(&cands[i..j]);
            i = j;
        }
        let at = |t: f64| frame.f(self.origin + self.dir * t);
        let mut out = Vec::with_capacity(groups.len());
        let mut before = false;
        for (k, g) in groups.iter().enumerate() {
            let after = match groups.get(k + 1) {
                Some(next) => at(0.5 * (g[g.len() - 1].0 + next[0].0)) < 0.0,
                None => false,
            };
            let (t, face) = (g[0].0, g[0].2);
            let passage = match (before, after) {
                (false, true) => Some(Passage::Entering),
                (true, false) => Some(Passage::Leaving),
                (false, false) => g
                    .iter()
                    .find(|c| {
                        c.1 == Some(Passage::Touching)
                            && frame.f_w(frame.local(self.origin + self.dir * c.0).0) <= 0.0
                    })
                    .map(|_| Passage::Touching),
                (true, true) => None,
            };
            // A crossing is its group's first candidate's; a touching its torus root's.
            let (t, face) = match passage {
                Some(Passage::Touching) => g
                    .iter()
                    .find(|c| c.1 == Some(Passage::Touching))
                    .map_or((t, face), |c| (c.0, c.2)),
                _ => (t, face),
            };
            out.push(Event {
                t,
                passage,
                face,
                inside_after: after,
            });
            before = after;
        }
        out
    }
}

/// A group of candidates on the whole line.
#[derive(Debug, Clone, Copy)]
struct Event {
    t: f64,
    passage: Option<Passage>,
    face: Face,
    inside_after: bool,
}

/// A sign change of `f` on `[a, b]`, bisected, or `None`.
pub(super) fn sign_change(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> Option<f64> {
    let (fa, fb) = (f(a), f(b));
    if fa.is_nan() || fb.is_nan() || fa == 0.0 || fb == 0.0 || (fa < 0.0) == (fb < 0.0) {
        return None;
    }
    bisect(f, a, b, fa)
}
