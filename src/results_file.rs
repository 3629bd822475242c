//! Any file the tool writes for `plot` and `compare` to read: a results file (`run`,
//! `time`, `cargo bench`) or a check file (`check`, every shape and precision), told apart
//! by `meta.tool` (`check`). The check kinds before it, one per shape
//! ([`crate::check::shapes::OLD_KINDS`]), are refused with the command that writes their
//! counts now.

use crate::check::record::{CheckFile, TOOL};
use crate::results::{Results, ResultsError, read_json};
use std::path::Path;

/// One file as read.
#[derive(Debug, Clone, PartialEq)]
pub enum ResultsFile {
    /// `run`, `time` or `cargo bench`.
    Results(Results),
    /// `check`.
    Check(CheckFile),
}

impl ResultsFile {
    /// Reads `path`, refusing other schema versions, the old check kinds and files of
    /// neither kind (the error names the file and the field).
    pub fn load(path: &Path) -> Result<ResultsFile, ResultsError> {
        let value = read_json(path)?;
        let parse = |e: String| ResultsError::Parse(path.into(), e);
        let tool = value.pointer("/meta/tool").and_then(|t| t.as_str());
        if tool == Some(TOOL) {
            return serde_json::from_value(value)
                .map(ResultsFile::Check)
                .map_err(|e| parse(e.to_string()));
        }
        let old = crate::check::shapes::OLD_KINDS
            .iter()
            .find(|(t, section, _)| tool == Some(*t) || value.get(section).is_some());
        if let Some((old, _, flags)) = old {
            return Err(parse(format!(
                "a `{old}` check file (meta.tool `{old}`), a kind no longer read: check files \
                 are now one kind, meta.tool `{TOOL}`; write one with `torus-cull check \
                 {flags}` (the same rays and counts for the same flags and seed)"
            )));
        }
        serde_json::from_value(value)
            .map(ResultsFile::Results)
            .map_err(|e| parse(e.to_string()))
    }

    /// What made the file, for messages: `meta.tool`, or `results` when unrecorded.
    pub fn tool(&self) -> &str {
        let meta = match self {
            ResultsFile::Results(r) => &r.meta,
            ResultsFile::Check(c) => &c.meta,
        };
        meta.tool.as_deref().unwrap_or("results")
    }
}
