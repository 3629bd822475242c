//! Where each of two results files was measured, and what that allows `compare` to say.
//!
//! A timing, a paired ratio included, is a fact about the machine as much as about the
//! code: the same build on an AVX-512 and an AVX2 processor differs by 1.5–2.4× in
//! absolute time and by several percent in ratios, because the SIMD width, the cache sizes
//! and the compiler's code for each differ. So when the **machine** differs (the CPU model
//! `meta.cpu`, the instruction set `meta.isa` the batch timings ran on, the GPU adapter
//! `meta.device`, the architecture in `meta.os`), `compare` says so first and gives no
//! timing verdict unless asked to (`--across-machines`). Rejection counts, miss capture,
//! false rejects and BVH hit counts are exact counts of the same rays, independent of the
//! machine, and keep their verdicts.
//!
//! Other differences of the **setup** (the compiler `meta.rustc`, the cores `meta.cores`,
//! the kernel in `meta.os`) are said too, as notes: comparing two compilers on one machine
//! is a legitimate question, so they withhold nothing.

use crate::results::Meta;

/// How the two files' `meta` blocks differ.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MetaDiff {
    /// Fields that make the machines different, each as `field: old vs new`.
    pub machine: Vec<String>,
    /// Other differences of the setup, each as `field: old vs new`.
    pub setup: Vec<String>,
}

impl MetaDiff {
    /// Whether the files were measured on different machines.
    pub fn machines_differ(&self) -> bool {
        !self.machine.is_empty()
    }
}

/// The differences between `old` and `new` (see the module docs). A field one file does
/// not record (older files, `meta.isa` of a file with no batch timing) is not a
/// difference of the machine: it is named as unknown among the setup notes.
pub fn differences(old: &Meta, new: &Meta) -> MetaDiff {
    let mut diff = MetaDiff::default();
    let shown = |v: &Option<String>| v.clone().unwrap_or_else(|| "not recorded".into());
    if old.cpu != new.cpu {
        diff.machine
            .push(format!("meta.cpu: '{}' vs '{}'", old.cpu, new.cpu));
    }
    for (field, a, b) in [
        ("meta.isa", &old.isa, &new.isa),
        ("meta.device", &old.device, &new.device),
    ] {
        match (a, b) {
            (Some(x), Some(y)) if x != y => diff.machine.push(format!("{field}: {x} vs {y}")),
            (Some(_), None) | (None, Some(_)) => {
                diff.setup
                    .push(format!("{field}: {} vs {}", shown(a), shown(b)))
            }
            _ => {}
        }
    }
    // `<os> <arch> [<kernel>]`: the first two words are the machine, the rest the setup.
    if let (Some(a), Some(b)) = (&old.os, &new.os) {
        let split = |s: &str| {
            let words: Vec<&str> = s.split_whitespace().collect();
            let cut = words.len().min(2);
            (words[..cut].join(" "), words[cut..].join(" "))
        };
        let ((a_arch, a_kernel), (b_arch, b_kernel)) = (split(a), split(b));
        if a_arch != b_arch {
            diff.machine.push(format!("meta.os: {a_arch} vs {b_arch}"));
        } else if a_kernel != b_kernel {
            diff.setup.push(format!("meta.os: {a} vs {b}"));
        }
    }
    if old.rustc != new.rustc {
        diff.setup
            .push(format!("meta.rustc: {} vs {}", old.rustc, new.rustc));
    }
    if let (Some(a), Some(b)) = (old.cores, new.cores) {
        if a != b {
            diff.setup.push(format!("meta.cores: {a} vs {b}"));
        }
    }
    diff
}

#[cfg(test)]
mod tests {
    use super::*;

    fn meta(cpu: &str, isa: Option<&str>) -> Meta {
        serde_json::from_value(serde_json::json!({
            "commit": null, "dirty": false, "created": "x", "rustc": "rustc 1.95.0",
            "cpu": cpu, "workload": "quick", "workload_sha256": "00",
            "isa": isa, "os": "linux x86_64 6.8.0", "cores": 2
        }))
        .unwrap()
    }

    #[test]
    fn cpu_and_isa_are_the_machine_rustc_and_kernel_the_setup() {
        let a = meta("Xeon", Some("avx512"));
        assert_eq!(differences(&a, &a), MetaDiff::default());
        let b = meta("EPYC", Some("avx2"));
        let d = differences(&a, &b);
        assert!(d.machines_differ());
        assert_eq!(d.machine.len(), 2, "{d:?}");
        assert!(d.machine[1].contains("avx512 vs avx2"), "{d:?}");
        // An ISA one side does not record is unknown, not a different machine.
        let c = meta("Xeon", None);
        let d = differences(&a, &c);
        assert!(!d.machines_differ(), "{d:?}");
        assert!(d.setup[0].contains("not recorded"), "{d:?}");
        let mut e = meta("Xeon", Some("avx512"));
        e.rustc = "rustc 1.96.0".into();
        e.os = Some("linux x86_64 6.9.1".into());
        let d = differences(&a, &e);
        assert!(!d.machines_differ() && d.setup.len() == 2, "{d:?}");
        e.os = Some("linux aarch64 6.9.1".into());
        assert!(differences(&a, &e).machines_differ());
    }
}
