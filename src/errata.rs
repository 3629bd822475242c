//! Test fixtures: the seed paper's culls as printed. **Not conservative**: they exist so the
//! errata tests (and `torus-cull run --culls cychosz_printed`) can show that the oracle
//! catches a broken cull. They are not part of the renderer API; never render with them.
//!
//! Each misprint and its correction are written up in the repository's `docs/math.md`
//! (errata) and in the docs of [`torus_cull::cull::CychoszCull`] and [`torus_cull::cull::SkalaCull`].

use glam::Vec3;
use pulp::Scalar;
use torus_cull::cull::{Cull, CullBounds, CullVisitor};
use torus_cull::internals::{LaneBounds, Real, SectionFormulas, Vec3s, foot_point, skala_keeps};

crate::named::named_enum! {
    /// The paper-as-printed culls by stable name, as [`torus_cull::cull::CullKind`] names the
    /// real ones: [`Named::ALL`](torus_cull::Named::ALL) lists every printed variant by the stable name used in
    /// results and the CLI.
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
    pub enum PrintedCull: "printed cull" {
        /// Cychosz with the paper's Eq. 35 misprint ([`CychoszPrintedCull`]).
        CychoszPrinted = "cychosz_printed",
        /// Skala with the printed Eq. 105, h_c² = r² − (a − r)² ([`SkalaPrintedCCull`]).
        SkalaPrintedC = "skala_printed_c",
        /// Skala with the printed Eq. 102–103 x_B ([`SkalaEq102Cull`]).
        SkalaEq102 = "skala_eq102",
    }
}

impl PrintedCull {
    /// Hands the concrete cull to `visitor`, as [`torus_cull::cull::CullKind::visit`] does.
    pub fn visit<V: CullVisitor>(self, visitor: V) -> V::Output {
        match self {
            PrintedCull::CychoszPrinted => visitor.visit(CychoszPrintedCull),
            PrintedCull::SkalaPrintedC => visitor.visit(SkalaPrintedCCull),
            PrintedCull::SkalaEq102 => visitor.visit(SkalaEq102Cull),
        }
    }
}

/// Cychosz with Eq. 35 as printed: reject if (y_min > r ∧ y_max > r) ∨ (y_min < r ∧ y_max < r).
/// The second clause should read "< −r"; as printed it rejects lines crossing the tube.
#[derive(Debug, Clone, Copy, Default)]
pub struct CychoszPrintedCull;

impl Cull for CychoszPrintedCull {
    fn name(&self) -> &'static str {
        "cychosz_printed"
    }

    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        let s = Scalar::new();
        let (p, inv_len_sq) = foot_point(Vec3s::splat(s, origin), Vec3s::splat(s, dir));
        let (foot, inv_len_sq) = (Vec3::new(p.x.v, p.y.v, p.z.v), inv_len_sq.v);
        let unit = dir * inv_len_sq.sqrt();
        let half_chord_sq = b.outer_safe_sq() - foot.length_squared();
        if half_chord_sq < 0.0 {
            return false;
        }
        let w = half_chord_sq.sqrt();
        let (y_min, y_max) = (foot.y - unit.y * w, foot.y + unit.y * w);
        let r = b.minor_radius();
        !((y_min > r && y_max > r) || (y_min < r && y_max < r))
    }
}

/// A Skala cull built from the section formulas `$formulas` (one of the printed
/// misreadings below), under the stable name `$name`.
macro_rules! printed_skala_cull {
    ($cull:ty, $name:literal, $formulas:ty) => {
        impl Cull for $cull {
            fn name(&self) -> &'static str {
                $name
            }

            fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
                skala_keeps::<$formulas>(b, origin, dir)
            }
        }
    };
}

/// Skala with Eq. 105 as printed: h_c² = r² − (a − r)² instead of r² − (a − R)².
#[derive(Debug, Clone, Copy, Default)]
pub struct SkalaPrintedCCull;

printed_skala_cull!(SkalaPrintedCCull, "skala_printed_c", Printed<false>);

/// Skala with Eq. 102–103 as printed: x_B = (R − r) cos φ with sin φ = a/R, i.e.
/// x_B² = (R − r)²(1 − a²/R²), wider than the true √((R − r)² − a²).
#[derive(Debug, Clone, Copy, Default)]
pub struct SkalaEq102Cull;

printed_skala_cull!(SkalaEq102Cull, "skala_eq102", Printed<true>);

/// The printed section formulas on the unpadded torus, one misprint at a time: with
/// `EQ102`, x_B as printed in Eq. 102–103 and h_c as corrected; without, x_B as in
/// Eq. 104 and h_c as printed in Eq. 105.
struct Printed<const EQ102: bool>;

impl<const EQ102: bool> SectionFormulas for Printed<EQ102> {
    fn minor<R: Real>(b: &LaneBounds<R>) -> R {
        b.minor_radius
    }
    fn hole_edge_sq_h2<R: Real>(b: &LaneBounds<R>, a_h: R, h_sq: R) -> R {
        let inner = b.major_radius - b.minor_radius;
        if EQ102 {
            let sin_phi_h = a_h / b.major_radius;
            inner * inner * (h_sq - sin_phi_h * sin_phi_h)
        } else {
            inner * inner * h_sq - a_h * a_h
        }
    }
    fn band_height_sq_h2<R: Real>(b: &LaneBounds<R>, a_h: R, h: R) -> R {
        let minor = b.minor_radius;
        // The printed Eq. 105 has r where the corrected one has R.
        let centre = if EQ102 { b.major_radius } else { minor };
        let off = a_h - centre * h;
        minor * minor * h * h - off * off
    }
}
