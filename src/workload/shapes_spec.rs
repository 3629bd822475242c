//! A workload file's `shapes` key: the torus-family members and pipe bends that
//! `torus-cull run` sweeps besides the ring torus of `cases` × `nu`.
//!
//! ```json
//! "shapes": { "rays": 4000,
//!   "family": { "nu": [16, 4, 1.25, 1, 0.5, 0.3, 0.1], "aspects": [0.25, 0.5, 1, 2, 4] },
//!   "bends": { "nu": [4], "segments_deg": [360, 180, 90, 30], "bores": [0, 0.5, 0.9] } }
//! ```
//!
//! `family`: one member per (ν, b/a), ν = R/a (> 1 a ring, elliptical where b/a ≠ 1; = 1
//! the horn; < 1 a spindle), a = 1. `bends`: one bend per (ν, Δφ, r_min/r_max), ν =
//! R/r_max, Δφ the segment in degrees, r_min/r_max the bore's share of the tube. Each
//! member draws `rays` rays; either list may be left out, not both.

use super::bend_spec::bore_ratio_ok;
use super::field_list::{FieldError, Repeats, check_list};
use crate::number::Num;
use serde::Deserialize;
use torus_cull::MAX_NU;
use torus_cull::family::{MAX_ASPECT, MIN_ASPECT, MIN_FAMILY_NU};

/// The most rays per member.
pub const MAX_SHAPE_RAYS: i64 = 10_000_000;

/// Δφ in radians of a segment of `deg` degrees (360 is exactly 2π, the whole ring).
pub fn segment_radians(deg: f64) -> f64 {
    deg.to_radians().min(std::f64::consts::TAU)
}

/// The members of a workload's `shapes` key.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapesSpec {
    /// Rays per member.
    pub rays: usize,
    /// The family members (ν = R/a, b/a), ν outermost, in file order.
    pub family: Vec<(f64, f64)>,
    /// The bends (ν = R/r_max, Δφ in degrees, r_min/r_max), ν outermost, in file order.
    pub bends: Vec<(f64, f64, f64)>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawShapes {
    rays: i64,
    #[serde(default)]
    family: Option<RawFamily>,
    #[serde(default)]
    bends: Option<RawBends>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFamily {
    nu: Vec<f64>,
    aspects: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBends {
    nu: Vec<f64>,
    segments_deg: Vec<f64>,
    bores: Vec<f64>,
}

/// The `shapes` key's value, checked field by field (rays, family.nu, family.aspects,
/// bends.nu, bends.segments_deg, bends.bores). Whether the library builds each bend (a
/// bore's torus, the wall) is asked before the sweep (`shape_sweep::refuse_bends`), which
/// names these fields too.
pub(super) fn parse_shapes(value: serde_json::Value) -> Result<ShapesSpec, FieldError> {
    let raw: RawShapes = serde_json::from_value(value).map_err(|e| {
        (
            "shapes".to_string(),
            format!(
                "{e} (expected rays and at least one of family {{nu, aspects}}, \
                 bends {{nu, segments_deg, bores}})"
            ),
        )
    })?;
    if !(1..=MAX_SHAPE_RAYS).contains(&raw.rays) {
        return Err((
            "shapes.rays".into(),
            format!("{} is invalid (allowed: 1 ..= {MAX_SHAPE_RAYS})", raw.rays),
        ));
    }
    if raw.family.is_none() && raw.bends.is_none() {
        return Err((
            "shapes".into(),
            "names no shape (allowed: a `family` key, a `bends` key, or both)".into(),
        ));
    }
    let mut family = Vec::new();
    if let Some(f) = raw.family {
        check_list(
            "shapes.family.nu",
            &f.nu,
            |nu| (MIN_FAMILY_NU..=MAX_NU).contains(&nu),
            &format!(
                "{MIN_FAMILY_NU} <= nu = R/a <= {MAX_NU}: > 1 a ring, 1 the horn, < 1 a spindle"
            ),
            Repeats::Refused,
        )?;
        check_list(
            "shapes.family.aspects",
            &f.aspects,
            |b| (MIN_ASPECT..=MAX_ASPECT).contains(&b),
            &format!("{MIN_ASPECT} <= b/a <= {MAX_ASPECT}"),
            Repeats::Refused,
        )?;
        for &nu in &f.nu {
            for &aspect in &f.aspects {
                // The library decides what it builds: a refusal names both fields.
                torus_cull::family::Toroid::canonical(nu, 1.0, aspect).map_err(|e| {
                    (
                        "shapes.family".to_string(),
                        format!(
                            "the member nu = {} with b/a = {} is refused: {e}",
                            Num(nu),
                            Num(aspect)
                        ),
                    )
                })?;
                family.push((nu, aspect));
            }
        }
    }
    let mut bends = Vec::new();
    if let Some(b) = raw.bends {
        check_list(
            "shapes.bends.nu",
            &b.nu,
            |nu| nu.is_finite() && nu > 1.0 && nu <= MAX_NU,
            &format!("1 < nu = R/r_max <= {MAX_NU}"),
            Repeats::Refused,
        )?;
        check_list(
            "shapes.bends.segments_deg",
            &b.segments_deg,
            |d| d > 0.0 && d <= 360.0,
            "0 < segment <= 360 degrees",
            Repeats::Refused,
        )?;
        check_list(
            "shapes.bends.bores",
            &b.bores,
            bore_ratio_ok,
            "0 <= r_min/r_max < 1",
            Repeats::Refused,
        )?;
        for &nu in &b.nu {
            for &deg in &b.segments_deg {
                bends.extend(b.bores.iter().map(|&bore| (nu, deg, bore)));
            }
        }
    }
    Ok(ShapesSpec {
        rays: raw.rays as usize,
        family,
        bends,
    })
}

#[cfg(test)]
mod tests {
    use super::super::spec::{Workload, WorkloadError};
    use std::path::Path;

    fn parse(shapes: &str) -> Result<Workload, WorkloadError> {
        let text = format!(
            r#"{{"name":"t","seed":7,"cases":["uniform"],"nu":[4],"rays":10,"shapes":{shapes}}}"#
        );
        Workload::parse(text.as_bytes(), Path::new("w.json"))
    }

    #[test]
    fn members_are_the_products_in_file_order() {
        let w = parse(
            r#"{"rays":5,"family":{"nu":[4,0.5],"aspects":[1,0.25]},
                "bends":{"nu":[4],"segments_deg":[360,30],"bores":[0,0.5]}}"#,
        )
        .unwrap();
        let s = w.shapes.unwrap();
        assert_eq!(s.rays, 5);
        assert_eq!(s.family, [(4.0, 1.0), (4.0, 0.25), (0.5, 1.0), (0.5, 0.25)]);
        assert_eq!(s.bends[0], (4.0, 360.0, 0.0));
        assert_eq!(s.bends.len(), 4);
        assert_eq!(super::segment_radians(360.0), std::f64::consts::TAU);
        let w = parse(r#"{"rays":5,"bends":{"nu":[2],"segments_deg":[90],"bores":[0]}}"#).unwrap();
        assert!(w.shapes.unwrap().family.is_empty());
        // A file without the key has no shapes.
        let plain = br#"{"name":"t","seed":7,"cases":["uniform"],"nu":[4],"rays":10}"#;
        assert_eq!(
            Workload::parse(plain, Path::new("w.json")).unwrap().shapes,
            None
        );
    }

    #[test]
    fn bad_shapes_name_file_field_and_range() {
        for (shapes, needle) in [
            (
                r#"{"rays":0,"family":{"nu":[4],"aspects":[1]}}"#,
                "field `shapes.rays`: 0 is invalid (allowed: 1 ..= 10000000)",
            ),
            (
                r#"{"rays":5}"#,
                "field `shapes`: names no shape (allowed: a `family` key, a `bends` key, or both)",
            ),
            (
                r#"{"rays":5,"family":{"nu":[0.001],"aspects":[1]}}"#,
                "field `shapes.family.nu[0]`: 0.001 is invalid (allowed: 0.01 <= nu = R/a <= 1000",
            ),
            (
                r#"{"rays":5,"family":{"nu":[4,4],"aspects":[1]}}"#,
                "field `shapes.family.nu[1]`: 4 is listed twice",
            ),
            (
                r#"{"rays":5,"family":{"nu":[],"aspects":[1]}}"#,
                "field `shapes.family.nu`: must list at least one value",
            ),
            (
                r#"{"rays":5,"family":{"nu":[4],"aspects":[8]}}"#,
                "field `shapes.family.aspects[0]`: 8 is invalid (allowed: 0.25 <= b/a <= 4)",
            ),
            (
                r#"{"rays":5,"bends":{"nu":[1],"segments_deg":[90],"bores":[0]}}"#,
                "field `shapes.bends.nu[0]`: 1 is invalid (allowed: 1 < nu = R/r_max <= 1000)",
            ),
            (
                r#"{"rays":5,"bends":{"nu":[4],"segments_deg":[400],"bores":[0]}}"#,
                "field `shapes.bends.segments_deg[0]`: 400 is invalid (allowed: 0 < segment <= 360 degrees)",
            ),
            (
                r#"{"rays":5,"bends":{"nu":[4],"segments_deg":[90],"bores":[1]}}"#,
                "field `shapes.bends.bores[0]`: 1 is invalid (allowed: 0 <= r_min/r_max < 1)",
            ),
            (
                r#"{"rays":5,"bends":{"nu":[4],"segments_deg":[90]}}"#,
                "field `shapes`: missing field `bores`",
            ),
            (
                r#"{"rays":5,"family":{"nu":[4],"aspects":[1],"colour":1}}"#,
                "field `shapes`: unknown field `colour`",
            ),
        ] {
            let e = parse(shapes).unwrap_err().to_string();
            assert!(
                e.starts_with("workload w.json: ") && e.contains(needle),
                "{shapes}\n  gave: {e}"
            );
        }
    }
}
