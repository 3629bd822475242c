//! The two ends of docs/math.md §9's rule for a ray spawned from a surface point, shared by
//! the ring torus's, the family's and the pipe bend's oracles: each finds its own surface
//! point, window and crossings, and the rule then reads the same for all three.

use super::{AMBIGUITY_REL, OracleClass, OracleLabel};

/// The oracle's own relative error (its crossings and distances, relative to the shape's
/// size): a rise or sink of the line smaller than `4·OWN_ERROR·size` is not information.
pub(crate) const OWN_ERROR: f64 = 1e-11;

/// A spawned ray's line, moved onto its surface point: the window `w` that holds the
/// origin's own crossing, the ray's range, `|d|` and the shape's size (the length the
/// tolerances scale with).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpawnedLine {
    pub window: f64,
    pub t_min: f64,
    pub t_max: f64,
    pub len: f64,
    pub size: f64,
}

/// A miss by `margin` (clamped at 0: the line stays out of the solid).
pub(crate) fn miss_by(margin: f64) -> OracleLabel {
    OracleLabel {
        class: OracleClass::Miss,
        margin: margin.max(0.0),
    }
}

impl SpawnedLine {
    /// The line of a ray whose origin lies `delta` (in the shape's distance function) from
    /// its surface point, leaving it at `cos` to the normal: the origin's own crossing lies
    /// within the window `w = 4·(δ + OWN_ERROR·size)/(cos·|d|)` of t = 0.
    pub(crate) fn new(
        delta: f64,
        cos: f64,
        (t_min, t_max): (f64, f64),
        len: f64,
        size: f64,
    ) -> Self {
        SpawnedLine {
            window: 4.0 * (delta + OWN_ERROR * size) / cos / len,
            t_min,
            t_max,
            len,
            size,
        }
    }

    /// A crossing at `t` is the ray's: past the origin's window, and in the range.
    pub(crate) fn ahead_in_range(&self, t: f64) -> bool {
        t > self.window && t >= self.t_min && t <= self.t_max
    }

    /// Out of the solid, the line rising from the origin: the label of the line over the
    /// range past its highest point `peak` (t, height), from `over(lo)` with
    /// `lo = max(t_min, t)`, unless its margin lies within `ε·size + 2·offset`, a graze
    /// that the origin's own offset from its surface point leaves undetermined.
    /// Without a peak, a miss by `miss_margin()` where the line never `comes_back`, and
    /// rounding only (undetermined) where it does; undetermined too where it comes back
    /// after rising by no more than the oracle's error. A range that ends before the peak
    /// is outside all the way: a miss by `miss_margin()`.
    pub(crate) fn leaving_solid<T>(
        &self,
        (peak, comes_back): (Option<(f64, f64)>, bool),
        miss_margin: impl Fn() -> f64,
        over: impl FnOnce(f64) -> OracleLabel,
        offset: f64,
        first: Option<T>,
    ) -> Option<(OracleLabel, Option<T>)> {
        let Some((t_a, height)) = peak else {
            return (!comes_back).then(|| (miss_by(miss_margin()), None));
        };
        if comes_back && height <= 4.0 * OWN_ERROR * self.size {
            return None;
        }
        let lo = self.t_min.max(t_a);
        if lo > self.t_max {
            return Some((miss_by(miss_margin()), None));
        }
        let label = over(lo);
        if label.margin.abs() <= AMBIGUITY_REL * self.size + 2.0 * offset {
            return None;
        }
        Some((label, first))
    }

    /// Into the solid: a hit when `exit`, the next crossing (where the ray leaves), lies in
    /// the range. Ambiguous where the line sinks by no more than the oracle's error
    /// (`deepest`, its lowest value before the exit), or the exit lies within
    /// `10·ε·size` of `t_max`. `outside(lo)` labels the line over `[lo, t_max]`,
    /// `lo = max(t_min, 2w)`: the answer where the exit comes before `lo`, and the margin
    /// of the hit or miss otherwise.
    pub(crate) fn entering_solid<F>(
        &self,
        exit: f64,
        deepest: Option<f64>,
        outside: impl FnOnce(f64) -> OracleLabel,
        first: F,
    ) -> Option<(OracleLabel, F)> {
        if deepest.is_some_and(|depth| depth >= -4.0 * OWN_ERROR * self.size) {
            return None;
        }
        let lo = self.t_min.max(2.0 * self.window);
        if lo > self.t_max {
            return None;
        }
        let outside = outside(lo);
        if exit < lo {
            return Some((outside, first));
        }
        if (exit - self.t_max).abs() * self.len <= 10.0 * AMBIGUITY_REL * self.size {
            return None;
        }
        let class = if exit <= self.t_max {
            OracleClass::Hit
        } else {
            OracleClass::Miss
        };
        let label = OracleLabel {
            class,
            margin: outside.margin,
        };
        Some((label, first))
    }
}
