//! Workload files (`workloads/*.json`): which cases, which ν, how many rays, which seed.
//!
//! ```json
//! { "name": "quick", "seed": 1, "cases": ["hole", "uniform"], "nu": [1.5, 4.0],
//!   "rays": 2000, "pose": "random" }
//! ```
//! Unknown fields are errors. Every error names the file, the field and what is allowed.

use super::{Case, Pose};
use serde::Deserialize;
use sha2::{Digest, Sha256};
use std::fmt;
use std::path::{Path, PathBuf};

/// The most rays per (case, ν) a workload may ask for.
pub const MAX_RAYS: i64 = 10_000_000;

/// A parsed, validated workload file.
#[derive(Debug, Clone, PartialEq)]
pub struct Workload {
    /// The workload's name (results record it).
    pub name: String,
    /// The base seed; each (case, ν) draws its own stream from it.
    pub seed: u64,
    /// The cases, in file order.
    pub cases: Vec<Case>,
    /// The ν sweep, ascending.
    pub nu: Vec<f64>,
    /// Rays per (case, ν).
    pub rays: usize,
    /// Where the torus sits.
    pub pose: Pose,
    /// The BVH scenes, if the file has a `bvh` key (kept as JSON for the BVH module).
    pub bvh: Option<serde_json::Value>,
    /// SHA-256 of the file's bytes, hex.
    pub sha256: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawWorkload {
    name: String,
    seed: serde_json::Number,
    cases: Vec<String>,
    nu: Vec<f64>,
    rays: i64,
    #[serde(default)]
    pose: Option<String>,
    #[serde(default)]
    bvh: Option<serde_json::Value>,
}

/// A workload file that cannot be used.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkloadError {
    /// The file.
    pub file: PathBuf,
    /// The field at fault, if one is.
    pub field: Option<String>,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl fmt::Display for WorkloadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.field {
            Some(field) => write!(
                f,
                "workload {}: field `{field}`: {}",
                self.file.display(),
                self.message
            ),
            None => write!(f, "workload {}: {}", self.file.display(), self.message),
        }
    }
}

impl std::error::Error for WorkloadError {}

impl Workload {
    /// Read and validate a workload file.
    pub fn load(path: &Path) -> Result<Workload, WorkloadError> {
        let bytes = std::fs::read(path).map_err(|e| WorkloadError {
            file: path.to_path_buf(),
            field: None,
            message: format!("cannot read: {e}"),
        })?;
        Workload::parse(&bytes, path)
    }

    /// Parse and validate the bytes of a workload file named `path`.
    pub fn parse(bytes: &[u8], path: &Path) -> Result<Workload, WorkloadError> {
        let err = |field: Option<&str>, message: String| WorkloadError {
            file: path.to_path_buf(),
            field: field.map(str::to_string),
            message,
        };
        let raw: RawWorkload = serde_json::from_slice(bytes).map_err(|e| {
            err(
                None,
                format!(
                    "{e} (expected an object with fields name, seed, cases, nu, rays, and optional pose, bvh)"
                ),
            )
        })?;
        if raw.name.trim().is_empty() {
            return Err(err(Some("name"), "must not be empty".into()));
        }
        if raw.cases.is_empty() {
            return Err(err(
                Some("cases"),
                format!("must list at least one of {}", case_names()),
            ));
        }
        let mut cases = Vec::new();
        for name in &raw.cases {
            let case: Case = name.parse().map_err(|e: String| err(Some("cases"), e))?;
            if cases.contains(&case) {
                return Err(err(Some("cases"), format!("'{name}' is listed twice")));
            }
            cases.push(case);
        }
        if raw.nu.is_empty() {
            return Err(err(
                Some("nu"),
                "must list at least one value (allowed: finite, > 1)".into(),
            ));
        }
        for (i, &nu) in raw.nu.iter().enumerate() {
            if !(nu.is_finite() && nu > 1.0) {
                let why = if cases.contains(&Case::Hole) {
                    "case hole needs a hole, so nu = R/r must be > 1"
                } else {
                    "nu = R/r must be finite and > 1 (ring tori only)"
                };
                return Err(err(
                    Some(&format!("nu[{i}]")),
                    format!("{nu} is invalid: {why}"),
                ));
            }
            if nu > 1e6 {
                return Err(err(
                    Some(&format!("nu[{i}]")),
                    format!("{nu} is invalid (allowed: 1 < nu <= 1e6)"),
                ));
            }
        }
        let mut nu = raw.nu.clone();
        nu.sort_by(f64::total_cmp);
        if nu.windows(2).any(|w| w[0] == w[1]) {
            return Err(err(Some("nu"), "lists a value twice".into()));
        }
        if !(1..=MAX_RAYS).contains(&raw.rays) {
            return Err(err(
                Some("rays"),
                format!("{} is invalid (allowed: 1 ..= {MAX_RAYS})", raw.rays),
            ));
        }
        let seed = raw.seed.as_u64().ok_or_else(|| {
            err(
                Some("seed"),
                format!(
                    "{} is invalid (allowed: an integer 0 ..= {})",
                    raw.seed,
                    u64::MAX
                ),
            )
        })?;
        let pose = match raw.pose.as_deref() {
            None | Some("random") => Pose::Random,
            Some("canonical") => Pose::Canonical,
            Some(other) => {
                return Err(err(
                    Some("pose"),
                    format!("'{other}' is invalid (allowed: random, canonical)"),
                ));
            }
        };
        Ok(Workload {
            name: raw.name,
            seed,
            cases,
            nu,
            rays: raw.rays as usize,
            pose,
            bvh: raw.bvh,
            sha256: hex(&Sha256::digest(bytes)),
        })
    }
}

fn case_names() -> String {
    Case::ALL.map(|c| c.name()).join(", ")
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Workload, WorkloadError> {
        Workload::parse(text.as_bytes(), Path::new("w.json"))
    }

    const GOOD: &str = r#"{"name":"t","seed":7,"cases":["hole","uniform"],"nu":[4,1.5],"rays":10}"#;

    #[test]
    fn good_file_parses_sorted() {
        let w = parse(GOOD).unwrap();
        assert_eq!(w.nu, vec![1.5, 4.0]);
        assert_eq!(w.cases, vec![Case::Hole, Case::Uniform]);
        assert_eq!((w.rays, w.seed, w.pose), (10, 7, Pose::Random));
        assert_eq!(w.sha256.len(), 64);
    }

    #[test]
    fn bad_files_name_file_field_and_range() {
        for (text, needle) in [
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[1.0],"rays":10}"#,
                "field `nu[0]`: 1 is invalid: case hole needs a hole",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["uniform"],"nu":[0.5],"rays":10}"#,
                "field `nu[0]`: 0.5 is invalid",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[],"rays":10}"#,
                "field `nu`: must list",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":-5}"#,
                "field `rays`: -5 is invalid (allowed: 1 ..= 10000000)",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":0}"#,
                "field `rays`: 0 is invalid",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["donut"],"nu":[2],"rays":1}"#,
                "field `cases`: unknown case 'donut' (allowed: hole, outer_band",
            ),
            (
                r#"{"name":"t","seed":7,"cases":[],"nu":[2],"rays":1}"#,
                "field `cases`: must list",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":1,"colour":1}"#,
                "unknown field `colour`",
            ),
            (
                r#"{"name":"t","cases":["hole"],"nu":[2],"rays":1}"#,
                "missing field `seed`",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":1,"pose":"tilted"}"#,
                "field `pose`: 'tilted' is invalid (allowed: random, canonical)",
            ),
            (
                r#"{"name":"t","seed":-1,"cases":["hole"],"nu":[2],"rays":1}"#,
                "field `seed`: -1 is invalid (allowed: an integer 0 ..=",
            ),
            ("not json", "w.json"),
        ] {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.contains(needle), "{text}\n  gave: {e}");
            assert!(e.starts_with("workload w.json"), "{e}");
        }
    }
}
