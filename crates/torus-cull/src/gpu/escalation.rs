//! What the kernel could not prove, and who finished it: [`Escalation`] (the step of the
//! certificate that did not go through), a result record read as a verdict, and
//! [`Finished`] / [`FinishCounts`] (the f32 kernel, the device's f64 pass or the host).

use super::{CODE_HIT, CODE_MISS};
use crate::certified::F32Verdict;
use glam::Vec3;

/// A result record `(t, n.xyz, code, why, 0, 0)` as a verdict and, for an escalated ray,
/// why; an unknown code escalates.
pub(crate) fn verdict(w: [f32; 8]) -> (F32Verdict, Option<Escalation>) {
    let normal = Vec3::new(w[1], w[2], w[3]);
    if w[4] == CODE_MISS as f32 {
        (F32Verdict::Miss, None)
    } else if w[4] == CODE_HIT as f32 && w[0].is_finite() && normal.is_finite() {
        (F32Verdict::Hit { t: w[0], normal }, None)
    } else {
        (
            F32Verdict::Escalate,
            Some(Escalation::from_code(w[5] as u32)),
        )
    }
}

/// A verdict for a ray whose origin the host moved `t0` along it: the ray's own t.
pub(crate) fn shifted(
    (verdict, why): (F32Verdict, Option<Escalation>),
    t0: f64,
) -> (F32Verdict, Option<Escalation>) {
    match verdict {
        F32Verdict::Hit { t, normal } if t0 != 0.0 => {
            let t = (f64::from(t) + t0) as f32;
            if t.is_finite() {
                (F32Verdict::Hit { t, normal }, None)
            } else {
                (F32Verdict::Escalate, Some(Escalation::TErrorTooLarge))
            }
        }
        _ => (verdict, why),
    }
}

/// Why the kernel escalated a ray: the step of the certificate that did not go through.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Escalation {
    /// The origin is more than 2²⁰·R from the centre: not sent to the kernel.
    FarOrigin,
    /// The line or its range is not finite in f32.
    NonFiniteLine,
    /// The quartic is not finite, or the solver flagged it (near-double resolvent root,
    /// near-tangent factor, cube root out of range).
    SolverUnsure,
    /// No root found, but F > 0 over the range was not proved.
    MissNotProved,
    /// The bracket around the root is empty (the root at the range's ends, within their
    /// error).
    EmptyBracket,
    /// The signed distance's sign change across the bracket was not proved (a tangent, an
    /// origin inside the tube, or a line error as large as the bracket).
    NoSignChange,
    /// A root before the bracket was not ruled out (F > 0 not proved there).
    EarlierRootNotRuledOut,
    /// The reported t would not be within 1.9·10⁻⁴·(R + r) of the root.
    TErrorTooLarge,
    /// The ray starts on the surface ([`crate::Ray::from_surface`]) and neither the
    /// cubic certificate (its origin's root divided out, `certified/surface_cubic.rs`)
    /// nor the literal ray past its origin's root proved it: the kernel (code 8), or the
    /// host where it has neither to send (no simple root at the origin and no start past
    /// it).
    OnSurface,
    /// A code the host does not know.
    Unknown,
}

impl Escalation {
    /// The escalations the module reports, in the order of their codes 1 to 8
    /// (`TorusHit.why`, `TORUS_WHY_<NAME>` with NAME = [`Escalation::name`] in capitals).
    pub const KERNEL: [Escalation; 8] = [
        Escalation::NonFiniteLine,
        Escalation::SolverUnsure,
        Escalation::MissNotProved,
        Escalation::EmptyBracket,
        Escalation::NoSignChange,
        Escalation::EarlierRootNotRuledOut,
        Escalation::TErrorTooLarge,
        Escalation::OnSurface,
    ];

    /// The module's code (`TorusHit.why`) for an escalation it reports; `None` for the
    /// host's own ([`Escalation::FarOrigin`], [`Escalation::Unknown`]).
    pub fn code(self) -> Option<u32> {
        Escalation::KERNEL
            .iter()
            .position(|&e| e == self)
            .map(|i| i as u32 + 1)
    }

    /// The escalation of a module code (`TorusHit.why`); an unknown code is
    /// [`Escalation::Unknown`].
    pub fn from_code(code: u32) -> Escalation {
        match code {
            1..=8 => Escalation::KERNEL[code as usize - 1],
            _ => Escalation::Unknown,
        }
    }

    /// The stable name.
    pub fn name(self) -> &'static str {
        match self {
            Escalation::FarOrigin => "far_origin",
            Escalation::NonFiniteLine => "non_finite_line",
            Escalation::SolverUnsure => "solver_unsure",
            Escalation::MissNotProved => "miss_not_proved",
            Escalation::EmptyBracket => "empty_bracket",
            Escalation::NoSignChange => "no_sign_change",
            Escalation::EarlierRootNotRuledOut => "earlier_root",
            Escalation::TErrorTooLarge => "t_error",
            Escalation::OnSurface => "on_surface",
            Escalation::Unknown => "unknown",
        }
    }
}

/// Who answered a ray ([`super::GpuIntersector::intersect_finished_where`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Finished {
    /// The certified f32 kernel proved the answer: nothing to finish.
    Proved,
    /// Escalated, and finished by the device's f64 pass.
    Device,
    /// Escalated, and finished on the host in f64 ([`crate::intersect()`]): the adapter
    /// has no f64, or the pass handed the ray back (module docs).
    Host,
}

impl Finished {
    /// The `finished` column of `eval --exact gpu`: empty where f32 proved the answer.
    pub fn name(self) -> &'static str {
        match self {
            Finished::Proved => "",
            Finished::Device => "device",
            Finished::Host => "host",
        }
    }
}

/// How many rays each of [`Finished`]'s answered.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct FinishCounts {
    /// Proved by the f32 kernel.
    pub proved: usize,
    /// Escalated and finished on the device (f64 pass).
    pub device: usize,
    /// Escalated and finished on the host.
    pub host: usize,
}

impl FinishCounts {
    /// The counts of a list of answers.
    pub fn of<'a>(answers: impl IntoIterator<Item = &'a Finished>) -> FinishCounts {
        let mut counts = FinishCounts::default();
        for f in answers {
            match f {
                Finished::Proved => counts.proved += 1,
                Finished::Device => counts.device += 1,
                Finished::Host => counts.host += 1,
            }
        }
        counts
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::CODE_ESCALATE;

    #[test]
    fn every_escalation_code_round_trips() {
        for (i, why) in Escalation::KERNEL.into_iter().enumerate() {
            assert_eq!(why.code(), Some(i as u32 + 1));
            assert_eq!(Escalation::from_code(i as u32 + 1), why);
            let record = [
                0.0,
                0.0,
                0.0,
                0.0,
                CODE_ESCALATE as f32,
                (i + 1) as f32,
                0.0,
                0.0,
            ];
            assert_eq!(verdict(record), (F32Verdict::Escalate, Some(why)));
        }
        for host in [Escalation::FarOrigin, Escalation::Unknown] {
            assert_eq!(host.code(), None);
        }
        assert_eq!(Escalation::from_code(0), Escalation::Unknown);
        assert_eq!(Escalation::from_code(9), Escalation::Unknown);
    }
}
