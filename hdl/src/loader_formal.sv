// Formal harness of the patch loader (`loader.rs`), run by `loader.sby` on the exported Verilog
// (`hdl/verilog/patch_loader.v`, top module `patch_loader`). See `hdl/FORMAL.md`.
//
// What it proves, for every input sequence the documented protocol allows (all inputs are free
// in every cycle; the only assumption is the memory port's protocol):
//
// * no overflow: at most DEPTH (16) patches are ever held (accepted and not yet sent out), and
//   `id_ready` is high exactly while fewer than 16 are held;
// * no underflow: `out_valid` is high exactly while a fetched patch is held whose response came
//   at least one cycle ago (so nothing is sent that was not fetched, and nothing fetched waits);
// * each accepted id is requested exactly once, in the next cycle, with `mem_addr` = the id;
// * no loss, duplication or reordering: the n-th patch out is the n-th id in, with the
//   coordinates of the n-th memory response (which, responses being in request order, is the
//   response to that id's request), for every n: the harness follows one patch, chosen freely
//   (`pick`), from its acceptance to its transfer out;
// * the output holds (`out_valid` and the data stable) while it waits for `out_ready`;
// * `loads` equals the number of memory responses.
//
// With `mode prove` the proof is a k-induction: the block's counters, pointers and FIFO lanes
// are made visible to the harness by the script in `loader.sby` (flatten, `memory_map`,
// `expose`), and the invariants below relate them to the harness's counts. They are
// assertions like the others: checked in the base case, assumed only in the induction step.

`default_nettype none

// Sixteen port connections `.lane_mem_<i>_(arr[i])` of one exposed FIFO lane.
`define LANE16(lane, arr) \
    .lane``_mem_0_(arr[0]), .lane``_mem_1_(arr[1]), .lane``_mem_2_(arr[2]), .lane``_mem_3_(arr[3]), \
    .lane``_mem_4_(arr[4]), .lane``_mem_5_(arr[5]), .lane``_mem_6_(arr[6]), .lane``_mem_7_(arr[7]), \
    .lane``_mem_8_(arr[8]), .lane``_mem_9_(arr[9]), .lane``_mem_10_(arr[10]), .lane``_mem_11_(arr[11]), \
    .lane``_mem_12_(arr[12]), .lane``_mem_13_(arr[13]), .lane``_mem_14_(arr[14]), .lane``_mem_15_(arr[15])

module loader_formal (
    input wire        clock,
    // The environment: free in every cycle.
    input wire        id_valid,
    input wire [15:0] id,
    input wire        mem_valid,
    input wire [16:0] mem_ax,
    input wire [16:0] mem_ay,
    input wire [16:0] mem_bx,
    input wire [16:0] mem_by,
    input wire        out_ready,
    // Chooses the patch the harness follows: the first id accepted while `pick` is high and no
    // patch is followed.
    input wire        pick
);
    localparam DEPTH = 16;

    wire        id_ready, id_ready_next, mem_req, out_valid;
    wire [15:0] mem_addr, out_id;
    wire [16:0] out_ax, out_ay, out_bx, out_by;
    wire [31:0] loads;
    // Internal state, exposed by loader.sby (not ports of the exported module).
    wire [4:0]  reserved, done;
    // `done`, `resp_ptr`, `rd_ptr` and `rd_inc_x` (rd_ptr + 1 with bit 0 inverted) are the
    // FIFO control's word count, tail, head and next read address (`prim::FifoControl`).
    wire [3:0]  req_ptr, resp_ptr, rd_ptr, rd_inc_x;
    wire [15:0] lane_id [0:15];
    wire [16:0] lane_ax [0:15];
    wire [16:0] lane_ay [0:15];
    wire [16:0] lane_bx [0:15];
    wire [16:0] lane_by [0:15];

    patch_loader dut (
        .clock(clock),
        .id_valid(id_valid), .id_ready(id_ready), .id(id), .id_ready_next(id_ready_next),
        .mem_req(mem_req), .mem_addr(mem_addr), .mem_valid(mem_valid),
        .mem_ax(mem_ax), .mem_ay(mem_ay), .mem_bx(mem_bx), .mem_by(mem_by),
        .out_valid(out_valid), .out_ready(out_ready), .out_id(out_id),
        .out_ax(out_ax), .out_ay(out_ay), .out_bx(out_bx), .out_by(out_by),
        .loads(loads)
`ifdef INDUCTION
        , .reserved$q(reserved), .fifo_words_q(done),
        .req_ptr$q(req_ptr), .fifo_tail_ptr_q(resp_ptr), .fifo_rd_ptr_q(rd_ptr),
        .fifo_rd_inc_x_q(rd_inc_x),
        `LANE16(lane_id, lane_id), `LANE16(lane_ax, lane_ax), `LANE16(lane_ay, lane_ay),
        `LANE16(lane_bx, lane_bx), `LANE16(lane_by, lane_by)
`endif
    );

    // Transfers, as the module documentation defines them: `valid && ready` before the edge.
    wire accept = id_valid && id_ready;
    wire pop = out_valid && out_ready;

    // ---- The harness's counts, from the ports only. ----
    reg        f_past = 1'b0;     // not the first cycle
    reg [5:0]  f_held = 6'd0;     // ids accepted, patch not yet sent out
    reg [5:0]  f_unresp = 6'd0;   // ids accepted, memory response not yet received
    reg [5:0]  f_outst = 6'd0;    // requests issued, response not yet received
    reg        f_mv = 1'b0;       // a memory response came in the previous cycle
    reg [31:0] f_loads = 32'd0;   // memory responses
    reg        f_full = 1'b0;     // the FIFO has been full (for the covers)
    wire [5:0] f_filled = f_held - f_unresp;  // held patches whose response has come

    always @(posedge clock) begin
        f_past <= 1'b1;
        f_held <= f_held + accept - pop;
        f_unresp <= f_unresp + accept - mem_valid;
        f_outst <= f_outst + mem_req - mem_valid;
        f_mv <= mem_valid;
        f_loads <= f_loads + mem_valid;
        if (!id_ready) f_full <= 1'b1;
    end

    // ---- The environment's only obligation: the memory port protocol. ----
    // loader.rs, "The memory port": the memory answers every request exactly once, in request
    // order, T_c >= 1 cycles after it; "a `mem_valid` without an outstanding request is a
    // protocol violation". Responses are matched to requests by order, so this is the whole
    // constraint; the response data are free (the proof is that they are passed on unchanged).
    always @(*) assume(!mem_valid || f_outst != 6'd0);

    // ---- The followed patch. ----
    reg        f_trk = 1'b0;      // following a patch that has been accepted, not yet sent out
    reg        f_resp = 1'b0;     // its memory response has come
    reg [15:0] f_id = 16'd0;
    reg [16:0] f_ax = 17'd0, f_ay = 17'd0, f_bx = 17'd0, f_by = 17'd0;
    reg [5:0]  f_ahead = 6'd0;    // patches to be sent out before it
    reg [5:0]  f_pend = 6'd0;     // memory responses to come before its own
    wire       f_out = f_trk && pop && f_ahead == 6'd0;  // it is sent out in this cycle

    always @(posedge clock) begin
        if (!f_trk) begin
            if (accept && pick) begin
                f_trk <= 1'b1;
                f_resp <= 1'b0;
                f_id <= id;
                f_ahead <= f_held - pop;
                f_pend <= f_unresp - mem_valid;
            end
        end else begin
            if (mem_valid && !f_resp) begin
                if (f_pend == 6'd0) begin
                    f_resp <= 1'b1;
                    f_ax <= mem_ax;
                    f_ay <= mem_ay;
                    f_bx <= mem_bx;
                    f_by <= mem_by;
                end else begin
                    f_pend <= f_pend - 6'd1;
                end
            end
            if (pop) begin
                if (f_ahead == 6'd0) f_trk <= 1'b0;
                else f_ahead <= f_ahead - 6'd1;
            end
        end
    end

    // ---- The properties (port level). ----
    always @(*) begin
        // No overflow: never more than DEPTH patches held; ids are taken exactly while there is
        // room (loader.rs: "an id is accepted only while fewer than DEPTH slots are reserved").
        a_overflow: assert(f_held <= DEPTH);
        a_id_ready: assert(id_ready == (f_held != DEPTH));
        // No underflow, no stuck patch: a patch is presented exactly when one is held whose
        // response came before this cycle (the block RAM reads before it writes).
        a_out_valid: assert(out_valid == (f_filled - f_mv != 6'd0));
        a_underflow: assert(!out_valid || f_filled != 6'd0);
        // Every accepted id is requested: accepted ids without a response are either in flight
        // at the memory or requested in this cycle.
        a_requests: assert(f_outst <= f_unresp && f_unresp == f_outst + mem_req);
        a_loads: assert(loads == f_loads);
        // No loss, duplication or reordering: the followed patch leaves as the n-th output when
        // it came as the n-th id, after its response, with its id and its response's data.
        if (f_out) begin
            a_fetched: assert(f_resp);
            a_order_id: assert(out_id == f_id);
            a_order_data: assert(out_ax == f_ax && out_ay == f_ay && out_bx == f_bx && out_by == f_by);
        end
    end

    always @(posedge clock) begin
        if (f_past) begin
            // One request per accepted id, in the next cycle, for that id.
            a_request_next: assert(mem_req == $past(accept));
            // `id_ready_next` is `id_ready` one edge ahead (the PE keeps its ready in a register).
            a_ready_next: assert(id_ready == $past(id_ready_next));
            if (mem_req) a_request_addr: assert(mem_addr == $past(id));
            // A presented patch stays, unchanged, until it is taken.
            if ($past(out_valid && !out_ready)) begin
                a_out_hold: assert(out_valid);
                a_out_stable: assert($stable(out_id) && $stable(out_ax) && $stable(out_ay)
                                     && $stable(out_bx) && $stable(out_by));
            end
        end
    end

`ifdef INDUCTION
    // ---- Invariants over the internal state (the induction's strengthening). ----
    wire [3:0] f_slot = rd_ptr + f_ahead[3:0];  // the followed patch's slot
    always @(*) begin
        // The counters are the harness's counts.
        // The id accepted at the last edge is in the request registers (`mem_req`,
        // `mem_addr`), its slot reserved at the next edge.
        i_reserved: assert(reserved + mem_req == f_held[4:0] && (!mem_req || f_held != 6'd0));
        i_done: assert(done == f_filled[4:0] && f_unresp <= f_held);
        // The pointers: slots rd_ptr .. rd_ptr + done - 1 are filled, up to rd_ptr + reserved - 1
        // reserved (their id written).
        i_req_ptr: assert(req_ptr == rd_ptr + reserved[3:0]);
        i_resp_ptr: assert(resp_ptr == rd_ptr + done[3:0]);
        i_rd_inc: assert(rd_inc_x == ((rd_ptr + 4'd1) ^ 4'd1));
        // The read registers show the head slot whenever they are presented.
        if (out_valid) begin
            i_head: assert(out_id == lane_id[rd_ptr] && out_ax == lane_ax[rd_ptr]
                           && out_ay == lane_ay[rd_ptr] && out_bx == lane_bx[rd_ptr]
                           && out_by == lane_by[rd_ptr]);
        end
        // The followed patch sits in its slot; responses come in order, so the filled slots
        // are all ahead of it until its own response has come.
        if (f_trk) begin
            i_trk_held: assert(f_ahead < f_held);
            if (mem_req && f_ahead == f_held - 6'd1) i_trk_req: assert(mem_addr == f_id);
            else i_trk_id: assert(lane_id[f_slot] == f_id);
            if (f_resp) begin
                i_trk_filled: assert(f_ahead < f_filled);
                i_trk_data: assert(lane_ax[f_slot] == f_ax && lane_ay[f_slot] == f_ay
                                   && lane_bx[f_slot] == f_bx && lane_by[f_slot] == f_by);
            end else begin
                i_trk_pending: assert(f_ahead == f_filled + f_pend && f_pend < f_unresp);
            end
        end
    end

`endif

    // ---- Covers: the environment is not over-constrained. ----
    always @(*) begin
        // The FIFO full of fetched patches, the output waiting.
        c_full: cover(f_filled == DEPTH && !id_ready && out_valid);
        // The followed patch leaves after the FIFO has been full.
        c_out_after_full: cover(f_out && f_full);
        // A patch leaves while the FIFO takes an id and receives a response (full throughput).
        c_out_accept_resp: cover(f_out && accept && mem_valid);
    end
endmodule
