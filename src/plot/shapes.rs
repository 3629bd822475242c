//! The charts of `run`'s other shapes (`results.shapes`): per aspect b/a of the family,
//! each cull's miss capture and rejection rate against ν = R/a (horn and spindle at
//! ν ≤ 1), one line per cull; per bore r_min/r_max and ν of the bends, the same against
//! Δφ, one line per cull and per `wedge+<cull>` (and `wedge`, the wedge alone). A cull
//! that declines a member's shape has no point there.

use super::{Charts, GroupChart, Place, Placed, group_charts};
use crate::results::shapes::ShapeRecord;

/// One shape record as a chart point: its group and its x (ν, or Δφ for a bend).
type Point<'a> = Placed<'a, ShapeRecord>;

/// Miss capture and rejection rate, as `run`'s ring charts.
fn specs<'a>() -> [GroupChart<Point<'a>>; 2] {
    [
        (
            "miss_capture",
            "miss capture (rejected / misses)",
            "miss capture",
            |p| {
                let r = p.record;
                r.counts
                    .miss_capture
                    .filter(|_| r.accepts)
                    .map(|v| (v, None))
            },
        ),
        (
            "rejection_rate",
            "rejection rate (rejected / rays)",
            "rejection rate",
            |p| {
                p.record
                    .accepts
                    .then_some((p.record.counts.rejection_rate, None))
            },
        ),
    ]
}

/// The family's charts into `family` (x: ν), `shapes-b<b/a>-*.svg`; the bends' into
/// `bends` (x: Δφ), `shapes-bend-bore<r>-nu<ν>-*.svg`.
pub(super) fn charts(
    records: &[ShapeRecord],
    family: &mut Charts<'_>,
    bends: &mut Charts<'_>,
) -> Result<(), Box<dyn std::error::Error>> {
    fn point(r: &ShapeRecord) -> Point<'_> {
        let (group, x) = match (r.aspect, r.segment_deg) {
            (Some(aspect), _) => (format!("b{aspect}"), r.counts.nu),
            (None, deg) => (
                format!("bend-bore{}-nu{}", r.bore.unwrap_or_default(), r.counts.nu),
                deg.unwrap_or(360.0),
            ),
        };
        Placed {
            place: Place::new(group, &r.counts.cull, x),
            record: r,
        }
    }
    let (of_family, of_bends): (Vec<Point<'_>>, Vec<Point<'_>>) = records
        .iter()
        .map(point)
        .partition(|p| p.record.aspect.is_some());
    group_charts(&of_family, family, ("shapes-", "family b/a = "), &specs())?;
    group_charts(&of_bends, bends, ("shapes-", "pipe "), &specs())?;
    Ok(())
}
