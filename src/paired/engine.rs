//! The rounds: every contender timed once per round, in a freshly shuffled order.
//!
//! Shuffling matters as much as pairing. In a fixed order the second contender always
//! runs on caches and branch predictors the first one left behind, and a slow-down that
//! ramps within a round always falls on the same contender; a random order spreads both
//! over all of them evenly.
//!
//! An [`Interleaver`] can be resumed: the workload driver visits every (case, ν) in
//! turn, many times, so that a spell of load lasting seconds falls on all of them alike
//! instead of on whichever one was being timed.

use super::switches::context_switches;
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_pcg::Pcg64;
use std::time::{Duration, Instant};

/// The rounds of one set of contenders, accumulated over any number of visits.
#[derive(Debug, Clone)]
pub struct Interleaver {
    rng: Pcg64,
    order: Vec<usize>,
    /// Nanoseconds per timing, `ns[contender][round]`, all of the same length.
    pub ns: Vec<Vec<f64>>,
    /// Per measured round: whether the operating system switched this thread out during
    /// it, just before it, or during the round before (whose state it inherits).
    pub disturbed: Vec<bool>,
    last_count: Option<u64>,
    last_switched: bool,
}

impl Interleaver {
    /// `contenders` contenders, with the round order shuffled by a Pcg64 seeded with `seed`.
    pub fn new(contenders: usize, seed: u64) -> Interleaver {
        Interleaver {
            rng: Pcg64::seed_from_u64(seed),
            order: (0..contenders).collect(),
            ns: vec![Vec::new(); contenders],
            disturbed: Vec::new(),
            last_count: context_switches(),
            last_switched: false,
        }
    }

    /// Measured rounds so far.
    pub fn rounds(&self) -> usize {
        self.ns.first().map_or(0, Vec::len)
    }

    /// One visit: `discard` rounds thrown away (caches, predictors and clock speed settle
    /// after other work), then measured rounds until `duration` has passed since the
    /// visit began and at least `min_rounds` were taken, or `max_rounds` were.
    ///
    /// Each round calls `time_one(i)` once for every contender `i`, in a shuffled order,
    /// and records the duration it returns; `time_one` times its own work, so setup and
    /// dispatch stay outside the timed region.
    pub fn visit(
        &mut self,
        time_one: &mut dyn FnMut(usize) -> Duration,
        discard: usize,
        duration: Duration,
        min_rounds: usize,
        max_rounds: usize,
    ) {
        if self.order.is_empty() {
            return;
        }
        let start = Instant::now();
        for _ in 0..discard {
            self.round(time_one, false);
        }
        let mut taken = 0;
        while taken < max_rounds && (taken < min_rounds || start.elapsed() < duration) {
            self.round(time_one, true);
            taken += 1;
        }
    }

    /// Rounds thrown away until `duration` has passed.
    pub fn warm_up(&mut self, time_one: &mut dyn FnMut(usize) -> Duration, duration: Duration) {
        let start = Instant::now();
        while !self.order.is_empty() && start.elapsed() < duration {
            self.round(time_one, false);
        }
    }

    fn round(&mut self, time_one: &mut dyn FnMut(usize) -> Duration, record: bool) {
        self.order.shuffle(&mut self.rng);
        let before = context_switches();
        for &i in &self.order {
            let t = time_one(i);
            if record {
                self.ns[i].push(t.as_nanos() as f64);
            }
        }
        let after = context_switches();
        let switched = before != after || before != self.last_count;
        if record {
            self.disturbed.push(switched || self.last_switched);
        }
        self.last_switched = switched;
        self.last_count = after;
    }
}

/// How long to run one set of contenders and how many rounds to take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Schedule {
    /// Rounds run first and thrown away for this long.
    pub warm_up: Duration,
    /// Measured rounds continue until this much time has passed …
    pub budget: Duration,
    /// … but at least this many are taken, so the interval has something to resample …
    pub min_rounds: usize,
    /// … and at most this many.
    pub max_rounds: usize,
    /// Seed of the Pcg64 that shuffles each round's order.
    pub seed: u64,
}

/// The timings of every measured round: `ns[contender][round]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Rounds {
    /// Nanoseconds per timing, one vector per contender, all of the same length.
    pub ns: Vec<Vec<f64>>,
    /// Per round: whether the operating system switched the thread out (see
    /// [`Interleaver::disturbed`]).
    pub disturbed: Vec<bool>,
}

impl Rounds {
    /// Measured rounds.
    pub fn len(&self) -> usize {
        self.ns.first().map_or(0, Vec::len)
    }

    /// Whether no round was measured.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One set of contenders in a single visit: a warm-up of `schedule.warm_up`, then
/// measured rounds as [`Interleaver::visit`] takes them.
pub fn interleave(
    contenders: usize,
    schedule: &Schedule,
    mut time_one: impl FnMut(usize) -> Duration,
) -> Rounds {
    let mut rounds = Interleaver::new(contenders, schedule.seed);
    rounds.warm_up(&mut time_one, schedule.warm_up);
    rounds.visit(
        &mut time_one,
        0,
        schedule.budget,
        schedule.min_rounds,
        schedule.max_rounds,
    );
    Rounds {
        ns: rounds.ns,
        disturbed: rounds.disturbed,
    }
}

/// One timed pass over `rays`: the wall time of `hit` on each, the hits counted and the
/// count and `state` (a traversal's statistics, or `()`) kept from the optimiser by
/// `black_box`, so that the work is done and nothing else is timed. Inlined into the
/// caller, whose `#[inline(never)]` visit monomorphizes it per cull: each contender's
/// loop is its own code, as when every pass wrote this loop out.
#[inline(always)]
pub fn timed_pass<R, S: Default>(rays: &[R], mut hit: impl FnMut(&R, &mut S) -> bool) -> Duration {
    let start = Instant::now();
    let mut state = S::default();
    let mut hits = 0usize;
    for ray in std::hint::black_box(rays) {
        hits += usize::from(hit(ray, &mut state));
    }
    std::hint::black_box((hits, state));
    start.elapsed()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paired::stats::ratio_estimate;
    use std::hint::black_box;

    fn schedule(min_rounds: usize, seed: u64) -> Schedule {
        Schedule {
            warm_up: Duration::ZERO,
            budget: Duration::ZERO,
            min_rounds,
            max_rounds: min_rounds,
            seed,
        }
    }

    /// Every round calls every contender once; who goes first is spread evenly; the order
    /// changes from round to round and is the same for the same seed.
    #[test]
    fn rounds_are_complete_shuffled_and_seeded() {
        let calls = |seed| {
            let mut log = Vec::new();
            let rounds = interleave(3, &schedule(600, seed), |i| {
                log.push(i);
                Duration::from_nanos(1 + i as u64)
            });
            assert_eq!(rounds.len(), 600);
            assert!(rounds.ns.iter().all(|v| v.len() == 600));
            // The recorded duration belongs to the contender that produced it.
            for (i, v) in rounds.ns.iter().enumerate() {
                assert!(v.iter().all(|&t| t == 1.0 + i as f64));
            }
            log
        };
        let log = calls(42);
        let mut first = [0usize; 3];
        let mut orders = std::collections::HashSet::new();
        for round in log.chunks(3) {
            let mut seen = round.to_vec();
            seen.sort_unstable();
            assert_eq!(seen, [0, 1, 2], "a round must time each contender once");
            first[round[0]] += 1;
            orders.insert(round.to_vec());
        }
        // 600 rounds, 1/3 each: 200 ± 50 is more than 4 standard deviations.
        assert!(first.iter().all(|&n| (150..=250).contains(&n)), "{first:?}");
        assert_eq!(orders.len(), 6, "all 3! orders occur");
        assert_eq!(log, calls(42));
        assert_ne!(log, calls(43));
    }

    #[test]
    fn visits_accumulate_and_discarded_rounds_are_not_recorded() {
        let mut calls = 0;
        let mut time_one = |_| {
            calls += 1;
            Duration::from_nanos(7)
        };
        let mut il = Interleaver::new(4, 1);
        il.visit(&mut time_one, 2, Duration::ZERO, 5, 100);
        il.visit(&mut time_one, 1, Duration::ZERO, 3, 100);
        assert_eq!(il.rounds(), 8);
        assert!(
            il.ns
                .iter()
                .all(|v| v.len() == 8 && v.iter().all(|&t| t == 7.0))
        );
        assert_eq!(calls, 4 * (2 + 5 + 1 + 3));
    }

    /// A round in which the thread sleeps (a voluntary switch) is disturbed, and so is the
    /// round after it, which starts on whatever state the sleep left.
    #[test]
    #[cfg(target_os = "linux")]
    fn a_round_with_a_context_switch_and_the_next_are_disturbed() {
        let mut calls = 0;
        let mut time_one = |_| {
            calls += 1;
            if calls == 2 * 10 + 1 {
                std::thread::sleep(Duration::from_millis(1));
            }
            Duration::from_nanos(5)
        };
        let mut il = Interleaver::new(2, 3);
        il.visit(&mut time_one, 0, Duration::ZERO, 30, 30);
        assert_eq!(il.disturbed.len(), 30);
        assert!(il.disturbed[10] && il.disturbed[11], "{:?}", il.disturbed);
        // Nothing else slept; on a busy machine the scheduler may still preempt a round
        // or two, so only most of the others must be clean.
        let clean = il.disturbed.iter().filter(|d| !**d).count();
        assert!(clean >= 20, "{:?}", il.disturbed);
    }

    #[test]
    fn budget_min_and_max_rounds_are_honoured() {
        let s = Schedule {
            warm_up: Duration::from_millis(1),
            budget: Duration::from_millis(5),
            min_rounds: 3,
            max_rounds: 1_000_000,
            seed: 1,
        };
        let r = interleave(2, &s, |_| {
            std::thread::sleep(Duration::from_micros(200));
            Duration::from_micros(200)
        });
        // 5 ms of 0.4 ms rounds: about 12; the budget stops it well before 1000.
        assert!(r.len() >= 3 && r.len() <= 25, "{} rounds", r.len());
        let r = interleave(2, &Schedule { max_rounds: 4, ..s }, |_| {
            Duration::from_nanos(5)
        });
        assert_eq!(r.len(), 4);
        assert!(interleave(0, &s, |_| Duration::ZERO).is_empty());
    }

    /// A deterministic busy loop of `n` dependent steps.
    fn spin(n: u64) -> Duration {
        let start = Instant::now();
        let mut x = 1u64;
        for i in 0..black_box(n) {
            x = black_box(x.wrapping_mul(6364136223846793005).wrapping_add(i));
        }
        black_box(x);
        start.elapsed()
    }

    /// The engine measures a contender that does twice the work as twice as slow, on a
    /// machine shared with others: only loose bounds are asserted.
    #[test]
    fn twice_the_work_measures_about_twice_the_time() {
        let s = Schedule {
            warm_up: Duration::from_millis(20),
            budget: Duration::from_millis(300),
            min_rounds: 50,
            max_rounds: 5000,
            seed: 7,
        };
        let n = 20_000;
        let rounds = interleave(2, &s, |i| spin(n * (i as u64 + 1)));
        let e = ratio_estimate(&rounds.ns[1], &rounds.ns[0], n as f64, 1).unwrap();
        let [lo, hi] = e.ratio_ci;
        assert!(lo <= e.ratio && e.ratio <= hi, "{e:?}");
        assert!((e.ratio - 2.0).abs() < 0.2, "{e:?}");
        // The interval is of the median of this run; allow 5 % for the loop's fixed cost
        // and the machine, and it must contain 2.
        assert!(lo * 0.95 <= 2.0 && 2.0 <= hi * 1.05, "{e:?}");
        assert!(hi - lo < 0.2, "a loose interval measures nothing: {e:?}");
    }
}
