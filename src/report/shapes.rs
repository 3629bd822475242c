//! The cells of `run`'s tables of the other shapes (`results.shapes`), laid out by
//! `report`'s one table writer.

use crate::results::shapes::ShapeRecord;

/// One cell: its table (`group`), row number, column name and text.
pub(super) struct Cell {
    pub(super) group: String,
    pub(super) row: f64,
    pub(super) column: String,
    pub(super) text: String,
}

/// A record's miss capture: `-` where the cull declines the shape, `n/a` without misses.
fn capture(r: &ShapeRecord) -> String {
    match (r.accepts, r.counts.miss_capture) {
        (false, _) => "-".into(),
        (true, None) => "n/a".into(),
        (true, Some(c)) => format!("{c:.3}"),
    }
}

/// The family's tables, then the bends', each written by `grid(cells, row name, title)`.
pub(super) fn tables(
    records: &[ShapeRecord],
    grid: impl Fn(&[Cell], &str, &dyn Fn(&str) -> String) -> String,
) -> String {
    let family: Vec<Cell> = records
        .iter()
        .filter_map(|r| {
            Some(Cell {
                group: format!("b/a={}", r.aspect?),
                row: r.counts.nu,
                column: r.counts.cull.clone(),
                text: capture(r),
            })
        })
        .collect();
    let bends: Vec<Cell> = records
        .iter()
        .filter(|r| r.segment_deg.is_some() && !r.counts.cull.starts_with("wedge"))
        .map(|r| {
            let behind = match r.counts.cull.as_str() {
                "none" => "wedge".to_string(),
                c => format!("wedge+{c}"),
            };
            let wedged = records.iter().find(|w| {
                w.counts.cull == behind
                    && (w.counts.nu, w.segment_deg, w.bore) == (r.counts.nu, r.segment_deg, r.bore)
            });
            Cell {
                group: format!(
                    "nu={} dphi={}",
                    r.counts.nu,
                    r.segment_deg.unwrap_or_default()
                ),
                row: r.bore.unwrap_or_default(),
                column: r.counts.cull.clone(),
                text: format!("{}/{}", capture(r), wedged.map_or("-".into(), capture)),
            }
        })
        .collect();
    let mut out = String::new();
    if !family.is_empty() {
        out += &grid(&family, "nu", &|g| {
            format!(
                "family {g} (nu > 1 ring, 1 horn, < 1 spindle): miss capture (rejected / \
                 misses; '-': the cull declines the shape and keeps every ray)"
            )
        });
    }
    if !bends.is_empty() {
        out += &grid(&bends, "bore", &|g| {
            format!(
                "bend {g}: miss capture alone / behind the segment's wedge (none: the wedge \
                 alone), rows r_min/r_max"
            )
        });
    }
    out
}
