//! The monotone pieces of F along the line (module docs of [`crate::oracle::bend`]): the
//! points between which both f_rad and f_w are monotone, and F's extremes over an interval.

use super::{BendQuery, Frame, cross, sign_change};

fn sort_dedup(v: &mut Vec<f64>) {
    v.sort_by(f64::total_cmp);
    v.dedup();
}

/// Adds to the sorted points `pts` each sign change of `f` between neighbours, then sorts
/// and dedups them again.
fn add_sign_changes(pts: &mut Vec<f64>, f: &dyn Fn(f64) -> f64) {
    let extra: Vec<f64> = pts
        .windows(2)
        .filter_map(|w| sign_change(f, w[0], w[1]))
        .collect();
    pts.extend(extra);
    sort_dedup(pts);
}

impl BendQuery {
    /// The breakpoints on the whole line: D's critical points, the roots of D = (r_min +
    /// r_max)/2, and each edge distance's minimum (the projected line's crossing of the
    /// edge ray, or its closest point to the axis).
    fn breaks(&self, frame: &Frame) -> Vec<f64> {
        let mut out = self.torus(self.tube).critical_ts();
        if self.bore > 0.0 {
            let mid = 0.5 * (self.bore + self.tube);
            out.extend(self.torus(mid).crossings().iter().map(|c| c.t));
        }
        if frame.wedge {
            let (q0, _) = frame.local(self.origin);
            let v = frame.plane_dir(self.dir);
            let vv = v.length_squared();
            if vv > 0.0 {
                out.push(-q0.dot(v) / vv);
                for u in [frame.s, frame.e] {
                    let cr = cross(v, u);
                    if cr != 0.0 {
                        let t = -cross(q0, u) / cr;
                        if t.is_finite() && (q0 + v * t).dot(u) >= 0.0 {
                            out.push(t);
                        }
                    }
                }
            }
        }
        out.retain(|t| t.is_finite());
        out
    }

    /// Points of `[a, b]` (finite) between which F is the max of two monotone functions,
    /// with each piece's crossing of the two: F's minimum and maximum over `[a, b]` are
    /// among them.
    pub(super) fn candidates(&self, frame: &Frame, a: f64, b: f64) -> Vec<f64> {
        let mut pts = vec![a, b];
        pts.extend(self.breaks(frame).into_iter().filter(|&t| t > a && t < b));
        sort_dedup(&mut pts);
        if !frame.wedge {
            return pts;
        }
        let point = |t: f64| self.origin + self.dir * t;
        let turn = |t: f64| {
            let (ds, de) = frame.edge_distances(frame.local(point(t)).0);
            ds - de
        };
        add_sign_changes(&mut pts, &turn);
        let gap = |t: f64| {
            let (q, y) = frame.local(point(t));
            frame.f_rad(frame.d_core(q, y)) - frame.f_w(q)
        };
        add_sign_changes(&mut pts, &gap);
        pts
    }

    /// The candidates of `[a, b]` with F at each, ascending in t.
    pub(super) fn profile(&self, frame: &Frame, a: f64, b: f64) -> Vec<(f64, f64)> {
        self.candidates(frame, a, b)
            .into_iter()
            .map(|t| (t, frame.f(self.origin + self.dir * t)))
            .collect()
    }
}

impl BendQuery {
    /// The second method: min F over the range's part in the ball of radius 2·(R + r_max)
    /// by `n` even samples and golden-section refinement around the best three, from the
    /// point itself; an upper bound on [`BendQuery::classify`]'s margin there. `None` where
    /// the range misses that ball.
    pub fn margin_by_sampling(&self, n: usize) -> Option<f64> {
        let frame = Frame::new(self);
        let (c0, c1) = self.chord()?;
        let (a, b) = (self.t_min.max(c0), self.t_max.min(c1));
        if a > b {
            return None;
        }
        let at = |t: f64| frame.f(self.origin + self.dir * t);
        let step = (b - a) / n as f64;
        let mut samples: Vec<(f64, f64)> = (0..=n)
            .map(|i| {
                let t = if i == n { b } else { a + step * i as f64 };
                (t, at(t))
            })
            .collect();
        let mut best = samples.iter().map(|s| s.1).fold(f64::INFINITY, f64::min);
        samples.sort_by(|x, y| x.1.total_cmp(&y.1));
        for &(t, _) in samples.iter().take(3) {
            let (mut lo, mut hi) = ((t - step).max(a), (t + step).min(b));
            let g = 0.5 * (5f64.sqrt() - 1.0);
            for _ in 0..200 {
                let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
                if at(x1) < at(x2) {
                    hi = x2;
                } else {
                    lo = x1;
                }
            }
            best = best.min(at(0.5 * (lo + hi)));
        }
        Some(best)
    }
}
