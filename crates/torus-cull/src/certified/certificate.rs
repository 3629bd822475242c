//! The certificate: what an f32 solve may claim, proved with error bounds, written once
//! over [`Real`] (f32 at width 1 is the scalar path, f32 lanes the batch path).
//!
//! Everything is in the line's scaled foot-point frame ([`super::line`]): the tube's core
//! circle has radius 1, the tube radius is `rr = r/R`, the point at parameter `u` is
//! `p(u) = q + u·d̂` with `q ⊥ d̂`, `|d̂| = 1`, and the torus quartic along the line is
//! `F(u) = u⁴ + c2 u² + c1 u + c0` (depressed, monic). The f32 line `(q̃, d̃)` stands
//! within `ε_p(u)` of the true one (rounding from f64, see [`PointBound`]).
//!
//! Three facts make the proof cheap (docs/math.md, "The certified f32 path"):
//! 1. **The sign of F is the sign of the signed distance** `sdf(p) = √((ρ − 1)² + y²) − rr`
//!    (F = g·g₊ with g = (h − rr)(h + rr), h the distance to the core circle, and
//!    g₊ = (ρ + 1)² + y² − rr² > 0). sdf is 1-Lipschitz in p and evaluates in f32 with an
//!    absolute error of a few ulps, whatever ν: well-conditioned where F is not.
//! 2. **F″(u) = 12u² + 2·c2** (true line): F is convex for u² ≥ −c2/6 and concave between.
//!    On a convex piece a tangent line lies below F; on the concave piece F lies above its
//!    chord. So a few point values and slopes prove "F > 0 on [a, b]".
//! 3. **A hit is a sign change**: sdf > 0 just before the candidate root and < 0 just
//!    after proves a root in between; with "F > 0 from the range's start up to there" it
//!    is the first one.
//!
//! A lane that proves neither a hit nor a miss is escalated to the f64 solver.

use crate::intersect::reduce::coefficients;
pub(crate) use crate::num::V3;
use crate::num::{Real, RealMask};
use crate::quartic::lanes::nearest_root;

/// 2⁻²⁴: the unit roundoff of f32.
pub(crate) const U32: f64 = 1.0 / 16_777_216.0;

/// Half the width of the bracket around a candidate root, in units of R: the proved first
/// root is within this of the reported one, so within 1.9·10⁻⁴·R < 2·10⁻⁴·(R + r) (the
/// accuracy the path promises). Wider proves more near-tangent hits (their signed
/// distance changes slowly); the reported root is the solver's, typically within 10⁻⁶.
pub(crate) const BRACKET: f64 = 1.9e-4;

/// A line in the scaled foot-point frame, with its search range, as [`decide`] takes it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ScaledLine<R> {
    /// The foot point over R (⊥ `d`, up to rounding).
    pub(crate) q: V3<R>,
    /// The unit direction.
    pub(crate) d: V3<R>,
    /// r/R.
    pub(crate) rr: R,
    /// The range `[t_min, t_max]` in `u` (either end may be infinite).
    pub(crate) lo: R,
    pub(crate) hi: R,
    /// How far the f32 line may stand from the true one, relative: `ε_p(u) ≤
    /// line_rel·(|q| + |u|) + line_abs`. On the CPU (f64 reparameterisation rounded once,
    /// then `q + u·d̂` in f32) `line_rel` = 3.1·2⁻²⁴.
    pub(crate) line_rel: R,
    pub(crate) line_abs: R,
}

/// What [`decide`] proved, per lane. A lane in neither mask escalates.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Decision<R: Real> {
    /// The candidate root `u` (meaningful where `hit`).
    pub(crate) u: R,
    /// A hit is proved, the first root in range within [`BRACKET`] of `u`.
    pub(crate) hit: R::Mask,
    /// No root in range, proved.
    pub(crate) miss: R::Mask,
}

/// The per-line constants of the bounds.
#[derive(Clone, Copy)]
struct Bounds<R> {
    /// |q|.
    q_len: R,
    /// 1 − rr².
    k: R,
    /// c2's error bound.
    c2_err: R,
}

/// One point of the line, with error bounds (item 1 and the slope of item 2 above).
#[derive(Clone, Copy)]
struct PointBound<R> {
    /// A lower bound of F there, ≤ 0 unless the point is proved outside the torus.
    f_lo: R,
    /// Lower and upper bounds of F′ there.
    slope_lo: R,
    slope_hi: R,
    /// Lower and upper bounds of sdf there.
    sdf_lo: R,
    sdf_hi: R,
}

#[inline(always)]
fn point_bound<R: Real>(line: &ScaledLine<R>, b: &Bounds<R>, u: R) -> PointBound<R> {
    let one = u.k(1.0);
    let eps = u.k(U32);
    let (q, d) = (line.q, line.d);
    let p = V3 {
        x: q.x + u * d.x,
        y: q.y + u * d.y,
        z: q.z + u * d.z,
    };
    // How far p (as computed) may be from the true line's point at u: the line's own
    // error plus the two roundings of q + u·d̂, 2u·(|q| + |u|).
    let reach = b.q_len + u.abs();
    let eps_p = line.line_rel * reach + line.line_abs;
    let rho_sq = p.x * p.x + p.z * p.z;
    let rho = rho_sq.sqrt();
    let e = rho - one;
    let h = (e * e + p.y * p.y).sqrt();
    let sdf = h - line.rr;
    // sdf is 1-Lipschitz in p, and its rounding adds 2u·ρ (√ of a rounded sum of
    // squares), u·|ρ − 1| ≤ u·(ρ + 1), 2u·h, u·|sdf| ≤ u·(h + rr) and rr's own u·rr:
    // 3u·(ρ + h) + u·(1 + 2rr), bounded here by 4u·(ρ + h) + 2u·(1 + rr) for the
    // second-order terms.
    let sdf_err = eps_p + u.k(4.0 * U32) * (rho + h) + u.k(2.0 * U32) * (one + line.rr);
    let sdf_lo = sdf - sdf_err;
    let sdf_hi = sdf + sdf_err;
    // F = (h − rr)(h + rr)·g₊ with h + rr ≥ 2rr + sdf_lo and g₊ ≥ 1 − rr² + 2ρ.
    let zero = u.k(0.0);
    let g_plus_lo = b.k + u.k(2.0) * (rho - sdf_err).max(zero);
    let f_lo = sdf_lo * (u.k(2.0) * line.rr + sdf_lo) * g_plus_lo * (one - u.k(8.0) * eps);
    let f_lo = R::select(sdf_lo.gt(zero), f_lo, one.negate());
    // F′ = ∇F·d̂ = 4(|p|² + k)(p·d̂) − 8(px d̂x + pz d̂z).
    let p_sq = rho_sq + p.y * p.y;
    let a = p_sq + b.k;
    let bb = p.dot(d);
    let c = p.x * d.x + p.z * d.z;
    let four = u.k(4.0);
    let eight = u.k(8.0);
    let slope = four * a * bb - eight * c;
    // Rounding (at most 10 roundings in a monomial), plus the line's error through F's
    // Hessian (‖H‖ ≤ 12|p|² + 12) and d̂'s rounding through ‖∇F‖ ≤ 4|p|³ + 12|p|.
    // |p| ≤ |q| + |u| (d̂ a unit vector to rounding; the term is tiny beside the others).
    let p_len = reach * u.k(1.0 + 4.0 * U32);
    let twelve = u.k(12.0);
    let slope_err = u.k(10.0 * U32) * (four * a.abs() * bb.abs() + eight * c.abs())
        + (twelve * p_sq + twelve) * eps_p
        + (four * p_sq * p_len + twelve * p_len) * u.k(2.0 * U32);
    PointBound {
        f_lo,
        slope_lo: slope - slope_err,
        slope_hi: slope + slope_err,
        sdf_lo,
        sdf_hi,
    }
}

/// Proved: F > 0 on the convex piece [α, β] (`at_a`, `at_b` its ends' bounds). The
/// tangents at α and β lie below F; their zeros α + F(α)/|F′(α)| and β − F(β)/F′(β)
/// overlap nowhere iff F(α)·F′(β) + F(β)·|F′(α)| > |F′(α)|·F′(β)·(β − α).
#[inline(always)]
fn convex_positive<R: Real>(
    alpha: R,
    beta: R,
    at_a: &PointBound<R>,
    at_b: &PointBound<R>,
) -> R::Mask {
    let zero = alpha.k(0.0);
    let both = at_a.f_lo.gt(zero) & at_b.f_lo.gt(zero);
    let sa = at_a.slope_lo;
    let sb = at_b.slope_hi;
    let lhs = at_a.f_lo * sb + at_b.f_lo * sa.negate();
    let rhs = sa.negate() * sb * (beta - alpha) * alpha.k(1.0 + 8.0 * U32);
    both & (sa.ge(zero) | sb.le(zero) | lhs.gt(rhs))
}

/// F's lowest point on a convex piece [α, β] (approximately: anything in the piece is
/// sound, a better one proves more): Newton on F′ = 4u³ + 2c2·u + c1, which is increasing
/// there and convex right of 0 (concave left of it), so Newton converges monotonically
/// from the piece's outer end (`from`).
#[inline(always)]
fn lowest<R: Real>(c2: R, c1: R, from: R, alpha: R, beta: R) -> R {
    let (two, four, twelve) = (from.k(2.0), from.k(4.0), from.k(12.0));
    let mut u = from;
    for _ in 0..5 {
        let slope = (four * u * u + two * c2) * u + c1;
        let curvature = twelve * u * u + two * c2;
        u = u - slope / curvature;
    }
    u.max(alpha).min(beta)
}

/// Proved: F > 0 on the convex piece [α, β], split at F's lowest point m (from `from`,
/// its outer end). Around m the signed distance does it: sdf is 1-Lipschitz and the
/// direction a unit vector, so sdf(m) > s > 0 keeps the line outside the tube on
/// [m − s, m + s]. Beyond, F slopes away from m by about F″·s, enough to clear the slope's
/// error bound, and the tangents prove each side.
#[inline(always)]
fn convex_piece_positive<R: Real>(
    line: &ScaledLine<R>,
    b: &Bounds<R>,
    (c2, c1): (R, R),
    (from, needed): (R, R::Mask),
    (alpha, at_a): (R, &PointBound<R>),
    (beta, at_b): (R, &PointBound<R>),
) -> R::Mask {
    let zero = alpha.k(0.0);
    // The tangents at the piece's ends alone prove most pieces (F falling towards a hit,
    // or rising away from the range start): the split below only where a lane needs it.
    let simple = convex_positive(alpha, beta, at_a, at_b);
    if !(needed & !simple).any() {
        return simple;
    }
    let m = lowest(c2, c1, from, alpha, beta);
    let at_m = point_bound(line, b, m);
    let clear = at_m.sdf_lo.max(zero);
    let before = (m - clear).max(alpha);
    let after = (m + clear).min(beta);
    let at_before = point_bound(line, b, before);
    let at_after = point_bound(line, b, after);
    simple
        | (at_m.sdf_lo.gt(zero)
            & convex_positive(alpha, before, at_a, &at_before)
            & convex_positive(after, beta, &at_after, at_b))
}

/// Lane by lane, `x` where `m`, else `y`.
#[inline(always)]
fn pick<R: Real>(m: R::Mask, x: &PointBound<R>, y: &PointBound<R>) -> PointBound<R> {
    PointBound {
        f_lo: R::select(m, x.f_lo, y.f_lo),
        slope_lo: R::select(m, x.slope_lo, y.slope_lo),
        slope_hi: R::select(m, x.slope_hi, y.slope_hi),
        sdf_lo: R::select(m, x.sdf_lo, y.sdf_lo),
        sdf_hi: R::select(m, x.sdf_hi, y.sdf_hi),
    }
}

/// w ≥ 0 such that F″ = 12u² + 2c2 ≥ 0 wherever u² ≥ w² (c2 taken at its lowest).
#[inline(always)]
fn inflection<R: Real>(f: &Quartic<R>) -> R {
    ((f.bounds.c2_err - f.c2) * f.c2.k((1.0 + 8.0 * U32) / 6.0))
        .max(f.c2.k(0.0))
        .sqrt()
}

/// Proved: F > 0 on [a, b] (true for an empty interval, a > b). Lanes outside `active`
/// (already decided) get an answer too, but no work is done for them alone.
#[inline(always)]
fn positive<R: Real>(
    line: &ScaledLine<R>,
    (f, w): (&Quartic<R>, R),
    active: R::Mask,
    (lo, at_lo): (R, &PointBound<R>),
    (hi, at_hi): (R, &PointBound<R>),
) -> R::Mask {
    let (b, c2, c1) = (&f.bounds, f.c2, f.c1);
    let zero = lo.k(0.0);
    let minus_w = w.negate();
    let at_minus_w = point_bound(line, b, minus_w);
    let at_w = point_bound(line, b, w);
    // Left convex piece [lo, min(hi, −w)].
    let left_end_is_hi = hi.le(minus_w);
    let left_end = R::select(left_end_is_hi, hi, minus_w);
    let left_exists = lo.le(left_end);
    let left_ok = convex_piece_positive(
        line,
        b,
        (c2, c1),
        (lo, active & left_exists),
        (lo, at_lo),
        (left_end, &pick(left_end_is_hi, at_hi, &at_minus_w)),
    );
    // Right convex piece [max(lo, w), hi].
    let right_start_is_lo = lo.ge(w);
    let right_start = R::select(right_start_is_lo, lo, w);
    let right_exists = right_start.le(hi);
    let right_ok = convex_piece_positive(
        line,
        b,
        (c2, c1),
        (hi, active & right_exists),
        (right_start, &pick(right_start_is_lo, at_lo, &at_w)),
        (hi, at_hi),
    );
    // Middle piece [max(lo, −w), min(hi, w)]: F″ ≤ 12w² + 2·c2_hi = 4·c2_err there, so F
    // is at least its chord's lower end minus 4·c2_err·(β − α)²/8.
    let mid_start_is_lo = lo.ge(minus_w);
    let mid_end_is_hi = hi.le(w);
    let alpha = R::select(mid_start_is_lo, lo, minus_w);
    let beta = R::select(mid_end_is_hi, hi, w);
    let mid_exists = alpha.le(beta);
    let f_alpha = R::select(mid_start_is_lo, at_lo.f_lo, at_minus_w.f_lo);
    let f_beta = R::select(mid_end_is_hi, at_hi.f_lo, at_w.f_lo);
    let span = beta - alpha;
    let sag = lo.k(0.5 * (1.0 + 8.0 * U32)) * b.c2_err * span * span;
    let mid_ok = f_alpha.gt(zero) & f_beta.gt(zero) & (f_alpha.min(f_beta)).gt(sag);
    (!left_exists | left_ok) & (!right_exists | right_ok) & (!mid_exists | mid_ok)
}

/// The quartic along a scaled line, and the range clipped to the bounding sphere's chord.
#[derive(Clone, Copy)]
struct Quartic<R: Real> {
    c2: R,
    c1: R,
    c0: R,
    bounds: Bounds<R>,
    /// An upper bound of the true chord's u²: negative for a line that misses the sphere.
    chord_sq: R,
    /// The range clipped to the chord.
    lo: R,
    hi: R,
}

#[inline(always)]
fn quartic<R: Real>(line: &ScaledLine<R>) -> Quartic<R> {
    let (q, d, rr) = (line.q, line.d, line.rr);
    let one = rr.k(1.0);
    let eps = rr.k(U32);
    // The quartic, in the f64 path's forms that do not cancel near the surface (the same
    // function).
    let [c2, c1, c0] = coefficients(q, d, rr);
    let rho = (q.x * q.x + q.z * q.z).sqrt();
    let two = rr.k(2.0);
    let q_len_sq = q.dot(q);
    let q_len = q_len_sq.sqrt();
    let line_at_foot = line.line_rel * q_len + line.line_abs;
    let rho_plus = rho + one;
    let c2_err = rr.k(16.0 * U32)
        * (two * rho_plus * rho_plus + two * (q.y * q.y + rr * rr) + rr.k(4.0))
        + rr.k(8.0) * line_at_foot
        + rr.k(8.0) * eps;
    // The chord: every true root has u² ≤ (1 + rr)² − |q_true|², which this bounds above.
    let outer = one + rr;
    let chord_sq = outer * outer * rr.k(1.0 + 16.0 * U32) - q_len_sq * rr.k(1.0 - 16.0 * U32)
        + rr.k(4.0) * line_at_foot;
    let chord = chord_sq.max(rr.k(0.0)).sqrt();
    Quartic {
        c2,
        c1,
        c0,
        bounds: Bounds {
            q_len,
            k: one - rr * rr,
            c2_err,
        },
        chord_sq,
        lo: line.lo.max(chord.negate()),
        hi: line.hi.min(chord),
    }
}

/// The f32 solve alone, with no proof: the nearest root in range (NaN for none). What the
/// certificate costs is timed against this (`batch_f32_uncertified_ns`); its answers are
/// not to be trusted near tangents.
#[inline(always)]
pub(crate) fn solve_uncertified<R: Real>(line: &ScaledLine<R>) -> R {
    let f = quartic(line);
    nearest_root(f.c2, f.c1, f.c0, f.lo, f.hi).0
}

/// What the quick stage computed, for [`decide`]'s full proof.
struct Stage<R: Real> {
    f: Quartic<R>,
    root: R,
    found: R::Mask,
    finite: R::Mask,
    left: R,
    at_left: PointBound<R>,
    at_lo: PointBound<R>,
    sign_change: R::Mask,
    /// [`inflection`]'s w, for the full proof's pieces.
    w: R,
}

/// The common case, cheaply (three point evaluations): a hit whose range start and
/// bracket lie on one convex piece of F, where the tangents at both ends prove F > 0
/// before the bracket (a ray entering the tube without passing near it first); a miss of
/// the bounding sphere, or a range outside its chord. Everything else is left undecided
/// for [`decide`]'s full proof.
#[inline(always)]
fn quick<R: Real>(line: &ScaledLine<R>) -> (Decision<R>, Stage<R>) {
    let f = quartic(line);
    let (lo, hi, b) = (f.lo, f.hi, f.bounds);
    let zero = lo.k(0.0);
    // The solver's "careful" lanes (near-double resolvent roots, near-tangent factors) are
    // not escalated on its word: soundness rests on the proof alone, which fails wherever
    // the f32 root is wrong, and often succeeds where the flag was only cautious.
    let (root, _careful) = nearest_root(f.c2, f.c1, f.c0, lo, hi);
    let found = !root.is_nan();
    let finite = line.rr.is_finite() & f.chord_sq.is_finite() & f.c2.is_finite() & f.c0.is_finite();

    // Hit: sdf > 0 at the bracket's start, < 0 at its end, F > 0 before it.
    let bracket = lo.k(BRACKET);
    let left = (root - bracket).max(lo);
    let right = (root + bracket).min(line.hi);
    let at_left = point_bound(line, &b, left);
    let at_right = point_bound(line, &b, right);
    let sign_change = at_left.sdf_lo.gt(zero) & at_right.sdf_hi.lt(zero);
    let w = inflection(&f);
    let one_piece = left.le(w.negate()) | lo.ge(w);
    let at_lo = point_bound(line, &b, lo);
    let hit =
        finite & found & sign_change & one_piece & convex_positive(lo, left, &at_lo, &at_left);
    let no_chord = f.chord_sq.lt(zero);
    let empty = hi.lt(lo);
    let miss = finite & (no_chord | empty);
    (
        Decision { u: root, hit, miss },
        Stage {
            f,
            root,
            found,
            finite,
            left,
            at_left,
            at_lo,
            sign_change,
            w,
        },
    )
}

/// Solve in f32 and prove the answer (module docs). Lanes with non-finite input escalate.
///
/// The quick stage first; where a lane is left undecided, the full proof of "F > 0" over
/// the convex, concave and convex pieces: up to the bracket for a hit, over the whole range
/// for a miss.
#[inline(always)]
pub(crate) fn decide<R: Real>(line: &ScaledLine<R>) -> Decision<R> {
    let (quick, stage) = quick(line);
    if (quick.hit | quick.miss).all() {
        return quick;
    }
    let f = &stage.f;
    let hit_range_hi = R::select(stage.found, stage.left, f.hi);
    let at_hi = pick(
        stage.found,
        &stage.at_left,
        &point_bound(line, &f.bounds, f.hi),
    );
    let undecided = !(quick.hit | quick.miss);
    let clear = positive(
        line,
        (f, stage.w),
        undecided,
        (f.lo, &stage.at_lo),
        (hit_range_hi, &at_hi),
    );
    Decision {
        u: stage.root,
        hit: quick.hit | (stage.finite & stage.found & stage.sign_change & clear),
        miss: quick.miss | (stage.finite & !stage.found & clear),
    }
}

/// The unit outward normal at `p(u)` in the scaled frame (the f64 path's function).
#[inline(always)]
pub(crate) fn normal_at<R: Real>(line: &ScaledLine<R>, u: R) -> V3<R> {
    let k = u.k(1.0) - line.rr * line.rr;
    crate::intersect::reduce::normal(line.q, line.d, u, k)
}
