//! The exact intersection's driver, written once over [`Real`]: at width 1 ([`Sc`]) it is
//! the scalar [`super::intersect()`], on f64 lanes the batch wavefront's.
//!
//! Steps (module docs of [`super`]): the foot-point line scaled by 1/R, the ray's range in
//! `u`, the bounding sphere's chord test, the depressed quartic, its nearest root in range,
//! then `t` and the normal. Early exits are "no lane still live" (`.any()`), which at width
//! 1 is the scalar `if`, so the scalar path skips the quartic on a chord miss exactly as a
//! hand-written one would. Only the solver differs between the two instantiations
//! ([`NearestRoot`]): the scalar one is the careful solver of [`crate::quartic`], the lane
//! one its common path, which flags the lanes it leaves to the careful one.

use super::reduce::{chord_in_range, coefficients, foot_line, normal};
use crate::geometry::Tube;
use crate::num::V3;
use crate::num::{Real, RealMask, Sc, sc, sc_mask};
use crate::quartic::{nearest_root_depressed, nearest_root_in_range};

/// The nearest root a driver instantiation uses.
pub(crate) trait NearestRoot<R: Real> {
    /// The nearest root of `u⁴ + c2 u² + c1 u + c0` in `[lo, hi]` (NaN for none), and the
    /// lanes left to the careful scalar solver.
    fn nearest(c2: R, c1: R, c0: R, lo: R, hi: R) -> (R, R::Mask);
}

/// The scalar solver ([`crate::quartic`]): every root decided, no lane left over.
/// `CHECKED` keeps its coefficient range check (for raw, unvalidated input).
pub(crate) struct Careful<const CHECKED: bool>;

impl<const CHECKED: bool> NearestRoot<Sc> for Careful<CHECKED> {
    #[inline(always)]
    fn nearest(c2: Sc, c1: Sc, c0: Sc, lo: Sc, hi: Sc) -> (Sc, <Sc as Real>::Mask) {
        let u = if CHECKED {
            nearest_root_depressed(c2.v, c1.v, c0.v, lo.v, hi.v)
        } else {
            nearest_root_in_range(c2.v, c1.v, c0.v, lo.v, hi.v)
        };
        (sc(u.unwrap_or(f64::NAN)), sc_mask(false))
    }
}

/// The lanes' answers (torus frame): `t` in units of `d`, the unit outward normal, the
/// lanes with a hit, and the lanes the careful solver must decide.
pub(crate) struct Found<R: Real> {
    pub(crate) t: R,
    pub(crate) normal: V3<R>,
    pub(crate) hit: R::Mask,
    pub(crate) fallback: R::Mask,
}

/// The nearest hit with `t ∈ [t_min, t_max]` of the torus-frame lines `o + t·d`, or `None`
/// when no lane has a hit or a fallback.
#[inline(always)]
pub(crate) fn nearest_hit<R: Real, N: NearestRoot<R>>(
    tube: &Tube,
    o: V3<R>,
    d: V3<R>,
    t_min: R,
    t_max: R,
) -> Option<Found<R>> {
    let inv_major = t_min.k(tube.inv_major);
    let line = foot_line(o, d, inv_major);
    let chord_sq = line.chord_sq(t_min.k(tube.outer));
    // Most misses end here, before the range's division.
    let touches = !chord_sq.lt(t_min.k(0.0));
    if !touches.any() {
        return None;
    }
    let (lo, hi) = line.u_range(t_min, t_max, inv_major);
    let reaches = touches & chord_in_range(chord_sq, lo, hi);
    if !reaches.any() {
        return None;
    }
    let [c2, c1, c0] = coefficients(line.p, line.dh, t_min.k(tube.minor_rel));
    let (u, cold) = N::nearest(c2, c1, c0, lo, hi);
    let hit = reaches & !u.is_nan() & !cold;
    let fallback = reaches & cold;
    if !(hit | fallback).any() {
        return None;
    }
    Some(Found {
        t: line.t_at(u, t_min.k(tube.major)),
        normal: normal(line.p, line.dh, u, t_min.k(tube.k)),
        hit,
        fallback,
    })
}
