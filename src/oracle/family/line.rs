//! The line in the family's frame, by unit arc length `s` from its foot point: E along it,
//! the monotone pieces of `½ dE²/ds` and its critical points.

use super::FamilyQuery;
use crate::oracle::frame::{foot_point, meridian, s_of_t};
use crate::oracle::interval::bisect;
use glam::DVec3;

/// The line `x(s) − c = p + s u` (`p` the foot point, `u` the unit direction,
/// `s = s0 + t |d|`) with what the method needs of it.
///
/// With `uh`, `ph` the parts of `u`, `p` perpendicular to the axis and `A = |uh|²`,
/// `ρ(s)² = A (s − s_m)² + m²`: `s_m = −(ph·uh)/A` is where the line is closest to the axis
/// and `m = |ph × uh|/|uh|` that closest distance (the kink of ρ where m = 0).
pub(super) struct Line {
    pub(super) major: f64,
    pub(super) radial: f64,
    pub(super) axial: f64,
    pub(super) axis: DVec3,
    /// The foot point relative to the centre.
    pub(super) p: DVec3,
    /// The unit direction.
    pub(super) u: DVec3,
    /// |d|: t = (s − s0)/|d|.
    pub(super) len: f64,
    /// The s of the ray origin.
    pub(super) s0: f64,
    /// u·axis.
    uy: f64,
    /// |uh|².
    a_h: f64,
    s_m: f64,
    m: f64,
    /// ph·uh.
    ph_uh: f64,
    /// Whether the line meets the axis to within rounding: the slope's pieces around s_m
    /// are narrower than a float there (m = 0, or s_m ± off rounds to s_m), so at s_m the
    /// one-sided slopes are those of a kink.
    kink: bool,
}

impl Line {
    pub(super) fn new(query: &FamilyQuery) -> Line {
        query.check_line();
        let axis = query.axis.normalize();
        let len = query.dir.length();
        let u = query.dir / len;
        let q = query.origin - query.center;
        let s0 = q.dot(u);
        // The exact cross products: p to rounding of |p| itself, however far the origin.
        let p = foot_point(q, query.dir);
        let uy = u.dot(axis);
        let uh = u - uy * axis;
        let ph = p - p.dot(axis) * axis;
        let a_h = uh.length_squared();
        let ph_uh = ph.dot(uh);
        let (s_m, m) = if a_h > 0.0 {
            (-ph_uh / a_h, ph.cross(uh).length() / a_h.sqrt())
        } else {
            (0.0, ph.length())
        };
        let mut line = Line {
            major: query.major,
            radial: query.radial,
            axial: query.axial,
            axis,
            p,
            u,
            len,
            s0,
            uy,
            a_h,
            s_m,
            m,
            ph_uh,
            kink: false,
        };
        let cuts = line.breakpoints();
        line.kink = a_h > 0.0 && (m == 0.0 || (cuts.len() == 3 && cuts[0] == cuts[2]));
        line
    }

    /// Whether every number derived from the line is finite (false where |o − c| or |d|
    /// is near f64's largest value).
    pub(super) fn is_finite(&self) -> bool {
        self.p.is_finite()
            && self.u.is_finite()
            && self.s0.is_finite()
            && self.len.is_finite()
            && self.s_m.is_finite()
            && self.m.is_finite()
    }

    pub(super) fn s_of_t(&self, t: f64) -> f64 {
        s_of_t(self.s0, self.len, t)
    }

    pub(super) fn t_of_s(&self, s: f64) -> f64 {
        (s - self.s0) / self.len
    }

    /// E(s) = √(((ρ − R)/a)² + (y/b)²).
    pub(super) fn e(&self, s: f64) -> f64 {
        let (rho, y) = meridian(self.p, self.u, self.axis, s);
        ((rho - self.major) / self.radial).hypot(y / self.axial)
    }

    /// The margin's integrand at s: (E − 1)·min(a, b).
    pub(super) fn g(&self, s: f64) -> f64 {
        (self.e(s) - 1.0) * self.radial.min(self.axial)
    }

    /// `a²·½ dE²/ds = (ρ − R) ρ′ + y u_y (a/b)²` (the factor a² keeps it finite for small
    /// tubes far away; only its sign and zeros are used), with ρ and ρ′ from the line's
    /// model `ρ² = A (s − s_m)² + m²`. Where the line meets the axis (m = 0, or so close
    /// that the pieces around s_m are narrower than a float) ρ′ jumps at s_m from −√A to
    /// +√A; `side` (−1 from the left, +1 from the right, 0 for neither) picks the
    /// one-sided value there.
    ///
    /// Its derivative is `A − R A m²/ρ³ + u_y² (a/b)²` (from ρ″ = A m²/ρ³), increasing in
    /// ρ: so it changes sign at most where `ρ³ = R A m² / W`, `W = A + u_y² (a/b)²`, and the
    /// slope is monotone on at most three pieces, split at `s_m ± √((ρ*² − m²)/A)`
    /// ([`Line::breakpoints`]).
    pub(super) fn half_slope(&self, s: f64, side: f64) -> f64 {
        let y = (self.p + s * self.u).dot(self.axis);
        let ratio = self.radial / self.axial;
        let along = y * self.uy * ratio * ratio;
        // ρ and ρ′ from the line's own model, ρ = √(w²/A + m²), ρ′ = w/ρ with
        // w = A (s − s_m) = ph·uh + s A (no cancellation however far s_m is), not from the
        // point: near the axis the point's part across the axis is mostly rounding, and
        // the model is what the breakpoints are derived from.
        let w = self.ph_uh + s * self.a_h;
        let rho = if self.a_h > 0.0 {
            (w / self.a_h.sqrt()).hypot(self.m)
        } else {
            self.m
        };
        let at_kink = self.kink && s == self.s_m && side != 0.0;
        let drho = if rho > 0.0 && !at_kink {
            w / rho
        } else {
            side * self.a_h.sqrt()
        };
        (rho - self.major) * drho + along
    }

    /// Where the slope's monotone pieces meet, and s_m (the kink, or the closest approach
    /// to the axis), sorted; empty for a line parallel to the axis.
    pub(super) fn breakpoints(&self) -> Vec<f64> {
        if self.a_h == 0.0 {
            return Vec::new();
        }
        let ratio = self.radial / self.axial;
        let w = self.a_h + self.uy * self.uy * ratio * ratio;
        let reach = self.major * self.a_h / w;
        let mut out = vec![self.s_m];
        // ρ* > m ⇔ R A m²/W > m³ ⇔ R A / W > m (m ≤ R there: no overflow).
        if self.m < reach {
            let m = self.m;
            let rho_star = (reach * m * m).cbrt();
            let off = ((rho_star - m) * (rho_star + m) / self.a_h).max(0.0).sqrt();
            out.insert(0, self.s_m - off);
            out.push(self.s_m + off);
        }
        out.retain(|s| s.is_finite());
        out
    }

    /// Every critical point of E² on the line (the zeros of [`Line::half_slope`] on each
    /// monotone piece, each bisected to adjacent floats) and every breakpoint, sorted.
    ///
    /// The two outer pieces run to ±∞, where the slope tends to ±∞ (E² grows like s²):
    /// their far end is found by doubling a step until the slope has the far sign.
    pub(super) fn stationary(&self) -> Vec<f64> {
        let mut cuts = self.breakpoints();
        if cuts.is_empty() {
            cuts.push(0.0);
        }
        let first = cuts[0];
        let last = cuts[cuts.len() - 1];
        let mut out = cuts.clone();
        let slope = |s: f64| self.half_slope(s, 0.0);
        let mut piece = |a: f64, b: f64, ha: f64, hb: f64| {
            if ha == 0.0 {
                out.push(a);
            }
            if hb == 0.0 {
                out.push(b);
            }
            if ha != 0.0 && hb != 0.0 && (ha < 0.0) != (hb < 0.0) {
                out.extend(bisect(&slope, a, b, ha));
            }
        };
        // Left of the first cut the slope increases from −∞.
        if let Some(far) = self.escape(first, -1.0, &|s| slope(s) < 0.0) {
            piece(far, first, slope(far), self.half_slope(first, -1.0));
        }
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if a < b {
                piece(a, b, self.half_slope(a, 1.0), self.half_slope(b, -1.0));
            }
        }
        if let Some(far) = self.escape(last, 1.0, &|s| slope(s) > 0.0) {
            piece(last, far, self.half_slope(last, 1.0), slope(far));
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }

    /// The first `from + side·step` with `done` true, the step starting at the tube's size
    /// plus |from| and doubling; `None` if it overflows first (a line whose numbers are
    /// near f64's largest value).
    pub(super) fn escape(&self, from: f64, side: f64, done: &dyn Fn(f64) -> bool) -> Option<f64> {
        let mut step = self.major + self.radial.max(self.axial) + from.abs() + self.p.length();
        for _ in 0..4096 {
            let s = from + side * step;
            if !s.is_finite() {
                return None;
            }
            if done(s) {
                return Some(s);
            }
            step *= 2.0;
        }
        None
    }
}
