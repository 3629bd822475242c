//! `--threads` of `run` and `f32-check`.

use crate::whole::Whole;

/// The most worker threads accepted: far beyond any core count the tool is run on, and
/// small enough that spawning them cannot exhaust the process's thread limit.
pub const MAX_THREADS: usize = 1024;

/// `--threads`: `1 ..= MAX_THREADS`, or the available cores when left out. Zero is
/// refused rather than read as "one" or "all": the user asked for something the tool
/// cannot do, and the message says what it can.
pub fn pick(asked: Option<Whole>) -> Result<usize, String> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    match asked {
        None => Ok(cores),
        Some(n) => n.within(
            "--threads",
            (1, MAX_THREADS),
            &format!("; leave it out for the available cores, {cores} here"),
        ),
    }
}
