// Formal harness of the first-word-fall-through FIFO (`prim/fifo.rs`: `FifoControl` over one
// `FifoRam` lane), run by `fifo.sby` on the exported Verilog (`hdl/verilog/fwft_fifo.v`, top
// module `fwft_fifo`, 16 words of 8 bits). See `hdl/FORMAL.md`.
//
// What it proves, for every input sequence the block's contract allows (`push` and `data_in`
// free, but no push while 16 words are held; `pop` free, but only while `valid`):
//
// * `count` is the number of words pushed and not popped;
// * `valid` is high exactly while a word pushed before the previous edge is held (the lane reads
//   before it writes: two clocks from a push to `valid` on an empty FIFO);
// * no loss, duplication or reordering: the n-th word popped is the n-th word pushed, for every
//   n: the harness follows one word, chosen freely (`pick`), from its push to its pop, and
//   `data_out` is that word whenever it is the head and `valid` is high;
// * the head holds (`valid` and `data_out` stable) while it is not popped.
//
// With `mode prove` the proof is a k-induction: the control's count and pointers and the lane's
// words are made visible by `fifo.sby` (flatten, `memory_map`, `expose`), and the invariants
// below relate them to the harness's counts.

`default_nettype none

module fifo_formal (
    input wire       clock,
    input wire       push,
    input wire [7:0] data_in,
    input wire       pop,
    // Chooses the word the harness follows: the first pushed while `pick` is high and no word
    // is followed.
    input wire       pick
);
    localparam DEPTH = 16;

    wire       valid;
    wire [7:0] data_out;
    wire [4:0] count;
`ifdef INDUCTION
    wire [4:0] words;
    wire [3:0] tail_ptr, rd_ptr, rd_inc_x;
    wire [7:0] mem [0:15];
`endif

    fwft_fifo dut (
        .clock(clock), .push(push), .data_in(data_in), .pop(pop),
        .valid(valid), .data_out(data_out), .count(count)
`ifdef INDUCTION
        , .control_words_q(words), .control_tail_ptr_q(tail_ptr), .control_rd_ptr_q(rd_ptr),
        .control_rd_inc_x_q(rd_inc_x),
        .lane_mem_0_(mem[0]), .lane_mem_1_(mem[1]), .lane_mem_2_(mem[2]), .lane_mem_3_(mem[3]),
        .lane_mem_4_(mem[4]), .lane_mem_5_(mem[5]), .lane_mem_6_(mem[6]), .lane_mem_7_(mem[7]),
        .lane_mem_8_(mem[8]), .lane_mem_9_(mem[9]), .lane_mem_10_(mem[10]), .lane_mem_11_(mem[11]),
        .lane_mem_12_(mem[12]), .lane_mem_13_(mem[13]), .lane_mem_14_(mem[14]), .lane_mem_15_(mem[15])
`endif
    );

    // ---- The harness's counts, from the ports only. ----
    reg        f_past = 1'b0;    // not the first cycle
    reg [5:0]  f_held = 6'd0;    // words pushed, not yet popped
    reg        f_pp = 1'b0;      // a word was pushed at the previous edge
    reg        f_full = 1'b0;    // the FIFO has been full (for the covers)
    always @(posedge clock) begin
        f_past <= 1'b1;
        f_held <= f_held + push - pop;
        f_pp <= push;
        if (f_held == DEPTH) f_full <= 1'b1;
    end

    // ---- The contract (prim/fifo.rs, "Timing"): the user prevents both. ----
    always @(*) begin
        assume(!push || f_held != DEPTH);
        assume(!pop || valid);
    end

    // ---- The followed word. ----
    reg        f_trk = 1'b0;
    reg [7:0]  f_data = 8'd0;
    reg [5:0]  f_ahead = 6'd0;   // words to be popped before it
    wire       f_head = f_trk && f_ahead == 6'd0;
    wire       f_out = f_head && pop;
    always @(posedge clock) begin
        if (!f_trk) begin
            if (push && pick) begin
                f_trk <= 1'b1;
                f_data <= data_in;
                f_ahead <= f_held - pop;
            end
        end else if (pop) begin
            if (f_ahead == 6'd0) f_trk <= 1'b0;
            else f_ahead <= f_ahead - 6'd1;
        end
    end

    // ---- The properties (port level). ----
    always @(*) begin
        // The harness's own facts: never more than DEPTH held, and a word pushed at the last
        // edge is still held (it cannot have been popped: it was not valid yet).
        a_held: assert(f_held <= DEPTH && (!f_pp || f_held != 6'd0));
        a_count: assert({1'b0, count} == f_held);
        a_valid: assert(valid == (f_held - f_pp != 6'd0));
        // The followed word is the head's data whenever it is presented: so it leaves once, as
        // the n-th word out when it came as the n-th in, with its data.
        if (f_head && valid) a_order: assert(data_out == f_data);
    end
    always @(posedge clock) begin
        if (f_past && $past(valid && !pop)) begin
            a_hold: assert(valid);
            a_stable: assert($stable(data_out));
        end
    end

`ifdef INDUCTION
    // ---- Invariants over the internal state (the induction's strengthening). ----
    always @(*) begin
        i_words: assert(words == count);
        i_tail: assert(tail_ptr == rd_ptr + words[3:0]);
        i_rd_inc: assert(rd_inc_x == ((rd_ptr + 4'd1) ^ 4'd1));
        if (valid) i_head: assert(data_out == mem[rd_ptr]);
        if (f_trk) begin
            i_trk_held: assert(f_ahead < f_held);
            i_trk_data: assert(mem[rd_ptr + f_ahead[3:0]] == f_data);
        end
    end
`endif

    // ---- Covers: the environment is not over-constrained. ----
    always @(*) begin
        c_full_out: cover(f_out && f_full);
        c_push_pop: cover(f_out && push && f_held == DEPTH - 1);
    end
endmodule
