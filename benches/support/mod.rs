//! Shared bench plumbing: size presets, reading criterion's estimates, the solver duel.
#![allow(dead_code, reason = "shared by the bench targets, each using a part")]

pub mod batch;
pub mod bvh;
pub mod counts;
pub mod ratios;
pub mod solver;

use std::path::Path;
use std::time::{Duration, SystemTime};
use torus_cull_lab::workload::spec::Workload;

/// How big a `cargo bench` run is (`TORUS_CULL_BENCH`).
pub struct BenchConfig {
    /// Preset name.
    pub name: &'static str,
    /// Timed ν values.
    pub nus: Vec<f64>,
    /// Rays per timed batch.
    pub batch: usize,
    /// Criterion warm-up per benchmark.
    pub warm_up: Duration,
    /// Criterion measurement per benchmark.
    pub measurement: Duration,
    /// Criterion samples per benchmark.
    pub samples: usize,
    /// Cap on rays per (case, ν) in the rejection sweep (`None`: the workload's count).
    pub sweep_rays: Option<usize>,
    /// Whether to run the workload's BVH scenes.
    pub bvh: bool,
    /// `smoke` shrinks the BVH scenes to seconds.
    pub small_bvh: bool,
    /// Whether `TORUS_CULL_BENCH_NU` chose the timed ν.
    pub nu_override: bool,
    /// Seconds for the paired ratios, over all (case, timed ν) together.
    pub ratio_seconds: f64,
    /// Independent runs sharing those seconds, each in a fresh layout of the ray buffers
    /// (see `torus_cull_lab::paired::runs`): the ratios get a between-run interval.
    pub ratio_runs: u64,
    /// Seconds for the paired BVH ratios (every scene and the family's), and their runs:
    /// as `time bvh` gives them, about 10 s a unit over 10 runs, so that its intervals
    /// meet issue 40's goals in the file the README quotes. The default preset's 160 s
    /// (120 s before issue 53's bounce rays added a fourth pass per cull to each round)
    /// keeps each pass's share of the rounds.
    pub bvh_seconds: f64,
    /// Runs sharing [`BenchConfig::bvh_seconds`].
    pub bvh_runs: usize,
}

/// The default timed ν subset: the full sweep stays in the (cheap) rejection counts.
pub const DEFAULT_TIMED_NU: [f64; 5] = [1.25, 2.0, 4.0, 8.0, 16.0];

/// The presets `TORUS_CULL_BENCH` accepts.
pub const PRESETS: [&str; 3] = ["smoke", "default", "full"];

impl BenchConfig {
    /// From `TORUS_CULL_BENCH` (smoke | default | full) and `TORUS_CULL_BENCH_NU` (a
    /// comma-separated ν list overriding the preset's; every ν must be one of the
    /// workload's). Errors name the variable and what is allowed.
    pub fn from_env(workload: &Workload) -> Result<BenchConfig, String> {
        let preset = match std::env::var("TORUS_CULL_BENCH") {
            Ok(p) => p,
            Err(std::env::VarError::NotPresent) => "default".into(),
            Err(e) => return Err(format!("TORUS_CULL_BENCH: {e}")),
        };
        let mut config = match preset.as_str() {
            "smoke" => BenchConfig {
                name: "smoke",
                nus: vec![2.0],
                batch: 256,
                warm_up: Duration::from_millis(5),
                measurement: Duration::from_millis(15),
                samples: 10,
                sweep_rays: Some(1_000),
                bvh: true,
                small_bvh: true,
                nu_override: false,
                ratio_seconds: 1.0,
                ratio_runs: 2,
                bvh_seconds: 1.0,
                bvh_runs: 2,
            },
            "default" => BenchConfig {
                name: "default",
                nus: DEFAULT_TIMED_NU.to_vec(),
                batch: 4096,
                warm_up: Duration::from_millis(200),
                measurement: Duration::from_millis(500),
                samples: 20,
                sweep_rays: None,
                bvh: true,
                small_bvh: false,
                nu_override: false,
                ratio_seconds: 60.0,
                ratio_runs: 3,
                bvh_seconds: 160.0,
                bvh_runs: 10,
            },
            "full" => BenchConfig {
                name: "full",
                nus: Vec::new(), // every ν of the workload
                batch: 4096,
                warm_up: Duration::from_secs(1),
                measurement: Duration::from_secs(3),
                samples: 50,
                sweep_rays: None,
                bvh: true,
                small_bvh: false,
                nu_override: false,
                ratio_seconds: 120.0,
                ratio_runs: 3,
                bvh_seconds: 320.0,
                bvh_runs: 10,
            },
            other => {
                return Err(format!(
                    "TORUS_CULL_BENCH={other:?} is invalid (allowed: {})",
                    PRESETS.join(", ")
                ));
            }
        };
        match std::env::var("TORUS_CULL_BENCH_NU") {
            Ok(list) => {
                let allowed = || {
                    let nus: Vec<String> = workload.nu.iter().map(|n| n.to_string()).collect();
                    format!(
                        "allowed: a comma-separated list of the workload's nu values, {}",
                        nus.join(", ")
                    )
                };
                let mut nus = Vec::new();
                for s in list.split(',') {
                    match s.trim().parse::<f64>() {
                        Ok(nu) if workload.nu.contains(&nu) => nus.push(nu),
                        _ => {
                            return Err(format!(
                                "TORUS_CULL_BENCH_NU={list:?}: {:?} is not a nu of workload {} ({})",
                                s.trim(),
                                workload.name,
                                allowed()
                            ));
                        }
                    }
                }
                config.nus = nus;
                config.nu_override = true;
            }
            Err(std::env::VarError::NotPresent) => {}
            Err(e) => return Err(format!("TORUS_CULL_BENCH_NU: {e}")),
        }
        Ok(config)
    }

    /// The file-name suffix that tells this configuration's results apart: empty for the
    /// default preset on the default workload (the file that gets committed).
    pub fn file_suffix(&self, workload: &Workload) -> String {
        let mut suffix = String::new();
        if workload.name != "default" {
            suffix += &format!("-{}", workload.name);
        }
        if self.name != "default" {
            suffix += &format!("-{}", self.name);
        }
        if self.nu_override {
            let nus: Vec<String> = self.nus.iter().map(|n| n.to_string()).collect();
            suffix += &format!("-nu{}", nus.join("_"));
        }
        suffix
    }

    /// The timed ν values for `workload`: the preset's that the workload has, or all of its.
    pub fn timed_nus(&self, workload: &Workload) -> Vec<f64> {
        let picked: Vec<f64> = self
            .nus
            .iter()
            .copied()
            .filter(|nu| workload.nu.contains(nu))
            .collect();
        if picked.is_empty() {
            workload.nu.clone()
        } else {
            picked
        }
    }

    /// The BVH spec to bench: the workload's, or a seconds-sized one for `smoke`.
    pub fn bvh_spec(
        &self,
        spec: &torus_cull_lab::workload::spec::BvhSpec,
    ) -> torus_cull_lab::workload::spec::BvhSpec {
        let mut s = spec.clone();
        if self.small_bvh {
            s.nu.truncate(1);
            s.tori = s.tori.min(64);
            s.image = s.image.min(32);
            s.random_rays = s.random_rays.min(512);
        }
        s
    }

    /// The workload the rejection sweep runs: the full one, or capped for `smoke`.
    pub fn sweep_workload(&self, workload: &Workload) -> Workload {
        let mut w = workload.clone();
        if let Some(cap) = self.sweep_rays {
            w.rays = w.rays.min(cap);
        }
        w
    }
}

/// A criterion median with its confidence interval.
#[derive(Debug, Clone, Copy)]
pub struct Estimate {
    pub median: f64,
    pub lower: f64,
    pub upper: f64,
}

impl Estimate {
    pub fn scaled(self, k: f64) -> Estimate {
        Estimate {
            median: self.median * k,
            lower: self.lower * k,
            upper: self.upper * k,
        }
    }
}

/// The median estimate (ns per iteration) criterion wrote for `group/function/nu` during
/// this run (`since`), or `None` if that benchmark did not run.
pub fn read_estimate(
    home: &Path,
    group: &str,
    function: &str,
    parameter: impl std::fmt::Display,
    since: SystemTime,
) -> Option<Estimate> {
    let path = home
        .join(group)
        .join(function)
        .join(parameter.to_string())
        .join("new/estimates.json");
    let fresh = std::fs::metadata(&path).ok()?.modified().ok()? >= since;
    if !fresh {
        return None;
    }
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).ok()?).ok()?;
    let median = &v["median"];
    Some(Estimate {
        median: median["point_estimate"].as_f64()?,
        lower: median["confidence_interval"]["lower_bound"].as_f64()?,
        upper: median["confidence_interval"]["upper_bound"].as_f64()?,
    })
}

/// What criterion will do with this invocation, from the arguments cargo passes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// `--list`: print the benchmark names, measure nothing.
    List,
    /// `cargo test --benches` or `--test`: run each benchmark once, untimed.
    Test,
    /// `--profile-time`: run under a profiler, no estimates.
    Profile,
    /// `cargo bench`: measure.
    Benchmark,
}

impl Mode {
    /// Criterion's own rule: `--list` wins, then `--test` or no `--bench` (cargo adds
    /// `--bench` only for `cargo bench`) means test mode, then `--profile-time`.
    pub fn from_args(args: &[String]) -> Mode {
        let has = |flag: &str| {
            args.iter()
                .any(|a| a == flag || a.strip_prefix(flag).is_some_and(|r| r.starts_with('=')))
        };
        if has("--list") {
            Mode::List
        } else if has("--test") || !has("--bench") {
            Mode::Test
        } else if has("--profile-time") {
            Mode::Profile
        } else {
            Mode::Benchmark
        }
    }
}
