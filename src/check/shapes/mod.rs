//! The shapes `torus-cull check` knows, one folder each: what is a shape's own (its
//! classes, ray kinds, oracle label, culls and intersectors) behind
//! [`super::CheckShape`]. This file is the one list of them and of the options each
//! takes; the generic check and the command name none.

pub mod bend;
pub mod family;
pub mod ring;

use super::CheckShape;
use std::path::PathBuf;

/// The shapes, as `--shape` names them, and the precisions each is checked at.
pub const SHAPES: [(&str, &str); 3] = [("family", "f64"), ("bend", "f64"), ("ring", "f32")];

/// The check files before `check`, one kind per shape: (`meta.tool`, the section that
/// told a file without it apart, `check`'s flags for the same counts).
pub const OLD_KINDS: [(&str, &str, &str); 3] = [
    ("f32-check", "families", "--shape ring --precision f32"),
    ("family", "members", "--shape family"),
    ("bend", "classes", "--shape bend"),
];

/// What a shape's own part of the check is asked: each option belongs to some shapes
/// only, and a shape refuses the ones it does not take (never ignores them).
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// `--shape`.
    pub shape: String,
    /// `--precision` (`None`: the shape's own).
    pub precision: Option<String>,
    /// `--nu` (bend).
    pub nu: Vec<f64>,
    /// `--delta-phi` (bend).
    pub delta_phi: Vec<f64>,
    /// `--bore-ratio` (bend).
    pub bore_ratio: Vec<f64>,
    /// `--workload` (bend): its classes, rays and seed.
    pub workload: Option<PathBuf>,
    /// `--rounds` (ring, f32): timing rounds per class.
    pub rounds: Option<u32>,
}

/// A shape built from its options.
pub struct Built {
    /// The shape.
    pub shape: Box<dyn CheckShape>,
    /// Rays per class and the seed, where the options fixed them (a workload file).
    pub rays_seed: Option<(usize, u64)>,
    /// The seed `--seed` defaults to for this shape.
    pub default_seed: u64,
    /// The most rays per class.
    pub max_rays: usize,
}

/// Refuses the options `o` gives that `shape` does not take, naming the option and the
/// shapes that take it.
fn refuse_others(o: &Options, shape: &str, takes: &[&str]) -> Result<(), String> {
    let given = [
        ("--nu", !o.nu.is_empty(), "bend"),
        ("--delta-phi", !o.delta_phi.is_empty(), "bend"),
        ("--bore-ratio", !o.bore_ratio.is_empty(), "bend"),
        ("--workload", o.workload.is_some(), "bend"),
        ("--rounds", o.rounds.is_some(), "ring (--precision f32)"),
    ];
    match given
        .iter()
        .find(|(flag, on, _)| *on && !takes.contains(flag))
    {
        Some((flag, _, whose)) => Err(format!(
            "{flag} is not an option of --shape {shape} (it is one of --shape {whose})"
        )),
        None => Ok(()),
    }
}

/// The shape `o.shape` at `o.precision`.
///
/// # Errors
///
/// An unknown shape, a precision the shape is not checked at, an option it does not
/// take, or one out of its range: each named with what is allowed.
pub fn build(o: &Options) -> Result<Built, String> {
    let Some(&(name, precision)) = SHAPES.iter().find(|(s, _)| *s == o.shape) else {
        let names: Vec<&str> = SHAPES.iter().map(|s| s.0).collect();
        return Err(format!(
            "--shape {} is unknown (allowed: {})",
            o.shape,
            names.join(", ")
        ));
    };
    if let Some(p) = o.precision.as_deref().filter(|p| *p != precision) {
        let at: Vec<String> = SHAPES.iter().map(|(s, p)| format!("{s} at {p}")).collect();
        return Err(format!(
            "--precision {p} is not checked for --shape {name} (allowed: {}; the ring \
             torus's culls and f64 intersection are checked in --shape family's ring \
             members)",
            at.join(", ")
        ));
    }
    let built = |shape: Box<dyn CheckShape>, rays_seed, default_seed, max_rays| Built {
        shape,
        rays_seed,
        default_seed,
        max_rays,
    };
    match name {
        "family" => {
            refuse_others(o, name, &[])?;
            Ok(built(
                Box::new(family::FamilyShape),
                None,
                family::SEED,
                1_000_000,
            ))
        }
        "bend" => {
            refuse_others(
                o,
                name,
                &["--nu", "--delta-phi", "--bore-ratio", "--workload"],
            )?;
            let (shape, rays_seed) = bend::build(o)?;
            Ok(built(Box::new(shape), rays_seed, bend::SEED, 10_000_000))
        }
        _ => {
            refuse_others(o, name, &["--rounds"])?;
            let shape = ring::RingF32 {
                families: ring::families::all(),
                rounds: o.rounds.unwrap_or(5),
            };
            Ok(built(Box::new(shape), None, ring::SEED, 1_000_000))
        }
    }
}
