// Formal harness of the backface screener (`screener.rs`), run by `screener.sby` on the exported
// Verilog (`hdl/verilog/screener.v`, top module `screener`). See `hdl/FORMAL.md`.
//
// Every input is free in every cycle: bundle setup, patch stream, `out_ready` and `pick`. There
// is no `assume` at all: the handshake needs none (the documented rule that the bundle setup is
// held while its patches stream matters only for the verdicts' values, which the simulation
// tests check bit for bit against the model; here any verdict may come of any setup). The
// script (screener.sby) also cuts the ten products and the divider's quotients free, which only
// widens the behaviours checked (the verdicts and the `W` words become arbitrary).
//
// Proved for all time (task `prove`, k-induction with k = 2, INDUCTION defined: the internal
// invariants below are asserted in the base case and assumed only in the induction step):
//
// * credits: at most DEPTH (32) patches are in flight (accepted, not yet out), and `in_ready`
//   is high exactly while fewer are (a_credits, a_in_ready);
// * no output without an input: `out_valid` only while a patch is in flight (a_no_spurious);
// * every patch is counted in exactly one verdict counter, once, a cycle after its verdict
//   (COUNT_LATENCY = 9 cycles after acceptance, shown from the next cycle on): the counters
//   start at zero and only ever grow by one, at most one of them in a cycle, and one exactly
//   when a patch was taken ten cycles before (a_counters_init, a_count_step, a_count_one,
//   a_count_when); so the five counters sum to the number of patches taken at least ten
//   cycles ago;
// * the output holds (`out_valid`, `out_id`, `out_pass`, `out_sh` stable) while it waits for
//   `out_ready`, and `in_ready` is not withdrawn without a transfer (a_out_hold, a_out_stable,
//   a_in_hold).
//
// Proved to depth 34 only (task `bmc`: every input sequence of 34 cycles; the latency, 28, plus
// six cycles, so a patch accepted in the first six cycles is followed out under any
// backpressure), besides all the above:
//
// * every patch that enters leaves exactly once, in order: the n-th patch out is the n-th in
//   (the harness follows one patch, chosen freely by `pick`; a_ahead, a_order); it is presented
//   exactly from LATENCY (28) cycles after its acceptance on, as soon as the patches before it
//   have left (a_latency);
// * it leaves passed (`out_pass` set) exactly when its verdict was counted in `passed`, and
//   screened out otherwise, counted in one of the other four (a_pass with the counting
//   properties): passed or counted as screened.
//
// The bound does not reach a full FIFO (32 patches) or the wrap of its 5-bit pointers; the
// induction covers those for the credit, pointer and head invariants (i_used .. i_head), but
// not for the followed patch's identity (its invariants i_trk_* are written below, but the
// induction step with them did not finish in 200-240 s here, so screener.sby removes them).
//
// Covers (task `cover`, depth 40): a full FIFO stalling the input, the followed patch leaving
// passed and screened out, and a patch leaving while another enters after all credits were
// taken. Mutants (`mutant_count`, `mutant_lost`, expected to FAIL): the passed counter never
// incremented is caught by a_count_when; the FIFO's id lane never written by a_order.

`default_nettype none

// Thirty-two port connections `.lane_mem_<i>_(arr[i])` of one exposed FIFO lane.
`define LANE32(lane, arr) \
    .lane``_mem_0_(arr[0]), .lane``_mem_1_(arr[1]), .lane``_mem_2_(arr[2]), .lane``_mem_3_(arr[3]), \
    .lane``_mem_4_(arr[4]), .lane``_mem_5_(arr[5]), .lane``_mem_6_(arr[6]), .lane``_mem_7_(arr[7]), \
    .lane``_mem_8_(arr[8]), .lane``_mem_9_(arr[9]), .lane``_mem_10_(arr[10]), .lane``_mem_11_(arr[11]), \
    .lane``_mem_12_(arr[12]), .lane``_mem_13_(arr[13]), .lane``_mem_14_(arr[14]), .lane``_mem_15_(arr[15]), \
    .lane``_mem_16_(arr[16]), .lane``_mem_17_(arr[17]), .lane``_mem_18_(arr[18]), .lane``_mem_19_(arr[19]), \
    .lane``_mem_20_(arr[20]), .lane``_mem_21_(arr[21]), .lane``_mem_22_(arr[22]), .lane``_mem_23_(arr[23]), \
    .lane``_mem_24_(arr[24]), .lane``_mem_25_(arr[25]), .lane``_mem_26_(arr[26]), .lane``_mem_27_(arr[27]), \
    .lane``_mem_28_(arr[28]), .lane``_mem_29_(arr[29]), .lane``_mem_30_(arr[30]), .lane``_mem_31_(arr[31])

module screener_formal (
    input wire        clock,
    // The environment: free in every cycle.
    input wire [16:0] origin_x,
    input wire [16:0] origin_y,
    input wire [17:0] normal_x,
    input wire [17:0] normal_y,
    input wire [17:0] first_x,
    input wire [17:0] first_y,
    input wire [17:0] last_x,
    input wire [17:0] last_y,
    input wire        in_valid,
    input wire [15:0] in_id,
    input wire [16:0] in_ax,
    input wire [16:0] in_ay,
    input wire [16:0] in_bx,
    input wire [16:0] in_by,
    input wire        in_bank,
    input wire        out_ready,
    // Chooses the patch the harness follows: the first one accepted while `pick` is high and
    // no patch is followed.
    input wire        pick
);
    localparam DEPTH = 32;
    localparam LATENCY = 28;
    localparam VERDICT_LATENCY = 8;
    localparam COUNT_LATENCY = VERDICT_LATENCY + 1;
    localparam DIV_LATENCY = 18;

    wire        in_ready, out_valid, out_pass, sector_read, sector_bank;
    wire [15:0] out_id;
    wire [17:0] out_ax, out_ay, out_bx, out_by, out_wx, out_wy;
    wire [5:0]  out_sh;
    wire [31:0] passed, backward, back_facing, outside, near;
    // Internal state, exposed by screener.sby for the induction (not ports of the exported
    // module): the stage valid bits and ids, the screens' registers of stages 7 and 8 (the
    // outside screen's gates `ha_open`, `hb_open`, and its verdict of stage 8, a wire), the
    // divider's tag pipeline (3 bits per stage, bit 0: a slot to complete), the verdict flags of
    // stage 9 (what is counted), the credit and FIFO
    // counters and pointers (done, fill_ptr, rd_ptr and rd_inc_x, rd_ptr + 1 with bit 0
    // inverted, are the FIFO control's word count, tail, head and next read address:
    // `prim::FifoControl`), and the output FIFO's lanes.
    wire        v1, v2, v3, v4, v5, v6, v7, v8;
    wire        backward7, back_facing7, backward8, back_facing8, outside8;
    wire        ha_open7, hb_open7, ha_open8, hb_open8;
    wire        pass9, backward9, back_facing9, outside9, near9;
    wire [15:0] id1, id2, id3, id4, id5, id6, id7, id8;
    wire [53:0] tgp;
    wire [5:0]  used, done;
    wire [4:0]  res_ptr, fill_ptr, rd_ptr, rd_inc_x;
    wire [15:0] lane_id [0:31];
    wire [6:0]  lane_sh [0:31];

    screener dut (
        .clock(clock),
        .origin_x(origin_x), .origin_y(origin_y), .normal_x(normal_x), .normal_y(normal_y),
        .first_x(first_x), .first_y(first_y), .last_x(last_x), .last_y(last_y),
        .in_valid(in_valid), .in_ready(in_ready), .in_id(in_id),
        .in_ax(in_ax), .in_ay(in_ay), .in_bx(in_bx), .in_by(in_by), .in_bank(in_bank),
        .sector_read(sector_read), .sector_bank(sector_bank),
        .out_valid(out_valid), .out_ready(out_ready), .out_id(out_id),
        .out_ax(out_ax), .out_ay(out_ay), .out_bx(out_bx), .out_by(out_by),
        .out_wx(out_wx), .out_wy(out_wy), .out_sh(out_sh), .out_pass(out_pass),
        .passed(passed), .backward(backward), .back_facing(back_facing), .outside(outside),
        .near(near)
`ifdef INDUCTION
        , .v1$q(v1), .v2$q(v2), .v3$q(v3), .v4$q(v4), .v5$q(v5), .v6$q(v6), .v7$q(v7),
        .v8$q(v8),
        .id1$q(id1), .id2$q(id2), .id3$q(id3), .id4$q(id4), .id5$q(id5), .id6$q(id6),
        .id7$q(id7), .id8$q(id8),
        .backward7$q(backward7), .back_facing7$q(back_facing7),
        .backward8$q(backward8), .back_facing8$q(back_facing8), .outside8(outside8),
        .ha_open7$q(ha_open7), .hb_open7$q(hb_open7), .ha_open8$q(ha_open8), .hb_open8$q(hb_open8),
        .pass9$q(pass9), .backward9$q(backward9), .back_facing9$q(back_facing9),
        .outside9$q(outside9), .near9$q(near9),
        .divider_tgp(tgp), .used$q(used), .fifo_words_q(done),
        .res_ptr$q(res_ptr), .fifo_tail_ptr_q(fill_ptr), .fifo_rd_ptr_q(rd_ptr), .fifo_rd_inc_x_q(rd_inc_x),
        `LANE32(lane_id, lane_id), `LANE32(lane_sh, lane_sh)
`endif
    );

    // Transfers: `valid && ready` before the edge (screener.rs, "Ports").
    wire take = in_valid && in_ready;
    wire pop = out_valid && out_ready;

    // ---- The harness's counts, from the ports only. ----
    reg        f_past = 1'b0;
    reg [6:0]  f_held = 7'd0;       // accepted, not yet out
    reg [LATENCY-1:1] f_sr = 0;     // f_sr[k]: a patch was taken k cycles ago
    reg        f_full = 1'b0;       // all credits have been taken (for the covers)

    always @(posedge clock) begin
        f_past <= 1'b1;
        f_held <= f_held + take - pop;
        f_sr <= {f_sr[LATENCY-2:1], take};
        if (f_held == DEPTH) f_full <= 1'b1;
    end

    // The counters in the previous cycle (zero before the first).
    reg [31:0] f_p_passed = 32'd0, f_p_backward = 32'd0, f_p_back_facing = 32'd0;
    reg [31:0] f_p_outside = 32'd0, f_p_near = 32'd0;
    always @(posedge clock) begin
        f_p_passed <= passed;
        f_p_backward <= backward;
        f_p_back_facing <= back_facing;
        f_p_outside <= outside;
        f_p_near <= near;
    end

    // ---- The followed patch. ----
    reg        f_trk = 1'b0;      // following a patch that has been accepted, not yet out
    reg [15:0] f_id = 16'd0;
    reg [6:0]  f_ahead = 7'd0;    // patches to leave before it
    reg [5:0]  f_age = 6'd0;      // cycles since its acceptance (saturating)
    reg        f_vpass = 1'b0;    // its verdict was counted in `passed`
    reg        f_bank = 1'b0;     // its `in_bank`
    wire       f_out = f_trk && pop && f_ahead == 7'd0;

    always @(posedge clock) begin
        if (!f_trk) begin
            if (take && pick) begin
                f_trk <= 1'b1;
                f_id <= in_id;
                f_bank <= in_bank;
                f_ahead <= f_held - pop;
                f_age <= 6'd1;
            end
        end else begin
            if (f_age != 6'd63) f_age <= f_age + 6'd1;
            // In cycle a + COUNT_LATENCY + 1 the counters show its verdict for the first time.
            if (f_age == COUNT_LATENCY + 1) f_vpass <= passed != f_p_passed;
            if (pop) begin
                if (f_ahead == 7'd0) f_trk <= 1'b0;
                else f_ahead <= f_ahead - 7'd1;
            end
        end
    end

    // ---- The properties. ----
    always @(*) begin
        // Credits: never more than DEPTH in flight; a patch is taken exactly while fewer are.
        a_credits: assert(f_held <= DEPTH);
        a_in_ready: assert(in_ready == (f_held != DEPTH));
        // No output without an input.
        a_no_spurious: assert(!out_valid || f_held != 7'd0);
        // The counters start at zero.
        if (!f_past) a_counters_init: assert(passed == 32'd0 && backward == 32'd0
                                             && back_facing == 32'd0 && outside == 32'd0
                                             && near == 32'd0);
        // The sector is read in stage 3 (SECTOR_STAGE) of every patch, and only then.
        a_sector_read: assert(sector_read == f_sr[3]);
        if (f_trk) begin
            // The followed patch shows its own bank when it reads the sector.
            if (f_age == 6'd3) a_sector_bank: assert(sector_read && sector_bank == f_bank);
            a_ahead: assert(f_ahead < f_held);
            // The followed patch is presented exactly from LATENCY cycles after its acceptance
            // on, once the patches before it have left.
            if (f_ahead == 7'd0) a_latency: assert(out_valid == (f_age >= LATENCY));
        end
        if (f_out) begin
            // It leaves in order (the n-th out is the n-th in), with the verdict it was
            // counted with.
            a_order: assert(out_id == f_id);
            a_pass: assert(out_pass == f_vpass);
        end
    end

    // Which counters grew since the previous cycle.
    wire [4:0] f_grew = {passed != f_p_passed, backward != f_p_backward,
                         back_facing != f_p_back_facing, outside != f_p_outside,
                         near != f_p_near};
    always @(posedge clock) begin
        if (f_past) begin
            // Every patch is counted in exactly one counter, once, a cycle after its verdict
            // (COUNT_LATENCY cycles after its acceptance; shown from the next cycle on): the
            // counters only ever grow by one, and exactly one grows for each patch taken
            // COUNT_LATENCY + 1 cycles before, none otherwise. (With a_counters_init: the
            // five counters sum to the number of patches taken at least ten cycles ago.)
            a_count_step: assert((passed == f_p_passed || passed == f_p_passed + 32'd1)
                                 && (backward == f_p_backward || backward == f_p_backward + 32'd1)
                                 && (back_facing == f_p_back_facing
                                     || back_facing == f_p_back_facing + 32'd1)
                                 && (outside == f_p_outside || outside == f_p_outside + 32'd1)
                                 && (near == f_p_near || near == f_p_near + 32'd1));
            a_count_one: assert(f_grew == 5'd0 || f_grew == 5'b00001 || f_grew == 5'b00010
                                || f_grew == 5'b00100 || f_grew == 5'b01000 || f_grew == 5'b10000);
            a_count_when: assert((f_grew != 5'd0) == f_sr[COUNT_LATENCY + 1]);
            // Handshake stability.
            if ($past(in_ready && !in_valid)) a_in_hold: assert(in_ready);
            if ($past(out_valid && !out_ready)) begin
                a_out_hold: assert(out_valid);
                a_out_stable: assert($stable(out_id) && $stable(out_pass) && $stable(out_sh));
            end
        end
    end

`ifdef INDUCTION
    // ---- Invariants over the internal state (the induction's strengthening). ----
    // The pipeline never stalls, so the take history locates every patch: one taken k cycles
    // ago is in stage k (k <= 8 = VERDICT_LATENCY), in divider stage k - 9 (9 <= k <= 26),
    // complete from k = 27 (LATENCY - 1).
    reg [6:0] f_young_v, f_young_d, f_young_l, f_younger;  // takes in the last 8, 26 and 27
                                                           // cycles, and in the followed
                                                           // patch's life
    integer k;
    always @(*) begin
        f_young_v = 7'd0;
        f_young_d = 7'd0;
        f_young_l = 7'd0;
        f_younger = 7'd0;
        for (k = 1; k <= LATENCY - 1; k = k + 1) begin
            if (k <= VERDICT_LATENCY) f_young_v = f_young_v + f_sr[k];
            if (k <= VERDICT_LATENCY + DIV_LATENCY) f_young_d = f_young_d + f_sr[k];
            f_young_l = f_young_l + f_sr[k];
            if (k <= f_age) f_younger = f_younger + f_sr[k];
        end
    end
    wire [17:0] f_tags;  // bit 0 of each divider stage's tag
    genvar g;
    generate
        for (g = 0; g < 18; g = g + 1) begin : tags
            assign f_tags[g] = tgp[3 * g];
        end
    endgenerate
    wire [4:0] f_slot = rd_ptr + f_ahead[4:0];  // the followed patch's slot (from stage 9 on)

    always @(*) begin
        i_stages: assert(v1 == f_sr[1] && v2 == f_sr[2] && v3 == f_sr[3] && v4 == f_sr[4]
                         && v5 == f_sr[5] && v6 == f_sr[6] && v7 == f_sr[7] && v8 == f_sr[8]);
        i_tags: assert(f_tags == f_sr[VERDICT_LATENCY + DIV_LATENCY:VERDICT_LATENCY + 1]);
        // At most one screen's register is set in each stage (the verdict is one of five).
        // (The outside screen is decided in stage 8 from its compares and its gates, which
        // stage 7 opens only for a patch neither backward nor back-facing: i_open.)
        i_open: assert(!((backward7 || back_facing7) && (ha_open7 || hb_open7))
                       && !((backward8 || back_facing8) && (ha_open8 || hb_open8)));
        i_verdict: assert(!(backward7 && back_facing7)
                          && !(backward8 && back_facing8) && !(backward8 && outside8)
                          && !(back_facing8 && outside8));
        // Stage 9 holds the verdict of the patch taken COUNT_LATENCY cycles ago, as one flag
        // (none without a patch).
        i_count9: assert({4'd0, pass9} + backward9 + back_facing9 + outside9 + near9
                         == {4'd0, f_sr[COUNT_LATENCY]});
        i_used: assert(used == f_held[5:0]);
        // Patches leave no earlier than LATENCY cycles after their acceptance.
        i_young: assert(f_young_l <= f_held);
        // Slots rd_ptr .. are reserved by the patches past stage 8, complete for those past
        // the divider (done).
        i_res_ptr: assert(res_ptr == rd_ptr + f_held[4:0] - f_young_v[4:0]);
        i_done: assert({1'b0, done} == f_held - f_young_d);
        i_fill_ptr: assert(fill_ptr == rd_ptr + done[4:0]);
        i_rd_inc: assert(rd_inc_x == ((rd_ptr + 5'd1) ^ 5'd1));
        // The head is presented exactly when it was complete before this cycle.
        i_head_valid: assert(out_valid == (done - f_sr[LATENCY - 1] != 6'd0));
        // The read registers show the head slot whenever they are presented.
        if (out_valid) begin
            i_head: assert(out_id == lane_id[rd_ptr] && out_pass == lane_sh[rd_ptr][6]
                           && out_sh == lane_sh[rd_ptr][5:0]);
        end
        // The followed patch: in its stage, then in its slot.
        if (f_trk) begin
            i_trk_age: assert(f_age != 6'd0);
            if (f_age <= LATENCY - 1) begin
                i_trk_young: assert(f_sr[f_age] && f_ahead == f_held - f_younger);
            end else begin
                i_trk_done: assert({1'b0, done} >= f_ahead + 7'd1 + f_sr[LATENCY - 1]);
            end
            if (f_age == 1) i_trk_id1: assert(id1 == f_id);
            if (f_age == 2) i_trk_id2: assert(id2 == f_id);
            if (f_age == 3) i_trk_id3: assert(id3 == f_id);
            if (f_age == 4) i_trk_id4: assert(id4 == f_id);
            if (f_age == 5) i_trk_id5: assert(id5 == f_id);
            if (f_age == 6) i_trk_id6: assert(id6 == f_id);
            if (f_age == 7) i_trk_id7: assert(id7 == f_id);
            if (f_age == 8) i_trk_id8: assert(id8 == f_id);
            if (f_age >= VERDICT_LATENCY + 1) i_trk_slot: assert(lane_id[f_slot] == f_id);
            if (f_age == COUNT_LATENCY) i_trk_pass9: assert(lane_sh[f_slot][6] == pass9);
            if (f_age >= COUNT_LATENCY + 2) i_trk_pass: assert(lane_sh[f_slot][6] == f_vpass);
        end
    end
    always @(posedge clock) begin
        if (f_past && f_trk && f_age == COUNT_LATENCY + 1) begin
            i_trk_pass_v: assert(lane_sh[f_slot][6] == (passed != f_p_passed));
        end
    end
`endif

    // ---- Covers: the environment is not over-constrained. ----
    always @(*) begin
        // All credits taken: the input stalls.
        c_full: cover(f_held == DEPTH && !in_ready);
        // The followed patch leaves passed, and one leaves screened out.
        c_out_pass: cover(f_out && out_pass);
        c_out_screened: cover(f_out && !out_pass);
        // A patch leaves while another enters, after all credits were taken.
        c_out_after_full: cover(f_out && take && f_full);
    end
endmodule
