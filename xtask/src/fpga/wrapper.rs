//! The register wrapper every block is placed and routed in.
//!
//! A block's ports (hundreds of bits for the processing element) outnumber the package pins, and
//! a block is meant to sit between registers of its neighbours anyway. So each block is wrapped
//! in a top module with six pins: `clock`, `sin`, `en_in`, `en_a`, `en_b` and `sout`.
//!
//! - Every input bit is a stage of one shift register (`shelling_fpga_in`, loaded from `sin`,
//!   its last stage on `sout`, so none is unobserved). The inputs of an array entry (`cmd_id$2`,
//!   the machine's PE 2) are consecutive stages, entry after entry, then the plain ports: a
//!   machine's PE has its own stretch of the chain, which the placer can put beside the PE,
//!   as a PE's host interface would be; in the ports' order (`dir_we$0`, `dir_we$1`, …) every
//!   link of the chain would join two PEs and hold all the input flip-flops in the die's
//!   centre, far from every PE;
//! - every output bit is captured by two registers (`shelling_fpga_cap_a`, `shelling_fpga_cap_b`,
//!   kept).
//!
//! Every path into and out of the block thus starts or ends at a flip-flop and counts in the
//! post-route fmax, as it would between the block's neighbours. The wrapper holds flip-flops and
//! nothing else: no LUT. Its flip-flops have their own clock enables (pins), so Yosys cannot merge
//! one with a block register. Each output has two captures so that on iCE40, where a logic cell
//! pairs a LUT with the flip-flop its output drives alone, no wrapper flip-flop shares a cell
//! with a LUT of the block: every wrapper flip-flop takes exactly one logic cell there, and the
//! wrapper's share of the counts is exactly its flip-flop count.

use anyhow::{bail, Context, Result};

/// Names of the wrapper's registers (wires in the synthesized netlist).
pub const WRAPPER_NETS: [&str; 3] = ["shelling_fpga_in", "shelling_fpga_cap_a", "shelling_fpga_cap_b"];

/// A port's direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    In,
    Out,
}

/// One port of a block's top module.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub dir: Dir,
    pub width: usize,
}

/// The ports of `module` in exported Verilog: the declarations (`input wire [17:0] dir_x;`) of
/// the module, checked against its port list.
pub fn ports(verilog: &str, module: &str) -> Result<Vec<Port>> {
    let head = format!("module {module}(");
    let start = verilog.find(&head).with_context(|| format!("no `module {module}(` in the Verilog"))?;
    let rest = &verilog[start + head.len()..];
    let list_end = rest.find(");").with_context(|| format!("module {module}: unterminated port list"))?;
    let listed: Vec<&str> = rest[..list_end].split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
    let body = &rest[list_end..rest.find("endmodule").unwrap_or(rest.len())];
    let mut ports = Vec::new();
    for line in body.lines().map(str::trim) {
        let dir = if line.starts_with("input ") {
            Dir::In
        } else if line.starts_with("output ") {
            Dir::Out
        } else if line.starts_with("inout ") {
            bail!("module {module}: inout port `{line}` cannot be wrapped");
        } else {
            continue;
        };
        let decl = line.strip_suffix(';').with_context(|| format!("module {module}: `{line}` has no `;`"))?;
        let words: Vec<&str> = decl.split_whitespace().collect();
        let name = words.last().copied().unwrap_or_default();
        let width = match words.iter().find(|w| w.starts_with('[')) {
            None => 1,
            Some(range) => {
                let inner = range.trim_start_matches('[').trim_end_matches(']');
                let (hi, lo) =
                    inner.split_once(':').with_context(|| format!("module {module}: range in `{line}`"))?;
                let hi: i64 =
                    hi.trim().parse().with_context(|| format!("module {module}: range in `{line}`"))?;
                let lo: i64 =
                    lo.trim().parse().with_context(|| format!("module {module}: range in `{line}`"))?;
                (hi - lo).unsigned_abs() as usize + 1
            }
        };
        ports.push(Port { name: name.to_string(), dir, width });
    }
    let declared: Vec<&str> = ports.iter().map(|p| p.name.as_str()).collect();
    if declared != listed {
        bail!("module {module}: the port list {listed:?} does not match the declarations {declared:?}");
    }
    match ports.iter().find(|p| p.name == "clock") {
        Some(p) if p.dir == Dir::In && p.width == 1 => {}
        _ => bail!("module {module}: no one-bit input `clock`"),
    }
    Ok(ports)
}

/// The index of an array port's entry (`dir_we$2`: 2), `usize::MAX` for a plain port.
fn array_index(name: &str) -> usize {
    name.rsplit_once('$').and_then(|(_, i)| i.parse().ok()).unwrap_or(usize::MAX)
}

/// A generated wrapper around one block.
#[derive(Clone, Debug)]
pub struct Wrapper {
    /// The wrapper's module name (the top for Yosys).
    pub top: String,
    /// Its Verilog.
    pub verilog: String,
    /// Input bits (shift register stages) and output bits (each captured twice).
    pub in_bits: usize,
    pub out_bits: usize,
}

/// The wrapper of `module` with these `ports` (see the module documentation).
pub fn wrap(module: &str, ports: &[Port]) -> Wrapper {
    let mut inputs: Vec<&Port> = ports.iter().filter(|p| p.dir == Dir::In && p.name != "clock").collect();
    // A machine's PEs each in their own stretch of the shift register (see the module
    // documentation); a stable sort, so a block without arrays keeps its port order.
    inputs.sort_by_key(|p| array_index(&p.name));
    let outputs: Vec<&Port> = ports.iter().filter(|p| p.dir == Dir::Out).collect();
    let ni: usize = inputs.iter().map(|p| p.width).sum();
    let no: usize = outputs.iter().map(|p| p.width).sum();
    let top = format!("{module}_fpga_top");
    let [sr, cap_a, cap_b] = WRAPPER_NETS;
    let mut v = format!(
        "// Register wrapper of {module} for place and route (written by `cargo xtask fpga`):\n\
         // every input bit a stage of the shift register {sr}, every output bit captured by\n\
         // {cap_a} and {cap_b}; flip-flops only.\n\
         module {top}(input wire clock, input wire sin, input wire en_in, input wire en_a, input wire en_b, output wire sout);\n"
    );
    let mut conns = vec![".clock(clock)".to_string()];
    if ni > 0 {
        v += &format!("  reg [{}:0] {sr};\n", ni - 1);
        if ni == 1 {
            v += &format!("  always @(posedge clock) if (en_in) {sr} <= sin;\n");
        } else {
            v += &format!("  always @(posedge clock) if (en_in) {sr} <= {{{sr}[{}:0], sin}};\n", ni - 2);
        }
        v += &format!("  assign sout = {sr}[{}];\n", ni - 1);
        let mut at = 0;
        for p in &inputs {
            conns.push(format!(".{}({sr}[{}:{}])", p.name, at + p.width - 1, at));
            at += p.width;
        }
    } else {
        v += "  assign sout = sin;\n";
    }
    if no > 0 {
        v += &format!("  wire [{}:0] block_out;\n", no - 1);
        v += &format!("  (* keep *) reg [{}:0] {cap_a};\n", no - 1);
        v += &format!("  (* keep *) reg [{}:0] {cap_b};\n", no - 1);
        v += &format!("  always @(posedge clock) if (en_a) {cap_a} <= block_out;\n");
        v += &format!("  always @(posedge clock) if (en_b) {cap_b} <= block_out;\n");
        let mut at = 0;
        for p in &outputs {
            conns.push(format!(".{}(block_out[{}:{}])", p.name, at + p.width - 1, at));
            at += p.width;
        }
    }
    v += &format!("  {module} block(\n    {}\n  );\n", conns.join(",\n    "));
    v += "endmodule\n";
    Wrapper { top, verilog: v, in_bits: ni, out_bits: no }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SAMPLE: &str = "// x\nmodule blk(clock,a,b,y);\n    // Module arguments\n    input wire  clock;\n    \
                          input wire  [9:0] a;\n    input wire  b;\n    output reg  signed [17:0] y;\n    \
                          reg  [3:0] internal;\nendmodule // blk\nmodule blk$sub(d,q,clock);\n    input wire  [99:0] d;\nendmodule\n";

    #[test]
    fn ports_are_read_from_the_top_module_only() {
        let p = ports(SAMPLE, "blk").unwrap();
        let got: Vec<(&str, Dir, usize)> = p.iter().map(|p| (p.name.as_str(), p.dir, p.width)).collect();
        assert_eq!(got, [("clock", Dir::In, 1), ("a", Dir::In, 10), ("b", Dir::In, 1), ("y", Dir::Out, 18)]);
        assert!(ports(SAMPLE, "nope").is_err());
    }

    #[test]
    fn wrapper_chains_inputs_and_captures_outputs() {
        let w = wrap("blk", &ports(SAMPLE, "blk").unwrap());
        assert_eq!((w.in_bits, w.out_bits, w.top.as_str()), (11, 18, "blk_fpga_top"));
        assert!(w.verilog.contains("shelling_fpga_in <= {shelling_fpga_in[9:0], sin}"), "{}", w.verilog);
        assert!(
            w.verilog.contains(".a(shelling_fpga_in[9:0])")
                && w.verilog.contains(".b(shelling_fpga_in[10:10])")
        );
        assert!(
            w.verilog.contains(".y(block_out[17:0])")
                && w.verilog.contains("(* keep *) reg [17:0] shelling_fpga_cap_b;")
        );
    }

    #[test]
    fn an_array_entrys_inputs_are_one_stretch_of_the_chain() {
        let port = |name: &str, width| Port { name: name.into(), dir: Dir::In, width };
        let ports = [
            port("clock", 1),
            port("a$0", 2),
            port("a$1", 2),
            port("b$0", 3),
            port("b$1", 3),
            port("cfg", 1),
        ];
        let w = wrap("m", &ports);
        for conn in
            [".a$0(shelling_fpga_in[1:0])", ".b$0(shelling_fpga_in[4:2])", ".a$1(shelling_fpga_in[6:5])"]
        {
            assert!(w.verilog.contains(conn), "{conn} in {}", w.verilog);
        }
        assert!(w.verilog.contains(".cfg(shelling_fpga_in[10:10])"), "{}", w.verilog);
    }
}
