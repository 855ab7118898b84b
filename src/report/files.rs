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
    let result = make(&tmp).and_then(|()| fs::rename(&tmp, path).map_err(io_err(path)));
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// Writes `bytes` to `path` atomically (see [`produce`]), flushing them to the file first.
pub(crate) fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    produce(path, |tmp| {
        let mut file = fs::File::create(tmp).map_err(io_err(path))?;
        std::io::Write::write_all(&mut file, bytes).map_err(io_err(path))?;
        file.sync_all().map_err(io_err(path))
    })
}
