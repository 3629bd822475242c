//! The second, independent method for the family's margin: dense samples of E in world
//! coordinates and golden-section refinement. Slow; the tests compare the oracle with it.

use super::FamilyQuery;
use crate::oracle::sampling::min_by_samples;

impl FamilyQuery {
    /// The margin by the second method: samples of `(E − 1)·min(a, b)` straight from the
    /// definition in world coordinates ([`FamilyQuery::g`]) over the part of the range that
    /// can hold the minimum, then golden-section refinement around every discrete local
    /// minimum. Same meaning as [`FamilyQuery::classify`]'s margin; for tests only.
    ///
    /// The window: with x_n the point of the range closest to the centre, every minimizer
    /// has E ≤ E(x_n), and E ≥ dist(x, core circle)/max(a, b) ≥ (|x| − R)/max(a, b), so
    /// |x| ≤ R + max(a, b)·E(x_n): the chord of that sphere, clipped to the range.
    pub fn margin_by_sampling(&self) -> f64 {
        self.check_line();
        assert!(self.t_min <= self.t_max, "bad range");
        let (o, d, c) = (self.origin, self.dir, self.center);
        let g = |t: f64| self.g(t);
        let dd = d.length_squared();
        let t_c = -(o - c).dot(d) / dd;
        let t_n = t_c.clamp(self.t_min, self.t_max);
        let d_c = (o + t_c * d - c).length();
        let e_n = g(t_n) / self.radial.min(self.axial) + 1.0;
        let big = (self.major + self.radial.max(self.axial) * e_n) * (1.0 + 1e-9);
        let half = (big * big - d_c * d_c).max(0.0).sqrt() / dd.sqrt();
        let lo = (t_c - half).max(self.t_min);
        let hi = (t_c + half).min(self.t_max);
        if lo > hi {
            // Only where rounding puts t_n just outside the chord: the nearest point.
            return g(t_n);
        }
        // Local minima of E along a line are about min(a, b) apart at least.
        let chord = (hi - lo) * dd.sqrt();
        let step = self.radial.min(self.axial) / 32.0;
        let n = ((chord / step).ceil() as usize).clamp(2000, 400_000);
        min_by_samples(&g, lo, hi, n, 160)
    }
}
