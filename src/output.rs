//! Output files that behave like a Unix tool's: every file this crate writes (results
//! JSON, SVG and PNG, `eval`'s CSV) goes through [`Output`].
//!
//! * **A regular file, or a path with nothing there yet, is replaced atomically.** The
//!   bytes go to a hidden temp file in the same directory, which is renamed over the
//!   target when complete: a reader never sees half a file, and a failed or interrupted
//!   writer leaves the old file as it was.
//! * **Modes follow the usual rules.** A new file gets `0666` minus the umask (`0644`
//!   under umask 022), as `open(2)` with `O_CREAT` gives; a replaced file keeps its mode.
//! * **Symlinks are followed**: the file a link points to is replaced and the link stays,
//!   as a shell redirection does.
//! * **Anything else is written in place.** A FIFO, a terminal, `/dev/stdout` or
//!   `/dev/full` is opened and written directly: renaming over it would replace the node
//!   and nothing would reach its reader. Write errors (`/dev/full`'s "no space") are
//!   returned, never dropped.
//! * **Nothing is created but the file.** A missing parent directory is an error (no
//!   `mkdir -p`), and so is an existing directory given as the file: [`check_writable`]
//!   finds both before any work, and [`check_not_input`] refuses an output that is one of
//!   the command's inputs (same file, by device and inode).
//! * **No temp file outlives the process.** A temp file is deleted when its [`Output`] is
//!   dropped unfinished (an error or a panic), and every pending one is listed so that a
//!   signal handler can delete them with [`remove_pending`] before the process dies; the
//!   `torus-cull` binary installs one for SIGINT, SIGTERM and SIGHUP.

use std::fs::{self, File, Metadata};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use tempfile::NamedTempFile;

/// Temp files not yet renamed into place, for [`remove_pending`].
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The prefix of this crate's temp files (hidden, and easy to recognise).
pub const TEMP_PREFIX: &str = ".torus-cull-";

/// An output file being written; [`Output::finish`] completes it.
pub struct Output {
    /// `None` once finished.
    target: Option<Target>,
}

enum Target {
    /// A non-regular file, written in place.
    Direct(File),
    /// A temp file, renamed to `dest` by `finish`.
    Atomic {
        tmp: NamedTempFile,
        dest: PathBuf,
        /// The mode of the file being replaced, kept on the new one.
        keep_mode: Option<fs::Permissions>,
    },
}

/// Where a path leads once symlinks are followed.
enum Resolved {
    /// A regular file (with its metadata), or nothing yet: replace atomically.
    Regular(PathBuf, Option<Metadata>),
    /// Something else: write in place, through the original path.
    Direct(PathBuf),
}

impl Output {
    /// Start writing `path` (see the module docs for what happens to what is there).
    /// A missing parent directory is an error, as for a shell redirection.
    pub fn create(path: &Path) -> io::Result<Output> {
        let target = match resolve(path)? {
            Resolved::Direct(p) => Target::Direct(fs::OpenOptions::new().write(true).open(p)?),
            Resolved::Regular(dest, existing) => {
                let tmp = temp_in(parent_of(&dest))?;
                register(tmp.path());
                Target::Atomic {
                    tmp,
                    dest,
                    keep_mode: existing.map(|m| m.permissions()),
                }
            }
        };
        Ok(Output {
            target: Some(target),
        })
    }

    /// Flush and complete the file: for a regular file, sync the temp file and rename it
    /// over the target.
    pub fn finish(mut self) -> io::Result<()> {
        self.flush()?;
        match self.target.take() {
            None => Ok(()),
            Some(Target::Direct(file)) => file.sync_all().or_else(ignore_unsyncable),
            Some(Target::Atomic {
                tmp,
                dest,
                keep_mode,
            }) => {
                let tmp_path = tmp.path().to_path_buf();
                let result = (|| {
                    if let Some(mode) = keep_mode {
                        tmp.as_file().set_permissions(mode)?;
                    }
                    tmp.as_file().sync_all()?;
                    tmp.persist(&dest).map_err(|e| e.error)?;
                    Ok(())
                })();
                unregister(&tmp_path);
                result
            }
        }
    }
}

impl Write for Output {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.target {
            Some(Target::Direct(f)) => f.write(buf),
            Some(Target::Atomic { tmp, .. }) => tmp.write(buf),
            None => Err(io::Error::other("output already finished")),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match &mut self.target {
            Some(Target::Direct(f)) => f.flush(),
            Some(Target::Atomic { tmp, .. }) => tmp.flush(),
            None => Ok(()),
        }
    }
}

impl Drop for Output {
    fn drop(&mut self) {
        // NamedTempFile deletes itself when dropped; only the registry needs updating.
        if let Some(Target::Atomic { tmp, .. }) = &self.target {
            unregister(tmp.path());
        }
    }
}

/// Write `bytes` to `path` as one [`Output`].
pub fn write_file(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut out = Output::create(path)?;
    out.write_all(bytes)?;
    out.finish()
}

/// Fail now, not after a long computation, if `path` cannot be written: for a regular
/// file (or nothing yet) its directory must exist and a temp file must be creatable there;
/// a directory is refused (`Is a directory`); a FIFO or device is not opened here (opening
/// a FIFO waits for its reader).
pub fn check_writable(path: &Path) -> io::Result<()> {
    match resolve(path)? {
        // A rename needs only the directory's permission, not the old file's.
        Resolved::Regular(dest, _) => temp_in(parent_of(&dest)).map(drop),
        Resolved::Direct(p) => {
            if fs::metadata(&p)?.is_dir() {
                Err(io::Error::new(
                    io::ErrorKind::IsADirectory,
                    "is a directory (give a file name)",
                ))
            } else {
                Ok(())
            }
        }
    }
}

/// Refuse to write `output` when it is one of `inputs` (each `(option, path)`): the same
/// file once links are followed (same device and inode). Nothing there yet is never an
/// input. The error names both options.
pub fn check_not_input(output: (&str, &Path), inputs: &[(&str, &Path)]) -> Result<(), String> {
    for (option, input) in inputs {
        if same_file(output.1, input) {
            return Err(format!(
                "{} {}: is the same file as {option} {} (refusing to overwrite an input)",
                output.0,
                output.1.display(),
                input.display()
            ));
        }
    }
    Ok(())
}

/// Whether `a` and `b` name the same existing file (links followed).
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (fs::metadata(a), fs::metadata(b)) {
        #[cfg(unix)]
        (Ok(ma), Ok(mb)) => {
            use std::os::unix::fs::MetadataExt;
            ma.dev() == mb.dev() && ma.ino() == mb.ino()
        }
        #[cfg(not(unix))]
        (Ok(_), Ok(_)) => match (fs::canonicalize(a), fs::canonicalize(b)) {
            (Ok(ca), Ok(cb)) => ca == cb,
            _ => false,
        },
        _ => false,
    }
}

/// For a default output path (one the user did not type, such as `results/<commit>.json`):
/// create its directory if it is missing, one level only, as the tool's own place for
/// results. A path the user typed never gets a directory created.
///
/// A directory made here is remembered: [`remove_pending`] (an interrupted run) removes
/// it again if it is still empty, so that a run stopped before it wrote anything leaves
/// no trace.
pub fn create_default_dir(path: &Path) -> io::Result<()> {
    let dir = parent_of(path);
    match fs::create_dir(dir) {
        Ok(()) => {
            if let Ok(mut made) = MADE_DIRS.lock() {
                made.push(dir.to_path_buf());
            }
            Ok(())
        }
        Err(e) if e.kind() != io::ErrorKind::AlreadyExists => Err(e),
        _ => Ok(()),
    }
}

/// Directories [`create_default_dir`] made in this process.
static MADE_DIRS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Delete every temp file not yet renamed into place, then every directory this process
/// made for a default output ([`create_default_dir`]) that is still empty. For signal
/// handlers: the process is about to die and its [`Output`]s will never be dropped.
pub fn remove_pending() {
    let pending = match PENDING.lock() {
        Ok(p) => p,
        Err(poisoned) => poisoned.into_inner(),
    };
    for path in pending.iter() {
        let _ = fs::remove_file(path);
    }
    let made = match MADE_DIRS.lock() {
        Ok(m) => m,
        Err(poisoned) => poisoned.into_inner(),
    };
    for dir in made.iter() {
        // remove_dir removes only an empty directory: one holding a file stays.
        let _ = fs::remove_dir(dir);
    }
}

fn register(path: &Path) {
    if let Ok(mut p) = PENDING.lock() {
        p.push(path.to_path_buf());
    }
}

fn unregister(path: &Path) {
    if let Ok(mut p) = PENDING.lock() {
        p.retain(|q| q != path);
    }
}

/// A temp file in `dir` (which must exist) whose mode is 0666 minus the umask.
fn temp_in(dir: &Path) -> io::Result<NamedTempFile> {
    match fs::metadata(dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => {
            return Err(io::Error::new(
                io::ErrorKind::NotADirectory,
                format!("{} is not a directory", dir.display()),
            ));
        }
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!(
                    "directory {} does not exist (it is not created: make it first)",
                    dir.display()
                ),
            ));
        }
        Err(e) => return Err(e),
    }
    let mut builder = tempfile::Builder::new();
    builder.prefix(TEMP_PREFIX).suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        // Passed to open(2), which applies the umask: the mode a plain create would get.
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    // tempfile's error names the temp file it tried, which the user never typed: name the
    // directory instead.
    builder.tempfile_in(dir).map_err(|e| {
        let mut why = e.to_string();
        if let Some(at) = why.find(" at path ") {
            why.truncate(at);
        }
        io::Error::new(
            e.kind(),
            format!("cannot create a file in directory {}: {why}", dir.display()),
        )
    })
}

fn parent_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// Follow `path` through symlinks by hand, so that a dangling link's target is created
/// (not the link replaced).
fn resolve(path: &Path) -> io::Result<Resolved> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                // Ask the kernel first: /proc/self/fd/N links name things like "pipe:[7]"
                // that exist only behind the link.
                if let Ok(target) = fs::metadata(&p) {
                    return Ok(if target.is_file() {
                        Resolved::Regular(fs::canonicalize(&p)?, Some(target))
                    } else {
                        Resolved::Direct(p)
                    });
                }
                let link = fs::read_link(&p)?;
                p = parent_of(&p).join(link);
            }
            Ok(m) if m.is_file() => return Ok(Resolved::Regular(p, Some(m))),
            // A directory lands here too, and opening it for writing reports EISDIR.
            Ok(_) => return Ok(Resolved::Direct(p)),
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Resolved::Regular(p, None)),
            Err(e) => return Err(e),
        }
    }
    Err(io::Error::other(
        "too many levels of symbolic links (more than 40)",
    ))
}

/// Terminals, pipes and character devices cannot be synced (EINVAL); that is not an error.
fn ignore_unsyncable(e: io::Error) -> io::Result<()> {
    if e.kind() == io::ErrorKind::InvalidInput {
        Ok(())
    } else {
        Err(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh directory holding one file, `name`, with `contents`; the directory and the
    /// file's path.
    fn dir_with_file(name: &str, contents: &str) -> (tempfile::TempDir, PathBuf) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(name);
        fs::write(&path, contents).unwrap();
        (dir, path)
    }

    #[test]
    fn replaces_a_regular_file_by_rename_and_leaves_no_temp() {
        let (dir, path) = dir_with_file("out.json", "old");
        // A hard link to the old file still sees the old bytes after a rename.
        let link = dir.path().join("old-link");
        fs::hard_link(&path, &link).unwrap();
        write_file(&path, b"new").unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "new");
        assert_eq!(fs::read_to_string(&link).unwrap(), "old");
        let names: Vec<_> = fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names.len(), 2, "{names:?}");
    }

    /// Issue 17: a directory given as the file (`TORUS_CULL_RESULTS=DIR cargo bench`,
    /// `run --out DIR`) and a missing parent are found before any work, and nothing is
    /// created.
    #[test]
    fn a_directory_or_a_missing_parent_is_refused_before_the_work() {
        let dir = tempfile::tempdir().unwrap();
        let e = check_writable(dir.path()).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::IsADirectory, "{e}");
        // Through a symlink too.
        #[cfg(unix)]
        {
            let link = dir.path().join("link");
            std::os::unix::fs::symlink(dir.path(), &link).unwrap();
            assert!(check_writable(&link).is_err());
        }
        let nested = dir.path().join("a").join("b.json");
        let e = check_writable(&nested).unwrap_err();
        assert!(e.to_string().contains("does not exist"), "{e}");
        assert!(write_file(&nested, b"x").is_err());
        assert!(!dir.path().join("a").exists());
        // A default path's own directory is made, one level only.
        create_default_dir(&nested).unwrap();
        check_writable(&nested).unwrap();
        assert!(create_default_dir(&dir.path().join("c").join("d").join("e.json")).is_err());
    }

    #[test]
    fn an_input_is_not_an_output() {
        let (dir, input) = dir_with_file("in.csv", "x");
        let same = dir.path().join(".").join("in.csv");
        let e = check_not_input(("--out", &same), &[("--rays", &input)]).unwrap_err();
        assert!(e.contains("--out") && e.contains("--rays"), "{e}");
        let other = dir.path().join("out.csv");
        check_not_input(("--out", &other), &[("--rays", &input)]).unwrap();
    }

    #[test]
    fn an_unfinished_output_leaves_the_old_file_and_no_temp() {
        let (dir, path) = dir_with_file("out.csv", "old");
        {
            let mut out = Output::create(&path).unwrap();
            out.write_all(b"half").unwrap();
            assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
        }
        assert_eq!(fs::read_to_string(&path).unwrap(), "old");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    /// Asserts that `path` is still a symbolic link (not replaced by a regular file).
    #[cfg(unix)]
    #[track_caller]
    fn assert_is_symlink(path: &Path) {
        assert!(
            fs::symlink_metadata(path).unwrap().file_type().is_symlink(),
            "{} is no longer a symlink",
            path.display()
        );
    }

    #[cfg(unix)]
    #[test]
    fn follows_symlinks_and_keeps_the_link() {
        let (dir, real) = dir_with_file("real.svg", "old");
        let link = dir.path().join("link.svg");
        std::os::unix::fs::symlink("real.svg", &link).unwrap();
        write_file(&link, b"new").unwrap();
        assert_is_symlink(&link);
        assert_eq!(fs::read_to_string(&real).unwrap(), "new");
        // A dangling link: its target is created.
        let dangling = dir.path().join("dangling");
        std::os::unix::fs::symlink("made.json", &dangling).unwrap();
        write_file(&dangling, b"made").unwrap();
        assert_is_symlink(&dangling);
        assert_eq!(
            fs::read_to_string(dir.path().join("made.json")).unwrap(),
            "made"
        );
    }

    #[cfg(unix)]
    #[test]
    fn modes_follow_the_umask_and_the_replaced_file() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("new.json");
        write_file(&path, b"x").unwrap();
        let mode = fs::metadata(&path).unwrap().permissions().mode() & 0o777;
        // Whatever the umask, a new file is readable by the group unless the umask says not
        // (tempfile's default would be 0600).
        let umask = current_umask();
        assert_eq!(mode, 0o666 & !umask, "umask {umask:o}");
        fs::set_permissions(&path, fs::Permissions::from_mode(0o640)).unwrap();
        write_file(&path, b"y").unwrap();
        assert_eq!(
            fs::metadata(&path).unwrap().permissions().mode() & 0o777,
            0o640
        );
    }

    /// The umask, read from /proc (Linux); 022 elsewhere.
    #[cfg(unix)]
    fn current_umask() -> u32 {
        fs::read_to_string("/proc/self/status")
            .ok()
            .and_then(|s| {
                s.lines()
                    .find_map(|l| l.strip_prefix("Umask:"))
                    .and_then(|v| u32::from_str_radix(v.trim(), 8).ok())
            })
            .unwrap_or(0o022)
    }

    #[cfg(unix)]
    #[test]
    fn non_regular_files_are_written_in_place_and_errors_reported() {
        use std::os::unix::fs::FileTypeExt;
        let dir = tempfile::tempdir().unwrap();
        if Path::new("/dev/full").exists() {
            // Through a link of our own: a broken build can only replace the link.
            let full = dir.path().join("full");
            std::os::unix::fs::symlink("/dev/full", &full).unwrap();
            let e = write_file(&full, &[0u8; 1 << 16]).unwrap_err();
            assert_eq!(e.raw_os_error(), Some(28), "{e}"); // ENOSPC
            assert_is_symlink(&full);
        }
        // A FIFO stays a FIFO, and its reader gets the bytes.
        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            let reader = {
                let fifo = fifo.clone();
                std::thread::spawn(move || fs::read_to_string(fifo).unwrap())
            };
            write_file(&fifo, b"through the pipe").unwrap();
            assert_eq!(reader.join().unwrap(), "through the pipe");
            assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
        }
    }
}
