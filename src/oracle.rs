//! The f64 ground truth: hit / miss / ambiguous with a signed margin. Never timed.
//!
//! **Definition.** The true torus is the one given by the f32 centre, the f32 axis
//! normalized in f64, and R, r, all converted to f64 exactly; the ray's f32 origin,
//! direction and range are converted exactly too. For a point x, with `c` the centre and
//! `â` the unit axis, `y = (x − c)·â` and `ρ = |(x − c) − y â|`, and
//!
//! `D(x) = √((ρ − R)² + y²)` (the distance from x to the core circle),
//! `margin = min over t ∈ [t_min, t_max] of D(o + t d) − r`.
//!
//! A negative margin means the ray enters the tube. Nothing here calls the crate's quartic
//! solver, its exact intersection or the f32 rotation of [`Torus`]: the oracle must be able
//! to catch their bugs, so it shares no code with them.
//!
//! **Method** (see also the repository's `docs/math.md`). Along the line, in unit arc
//! length `s` measured from the foot point p (the point closest to the centre, which keeps
//! far origins well conditioned), the minimum of D over an interval is at an end or at a critical point of D. Two sets
//! of candidates are evaluated with D itself:
//! - every critical point of D, found exactly by splitting `½ dD²/ds` into at most three
//!   monotone pieces (see `Frame::half_slope`) and bisecting each sign change to the last
//!   bit: this makes the minimum exact, not just close;
//! - every real root of the cubic F′, where F is the torus quartic (own cubic solver,
//!   by monotone pieces and bisection). Since F = (D² − r²)·G with G > 0, F < 0 exactly
//!   where D < r, so these alone already give the right *sign*; the test
//!   `f_prime_candidates_give_the_same_class` checks that.
//!
//! Every candidate is a real point of the interval, so each evaluation is an upper bound
//! on the true minimum and extra candidates can only help.
//!
//! [`margin_by_sampling`] is the second, independent method (dense samples in world
//! coordinates + golden-section refinement) that the tests compare against.

use crate::{Ray, Torus};
use glam::DVec3;

/// Relative half-width ε of the ambiguity band: a label is [`OracleClass::Ambiguous`] iff
/// `|margin| ≤ ε·(R + r)`.
///
/// The oracle's own error is about 1e-16·(R + r + distance of the origin), so 1e-9 leaves
/// orders of magnitude of room for origins up to ~10⁵·R while still being far below what an
/// f32 renderer can resolve.
pub const AMBIGUITY_REL: f64 = 1e-9;

/// The oracle's class for a line or ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OracleClass {
    /// Enters the tube by more than the ambiguity band.
    Hit,
    /// Stays outside the tube by more than the ambiguity band.
    Miss,
    /// |margin| ≤ AMBIGUITY_REL·(R + r).
    Ambiguous,
}

/// The oracle's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OracleLabel {
    /// The class.
    pub class: OracleClass,
    /// min over t of dist(P(t), core circle) − r, in length units; negative enters the tube.
    pub margin: f64,
}

impl OracleLabel {
    /// The label for a margin on a torus with radii R, r.
    pub fn from_margin(margin: f64, major: f64, minor: f64) -> OracleLabel {
        let band = AMBIGUITY_REL * (major + minor);
        let class = if margin.abs() <= band {
            OracleClass::Ambiguous
        } else if margin < 0.0 {
            OracleClass::Hit
        } else {
            OracleClass::Miss
        };
        OracleLabel { class, margin }
    }
}

/// Classify the ray over `t ∈ [t_min, t_max]` (ray mode; `t_max` may be +∞).
pub fn classify(torus: &Torus, ray: &Ray) -> OracleLabel {
    let (c, a, big, small) = torus_f64(torus);
    classify_f64(
        c,
        a,
        big,
        small,
        ray.origin().as_dvec3(),
        ray.dir().as_dvec3(),
        f64::from(ray.t_min()),
        f64::from(ray.t_max()),
    )
}

/// Classify the ray's whole line, `t ∈ (−∞, +∞)` (line mode: the range is ignored).
pub fn classify_line(torus: &Torus, ray: &Ray) -> OracleLabel {
    let (c, a, big, small) = torus_f64(torus);
    classify_f64(
        c,
        a,
        big,
        small,
        ray.origin().as_dvec3(),
        ray.dir().as_dvec3(),
        f64::NEG_INFINITY,
        f64::INFINITY,
    )
}

/// The f64 entry point behind [`classify`] and [`classify_line`]: the line `o + t d`,
/// `t ∈ [t_min, t_max]` (either end may be infinite), against the torus with centre
/// `center`, rotation `axis` (normalized here), R = `major`, r = `minor`.
///
/// `d` need not be unit length; `t` is in units of `d`.
///
/// # Panics
/// If `d` or `axis` is zero or not finite, if `o` or `center` is not finite, if the radii
/// are not `major > minor > 0`, or if `t_min > t_max` or either is NaN.
#[allow(clippy::too_many_arguments)]
pub fn classify_f64(
    center: DVec3,
    axis: DVec3,
    major: f64,
    minor: f64,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) -> OracleLabel {
    let frame = Frame::new(center, axis, major, minor, o, d);
    let (lo, hi) = frame.s_range(t_min, t_max);
    let mut best = f64::INFINITY;
    for s in frame
        .d_candidates(lo, hi)
        .into_iter()
        .chain(frame.f_prime_roots())
    {
        if s >= lo && s <= hi {
            best = best.min(frame.dist(s));
        }
    }
    for s in [lo, hi] {
        if s.is_finite() {
            best = best.min(frame.dist(s));
        }
    }
    OracleLabel::from_margin(best - minor, major, minor)
}

/// All `t ∈ [t_min, t_max]` where the line `o + t d` crosses the torus surface (D = r),
/// sorted, to near f64 precision. Pass infinite ends for the whole line.
///
/// D is monotone between consecutive critical points of D, so each such segment holds at
/// most one crossing; each sign change of `g = D − r` is bisected to adjacent floats in the
/// unit-arc-length parameter, then mapped back to `t`.
///
/// **Tangencies.** Only sign changes are reported (g = 0 counts as outside). A line that
/// touches the surface reports no root if its computed minimum of g is ≥ 0 and two nearly
/// equal roots if it is < 0. So for an [`OracleClass::Ambiguous`] line the roots near the
/// tangency are not meaningful: compare root counts only outside the ambiguity band, where a
/// line hit gives 2 or 4 roots and a line miss gives none.
///
/// # Panics
/// As [`classify_f64`].
#[allow(clippy::too_many_arguments)]
pub fn reference_roots(
    center: DVec3,
    axis: DVec3,
    major: f64,
    minor: f64,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) -> Vec<f64> {
    let frame = Frame::new(center, axis, major, minor, o, d);
    // Beyond |s + p·u| > R + r the point is farther than R + r from the centre, so D > r.
    let reach = (major + minor) * (1.0 + 1e-6) + frame.e.abs();
    let mut cuts = vec![-reach - frame.e];
    cuts.extend(
        frame
            .d_candidates(f64::NEG_INFINITY, f64::INFINITY)
            .into_iter()
            .filter(|&s| s > -reach - frame.e && s < reach - frame.e),
    );
    cuts.push(reach - frame.e);
    cuts.sort_by(f64::total_cmp);
    let g = |s: f64| frame.dist(s) - minor;
    let mut roots = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (ga, gb) = (g(a), g(b));
        if (ga < 0.0) != (gb < 0.0) {
            let s = bisect(&g, a, b, ga);
            roots.push(frame.t_of_s(s));
        }
    }
    roots.retain(|&t| t >= t_min && t <= t_max);
    roots
}

/// The margin by the second, independent method: dense sampling of D in world coordinates
/// over the part of the line that can hold the minimum, then golden-section refinement
/// around every discrete local minimum. Same inputs and meaning as [`classify_f64`]; slow,
/// for tests only.
///
/// The window: let x_n be the point of the range closest to the centre. D(x_n) ≤ |x_n| + R
/// and D(x) ≥ |x| − R everywhere, so every minimizer has |x| ≤ |x_n| + 2R: sampling the
/// chord of that sphere (clipped to the range) is enough, also for lines that miss the torus.
#[allow(clippy::too_many_arguments)]
pub fn margin_by_sampling(
    center: DVec3,
    axis: DVec3,
    major: f64,
    minor: f64,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) -> f64 {
    check_inputs(center, axis, major, minor, o, d, t_min, t_max);
    let a = axis.normalize();
    let dist = |t: f64| {
        let x = (o + t * d) - center;
        let y = x.dot(a);
        let rho = (x - y * a).length();
        (rho - major).hypot(y)
    };
    let dd = d.length_squared();
    let t_c = -(o - center).dot(d) / dd;
    let t_n = t_c.clamp(t_min, t_max);
    let d_c = (o + t_c * d - center).length();
    let d_n = (o + t_n * d - center).length();
    let big = d_n + 2.0 * major + minor;
    let half = ((big * big - d_c * d_c).max(0.0)).sqrt() / dd.sqrt();
    let lo = (t_c - half).max(t_min);
    let hi = (t_c + half).min(t_max);
    // Local minima of D along a line are about r apart at least; r/32 resolves them.
    let chord = (hi - lo) * dd.sqrt();
    let n = ((chord / (minor / 32.0)).ceil() as usize).clamp(2000, 400_000);
    let ts: Vec<f64> = (0..=n)
        .map(|i| lo + (hi - lo) * (i as f64 / n as f64))
        .collect();
    let ds: Vec<f64> = ts.iter().map(|&t| dist(t)).collect();
    let mut best = ds.iter().copied().fold(f64::INFINITY, f64::min);
    for i in 0..=n {
        let left = if i > 0 { ds[i - 1] } else { f64::INFINITY };
        let right = if i < n { ds[i + 1] } else { f64::INFINITY };
        if ds[i] <= left && ds[i] <= right {
            let a = ts[i.saturating_sub(1)];
            let b = ts[(i + 1).min(n)];
            best = best.min(golden_min(&dist, a, b));
        }
    }
    best - minor
}

/// The torus as the oracle defines it: f32 fields converted exactly, axis normalized in f64.
fn torus_f64(torus: &Torus) -> (DVec3, DVec3, f64, f64) {
    (
        torus.center().as_dvec3(),
        torus.axis().as_dvec3().normalize(),
        f64::from(torus.major_radius()),
        f64::from(torus.minor_radius()),
    )
}

#[allow(clippy::too_many_arguments)]
fn check_inputs(
    center: DVec3,
    axis: DVec3,
    major: f64,
    minor: f64,
    o: DVec3,
    d: DVec3,
    t_min: f64,
    t_max: f64,
) {
    assert!(center.is_finite() && o.is_finite(), "non-finite point");
    assert!(
        axis.is_finite() && axis.length_squared() > 0.0,
        "bad axis {axis}"
    );
    assert!(d.is_finite() && d.length_squared() > 0.0, "bad dir {d}");
    assert!(
        minor > 0.0 && major > minor && major.is_finite(),
        "need R > r > 0, got R = {major}, r = {minor}"
    );
    assert!(t_min <= t_max, "bad range [{t_min}, {t_max}]");
}

/// The line in the torus's own terms, parametrized by unit arc length `s` from the foot
/// point: `x(s) − c = p + s u`, `s = s0 + t |d|`.
///
/// With `uh`, `ph` the parts of `u`, `p` perpendicular to the axis, the distance from the
/// axis is `ρ(s)² = A (s − s_m)² + m2`, with `A = |uh|²`, `s_m = −(ph·uh)/A` and
/// `m2 = |ph × uh|²/A` (the closest approach to the axis, exact via the cross product).
struct Frame {
    major: f64,
    minor: f64,
    axis: DVec3,
    /// The foot point relative to the centre.
    p: DVec3,
    /// The unit direction.
    u: DVec3,
    /// |d|: t = (s − s0)/|d|.
    len: f64,
    /// The s of the ray origin.
    s0: f64,
    /// p·u, zero up to rounding; kept so that x(s)·u is exact to rounding.
    e: f64,
    /// u·u, one up to rounding.
    uu: f64,
    a_h: f64,
    s_m: f64,
    m2: f64,
}

impl Frame {
    fn new(center: DVec3, axis: DVec3, major: f64, minor: f64, o: DVec3, d: DVec3) -> Frame {
        check_inputs(center, axis, major, minor, o, d, 0.0, 0.0);
        let axis = axis.normalize();
        let len = d.length();
        let u = d / len;
        let q = o - center;
        let s_origin = q.dot(u);
        // The foot point: removing the along-line part first keeps |p| ≤ |q| and makes
        // every later quantity O(R) for lines near the torus, however far the origin.
        let p = q - s_origin * u;
        let uh = u - u.dot(axis) * axis;
        let ph = p - p.dot(axis) * axis;
        let a_h = uh.length_squared();
        let (s_m, m2) = if a_h > 0.0 {
            (-ph.dot(uh) / a_h, ph.cross(uh).length_squared() / a_h)
        } else {
            (0.0, ph.length_squared())
        };
        Frame {
            major,
            minor,
            axis,
            p,
            u,
            len,
            s0: s_origin,
            e: p.dot(u),
            uu: u.length_squared(),
            a_h,
            s_m,
            m2,
        }
    }

    fn s_of_t(&self, t: f64) -> f64 {
        if t.is_infinite() {
            t
        } else {
            self.s0 + t * self.len
        }
    }

    fn t_of_s(&self, s: f64) -> f64 {
        (s - self.s0) / self.len
    }

    fn s_range(&self, t_min: f64, t_max: f64) -> (f64, f64) {
        assert!(t_min <= t_max, "bad range [{t_min}, {t_max}]");
        (self.s_of_t(t_min), self.s_of_t(t_max))
    }

    /// D(s), from the point itself (not from the ρ² formula), so that it is accurate to
    /// rounding wherever the point is.
    fn dist(&self, s: f64) -> f64 {
        let x = self.p + s * self.u;
        let y = x.dot(self.axis);
        let rho = (x - y * self.axis).length();
        (rho - self.major).hypot(y)
    }

    /// h(s) = ½ dD²/ds = x·u − R (A (s − s_m))/ρ(s), from D² = |x|² + R² − 2Rρ.
    ///
    /// h′(s) = |u|² − R·A·m2/ρ³, which changes sign only where ρ² = k = (R A m2)^(2/3):
    /// so h is monotone on at most three pieces, split at s_m ± √((k − m2)/A). When the
    /// line crosses the axis (m2 = 0) h jumps at s_m by −2R√A; `side` (−1 from the left,
    /// +1 from the right) picks the one-sided limit there.
    fn half_slope(&self, s: f64, side: f64) -> f64 {
        let along = self.e + s * self.uu;
        if self.a_h == 0.0 {
            return along;
        }
        let sigma = s - self.s_m;
        let rho = (self.a_h * sigma * sigma + self.m2).sqrt();
        if rho == 0.0 {
            along - side * self.major * self.a_h.sqrt()
        } else {
            along - self.major * self.a_h * sigma / rho
        }
    }

    /// Where h′ changes sign (and s_m itself), sorted; empty for a line parallel to the axis.
    fn breakpoints(&self) -> Vec<f64> {
        if self.a_h == 0.0 || !self.s_m.is_finite() {
            return Vec::new();
        }
        let k = (self.major * self.a_h * self.m2).cbrt().powi(2);
        let off = ((k - self.m2).max(0.0) / self.a_h).sqrt();
        vec![self.s_m - off, self.s_m, self.s_m + off]
    }

    /// Every critical point of D (both kinds) and every breakpoint, within [lo, hi].
    ///
    /// Critical points satisfy |x·u| = R|A(s − s_m)|/ρ ≤ R√A ≤ R, so they lie in
    /// |s + p·u| ≤ R; the scan covers a little more.
    fn d_candidates(&self, lo: f64, hi: f64) -> Vec<f64> {
        let reach = 1.01 * self.major + self.e.abs() + f64::MIN_POSITIVE;
        let mut cuts = vec![-reach];
        cuts.extend(self.breakpoints().into_iter().filter(|s| s.abs() < reach));
        cuts.push(reach);
        let mut out: Vec<f64> = cuts[1..cuts.len() - 1].to_vec();
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if a >= b {
                continue;
            }
            let ha = self.half_slope(a, 1.0);
            let hb = self.half_slope(b, -1.0);
            if ha == 0.0 {
                out.push(a);
            }
            if hb == 0.0 {
                out.push(b);
            }
            if (ha < 0.0) != (hb < 0.0) && ha != 0.0 && hb != 0.0 {
                // Inside the open piece ρ > 0 (or m2 > 0), so the plain formula is fine.
                out.push(bisect(&|s| self.half_slope(s, 0.0), a, b, ha));
            }
        }
        out.retain(|&s| s >= lo && s <= hi);
        out
    }

    /// The real roots of F′(s), F the torus quartic written in s:
    /// F = W² − 4R²ρ², W = ρ² + y² + R² − r² = w2 s² + w1 s + w0, ρ² = A s² + 2B s + C.
    fn f_prime_roots(&self) -> Vec<f64> {
        let ax = self.axis;
        let (uy, py) = (self.u.dot(ax), self.p.dot(ax));
        let uh = self.u - uy * ax;
        let ph = self.p - py * ax;
        let (a, b, c) = (uh.length_squared(), ph.dot(uh), ph.length_squared());
        let r2 = self.major * self.major;
        let w2 = a + uy * uy;
        let w1 = 2.0 * (b + py * uy);
        let w0 = c + py * py + r2 - self.minor * self.minor;
        // ½F′ = W W′ − 4R²(A s + B), expanded by powers of s.
        let c3 = 2.0 * w2 * w2;
        let c2 = 3.0 * w1 * w2;
        let c1 = w1 * w1 + 2.0 * w0 * w2 - 4.0 * r2 * a;
        let c0 = w0 * w1 - 4.0 * r2 * b;
        cubic_real_roots(c3, c2, c1, c0)
    }
}

/// A root of `f` in [a, b], given `fa = f(a)` and a sign change over [a, b], bisected until
/// a and b are adjacent floats; returns the end with the smaller |f|.
fn bisect(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    let mut fb = f(b);
    loop {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
            fb = fm;
        }
    }
    if fa.abs() <= fb.abs() { a } else { b }
}

/// The least value of `f` found by golden-section search on [a, b] (unimodal assumed;
/// otherwise still an upper bound on the minimum, since every value is a real sample).
fn golden_min(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut best = f(a).min(f(b));
    let mut x1 = b - g * (b - a);
    let mut x2 = a + g * (b - a);
    let (mut f1, mut f2) = (f(x1), f(x2));
    // 0.618^120 ≈ 1e-25: far past f64 resolution of any bracket.
    for _ in 0..120 {
        best = best.min(f1).min(f2);
        if f1 <= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
        if !(a < x1 && x1 <= x2 && x2 < b) {
            break;
        }
    }
    best.min(f1).min(f2)
}

/// The real roots of c3 s³ + c2 s² + c1 s + c0 (c3 > 0), sorted.
///
/// No closed form: the roots of the derivative split [−M, M] (M the Cauchy bound) into
/// monotone pieces and each sign change is bisected. Slow and sure, which is what the
/// oracle wants; a double root without a sign change is not an extremum of F, so skipping
/// it loses nothing here.
fn cubic_real_roots(c3: f64, c2: f64, c1: f64, c0: f64) -> Vec<f64> {
    let f = |s: f64| ((c3 * s + c2) * s + c1) * s + c0;
    let bound = 1.0 + (c2.abs().max(c1.abs()).max(c0.abs())) / c3;
    let mut cuts = vec![-bound];
    let mut crit = quadratic_real_roots(3.0 * c3, 2.0 * c2, c1);
    crit.retain(|s| s.abs() < bound);
    cuts.extend(crit);
    cuts.push(bound);
    let mut roots = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (fa, fb) = (f(a), f(b));
        if fa == 0.0 {
            roots.push(a);
        } else if (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
            roots.push(bisect(&f, a, b, fa));
        }
    }
    if f(bound) == 0.0 {
        roots.push(bound);
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup();
    roots
}

/// The real roots of a s² + b s + c, a ≠ 0, by the cancellation-free form.
fn quadratic_real_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return Vec::new();
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    let mut r = vec![q / a, c / q];
    r.sort_by(f64::total_cmp);
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;
    use rand::{RngExt, SeedableRng};
    use rand_pcg::Pcg64;

    const NUS: [f64; 4] = [1.1, 2.0, 10.0, 32.0];
    const INF: f64 = f64::INFINITY;

    /// A torus pose in f64: centre, unit axis and two unit vectors completing the frame.
    #[derive(Clone, Copy)]
    struct Pose {
        c: DVec3,
        a: DVec3,
        x: DVec3,
        z: DVec3,
        big: f64,
        small: f64,
    }

    impl Pose {
        fn canonical(big: f64, small: f64) -> Pose {
            Pose {
                c: DVec3::ZERO,
                a: DVec3::Y,
                x: DVec3::X,
                z: DVec3::Z,
                big,
                small,
            }
        }
        fn random(rng: &mut Pcg64, big: f64, small: f64) -> Pose {
            let a = unit(rng);
            let (x, z) = a.any_orthonormal_pair();
            let c = DVec3::new(
                rng.random_range(-5.0..5.0),
                rng.random_range(-5.0..5.0),
                rng.random_range(-5.0..5.0),
            ) * big;
            Pose {
                c,
                a,
                x,
                z,
                big,
                small,
            }
        }
        fn point(&self, l: DVec3) -> DVec3 {
            self.c + l.x * self.x + l.y * self.a + l.z * self.z
        }
        fn dir(&self, l: DVec3) -> DVec3 {
            l.x * self.x + l.y * self.a + l.z * self.z
        }
        fn label(&self, o: DVec3, d: DVec3, t0: f64, t1: f64) -> OracleLabel {
            classify_f64(self.c, self.a, self.big, self.small, o, d, t0, t1)
        }
        fn sampled(&self, o: DVec3, d: DVec3, t0: f64, t1: f64) -> f64 {
            margin_by_sampling(self.c, self.a, self.big, self.small, o, d, t0, t1)
        }
        fn roots(&self, o: DVec3, d: DVec3, t0: f64, t1: f64) -> Vec<f64> {
            reference_roots(self.c, self.a, self.big, self.small, o, d, t0, t1)
        }
        /// g = D − r at o + t d, straight from the definition in world coordinates.
        fn g(&self, o: DVec3, d: DVec3, t: f64) -> f64 {
            let x = o + t * d - self.c;
            let y = x.dot(self.a);
            ((x - y * self.a).length() - self.big).hypot(y) - self.small
        }
        fn band(&self) -> f64 {
            AMBIGUITY_REL * (self.big + self.small)
        }
        /// A point on the surface (torus frame) with its outward normal, at angles φ, θ.
        fn surface(&self, phi: f64, theta: f64) -> (DVec3, DVec3) {
            let n = DVec3::new(
                theta.cos() * phi.cos(),
                theta.sin(),
                theta.cos() * phi.sin(),
            );
            let core = DVec3::new(self.big * phi.cos(), 0.0, self.big * phi.sin());
            (core + self.small * n, n)
        }
    }

    fn unit(rng: &mut Pcg64) -> DVec3 {
        loop {
            let v = DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            let l2 = v.length_squared();
            if l2 > 1e-4 && l2 <= 1.0 {
                return v / l2.sqrt();
            }
        }
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn hand_computed_lines_on_the_canonical_torus() {
        let p = Pose::canonical(2.0, 1.0);
        let x = DVec3::X;
        // Along the x axis: through both tube centres (D = 0 at x = ±2), margin −r.
        let o = DVec3::new(-5.0, 0.0, 0.0);
        let l = p.label(o, x, -INF, INF);
        assert_eq!(l.class, OracleClass::Hit);
        assert!(close(l.margin, -1.0, 1e-15), "{l:?}");
        let roots = p.roots(o, x, -INF, INF);
        assert_eq!(roots.len(), 4, "{roots:?}");
        for (t, want) in roots.iter().zip([2.0, 4.0, 6.0, 8.0]) {
            assert!(close(*t, want, 1e-14), "{roots:?}");
        }
        // Vertical line at ρ = 0.5 through the hole: margin |0.5 − 2| − 1.
        let o = DVec3::new(0.3, 3.0, 0.4);
        let l = p.label(o, -DVec3::Y, -INF, INF);
        assert_eq!(l.class, OracleClass::Miss);
        assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
        assert!(p.roots(o, -DVec3::Y, -INF, INF).is_empty());
        // Horizontal line at height 1.5 over both tubes: margin 0.5.
        let l = p.label(DVec3::new(-5.0, 1.5, 0.0), x, -INF, INF);
        assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
        // In the plane z = 2.5 (R ≤ a < R + r), y = 0: ρ ≥ 2.5, so min D = 0.5.
        let l = p.label(DVec3::new(-5.0, 0.0, 2.5), x, -INF, INF);
        assert!(close(l.margin, -0.5, 1e-15), "{l:?}");
        // Inner-equator point, circle-tangent direction: the saddle side, it dips to the core.
        let l = p.label(DVec3::new(1.0, 0.0, -5.0), DVec3::Z, -INF, INF);
        assert!(close(l.margin, -1.0, 1e-15), "{l:?}");
    }

    #[test]
    fn ray_mode_counts_only_the_range() {
        let p = Pose::canonical(2.0, 1.0);
        // The torus is behind the origin: the ray starts at D = 3 and moves away.
        let (o, d) = (DVec3::new(5.0, 0.0, 0.0), DVec3::X);
        let l = p.label(o, d, 0.0, INF);
        assert_eq!(l.class, OracleClass::Miss);
        assert!(close(l.margin, 2.0, 1e-15), "{l:?}");
        assert!(p.roots(o, d, 0.0, INF).is_empty());
        assert_eq!(p.label(o, d, -INF, INF).class, OracleClass::Hit);
        // A non-unit direction and a t_max that stops before the tube: ends at x = −3.5.
        let (o, d) = (DVec3::new(-5.0, 0.0, 0.0), DVec3::new(2.0, 0.0, 0.0));
        let l = p.label(o, d, 0.0, 0.75);
        assert_eq!(l.class, OracleClass::Miss);
        assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
        // Stopping at x = −2.5, inside the tube: one crossing, at x = −3 (t = 1).
        let l = p.label(o, d, 0.0, 1.25);
        assert_eq!(l.class, OracleClass::Hit);
        assert!(close(l.margin, -0.5, 1e-15), "{l:?}");
        assert_eq!(p.roots(o, d, 0.0, 1.25), vec![1.0]);
        // Starting on the core circle: margin −r, one exit at t = 1.
        let (o, d) = (DVec3::new(2.0, 0.0, 0.0), DVec3::Y);
        let l = p.label(o, d, 0.0, INF);
        assert!(close(l.margin, -1.0, 1e-15), "{l:?}");
        let roots = p.roots(o, d, 0.0, INF);
        assert_eq!(roots.len(), 1);
        assert!(close(roots[0], 1.0, 1e-15), "{roots:?}");
    }

    #[test]
    fn f32_wrappers_use_the_ray_range_and_the_line() {
        let torus = Torus::canonical(2.0, 1.0).unwrap();
        let behind = Ray::new(Vec3::new(5.0, 0.0, 0.0), Vec3::X).unwrap();
        assert_eq!(classify(&torus, &behind).class, OracleClass::Miss);
        let line = classify_line(&torus, &behind);
        assert_eq!(line.class, OracleClass::Hit);
        assert!(close(line.margin, -1.0, 1e-15));
        let short = Ray::with_range(Vec3::new(-5.0, 0.0, 0.0), Vec3::X, 0.0, 1.5).unwrap();
        let l = classify(&torus, &short);
        assert!(close(l.margin, 0.5, 1e-15), "{l:?}");
    }

    #[test]
    fn design_section7_counterexamples_are_hits() {
        let p = Pose::canonical(2.0, 1.0);
        let x = DVec3::X;
        // Eq. 35: y = 0.5 through both tubes; crossings at x = ±2 ± √0.75.
        let o = DVec3::new(-6.0, 0.5, 0.0);
        let l = p.label(o, x, -INF, INF);
        assert_eq!(l.class, OracleClass::Hit);
        assert!(close(l.margin, -0.5, 1e-15), "{l:?}");
        let roots = p.roots(o, x, -INF, INF);
        let h = 0.75f64.sqrt();
        let want = [6.0 - 2.0 - h, 6.0 - 2.0 + h, 6.0 + 2.0 - h, 6.0 + 2.0 + h];
        assert_eq!(roots.len(), 4, "{roots:?}");
        for (t, w) in roots.iter().zip(want) {
            assert!(close(*t, w, 1e-14), "{roots:?}");
        }
        // Eq. 105: the plane z = 2, y = 0.5; crossings at x = ±√((2 + √0.75)² − 4) ≈ ±2.0528.
        let o = DVec3::new(-5.0, 0.5, 2.0);
        let l = p.label(o, x, -INF, INF);
        assert_eq!(l.class, OracleClass::Hit);
        assert!(close(l.margin, -0.5, 1e-15), "{l:?}");
        let xr = ((2.0 + h).powi(2) - 4.0).sqrt();
        assert!(close(xr, 2.0528, 1e-4));
        let roots = p.roots(o, x, -INF, INF);
        assert_eq!(roots.len(), 2, "{roots:?}");
        assert!(close(roots[0], 5.0 - xr, 1e-14) && close(roots[1], 5.0 + xr, 1e-14));
        // Eq. 102: steep line through the hole's edge; at t = 3 it is at ρ ≈ 1.056, y = 0.
        let (o, d) = (DVec3::new(0.9, -3.0, 0.5), DVec3::new(0.01, 1.0, 0.0));
        let l = p.label(o, d, -INF, INF);
        assert_eq!(l.class, OracleClass::Hit);
        assert!(l.margin <= p.g(o, d, 3.0) + 1e-15 && p.g(o, d, 3.0) < -0.05);
        assert!(close(l.margin, p.sampled(o, d, -INF, INF), 1e-12));
        assert_eq!(p.roots(o, d, -INF, INF).len(), 2);
    }

    /// Tangent lines whose minimum distance to the core circle is known exactly:
    /// (point, direction) in the torus frame, pushed out by δ along the normal.
    fn exact_tangents(big: f64, small: f64, push: f64) -> [(DVec3, DVec3); 5] {
        let out = big + small + push;
        let top = small + push;
        let inner = big - small - push;
        [
            // Outer equator, vertical: ρ is constant, D ≥ ρ − R.
            (DVec3::new(out, 0.0, 0.0), DVec3::Y),
            // Outer equator, along the circle: ρ only grows, y = 0.
            (DVec3::new(out, 0.0, 0.0), DVec3::Z),
            // Top, across the hole: y is constant, D ≥ |y|, equality at ρ = R.
            (DVec3::new(big, top, 0.0), DVec3::X),
            // Top, along the circle: y constant, equality at the touching point.
            (DVec3::new(big, top, 0.0), DVec3::Z),
            // Inner equator, vertical: ρ constant, D ≥ R − ρ.
            (DVec3::new(inner, 0.0, 0.0), DVec3::Y),
        ]
    }

    #[test]
    fn exact_grazing_lines_have_margin_equal_to_the_push() {
        let mut rng = Pcg64::seed_from_u64(7);
        for nu in NUS {
            let small = 1.0;
            let big = nu * small;
            for pose in [
                Pose::canonical(big, small),
                Pose::random(&mut rng, big, small),
            ] {
                for delta in [1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6] {
                    for (pt, dir) in exact_tangents(big, small, delta * small) {
                        let (o, d) = (pose.point(pt - 3.0 * dir), pose.dir(dir) * 0.7);
                        let l = pose.label(o, d, -INF, INF);
                        // Rounding of the pose: ~1e-16 of |c| ≤ 9R.
                        let tol = 1e-13 * (big + small);
                        assert!(
                            close(l.margin, delta * small, tol),
                            "nu {nu} delta {delta} {pt} {dir}: {l:?}"
                        );
                        let want = if delta < 0.0 {
                            OracleClass::Hit
                        } else {
                            OracleClass::Miss
                        };
                        assert_eq!(l.class, want);
                        let n = pose.roots(o, d, -INF, INF).len();
                        if delta < 0.0 {
                            assert!(n == 2 || n == 4, "{n}");
                        } else {
                            assert_eq!(n, 0);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn ambiguity_band_is_relative_to_the_outer_radius() {
        let p = Pose::canonical(2.0, 1.0);
        let band = p.band();
        for (push, want) in [
            (0.5 * band, OracleClass::Ambiguous),
            (-0.5 * band, OracleClass::Ambiguous),
            (4.0 * band, OracleClass::Miss),
            (-4.0 * band, OracleClass::Hit),
        ] {
            for (pt, dir) in exact_tangents(2.0, 1.0, push) {
                let l = p.label(pt, dir, -INF, INF);
                assert_eq!(l.class, want, "push {push} {pt} {dir}: {l:?}");
                assert!(close(l.margin, push, 1e-15));
            }
        }
    }

    #[test]
    fn random_grazing_lines_touch_at_the_push() {
        let mut rng = Pcg64::seed_from_u64(11);
        let mut windowed = 0;
        for nu in NUS {
            let small = 1.0 / nu.sqrt();
            let big = nu * small;
            for _ in 0..200 {
                let pose = Pose::random(&mut rng, big, small);
                let phi = rng.random_range(0.0..std::f64::consts::TAU);
                let theta = rng.random_range(0.0..std::f64::consts::TAU);
                let (surf, n) = pose.surface(phi, theta);
                let e_phi = DVec3::new(-phi.sin(), 0.0, phi.cos());
                let e_m = n.cross(e_phi);
                let psi = rng.random_range(0.0..std::f64::consts::TAU);
                let dir = psi.cos() * e_m + psi.sin() * e_phi;
                let delta = [1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6][rng.random_range(0..6)];
                let push = delta * small;
                let (o, d) = (pose.point(surf + push * n), pose.dir(dir));
                let tol = 1e-13 * (big + small);
                // The pushed point is at D = r + push and D′ = n·u = 0 there.
                assert!(close(pose.g(o, d, 0.0), push, tol));
                let line = pose.label(o, d, -INF, INF);
                assert!(line.margin <= push + tol, "{line:?} push {push}");
                if delta < 0.0 {
                    assert_eq!(line.class, OracleClass::Hit);
                }
                // Where both curvatures are positive, D″ = cos²ψ/D + sin²ψ·cosθ/ρ > 0: the
                // pushed point is the minimum over a short window around it.
                if theta.cos() > 0.3 {
                    windowed += 1;
                    let w = 0.05 * small;
                    let l = pose.label(o, d, -w, w);
                    assert!(close(l.margin, push, tol), "{l:?} push {push}");
                }
            }
        }
        assert!(windowed > 100);
    }

    /// One random test line in world coordinates: (o, d, t_min, t_max).
    fn random_line(
        rng: &mut Pcg64,
        pose: &Pose,
        kind: usize,
    ) -> (DVec3, DVec3, f64, f64, &'static str) {
        let (big, small) = (pose.big, pose.small);
        let outer = big + small;
        let tau = std::f64::consts::TAU;
        let (name, point, dir) = match kind {
            0 => {
                // Isotropic through the bounding sphere (a little beyond it).
                let u = unit(rng);
                let (e1, e2) = u.any_orthonormal_pair();
                let rad = 1.05 * outer * rng.random::<f64>().sqrt();
                let ang = rng.random_range(0.0..tau);
                ("uniform", rad * (ang.cos() * e1 + ang.sin() * e2), u)
            }
            1 => {
                // Through the hole disk, any direction.
                let rad = (big - small) * rng.random::<f64>().sqrt();
                let ang = rng.random_range(0.0..tau);
                let pt = DVec3::new(rad * ang.cos(), 0.0, rad * ang.sin());
                ("hole", pt, unit(rng))
            }
            2 => {
                let (surf, n) =
                    pose.surface(rng.random_range(0.0..tau), rng.random_range(0.0..tau));
                let t = n.any_orthonormal_pair();
                let psi = rng.random_range(0.0..tau);
                // ±1e-8 sits just outside the band, ±1e-11 inside it.
                let pushes = [
                    1e-2, -1e-2, 1e-4, -1e-4, 1e-6, -1e-6, 1e-8, -1e-8, 1e-11, -1e-11,
                ];
                let delta = pushes[rng.random_range(0..pushes.len())];
                let dir = psi.cos() * t.0 + psi.sin() * t.1;
                ("grazing", surf + delta * small * n, dir)
            }
            3 => {
                // Through a point of the axis: D has a kink there.
                let pt = DVec3::new(0.0, rng.random_range(-2.0..2.0) * small, 0.0);
                ("axis", pt, unit(rng))
            }
            4 => {
                // Parallel to the axis: ρ is constant.
                let rad = rng.random_range(0.0..outer + small);
                let ang = rng.random_range(0.0..tau);
                let pt = DVec3::new(
                    rad * ang.cos(),
                    rng.random_range(-3.0..3.0),
                    rad * ang.sin(),
                );
                let s = if rng.random::<bool>() { 1.0 } else { -1.0 };
                ("parallel", pt, DVec3::Y * s)
            }
            _ => {
                // From 100·R away, aimed into the bounding sphere.
                let from = 100.0 * big * unit(rng);
                let to = unit(rng) * outer * rng.random::<f64>().cbrt();
                ("far", to, (to - from).normalize())
            }
        };
        let back = if name == "far" {
            100.0 * big
        } else {
            rng.random_range(0.0..3.0 * outer)
        };
        let scale = 10f64.powf(rng.random_range(-1.0..1.0));
        let o = pose.point(point - back * dir);
        let d = pose.dir(dir) * scale;
        let t_near = back / scale;
        let (t0, t1) = match rng.random_range(0..4) {
            0 | 1 => (-INF, INF),
            2 => (0.0, INF),
            _ => {
                let a = t_near + rng.random_range(-2.0..2.0) * outer / scale;
                let b = a + rng.random_range(0.0..3.0) * outer / scale;
                (a, b)
            }
        };
        (o, d, t0, t1, name)
    }

    #[test]
    fn methods_agree_on_random_lines() {
        let mut rng = Pcg64::seed_from_u64(2024);
        let per = 500;
        let mut counts = [0usize; 3];
        let mut lines = 0;
        for nu in NUS {
            let small = 1.0 / nu;
            let big = nu * small;
            for kind in 0..6 {
                for i in 0..per {
                    let pose = if i % 4 == 0 {
                        Pose::canonical(big, small)
                    } else {
                        Pose::random(&mut rng, big, small)
                    };
                    let (o, d, t0, t1, name) = random_line(&mut rng, &pose, kind);
                    lines += 1;
                    let l = pose.label(o, d, t0, t1);
                    let m2 = pose.sampled(o, d, t0, t1);
                    let band = pose.band();
                    let ctx =
                        format!("nu {nu} {name} #{i}: o {o} d {d} [{t0}, {t1}] {l:?} sampled {m2}");
                    // The primary method is the exact minimum; sampling is an upper bound.
                    assert!(l.margin <= m2 + 1e-12 * (big + small), "{ctx}");
                    assert!(m2 - l.margin <= 1e-9 * (big + small), "{ctx}");
                    if l.margin.abs() > 2.0 * band {
                        assert_eq!(
                            OracleLabel::from_margin(m2, big, small).class,
                            l.class,
                            "{ctx}"
                        );
                    }
                    counts[l.class as usize] += 1;
                    // Roots lie on the surface and their count fits the class.
                    let roots = pose.roots(o, d, t0, t1);
                    let scale = big + small + (o - pose.c).length().min(1e3 * big);
                    for &t in &roots {
                        assert!(pose.g(o, d, t).abs() <= 1e-13 * scale, "{ctx} root {t}");
                        assert!(t >= t0 && t <= t1);
                    }
                    assert!(roots.windows(2).all(|w| w[0] < w[1]), "{ctx} {roots:?}");
                    if l.class == OracleClass::Ambiguous {
                        continue;
                    }
                    if t0 == -INF {
                        let ok = match l.class {
                            OracleClass::Hit => roots.len() == 2 || roots.len() == 4,
                            _ => roots.is_empty(),
                        };
                        assert!(ok, "{ctx} {roots:?}");
                    } else {
                        let inside = |t: f64| t.is_finite() && pose.g(o, d, t) < 0.0;
                        let end_clear = |t: f64| !t.is_finite() || pose.g(o, d, t).abs() > band;
                        if end_clear(t0) && end_clear(t1) {
                            assert_eq!(
                                roots.len() % 2 == 1,
                                inside(t0) != inside(t1),
                                "{ctx} {roots:?}"
                            );
                        }
                        if l.class == OracleClass::Miss {
                            assert!(roots.is_empty(), "{ctx} {roots:?}");
                        }
                    }
                }
            }
        }
        assert_eq!(lines, NUS.len() * 6 * per);
        // The workload must exercise all three classes, or the test proves little.
        assert!(
            counts[0] > 500 && counts[1] > 500 && counts[2] > 20,
            "{counts:?}"
        );
    }

    #[test]
    fn f_prime_candidates_give_the_same_class() {
        let mut rng = Pcg64::seed_from_u64(99);
        for nu in NUS {
            let (big, small) = (nu, 1.0);
            for i in 0..2000 {
                let pose = Pose::random(&mut rng, big, small);
                let (o, d, _, _, _) = random_line(&mut rng, &pose, i % 6);
                let l = pose.label(o, d, -INF, INF);
                let frame = Frame::new(pose.c, pose.a, big, small, o, d);
                let by_f = frame
                    .f_prime_roots()
                    .into_iter()
                    .map(|s| frame.dist(s) - small)
                    .fold(INF, f64::min);
                assert!(by_f >= l.margin - 1e-13 * (big + small));
                if l.margin.abs() > pose.band() {
                    assert_eq!((by_f < 0.0), (l.margin < 0.0), "{l:?} by F′ {by_f}");
                }
            }
        }
    }

    #[test]
    fn f32_wrappers_agree_with_sampling_on_random_rays() {
        let mut rng = Pcg64::seed_from_u64(5);
        for nu in [1.1f32, 4.0, 32.0] {
            for _ in 0..300 {
                let axis = unit(&mut rng).as_vec3();
                let center = (unit(&mut rng) * 3.0).as_vec3();
                let torus = Torus::new(center, axis, nu, 1.0).unwrap();
                let target = center + (unit(&mut rng) * f64::from(nu + 1.0)).as_vec3();
                let origin = center + (unit(&mut rng) * f64::from(4.0 * nu)).as_vec3();
                let ray = Ray::new(origin, target - origin).unwrap();
                let (c, a, big, small) = torus_f64(&torus);
                let (o, d) = (origin.as_dvec3(), ray.dir().as_dvec3());
                let ray_m = classify(&torus, &ray).margin;
                let line_m = classify_line(&torus, &ray).margin;
                assert!(close(
                    ray_m,
                    margin_by_sampling(c, a, big, small, o, d, 0.0, INF),
                    1e-9 * (big + small)
                ));
                assert!(close(
                    line_m,
                    margin_by_sampling(c, a, big, small, o, d, -INF, INF),
                    1e-9 * (big + small)
                ));
                assert!(line_m <= ray_m);
            }
        }
    }

    #[test]
    fn cubic_and_quadratic_solvers() {
        let r = cubic_real_roots(1.0, 0.0, -7.0, 6.0); // (s − 1)(s − 2)(s + 3)
        assert_eq!(r.len(), 3);
        for (x, w) in r.iter().zip([-3.0, 1.0, 2.0]) {
            assert!(close(*x, w, 1e-15), "{r:?}");
        }
        assert_eq!(cubic_real_roots(1.0, -3.0, 3.0, -1.0), vec![1.0]); // (s − 1)³
        let r = cubic_real_roots(2.0, 0.0, 2.0, -4.0); // 2(s − 1)(s² + s + 2)
        assert_eq!(r.len(), 1);
        assert!(close(r[0], 1.0, 1e-15));
        // Close roots 1 ± 1e-6 and a far one at −1e4.
        let (a, b, c) = (1.0 - 1e-6, 1.0 + 1e-6, -1e4);
        let r = cubic_real_roots(1.0, -(a + b + c), a * b + a * c + b * c, -a * b * c);
        assert_eq!(r.len(), 3, "{r:?}");
        // The rounded coefficients move the close pair by ~1e-10: that is conditioning.
        assert!(
            close(r[0], c, 1e-10) && close(r[1], a, 1e-9) && close(r[2], b, 1e-9),
            "{r:?}"
        );
        let f = |s: f64| ((s - (a + b + c)) * s + (a * b + a * c + b * c)) * s - a * b * c;
        let (lo, hi) = (f(r[1]).abs(), f(r[2]).abs());
        assert!(lo < 1e-9 && hi < 1e-9, "{lo} {hi}");
        assert_eq!(quadratic_real_roots(1.0, 0.0, 1.0), Vec::<f64>::new());
        assert_eq!(quadratic_real_roots(1.0, -3.0, 2.0), vec![1.0, 2.0]);
    }
}
