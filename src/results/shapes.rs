//! The rejection records of `run`'s other shapes (the torus family's members and the pipe
//! bends of a workload's `shapes` key): a [`RejectionRecord`] per (member, cull), its
//! fields as the ring's, with the member's parameters beside them. In the results file
//! they are the `shapes` array, apart from the ring's `rejection`, so a ring record and
//! every reader of it stay as they were.

use super::RejectionRecord;
use serde::{Deserialize, Serialize};

/// One cull on one member of the family or one bend: the ring's record (`case` is
/// [`MIXED_CASE`], `nu` the member's ν) with the shape's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShapeRecord {
    /// `ring`, `elliptic` (a ring with b/a ≠ 1), `horn`, `spindle` or `bend`.
    pub shape: String,
    /// b/a, the tube's axial over radial semi-axis (family members; absent for bends).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub aspect: Option<f64>,
    /// r_min/r_max, the bore's share of the tube (bends; absent for family members).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bore: Option<f64>,
    /// Δφ, the segment in degrees (bends; absent for family members).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub segment_deg: Option<f64>,
    /// Whether the cull accepts the member's shape. A cull that declines it (the
    /// `discriminant` culls on a horn or spindle) keeps every ray: its record then counts
    /// 0 rejected because nothing was culled, not because the cull found nothing to cull.
    pub accepts: bool,
    /// The counts, in the file the fields of the record: `case`, `nu` (R/a for the
    /// family, R/r_max for a bend), `cull` (a bend's also `wedge` and `wedge+<cull>`),
    /// `rays`, `hits`, `misses`, `ambiguous`, `rejected`, `false_rejects`,
    /// `rejection_rate`, `miss_capture`.
    #[serde(flatten)]
    pub counts: RejectionRecord,
}

/// The `case` of every shape record: the member's ray kinds in turn (docs/results.md).
pub const MIXED_CASE: &str = "mixed";

impl ShapeRecord {
    /// The member, as the tables name it: `elliptic nu=4 b/a=0.5`, `bend nu=4 dphi=90
    /// bore=0.5`.
    pub fn member(&self) -> String {
        match (self.aspect, self.segment_deg, self.bore) {
            (Some(aspect), _, _) => format!("{} nu={} b/a={aspect}", self.shape, self.counts.nu),
            (None, Some(deg), bore) => format!(
                "{} nu={} dphi={deg} bore={}",
                self.shape,
                self.counts.nu,
                bore.unwrap_or(0.0)
            ),
            (None, None, _) => format!("{} nu={}", self.shape, self.counts.nu),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::results::Results;

    /// A file from before the shapes (no `shapes` key) loads with none, and a file with
    /// none is written without the key, byte for byte as before.
    #[test]
    fn files_without_shapes_load_and_are_written_as_before() {
        let workload = crate::workload::spec::Workload::drawn("t", 1, 1, "t");
        let r = Results::new(&workload, "run");
        let text = serde_json::to_string(&r).unwrap();
        assert!(!text.contains("shapes"), "{text}");
        let back: Results = serde_json::from_str(&text).unwrap();
        assert!(back.shapes.is_empty());
        assert_eq!(back, r);
    }
}
