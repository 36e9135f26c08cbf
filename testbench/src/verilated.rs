//! The processing element as a compiled simulation: its exported Verilog built by Verilator
//! into a shared library, loaded at run time and stepped through [`PeSim`] by the same host
//! loop ([`crate::pe::run`]) as rust-hdl's simulation, cycle for cycle the same.
//!
//! # Why
//!
//! rust-hdl's simulator settles the whole PE several times per clock through dynamic dispatch
//! over every signal (about 40k cycles a second on one core). Verilator turns the same Verilog
//! into straight-line C++ that evaluates each clock once: the paper's full workload becomes a
//! matter of seconds. What it cannot do is stream a VCD or record ports; use the
//! [`Driver`](crate::Driver) for those.
//!
//! # What is trusted
//!
//! The compiled model is the exported Verilog, not the rust-hdl block, and rust-hdl's Verilog
//! can disagree with its own simulation (rung 4 of the equivalence ladder exists for that). The
//! PE's rung-4 replays check the Verilog against rust-hdl port by port on every cycle, under
//! Verilator among others; `tests/cosim.rs` runs whole sources on both simulators and compares
//! hits, counters and cycles.
//!
//! # Building
//!
//! [`VerilatedPe::new`] exports the PE's Verilog afresh, writes the C glue from
//! [`INPUT_PORTS`] and [`OUTPUT_PORTS`] (after [`check_ports`]) and runs
//! `verilator --cc --exe --build` (about 15 s on two cores). The library is cached under
//! [`cache_dir`], keyed by a hash of the Verilog, the glue, Verilator's version and its
//! arguments, so later
//! runs and processes load it at once; a build is made in a scratch folder and renamed into
//! place, so concurrent builders never see half a library. The library stays loaded for the
//! life of the process.
//!
//! Each model has a `VerilatedContext` of its own, so models share no state: a `VerilatedPe` may
//! move to another thread (`Send`; the machine's `Composed::threaded` steps half its PEs on a
//! second one), but is used by one thread at a time (not `Sync`).

use crate::pe_sim::{check_ports, PeInputs, PeOutputs, PeSim, INPUT_PORTS, OUTPUT_PORTS};
use crate::replay::{export_verilog, run_tool};
use crate::{Error, Result};
use libloading::Library;
use rust_hdl::core::prelude::Block;
use shelling_hdl::pe::ProcessingElement;
use std::ffi::c_void;
use std::fmt::Write as _;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The exported PE's module name.
const PE: &str = "processing_element";
/// The compiled model's top: a wrapper whose ports are the PE's with an `i_` or `o_` in front,
/// so that none is a C++ keyword (Verilator renames those: the PE's `near`).
const TOP: &str = "shelling_pe";
/// The environment variable that overrides [`cache_dir`].
pub const CACHE_ENV: &str = "SHELLING_VERILATED_DIR";

/// Whether `verilator` runs here (`verilator --version`): the compiled PE can be tried.
pub fn available() -> bool {
    std::process::Command::new("verilator").arg("--version").output().is_ok_and(|o| o.status.success())
}

/// Where compiled models are kept: `$SHELLING_VERILATED_DIR`, else `shelling-verilated` in
/// the system's temporary folder.
pub fn cache_dir() -> PathBuf {
    std::env::var_os(CACHE_ENV)
        .map(PathBuf::from)
        .unwrap_or_else(|| std::env::temp_dir().join("shelling-verilated"))
}

type NewFn = unsafe extern "C" fn() -> *mut c_void;
type FreeFn = unsafe extern "C" fn(*mut c_void);
type DriveFn = unsafe extern "C" fn(*mut c_void, *const u64, *mut u64);
type TickFn = unsafe extern "C" fn(*mut c_void, *mut u64);

/// The compiled model's entry points, from a library loaded for good.
#[derive(Clone, Copy)]
struct Api {
    new: NewFn,
    free: FreeFn,
    drive: DriveFn,
    tick: TickFn,
}

/// The library loaded by this process, if any.
static LOADED: Mutex<Option<Api>> = Mutex::new(None);

/// A processing element simulated by Verilator (see the [module documentation](self)), fresh
/// from power-up: every register and memory zero, as in rust-hdl's simulation.
pub struct VerilatedPe {
    api: Api,
    model: *mut c_void,
    inputs: PeInputs,
    outputs: PeOutputs,
    cycles: u64,
}

impl VerilatedPe {
    /// Builds the compiled model if [`cache_dir`] does not hold it yet, loads it and makes a
    /// PE. The error names what is missing (Verilator, a C++ compiler) or what failed.
    pub fn new() -> Result<Self> {
        let api = load()?;
        // SAFETY: `new` is the glue's constructor: it takes nothing and returns a fresh model
        // (or null if C++ could not make one).
        let model = unsafe { (api.new)() };
        if model.is_null() {
            return Err(Error::new("the compiled PE model could not be constructed"));
        }
        let mut pe =
            Self { api, model, inputs: PeInputs::default(), outputs: PeOutputs::default(), cycles: 0 };
        pe.drive(|_| {})?;
        Ok(pe)
    }

    fn words(&self) -> [u64; OUTPUT_PORTS.len()] {
        [0; OUTPUT_PORTS.len()]
    }
}

impl Drop for VerilatedPe {
    fn drop(&mut self) {
        // SAFETY: `model` came from `new` of the same library, which stays loaded, and is freed
        // once.
        unsafe { (self.api.free)(self.model) }
    }
}

// SAFETY: the model is a heap object that this value alone points to, with its own
// `VerilatedContext` (the glue's `pe_new`): nothing of it is shared with another model or
// bound to the thread that made it, and `&mut self` gives one thread at a time its use.
unsafe impl Send for VerilatedPe {}

impl PeSim for VerilatedPe {
    fn drive(&mut self, set: impl FnOnce(&mut PeInputs)) -> Result<()> {
        set(&mut self.inputs);
        let inputs = self.inputs.to_words();
        let mut out = self.words();
        // SAFETY: the glue reads `INPUT_PORTS.len()` words and writes `OUTPUT_PORTS.len()`,
        // the arrays' lengths (both generated from the same table).
        unsafe { (self.api.drive)(self.model, inputs.as_ptr(), out.as_mut_ptr()) };
        self.outputs = PeOutputs::from_words(&out);
        Ok(())
    }

    fn tick(&mut self) -> Result<()> {
        let mut out = self.words();
        // SAFETY: as in `drive`.
        unsafe { (self.api.tick)(self.model, out.as_mut_ptr()) };
        self.outputs = PeOutputs::from_words(&out);
        self.cycles += 1;
        Ok(())
    }

    fn outputs(&self) -> PeOutputs {
        self.outputs
    }

    fn cycles(&self) -> u64 {
        self.cycles
    }
}

/// Loads the compiled model, building it first if needed (once per process).
fn load() -> Result<Api> {
    let mut loaded = LOADED.lock().map_err(|_| Error::new("an earlier build of the compiled PE panicked"))?;
    if let Some(api) = *loaded {
        return Ok(api);
    }
    let lib = build(&cache_dir())?;
    // SAFETY: the library is the glue just built or found under its content hash; loading it
    // runs Verilator's static constructors only.
    let lib = unsafe { Library::new(&lib) }
        .map_err(|e| Error::new(format!("loading the compiled PE {}: {e}", lib.display())))?;
    let lib: &'static Library = Box::leak(Box::new(lib));
    fn symbol<T: Copy>(lib: &'static Library, name: &str) -> Result<T> {
        // SAFETY: the glue defines each symbol with the type asked for here.
        unsafe { lib.get::<T>(name.as_bytes()) }
            .map(|s| *s)
            .map_err(|e| Error::new(format!("the compiled PE lacks `{name}`: {e}")))
    }
    let api = Api {
        new: symbol(lib, "pe_new")?,
        free: symbol(lib, "pe_free")?,
        drive: symbol(lib, "pe_drive")?,
        tick: symbol(lib, "pe_tick")?,
    };
    *loaded = Some(api);
    Ok(api)
}

/// The Verilog wrapper [`TOP`] around the PE.
fn wrapper() -> String {
    let decl = |dir: &str, p: char, &(name, width): &(&str, usize)| {
        let range = if width > 1 { format!("[{}:0] ", width - 1) } else { String::new() };
        format!("    {dir} wire {range}{p}_{name},\n")
    };
    let conn = |p: char, &(name, _): &(&str, usize)| format!(",\n        .{name}({p}_{name})");
    let mut s = format!("// Generated by shelling-testbench (verilated.rs).\nmodule {TOP}(\n");
    INPUT_PORTS.iter().for_each(|p| s.push_str(&decl("input", 'i', p)));
    OUTPUT_PORTS.iter().for_each(|p| s.push_str(&decl("output", 'o', p)));
    let _ = write!(s, "    input wire clock\n);\n    {PE} pe(\n        .clock(clock)");
    INPUT_PORTS.iter().for_each(|p| s.push_str(&conn('i', p)));
    OUTPUT_PORTS.iter().for_each(|p| s.push_str(&conn('o', p)));
    s.push_str("\n    );\nendmodule\n");
    s
}

/// The C++ glue between the port table and Verilator's model class.
fn glue() -> String {
    let class = format!("V{TOP}");
    let mut s = format!(
        "// Generated by shelling-testbench (verilated.rs): the PE's ports as arrays of words.\n\
         #include \"{class}.h\"\n#include \"verilated.h\"\n#include <cstdint>\n\n\
         static void read({class}* t, uint64_t* out) {{\n"
    );
    for (k, (name, _)) in OUTPUT_PORTS.iter().enumerate() {
        let _ = writeln!(s, "    out[{k}] = t->o_{name};");
    }
    s.push_str("}\n\nextern \"C\" {\n");
    let _ = write!(
        s,
        "void* pe_new() {{\n    auto* t = new {class}{{new VerilatedContext}};\n    t->clock = 0;\n    t->eval();\n    return t;\n}}\n\n\
         void pe_free(void* p) {{\n    auto* t = static_cast<{class}*>(p);\n    auto* c = t->contextp();\n    t->final();\n    delete t;\n    delete c;\n}}\n\n\
         void pe_drive(void* p, const uint64_t* in, uint64_t* out) {{\n    auto* t = static_cast<{class}*>(p);\n    t->clock = 0;\n"
    );
    for (k, (name, _)) in INPUT_PORTS.iter().enumerate() {
        let _ = writeln!(s, "    t->i_{name} = in[{k}];");
    }
    let _ = write!(
        s,
        "    t->eval();\n    read(t, out);\n}}\n\n\
         void pe_tick(void* p, uint64_t* out) {{\n    auto* t = static_cast<{class}*>(p);\n    t->clock = 1;\n    t->eval();\n    read(t, out);\n}}\n}}\n"
    );
    s
}

/// Builds the library into `cache` unless it is there; returns its path.
fn build(cache: &Path) -> Result<PathBuf> {
    check_ports()?;
    let mut pe = ProcessingElement::default();
    pe.connect_all();
    let verilog = export_verilog(&pe, PE)? + &wrapper();
    let glue = glue();
    let version = run_tool(cache_parent(cache)?, "verilator", &["--version"], INSTALL)?;
    let args = [
        "--cc",
        "--exe",
        "--build",
        "-j",
        "0",
        "-Wno-fatal",
        "-Wno-lint",
        "-Wno-style",
        "--top-module",
        TOP,
        "-CFLAGS",
        "-fPIC",
        "-LDFLAGS",
        "-shared",
        "-MAKEFLAGS",
        "OPT_FAST=-O2",
        "--Mdir",
        "obj",
        "-o",
        LIB,
        "pe.v",
        "glue.cpp",
    ];
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (&verilog, &glue, &version.stdout, &args).hash(&mut h);
    let key = format!("pe-{:016x}", h.finish());
    let done = cache.join(&key);
    let lib = done.join("obj").join(LIB);
    if lib.is_file() {
        return Ok(lib);
    }
    let scratch = cache.join(format!("{key}.building-{}", std::process::id()));
    let io = |e: std::io::Error, p: &Path| Error::new(format!("{}: {e}", p.display()));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).map_err(|e| io(e, &scratch))?;
    for (name, text) in [("pe.v", verilog.as_str()), ("glue.cpp", glue.as_str())] {
        std::fs::write(scratch.join(name), text).map_err(|e| io(e, &scratch.join(name)))?;
    }
    run_tool(&scratch, "verilator", &args, INSTALL).map_err(|e| e.context("building the compiled PE"))?;
    // Another process may have finished first: its library is as good as ours.
    if std::fs::rename(&scratch, &done).is_err() && lib.is_file() {
        let _ = std::fs::remove_dir_all(&scratch);
    }
    if !lib.is_file() {
        return Err(Error::new(format!("the compiled PE was built but {} is missing", lib.display())));
    }
    Ok(lib)
}

const LIB: &str = "libshelling_pe.so";
const INSTALL: &str = "apt-get install -y verilator g++ make";

/// Makes the cache folder and returns it (as a folder to run `verilator --version` in).
fn cache_parent(cache: &Path) -> Result<&Path> {
    std::fs::create_dir_all(cache).map_err(|e| Error::new(format!("{}: {e}", cache.display())))?;
    Ok(cache)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glue_drives_every_input_and_reads_every_output_once() {
        let g = glue();
        for (k, (name, _)) in INPUT_PORTS.iter().enumerate() {
            assert_eq!(g.matches(&format!("t->i_{name} = in[{k}];")).count(), 1, "{name}");
        }
        for (k, (name, _)) in OUTPUT_PORTS.iter().enumerate() {
            assert_eq!(g.matches(&format!("out[{k}] = t->o_{name};")).count(), 1, "{name}");
        }
    }

    #[test]
    fn the_port_table_is_the_blocks() {
        check_ports().unwrap();
    }
}
