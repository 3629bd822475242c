//! The f64 ground truth for the torus family: ring, horn and spindle tori with an
//! elliptical tube. Independent of the library: no quartic, no code of its solver.
//!
//! **Definition.** Centre `c`, unit axis `â` (normalized here), major radius R > 0, tube
//! semi-axes `a` (radial, in the equatorial plane) and `b` (along the axis). For a point x,
//! `y = (x − c)·â`, `ρ = |(x − c) − y â|` (≥ 0), and
//!
//! `E(x) = √(((ρ − R)/a)² + (y/b)²)`; the solid is `E ≤ 1`, its surface `E = 1`.
//!
//! Because ρ ≥ 0, for a spindle (R < a) this is the "apple", the outer boundary of the solid
//! of revolution: the inner "lemon" (`((ρ + R)/a)² + (y/b)² = 1`, the tube's far side
//! mirrored through the axis) is inside the solid and never a crossing. A horn (R = a)
//! touches itself at the centre, where E = 1.
//!
//! `margin = min over t ∈ [t_min, t_max] of (E(o + t d) − 1)·min(a, b)`, a length (for
//! a = b it is the distance to the core circle minus r, the ring oracle's margin); negative
//! enters the solid. The label is ambiguous iff `|margin| ≤ AMBIGUITY_REL·(R + max(a, b))`.
//!
//! **Method.** E is never squared into a polynomial in t. The line is written in unit arc
//! length s from its foot point (the point closest to the centre, by the ring oracle's exact
//! cross products, so far origins stay well conditioned): `x(s) − c = p + s u`. Along it
//! `ρ(s)² = A (s − s_m)² + m²` (A the squared part of u across the axis, m the closest
//! approach to the axis), so ρ has one kink, at s_m, when m = 0. The slope
//! `h = a²·½ dE²/ds = (ρ − R) ρ′ + y u_y (a/b)²` has derivative `A − R A m²/ρ³ + u_y² (a/b)²`,
//! increasing in ρ: h is monotone on at most three pieces, split at `s_m` and at
//! `s_m ± √((ρ*² − m²)/A)`, `ρ*³ = R A m² / (A + u_y² (a/b)²)` (see `line.rs`). Each sign
//! change of h on a piece (the outer pieces closed by doubling a step until h has the sign
//! of its limit ±∞) is bisected to adjacent floats. h takes ρ and ρ′ from that model of
//! the line, not from the point (near the axis the point's part across it is mostly
//! rounding); where the line meets the axis to within rounding (m = 0, or the pieces
//! around s_m narrower than a float) its one-sided values at s_m are the kink's, ρ′ = ∓√A.
//! Between two consecutive points of that set (critical points and cuts) E is monotone, so:
//! - the minimum over the range is the least E at those points in the range and the
//!   range's finite ends, each evaluated from the point itself;
//! - each sign change of `E − 1` between consecutive points (the outermost closed by
//!   doubling until E > 1) is one crossing, bisected to adjacent floats ([`crossings`]).
//!
//! [`margin_by_sampling`] is the second, independent method; [`classify_from_surface`] the
//! rule for rays spawned from a surface point.
//!
//! [`crossings`]: FamilyQuery::crossings
//! [`margin_by_sampling`]: FamilyQuery::margin_by_sampling
//! [`classify_from_surface`]: FamilyQuery::classify_from_surface

mod ellipse;
mod line;
mod sampling;
mod surface;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_surface;

pub use ellipse::nearest_on_ellipse;

use super::{OracleClass, OracleLabel, Query, check_pose};
use crate::oracle::interval::bisect;
use glam::DVec3;
use line::Line;

/// One question to the family oracle: the line `origin + t dir`, `t ∈ [t_min, t_max]`
/// (either end may be infinite; t in units of `dir`, any non-zero length), against the
/// family torus with centre `center`, axis `axis` (normalized by the oracle), R = `major`,
/// tube semi-axes `radial` (a) and `axial` (b); all f64, world frame.
///
/// Every method panics if `dir` or `axis` is zero or not finite, `origin` or `center` not
/// finite, a radius not positive and finite, or `t_min > t_max` or either NaN.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FamilyQuery {
    /// The torus's centre.
    pub center: DVec3,
    /// The torus's axis (unit; normalized again by the oracle).
    pub axis: DVec3,
    /// R.
    pub major: f64,
    /// a, the tube's semi-axis in the equatorial plane.
    pub radial: f64,
    /// b, the tube's semi-axis along the axis.
    pub axial: f64,
    /// The line's origin.
    pub origin: DVec3,
    /// The line's direction.
    pub dir: DVec3,
    /// The range's start.
    pub t_min: f64,
    /// The range's end.
    pub t_max: f64,
}

/// How the line passes the surface at a crossing, in the direction of increasing t.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Passage {
    /// From outside (E ≥ 1) into the solid (E < 1).
    Entering,
    /// From the solid out.
    Leaving,
    /// Touches the surface without crossing it: a critical point of E where E = 1 exactly
    /// in f64, or crossings closer together than rounding that leave the line on the side
    /// it came from (a horn's centre, a minimum of E a float or two below 1).
    Touching,
}

/// One point where the line meets the surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// The line parameter, in units of `dir`.
    pub t: f64,
    /// Which way it passes.
    pub passage: Passage,
}

impl FamilyQuery {
    /// A query from plain values (see the fields).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        center: DVec3,
        axis: DVec3,
        major: f64,
        radial: f64,
        axial: f64,
        origin: DVec3,
        dir: DVec3,
        t_min: f64,
        t_max: f64,
    ) -> FamilyQuery {
        FamilyQuery {
            center,
            axis,
            major,
            radial,
            axial,
            origin,
            dir,
            t_min,
            t_max,
        }
    }

    /// A torus at the origin with axis +y, over the whole line.
    pub fn canonical(
        major: f64,
        radial: f64,
        axial: f64,
        origin: DVec3,
        dir: DVec3,
    ) -> FamilyQuery {
        FamilyQuery::new(
            DVec3::ZERO,
            DVec3::Y,
            major,
            radial,
            axial,
            origin,
            dir,
            f64::NEG_INFINITY,
            f64::INFINITY,
        )
    }

    /// The ring oracle's query as a family query with a = b = r.
    pub fn from_ring(query: &Query) -> FamilyQuery {
        FamilyQuery::new(
            query.center,
            query.axis.normalize(),
            query.major,
            query.minor,
            query.minor,
            query.o,
            query.d,
            query.t_min,
            query.t_max,
        )
    }

    /// The same line over `[t_min, t_max]`.
    pub fn over(self, t_min: f64, t_max: f64) -> FamilyQuery {
        FamilyQuery {
            t_min,
            t_max,
            ..self
        }
    }

    /// R + max(a, b): the size the ambiguity band is relative to.
    pub fn size(&self) -> f64 {
        self.major + self.radial.max(self.axial)
    }

    /// The margin's integrand at t, from the definition in world coordinates:
    /// `(E(o + t d) − 1)·min(a, b)`.
    pub fn g(&self, t: f64) -> f64 {
        let axis = self.axis.normalize();
        let x = self.origin + t * self.dir - self.center;
        let y = x.dot(axis);
        let rho = (x - y * axis).length();
        let e = ((rho - self.major) / self.radial).hypot(y / self.axial);
        (e - 1.0) * self.radial.min(self.axial)
    }

    /// The oracle's class and margin (module docs). A line whose numbers overflow f64 gets
    /// a NaN margin and [`OracleClass::Ambiguous`].
    pub fn classify(&self) -> OracleLabel {
        self.check_range();
        let line = Line::new(self);
        if !line.is_finite() {
            return OracleLabel {
                class: OracleClass::Ambiguous,
                margin: f64::NAN,
            };
        }
        let (lo, hi) = (line.s_of_t(self.t_min), line.s_of_t(self.t_max));
        let mut best = f64::INFINITY;
        for s in line.stationary().into_iter().chain([lo, hi]) {
            if s.is_finite() && s >= lo && s <= hi {
                best = best.min(line.g(s));
            }
        }
        OracleLabel::from_margin(best, self.major, self.radial.max(self.axial))
    }

    /// Every point of `[t_min, t_max]` where the line meets the surface, in increasing t:
    /// each sign change of `E − 1` (E = 1 counts as outside) bisected to adjacent floats
    /// in arc length, marked entering or leaving; and touchings ([`Passage::Touching`]).
    ///
    /// Crossings of the whole line closer together than rounding (`8 ε (S + |s|)` in arc
    /// length, S = R + max(a, b)) are one: the one passage where they change the side, a
    /// touching where they do not. Otherwise, near a tangency the crossings are as rounding
    /// makes them: a computed minimum of E just below 1 gives two close crossings, just
    /// above none. Compare crossing counts only outside the ambiguity band.
    pub fn crossings(&self) -> Vec<Crossing> {
        self.check_range();
        let line = Line::new(self);
        if !line.is_finite() {
            return Vec::new();
        }
        let g = |s: f64| line.e(s) - 1.0;
        let mut pts = line.stationary();
        // Critical points (and cuts) with E = 1 exactly: touchings, unless a crossing
        // lands on them (see `resolve_clusters`).
        let touch: Vec<f64> = pts.iter().copied().filter(|&s| g(s) == 0.0).collect();
        let mut found: Vec<(f64, Passage)> = Vec::new();
        let outside = |s: f64| g(s) > 0.0;
        if let Some(far) = line.escape(pts[0], -1.0, &outside) {
            pts.insert(0, far);
        }
        if let Some(far) = line.escape(pts[pts.len() - 1], 1.0, &outside) {
            pts.push(far);
        }
        for w in pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            let (ga, gb) = (g(a), g(b));
            if (ga < 0.0) != (gb < 0.0) {
                let passage = if ga < 0.0 {
                    Passage::Leaving
                } else {
                    Passage::Entering
                };
                if let Some(s) = bisect(&g, a, b, ga) {
                    found.push((s, passage));
                }
            }
        }
        found.extend(touch.into_iter().map(|s| (s, Passage::Touching)));
        found.sort_by(|x, y| x.0.total_cmp(&y.0));
        let out: Vec<Crossing> = resolve_clusters(found, self.size())
            .into_iter()
            .map(|(s, passage)| Crossing {
                t: line.t_of_s(s),
                passage,
            })
            .filter(|c| c.t >= self.t_min && c.t <= self.t_max)
            .collect();
        out
    }

    /// Every critical point of E on the whole line and every cut between the monotone
    /// pieces of its slope, as t, sorted: E is monotone between consecutive ones (and
    /// beyond the first and the last). Empty for a line whose numbers overflow. For the
    /// pipe-bend oracle (`oracle::bend`), which needs D's monotone pieces.
    pub fn critical_ts(&self) -> Vec<f64> {
        self.check_line();
        let line = Line::new(self);
        if !line.is_finite() {
            return Vec::new();
        }
        let mut out: Vec<f64> = line
            .stationary()
            .into_iter()
            .map(|s| line.t_of_s(s))
            .collect();
        out.sort_by(f64::total_cmp);
        out
    }

    /// The first point of [`FamilyQuery::crossings`] (entering, leaving or touching: a ray
    /// that starts at a horn's centre and runs into the tube reports t = 0).
    pub fn first_crossing(&self) -> Option<f64> {
        self.crossings().first().map(|c| c.t)
    }

    /// The torus and the line are valid.
    pub(super) fn check_line(&self) {
        check_pose(self.center, self.axis, self.origin, self.dir);
        let (major, radial, axial) = (self.major, self.radial, self.axial);
        for v in [major, radial, axial] {
            assert!(
                v > 0.0 && v.is_finite(),
                "need R, a, b > 0 and finite, got R = {major}, a = {radial}, b = {axial}"
            );
        }
    }

    fn check_range(&self) {
        let (t_min, t_max) = (self.t_min, self.t_max);
        assert!(t_min <= t_max, "bad range [{t_min}, {t_max}]");
    }
}

/// The crossings of the whole line, sorted by s, with every cluster of them closer than
/// rounding (`8 ε (S + |s|)` apart, S = R + max(a, b)) made one: where E − 1 is zero over
/// a few floats (a horn's centre: a leave, the touch and an enter within 1e-16·R) or a
/// computed minimum dips just below 1 for a float or two. The line is outside at s = −∞;
/// a cluster that leaves the inside/outside state as it found it is one touching (at its
/// exact zero of E − 1 if it has one, else at its first point), one that changes it is
/// the one entering or leaving (at the first such point in it).
fn resolve_clusters(sorted: Vec<(f64, Passage)>, size: f64) -> Vec<(f64, Passage)> {
    let mut out = Vec::with_capacity(sorted.len());
    let mut inside = false;
    let mut i = 0;
    while i < sorted.len() {
        let mut j = i + 1;
        while j < sorted.len()
            && sorted[j].0 - sorted[j - 1].0 <= 8.0 * f64::EPSILON * (size + sorted[j].0.abs())
        {
            j += 1;
        }
        let cluster = &sorted[i..j];
        let after = match cluster.iter().rev().find(|c| c.1 != Passage::Touching) {
            Some(c) => c.1 == Passage::Entering,
            None => inside,
        };
        let rep = if after == inside {
            let at = cluster
                .iter()
                .find(|c| c.1 == Passage::Touching)
                .unwrap_or(&cluster[0]);
            (at.0, Passage::Touching)
        } else {
            let want = if after {
                Passage::Entering
            } else {
                Passage::Leaving
            };
            *cluster.iter().find(|c| c.1 == want).unwrap_or(&cluster[0])
        };
        out.push(rep);
        inside = after;
        i = j;
    }
    out
}
