//! VCD streaming: waveforms written while the simulation runs, never held in memory.
//!
//! Opened through [`Driver::stream_vcd`](crate::Driver::stream_vcd). Uses rust-hdl's public
//! `write_vcd_header` / `write_vcd_dump` / `write_vcd_change`, so every signal of the design
//! appears under its hierarchical name (`uut.stage2.q`...). The header is always written; value
//! changes only for the cycles inside the requested window, the first of them as a full
//! `$dumpvars` so the window starts with every value known.
//!
//! rust-hdl's VCD writer panics on I/O errors; the file is therefore wrapped in a writer that
//! never fails but remembers the first error, reported by [`Driver::finish_vcd`](crate::Driver::finish_vcd).
//!
//! Waveforms of tests go under `waveforms/` at the workspace root (git ignores `*.vcd` there):
//! use [`waveform_path`].

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::ops::{Bound, RangeBounds};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

use rust_hdl::core::prelude::{write_vcd_change, write_vcd_dump, write_vcd_header, Block};
use rust_hdl::core::vcd_probe::VCDProbe;

use crate::{Error, Result};

/// Length of one clock cycle in the VCD (rust-hdl writes a 1 ps timescale): cycle `c` starts at
/// `c * CYCLE_PS` with the inputs applied and the clock low; the clock rises half a cycle later.
pub const CYCLE_PS: u64 = 1000;

/// `waveforms/<name>.vcd` at the workspace root, the default place for test waveforms.
pub fn waveform_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("waveforms").join(format!("{name}.vcd"))
}

/// A file that never reports a write error to rust-hdl's VCD writer (which would panic) but
/// keeps the first one for [`VcdStream::finish`]. Sits under a `BufWriter`, so it sees only
/// large writes.
struct LatchingFile {
    file: File,
    error: Arc<Mutex<Option<io::Error>>>,
}

impl LatchingFile {
    fn latch(&self, result: io::Result<()>) {
        if let Err(e) = result {
            self.error.lock().unwrap_or_else(PoisonError::into_inner).get_or_insert(e);
        }
    }
}

impl Write for LatchingFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let result = self.file.write_all(buf);
        self.latch(result);
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        let result = self.file.flush();
        self.latch(result);
        Ok(())
    }
}

/// An open VCD stream (see the [module docs](self)).
pub(crate) struct VcdStream {
    probe: Option<VCDProbe<BufWriter<LatchingFile>>>,
    path: PathBuf,
    error: Arc<Mutex<Option<io::Error>>>,
    from: u64,
    to: Option<u64>,
    dumped: bool,
}

impl VcdStream {
    /// Creates the file and writes the header of `uut`'s hierarchy.
    pub(crate) fn create(path: &Path, uut: &dyn Block, window: impl RangeBounds<u64>) -> Result<Self> {
        let io_err = |e: io::Error| Error::new(format!("cannot create VCD {}: {e}", path.display()));
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(io_err)?;
        }
        let file = File::create(path).map_err(io_err)?;
        let error = Arc::new(Mutex::new(None));
        let writer = BufWriter::with_capacity(1 << 16, LatchingFile { file, error: error.clone() });
        let from = match window.start_bound() {
            Bound::Included(&c) => c,
            Bound::Excluded(&c) => c + 1,
            Bound::Unbounded => 0,
        };
        let to = match window.end_bound() {
            Bound::Included(&c) => Some(c + 1),
            Bound::Excluded(&c) => Some(c),
            Bound::Unbounded => None,
        };
        Ok(Self {
            probe: Some(write_vcd_header(writer, uut)),
            path: path.to_owned(),
            error,
            from,
            to,
            dumped: false,
        })
    }

    /// Writes the values of `cycle`, before or after its rising edge, if the cycle is inside the
    /// window.
    pub(crate) fn sample(&mut self, uut: &dyn Block, cycle: u64, after_edge: bool) {
        if cycle < self.from || self.to.is_some_and(|to| cycle >= to) {
            return;
        }
        if let Some(mut probe) = self.probe.take() {
            let time = cycle * CYCLE_PS + if after_edge { CYCLE_PS / 2 } else { 0 };
            // Errors of the underlying file are latched by `LatchingFile`; the `vcd` crate's
            // own formatting into a `BufWriter` cannot fail otherwise.
            let _ = probe.timestamp(time);
            probe = if self.dumped {
                write_vcd_change(probe, uut)
            } else {
                self.dumped = true;
                write_vcd_dump(probe, uut)
            };
            self.probe = Some(probe);
        }
    }

    /// Flushes and closes the file; returns its path or the first write error.
    pub(crate) fn finish(mut self) -> Result<PathBuf> {
        // Dropping the probe drops its `BufWriter`, which flushes into the latching file.
        drop(self.probe.take());
        match self.error.lock().unwrap_or_else(PoisonError::into_inner).take() {
            Some(e) => Err(Error::new(format!("writing VCD {} failed: {e}", self.path.display()))),
            None => Ok(self.path),
        }
    }
}
