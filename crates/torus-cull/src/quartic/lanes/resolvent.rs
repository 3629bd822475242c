//! The greatest root of Ferrari's resolvent in z = m², over lanes (f64, or f32 for the certified path): the scalar
//! [`crate::quartic`] resolvent's steps (one source, generic over [`Real`]), selected
//! instead of branched on, with its cold case handed back.

use crate::num::CBRT_RANGE;
use crate::num::{Real, RealMask};
use crate::quartic::resolvent::{cardano, cubic, trigonometric};

/// `(z, h′(z), fallback)`: z ≥ 0 the greatest root of
/// h(z) = z³ + 2p z² + (p² − 4r) z − q² for x⁴ + p x² + q x + r, and the lanes the
/// scalar solver must take instead.
///
/// As in the scalar solver, and with its functions: z = w − 2p/3 with w the greatest root
/// of the depressed cubic w³ + 3P′w + 2Q′ ([`cubic`]), by Cardano (one real root,
/// Δ = Q′² + P′³ > 0) or the trigonometric form (three), each computed where a lane of
/// the register needs it and selected; a small root by the fixed point, which keeps its
/// relative precision; then two guarded Newton steps. Unlike the scalar driver, every
/// lane is polished (a lane cannot skip the steps where its neighbours need them) and
/// Vieta's form of a small Cardano root is not used (the polish recovers it).
///
/// Fallback lanes: |Δ| ≤ 10⁻⁹·scale (a near-double root of the resolvent, which the
/// scalar solver settles by the cubic's value at its local minimum: rare, and not worth
/// a lane's worth of work for everyone), a Cardano argument outside the lane cube
/// root's range, and anything not finite.
#[inline(always)]
pub(crate) fn greatest_root<R: Real>(p: R, q: R, r: R) -> (R, R, R::Mask) {
    let zero = p.k(0.0);
    let cubic = cubic(p, q, r);
    // NaN (overflow) is left to the scalar solver too.
    let near_double = cubic.near_double() | cubic.disc.is_nan();

    // Each formula runs only if a lane of this register needs it: in a register whose
    // lanes agree (often, on coherent rays) that halves the work; otherwise both run and
    // the lane's case selects.
    let one_real = cubic.disc.gt(zero);
    let (cardano, outside_cbrt) = if one_real.any() {
        let (u, v, cube) = cardano(cubic.third_p, cubic.half_q, cubic.disc);
        let in_range = cube.ge(zero.k(CBRT_RANGE.0)) & cube.le(zero.k(CBRT_RANGE.1));
        (u + v, one_real & !in_range)
    } else {
        (zero, one_real)
    };
    let trig = if !one_real.all() {
        trigonometric(cubic.third_p, cubic.half_q)
    } else {
        zero
    };
    let w = R::select(one_real, cardano, trig);
    let mut z = (w - cubic.a3).max(zero);
    let tiny = cubic.is_small_root(z);
    if tiny.any() {
        // Rare (a line nearly through the foot point's quartic minimum): only a register
        // with such a lane pays the two divisions.
        z = R::select(tiny, cubic.small_root(q), z);
    }
    let z = cubic.polish(z);
    let dz = cubic.dh(z);
    let fallback = near_double | outside_cbrt | !z.is_finite() | !dz.is_finite();
    (z, dz, fallback)
}
