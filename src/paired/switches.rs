//! How often the operating system has taken the CPU from this thread: a round during
//! which that happened ran partly on caches and branch predictors another process left
//! behind, so its timings are not comparable with the others.

/// Context switches of the calling thread so far, voluntary and involuntary
/// (`getrusage(RUSAGE_THREAD)`: `ru_nvcsw + ru_nivcsw`); `None` where the platform does
/// not count them per thread.
#[cfg(target_os = "linux")]
pub fn context_switches() -> Option<u64> {
    let mut usage = std::mem::MaybeUninit::<libc::rusage>::zeroed();
    // SAFETY: getrusage writes a whole `rusage` into the pointer it is given and reads
    // nothing from it; RUSAGE_THREAD is valid on Linux since 2.6.26.
    let rc = unsafe { libc::getrusage(libc::RUSAGE_THREAD, usage.as_mut_ptr()) };
    if rc != 0 {
        return None;
    }
    // SAFETY: rc == 0, so the kernel filled the struct.
    let usage = unsafe { usage.assume_init() };
    Some((usage.ru_nvcsw as u64).wrapping_add(usage.ru_nivcsw as u64))
}

/// Context switches of the calling thread so far; `None` where the platform does not
/// count them per thread.
#[cfg(not(target_os = "linux"))]
pub fn context_switches() -> Option<u64> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[cfg(target_os = "linux")]
    fn sleeping_is_a_context_switch() {
        let before = context_switches().expect("Linux counts them");
        std::thread::sleep(std::time::Duration::from_millis(2));
        let after = context_switches().unwrap();
        assert!(after > before, "{before} -> {after}");
    }
}
