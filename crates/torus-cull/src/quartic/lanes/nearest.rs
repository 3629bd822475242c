//! Ferrari's split and the nearest root in range, over lanes (f64, or f32 for the certified path): the scalar
//! [`crate::quartic::nearest_root_depressed`]'s common ("clear") path, with its own
//! functions (one source, generic over [`Real`]).

use super::resolvent::greatest_root;
use crate::num::Real;
use crate::quartic::factor::split_at;
use crate::quartic::nearest::{clear_factors, nearest_of_clear};
use crate::quartic::resolvent::Root;

/// The nearest root of x⁴ + p x² + q x + r in [lo, hi] (NaN for none), and the lanes the
/// scalar solver must decide instead.
///
/// The quartic splits as (x² + m x + n₁)(x² − m x + n₂) with z = m² the resolvent's
/// greatest root ([`split_at`], the scalar split); where both factors are clear
/// ([`clear_factors`]) their roots and the nearest one in range come from
/// [`nearest_of_clear`], exactly as in the scalar solver.
///
/// Fallback lanes: the resolvent's (see [`greatest_root`]), and a factor whose
/// discriminant is within 10⁻⁷ of zero relative to its size: a tangent or near-tangent
/// line, decided by the scalar solver on the quartic itself.
#[inline(always)]
pub(crate) fn nearest_root<R: Real>(p: R, q: R, r: R, lo: R, hi: R) -> (R, R::Mask) {
    let (z, dh, resolvent_fallback) = greatest_root(p, q, r);
    let m = z.sqrt();
    // The lane resolvent has no Vieta form: q/m is taken as it comes.
    let root = Root {
        z,
        dh,
        m,
        q_over_m: q / m,
        q_over_m_exact: z.lt(z), // all false
        z_early: z,
    };
    let split = split_at(p, q, r, &root);
    let (disc1, disc2, clear) = clear_factors(&split);
    let best = nearest_of_clear(&split, disc1, disc2, lo, hi);
    let root = R::select(best.eq(p.k(f64::INFINITY)), p.k(f64::NAN), best);
    let bad_input = !(p.is_finite() & q.is_finite() & r.is_finite());
    (root, resolvent_fallback | !clear | bad_input)
}
