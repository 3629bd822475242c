//! The bend oracle's label for a ray whose origin is a point of a face (a ray spawned from
//! a hit), by the rule of the family oracle's `surface.rs`: the origin is the face point it
//! rounds, its own crossing is excluded, the rest of the ray is labelled as any ray is.
//!
//! **The face point.** The origin's faces are those within `10⁻⁸·S` of it (S = R + r_max;
//! two at a cap's edge). It is moved onto each, by the oracle's own projection: onto a
//! torus along its meridian (the core circle's nearest point, out by r), onto a cap along
//! its plane's normal (first the torus, then the cap, at an edge). An origin on no face is
//! not a surface point: ambiguous.
//!
//! **The rule.** With `cos θ_f` the cosine between the direction and each own face's
//! normal, the own crossing lies within `w = 4·(δ + 10⁻¹¹·S)/(min |cos θ_f|·|d|)` of
//! t = 0 (δ the moved point's residual distance from its faces); the own crossing is the
//! line's crossing nearest t = 0 within `w`. Ambiguous: a direction within 10⁻⁹ of
//! tangent to an own face, any other crossing in `(−w, 2w]` (a ray within about
//! 10⁻⁵ of tangent to a torus face that dips into the tube, or out into the bore, by
//! less than about 10⁻¹¹·S has its exit, or its re-hit, inside the window: the oracle
//! cannot separate it from the origin's own, and must not drop it as the origin's).
//! Then:
//! - **outward** (F > 0 past the origin): the first local maximum `t_a` of F past `w`
//!   (before the next crossing); none and no next crossing: a **miss**; none before a
//!   next crossing, or F there ≤ `4·10⁻¹¹·S`: ambiguous (a re-hit that cannot be told
//!   from a touch at the origin). Otherwise the label of the line over
//!   `[max(t_min, t_a), t_max]`, ambiguous within `ε·S + 2·|o − p′|`;
//! - **inward**: the next crossing is the exit; ambiguous when the line is no deeper than
//!   `4·10⁻¹¹·S` before it, or it lies within `10·ε·S` of `t_max`; a hit if it is in
//!   range. The margin is that of the range past `2w`.
//!
//! The first crossing is the first of [`BendQuery::crossings`] on the line through the
//! moved point past `w`, in the range.

use super::{BendQuery, Face, Frame, Passage};
use crate::oracle::spawned_rule::SpawnedLine;
use crate::oracle::{OracleClass, OracleLabel};
use glam::DVec3;

/// How far a marked origin may lie from a face, × S.
const OWN_REACH: f64 = 1e-8;

/// A first crossing: t, passage, face.
type First = Option<(f64, Passage, Face)>;

impl BendQuery {
    /// The origin moved onto its faces (module docs), with the faces; `None` on no face.
    pub fn on_surface(&self) -> Option<(BendQuery, Vec<Face>)> {
        let frame = Frame::new(self);
        let faces = self.faces_at(self.origin, OWN_REACH * self.size());
        if faces.is_empty() {
            return None;
        }
        let (mut q, mut y) = frame.local(self.origin);
        for &face in &faces {
            let r = match face {
                Face::Outer => self.tube,
                Face::Inner => self.bore,
                _ => continue,
            };
            let rho = q.length();
            let core = q * (self.major / rho);
            let dist = (q - core).length().hypot(y);
            q = core + (q - core) * (r / dist);
            y *= r / dist;
        }
        for &face in &faces {
            let u = match face {
                Face::StartCap => frame.s,
                Face::EndCap => frame.e,
                _ => continue,
            };
            q = u * q.dot(u);
        }
        let origin = frame.world(q, y);
        Some((BendQuery { origin, ..*self }, faces))
    }

    /// [`BendQuery::classify`] for a ray from a face point: the rule of the module docs.
    /// Ambiguous labels carry margin 0.
    pub fn classify_from_surface(&self) -> OracleLabel {
        match self.decide() {
            Some((label, _)) => label,
            None => OracleLabel {
                class: OracleClass::Ambiguous,
                margin: 0.0,
            },
        }
    }

    /// For a ray that [`BendQuery::classify_from_surface`] labels a hit: its first
    /// crossing past the origin's own (t from the moved point, in units of `dir`).
    pub fn first_crossing_from_surface(&self) -> First {
        self.decide()
            .and_then(|(l, first)| (l.class == OracleClass::Hit).then_some(first)?)
    }

    fn decide(&self) -> Option<(OracleLabel, First)> {
        let size = self.size();
        let (line, faces) = self.on_surface()?;
        let frame = Frame::new(&line);
        let len = line.dir.length();
        let unit = line.dir / len;
        let p = line.origin;
        let (q, y) = frame.local(p);
        let d = frame.d_core(q, y);
        let mut cos_min = f64::INFINITY;
        let mut delta: f64 = 0.0;
        for &face in &faces {
            cos_min = cos_min.min(line.normal(face, p).dot(unit).abs());
            delta = delta.max(match face {
                Face::Outer => (d - self.tube).abs(),
                Face::Inner => (d - self.bore).abs(),
                Face::StartCap => super::cross(q, frame.s).abs(),
                Face::EndCap => super::cross(q, frame.e).abs(),
            });
        }
        if cos_min <= 1e-9 {
            return None;
        }
        let offset = (p - self.origin).length();
        let spawned = SpawnedLine::new(delta, cos_min, (self.t_min, self.t_max), len, size);
        let window = spawned.window;
        let whole = line.over(f64::NEG_INFINITY, f64::INFINITY);
        let events: Vec<(f64, Passage, Face)> = whole.crossings();
        // The origin's own crossing is the one nearest t = 0 within the window; any other
        // ahead of the origin within 2w (a near-tangent ray's exit, or its re-hit of a
        // concave face, closer than the window) cannot be told from it at the oracle's
        // error. One behind the origin is not the ray's (a cap edge's other face): the ray
        // starts past it, whichever of the two is the origin's own.
        let own = events
            .iter()
            .map(|c| c.0)
            .filter(|t| t.abs() <= window)
            .min_by(|a, b| a.abs().total_cmp(&b.abs()));
        let crowded = events
            .iter()
            .any(|c| c.0 > 0.0 && c.0 <= 2.0 * window && Some(c.0) != own);
        if crowded {
            return None;
        }
        let next = events.iter().map(|c| c.0).find(|&t| t > window);
        let first = events.iter().copied().find(|c| spawned.ahead_in_range(c.0));
        let far = whole.chord().map_or(window, |c| c.1).max(window);
        let end = next.unwrap_or(far);
        let at = |t: f64| frame.f(p + line.dir * t);
        let inward = next.is_some_and(|n| at(0.5 * (window + n)) < 0.0);
        let profile: Vec<(f64, f64)> = if end > window {
            whole.profile(&frame, window, end)
        } else {
            Vec::new()
        };
        // The line over [lo, t_max]: the answer past the extreme point.
        let over = |lo: f64| line.over(lo, self.t_max).classify();
        if !inward {
            // The first local maximum of F past the window; a miss's margin is F at the
            // range's start past the window.
            let peak = profile
                .windows(3)
                .find(|w| w[1].1 >= w[0].1 && w[1].1 >= w[2].1)
                .map(|w| w[1]);
            let start = self.t_min.max(window).min(self.t_max);
            let rise = (peak, next.is_some());
            return spawned.leaving_solid(rise, || at(start), over, offset, first);
        }
        let deepest = profile.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
        spawned.entering_solid(next?, Some(deepest), over, first)
    }
}

/// The world point `p` moved onto the face nearest to it, for tests that make surface
/// points: `None` where no face is within `10⁻⁸·S`.
pub fn onto_face(query: &BendQuery, p: DVec3) -> Option<DVec3> {
    BendQuery {
        origin: p,
        ..*query
    }
    .on_surface()
    .map(|(q, _)| q.origin)
}
