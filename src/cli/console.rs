//! The command's console: stdout that a closed pipe does not break ([`write_stdout`],
//! `out!`, `outln!`) and the progress lines printed when stderr is not a terminal
//! ([`Heartbeat`], and [`Ticker`] where the work reports no steps of its own). The ground floor of the command: every command module uses it.

/// Progress where the bar cannot be seen: with stderr not a terminal (a CI log, `2> log`)
/// indicatif draws nothing, so this prints a line when the work starts, then at most one
/// every [`Heartbeat::EVERY`], and one at the end.
pub(crate) struct Heartbeat {
    label: String,
    unit: &'static str,
    start: std::time::Instant,
    last: std::sync::Mutex<Option<std::time::Instant>>,
    active: bool,
}

impl Heartbeat {
    /// The longest silence between two lines.
    const EVERY: std::time::Duration = std::time::Duration::from_secs(5);

    /// Active only when stderr is not a terminal.
    pub(crate) fn new(label: String, unit: &'static str) -> Heartbeat {
        use std::io::IsTerminal;
        Heartbeat {
            label,
            unit,
            start: std::time::Instant::now(),
            last: std::sync::Mutex::new(None),
            active: !std::io::stderr().is_terminal(),
        }
    }

    /// `done` of `total` units finished.
    pub(crate) fn update(&self, done: u64, total: u64) {
        if !self.active {
            return;
        }
        let now = std::time::Instant::now();
        let Ok(mut last) = self.last.lock() else {
            return;
        };
        let due = last.is_none_or(|t| now - t >= Self::EVERY) || (total > 0 && done >= total);
        if due && *last != Some(now) {
            let pct = if total > 0 {
                100.0 * done as f64 / total as f64
            } else {
                0.0
            };
            eprintln!(
                "{}: {done}/{total} {} ({pct:.0}%), {:.0} s",
                self.label,
                self.unit,
                (now - self.start).as_secs_f64()
            );
            *last = Some(now);
        }
    }
}

/// A [`Heartbeat`] driven by the clock, for work that cannot report its steps often
/// enough (a shape's rounds, a GPU unit's): a thread that prints the heartbeat's line
/// every [`Heartbeat::EVERY`] with the progress last given to [`Ticker::set`], until the
/// ticker is dropped. Its thread sleeps between lines, so it costs the timed thread
/// nothing but one wake-up in 5 s (and a round it disturbs is set aside as any other).
pub(crate) struct Ticker {
    /// Units done and in all.
    done: std::sync::Arc<[std::sync::atomic::AtomicU64; 2]>,
    stop: Option<std::sync::mpsc::Sender<()>>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Ticker {
    /// Starts ticking `heartbeat` over `total` units, none done yet.
    pub(crate) fn start(heartbeat: Heartbeat, total: u64) -> Ticker {
        use std::sync::atomic::AtomicU64;
        use std::sync::atomic::Ordering;
        let done = std::sync::Arc::new([AtomicU64::new(0), AtomicU64::new(total)]);
        let (stop, stopped) = std::sync::mpsc::channel::<()>();
        let seen = std::sync::Arc::clone(&done);
        let beat = move || {
            heartbeat.update(
                seen[0].load(Ordering::Relaxed),
                seen[1].load(Ordering::Relaxed),
            )
        };
        let thread = std::thread::spawn(move || {
            beat();
            while let Err(std::sync::mpsc::RecvTimeoutError::Timeout) =
                stopped.recv_timeout(Heartbeat::EVERY)
            {
                beat();
            }
            // The end's line when all was done (an error leaves it out).
            beat();
        });
        Ticker {
            done,
            stop: Some(stop),
            thread: Some(thread),
        }
    }

    /// `done` units finished.
    pub(crate) fn set(&self, done: u64) {
        self.done[0].store(done, std::sync::atomic::Ordering::Relaxed);
    }

    /// `done` of `total` units finished, where the total is known only as the work goes.
    pub(crate) fn set_of(&self, done: u64, total: u64) {
        self.done[1].store(total, std::sync::atomic::Ordering::Relaxed);
        self.set(done);
    }
}

impl Drop for Ticker {
    fn drop(&mut self) {
        drop(self.stop.take());
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// Set once stdout's reader has gone (`torus-cull run … | head -1`): later output is
/// dropped, and the command finishes its files and exits as it would have.
static STDOUT_CLOSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Writes to stdout like `print!`, but a closed pipe is not an error (nor a panic): the
/// output is dropped from then on. Other write errors (`/dev/full`) are returned, naming
/// stdout.
pub(crate) fn write_stdout(args: std::fmt::Arguments) -> std::io::Result<()> {
    use std::io::Write;
    use std::sync::atomic::Ordering;
    if STDOUT_CLOSED.load(Ordering::Relaxed) {
        return Ok(());
    }
    let mut out = std::io::stdout().lock();
    match out.write_fmt(args).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
            STDOUT_CLOSED.store(true, Ordering::Relaxed);
            Ok(())
        }
        Err(e) => Err(std::io::Error::new(e.kind(), format!("stdout: {e}"))),
        Ok(()) => Ok(()),
    }
}

/// `print!` through [`write_stdout`]: `out!(...)?`.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::console::write_stdout(format_args!($($arg)*))
    };
}

/// `println!` through [`write_stdout`]: `outln!(...)?`.
macro_rules! outln {
    () => {
        $crate::console::write_stdout(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::console::write_stdout(format_args!("{}\n", format_args!($($arg)*)))
    };
}
pub(crate) use {out, outln};

/// What every command returns: its exit code, or an error `main` prints.
pub(crate) type CliResult = Result<std::process::ExitCode, Box<dyn std::error::Error>>;
