//! Files written atomically: every output goes to a temporary file beside its final name and
//! is renamed into place only when complete, so a failed run (a full disk, a file-size limit)
//! never leaves a truncated file under an output's name.

use crate::report::error::{io_err, Result};
use std::fs;
use std::path::{Path, PathBuf};

/// A temporary path beside `path`, in the same folder (so a rename is atomic), keeping its
/// extension (plotters picks the image format from it): `.<stem>.<pid>.tmp.<ext>`.
fn temporary_beside(path: &Path) -> PathBuf {
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("output");
    let ext = path.extension().and_then(|s| s.to_str()).unwrap_or("tmp");
    path.with_file_name(format!(".{stem}.{}.tmp.{ext}", std::process::id()))
}

/// Produces `path` atomically: `make` writes a temporary file beside it, which is renamed
/// over `path` only if `make` succeeded; on failure the temporary file is removed, so a
/// failed run (a full disk, a file-size limit) never leaves a truncated file under an
/// output's name.
pub(crate) fn produce(path: &Path, make: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    let tmp = temporary_beside(path);
    let slot = interrupt::register(&tmp);
    let result = make(&tmp).and_then(|()| fs::rename(&tmp, path).map_err(io_err(path)));
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    interrupt::release(slot);
    result
}

/// Removing the temporary files of a run stopped by Ctrl-C ([`remove_temporaries_on_interrupt`]).
mod interrupt {
    use std::path::Path;
    #[cfg(target_os = "linux")]
    use std::sync::atomic::{AtomicPtr, Ordering};

    /// Temporary files being written at once, at most (more are written, but not removed on
    /// an interrupt: the run's threads number far fewer).
    #[cfg(target_os = "linux")]
    const SLOTS: usize = 256;

    /// The paths (NUL-terminated, leaked: a handler may read one while its writer finishes)
    /// of the temporary files being written.
    #[cfg(target_os = "linux")]
    static LIVE: [AtomicPtr<libc::c_char>; SLOTS] =
        [const { AtomicPtr::new(std::ptr::null_mut()) }; SLOTS];

    /// Records `tmp` as being written; the slot to release.
    pub(super) fn register(tmp: &Path) -> Option<usize> {
        #[cfg(target_os = "linux")]
        {
            use std::os::unix::ffi::OsStrExt;
            let c = std::ffi::CString::new(tmp.as_os_str().as_bytes()).ok()?;
            let ptr = c.into_raw();
            for (k, slot) in LIVE.iter().enumerate() {
                if slot
                    .compare_exchange(
                        std::ptr::null_mut(),
                        ptr,
                        Ordering::SeqCst,
                        Ordering::SeqCst,
                    )
                    .is_ok()
                {
                    return Some(k);
                }
            }
            None
        }
        #[cfg(not(target_os = "linux"))]
        {
            let _ = tmp;
            None
        }
    }

    /// The file of `slot` is renamed or removed.
    pub(super) fn release(slot: Option<usize>) {
        #[cfg(target_os = "linux")]
        if let Some(k) = slot {
            LIVE[k].store(std::ptr::null_mut(), Ordering::SeqCst);
        }
        #[cfg(not(target_os = "linux"))]
        let _ = slot;
    }

    /// The handler: unlinks every live temporary file (`unlink` is async-signal-safe), then
    /// dies of the signal as it would have.
    #[cfg(target_os = "linux")]
    extern "C" fn on_signal(signal: libc::c_int) {
        for slot in &LIVE {
            let ptr = slot.load(Ordering::SeqCst);
            if !ptr.is_null() {
                // SAFETY: a registered pointer is a leaked, never-freed NUL-terminated path
                unsafe {
                    libc::unlink(ptr);
                }
            }
        }
        // SAFETY: restoring the default action and re-raising are async-signal-safe
        unsafe {
            libc::signal(signal, libc::SIG_DFL);
            libc::raise(signal);
        }
    }

    pub(super) fn install() {
        #[cfg(target_os = "linux")]
        // SAFETY: the handler only unlinks and re-raises (async-signal-safe calls)
        unsafe {
            let handler = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
            libc::signal(libc::SIGINT, handler);
            libc::signal(libc::SIGTERM, handler);
        }
    }
}

/// Makes Ctrl-C (SIGINT) and SIGTERM remove the temporary files being written before the
/// process stops, so an interrupted run leaves neither a truncated output nor a temporary
/// file (Linux; elsewhere a no-op). The `splinelab` program calls it first.
pub fn remove_temporaries_on_interrupt() {
    interrupt::install();
}

/// Writes `bytes` to `path` atomically (see [`produce`]), flushing them to the file first.
pub(crate) fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    produce(path, |tmp| {
        let mut file = fs::File::create(tmp).map_err(io_err(path))?;
        std::io::Write::write_all(&mut file, bytes).map_err(io_err(path))?;
        file.sync_all().map_err(io_err(path))
    })
}
