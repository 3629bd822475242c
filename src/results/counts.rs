//! The count channel's records (`torus-cull count`, [`crate::count`]): instructions per ray
//! under callgrind, beside the wall-clock ratios. In the results file they are the `counts`
//! array, and `meta.counts` says how they were counted (valgrind's version, the
//! instruction set the dispatch chose under it, the rays per region). A file without them
//! (every file from before they existed) reads as having none.
//!
//! A count is the number of guest instructions callgrind executed inside one region (one
//! pass of one path over one fixed, seeded ray set), divided by the region's rays. For the
//! same binary and the same rays it is the same number whatever else the machine does,
//! which is why `compare` can judge it at a threshold of 0.1 % where a wall ratio needs
//! its intervals (docs/counts.md).

use serde::{Deserialize, Serialize};

/// How a file's counts were made: two files whose counts differ here count different
/// code (another instruction set) or are not comparable record by record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CountMeta {
    /// `valgrind --version`, e.g. `valgrind-3.19.0`.
    pub valgrind: String,
    /// The instruction set the runtime dispatch ([`torus_cull::batch::Dispatch`]) chose
    /// under valgrind, which has no AVX-512: `avx2` on an x86-64 with AVX2 (the batch
    /// records ran at it; the scalar records ran the baseline code either way).
    pub isa: String,
    /// Rays per (case, ν) region (the first rays of the workload's stream).
    pub rays: u64,
    /// The instructions of an empty region (the call into it and out), subtracted from
    /// every record's total.
    pub overhead: u64,
}

/// One region's count.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CountRecord {
    /// What the region runs: `ring` (one torus of the workload: a cull alone, or a cull
    /// and the exact intersection, ray by ray or as a wavefront), `solver` (the quartic
    /// solver on one line family's quartics), `bvh` (a traversal of one scene).
    pub group: String,
    /// The workload case, the solver's line family, or the BVH scene.
    pub case: String,
    /// ν = R/r of the torus (of the scene's tori; 0 for the solver families, which mix ν).
    pub nu: f64,
    /// The cull (`none` for no cull; the solver's name in the `solver` group).
    pub cull: String,
    /// What the region runs: `total` (cull + exact intersection when kept, one ray at a
    /// time: [`torus_cull::intersect_culled`]), `cull` (the cull alone on torus-frame
    /// lines), `batch_total`, `batch_cull`, `batch_f32_total` (the wavefront at the
    /// dispatch level: f64, the SIMD cull alone, the certified f32 path), `solve` (one
    /// quartic), `bvh_closest` and `bvh_anyhit` (a BVH traversal: closest hit per camera
    /// ray, any hit per shadow ray). The wall channel's metric is
    /// this name with `_ns` appended.
    pub metric: String,
    /// Rays (quartics) the region ran.
    pub rays: u64,
    /// Instructions the region executed, less [`CountMeta::overhead`].
    pub instructions: u64,
    /// `instructions / rays`.
    pub per_ray: f64,
    /// The record this one is divided by: `cychosz` under the same metric and unit
    /// (`none` in the `bvh` group); absent for the reference itself and where there is
    /// none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<String>,
    /// `per_ray / reference's per_ray`: the count's counterpart of the paired wall ratio.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio: Option<f64>,
}

impl CountRecord {
    /// `group case ν cull metric`: what `compare` pairs on.
    pub fn key(&self) -> String {
        format!(
            "{} {} {} {} {}",
            self.group, self.case, self.nu, self.cull, self.metric
        )
    }
}

/// Fills every record's [`CountRecord::reference`] and [`CountRecord::ratio`]: `cychosz`'s
/// record of the same group, case, ν and metric (`none`'s in the `bvh` group), where it is
/// present and is not the record itself.
pub fn fill_ratios(records: &mut [CountRecord]) {
    let lookup: std::collections::BTreeMap<String, f64> =
        records.iter().map(|r| (r.key(), r.per_ray)).collect();
    for r in records.iter_mut() {
        let reference = if r.group == "bvh" { "none" } else { "cychosz" };
        if r.cull == reference || r.group == "solver" {
            continue;
        }
        let key = CountRecord {
            cull: reference.into(),
            ..r.clone()
        }
        .key();
        if let Some(&per_ray) = lookup.get(&key)
            && per_ray > 0.0
        {
            r.reference = Some(reference.into());
            r.ratio = Some(r.per_ray / per_ray);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rec(cull: &str, per_ray: f64) -> CountRecord {
        CountRecord {
            group: "ring".into(),
            case: "hole".into(),
            nu: 2.0,
            cull: cull.into(),
            metric: "total".into(),
            rays: 4,
            instructions: (per_ray * 4.0) as u64,
            per_ray,
            reference: None,
            ratio: None,
        }
    }

    /// Each cull over `cychosz` of the same key; the reference itself has no ratio.
    #[test]
    fn ratios_are_over_the_reference() {
        let mut r = vec![rec("cychosz", 200.0), rec("skala", 100.0)];
        fill_ratios(&mut r);
        assert_eq!(r[0].ratio, None);
        assert_eq!(r[1].ratio, Some(0.5));
        assert_eq!(r[1].reference.as_deref(), Some("cychosz"));
        let text = serde_json::to_string(&r[0]).unwrap();
        assert!(!text.contains("ratio"), "{text}");
        assert_eq!(serde_json::from_str::<CountRecord>(&text).unwrap(), r[0]);
    }
}
