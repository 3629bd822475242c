//! The statistics of a paired ratio: the median of per-round ratios and its percentile
//! bootstrap confidence interval (Efron & Tibshirani, *An Introduction to the Bootstrap*,
//! 1993, ch. 13).
//!
//! The median, not the mean: a round in which the machine stalled gives one wild ratio,
//! which moves the mean but not the median.

use rand::RngExt;
use rand::SeedableRng;
use rand_pcg::Pcg64;

/// The median of `values` (the mean of the two middle ones for an even count); `NaN` for
/// an empty slice. Reorders `values`.
pub fn median(values: &mut [f64]) -> f64 {
    let n = values.len();
    if n == 0 {
        return f64::NAN;
    }
    let (_, upper, _) = values.select_nth_unstable_by(n / 2, f64::total_cmp);
    let upper = *upper;
    if n % 2 == 1 {
        return upper;
    }
    // The lower middle is the largest of the lower half, which selection left below n/2.
    let lower = values[..n / 2]
        .iter()
        .copied()
        .max_by(f64::total_cmp)
        .expect("n >= 2");
    0.5 * (lower + upper)
}

/// Percentile bootstrap interval `[lo, hi]` at `level` (0.95 for 95 %) of the median of
/// `values`: the median of `resamples` resamples with replacement, drawn from a Pcg64
/// seeded with `seed`, and their `(1 − level)/2` and `(1 + level)/2` quantiles.
///
/// Deterministic for a given seed. For fewer than two values the interval is the single
/// value (or `NaN`s when empty): there is nothing to resample.
pub fn bootstrap_median_ci(values: &[f64], resamples: usize, level: f64, seed: u64) -> [f64; 2] {
    let n = values.len();
    if n < 2 || resamples == 0 {
        let m = median(&mut values.to_vec());
        return [m, m];
    }
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut sample = vec![0.0; n];
    let mut medians: Vec<f64> = (0..resamples)
        .map(|_| {
            for s in sample.iter_mut() {
                *s = values[rng.random_range(0..n)];
            }
            median(&mut sample)
        })
        .collect();
    medians.sort_unstable_by(f64::total_cmp);
    let alpha = (1.0 - level.clamp(0.0, 1.0)) / 2.0;
    let at = |q: f64| {
        let i = (q * (resamples - 1) as f64).round() as usize;
        medians[i.min(resamples - 1)]
    };
    [at(alpha), at(1.0 - alpha)]
}

/// The share of rounds the ratios are taken over: the quietest quarter.
pub const QUIET_FRACTION: f64 = 0.25;

/// Indices (ascending) of the quietest `fraction` of the `eligible` rounds in
/// `ns[contender][round]`.
///
/// A round's slowness is the mean over contenders of ln(t / median t of that contender):
/// how much slower than usual the machine ran that round, all contenders together. Load
/// only ever adds time (Chen & Revels, "Robust benchmarking in noisy environments",
/// 2016), and on a shared machine it comes in spells lasting seconds (another tenant on
/// the core, a busy SMT sibling) that slow some code more than other code, so they shift
/// the ratios themselves; the quietest rounds are the ones such a spell spared. A round
/// with a timing that is not a positive finite number is never chosen.
pub fn quiet_rounds(ns: &[Vec<f64>], eligible: &[bool], fraction: f64) -> Vec<usize> {
    let rounds = ns.first().map_or(0, Vec::len);
    let candidates: Vec<usize> = (0..rounds)
        .filter(|&k| eligible.get(k).copied().unwrap_or(false))
        .collect();
    let valid = |t: f64| t.is_finite() && t > 0.0;
    let medians: Vec<f64> = ns
        .iter()
        .map(|v| {
            median(
                &mut candidates
                    .iter()
                    .map(|&k| v[k])
                    .filter(|&t| valid(t))
                    .collect::<Vec<_>>(),
            )
        })
        .collect();
    let slowness = |k: usize| {
        let mut sum = 0.0;
        for (v, &m) in ns.iter().zip(&medians) {
            if !(valid(v[k]) && valid(m)) {
                return f64::INFINITY;
            }
            sum += (v[k] / m).ln();
        }
        sum / ns.len() as f64
    };
    let mut ranked: Vec<(f64, usize)> = candidates.iter().map(|&k| (slowness(k), k)).collect();
    ranked.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let keep = ((fraction.clamp(0.0, 1.0) * ranked.len() as f64).ceil() as usize).min(ranked.len());
    let mut chosen: Vec<usize> = ranked[..keep]
        .iter()
        .filter(|(s, _)| s.is_finite())
        .map(|&(_, k)| k)
        .collect();
    chosen.sort_unstable();
    chosen
}

/// One contender against one reference, from paired per-round timings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RatioEstimate {
    /// Median over rounds of `t(contender) / t(reference)`.
    pub ratio: f64,
    /// Bootstrap 95 % interval of that median.
    pub ratio_ci: [f64; 2],
    /// Rounds that entered the ratio.
    pub rounds: usize,
    /// Median over rounds of the contender's time per unit of work (ns per ray).
    pub ns_per_ray: f64,
    /// The same for the reference.
    pub reference_ns_per_ray: f64,
}

/// Bootstrap resamples behind every ratio interval.
pub const RESAMPLES: usize = 2000;

/// The paired ratio of `contender_ns` to `reference_ns` (one timing per round each, in
/// the same rounds), with per-ray medians for `work` rays per timing.
///
/// Rounds where either timing is not a positive finite number (a clock that did not
/// advance) are left out, so the result never holds a NaN or an infinity; `None` when
/// no round is left.
pub fn ratio_estimate(
    contender_ns: &[f64],
    reference_ns: &[f64],
    work: f64,
    seed: u64,
) -> Option<RatioEstimate> {
    let valid = |t: f64| t.is_finite() && t > 0.0;
    let pairs: Vec<(f64, f64)> = contender_ns
        .iter()
        .zip(reference_ns)
        .map(|(&c, &r)| (c, r))
        .filter(|&(c, r)| valid(c) && valid(r))
        .collect();
    if pairs.is_empty() || !(work.is_finite() && work > 0.0) {
        return None;
    }
    let mut ratios: Vec<f64> = pairs.iter().map(|(c, r)| c / r).collect();
    let ratio_ci = bootstrap_median_ci(&ratios, RESAMPLES, 0.95, seed);
    let ratio = median(&mut ratios);
    let mut mine: Vec<f64> = pairs.iter().map(|(c, _)| c / work).collect();
    let mut theirs: Vec<f64> = pairs.iter().map(|(_, r)| r / work).collect();
    Some(RatioEstimate {
        ratio,
        ratio_ci,
        rounds: pairs.len(),
        ns_per_ray: median(&mut mine),
        reference_ns_per_ray: median(&mut theirs),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::seq::SliceRandom;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 3.0, 2.0]), 2.5);
        assert_eq!(median(&mut [7.0]), 7.0);
        assert!(median(&mut []).is_nan());
        // A wild outlier does not move it.
        assert_eq!(median(&mut [1.0, 1.1, 0.9, 1e9, 1.0]), 1.0);
    }

    #[test]
    fn median_matches_sorting_on_shuffled_data() {
        let mut rng = Pcg64::seed_from_u64(3);
        for n in 1..60 {
            let mut v: Vec<f64> = (0..n)
                .map(|i| (i * i % 17) as f64 + i as f64 * 0.01)
                .collect();
            let mut sorted = v.clone();
            sorted.sort_by(f64::total_cmp);
            let want = if n % 2 == 1 {
                sorted[n / 2]
            } else {
                0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
            };
            v.shuffle(&mut rng);
            assert_eq!(median(&mut v), want, "n = {n}");
        }
    }

    /// A standard normal draw (Box–Muller), for data with a known answer.
    fn normal(rng: &mut Pcg64) -> f64 {
        let u1: f64 = 1.0 - rng.random::<f64>();
        let u2: f64 = rng.random();
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }

    #[test]
    fn bootstrap_interval_of_normal_data_has_the_textbook_width() {
        // The median of n normal draws has standard error √(π/2)·σ/√n, so a 95 % interval
        // is about ±1.96 of that around the true median.
        let (n, mu, sigma) = (2001, 5.0, 0.5);
        let mut rng = Pcg64::seed_from_u64(11);
        let data: Vec<f64> = (0..n).map(|_| mu + sigma * normal(&mut rng)).collect();
        let [lo, hi] = bootstrap_median_ci(&data, RESAMPLES, 0.95, 1);
        let se = (std::f64::consts::PI / 2.0).sqrt() * sigma / (n as f64).sqrt();
        let half = 0.5 * (hi - lo);
        assert!(lo < mu && mu < hi, "[{lo}, {hi}] misses {mu}");
        assert!(
            half > 0.7 * 1.96 * se && half < 1.3 * 1.96 * se,
            "half width {half}, expected about {}",
            1.96 * se
        );
    }

    #[test]
    fn bootstrap_interval_covers_the_true_median_about_95_percent_of_the_time() {
        let mut rng = Pcg64::seed_from_u64(5);
        let trials = 200;
        let covered = (0..trials)
            .filter(|&t| {
                let data: Vec<f64> = (0..301).map(|_| normal(&mut rng)).collect();
                let [lo, hi] = bootstrap_median_ci(&data, 500, 0.95, t);
                lo <= 0.0 && 0.0 <= hi
            })
            .count();
        // Binomial(200, 0.95) lies in [176, 199] with probability > 0.999.
        assert!(
            (176..=200).contains(&covered),
            "covered {covered} of {trials}"
        );
    }

    #[test]
    fn bootstrap_is_deterministic_per_seed_and_degenerate_inputs_are_safe() {
        let data: Vec<f64> = (0..101).map(|i| (i as f64).sin()).collect();
        assert_eq!(
            bootstrap_median_ci(&data, 300, 0.95, 9),
            bootstrap_median_ci(&data, 300, 0.95, 9)
        );
        assert_eq!(bootstrap_median_ci(&[2.0], RESAMPLES, 0.95, 1), [2.0, 2.0]);
        let [lo, hi] = bootstrap_median_ci(&[], RESAMPLES, 0.95, 1);
        assert!(lo.is_nan() && hi.is_nan());
    }

    /// The machine runs in two states for long spells, and the slow one changes the
    /// ratio (2 becomes 1.5): the quiet rounds are the fast state's, in time order, and
    /// a round with a broken timing is never among them.
    #[test]
    fn quiet_rounds_pick_the_fast_state() {
        let mut reference = Vec::new();
        let mut contender = Vec::new();
        for k in 0..400 {
            let jitter = 1.0 + 0.01 * ((k * 7919 % 13) as f64 / 13.0);
            if (100..300).contains(&k) {
                reference.push(1300.0 * jitter);
                contender.push(1950.0 * jitter);
            } else {
                reference.push(1000.0 * jitter);
                contender.push(2000.0 * jitter);
            }
        }
        reference[5] = 0.0;
        let ns = vec![contender, reference];
        let all = vec![true; 400];
        let quiet = quiet_rounds(&ns, &all, 0.25);
        assert_eq!(quiet.len(), 100);
        assert!(quiet.windows(2).all(|w| w[0] < w[1]));
        assert!(
            quiet.iter().all(|k| !(100..300).contains(k) && *k != 5),
            "{quiet:?}"
        );
        let pick = |v: &[f64]| quiet.iter().map(|&k| v[k]).collect::<Vec<f64>>();
        let e = ratio_estimate(&pick(&ns[0]), &pick(&ns[1]), 1.0, 1).unwrap();
        assert!((e.ratio - 2.0).abs() < 1e-9, "{e:?}");
        assert_eq!(quiet_rounds(&ns, &all, 1.0).len(), 399);
        assert!(quiet_rounds(&[], &[], 0.25).is_empty());
        // Only eligible rounds are chosen: here the slow state's.
        let slow: Vec<bool> = (0..400).map(|k| (100..300).contains(&k)).collect();
        let quiet = quiet_rounds(&ns, &slow, 0.5);
        assert_eq!(quiet.len(), 100);
        assert!(quiet.iter().all(|k| (100..300).contains(k)));
    }

    #[test]
    fn ratio_estimate_pairs_rounds_and_drops_broken_ones() {
        // The contender takes exactly twice the reference in every round, while the
        // machine's speed drifts by a factor of 3 across the rounds: the ratio is exact.
        let reference: Vec<f64> = (0..100)
            .map(|i| 1000.0 * (1.0 + 2.0 * i as f64 / 99.0))
            .collect();
        let contender: Vec<f64> = reference.iter().map(|t| 2.0 * t).collect();
        let e = ratio_estimate(&contender, &reference, 10.0, 1).unwrap();
        assert_eq!(e.ratio, 2.0);
        assert_eq!(e.ratio_ci, [2.0, 2.0]);
        assert_eq!(e.rounds, 100);
        assert!((e.reference_ns_per_ray - 200.0).abs() < 2.0);
        assert!((e.ns_per_ray - 2.0 * e.reference_ns_per_ray).abs() < 1e-9);

        // A clock that did not advance, or a NaN, drops the round instead of poisoning it.
        let e = ratio_estimate(&[2.0, 0.0, f64::NAN, 4.0], &[1.0, 1.0, 1.0, 0.0], 1.0, 1).unwrap();
        assert_eq!((e.ratio, e.rounds), (2.0, 1));
        assert!(ratio_estimate(&[0.0], &[1.0], 1.0, 1).is_none());
        assert!(ratio_estimate(&[1.0], &[1.0], 0.0, 1).is_none());
    }
}
