//! Block and LUT RAMs with a Rust model and a Verilog body that agree bit for bit, including
//! at power-up (every word zero, where rust-hdl's `RAM` reads `X` in Verilog):
//!
//! * [`Bram`]: a simple dual-port RAM, `2^A` words of `D ≤ 32` bits, registered read
//!   (read-before-write on the same address); infers block RAM (LUT RAM when small).
//! * [`BramOut`]: [`Bram`] with its read registered twice (two clocks from address to data); on
//!   ECP5 (`SHELLING_ECP5` defined) hand-instantiated `DP16KD`s with their output register on,
//!   0.96 ns from clock to data instead of 5.83.
//! * [`FifoRam`]: the storage of a first-word-fall-through FIFO, the head and the word after it
//!   read in every clock so that no read address depends on this clock's pop; on iCE40
//!   (`SHELLING_ICE40` defined) a second memory copy for the second read.

use super::clocked;
use rust_hdl::prelude::*;

/// Simple dual-port block RAM: `2^A` words of `D` bits (D ≤ 32), one write and one registered
/// read per clock, read-before-write, all words zero at power-up.
#[derive(LogicBlock)]
pub struct Bram<const D: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    pub read_address: Signal<In, Bits<A>>,
    pub read_data: Signal<Out, Bits<D>>,
    pub write_address: Signal<In, Bits<A>>,
    pub write_data: Signal<In, Bits<D>>,
    pub write_enable: Signal<In, bool>,
    _mem: Vec<u32>,
}

impl<const D: usize, const A: usize> Default for Bram<D, A> {
    fn default() -> Self {
        assert!(D <= 32, "Bram words are at most 32 bits");
        Bram {
            clock: Default::default(),
            read_address: Default::default(),
            read_data: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            _mem: vec![0; 1 << A],
        }
    }
}

impl<const D: usize, const A: usize> Logic for Bram<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.read_data.next = Bits::from(self._mem[self.read_address.val().index()] as u64);
            if self.write_enable.val() {
                self._mem[self.write_address.val().index()] = self.write_data.val().to_u32();
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
reg [{dm}:0] mem [0:{words}];
integer i;
initial begin
   for (i = 0; i <= {words}; i = i + 1) mem[i] = {d}'d0;
   read_data = {d}'d0;
end
always @(posedge clock) begin
   read_data <= mem[read_address];
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
",
            dm = D - 1,
            d = D,
            words = (1usize << A) - 1
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked("bram", &["read_address", "write_address", "write_data", "write_enable"], &["read_data"])
    }
}

/// The storage of a first-word-fall-through FIFO: `2^A` words of `D ≤ 32` bits (LUT RAM on an
/// FPGA), one write per clock and two registered reads, the head and the word after it, so that
/// no read address depends on this clock's pop.
///
/// Ports: `write_address`, `write_data`, `write_enable` (a write, seen by reads at later edges:
/// read before write); `head_address` (the FIFO's read pointer) and `next_address` (the read
/// pointer plus one), both sampled at every rising edge; `pop` (the head leaves in this clock);
/// out `read_data`, the word at the head after the edge: the `next_address` read when `pop` was
/// high at that edge, else the `head_address` read. So with the read pointer advanced on a pop,
/// `read_data` is always the word at the read pointer as of the previous clock's memory.
///
/// Latency one clock from address to `read_data`; one write and one pop per clock. `read_data`
/// is a function of registers only (two read registers and a registered `pop` before one
/// multiplexer): a consumer's `ready` that decides the pop reaches one flip-flop and the
/// read pointer, not the RAM's address pins (with a single read at `pop ? next : head` it ran
/// through the address multiplexer into every LUT RAM of the FIFO: 5.8 ns of routing in the
/// processing element). ECP5 synthesis duplicates the LUT RAM for the second read port. For
/// iCE40 (Verilog define `SHELLING_ICE40`, set by the FPGA flow) the body keeps a second copy of
/// the memory for that read, written alongside: with one memory and two reads Yosys' iCE40
/// mapping keeps 16-word lanes in flip-flops (the loader at 42 MHz instead of 65). All
/// words and registers are zero at power-up. The Rust `update` is the bit-true model.
///
/// [`FifoRam::head_registered`] makes a lane whose `read_data` is one register: the two words
/// are read without a clock (two LUT RAM reads by the address registers, from two copies of
/// the words so that no read address depends on the pop) and the pop chooses between them
/// before that register, so a consumer deciding from the head word sees a flip-flop, and the
/// pop reaches one multiplexer a bit. Meant for narrow lanes (a flag); the same model, cycle
/// for cycle.
#[derive(LogicBlock)]
pub struct FifoRam<const D: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    pub write_address: Signal<In, Bits<A>>,
    pub write_data: Signal<In, Bits<D>>,
    pub write_enable: Signal<In, bool>,
    pub head_address: Signal<In, Bits<A>>,
    pub next_address: Signal<In, Bits<A>>,
    pub pop: Signal<In, bool>,
    pub read_data: Signal<Out, Bits<D>>,
    _mem: Vec<u32>,
    /// The head word in one register (see [`FifoRam::head_registered`]): the Verilog body only.
    _head_registered: bool,
}

impl<const D: usize, const A: usize> FifoRam<D, A> {
    /// A lane whose `read_data` is a register of its own (see the type's documentation).
    pub fn head_registered() -> Self {
        FifoRam { _head_registered: true, ..Default::default() }
    }
}

impl<const D: usize, const A: usize> Default for FifoRam<D, A> {
    fn default() -> Self {
        assert!(D <= 32, "FifoRam words are at most 32 bits");
        FifoRam {
            clock: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            head_address: Default::default(),
            next_address: Default::default(),
            pop: Default::default(),
            read_data: Default::default(),
            _mem: vec![0; 1 << A],
            _head_registered: false,
        }
    }
}

impl<const D: usize, const A: usize> Logic for FifoRam<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let read = if self.pop.val() { self.next_address.val() } else { self.head_address.val() };
            self.read_data.next = Bits::from(self._mem[read.index()] as u64);
            if self.write_enable.val() {
                self._mem[self.write_address.val().index()] = self.write_data.val().to_u32();
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        if self._head_registered {
            return Verilog::Custom(format!(
                "\
// Two copies under the same writes, one read each: from one memory, Yosys makes the two reads
// one port whose address is chosen by `pop` (pop, address, RAM, register: measured 141 MHz).
reg [{dm}:0] mem [0:{words}];
reg [{dm}:0] mem_n [0:{words}];
reg [{dm}:0] read_r;
integer i;
initial begin
   for (i = 0; i <= {words}; i = i + 1) begin
      mem[i] = {d}'d0;
      mem_n[i] = {d}'d0;
   end
   read_r = {d}'d0;
end
always @(posedge clock) begin
   read_r <= pop ? mem_n[next_address] : mem[head_address];
   if (write_enable) begin
      mem[write_address] <= write_data;
      mem_n[write_address] <= write_data;
   end
end
always @(*) read_data = read_r;
",
                dm = D - 1,
                d = D,
                words = (1usize << A) - 1
            ));
        }
        Verilog::Custom(format!(
            "\
reg [{dm}:0] mem [0:{words}];
reg [{dm}:0] head_r;
reg [{dm}:0] next_r;
reg popped;
integer i;
`ifdef SHELLING_ICE40
// A copy for the second read (the same writes): one read port per memory.
reg [{dm}:0] mem_n [0:{words}];
initial for (i = 0; i <= {words}; i = i + 1) mem_n[i] = {d}'d0;
always @(posedge clock) begin
   next_r <= mem_n[next_address];
   if (write_enable) begin
      mem_n[write_address] <= write_data;
   end
end
`else
always @(posedge clock) next_r <= mem[next_address];
`endif
initial begin
   for (i = 0; i <= {words}; i = i + 1) mem[i] = {d}'d0;
   head_r = {d}'d0;
   next_r = {d}'d0;
   popped = 1'b0;
end
always @(posedge clock) begin
   head_r <= mem[head_address];
   popped <= pop;
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
always @(*) read_data = popped ? next_r : head_r;
",
            dm = D - 1,
            d = D,
            words = (1usize << A) - 1
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked(
            "fifo_ram",
            &["write_address", "write_data", "write_enable", "head_address", "next_address", "pop"],
            &["read_data"],
        )
    }
}

/// Simple dual-port block RAM with a two-clock registered read: `2^A` words of `D ≤ 32` bits,
/// one write and one read per clock, all words and both read registers zero at power-up. The
/// read address presented in one clock (sampled at its rising edge `t`) gives its word on
/// `read_data` after edge `t + 1`; a write presented in the same clock as that read and to the
/// same address is *not* seen by it (it is seen by reads sampled at later edges).
///
/// On ECP5 (Verilog define `SHELLING_ECP5`, set by the FPGA flow) its Verilog body instantiates
/// `DP16KD` tiles by hand, port A writing and port B reading with its output register
/// (`REGMODE_B = "OUTREG"`): about 1 ns clock-to-out instead of the 5.8 ns of the read Yosys'
/// memory mapping gives (always `NOREG`). Tile widths: 18 bits for `A ≤ 10`, 9 for `A = 11`, 4
/// for `A = 12`. Without the define (simulators, iCE40, the gate-level netlists of rung 5) the
/// body is the behavioural two-register read that the Rust `update` models bit for bit.
///
/// For formal harnesses only, the define `SHELLING_FORMAL_BRAM_WORDS` (a number `n`) keeps the
/// behavioural body's first `n` words and, in a `FORMAL` build, asserts that every read address
/// and every written address is below `n`: a harness whose design can only address `n` words
/// (the patch cache with `cfg_mask < n`, `cache.sby`) proves the same logic on arrays the
/// solver can handle, and the assertion proves it addressed nothing else.
///
/// **A read and a write of the same address in the same clock**: the block RAM's cross-port
/// result is undefined, so the model and the behavioural Verilog both return a poison word, the
/// bitwise NOT of the word before the write: a design relying on that read fails its tests. A
/// user must forward over the write instead.
#[derive(LogicBlock)]
pub struct BramOut<const D: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    pub read_address: Signal<In, Bits<A>>,
    pub read_data: Signal<Out, Bits<D>>,
    pub write_address: Signal<In, Bits<A>>,
    pub write_data: Signal<In, Bits<D>>,
    pub write_enable: Signal<In, bool>,
    _mem: Vec<u32>,
    /// The first read register (the block RAM's latch stage).
    _r1: u32,
}

impl<const D: usize, const A: usize> Default for BramOut<D, A> {
    fn default() -> Self {
        assert!(D <= 32, "BramOut words are at most 32 bits");
        assert!(A <= 12, "BramOut has at most 4096 words");
        BramOut {
            clock: Default::default(),
            read_address: Default::default(),
            read_data: Default::default(),
            write_address: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            _mem: vec![0; 1 << A],
            _r1: 0,
        }
    }
}

/// The DP16KD data width per tile of a `BramOut` with `a` address bits.
pub fn bram_out_tile_width(a: usize) -> usize {
    match a {
        0..=10 => 18,
        11 => 9,
        _ => 4,
    }
}

impl<const D: usize, const A: usize> BramOut<D, A> {
    /// The word the read of `read` returns when `write` (address, enabled) is presented in the
    /// same clock: the memory's word, or its bitwise NOT on a same-address collision.
    fn read_word(&self, read: usize, write: Option<usize>) -> u32 {
        let mask = if D == 32 { u32::MAX } else { (1u32 << D) - 1 };
        let w = self._mem[read];
        if write == Some(read) {
            !w & mask
        } else {
            w
        }
    }

    fn ecp5_body() -> String {
        let w = bram_out_tile_width(A);
        let tiles = D.div_ceil(w);
        // Address pins: the address in the top bits (13 down), the rest zero, except the two
        // byte enables of an 18-bit write port.
        let lsb = match w {
            18 => 4,
            9 => 3,
            _ => 2,
        };
        let abits = 14 - lsb; // address bits the tile uses
        let mut v = String::new();
        v += &format!("wire [{}:0] bo_rd;\n", tiles * w - 1);
        let pad = tiles * w - D;
        if pad == 0 {
            v += &format!("wire [{}:0] bo_wd = write_data;\n", tiles * w - 1);
        } else {
            v += &format!("wire [{}:0] bo_wd = {{{pad}'d0, write_data}};\n", tiles * w - 1);
        }
        v += &format!("wire [{}:0] bo_ra = read_address;\n", abits - 1);
        v += &format!("wire [{}:0] bo_wa = write_address;\n", abits - 1);
        for t in 0..tiles {
            v += &format!(
                "DP16KD #(.DATA_WIDTH_A({w}), .DATA_WIDTH_B({w}), .REGMODE_A(\"NOREG\"), \
.REGMODE_B(\"OUTREG\"), .RESETMODE(\"SYNC\"), .ASYNC_RESET_RELEASE(\"SYNC\"), \
.CSDECODE_A(\"0b000\"), .CSDECODE_B(\"0b000\"), .WRITEMODE_A(\"NORMAL\"), \
.WRITEMODE_B(\"NORMAL\"), .GSR(\"DISABLED\")) bo_tile{t} (\n"
            );
            v += "   .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),\n";
            v += "   .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),\n";
            v += "   .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),\n";
            v += "   .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0)";
            for (port, addr) in [("A", "bo_wa"), ("B", "bo_ra")] {
                for pin in 0..14 {
                    let s = if pin >= lsb {
                        format!("{addr}[{}]", pin - lsb)
                    } else if w == 18 && pin < 2 && port == "A" {
                        "1'b1".to_string()
                    } else {
                        "1'b0".to_string()
                    };
                    v += &format!(",\n   .AD{port}{pin}({s})");
                }
            }
            for bit in 0..w {
                v += &format!(",\n   .DIA{bit}(bo_wd[{}]), .DOB{bit}(bo_rd[{}])", t * w + bit, t * w + bit);
            }
            for bit in w..18 {
                v += &format!(",\n   .DIA{bit}(1'b0)");
            }
            v += ",\n   .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), \
.DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), \
.DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)\n);\n";
        }
        v += &format!("always @(*) read_data = bo_rd[{}:0];\n", D - 1);
        v
    }
}

impl<const D: usize, const A: usize> Logic for BramOut<D, A> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.read_data.next = Bits::from(self._r1 as u64);
            let write = self.write_enable.val().then(|| self.write_address.val().index());
            self._r1 = self.read_word(self.read_address.val().index(), write);
            if let Some(a) = write {
                self._mem[a] = self.write_data.val().to_u32();
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
`ifdef SHELLING_ECP5
{ecp5}`else
// `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
// first ones, and a FORMAL build asserts that no address beyond them is used.
`ifdef SHELLING_FORMAL_BRAM_WORDS
localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
`else
localparam WORDS = {words1};
`endif
reg [{dm}:0] mem [0:WORDS-1];
reg [{dm}:0] r1;
reg collided;
integer i;
`ifdef FORMAL
always @(*) begin
   a_bram_read_address: assert(read_address < WORDS);
   if (write_enable) a_bram_write_address: assert(write_address < WORDS);
end
`endif
initial begin
   for (i = 0; i < WORDS; i = i + 1) mem[i] = {d}'d0;
   r1 = {d}'d0;
   collided = 1'b0;
   read_data = {d}'d0;
end
always @(posedge clock) begin
   // A plain registered read (read before write), so that synthesis infers block RAM; a read
   // and a write of the same address in one clock are poisoned after the read register (see
   // the Rust docs).
   r1 <= mem[read_address];
   collided <= write_enable && write_address == read_address;
   read_data <= collided ? ~r1 : r1;
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
`endif
",
            ecp5 = Self::ecp5_body(),
            dm = D - 1,
            d = D,
            words1 = 1usize << A
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        clocked("bram_out", &["read_address", "write_address", "write_data", "write_enable"], &["read_data"])
    }
}

#[cfg(test)]
mod bram_out_tests {
    use super::BramOut;
    use rust_hdl::core::prelude::simulate;
    use rust_hdl::prelude::*;

    /// One clock of a `BramOut`: inputs set while the clock is low, then the rising edge.
    fn clock<const D: usize, const A: usize>(m: &mut BramOut<D, A>, ra: u64, w: Option<(u64, u64)>) {
        m.clock.next = false.into();
        m.read_address.next = ra.into();
        m.write_enable.next = w.is_some();
        if let Some((a, d)) = w {
            m.write_address.next = a.into();
            m.write_data.next = d.into();
        }
        assert!(simulate(m, 100));
        m.clock.next = true.into();
        assert!(simulate(m, 100));
    }

    fn out<const D: usize, const A: usize>(m: &BramOut<D, A>) -> u64 {
        m.read_data.val().to_u64()
    }

    /// Two-clock read, zero at power-up, a write seen by reads sampled at later edges only, and
    /// the poison of a same-address read and write.
    #[test]
    fn two_clock_read_and_poison() {
        let mut m = BramOut::<17, 10>::default();
        m.connect_all();
        clock(&mut m, 5, Some((5, 0x1_2345))); // edge 0: read 5 (collision: poison of 0), write 5
        assert_eq!(out(&m), 0, "power-up");
        clock(&mut m, 5, None); // edge 1: read 5 again
        assert_eq!(out(&m), 0x1_ffff, "edge 0's read, one clock later: the poison (NOT of 0)");
        clock(&mut m, 6, Some((7, 3))); // edge 2
        assert_eq!(out(&m), 0x1_2345, "edge 1's read sees edge 0's write");
        clock(&mut m, 7, None); // edge 3
        assert_eq!(out(&m), 0, "ray 6 was never written");
        clock(&mut m, 7, Some((7, 9))); // edge 4: collision, old word 3
        assert_eq!(out(&m), 3);
        clock(&mut m, 0, None);
        assert_eq!(out(&m), !3u64 & 0x1_ffff, "poison: NOT of the old word");
        clock(&mut m, 0, None);
        assert_eq!(out(&m), 0);
    }

    /// The Verilog body has both branches, and the ECP5 one has one `DP16KD` per 18 bits with
    /// the output register.
    #[test]
    fn verilog_has_the_ecp5_tiles() {
        let m = BramOut::<32, 10>::default();
        let Verilog::Custom(v) = m.hdl() else { panic!("custom Verilog") };
        assert!(v.contains("`ifdef SHELLING_ECP5") && v.contains("`else") && v.contains("`endif"));
        assert_eq!(v.matches("DP16KD #(").count(), 2);
        assert_eq!(v.matches("REGMODE_B(\"OUTREG\")").count(), 2);
        assert_eq!(super::bram_out_tile_width(11), 9);
        let m = BramOut::<9, 11>::default();
        let Verilog::Custom(v) = m.hdl() else { panic!("custom Verilog") };
        assert_eq!(v.matches("DP16KD #(").count(), 1);
    }
}
