//! Any file the tool writes for `plot` and `compare` to read: a results file (`run`,
//! `time`, `cargo bench`), an f32-check file, a family-check file or a bend-check file,
//! told apart by `meta.tool` (`f32-check`, `family`, `bend`) or, in files without it, by
//! their own sections (`families`, `members`, `classes`).

use crate::bend_check::BendFile;
use crate::f32_check::CheckFile;
use crate::family_check::FamilyFile;
use crate::results::{Results, ResultsError, read_json};
use std::path::Path;

/// One file as read.
#[derive(Debug, Clone, PartialEq)]
pub enum ResultsFile {
    /// `run`, `time` or `cargo bench`.
    Results(Results),
    /// `f32-check`.
    F32Check(CheckFile),
    /// `family`.
    Family(Box<FamilyFile>),
    /// `bend`.
    Bend(Box<BendFile>),
}

impl ResultsFile {
    /// Reads `path`, refusing other schema versions and files of neither kind (the error
    /// names the file and the field).
    pub fn load(path: &Path) -> Result<ResultsFile, ResultsError> {
        let value = read_json(path)?;
        let parse = |e: serde_json::Error| ResultsError::Parse(path.into(), e.to_string());
        let tool = value.pointer("/meta/tool").and_then(|t| t.as_str());
        if tool == Some("f32-check") || value.get("families").is_some() {
            serde_json::from_value(value)
                .map(ResultsFile::F32Check)
                .map_err(parse)
        } else if tool == Some("family") || value.get("members").is_some() {
            serde_json::from_value(value)
                .map(|f| ResultsFile::Family(Box::new(f)))
                .map_err(parse)
        } else if tool == Some("bend") || value.get("classes").is_some() {
            serde_json::from_value(value)
                .map(|f| ResultsFile::Bend(Box::new(f)))
                .map_err(parse)
        } else {
            serde_json::from_value(value)
                .map(ResultsFile::Results)
                .map_err(parse)
        }
    }

    /// What made the file, for messages: `meta.tool`, or `results` when unrecorded.
    pub fn tool(&self) -> &str {
        let meta = match self {
            ResultsFile::Results(r) => &r.meta,
            ResultsFile::F32Check(c) => &c.meta,
            ResultsFile::Family(f) => &f.meta,
            ResultsFile::Bend(b) => &b.meta,
        };
        meta.tool.as_deref().unwrap_or("results")
    }
}
