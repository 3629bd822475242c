//! A workload file's `bend` key: the pipe bends `torus-cull bend --workload FILE` checks.
//!
//! ```json
//! "bend": { "nu": [4], "delta_phi": [6.283185307179586, 3.14159, 1.5708, 0.5236],
//!           "bore_ratio": [0, 0.5, 0.9], "rays": 100000 }
//! ```
//!
//! Each (ν, Δφ, r_min/r_max) is a class of `rays` rays (ν = R/r_max, Δφ the segment in
//! radians, r_min/r_max the bore's share of the tube), posed and scaled as the command
//! does; the workload's `seed` seeds them.

use super::field_list::{FieldError, Repeats, check_list};
use serde::Deserialize;
use std::f64::consts::TAU;
use torus_cull::MAX_NU;

/// The pipe bends of a workload's `bend` key.
#[derive(Debug, Clone, PartialEq)]
pub struct BendSpec {
    /// ν = R/r_max of the classes.
    pub nu: Vec<f64>,
    /// The segments Δφ, radians.
    pub delta_phi: Vec<f64>,
    /// r_min/r_max of the classes.
    pub bore_ratio: Vec<f64>,
    /// Rays per class.
    pub rays: usize,
}

/// The most rays per class.
pub const MAX_BEND_RAYS: i64 = 10_000_000;

/// Whether `delta_phi` is a segment a bend takes: 0 < Δφ ≤ 2π (`PipeBend`'s own range).
pub fn delta_phi_ok(delta_phi: f64) -> bool {
    delta_phi > 0.0 && delta_phi <= TAU
}

/// Whether `ratio` is an r_min/r_max a bend takes: 0 ≤ ratio < 1 (the bore inside the tube).
pub fn bore_ratio_ok(ratio: f64) -> bool {
    (0.0..1.0).contains(&ratio)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBend {
    nu: Vec<f64>,
    delta_phi: Vec<f64>,
    bore_ratio: Vec<f64>,
    rays: i64,
}

/// The `bend` key's value, checked field by field (nu, delta_phi, bore_ratio, rays).
pub(super) fn parse_bend(value: serde_json::Value) -> Result<BendSpec, FieldError> {
    let raw: RawBend = serde_json::from_value(value).map_err(|e| {
        (
            "bend".to_string(),
            format!("{e} (expected nu, delta_phi, bore_ratio, rays)"),
        )
    })?;
    check_list(
        "bend.nu",
        &raw.nu,
        |nu| nu.is_finite() && nu > 1.0 && nu <= MAX_NU,
        &format!("1 < nu <= {MAX_NU}"),
        Repeats::Allowed,
    )?;
    check_list(
        "bend.delta_phi",
        &raw.delta_phi,
        delta_phi_ok,
        "0 < delta_phi <= 2*pi = 6.283185307179586",
        Repeats::Allowed,
    )?;
    check_list(
        "bend.bore_ratio",
        &raw.bore_ratio,
        bore_ratio_ok,
        "0 <= bore_ratio < 1",
        Repeats::Allowed,
    )?;
    if !(1..=MAX_BEND_RAYS).contains(&raw.rays) {
        return Err((
            "bend.rays".into(),
            format!("{} is invalid (allowed: 1 ..= {MAX_BEND_RAYS})", raw.rays),
        ));
    }
    Ok(BendSpec {
        nu: raw.nu,
        delta_phi: raw.delta_phi,
        bore_ratio: raw.bore_ratio,
        rays: raw.rays as usize,
    })
}
