//! The paired ratios a complete bench takes beyond the ring torus's: the torus family's,
//! the pipe bends' and the BVH's, as `time family`, `time bend` and `time bvh` take them.

use super::BenchConfig;
use torus_cull::CullKind;
use torus_cull::batch::Dispatch;
use torus_cull_lab::paired;
use torus_cull_lab::paired::shapes::shape_records;
use torus_cull_lab::results::RatioRecord;

/// The torus family's and the pipe bends' paired ratios, as `time family` and `time
/// bend` take them (metrics `family_total_ns`, `bend_total_ns`), each in a quarter of
/// the ring torus's paired time, over the same runs.
pub fn shapes(config: &BenchConfig, seed: u64) -> Vec<RatioRecord> {
    let runs = config.ratio_runs.max(1) as usize;
    let rays = config.batch.min(paired::sweep::DEFAULT_BATCH);
    let quarter = config.ratio_seconds / 4.0 / runs as f64;
    let both = || -> Result<Vec<RatioRecord>, String> {
        let (members, bends) = (paired::family::members()?, paired::bend::bends()?);
        let share = |n: usize| (runs, quarter / n as f64);
        let mut records = shape_records(&members, seed, rays, share(members.len()), |_, _| {})?;
        records.extend(shape_records(
            &bends,
            seed,
            rays,
            share(bends.len()),
            |_, _| {},
        )?);
        Ok(records)
    };
    both().unwrap_or_else(|e| panic!("{e}"))
}

/// The paired BVH ratios `time bvh` takes (metrics `bvh_closest_ns`, `bvh_anyhit_ns`,
/// `bvh_bounce_ns`, `bvh_batched_ns`) on the same units: the bench's scenes at each of its ν, the scenes it
/// lacks and the torus family's at ν = 4, in [`BenchConfig::bvh_seconds`] over
/// [`BenchConfig::bvh_runs`] runs (the README's BVH line quotes a bench).
pub fn bvh(
    spec: &torus_cull_lab::workload::spec::BvhSpec,
    config: &BenchConfig,
    seed: u64,
    dispatch: &Dispatch,
) -> Vec<RatioRecord> {
    let timing = paired::bvh::BvhTiming {
        units: paired::bvh::units_of(&spec.scenes, &spec.nu),
        tori: spec.tori,
        seed,
        culls: CullKind::TIMED.to_vec(),
        rays: config.batch.min(1024),
        seconds: config.bvh_seconds,
        runs: config.bvh_runs,
        dispatch: *dispatch,
        family: Some(paired::bvh::NEW_SCENE_NU),
    };
    paired::bvh::time_bvh(&timing, &mut |_, _| {}).unwrap_or_else(|e| panic!("{e:?}"))
}
