//! What the command's tests share: the binary, the repository root, and running it there.

use std::process::{Command, Output};

/// The `torus-cull` binary cargo built for these tests.
pub const BIN: &str = env!("CARGO_BIN_EXE_torus-cull");
/// The repository root, where every test runs the binary.
pub const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Runs `torus-cull args…` in the repository root and waits for it.
pub fn torus_cull(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .current_dir(ROOT)
        .output()
        .expect("run torus-cull")
}

/// The run's standard error, as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The run's standard output, as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}
