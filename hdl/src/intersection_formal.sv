// Formal harness of the intersection unit (`intersection.rs`), run by `intersection.sby` on the
// exported Verilog (`hdl/verilog/intersection_unit.v`, top module `intersection_unit`). See
// `hdl/FORMAL.md`.
//
// Every input is free in every cycle except for the two rules of the module documentation (the
// host writes directions and reads results only while the unit is not busy). Proved for all
// time (k-induction, task `prove`, k = 2, with INDUCTION defined; also checked by the bounded
// task `bmc`):
//
// * the patch handshake is the documented one: `patch_ready` is high exactly while fewer than
//   two rays of the current patch remain to be issued, the harness following the sequencer from
//   the ports (`patch_first`, `patch_count`, one ray per clock); so it is never withdrawn
//   without a transfer;
// * no test without an input: `tests` grows by at most one per cycle, and only for a ray of a
//   test (not retire) job issued three cycles before; it never exceeds the number of such rays;
// * `busy` is high while a ray is issued and in the cycle after a test ray, and never without
//   a ray issued or a marker taken in the last nine cycles (the write is at the end of stage 9);
// * a marker (a retire of no rays) is counted on `marks` exactly ten cycles after it is taken:
//   in the cycle after the write-back of the last test issued before it, never earlier (the
//   host reads a half out from then on).
//
// Proved to a bounded depth only (they need the ray memories' contents):
//
// * task `bmc_live`, depth 10 (every input sequence of 10 cycles; a test ray can first be
//   issued in cycle 1, after a direction write and a patch in cycle 0, and counts three cycles
//   later, so the tests issued in cycles 1 to 6 are checked): `tests` grows for a test ray
//   issued three cycles before exactly when the ray was live (a_tests_live, a_tests_dead; the
//   harness keeps the live bit of one arbitrary ray F_RAY: a direction write makes it live, a
//   retire job's issue of it kills it);
// * task `bmc_results`, depth 15: no result without an input: a readout that
//   reports a hit on ray F_RAY (two cycles after its request) follows a live test of F_RAY
//   since its last readout, by a job with id F_ID if the reported id is F_ID (F_RAY and F_ID
//   arbitrary; a_hit_tested, a_hit_id). The cover task reaches the first readout that reports
//   a test's hit (c_hit) at step 14: a readout of F_RAY, then a test of it written nine
//   cycles after its issue, then its readout answered two cycles after the request. Shorter
//   sequences check readouts of a ray not tested since its last readout, among them two
//   readouts of it in consecutive clocks (the second cannot see the first's clear).
//
// Task `bmc` checks all the properties together to depth 15; it takes many minutes and is run
// by hand, not by `cargo test`.

`default_nettype none

module intersection_formal (
    input wire        clock,
    // The environment: free in every cycle (the two assumptions below aside).
    input wire        dir_we,
    input wire [10:0] dir_addr,
    input wire [17:0] dir_x,
    input wire [17:0] dir_y,
    input wire        patch_valid,
    input wire [17:0] patch_ax,
    input wire [17:0] patch_ay,
    input wire [17:0] patch_bx,
    input wire [17:0] patch_by,
    input wire [17:0] patch_wx,
    input wire [17:0] patch_wy,
    input wire [5:0]  patch_sh,
    input wire [15:0] patch_id,
    input wire [10:0] patch_first,
    input wire [10:0] patch_count,
    input wire        patch_retire,
    input wire        res_re,
    input wire [10:0] res_addr
);
    wire        patch_ready, res_hit, busy;
    wire [15:0] res_id;
    wire [31:0] res_key, tests, marks;
    // Internal state, exposed by intersection.sby for the induction (not ports of the exported
    // module): the sequencer and the stage valid bits, registers of the leaves `seq`
    // (IssueSequencer), `pipe` (HitPipe) and `merge` (NearestMerge).
    wire [10:0] remaining;
    wire [10:0] cur;
    wire        p_retire, v1, v2, v3, v4, v5, v6, v7, v8, v9;
    wire        mk1, mk2, mk3, mk4, mk5, mk6, mk7, mk8, mk9;

    intersection_unit dut (
        .clock(clock),
        .dir_we(dir_we), .dir_addr(dir_addr), .dir_x(dir_x), .dir_y(dir_y),
        .patch_valid(patch_valid), .patch_ready(patch_ready),
        .patch_ax(patch_ax), .patch_ay(patch_ay), .patch_bx(patch_bx), .patch_by(patch_by),
        .patch_wx(patch_wx), .patch_wy(patch_wy), .patch_sh(patch_sh), .patch_id(patch_id),
        .patch_first(patch_first), .patch_count(patch_count), .patch_retire(patch_retire),
        .res_re(res_re), .res_addr(res_addr), .res_hit(res_hit), .res_id(res_id),
        .res_key(res_key), .busy(busy), .tests(tests), .marks(marks)
`ifdef INVARIANTS
        , .seq_remaining(remaining), .seq$cur(cur), .seq_p_retire(p_retire),
        .seq$v1(v1), .pipe_v2(v2), .pipe_v3(v3), .pipe_v4(v4), .pipe_v5(v5), .pipe_v6(v6),
        .pipe_v7(v7), .pipe_v8(v8), .merge_v9(v9),
        .seq$mark1(mk1), .pipe_mk2(mk2), .pipe_mk3(mk3), .pipe_mk4(mk4), .pipe_mk5(mk5),
        .pipe_mk6(mk6), .pipe_mk7(mk7), .pipe_mark8(mk8), .merge_mark9(mk9)
`endif
    );

    // ---- The environment's obligations (intersection.rs, "Ports" and "Live rays"). ----
    // "res_re, res_addr: readout: read and clear ray res_addr (only while not busy)".
    always @(*) assume(!res_re || !busy);
    // "The host writes directions only while the unit is not busy."
    always @(*) assume(!dir_we || !busy);

    // The ray and the patch id the live-bit and no-result-without-input properties follow.
    (* anyconst *) reg [10:0] F_RAY;
    (* anyconst *) reg [15:0] F_ID;

    // ---- The harness's sequencer, from the ports: the documented behaviour. ----
    // A patch transfers when patch_valid && patch_ready; it issues rays first .. first + count - 1
    // (the low ten bits mod 1024: a range stays in its half of the ray memory), one per clock;
    // a retire job kills them instead of testing them. A retire of no rays is a marker.
    wire take = patch_valid && patch_ready;
    reg         f_past = 1'b0;
    reg         f_past2 = 1'b0;     // two cycles since power-up (for $past(.., 2))
    reg  [10:0] f_rem = 11'd0;     // rays of the current patch still to issue
    reg  [10:0] f_cur = 11'd0;     // the ray issued in this cycle (when f_rem != 0)
    reg         f_retire = 1'b0;
    reg  [15:0] f_pid = 16'd0;
    wire        issue = f_rem != 11'd0;
    wire        test = issue && !f_retire;    // a ray of a test job is issued
    reg  [9:1]  f_is = 9'd0;       // f_is[k]: a ray was issued k cycles ago
    reg  [9:1]  f_test = 9'd0;     // f_test[k]: a test ray was issued k cycles ago
    reg  [10:1] f_mk = 10'd0;      // f_mk[k]: a marker was taken k cycles ago
    reg  [31:0] f_tests = 32'd0;   // test rays issued at least three cycles ago (saturating)

    always @(posedge clock) begin
        f_past <= 1'b1;
        f_past2 <= f_past;
        if (take) begin
            f_rem <= patch_count;
            f_cur <= patch_first;
            f_retire <= patch_retire;
            f_pid <= patch_id;
        end else if (issue) begin
            f_rem <= f_rem - 11'd1;
            f_cur <= {f_cur[10], f_cur[9:0] + 10'd1};
        end
        f_is <= {f_is[8:1], issue};
        f_test <= {f_test[8:1], test};
        f_mk <= {f_mk[9:1], take && patch_retire && patch_count == 11'd0};
        if (f_tests != 32'hffff_ffff) f_tests <= f_tests + f_test[2];
    end

    // ---- The properties. ----
    always @(*) begin
        a_patch_ready: assert(patch_ready == (f_rem <= 11'd1));
        // Never more tests than test rays issued (at least three cycles before).
        a_tests_bound: assert(tests <= f_tests);
        if (!f_past) a_tests_init: assert(tests == 32'd0);
        // busy: at least while a ray is issued and the cycle after a test ray; never without
        // a ray issued or a marker taken in the last nine cycles.
        a_busy_issue: assert(!(issue || f_test[1]) || busy);
        a_busy_cause: assert(!busy || issue || f_is != 9'd0 || f_mk[9:1] != 9'd0);
        if (!f_past) a_marks_init: assert(marks == 32'd0);
    end

    always @(posedge clock) begin
        if (f_past) begin
            // A ready patch port stays ready until a transfer.
            if ($past(patch_ready && !patch_valid)) a_ready_hold: assert(patch_ready);
            // tests grows by at most one, and only for a test ray issued three cycles before.
            a_tests_step: assert(tests == $past(tests)
                                 || (tests == $past(tests) + 32'd1 && f_test[3]));
            // A marker is counted ten cycles after it is taken: in the cycle after the
            // write-back (end of stage 9) of the last test issued before it.
            a_marks_step: assert(marks == $past(marks) + {31'd0, f_mk[10]});
        end
    end

`ifdef INVARIANTS
    // ---- Invariants over the internal state (the induction's strengthening; in the bounded
    // proof they are lemmas that spare the solver re-deriving them at every step). ----
    always @(*) begin
        i_sequencer: assert(remaining == f_rem && cur == f_cur && p_retire == f_retire);
        i_history: assert((f_test & ~f_is) == 9'd0);
        // A stage holds a test of a ray issued as many cycles before (from stage 3 on, of a
        // live ray only).
        i_stages: assert(v1 == f_test[1] && v2 == f_test[2] && (!v3 || f_test[3])
                         && (!v4 || f_test[4]) && (!v5 || f_test[5]) && (!v6 || f_test[6])
                         && (!v7 || f_test[7]) && (!v8 || f_test[8]) && (!v9 || f_test[9]));
        // A stage holds a marker exactly when one was taken as many cycles before.
        i_markers: assert({mk9, mk8, mk7, mk6, mk5, mk4, mk3, mk2, mk1} == f_mk[9:1]);
    end
`endif

`ifndef INDUCTION
    // ---- Bounded only: the live bit of F_RAY and the ray memory. ----
    // intersection.sby drops the power-up contents of the unit's memories for this part (the
    // solver is far slower on arrays initialised word by word), so they start arbitrary: a
    // sound over-approximation. The properties are therefore stated once F_RAY's live bit has
    // been set or cleared (a direction write or a retire), and once F_RAY has been read out
    // (which clears its result).
    reg         f_alive = 1'b0;        // F_RAY is live
    reg         f_alive_known = 1'b0;  // ... and that is known (written or retired since power-up)
    wire        test_f = test && f_cur == F_RAY;
    reg  [3:1]  f_live_f = 3'd0;       // f_live_f[k]: a test of F_RAY, known live, k cycles ago
    reg  [3:1]  f_dead_f = 3'd0;       // f_dead_f[k]: a test of F_RAY, known dead, k cycles ago
    reg         f_cleared = 1'b0;      // F_RAY has been read out
    reg         f_ray_tested = 1'b0;   // a live test of F_RAY since its last readout
    reg         f_pair_tested = 1'b0;  // ... by a job with id F_ID
    reg         f_busy_seen = 1'b0;

    always @(posedge clock) begin
        if (dir_we && dir_addr == F_RAY) begin
            f_alive <= 1'b1;
            f_alive_known <= 1'b1;
        end else if (issue && f_retire && f_cur == F_RAY) begin
            f_alive <= 1'b0;
            f_alive_known <= 1'b1;
        end
        f_live_f <= {f_live_f[2:1], test_f && f_alive_known && f_alive};
        f_dead_f <= {f_dead_f[2:1], test_f && f_alive_known && !f_alive};
        if (res_re && res_addr == F_RAY) begin
            f_cleared <= 1'b1;
            f_ray_tested <= 1'b0;
            f_pair_tested <= 1'b0;
        end
        // A test of F_RAY that may write its result (live, or of unknown liveness).
        if (test_f && !(f_alive_known && !f_alive)) begin
            f_ray_tested <= 1'b1;
            if (f_pid == F_ID) f_pair_tested <= 1'b1;
        end
        if (busy) f_busy_seen <= 1'b1;
    end

    always @(posedge clock) begin
        if (f_past) begin
            // A test of F_RAY counts exactly when F_RAY was live.
            if (f_live_f[3]) a_tests_live: assert(tests == $past(tests) + 32'd1);
            if (f_dead_f[3]) a_tests_dead: assert(tests == $past(tests));
        end
        if (f_past2) begin
            // No result without an input: a hit reported on F_RAY (two cycles after its
            // readout request), read out before, follows a test of it since that readout, by a
            // job with the reported id if that is F_ID.
            if ($past(res_re && res_addr == F_RAY && f_cleared, 2) && res_hit) begin
                a_hit_tested: assert($past(f_ray_tested, 2));
                if (res_id == F_ID) a_hit_id: assert($past(f_pair_tested, 2));
            end
            // Cover: such a readout reports a hit of F_ID on F_RAY.
            c_hit: cover($past(res_re && res_addr == F_RAY && f_cleared, 2) && res_hit
                         && res_id == F_ID);
        end
    end

    // ---- Covers: the environment is not over-constrained. ----
    always @(*) begin
        // Back-to-back patches: one is taken while the previous one issues its last ray.
        c_back_to_back: cover(take && f_rem == 11'd1 && tests != 32'd0);
        // A test of F_RAY while it is known dead, after the unit was busy, and one while live.
        c_dead_test: cover(test_f && f_alive_known && !f_alive && f_busy_seen);
        c_live_test: cover(test_f && f_alive_known && f_alive);
    end
`endif
endmodule
