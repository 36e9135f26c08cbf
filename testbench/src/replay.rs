//! Rungs 4 and 5 of the equivalence ladder: replay a rust-hdl run against the block's exported
//! Verilog, or against a Yosys netlist of it.
//!
//! rust-hdl's Verilog generator and its simulator disagree on expression widths in known cases
//! (rust-hdl 0.46), so a block is only done when its exported Verilog
//! reproduces the rust-hdl simulation bit-exactly (rung 4 of the equivalence ladder). This module checks that on
//! any block, without hand-written port lists:
//!
//! 1. [`Driver::record_ports`](crate::Driver::record_ports) finds the block's top-level ports
//!    with a rust-hdl [`Probe`] (the visitor rust-hdl's own VCD writer and Verilog generator use)
//!    and, every cycle, records each input as driven before the rising edge and each output both
//!    before the edge (after the inputs settled: checks combinational paths) and after it.
//! 2. [`Recording::replay`] exports the block's Verilog ([`export_verilog`]), writes one
//!    `$readmemh` file per port and phase plus a self-checking testbench `tb.v` that drives the
//!    recorded inputs cycle by cycle and compares every output with `!==` (an `x` from the
//!    Verilog is a mismatch), then runs it under Icarus Verilog (`iverilog -g2012` + `vvp`) or
//!    Verilator (`--binary --timing`) and parses the testbench's summary line.
//! 3. [`Recording::replay_netlist`] does the same through a Yosys netlist of the exported
//!    Verilog instead ([`Design`]: word-level or gate-level), rung 5 of the ladder.
//!
//! The first mismatches are printed in detail (cycle, port, phase, expected, got) and returned in
//! the [`Error`]; all artefacts stay in the directory given to [`Recording::replay`] for a
//! closer look (`iverilog -g2012 -o x tb.v dut.v && vvp x`). A missing simulator is an error,
//! never a silent skip.
//!
//! Supported top-level ports: plain `Signal<In|Out, _>` of `Bits<N>`, `Signed<N>`, `Bit`, plus
//! the one clock (driven by the testbench, not recorded). Ports inside an interface appear as
//! `iface$signal`, as in the exported Verilog. Enum, struct and inout ports are refused.
//!
//! Outputs whose value is meaningless in some cycles (a FIFO's `data_out` while `empty`, whose
//! Verilog RAM powers up as `x` while rust-hdl's is 0) can be excluded from the comparison in
//! those cycles with [`Recording::dont_care_when`].

use std::fmt::{self, Write as _};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use rust_hdl::core::prelude::{check_all, Atom, AtomKind, Block, ModuleDefines, Probe, TypeKind, VCDValue};
use vcd::Value;

use crate::{Error, Result};

/// The Verilog module name given to the block under test in the replay.
pub const DUT_MODULE: &str = "dut";
/// The testbench's module name.
pub const TB_MODULE: &str = "replay_tb";
/// How many mismatches the testbench prints in detail.
pub const MISMATCHES_SHOWN: usize = 10;
const SUMMARY_TAG: &str = "REPLAY-SUMMARY";
const MISMATCH_TAG: &str = "MISMATCH";

/// Direction of a top-level port.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PortDir {
    /// `Signal<In, _>`: recorded before each rising edge and driven by the testbench.
    Input,
    /// `Signal<Out, _>`: recorded before and after each rising edge and checked.
    Output,
}

/// A top-level port of the block (the clock excluded).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    /// Name as in the exported Verilog (`y`, or `iface$signal` inside an interface).
    pub name: String,
    /// Width in bits.
    pub width: usize,
    /// Direction.
    pub dir: PortDir,
}

/// Which sample of a cycle a value belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    BeforeEdge,
    AfterEdge,
}

impl fmt::Display for Phase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Phase::BeforeEdge => "before",
            Phase::AfterEdge => "after",
        })
    }
}

/// The recorded values of one port: fixed-width hex digits per cycle, concatenated; `x` digits
/// mark don't-care samples. Inputs use only `before`.
#[derive(Clone, Debug)]
struct Column {
    digits: usize,
    before: String,
    after: String,
}

impl Column {
    fn samples(&self, phase: Phase) -> &String {
        match phase {
            Phase::BeforeEdge => &self.before,
            Phase::AfterEdge => &self.after,
        }
    }

    fn samples_mut(&mut self, phase: Phase) -> &mut String {
        match phase {
            Phase::BeforeEdge => &mut self.before,
            Phase::AfterEdge => &mut self.after,
        }
    }

    fn value(&self, phase: Phase, cycle: usize) -> &str {
        &self.samples(phase)[cycle * self.digits..(cycle + 1) * self.digits]
    }
}

/// Finds the top-level ports: atoms visited at depth 1 of the block hierarchy.
struct PortScan {
    clock_id: usize,
    depth: usize,
    namespace: Vec<String>,
    ports: Vec<Port>,
    ids: Vec<usize>,
    clock_name: Option<String>,
    errors: Vec<String>,
}

impl Probe for PortScan {
    fn visit_start_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth += 1;
    }

    fn visit_start_namespace(&mut self, name: &str, _node: &dyn Block) {
        if self.depth == 1 {
            self.namespace.push(name.to_owned());
        }
    }

    fn visit_atom(&mut self, name: &str, atom: &dyn Atom) {
        if self.depth != 1 {
            return;
        }
        let name = self.namespace.iter().map(String::as_str).chain([name]).collect::<Vec<_>>().join("$");
        let dir = match atom.kind() {
            AtomKind::InputParameter if atom.id() == self.clock_id => {
                self.clock_name = Some(name);
                return;
            }
            AtomKind::InputParameter => PortDir::Input,
            AtomKind::OutputParameter => PortDir::Output,
            AtomKind::InOutParameter | AtomKind::OutputPassthrough => {
                self.errors.push(format!("port `{name}`: inout ports are not supported"));
                return;
            }
            _ => return,
        };
        let descriptor = atom.descriptor();
        match descriptor.kind {
            TypeKind::Bits(_) | TypeKind::Signed(_) => {
                self.ports.push(Port { name, width: atom.bits(), dir });
                self.ids.push(atom.id());
            }
            _ => self.errors.push(format!(
                "port `{name}` of type {}: only Bits, Signed and Bit ports are supported",
                descriptor.name
            )),
        }
    }

    fn visit_end_namespace(&mut self, _name: &str, _node: &dyn Block) {
        if self.depth == 1 {
            self.namespace.pop();
        }
    }

    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth -= 1;
    }
}

/// Appends the hex digits of a plain bit-vector value (MSB first, zero-padded to `digits`).
fn push_hex(out: &mut String, value: &VCDValue, width: usize) -> std::result::Result<(), String> {
    let bits = match value {
        VCDValue::Single(v) => std::slice::from_ref(v),
        VCDValue::Vector(v) => v.as_slice(),
        _ => return Err("not a plain bit vector".into()),
    };
    if bits.len() != width {
        return Err(format!("{} bits where {width} were expected", bits.len()));
    }
    let pad = width.div_ceil(4) * 4 - width;
    let mut nibble = 0u32;
    for i in 0..pad + width {
        let bit = match if i < pad { Value::V0 } else { bits[i - pad] } {
            Value::V0 => 0,
            Value::V1 => 1,
            other => return Err(format!("undefined bit `{other}`")),
        };
        nibble = nibble << 1 | bit;
        if i % 4 == 3 {
            out.push(char::from_digit(nibble, 16).unwrap_or('?'));
            nibble = 0;
        }
    }
    Ok(())
}

/// Reads the top-level ports' current values into the recorder's columns.
struct Sampler<'a> {
    ids: &'a [usize],
    ports: &'a [Port],
    columns: &'a mut [Column],
    phase: Phase,
    depth: usize,
    next: usize,
    error: Option<String>,
}

impl Probe for Sampler<'_> {
    fn visit_start_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth += 1;
    }

    fn visit_atom(&mut self, _name: &str, atom: &dyn Atom) {
        if self.depth != 1 || self.ids.get(self.next) != Some(&atom.id()) {
            return;
        }
        let (port, column) = (&self.ports[self.next], &mut self.columns[self.next]);
        self.next += 1;
        if port.dir == PortDir::Input && self.phase == Phase::AfterEdge {
            return;
        }
        if let Err(e) = push_hex(column.samples_mut(self.phase), &atom.vcd(), port.width) {
            self.error.get_or_insert(format!("port `{}`: {e}", port.name));
        }
    }

    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.depth -= 1;
    }
}

/// Records the top-level ports cycle by cycle; owned by the [`Driver`](crate::Driver).
pub(crate) struct Recorder {
    recording: Recording,
    ids: Vec<usize>,
}

impl Recorder {
    /// Finds the ports of `uut`; `clock_id` is the id of its clock input.
    pub(crate) fn new(uut: &dyn Block, clock_id: usize) -> Result<Self> {
        let mut scan = PortScan {
            clock_id,
            depth: 0,
            namespace: vec![],
            ports: vec![],
            ids: vec![],
            clock_name: None,
            errors: vec![],
        };
        uut.accept(DUT_MODULE, &mut scan);
        if !scan.errors.is_empty() {
            return Err(Error::new(format!("cannot record this block: {}", scan.errors.join("; "))));
        }
        let clock =
            scan.clock_name.ok_or_else(|| Error::new("the clock is not a top-level input of the block"))?;
        let columns = scan
            .ports
            .iter()
            .map(|p| Column { digits: p.width.div_ceil(4), before: String::new(), after: String::new() })
            .collect();
        Ok(Self { recording: Recording { ports: scan.ports, clock, columns, cycles: 0 }, ids: scan.ids })
    }

    pub(crate) fn sample_before_edge(&mut self, uut: &dyn Block) -> Result<()> {
        self.sample(uut, Phase::BeforeEdge)
    }

    pub(crate) fn sample_after_edge(&mut self, uut: &dyn Block) -> Result<()> {
        self.sample(uut, Phase::AfterEdge)?;
        self.recording.cycles += 1;
        Ok(())
    }

    fn sample(&mut self, uut: &dyn Block, phase: Phase) -> Result<()> {
        let rec = &mut self.recording;
        let mut sampler = Sampler {
            ids: &self.ids,
            ports: &rec.ports,
            columns: &mut rec.columns,
            phase,
            depth: 0,
            next: 0,
            error: None,
        };
        uut.accept(DUT_MODULE, &mut sampler);
        let cycle = rec.cycles;
        if let Some(e) = sampler.error {
            return Err(Error::new(format!("recording cycle {cycle} ({phase} edge): {e}")));
        }
        if sampler.next != self.ids.len() {
            return Err(Error::new(format!(
                "recording cycle {cycle}: found {} of the {} top-level ports",
                sampler.next,
                self.ids.len()
            )));
        }
        Ok(())
    }

    pub(crate) fn finish(self) -> Recording {
        self.recording
    }
}

/// The Verilog simulator a [`Recording`] is replayed under.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Simulator {
    /// Icarus Verilog: `iverilog -g2012` then `vvp`. Four-state: an `x` is a mismatch.
    Icarus,
    /// Verilator 5: `verilator --binary --timing`. Two-state (`x` becomes 0), slower to build,
    /// a second, independent reading of the same Verilog.
    Verilator,
}

/// What a [`Recording`] is replayed through: the exported Verilog itself (rung 4) or a Yosys
/// netlist of it (rung 5, [`Recording::replay_netlist`]), written to `netlist.v` beside the
/// testbench with Yosys' log in `netlist.log`. A netlist catches what synthesis reads
/// differently from simulation: initial values, `x` propagation, sensitivity lists, width and
/// sign rules, memory inference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Design {
    /// The exported Verilog (`dut.v`).
    Rtl,
    /// Yosys' word-level netlist ([`WORD_PASSES`]): processes turned into multiplexers and
    /// flip-flops, the hierarchy flattened, expressions optimised and narrowed, block RAMs
    /// inferred as `$mem` cells; operators stay words (`$add`, `$mul`, …).
    Words,
    /// Yosys' gate-level netlist ([`GATE_PASSES`]): generic synthesis down to single-bit gates
    /// and flip-flops (`techmap`, `abc`); block RAMs stay `$mem` arrays. Tens of thousands of
    /// gates for the PE: event-driven simulators crawl through it (Icarus: a few cycles a
    /// second), Verilator does not.
    Gates,
}

/// The Yosys passes of [`Design::Words`], after `read_verilog dut.v`.
pub const WORD_PASSES: &str = "hierarchy -top dut; proc; flatten; opt_expr; opt_clean; opt -full; wreduce; \
     peepopt; opt_clean; memory -nomap; opt -full; stat";
/// The Yosys passes of [`Design::Gates`], after `read_verilog dut.v`: Yosys' generic `synth` up
/// to (not including) its mapping of memories to flip-flops, then its gate mapping.
pub const GATE_PASSES: &str =
    "synth -flatten -top dut -run begin:fine; opt -fast -full; techmap; opt -fast; abc -fast; opt_clean; stat";

impl Design {
    /// The Yosys script that makes `netlist.v` from `dut.v`, or `None` for [`Design::Rtl`].
    fn script(self) -> Option<String> {
        let passes = match self {
            Design::Rtl => return None,
            Design::Words => WORD_PASSES,
            Design::Gates => GATE_PASSES,
        };
        Some(format!("read_verilog dut.v; {passes}; write_verilog -noattr netlist.v"))
    }

    /// The file the simulator compiles.
    fn file(self) -> &'static str {
        match self {
            Design::Rtl => "dut.v",
            Design::Words | Design::Gates => "netlist.v",
        }
    }
}

impl fmt::Display for Design {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Design::Rtl => "exported Verilog",
            Design::Words => "Yosys word-level netlist",
            Design::Gates => "Yosys gate-level netlist",
        })
    }
}

impl fmt::Display for Simulator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Simulator::Icarus => "Icarus Verilog",
            Simulator::Verilator => "Verilator",
        })
    }
}

/// A successful replay.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReplayReport {
    /// The simulator that ran it.
    pub simulator: Simulator,
    /// What it simulated.
    pub design: Design,
    /// Cycles replayed.
    pub cycles: usize,
    /// Output values compared (don't-care samples excluded), all equal.
    pub checks: usize,
    /// Where `dut.v`, `tb.v` and the recorded values are.
    pub dir: PathBuf,
}

impl fmt::Display for ReplayReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} under {}: {} cycles, {} output values, all equal to the rust-hdl simulation ({})",
            self.design,
            self.simulator,
            self.cycles,
            self.checks,
            self.dir.display()
        )
    }
}

/// The Verilog of `uut` with its top module named `module` (children become `module$child`).
/// Runs rust-hdl's `check_all` first and returns its report instead of panicking, unlike
/// rust-hdl's `generate_verilog`.
pub fn export_verilog(uut: &dyn Block, module: &str) -> Result<String> {
    check_all(uut).map_err(|e| Error::new(format!("rust-hdl connectivity check failed: {e:?}")))?;
    let mut defines = ModuleDefines::default();
    uut.accept(module, &mut defines);
    Ok(defines.defines())
}

/// The top-level ports and their values, cycle by cycle, of a rust-hdl run (see the
/// [module docs](self)). Made by [`Driver::take_recording`](crate::Driver::take_recording).
#[derive(Clone, Debug)]
pub struct Recording {
    ports: Vec<Port>,
    clock: String,
    columns: Vec<Column>,
    cycles: usize,
}

impl Recording {
    /// Cycles recorded.
    pub fn cycles(&self) -> usize {
        self.cycles
    }

    /// The top-level ports, clock excluded, in declaration order.
    pub fn ports(&self) -> &[Port] {
        &self.ports
    }

    /// The clock port's name.
    pub fn clock(&self) -> &str {
        &self.clock
    }

    fn port_index(&self, name: &str) -> Result<usize> {
        self.ports.iter().position(|p| p.name == name).ok_or_else(|| {
            let names = self.ports.iter().map(|p| p.name.as_str()).collect::<Vec<_>>();
            Error::new(format!("no port `{name}` (ports: {})", names.join(", ")))
        })
    }

    fn output_index(&self, name: &str) -> Result<usize> {
        let i = self.port_index(name)?;
        if self.ports[i].dir != PortDir::Output {
            return Err(Error::new(format!("port `{name}` is an input, not an output")));
        }
        Ok(i)
    }

    /// Excludes output `port` from the comparison in every sample where output `qualifier` had
    /// the value `value` in the same sample: `dont_care_when("data_out", "empty", 1)`. Returns
    /// how many samples (before- and after-edge) were excluded.
    pub fn dont_care_when(&mut self, port: &str, qualifier: &str, value: u64) -> Result<usize> {
        let (p, q) = (self.output_index(port)?, self.output_index(qualifier)?);
        if self.ports[q].width > 64 {
            return Err(Error::new(format!("qualifier `{qualifier}` is wider than 64 bits")));
        }
        let want = format!("{value:0width$x}", width = self.columns[q].digits);
        let mut excluded = 0;
        for phase in [Phase::BeforeEdge, Phase::AfterEdge] {
            for cycle in 0..self.cycles {
                if self.columns[q].value(phase, cycle) == want {
                    let d = self.columns[p].digits;
                    self.columns[p]
                        .samples_mut(phase)
                        .replace_range(cycle * d..(cycle + 1) * d, &"x".repeat(d));
                    excluded += 1;
                }
            }
        }
        Ok(excluded)
    }

    /// Flips bit `bit` of the value output `port` was recorded with after the rising edge of
    /// `cycle`: a deliberately wrong expectation, for checking that the replay catches it.
    pub fn flip_expected_bit(&mut self, cycle: usize, port: &str, bit: usize) -> Result<()> {
        let p = self.output_index(port)?;
        if cycle >= self.cycles || bit >= self.ports[p].width {
            return Err(Error::new(format!(
                "no bit {bit} of `{port}` at cycle {cycle} ({} bits, {} cycles)",
                self.ports[p].width, self.cycles
            )));
        }
        let column = &mut self.columns[p];
        let at = (cycle + 1) * column.digits - 1 - bit / 4;
        let digit = column.after.as_bytes()[at] as char;
        let flipped = digit
            .to_digit(16)
            .and_then(|d| char::from_digit(d ^ (1 << (bit % 4)), 16))
            .ok_or_else(|| Error::new(format!("`{port}` at cycle {cycle} is a don't-care")))?;
        column.after.replace_range(at..at + 1, flipped.encode_utf8(&mut [0; 4]));
        Ok(())
    }

    /// Exports `uut`'s Verilog, writes the recorded values and the self-checking testbench into
    /// `dir` (created if needed; previous replay files there are overwritten) and runs it under
    /// `simulator`. `Ok` means every compared output value was equal in every cycle; otherwise
    /// the error lists the first mismatches. `uut` is the recorded block (its structure, not its
    /// state, is exported): typically `driver.uut()`.
    pub fn replay(&self, uut: &dyn Block, dir: &Path, simulator: Simulator) -> Result<ReplayReport> {
        self.replay_netlist(uut, dir, Design::Rtl, simulator)
    }

    /// As [`Self::replay`], with Verilog macros defined for the simulator's compile (`defines`:
    /// names such as `SHELLING_ICE40`, which select a leaf's body for one FPGA family).
    pub fn replay_with_defines(
        &self,
        uut: &dyn Block,
        dir: &Path,
        simulator: Simulator,
        defines: &[&str],
    ) -> Result<ReplayReport> {
        self.run_replay(uut, dir, Design::Rtl, simulator, defines)
    }

    /// As [`Self::replay`], through `design`: the exported Verilog, or a Yosys netlist of it
    /// (rung 5) made in `dir` by the `yosys` on PATH.
    pub fn replay_netlist(
        &self,
        uut: &dyn Block,
        dir: &Path,
        design: Design,
        simulator: Simulator,
    ) -> Result<ReplayReport> {
        self.run_replay(uut, dir, design, simulator, &[])
    }

    fn run_replay(
        &self,
        uut: &dyn Block,
        dir: &Path,
        design: Design,
        simulator: Simulator,
        defines: &[&str],
    ) -> Result<ReplayReport> {
        if self.cycles == 0 {
            return Err(Error::new("nothing to replay: no cycle was recorded"));
        }
        let dir = &std::path::absolute(dir)
            .map_err(|e| Error::new(format!("bad replay directory {}: {e}", dir.display())))?;
        let verilog = export_verilog(uut, DUT_MODULE)?;
        let write = |name: &str, text: &str| {
            std::fs::write(dir.join(name), text)
                .map_err(|e| Error::new(format!("cannot write {}: {e}", dir.join(name).display())))
        };
        std::fs::create_dir_all(dir)
            .map_err(|e| Error::new(format!("cannot create {}: {e}", dir.display())))?;
        write("dut.v", &verilog)?;
        for (file, text) in self.data_files() {
            write(&file, &text)?;
        }
        write("tb.v", &self.testbench())?;
        if let Some(script) = design.script() {
            run_tool(dir, "yosys", &["-q", "-l", "netlist.log", "-p", &script], "apt-get install -y yosys")?;
        }
        let defines: Vec<String> = defines.iter().map(|d| format!("-D{d}")).collect();
        let output = match simulator {
            Simulator::Icarus => run_icarus(dir, design.file(), &defines)?,
            Simulator::Verilator => run_verilator(dir, design, &defines)?,
        };
        let (cycles, checks) = parse_summary(&output, self.cycles).map_err(|e| {
            e.context(format_args!("{design} under {simulator}, replay in {}", dir.display()))
        })?;
        Ok(ReplayReport { simulator, design, cycles, checks, dir: dir.to_owned() })
    }

    /// Whether any sample of output column `i` in `phase` is a don't-care.
    fn has_dont_care(&self, i: usize, phase: Phase) -> bool {
        self.columns[i].samples(phase).contains('x')
    }

    /// The `$readmemh` files: `in_<i>.hex` per input, `before_<i>.hex` and `after_<i>.hex` per
    /// output (don't-cares written as 0) and, where a column has don't-cares, a 0/1
    /// `care_before_<i>.hex` / `care_after_<i>.hex` mask (Verilator is two-state).
    fn data_files(&self) -> Vec<(String, String)> {
        let lines = |samples: &str, digits: usize, f: &dyn Fn(&str) -> String| {
            let mut text = String::with_capacity(samples.len() + samples.len() / digits);
            for chunk in samples.as_bytes().chunks(digits) {
                // Chunks of ASCII hex digits, so always valid UTF-8.
                text.push_str(&f(std::str::from_utf8(chunk).unwrap_or_default()));
                text.push('\n');
            }
            text
        };
        let value = |s: &str| s.replace('x', "0");
        let care = |s: &str| if s.contains('x') { "0" } else { "1" }.to_owned();
        let mut files = vec![];
        for (i, (port, column)) in self.ports.iter().zip(&self.columns).enumerate() {
            let phases: &[Phase] = match port.dir {
                PortDir::Input => {
                    files.push((format!("in_{i}.hex"), lines(&column.before, column.digits, &value)));
                    continue;
                }
                PortDir::Output => &[Phase::BeforeEdge, Phase::AfterEdge],
            };
            for &phase in phases {
                let samples = column.samples(phase);
                files.push((format!("{phase}_{i}.hex"), lines(samples, column.digits, &value)));
                if self.has_dont_care(i, phase) {
                    files.push((format!("care_{phase}_{i}.hex"), lines(samples, column.digits, &care)));
                }
            }
        }
        files
    }

    /// The self-checking testbench (module [`TB_MODULE`]) for the files of [`Self::data_files`].
    fn testbench(&self) -> String {
        let n = self.cycles;
        let mut decl = String::new();
        let mut load = String::new();
        let mut conn = vec![format!(".{}(clock)", self.clock)];
        let mut drive = String::new();
        let mut checks = [String::new(), String::new()];
        for (i, port) in self.ports.iter().enumerate() {
            let range = format!("[{}:0]", port.width - 1);
            match port.dir {
                PortDir::Input => {
                    let _ = writeln!(decl, "  reg {range} in_{i}; // {}", port.name);
                    let _ = writeln!(decl, "  reg {range} in_{i}_mem [0:{}];", n - 1);
                    let _ = writeln!(load, "    $readmemh(\"in_{i}.hex\", in_{i}_mem);");
                    let _ = writeln!(drive, "      in_{i} = in_{i}_mem[cycle];");
                    conn.push(format!(".{}(in_{i})", port.name));
                }
                PortDir::Output => {
                    let _ = writeln!(decl, "  wire {range} out_{i}; // {}", port.name);
                    conn.push(format!(".{}(out_{i})", port.name));
                    for (phase, check) in [Phase::BeforeEdge, Phase::AfterEdge].into_iter().zip(&mut checks) {
                        let mem = format!("{phase}_{i}_mem");
                        let _ = writeln!(decl, "  reg {range} {mem} [0:{}];", n - 1);
                        let _ = writeln!(load, "    $readmemh(\"{phase}_{i}.hex\", {mem});");
                        let mut condition = String::from("1'b1");
                        if self.has_dont_care(i, phase) {
                            let _ = writeln!(decl, "  reg care_{mem} [0:{}];", n - 1);
                            let _ = writeln!(load, "    $readmemh(\"care_{phase}_{i}.hex\", care_{mem});");
                            condition = format!("care_{mem}[cycle]");
                        }
                        let name = &port.name;
                        let _ = writeln!(
                            check,
                            "      if ({condition}) begin\n\
                             \x20       checks = checks + 1;\n\
                             \x20       if (out_{i} !== {mem}[cycle]) begin\n\
                             \x20         mismatches = mismatches + 1;\n\
                             \x20         if (mismatches <= {MISMATCHES_SHOWN})\n\
                             \x20           $display(\"{MISMATCH_TAG} cycle=%0d port={name} phase={phase} \
                             expected=%h got=%h\", cycle, {mem}[cycle], out_{i});\n\
                             \x20       end\n\
                             \x20     end"
                        );
                    }
                }
            }
        }
        format!(
            "// Generated by shelling-testbench (replay.rs): replays {n} cycles recorded from the rust-hdl\n\
             // simulation of module `{DUT_MODULE}` (dut.v) and checks every output, every cycle.\n\
             module {TB_MODULE};\n\
             \x20 reg clock = 1'b0;\n\
             \x20 integer cycle;\n\
             \x20 integer checks = 0;\n\
             \x20 integer mismatches = 0;\n\
             {decl}\n\
             \x20 {DUT_MODULE} uut({conn});\n\n\
             \x20 initial begin\n\
             {load}\
             \x20   for (cycle = 0; cycle < {n}; cycle = cycle + 1) begin\n\
             \x20     #5;\n\
             {drive}\
             \x20     #5;\n\
             {before}\
             \x20     clock = 1'b1;\n\
             \x20     #5;\n\
             {after}\
             \x20     clock = 1'b0;\n\
             \x20   end\n\
             \x20   $display(\"{SUMMARY_TAG} cycles=%0d checks=%0d mismatches=%0d\", cycle, checks, mismatches);\n\
             \x20   $finish;\n\
             \x20 end\n\
             endmodule\n",
            conn = conn.join(", "),
            before = checks[0],
            after = checks[1],
        )
    }
}

/// Runs `program` with `args` in `dir`; a missing program or a non-zero exit is an error that
/// quotes the program's output.
pub(crate) fn run_tool(dir: &Path, program: &str, args: &[&str], install: &str) -> Result<Output> {
    // A program given as a path is resolved against `dir`, not against our working directory.
    let output = Command::new(if program.contains('/') { dir.join(program) } else { program.into() })
        .args(args)
        .current_dir(dir)
        .output()
        .map_err(|e| {
            if e.kind() == std::io::ErrorKind::NotFound {
                Error::new(format!(
                    "`{program}` is not installed or not on PATH; this step needs it ({install})"
                ))
            } else {
                Error::new(format!("cannot run `{program}`: {e}"))
            }
        })?;
    if !output.status.success() {
        return Err(Error::new(format!(
            "`{program} {}` failed in {} ({}):\n{}{}",
            args.join(" "),
            dir.display(),
            output.status,
            tail(&String::from_utf8_lossy(&output.stdout)),
            tail(&String::from_utf8_lossy(&output.stderr)),
        )));
    }
    Ok(output)
}

/// The last lines of a long tool output.
fn tail(text: &str) -> String {
    const LINES: usize = 40;
    let lines = text.lines().collect::<Vec<_>>();
    let skip = lines.len().saturating_sub(LINES);
    let mut out = if skip > 0 { format!("[{skip} lines skipped]\n") } else { String::new() };
    for line in &lines[skip..] {
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// Compiles `tb.v` with the design in `design` (the exported Verilog or a netlist of it), the
/// `-D` options in `defines` first.
fn run_icarus(dir: &Path, design: &str, defines: &[String]) -> Result<String> {
    const INSTALL: &str = "apt-get install -y iverilog";
    let mut compile: Vec<&str> = defines.iter().map(String::as_str).collect();
    compile.extend(["-g2012", "-s", TB_MODULE, "-o", "replay.vvp", "tb.v", design]);
    run_tool(dir, "iverilog", &compile, INSTALL)?;
    let run = run_tool(dir, "vvp", &["-n", "replay.vvp"], INSTALL)?;
    Ok(String::from_utf8_lossy(&run.stdout).into_owned())
}

/// Builds `tb.v` with `design`'s file into a binary (the `-D` options in `defines` first) and
/// runs it.
///
/// A netlist is built without Verilator's bit-op-tree folding, which evaluates some XOR trees
/// of Yosys' gate netlists wrongly (upstream issues 4059 and 5186; Debian's 5.006 has them): on
/// the PE's gate netlist it set the sign bit of a positive product, so every key read out was 1,
/// where Icarus on the same netlist and Verilator without that one optimisation agree with the
/// RTL on every cycle. The RTL is built as the compiled PE (`verilated.rs`) is, with it: its
/// replays check that build.
fn run_verilator(dir: &Path, design: Design, defines: &[String]) -> Result<String> {
    let mut build: Vec<&str> = defines.iter().map(String::as_str).collect();
    if design != Design::Rtl {
        build.push("-fno-const-bit-op-tree");
    }
    build.extend([
        "--binary",
        "--timing",
        "-j",
        "0",
        "-Wno-fatal",
        "-Wno-lint",
        "-Wno-style",
        // The generated C++ unoptimised: builds in well under half the time of Verilator's
        // default `-Os`, and a replay's few hundred thousand cycles still run in seconds.
        "-MAKEFLAGS",
        "OPT_FAST=-O0",
        "--top-module",
        TB_MODULE,
        "--Mdir",
        "verilator",
        "-o",
        "replay",
        "tb.v",
        design.file(),
    ]);
    run_tool(dir, "verilator", &build, "apt-get install -y verilator")?;
    let run = run_tool(dir, "verilator/replay", &[], "it was just built")?;
    Ok(String::from_utf8_lossy(&run.stdout).into_owned())
}

/// Checks the testbench's summary line; returns (cycles, checks) or the mismatches.
fn parse_summary(output: &str, expected_cycles: usize) -> Result<(usize, usize)> {
    let summary = output.lines().find_map(|l| l.trim().strip_prefix(SUMMARY_TAG)).ok_or_else(|| {
        Error::new(format!("the testbench printed no `{SUMMARY_TAG}` line; its output:\n{}", tail(output)))
    })?;
    let field = |key: &str| {
        summary
            .split_whitespace()
            .find_map(|kv| kv.strip_prefix(key)?.strip_prefix('=')?.parse::<usize>().ok())
            .ok_or_else(|| Error::new(format!("malformed summary line `{SUMMARY_TAG}{summary}`")))
    };
    let (cycles, checks, mismatches) = (field("cycles")?, field("checks")?, field("mismatches")?);
    if mismatches > 0 {
        let details = output
            .lines()
            .filter(|l| l.trim_start().starts_with(MISMATCH_TAG))
            .map(|l| format!("  {}", l.trim()))
            .collect::<Vec<_>>()
            .join("\n");
        return Err(Error::new(format!(
            "{mismatches} of {checks} output values differ from the rust-hdl simulation over {cycles} \
             cycles; the first {}:\n{details}",
            mismatches.min(MISMATCHES_SHOWN)
        )));
    }
    if cycles != expected_cycles {
        return Err(Error::new(format!("replayed {cycles} cycles instead of {expected_cycles}")));
    }
    Ok((cycles, checks))
}

#[cfg(test)]
mod tests {
    use rust_hdl::core::prelude::{bits, signed, Bits, Synth};

    use super::*;

    fn hex(value: VCDValue, width: usize) -> std::result::Result<String, String> {
        let mut out = String::new();
        push_hex(&mut out, &value, width).map(|()| out)
    }

    #[test]
    fn values_become_zero_padded_hex() {
        assert_eq!(hex(true.vcd(), 1), Ok("1".into()));
        assert_eq!(hex(bits::<5>(0x13).vcd(), 5), Ok("13".into()));
        assert_eq!(hex(bits::<32>(0xdead_beef).vcd(), 32), Ok("deadbeef".into()));
        assert_eq!(hex(Bits::<70>::from(1u64 << 63).vcd(), 70), Ok("008000000000000000".into()));
        assert_eq!(hex(signed::<12>(-2).vcd(), 12), Ok("ffe".into()));
        assert!(hex(bits::<5>(1).vcd(), 6).is_err());
    }

    #[test]
    fn summary_is_parsed_and_mismatches_are_reported() {
        let ok = "noise\nREPLAY-SUMMARY cycles=3 checks=12 mismatches=0\n";
        assert_eq!(parse_summary(ok, 3), Ok((3, 12)));
        assert!(parse_summary(ok, 4).unwrap_err().message().contains("replayed 3 cycles instead of 4"));
        let bad = "MISMATCH cycle=1 port=y phase=after expected=1 got=0\n\
                   REPLAY-SUMMARY cycles=3 checks=12 mismatches=1\n";
        let msg = parse_summary(bad, 3).unwrap_err().to_string();
        assert!(msg.starts_with("1 of 12 output values differ") && msg.contains("cycle=1 port=y"), "{msg}");
        assert!(parse_summary("syntax error\n", 3).unwrap_err().message().contains("syntax error"));
    }

    #[test]
    fn missing_simulator_is_an_error_that_says_so() {
        let err = run_tool(Path::new("."), "no-such-simulator-4e91", &[], "install it").unwrap_err();
        assert!(err.message().contains("`no-such-simulator-4e91` is not installed or not on PATH"), "{err}");
    }
}
