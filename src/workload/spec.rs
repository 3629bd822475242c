//! Workload files (`workloads/*.json`): which cases, which ν, how many rays, which seed.
//!
//! ```json
//! { "name": "quick", "seed": 1, "cases": ["hole", "uniform"], "nu": [1.5, 4.0],
//!   "rays": 2000, "pose": "random" }
//! ```
//! Unknown fields are errors. Every error names the file, the field and what is allowed.

use super::bend_spec::{BendSpec, parse_bend};
use super::shapes_spec::{ShapesSpec, parse_shapes};
use super::{Case, Pose};
use crate::scene_kind::SceneKind;
use serde::Deserialize;
use sha2::{Digest, Sha256};
use std::fmt;
use std::path::{Path, PathBuf};
use torus_cull::{MAX_NU, Named};

/// The most rays per (case, ν) a workload may ask for.
pub const MAX_RAYS: i64 = 10_000_000;

/// The workloads built into the binary, by name: `--workload default` and
/// `--workload quick` need no file, so the installed command runs from any folder. Their
/// bytes are the repository's `workloads/default.json` and `workloads/quick.json`, so a
/// run records the same name and `workload_sha256` as one that reads the file.
pub const BUILT_IN: [(&str, &str); 2] = [
    ("default", include_str!("../../workloads/default.json")),
    ("quick", include_str!("../../workloads/quick.json")),
];

/// The text of the built-in workload that `arg` names, if it is exactly one of the names
/// of [`BUILT_IN`] (anything else, `./quick` included, is a file path).
pub fn built_in(arg: &Path) -> Option<&'static str> {
    BUILT_IN
        .iter()
        .find(|(name, _)| arg.as_os_str() == *name)
        .map(|&(_, text)| text)
}

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
    /// The many-torus BVH scenes, if the file has a `bvh` key.
    pub bvh: Option<BvhSpec>,
    /// The pipe bends, if the file has a `bend` key (`torus-cull bend --workload`).
    pub bend: Option<BendSpec>,
    /// The family members and bends `run` sweeps, if the file has a `shapes` key.
    pub shapes: Option<ShapesSpec>,
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
    #[serde(default)]
    bend: Option<serde_json::Value>,
    #[serde(default)]
    shapes: Option<serde_json::Value>,
}

/// The `bvh` key: many-torus scenes for the BVH bench and `render`.
///
/// ```json
/// "bvh": { "scenes": ["ring_field", "chain", "facing_grid"], "nu": [2, 4, 8],
///          "tori": 1000, "image": 512, "random_rays": 65536, "brute_force_stride": 16 }
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BvhSpec {
    /// Scene layouts.
    pub scenes: Vec<SceneKind>,
    /// ν of the scenes' tori.
    pub nu: Vec<f64>,
    /// Tori per scene.
    pub tori: usize,
    /// Camera image side, pixels (image × image camera rays).
    pub image: usize,
    /// Random rays through the scene's bounds.
    pub random_rays: usize,
    /// Every this many rays is also checked against brute force (all tori, no cull).
    pub brute_force_stride: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBvh {
    scenes: Vec<String>,
    nu: Vec<f64>,
    tori: i64,
    image: i64,
    random_rays: i64,
    #[serde(default)]
    brute_force_stride: Option<i64>,
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
    /// The workload of a check that draws its own rays (`f32-check`, `family`): no cases
    /// and no ν of its own, `rays` per family from `seed`, random poses, identified by the
    /// SHA-256 of `spec` (what it draws, in words) where a file's would be.
    pub fn drawn(name: &str, seed: u64, rays: usize, spec: &str) -> Workload {
        Workload {
            name: name.into(),
            seed,
            cases: Vec::new(),
            nu: Vec::new(),
            rays,
            pose: Pose::Random,
            bvh: None,
            bend: None,
            shapes: None,
            sha256: hex(&Sha256::digest(spec.as_bytes())),
        }
    }

    /// `--workload ARG`: the built-in workload `arg` names ([`BUILT_IN`]), or else the
    /// workload file at `arg`.
    pub fn open(arg: &Path) -> Result<Workload, WorkloadError> {
        match built_in(arg) {
            Some(text) => Workload::parse(text.as_bytes(), arg),
            None => Workload::load(arg),
        }
    }

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
        let raw: RawWorkload = serde_json::from_slice(bytes).map_err(|e| WorkloadError {
            file: path.to_path_buf(),
            field: None,
            message: format!(
                "{e} (expected an object with fields name, seed, cases, nu, rays, and optional pose, bvh, bend, shapes)"
            ),
        })?;
        validate(raw, hex(&Sha256::digest(bytes))).map_err(|(field, message)| WorkloadError {
            file: path.to_path_buf(),
            field: Some(field),
            message,
        })
    }
}

/// What is wrong with a well-formed file: (the field at fault, what is wrong and what is
/// allowed).
type FieldError = (String, String);

/// The workload `raw` describes, checked one field at a time in a fixed order (name,
/// cases, nu, rays, seed, pose, bvh, bend, shapes): of a file's several faults, the same one is
/// named.
fn validate(raw: RawWorkload, sha256: String) -> Result<Workload, FieldError> {
    check_name(&raw.name)?;
    let cases = parse_cases(&raw.cases)?;
    let nu = parse_nu(&raw.nu, &cases)?;
    let rays = check_rays(raw.rays)?;
    let seed = parse_seed(&raw.seed)?;
    let pose = parse_pose(raw.pose.as_deref())?;
    let bvh = raw.bvh.map(parse_bvh).transpose()?;
    let bend = raw.bend.map(parse_bend).transpose()?;
    let shapes = raw.shapes.map(parse_shapes).transpose()?;
    Ok(Workload {
        name: raw.name,
        seed,
        cases,
        nu,
        rays,
        pose,
        bvh,
        bend,
        shapes,
        sha256,
    })
}

fn check_name(name: &str) -> Result<(), FieldError> {
    let field = || "name".to_string();
    if name.trim().is_empty() {
        return Err((field(), "must not be empty".into()));
    }
    // The name goes into default file names under results/: it must stay a file name.
    if name.contains(['/', '\\', '\0']) || name == "." || name.contains("..") {
        return Err((
            field(),
            format!(
                "'{}' is invalid: it is part of output file names under results/ \
                 (allowed: no '/', '\\', NUL or '..')",
                name.escape_debug()
            ),
        ));
    }
    Ok(())
}

fn parse_cases(names: &[String]) -> Result<Vec<Case>, FieldError> {
    let field = || "cases".to_string();
    if names.is_empty() {
        return Err((
            field(),
            format!("must list at least one of {}", case_names()),
        ));
    }
    let mut cases = Vec::new();
    for name in names {
        let case = Case::parse(name).map_err(|e| (field(), e.to_string()))?;
        if cases.contains(&case) {
            return Err((field(), format!("'{name}' is listed twice")));
        }
        cases.push(case);
    }
    Ok(cases)
}

/// The ν sweep, ascending; each value must suit every one of `cases`.
fn parse_nu(values: &[f64], cases: &[Case]) -> Result<Vec<f64>, FieldError> {
    if values.is_empty() {
        return Err((
            "nu".into(),
            "must list at least one value (allowed: finite, > 1)".into(),
        ));
    }
    for (i, &nu) in values.iter().enumerate() {
        check_nu(nu, cases).map_err(|message| (format!("nu[{i}]"), message))?;
    }
    let mut nu = values.to_vec();
    nu.sort_by(f64::total_cmp);
    if nu.windows(2).any(|w| w[0] == w[1]) {
        return Err(("nu".into(), "lists a value twice".into()));
    }
    Ok(nu)
}

/// Why one ν is unusable with `cases`, if it is.
fn check_nu(nu: f64, cases: &[Case]) -> Result<(), String> {
    if !(nu.is_finite() && nu > 1.0) {
        let why = if cases.contains(&Case::Hole) {
            "case hole needs a hole, so nu = R/r must be > 1"
        } else {
            "nu = R/r must be finite and > 1 (ring tori only)"
        };
        return Err(format!("{} is invalid: {why}", crate::number::Num(nu)));
    }
    if nu > MAX_NU {
        return Err(format!(
            "{} is invalid (allowed: 1 < nu <= {MAX_NU}, the largest nu the \
             intersection and the culls are tested at)",
            crate::number::Num(nu)
        ));
    }
    if let Some(case) = cases.iter().find(|c| nu < c.min_nu()) {
        return Err(format!(
            "{nu} is too close to 1 for case {case}: its generator could not find \
             enough rays (allowed with case {case}: nu >= {})",
            case.min_nu()
        ));
    }
    Ok(())
}

fn check_rays(rays: i64) -> Result<usize, FieldError> {
    if !(1..=MAX_RAYS).contains(&rays) {
        return Err((
            "rays".into(),
            format!("{rays} is invalid (allowed: 1 ..= {MAX_RAYS})"),
        ));
    }
    Ok(rays as usize)
}

fn parse_seed(seed: &serde_json::Number) -> Result<u64, FieldError> {
    seed.as_u64().ok_or_else(|| {
        (
            "seed".into(),
            format!("{seed} is invalid (allowed: an integer 0 ..= {})", u64::MAX),
        )
    })
}

fn parse_pose(pose: Option<&str>) -> Result<Pose, FieldError> {
    match pose {
        None | Some("random") => Ok(Pose::Random),
        Some("canonical") => Ok(Pose::Canonical),
        Some(other) => Err((
            "pose".into(),
            format!("'{other}' is invalid (allowed: random, canonical)"),
        )),
    }
}

fn parse_bvh(value: serde_json::Value) -> Result<BvhSpec, FieldError> {
    let raw: RawBvh = serde_json::from_value(value).map_err(|e| {
        (
            "bvh".to_string(),
            format!(
                "{e} (expected scenes, nu, tori, image, random_rays, optional brute_force_stride)"
            ),
        )
    })?;
    let field = |name: &str| format!("bvh.{name}");
    if raw.scenes.is_empty() {
        return Err((field("scenes"), "must list at least one scene".into()));
    }
    let mut scenes = Vec::new();
    for name in &raw.scenes {
        scenes.push(SceneKind::parse(name).map_err(|e| (field("scenes"), e.to_string()))?);
    }
    if raw.nu.is_empty() {
        return Err((
            field("nu"),
            "must list at least one value (allowed: finite, > 1)".into(),
        ));
    }
    for (i, &nu) in raw.nu.iter().enumerate() {
        if !(nu.is_finite() && nu > 1.0 && nu <= MAX_NU) {
            return Err((
                format!("bvh.nu[{i}]"),
                format!(
                    "{} is invalid (allowed: 1 < nu <= {MAX_NU})",
                    crate::number::Num(nu)
                ),
            ));
        }
    }
    let ranged = |name: &str, v: i64, lo: i64, hi: i64| {
        if (lo..=hi).contains(&v) {
            Ok(v as usize)
        } else {
            Err((
                field(name),
                format!("{v} is invalid (allowed: {lo} ..= {hi})"),
            ))
        }
    };
    Ok(BvhSpec {
        scenes,
        nu: raw.nu,
        tori: ranged("tori", raw.tori, 1, 1_000_000)?,
        image: ranged("image", raw.image, 1, 8192)?,
        random_rays: ranged("random_rays", raw.random_rays, 0, MAX_RAYS)?,
        brute_force_stride: ranged(
            "brute_force_stride",
            raw.brute_force_stride.unwrap_or(16),
            1,
            1 << 30,
        )?,
    })
}

fn case_names() -> String {
    Case::allowed().join(", ")
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

    /// Each built-in workload is valid, is named as it is asked for, and is the file's
    /// workload, hash included.
    #[test]
    fn built_in_workloads_are_the_files() {
        for (name, _) in BUILT_IN {
            let embedded = Workload::open(Path::new(name)).unwrap();
            assert_eq!(embedded.name, name);
            let file = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("workloads")
                .join(format!("{name}.json"));
            assert_eq!(embedded, Workload::load(&file).unwrap());
        }
        assert!(built_in(Path::new("./quick")).is_none());
        assert!(built_in(Path::new("quick.json")).is_none());
    }

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
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[1.0000001],"rays":10}"#,
                "field `nu[0]`: 1.0000001 is too close to 1 for case hole",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["uniform"],"nu":[1001],"rays":10}"#,
                "field `nu[0]`: 1001 is invalid (allowed: 1 < nu <= 1000",
            ),
            (
                r#"{"name":"../../evil","seed":7,"cases":["uniform"],"nu":[2],"rays":10}"#,
                "field `name`: '../../evil' is invalid",
            ),
            (
                r#"{"name":"a/b","seed":7,"cases":["uniform"],"nu":[2],"rays":10}"#,
                "field `name`: 'a/b' is invalid",
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
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":1,"bvh":{"scenes":["torus_soup"],"nu":[2],"tori":10,"image":8,"random_rays":0}}"#,
                "field `bvh.scenes`: unknown scene 'torus_soup'",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":1,"bvh":{"scenes":["chain"],"nu":[2],"tori":0,"image":8,"random_rays":0}}"#,
                "field `bvh.tori`: 0 is invalid (allowed: 1 ..= 1000000)",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":1,"bvh":{"scenes":["chain"],"nu":[0.9],"tori":5,"image":8,"random_rays":0}}"#,
                "field `bvh.nu[0]`: 0.9 is invalid",
            ),
            (
                r#"{"name":"t","seed":7,"cases":["hole"],"nu":[2],"rays":1,"bvh":{"scenes":["chain"],"nu":[2],"tori":5,"image":8,"random_rays":0,"lights":3}}"#,
                "field `bvh`: unknown field `lights`",
            ),
        ] {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.contains(needle), "{text}\n  gave: {e}");
            assert!(e.starts_with("workload w.json"), "{e}");
        }
    }
}
