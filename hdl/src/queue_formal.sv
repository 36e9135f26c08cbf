// Formal harness of the processing element's job queue (`queue.rs`: `FifoControl` over eight
// `FifoRam` lanes, 16 jobs), run by `queue.sby` on the exported Verilog
// (`hdl/verilog/job_queue.v`, top module `job_queue`). See `hdl/FORMAL.md`.
//
// For every input sequence (every input free in every cycle; the queue decides its transfers
// by its own `in_ready`), bounded:
//
// * `in_ready` is high exactly while fewer than 16 jobs are held, `occupied` while any is;
// * `out_valid` is high exactly while a job taken before the last two edges is held (a job
//   taken waits one clock in the input register, then one in the lanes' read registers);
// * no loss, duplication or reordering, and no field mixed up between jobs: the harness follows
//   one job, chosen freely (`pick`), from its transfer in to its transfer out, and every
//   `out_*` field is that job's whenever it is the head and `out_valid` is high;
// * the head holds (`out_valid` and every field stable) while it is not taken.
//
// With `mode prove` (task `prove`) this is a k-induction, for all time: `queue.sby` makes the
// control's count and pointers and the eight lanes' words visible (flatten, `memory_map`,
// `expose`), and the invariants below relate them to the harness's counts and to the followed
// job, as `fifo_formal.sv` does for the FIFO block of one lane.

`default_nettype none

// Sixteen port connections `.lane_mem_<i>_(arr[i])` of one exposed lane.
`define LANE16(lane, arr) \
    .lane``_mem_0_(arr[0]), .lane``_mem_1_(arr[1]), .lane``_mem_2_(arr[2]), .lane``_mem_3_(arr[3]), \
    .lane``_mem_4_(arr[4]), .lane``_mem_5_(arr[5]), .lane``_mem_6_(arr[6]), .lane``_mem_7_(arr[7]), \
    .lane``_mem_8_(arr[8]), .lane``_mem_9_(arr[9]), .lane``_mem_10_(arr[10]), .lane``_mem_11_(arr[11]), \
    .lane``_mem_12_(arr[12]), .lane``_mem_13_(arr[13]), .lane``_mem_14_(arr[14]), .lane``_mem_15_(arr[15])

module queue_formal (
    input wire        clock,
    input wire        in_valid,
    input wire [15:0] in_id,
    input wire [17:0] in_ax,
    input wire [17:0] in_ay,
    input wire [17:0] in_bx,
    input wire [17:0] in_by,
    input wire [17:0] in_wx,
    input wire [17:0] in_wy,
    input wire [5:0]  in_sh,
    input wire [10:0] in_first,
    input wire [10:0] in_count,
    input wire        in_retire,
    input wire        out_ready,
    // Chooses the job the harness follows: the first taken while `pick` is high and no job is
    // followed.
    input wire        pick
);
    localparam DEPTH = 16;

    wire        in_ready, out_valid, out_retire, occupied;
    wire [15:0] out_id;
    wire [17:0] out_ax, out_ay, out_bx, out_by, out_wx, out_wy;
    wire [5:0]  out_sh;
    wire [10:0] out_first;
    wire [10:0] out_count;
`ifdef INDUCTION
    wire [4:0]  words;
    wire [3:0]  tail_ptr, rd_ptr, rd_inc_x;
    wire [15:0] m_id [0:15];
    wire [17:0] m_ax [0:15], m_ay [0:15], m_bx [0:15], m_by [0:15], m_wx [0:15], m_wy [0:15];
    wire [28:0] m_job [0:15];
    // The input register (the job taken at the last edge) and the held count.
    wire        p_valid, held_full;
    wire [15:0] p_id;
    wire [17:0] p_ax, p_ay, p_bx, p_by, p_wx, p_wy;
    wire [28:0] p_job;
    wire [4:0]  held;
`endif

    job_queue dut (
        .clock(clock), .in_valid(in_valid), .in_ready(in_ready), .in_id(in_id),
        .in_ax(in_ax), .in_ay(in_ay), .in_bx(in_bx), .in_by(in_by), .in_wx(in_wx), .in_wy(in_wy),
        .in_sh(in_sh), .in_first(in_first), .in_count(in_count), .in_retire(in_retire),
        .out_valid(out_valid), .out_ready(out_ready), .out_id(out_id),
        .out_ax(out_ax), .out_ay(out_ay), .out_bx(out_bx), .out_by(out_by), .out_wx(out_wx),
        .out_wy(out_wy), .out_sh(out_sh), .out_first(out_first), .out_count(out_count),
        .out_retire(out_retire), .occupied(occupied)
`ifdef INDUCTION
        , .control_words_q(words), .control_tail_ptr_q(tail_ptr), .control_rd_ptr_q(rd_ptr),
        .control_rd_inc_x_q(rd_inc_x),
        `LANE16(lane_id, m_id), `LANE16(lane_ax, m_ax), `LANE16(lane_ay, m_ay),
        `LANE16(lane_bx, m_bx), `LANE16(lane_by, m_by), `LANE16(lane_wx, m_wx),
        `LANE16(lane_wy, m_wy), `LANE16(lane_job, m_job),
        .p_valid$q(p_valid), .p_id$q(p_id), .p_ax$q(p_ax), .p_ay$q(p_ay), .p_bx$q(p_bx),
        .p_by$q(p_by), .p_wx$q(p_wx), .p_wy$q(p_wy), .p_job$q(p_job), .held$q(held),
        .held_full$q(held_full)
`endif
    );

    // A job as one word: every field, in port order.
    wire [171:0] in_job = {in_id, in_ax, in_ay, in_bx, in_by, in_wx, in_wy, in_sh, in_first,
                           in_count, in_retire};
    wire [171:0] out_job = {out_id, out_ax, out_ay, out_bx, out_by, out_wx, out_wy, out_sh,
                            out_first, out_count, out_retire};
    wire take = in_valid && in_ready;
    wire give = out_valid && out_ready;

    // ---- The harness's counts, from the ports only. ----
    reg        f_past = 1'b0;
    reg [5:0]  f_held = 6'd0;    // jobs taken, not yet given
    reg        f_tp = 1'b0;      // a job was taken at the previous edge
    reg        f_tp2 = 1'b0;     // a job was taken at the edge before
    reg        f_full = 1'b0;    // the queue has been full (for the covers)
    always @(posedge clock) begin
        f_past <= 1'b1;
        f_held <= f_held + take - give;
        f_tp <= take;
        f_tp2 <= f_tp;
        if (f_held == DEPTH) f_full <= 1'b1;
    end

    // ---- The followed job. ----
    reg         f_trk = 1'b0;
    reg [171:0] f_job = 172'd0;
    reg [5:0]   f_ahead = 6'd0;  // jobs to leave before it
    wire        f_head = f_trk && f_ahead == 6'd0;
    always @(posedge clock) begin
        if (!f_trk) begin
            if (take && pick) begin
                f_trk <= 1'b1;
                f_job <= in_job;
                f_ahead <= f_held - give;
            end
        end else if (give) begin
            if (f_ahead == 6'd0) f_trk <= 1'b0;
            else f_ahead <= f_ahead - 6'd1;
        end
    end

    // ---- The properties. ----
    always @(*) begin
        a_held: assert(f_held <= DEPTH && f_tp + f_tp2 <= f_held);
        a_in_ready: assert(in_ready == (f_held != DEPTH));
        a_occupied: assert(occupied == (f_held != 6'd0));
        a_valid: assert(out_valid == (f_held - f_tp - f_tp2 != 6'd0));
        if (f_trk) a_ahead: assert(f_ahead < f_held);
        if (f_head && out_valid) a_order: assert(out_job == f_job);
    end
    always @(posedge clock) begin
        if (f_past && $past(out_valid && !out_ready)) begin
            a_hold: assert(out_valid);
            a_stable: assert($stable(out_job));
        end
    end

`ifdef INDUCTION
    // ---- Invariants over the internal state (the induction's strengthening). ----
    // Slot i of the lanes as a job, fields in port order (the fourth lane unpacked: sh in bits
    // 23..28, retire in 22, first in 11..21, count in 0..10).
    wire [171:0] m [0:15];
    genvar i;
    generate
        for (i = 0; i < 16; i = i + 1) begin : slot
            assign m[i] = {m_id[i], m_ax[i], m_ay[i], m_bx[i], m_by[i], m_wx[i], m_wy[i],
                           m_job[i][28:23], m_job[i][21:11], m_job[i][10:0], m_job[i][22]};
        end
    endgenerate
    // The input register as a job.
    wire [171:0] p = {p_id, p_ax, p_ay, p_bx, p_by, p_wx, p_wy, p_job[28:23], p_job[21:11],
                      p_job[10:0], p_job[22]};
    always @(*) begin
        i_held: assert({1'b0, held} == f_held && held_full == (f_held == DEPTH));
        i_p_valid: assert(p_valid == f_tp);
        i_words: assert({1'b0, words} == f_held - p_valid);
        i_tail: assert(tail_ptr == rd_ptr + words[3:0]);
        i_rd_inc: assert(rd_inc_x == ((rd_ptr + 4'd1) ^ 4'd1));
        if (out_valid) i_head: assert(out_job == m[rd_ptr]);
        // The followed job: in the input register when it is the last taken and was taken at
        // the last edge, else in its slot.
        if (f_trk && p_valid && f_ahead == f_held - 6'd1) i_trk_p: assert(p == f_job);
        else if (f_trk) i_trk_job: assert(m[rd_ptr + f_ahead[3:0]] == f_job);
    end
`endif

    // ---- Covers: the environment is not over-constrained. ----
    always @(*) begin
        c_full_out: cover(f_head && give && f_full);
        c_take_give_full: cover(give && take && f_held == DEPTH - 1);
    end
endmodule
