//! Several independent runs of the same paired ratios, combined: the within-run interval
//! and the between-run interval side by side.
//!
//! One run's bootstrap interval measures round-to-round noise inside one process. It
//! misses whatever moves a whole run: where the code and the data landed in memory
//! (cache sets, alignment, physical pages), the machine's frequency and load while it
//! ran. Two back-to-back runs of the quick workload moved some ratios by 2–5 % with
//! disjoint intervals (issue 29). The remedy is to measure that effect: K runs, each in a
//! fresh layout (`torus-cull time`: a worker process each; `cargo bench`: fresh buffers in
//! one process, see [`crate::paired::sweep::PairedOptions::run`]), and an interval over
//! the K run ratios.
//!
//! For one record with run ratios `rₖ` and run intervals `[loₖ, hiₖ]`, on the log scale
//! `yₖ = ln rₖ` (a ratio's noise is multiplicative, and ln makes r and 1/r symmetric):
//!
//! * ratio: the geometric mean, `exp(ȳ)`, `ȳ = Σ yₖ / K`;
//! * within-run interval: `exp(ȳ − √(Σ (yₖ − ln loₖ)²) / K)` to
//!   `exp(ȳ + √(Σ (ln hiₖ − yₖ)²) / K)`: each side's half-width combined as the standard
//!   error of a mean of K independent estimates, so the interval the rounds alone would
//!   give if the runs did not differ (for K = 1, the run's own interval);
//! * between-run interval: `exp(ȳ ± t₀.₉₇₅,df · s / √K)`, `s` the run-to-run standard
//!   deviation of the `yₖ` ([`RunSpread`]): the record's own sample one (df = K − 1) or
//!   the one pooled over every cull and ν of the same comparison on the same case
//!   ([`pooled_spreads`]; df the pool's), whichever gives the wider interval. Widened
//!   where needed to hold the within-run interval: a few runs that happen to agree do
//!   not make a figure surer than its rounds.
//!
//! A record's own spread from 2 to 5 runs is a poor estimate (with K = 3 the t quantile
//! is 4.30, and two runs that agree by chance give a zero spread); the pool over the
//! workload's batches is a good one, and what moves a whole run moves every batch alike.
//!
//! Runs in a slow state of the machine are set aside first ([`SLOW_STATE`]).

use super::contender::Metric;
use crate::results::{RatioRecord, RunSpread};
use std::fmt;
use torus_cull::{CullKind, Named};

/// The two-sided 95 % quantile of Student's t with `df` degrees of freedom, `t₀.₉₇₅,df`:
/// tabulated (to 3 decimals) up to 30, and beyond by the Cornish–Fisher expansion
/// `z + (z³ + z)/(4 df) + (5z⁵ + 16z³ + 3z)/(96 df²)` with `z = 1.959964` (error below
/// 0.001 there). `NaN` for `df = 0`.
pub fn t_975(df: usize) -> f64 {
    const TABLE: [f64; 30] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
        2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
        2.052, 2.048, 2.045, 2.042,
    ];
    match df {
        0 => f64::NAN,
        1..=30 => TABLE[df - 1],
        _ => {
            let z: f64 = 1.959_964;
            let d = df as f64;
            z + (z.powi(3) + z) / (4.0 * d)
                + (5.0 * z.powi(5) + 16.0 * z.powi(3) + 3.0 * z) / (96.0 * d * d)
        }
    }
}

/// The between-run 95 % interval of the geometric mean of `run_ratios` (see the module
/// text): `exp(ȳ ± t₀.₉₇₅,K−1 · s / √K)` on `yₖ = ln rₖ`. `None` for fewer than two runs
/// or a ratio that is not a positive finite number.
pub fn between_run_interval(run_ratios: &[f64]) -> Option<[f64; 2]> {
    let s = own_spread(run_ratios)?;
    let k = run_ratios.len() as f64;
    Some(around(
        log_mean(run_ratios),
        t_975(k as usize - 1) * s.log_sd / k.sqrt(),
    ))
}

/// Where the geometric mean of `next` further runs should land, 95 %: the prediction
/// interval `exp(ȳ ± t₀.₉₇₅,K−1 · s · √(1/K + 1/next))` on `yₖ = ln rₖ`. The between-run
/// interval is one for the mean itself, and a repeat's mean, itself uncertain, falls
/// inside a 95 % interval of the mean only about 83 % of the time (Cumming & Maillardet,
/// 2006): a promise about the next run needs the `1/next` term. `None` as for
/// [`between_run_interval`], or for `next = 0`.
pub fn next_run_interval(run_ratios: &[f64], next: usize) -> Option<[f64; 2]> {
    let s = own_spread(run_ratios).filter(|_| next > 0)?;
    let k = run_ratios.len() as f64;
    let half = t_975(k as usize - 1) * s.log_sd * (1.0 / k + 1.0 / next as f64).sqrt();
    Some(around(log_mean(run_ratios), half))
}

/// `[exp(y − half), exp(y + half)]`: an interval on the log scale, back in ratios.
fn around(y: f64, half: f64) -> [f64; 2] {
    [(y - half).exp(), (y + half).exp()]
}

/// `interval` widened where needed to hold `within`: a spread between runs never makes a
/// figure surer than its rounds.
fn holding(interval: [f64; 2], within: [f64; 2]) -> [f64; 2] {
    [interval[0].min(within[0]), interval[1].max(within[1])]
}

/// The mean of the logarithms of `ratios`, `ȳ`.
fn log_mean(ratios: &[f64]) -> f64 {
    ratios.iter().map(|r| r.ln()).sum::<f64>() / ratios.len() as f64
}

/// The within-run interval of K runs pooled (see the module text), around the geometric
/// mean of `run_ratios`, from each run's interval `run_cis`; for one run, its own interval.
pub fn pooled_within_interval(run_ratios: &[f64], run_cis: &[[f64; 2]]) -> [f64; 2] {
    let k = run_ratios.len() as f64;
    let mean = log_mean(run_ratios);
    let side = |f: &dyn Fn(f64, [f64; 2]) -> f64| {
        run_ratios
            .iter()
            .zip(run_cis)
            .map(|(&r, &ci)| f(r.ln(), ci).max(0.0).powi(2))
            .sum::<f64>()
            .sqrt()
            / k
    };
    let below = side(&|y, ci| y - ci[0].ln());
    let above = side(&|y, ci| ci[1].ln() - y);
    [(mean - below).exp(), (mean + above).exp()]
}

/// Why runs could not be combined: they do not hold the same records.
#[derive(Debug, Clone, PartialEq)]
pub struct RunsDiffer {
    /// The run (from 1) that differs from the first.
    pub run: usize,
    /// What differs.
    pub what: String,
}

impl fmt::Display for RunsDiffer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "run {} does not hold the same ratio records as run 1: {}",
            self.run, self.what
        )
    }
}

impl std::error::Error for RunsDiffer {}

/// The identity of a record: what must agree across runs.
fn identity(r: &RatioRecord) -> (&str, f64, &str, &str, &str, &str, &str, u64) {
    (
        &r.case,
        r.nu,
        &r.cull,
        &r.reference,
        &r.metric,
        &r.precision,
        &r.device,
        r.rays,
    )
}

/// The median of `values` (not empty).
fn median_of(values: impl Iterator<Item = f64>) -> f64 {
    super::stats::median(&mut values.collect::<Vec<f64>>())
}

/// A run in which a batch's exact intersection, timed alone (the `none` contender's
/// `total_ns`), took more than this fraction longer per ray than in the batch's fastest
/// run ran in a slow state of the machine, and is set aside for that batch.
///
/// On the 2-core VM of docs/results.md the machine switches, for spells of a fraction of
/// a second to seconds, into a state where the quartic costs about 20 ns (some 35 %) more
/// per ray and a cull in front of it less than that: a temporal state, not a placement
/// (the same buffers, timed over and over, switch between the two). It shifts the ratios
/// themselves (`none` over `cychosz` on hole rays: 0.787 fast, about 0.92 slow), so a mean
/// over runs would inherit each run's draw of states. The intersection's own time is the
/// state's clearest sign: rounds inside a run agree to 0.1 %, fast-state runs to about
/// 2 %, so 8 % separates them. The fast-state ratio is what the code does when the
/// machine lets it.
pub const SLOW_STATE: f64 = 0.08;

/// One record per record of the runs, combining the K runs' records in the same place
/// (every run holds the same records, in the same order). Runs in a slow state
/// ([`SLOW_STATE`]) are set aside per batch and counted (`runs_set_aside`). Of the
/// others: the ratio, the within-run interval, and the between-run interval of the
/// module text with the spread [`RunSpread`] of [`pooled_spreads`]; `runs` (those kept),
/// the run ratios, the rounds summed and the ns per ray the median over them. A single
/// run's records come back as they were. Fails, naming the run and the record, when the
/// runs' records differ.
pub fn combine_runs(runs: &[Vec<RatioRecord>]) -> Result<Vec<RatioRecord>, RunsDiffer> {
    let Some(first) = runs.first() else {
        return Ok(Vec::new());
    };
    if runs.len() == 1 {
        return Ok(first.clone());
    }
    for (k, run) in runs.iter().enumerate().skip(1) {
        if run.len() != first.len() {
            return Err(RunsDiffer {
                run: k + 1,
                what: format!("{} records, not {}", run.len(), first.len()),
            });
        }
        if let Some((a, b)) = first
            .iter()
            .zip(run)
            .find(|(a, b)| identity(a) != identity(b))
        {
            return Err(RunsDiffer {
                run: k + 1,
                what: format!("{:?} where run 1 has {:?}", identity(b), identity(a)),
            });
        }
    }
    let kept = fast_state_runs(runs);
    let mut combined: Vec<RatioRecord> = (0..first.len())
        .map(|i| {
            let all: Vec<&RatioRecord> = runs.iter().map(|run| &run[i]).collect();
            let keep = &kept[&unit_of(&first[i])];
            let of_runs: Vec<&RatioRecord> = all
                .iter()
                .zip(keep)
                .filter(|(_, k)| **k)
                .map(|(r, _)| *r)
                .collect();
            let ratios: Vec<f64> = of_runs.iter().map(|r| r.ratio).collect();
            let cis: Vec<[f64; 2]> = of_runs.iter().map(|r| r.ratio_ci).collect();
            RatioRecord {
                ratio: log_mean(&ratios).exp(),
                ratio_ci: pooled_within_interval(&ratios, &cis),
                rounds: of_runs.iter().map(|r| r.rounds).sum(),
                rounds_measured: all.iter().map(|r| r.rounds_measured).sum(),
                ns_per_ray: median_of(of_runs.iter().map(|r| r.ns_per_ray)),
                reference_ns_per_ray: median_of(of_runs.iter().map(|r| r.reference_ns_per_ray)),
                runs: of_runs.len() as u64,
                runs_set_aside: (all.len() - of_runs.len()) as u64,
                run_ratios: ratios,
                ..first[i].clone()
            }
        })
        .collect();
    let pooled = pooled_spreads(&combined);
    for r in &mut combined {
        let own = own_spread(&r.run_ratios);
        let pool = pooled.get(&comparison_of(r)).copied();
        // The wider interval of the two: t₀.₉₇₅ of each one's degrees of freedom times
        // its spread.
        let width = |s: &RunSpread| t_975(s.df as usize) * s.log_sd;
        r.run_spread = match (own, pool) {
            (Some(o), Some(p)) if width(&p) > width(&o) => Some(p),
            (Some(o), _) => Some(o),
            (None, p) => p,
        };
        r.ratio_ci_between = r
            .run_spread
            .map(|s| spread_interval(r, s, 1.0 / r.runs as f64));
        if r.runs < 2 {
            r.run_ratios.clear();
        }
    }
    Ok(combined)
}

/// The spread of one record's run ratios: the sample standard deviation of their
/// logarithms, with runs − 1 degrees of freedom; `None` for fewer than two runs or a
/// ratio that is not a positive finite number.
fn own_spread(run_ratios: &[f64]) -> Option<RunSpread> {
    let k = run_ratios.len();
    if k < 2 || !run_ratios.iter().all(|r| r.is_finite() && *r > 0.0) {
        return None;
    }
    let mean = log_mean(run_ratios);
    let var = run_ratios
        .iter()
        .map(|r| (r.ln() - mean).powi(2))
        .sum::<f64>()
        / (k - 1) as f64;
    Some(RunSpread {
        log_sd: var.sqrt(),
        df: (k - 1) as u64,
        pooled: false,
    })
}

/// The comparison a record makes on one kind of rays, whatever the cull and ν: (metric,
/// reference, precision, device, case). Its run-to-run spread is pooled over those.
///
/// The case is part of it because the spread differs by kind of rays: in the bench of
/// d0e47f6 the f32 / f64 wavefront ratios spread 0.4–1.5 % from run to run on primary
/// rays and 3.2–4.0 % on secondary ones, and one pool over both gave every primary record
/// the secondary rays' spread.
pub type Comparison = (String, String, String, String, String);

fn comparison_of(r: &RatioRecord) -> Comparison {
    (
        r.metric.clone(),
        r.reference.clone(),
        r.precision.clone(),
        r.device.clone(),
        r.case.clone(),
    )
}

/// Per comparison (metric, reference, precision, device, case), the run-to-run spread
/// pooled over every record (each cull and ν) with two runs or more:
/// `s² = Σ Σₖ (yₖ − ȳ)² / Σ (K − 1)` on `yₖ = ln rₖ`, with `Σ (K − 1)` degrees of freedom
/// (`pooled: true`).
///
/// One record's 2 to 5 runs estimate its spread poorly: two runs that happen to agree
/// promise a precision no run gave, and a record with one run kept has none at all. The
/// run-wide effects (the machine's state, placement) move every batch of a comparison
/// alike, so the pool is the better estimate, and a record's interval takes whichever of
/// its own spread and the pooled one gives the wider interval (`t₀.₉₇₅,df · s`): widened by
/// the pool, never narrowed by it.
#[must_use]
pub fn pooled_spreads(
    records: &[RatioRecord],
) -> std::collections::BTreeMap<Comparison, RunSpread> {
    let mut sums: std::collections::BTreeMap<_, (f64, u64)> = std::collections::BTreeMap::new();
    for r in records {
        let Some(own) = own_spread(&r.run_ratios) else {
            continue;
        };
        let sum = sums.entry(comparison_of(r)).or_insert((0.0, 0));
        sum.0 += own.log_sd.powi(2) * own.df as f64;
        sum.1 += own.df;
    }
    sums.into_iter()
        .map(|(c, (ss, df))| {
            (
                c,
                RunSpread {
                    log_sd: (ss / df as f64).sqrt(),
                    df,
                    pooled: true,
                },
            )
        })
        .collect()
}

/// Where the geometric mean of `next` further runs of `record` should land, 95 %:
/// [`next_run_interval`]'s prediction interval with the record's own [`RunSpread`]
/// (`exp(ln r ± t₀.₉₇₅,df · s · √(1/K + 1/next))`), widened to hold the within-run
/// interval; for a record written before the spread was kept, [`next_run_interval`] of
/// its run ratios. `None` where neither is known.
#[must_use]
pub fn next_run_interval_of(record: &RatioRecord, next: usize) -> Option<[f64; 2]> {
    let Some(s) = record.run_spread else {
        return next_run_interval(&record.run_ratios, next);
    };
    if next == 0 || record.runs == 0 || !(record.ratio.is_finite() && record.ratio > 0.0) {
        return None;
    }
    Some(spread_interval(
        record,
        s,
        1.0 / record.runs as f64 + 1.0 / next as f64,
    ))
}

/// `exp(ln r ± t₀.₉₇₅,df · s · √variance_factor)` around `record`'s ratio, with the spread
/// `s`, widened to hold the within-run interval: the between-run interval for
/// `variance_factor = 1/K`, the next-run one for `1/K + 1/next`.
fn spread_interval(record: &RatioRecord, s: RunSpread, variance_factor: f64) -> [f64; 2] {
    let half = t_975(s.df as usize) * s.log_sd * variance_factor.sqrt();
    holding(around(record.ratio.ln(), half), record.ratio_ci)
}

/// The batch a record was timed on: every record of one (case, ν, device, batch) comes
/// from the same rounds of a run, so the state is judged per batch and all its records
/// keep the same runs (an f32 record's reference time stays the f64 record's own).
fn unit_of(r: &RatioRecord) -> (String, u64, String, u64) {
    (r.case.clone(), r.nu.to_bits(), r.device.clone(), r.rays)
}

/// The time per ray of the exact intersection alone (the `none` contender, `total_ns`)
/// in a record that holds it, as the cull or as the reference.
fn intersection_ns(r: &RatioRecord) -> Option<f64> {
    if r.metric != Metric::TotalNs.name() {
        return None;
    }
    let none = CullKind::NoCull.name();
    if r.reference == none {
        Some(r.reference_ns_per_ray)
    } else if r.cull == none {
        Some(r.ns_per_ray)
    } else {
        None
    }
}

/// For each batch ([`unit_of`]), which runs ran in the machine's fast state: those whose
/// time per ray of the exact intersection alone ([`intersection_ns`]) is within
/// [`SLOW_STATE`] of the fastest run's. A batch without that record (no `none`
/// contender, e.g. a GPU or a hand-made file) is judged by the ns per ray summed over its
/// records instead. At least one run is kept; a run without positive finite times is
/// kept (nothing to judge it by).
fn fast_state_runs(
    runs: &[Vec<RatioRecord>],
) -> std::collections::BTreeMap<(String, u64, String, u64), Vec<bool>> {
    let mut cost: std::collections::BTreeMap<_, (Vec<f64>, Vec<Option<f64>>)> =
        std::collections::BTreeMap::new();
    for (k, run) in runs.iter().enumerate() {
        for r in run {
            let (summed, alone) = cost
                .entry(unit_of(r))
                .or_insert_with(|| (vec![0.0; runs.len()], vec![None; runs.len()]));
            summed[k] += r.ns_per_ray + r.reference_ns_per_ray;
            if alone[k].is_none() {
                alone[k] = intersection_ns(r);
            }
        }
    }
    cost.into_iter()
        .map(|(unit, (summed, alone))| {
            let c: Vec<f64> = if alone.iter().all(Option::is_some) {
                alone.into_iter().flatten().collect()
            } else {
                summed
            };
            let fastest = c
                .iter()
                .copied()
                .filter(|c| c.is_finite() && *c > 0.0)
                .fold(f64::INFINITY, f64::min);
            let keep = c
                .iter()
                .map(|&c| !(c.is_finite() && c > 0.0) || c <= (1.0 + SLOW_STATE) * fastest)
                .collect();
            (unit, keep)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::RngExt;
    use rand::SeedableRng;
    use rand_pcg::Pcg64;

    fn record(ratio: f64, ci: [f64; 2]) -> RatioRecord {
        RatioRecord {
            case: "hole".into(),
            nu: 8.0,
            cull: "skala".into(),
            reference: "cychosz".into(),
            metric: "total_ns".into(),
            ratio,
            ratio_ci: ci,
            rounds: 100,
            rounds_measured: 400,
            rays: 1024,
            ns_per_ray: 10.0 * ratio,
            reference_ns_per_ray: 10.0,
            precision: "f64".into(),
            device: "cpu".into(),
            ..RatioRecord::default()
        }
    }

    #[test]
    fn t_quantiles_match_the_table_and_the_normal_limit() {
        assert!(t_975(0).is_nan());
        assert_eq!(t_975(1), 12.706);
        assert_eq!(t_975(2), 4.303);
        // The expansion joins the table smoothly and tends to the normal quantile.
        assert!((t_975(31) - 2.040).abs() < 0.001, "{}", t_975(31));
        assert!((t_975(60) - 2.000).abs() < 0.001, "{}", t_975(60));
        assert!((t_975(120) - 1.980).abs() < 0.001, "{}", t_975(120));
        assert!((t_975(100_000) - 1.960).abs() < 0.001);
        assert!((1..200).all(|d| t_975(d + 1) < t_975(d)));
    }

    /// Worked by hand: ratios 1, e^0.1, e^0.2 have ȳ = 0.1, s = 0.1, so the interval is
    /// exp(0.1 ± 4.303 · 0.1 / √3).
    #[test]
    fn next_run_interval_is_the_between_run_one_widened_by_the_next_runs_spread() {
        let runs = [1.0, 1.02, 0.99];
        let [lo, hi] = between_run_interval(&runs).expect("three runs");
        let [plo, phi] = next_run_interval(&runs, 3).expect("three runs");
        // Same centre on the log scale, √2 wider for a next mean of as many runs.
        assert!(((plo * phi).ln() - (lo * hi).ln()).abs() < 1e-12);
        let ratio = (phi / plo).ln() / (hi / lo).ln();
        assert!((ratio - 2f64.sqrt()).abs() < 1e-12, "{ratio}");
        assert_eq!(next_run_interval(&runs, 0), None);
        assert_eq!(next_run_interval(&[1.0], 3), None);
    }

    #[test]
    fn between_run_interval_by_hand() {
        let r = [1.0, 0.1f64.exp(), 0.2f64.exp()];
        let [lo, hi] = between_run_interval(&r).unwrap();
        let half = 4.303 * 0.1 / 3f64.sqrt();
        assert!((lo.ln() - (0.1 - half)).abs() < 1e-12, "{lo}");
        assert!((hi.ln() - (0.1 + half)).abs() < 1e-12, "{hi}");
        // Symmetric in r ↔ 1/r: the interval of the inverses is the inverse interval.
        let inv: Vec<f64> = r.iter().map(|x| 1.0 / x).collect();
        let [ilo, ihi] = between_run_interval(&inv).unwrap();
        assert!((ilo - 1.0 / hi).abs() < 1e-12 && (ihi - 1.0 / lo).abs() < 1e-12);
        // Identical runs: a zero-width interval (combine_runs widens it to the within one).
        assert_eq!(between_run_interval(&[2.0, 2.0]), Some([2.0, 2.0]));
        assert_eq!(between_run_interval(&[2.0]), None);
        assert_eq!(between_run_interval(&[2.0, 0.0]), None);
        assert_eq!(between_run_interval(&[2.0, f64::NAN]), None);
    }

    /// Runs whose ratio is shifted by a run-wide effect (σ_b = 2 % on the log scale) plus
    /// round noise: the between-run interval covers the true ratio about 95 % of the time,
    /// while the pooled within-run interval, which sees only the round noise (σ_w =
    /// 0.3 %), covers it far less often: the blind spot of issue 29.
    #[test]
    fn between_run_interval_covers_a_run_wide_effect_and_the_within_one_does_not() {
        let mut rng = Pcg64::seed_from_u64(29);
        let mut normal = || {
            let u1: f64 = 1.0 - rng.random::<f64>();
            let u2: f64 = rng.random();
            (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
        };
        let (truth, sigma_b, sigma_w) = (0.8f64, 0.02, 0.003);
        let trials = 1000;
        let (mut between, mut within) = (0, 0);
        for _ in 0..trials {
            let runs: Vec<Vec<RatioRecord>> = (0..3)
                .map(|_| {
                    let y = truth.ln() + sigma_b * normal() + sigma_w * normal();
                    let h = 1.96 * sigma_w;
                    vec![record(y.exp(), [(y - h).exp(), (y + h).exp()])]
                })
                .collect();
            let c = &combine_runs(&runs).unwrap()[0];
            let [lo, hi] = c.ratio_ci_between.unwrap();
            between += usize::from(lo <= truth && truth <= hi);
            within += usize::from(c.ratio_ci[0] <= truth && truth <= c.ratio_ci[1]);
        }
        // Binomial(1000, 0.95) lies in [925, 975] with probability > 0.999.
        assert!((925..=975).contains(&between), "between covered {between}");
        // The within interval (half-width 1.96 · 0.003 / √3) covers a spread of about
        // 0.02 / √3 ≈ 0.0116 about 23 % of the time.
        assert!(within < 400, "within covered {within}");
    }

    #[test]
    fn combined_record_fields() {
        let a = record(1.0, [0.99, 1.01]);
        let b = record(1.1, [1.08, 1.12]);
        let c = record(1.05, [1.04, 1.06]);
        let runs = vec![vec![a.clone()], vec![b], vec![c]];
        let x = &combine_runs(&runs).unwrap()[0];
        let gm = (1.0f64 * 1.1 * 1.05).powf(1.0 / 3.0);
        assert!((x.ratio - gm).abs() < 1e-12);
        assert_eq!(x.runs, 3);
        assert_eq!(x.run_ratios, [1.0, 1.1, 1.05]);
        assert_eq!((x.rounds, x.rounds_measured), (300, 1200));
        assert_eq!(x.ns_per_ray, 10.5);
        let [lo, hi] = x.ratio_ci;
        assert!(lo < x.ratio && x.ratio < hi);
        // Pooled: narrower than every single run's interval (on the log scale; the
        // narrowest is the third's, ln(1.06 / 1.04)).
        assert!((hi / lo).ln() < (1.06f64 / 1.04).ln(), "{:?}", x.ratio_ci);
        let below = ((1.0f64 / 0.99).ln().powi(2)
            + (1.1f64 / 1.08).ln().powi(2)
            + (1.05f64 / 1.04).ln().powi(2))
        .sqrt()
            / 3.0;
        assert!((lo.ln() - (gm.ln() - below)).abs() < 1e-12, "{lo}");
        let [blo, bhi] = x.ratio_ci_between.unwrap();
        assert!(blo <= lo && hi <= bhi, "between holds within");
        assert!(
            blo < 1.0 && 1.1 < bhi,
            "three runs 10 % apart: a wide interval"
        );
        // One run: its records unchanged.
        assert_eq!(combine_runs(&[vec![a.clone()]]).unwrap(), vec![a.clone()]);
        // Runs that agree exactly: the between interval is the within one.
        let same = combine_runs(&[vec![a.clone()], vec![a.clone()]]).unwrap();
        assert_eq!(same[0].ratio_ci_between, Some(same[0].ratio_ci));
        // Runs of different records are refused, naming the run.
        let other = RatioRecord {
            cull: "aabb".into(),
            ..a.clone()
        };
        let e = combine_runs(&[vec![a.clone()], vec![a.clone()], vec![other]]).unwrap_err();
        assert_eq!(e.run, 3);
        assert!(e.to_string().contains("aabb"), "{e}");
        let e = combine_runs(&[vec![a.clone()], vec![]]).unwrap_err();
        assert!(e.to_string().contains("0 records, not 1"), "{e}");
    }

    /// The state is judged by the exact intersection's own time when the batch has it:
    /// here the quartic (`none`) took 20 % longer in run 2 while the cull in front of it
    /// barely moved, so the pair's summed time stayed within 8 %; run 2 is set aside for
    /// every record of the batch all the same.
    #[test]
    fn the_intersection_alone_judges_the_state() {
        let at =
            |cull: &str, reference: &str, ratio: f64, ns: f64, reference_ns: f64| RatioRecord {
                cull: cull.into(),
                reference: reference.into(),
                ns_per_ray: ns,
                reference_ns_per_ray: reference_ns,
                ..record(ratio, [ratio * 0.999, ratio * 1.001])
            };
        let run = |quartic: f64, cychosz: f64| {
            vec![
                at("cychosz", "none", cychosz / quartic, cychosz, quartic),
                at("skala", "cychosz", 0.5, 0.5 * cychosz, cychosz),
            ]
        };
        let runs = [run(52.0, 66.0), run(62.4, 67.0), run(52.3, 66.2)];
        // Summed, run 2 is only 6 % above run 1: the old rule kept it.
        let summed = |r: &[RatioRecord]| -> f64 {
            r.iter()
                .map(|x| x.ns_per_ray + x.reference_ns_per_ray)
                .sum()
        };
        assert!(summed(&runs[1]) < 1.08 * summed(&runs[0]));
        let c = combine_runs(&runs).unwrap();
        for x in &c {
            assert_eq!((x.runs, x.runs_set_aside), (2, 1), "{x:?}");
        }
        assert!((c[0].ratio - (66.0f64 / 52.0 * 66.2 / 52.3).sqrt()).abs() < 1e-12);
    }

    /// Two runs that agree exactly promise nothing about a third: the spread pooled over
    /// the comparison's other batches widens their interval, and gives a record with one
    /// run kept an interval at all. A record whose own spread gives the wider interval keeps
    /// it.
    #[test]
    fn the_pooled_spread_widens_intervals_that_agree_by_chance() {
        let at = |nu: f64, ratio: f64| RatioRecord {
            nu,
            ..record(ratio, [ratio * 0.999, ratio * 1.001])
        };
        // Batches of one case at ν = 1, 2: ±1 % between the runs; 3: identical runs;
        // 4: ±3 %. A batch of another case has its own pool.
        let other = |ratio: f64| RatioRecord {
            case: "uniform".into(),
            ..record(ratio, [ratio * 0.999, ratio * 1.001])
        };
        let runs = vec![
            vec![
                at(1.0, 1.01),
                at(2.0, 0.99),
                at(3.0, 1.0),
                at(4.0, 1.03),
                other(1.02),
            ],
            vec![
                at(1.0, 0.99),
                at(2.0, 1.01),
                at(3.0, 1.0),
                at(4.0, 0.97),
                other(1.0),
            ],
        ];
        let c = combine_runs(&runs).unwrap();
        let own = |hi: f64, lo: f64| (hi / lo).ln() / 2f64.sqrt();
        let pooled = ((2.0 * own(1.01, 0.99).powi(2) + own(1.03, 0.97).powi(2)) / 4.0).sqrt();
        let spread = |i: usize| c[i].run_spread.expect("a spread");
        assert!((spread(2).log_sd - pooled).abs() < 1e-12, "{:?}", spread(2));
        assert_eq!((spread(2).df, spread(2).pooled), (4, true));
        let [lo, hi] = c[2].ratio_ci_between.unwrap();
        let half = t_975(4) * pooled / 2f64.sqrt();
        assert!((hi.ln() - half).abs() < 1e-12 && (lo.ln() + half).abs() < 1e-12);
        // ν = 4's own spread gives the wider interval: kept, with its own degree of freedom.
        assert!(!spread(3).pooled && spread(3).df == 1);
        assert!((spread(3).log_sd - own(1.03, 0.97)).abs() < 1e-12);
        // The other case is in a pool of its own (the value above left it out).
        assert!((spread(4).log_sd - own(1.02, 1.0)).abs() < 1e-12);
        // One run kept: the pool's spread gives it a between-run interval.
        let mut slow = runs.clone();
        slow[1][2].reference_ns_per_ray = 20.0;
        let c = combine_runs(&slow).unwrap();
        assert_eq!((c[2].runs, c[2].runs_set_aside), (1, 1));
        assert!(c[2].run_ratios.is_empty());
        let [lo, hi] = c[2].ratio_ci_between.expect("the pool's interval");
        assert!(lo < 0.99 && 1.01 < hi, "{lo} {hi}");
        let [plo, phi] = next_run_interval_of(&c[2], 1).unwrap();
        // A next single run: √(1/1 + 1/1) times the spread, against √(1/1) for the mean.
        let ratio = (phi / plo).ln() / (hi / lo).ln();
        assert!((ratio - 2f64.sqrt()).abs() < 1e-9, "{ratio}");
        assert_eq!(next_run_interval_of(&c[2], 0), None);
    }

    /// A run whose batch took 20 % longer per ray ran in a slow state: set aside, counted,
    /// and the ratio is the other runs' alone; within 8 %, every run counts.
    #[test]
    fn a_run_in_a_slow_state_is_set_aside() {
        let fast = |ratio: f64| record(ratio, [ratio * 0.99, ratio * 1.01]);
        let mut slow = record(0.92, [0.91, 0.93]);
        slow.ns_per_ray = 70.0;
        slow.reference_ns_per_ray = 76.0;
        let mut a = fast(0.785);
        (a.ns_per_ray, a.reference_ns_per_ray) = (51.0, 65.0);
        let mut b = fast(0.787);
        (b.ns_per_ray, b.reference_ns_per_ray) = (51.5, 65.4);
        let combined = combine_runs(&[vec![a.clone()], vec![slow], vec![b.clone()]]).unwrap();
        let c = &combined[0];
        assert_eq!((c.runs, c.runs_set_aside), (2, 1));
        assert_eq!(c.run_ratios, vec![0.785, 0.787]);
        assert!((c.ratio - (0.785f64 * 0.787).sqrt()).abs() < 1e-12, "{c:?}");
        assert!(c.ratio_ci_between.is_some());
        let mut near = fast(0.80);
        (near.ns_per_ray, near.reference_ns_per_ray) = (54.0, 67.0);
        let all = combine_runs(&[vec![a], vec![near], vec![b]]).unwrap();
        assert_eq!((all[0].runs, all[0].runs_set_aside), (3, 0));
    }
}
