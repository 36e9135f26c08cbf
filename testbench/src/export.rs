//! Verilog export of every RTL block, for FPGA flows: one file per block, its top module named
//! after the block, plus a file list. `shelling export-verilog --out DIR` writes them; the copies
//! committed under `hdl/verilog/` are checked against a fresh export by the test suite.

use crate::replay::export_verilog;
use crate::{Error, Result};
use rust_hdl::core::prelude::Block;
use shelling_hdl::arbiter::{MemoryArbiter, MAX_PES};
use shelling_hdl::cache::PatchCache;
use shelling_hdl::intersection::IntersectionUnit;
use shelling_hdl::loader::PatchLoader;
use shelling_hdl::machine::Machine;
use shelling_hdl::pe::ProcessingElement;
use shelling_hdl::prim::Fifo;
use shelling_hdl::queue::JobQueue;
use shelling_hdl::screener::Screener;
use std::path::{Path, PathBuf};

/// Name of the file list written beside the Verilog files.
pub const FILE_LIST: &str = "files.f";

/// The FIFO block exported on its own, for its cross-simulation and its formal task
/// (`hdl/src/fifo.sby`): 16 words of 8 bits.
pub type FwftFifo = Fifo<8, 4, 5>;

/// The memory arbiter exported on its own, for its cross-simulation, its formal task
/// (`hdl/src/arbiter.sby`) and its resources: four PEs.
pub type MemoryArbiter4 = MemoryArbiter<4>;

/// The machine exported for its cross-simulation and the FPGA flow: two PEs (each PE's Verilog
/// is written once per instance, so every PE adds the processing element's whole text).
pub type Machine2 = Machine<2>;

/// The blocks exported, by module name, each freshly built and connected.
pub fn blocks() -> Vec<(&'static str, Box<dyn Block>)> {
    let mut iu = IntersectionUnit::default();
    iu.connect_all();
    let mut loader = PatchLoader::default();
    loader.connect_all();
    let mut cache = PatchCache::default();
    cache.connect_all();
    let mut screener = Screener::default();
    screener.connect_all();
    let mut pe = ProcessingElement::default();
    pe.connect_all();
    let mut fifo = FwftFifo::default();
    fifo.connect_all();
    let mut queue = JobQueue::default();
    queue.connect_all();
    let mut arbiter = MemoryArbiter4::default();
    arbiter.connect_all();
    let mut machine = Machine2::default();
    machine.connect_all();
    vec![
        ("patch_loader", Box::new(loader)),
        ("patch_cache", Box::new(cache)),
        ("screener", Box::new(screener)),
        ("intersection_unit", Box::new(iu)),
        ("processing_element", Box::new(pe)),
        ("fwft_fifo", Box::new(fifo)),
        ("job_queue", Box::new(queue)),
        ("memory_arbiter", Box::new(arbiter)),
        ("machine", Box::new(machine)),
    ]
}

/// The exported text of every block: `(file name, Verilog)`, in a fixed order.
pub fn verilog() -> Result<Vec<(String, String)>> {
    blocks().into_iter().map(|(name, block)| file(name, block.as_ref())).collect()
}

/// One block's file: `(name.v, Verilog)`.
fn file(name: &str, block: &dyn Block) -> Result<(String, String)> {
    let text = export_verilog(block, name).map_err(|e| e.context(name))?;
    Ok((
        format!("{name}.v"),
        format!("// {name}: exported from rust-hdl by `shelling export-verilog`; do not edit.\n{text}"),
    ))
}

/// The name of the block [`machine_verilog`] exports for `pes` PEs.
pub fn machine_block(pes: usize) -> String {
    format!("machine_{pes}")
}

/// The PEs of a block named as [`machine_block`] names it (`machine_6`: 6), if it is one.
pub fn machine_block_pes(block: &str) -> Option<usize> {
    block.strip_prefix("machine_")?.parse().ok().filter(|n| (1..=MAX_PES).contains(n))
}

/// The machine of `pes` PEs (1 to [`MAX_PES`]) as the block `machine_{pes}`: `(file name,
/// Verilog)`. For the FPGA flow's machine of more PEs than the committed two-PE `machine`; not
/// committed (every PE adds the processing element's whole text, half a megabyte).
pub fn machine_verilog(pes: usize) -> Result<(String, String)> {
    // The machine's block is built on the stack (eight PEs are tens of megabytes of it): on a
    // thread of its own, with room for it.
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(move || machine_verilog_here(pes))
        .map_err(|e| Error::new(format!("a thread to export the machine: {e}")))?
        .join()
        .map_err(|_| Error::new("exporting the machine panicked"))?
}

fn machine_verilog_here(pes: usize) -> Result<(String, String)> {
    macro_rules! export {
        ($($n:literal)*) => {
            match pes {
                $($n => {
                    let mut m = Machine::<$n>::default();
                    m.connect_all();
                    file(&machine_block(pes), &m)
                })*
                _ => Err(Error::new(format!("a machine has 1 to {MAX_PES} PEs, not {pes}"))),
            }
        };
    }
    export!(1 2 3 4 5 6 7 8)
}
const _: () = assert!(MAX_PES == 8, "machine_verilog lists the machines of 1 to 8 PEs");

/// FNV-1a, 64 bits, of `bytes`: a hash stable across platforms and releases (unlike the
/// standard library's hashers), for naming what a result was computed from.
pub fn fnv1a64(bytes: impl IntoIterator<Item = u8>) -> u64 {
    bytes.into_iter().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3))
}

/// The hash of an export, `(file name, Verilog)` as [`verilog`] gives it: [`fnv1a64`] of every
/// file's name and text in order, each followed by a NUL byte, as 16 hex digits. An FPGA result
/// records it, so that a test can tell whether the committed Verilog is still what was measured.
pub fn hash(files: &[(String, String)]) -> String {
    let bytes = files.iter().flat_map(|(n, t)| n.bytes().chain([0]).chain(t.bytes()).chain([0]));
    format!("{:016x}", fnv1a64(bytes))
}

/// The files of an export in `dir` (as [`write`](fn@write) leaves them), in the order of its file list.
pub fn read(dir: &Path) -> Result<Vec<(String, String)>> {
    let io = |e: std::io::Error, p: &Path| Error::new(format!("reading {}: {e}", p.display()));
    let list = dir.join(FILE_LIST);
    let names = std::fs::read_to_string(&list).map_err(|e| io(e, &list))?;
    names
        .lines()
        .map(|n| {
            let p = dir.join(n);
            Ok((n.to_string(), std::fs::read_to_string(&p).map_err(|e| io(e, &p))?))
        })
        .collect()
}

/// Writes every block and the file list into `dir` (created if missing); returns the paths.
pub fn write(dir: &Path) -> Result<Vec<PathBuf>> {
    let io = |e: std::io::Error, p: &Path| Error::new(format!("writing {}: {e}", p.display()));
    std::fs::create_dir_all(dir).map_err(|e| io(e, dir))?;
    let mut paths = Vec::new();
    let files = verilog()?;
    for (name, text) in &files {
        let p = dir.join(name);
        std::fs::write(&p, text).map_err(|e| io(e, &p))?;
        paths.push(p);
    }
    let list = dir.join(FILE_LIST);
    let body: String = files.iter().map(|(n, _)| format!("{n}\n")).collect();
    std::fs::write(&list, body).map_err(|e| io(e, &list))?;
    paths.push(list);
    Ok(paths)
}
