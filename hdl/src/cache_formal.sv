// Formal harness of the patch cache (`cache.rs`), run by `cache.sby` on the exported Verilog
// (`hdl/verilog/patch_cache.v`, top module `patch_cache`). See `hdl/FORMAL.md`.
//
// What it proves, for every input sequence the documented protocol allows (with `mode prove`
// a k-induction, so for all time; every input free in every cycle except as assumed below):
//
// * every client request is answered exactly once, in request order, with the patch of the
//   requested id: no answer lost, duplicated, reordered or carrying another patch. The harness
//   follows one request, chosen freely (`pick`), from its request to its answer: when its turn
//   comes (all requests before it answered), the answer is its own patch (`a_answer`); it is
//   answered only after the requests before it (`a_ahead`) and no answer comes while nothing
//   is outstanding (`a_no_invented`). This holds through hits, misses, hits behind misses,
//   ids evicting each other from a line, requests for an id whose miss is not yet filled (the
//   rewinds), a full miss table and lookups that read a line in the cycle it is written;
// * at most four host requests are outstanding (`a_host_misses`, the miss table's size);
// * a host request is only for an id that a client request still outstanding asked for
//   (`a_host_asked`), and never for an id already outstanding at the host (`a_host_distinct`:
//   a request for the id of a miss not yet filled waits for that miss's fill instead of
//   asking again, as `cache.rs` documents).
//
// These are safety properties: that every request is answered at all (no deadlock, the
// rewinds end) is not proved here; the simulation tests wait for every response, at the cycle
// `model::schedule` gives.
//
// "The patch of an id": the host memory's contents are modelled by one id `f_c` and its
// patch `f_d`, both chosen freely once (`anyconst`): the host answers a request for `f_c`
// with `f_d`, and a request for any other id with anything (`mem_free`, free in every cycle).
// Since `f_c` and `f_d` are arbitrary, "the followed request, if its id is `f_c`, is answered
// with `f_d`" is "every request is answered with the host memory's patch of its id" for
// every host memory, even one whose answers for the other ids are inconsistent.
//
// The assumptions, each the block's documented protocol (`cache.rs`, "Ports"), or a limit of
// this check:
//
// * the client keeps at most 16 requests outstanding (`QUEUE_DEPTH`): no request while 16
//   are outstanding, unless one of them is answered in that cycle (a request is outstanding
//   from its `req` to its `resp_valid`);
// * the host answers its requests in order, each one any number >= 1 of cycles later (an
//   answer only while one of its requests, made in an earlier cycle, is unanswered), with the
//   patch of the requested id (above);
// * the cache is enabled (`cfg_enable` high: disabled, the block is wires) and `flush` is low;
//   `cfg_mask` is a free constant of at most 3 (one to four lines, any of 0, 1, 2, 3): the
//   script cuts the five line memories to their first four words
//   (`-DSHELLING_FORMAL_BRAM_WORDS=4`, `prim::BramOut`), and their own assertions that no
//   address beyond them is used are part of the proof. A flush walks all 1024 lines, so it
//   cannot run on the cut memories; masks above 3 address lines the cut does not keep. The
//   cache's logic does not depend on the number of lines (a line is an address and a compare),
//   and four lines give the cases that matter: one line shared by every id, ids evicting each
//   other, and several lines. Ids are any 16-bit values.
//
// With `mode prove` the proof is a k-induction (k = 1): `cache.sby` makes the block's state
// visible (flatten, `memory_map`, `expose`: the request queue and its pointers, the lookup
// stages, the miss table, the answer and return queues, the line memories and their read
// registers), and the invariants under `INDUCTION` below relate it to the harness's counts, to
// the host's outstanding requests and to the patch `f_d`. They are assertions like the others:
// checked in the base case, assumed only in the induction step. The one helper register they
// need beyond the block's state, `g_pos`, records for each entry of the miss table the answer
// queue slot its request was written to (the answer queue does not say which table entry a
// miss is). The invariants are named by group (`i_q_*` the client and the request queue,
// `i_a_*` the answer queue, `i_t_*` the miss table, `i_r_*` the return queue and the host,
// `i_s_*` the staleness check, `i_l_*` the lines), so that `cache.sby` can check the induction
// step one group at a time (its header says how, and why that is the same proof).
//
// The covers (task `cover`) show the interesting cases are reachable within their depth: four
// misses at the host at once, a request waiting for the fill of its own id's miss and then
// answered from the line, an evicted id missing again, a hit behind two misses, and a request
// made while 16 are outstanding. The mutants (`mutant_stale`, `mutant_order`) show that the
// properties catch a cache that asks the host twice for one id and one that answers a miss
// with another miss's patch.

`default_nettype none

// Connections `.lane_mem_<i>_(arr[i])` of one exposed memory of sixteen or four words.
`define MEM16(lane, arr) \
    .lane``_mem_0_(arr[0]), .lane``_mem_1_(arr[1]), .lane``_mem_2_(arr[2]), .lane``_mem_3_(arr[3]), \
    .lane``_mem_4_(arr[4]), .lane``_mem_5_(arr[5]), .lane``_mem_6_(arr[6]), .lane``_mem_7_(arr[7]), \
    .lane``_mem_8_(arr[8]), .lane``_mem_9_(arr[9]), .lane``_mem_10_(arr[10]), .lane``_mem_11_(arr[11]), \
    .lane``_mem_12_(arr[12]), .lane``_mem_13_(arr[13]), .lane``_mem_14_(arr[14]), .lane``_mem_15_(arr[15])
`define MEM4(lane, arr) \
    .lane``_mem_0_(arr[0]), .lane``_mem_1_(arr[1]), .lane``_mem_2_(arr[2]), .lane``_mem_3_(arr[3])

module cache_formal (
    input wire        clock,
    // The client: free in every cycle (within the assumptions).
    input wire        req,
    input wire [15:0] addr,
    // The host: when it answers, and its answer for an id other than `f_c`.
    input wire        mem_valid,
    input wire [67:0] mem_free,
    // Chooses the request the harness follows: the first made while `pick` is high and no
    // request is followed.
    input wire        pick
);
    localparam DEPTH = 16;

    // The configuration and the host memory's patch `f_d` of id `f_c`: free constants.
    (* anyconst *) reg [9:0] f_mask;
    (* anyconst *) reg [15:0] f_c;
    (* anyconst *) reg [67:0] f_d;
    always @(*) assume(f_mask <= 10'd3);

    // ---- The host: its outstanding requests' ids, oldest first (four: a fifth fails
    // `a_host_misses` before it could overwrite one). ----
    (* mem2reg *) reg [15:0] h_id [0:3];
    reg [1:0]  h_rd = 2'd0, h_wr = 2'd0;
    reg [3:0]  h_n = 4'd0;
    // The answer in this cycle (meaningful while `mem_valid`): to the oldest request.
    wire [67:0] mem_data = h_id[h_rd] == f_c ? f_d : mem_free;

    wire        flushing, resp_valid, mem_req;
    wire [16:0] resp_ax, resp_ay, resp_bx, resp_by;
    wire [15:0] mem_addr;
    wire [31:0] hits, misses;
`ifdef INDUCTION
    // Internal state, exposed by cache.sby (not ports of the exported module).
    // The request queue: its lane, the lane's read register, the pointers, stage Q's valid.
    wire [15:0] qm [0:15];
    wire [15:0] q_rd;
    wire [4:0]  wr_ptr, rd_ptr, sp, rd_inc_x, sp_inc_x;
    wire        q_valid;
    // Stages S1, S2 and S3.
    wire        v1, v2, v3;
    wire [15:0] id1, id2, id3;
    wire [16:0] key1, key2;
    wire [9:0] line1, line2, line3;
    wire        match3, lconf3, iconf3;
    wire [16:0] ax3, ay3, bx3, by3;
    wire        mi0, mi1, mi2, mi3, mis3, mis2, mlf;
    // The miss table, the last fill, the previous cycle's hit, the lookup's miss.
    wire [15:0] t_id0, t_id1, t_id2, t_id3;
    wire [9:0] t_line0, t_line1, t_line2, t_line3;
    wire        t_v0, t_v1, t_v2, t_v3, t_any, t_full;
    wire [2:0]  t_n;
    wire [1:0]  t_wp, t_rp;
    wire [9:0] f_line1;
    wire        f_v1, hit_r, fl_on, miss;
    // The answer queue: the control's count, pointers and head valid; the lanes' words and
    // read data ({miss, line, id} in the meta lane).
    wire [4:0]  a_words;
    wire [3:0]  a_tail, a_rd, a_inc_x;
    wire        a_hv;
    wire [16:0] am_ax [0:15], am_ay [0:15], am_bx [0:15], am_by [0:15];
    wire [26:0] am_meta [0:15];
    wire [16:0] ad_ax, ad_ay, ad_bx, ad_by;
    wire [26:0] ad_meta;
    // The return queue, likewise.
    wire [2:0]  r_words;
    wire [1:0]  r_tail, r_rd, r_inc_x;
    wire        r_full;
    wire        r_hv;
    wire [16:0] rm_ax [0:3], rm_ay [0:3], rm_bx [0:3], rm_by [0:3];
    wire [16:0] rd_ax, rd_ay, rd_bx, rd_by;
    // The line memories: words, first read register, collision flag, read data.
    wire [16:0] tm [0:3], lm_ax [0:3], lm_ay [0:3], lm_bx [0:3], lm_by [0:3];
    wire [16:0] tag_r1, ax_r1, ay_r1, bx_r1, by_r1;
    wire        tag_col, ax_col, ay_col, bx_col, by_col;
    wire [16:0] tag_rd, lax_rd, lay_rd, lbx_rd, lby_rd;
`endif

    patch_cache dut (
        .clock(clock), .cfg_enable(1'b1), .cfg_mask(f_mask), .flush(1'b0), .flushing(flushing),
        .req(req), .addr(addr), .resp_valid(resp_valid), .resp_ax(resp_ax), .resp_ay(resp_ay),
        .resp_bx(resp_bx), .resp_by(resp_by), .mem_req(mem_req), .mem_addr(mem_addr),
        .mem_valid(mem_valid), .mem_ax(mem_data[67:51]), .mem_ay(mem_data[50:34]),
        .mem_bx(mem_data[33:17]), .mem_by(mem_data[16:0]), .hits(hits), .misses(misses)
`ifdef INDUCTION
        , `MEM16(q_lane, qm), .q_lane_read_data(q_rd),
        .wr_ptr_q(wr_ptr), .rd_ptr_q(rd_ptr), .sp_q(sp), .rd_inc_x_q(rd_inc_x),
        .sp_inc_x_q(sp_inc_x), .q_valid_q(q_valid),
        .v1_q(v1), .v2_q(v2), .v3_q(v3), .id1_q(id1), .id2_q(id2), .id3_q(id3),
        .key1_q(key1), .key2_q(key2), .line1_q(line1), .line2_q(line2), .line3_q(line3),
        .match3_q(match3), .lconf3_q(lconf3), .iconf3_q(iconf3),
        .ax3_q(ax3), .ay3_q(ay3), .bx3_q(bx3), .by3_q(by3),
        .mi0_q(mi0), .mi1_q(mi1), .mi2_q(mi2), .mi3_q(mi3), .mis3_q(mis3), .mis2_q(mis2),
        .mlf_q(mlf),
        .t_id0_q(t_id0), .t_id1_q(t_id1), .t_id2_q(t_id2), .t_id3_q(t_id3),
        .t_line0_q(t_line0), .t_line1_q(t_line1), .t_line2_q(t_line2), .t_line3_q(t_line3),
        .t_v0_q(t_v0), .t_v1_q(t_v1), .t_v2_q(t_v2), .t_v3_q(t_v3), .t_any_q(t_any), .t_full_q(t_full),
        .t_n_q(t_n), .t_wp_q(t_wp), .t_rp_q(t_rp),
        .f_line1_q(f_line1), .f_v1_q(f_v1), .hit_r_q(hit_r), .fl_on_q(fl_on), .miss(miss),
        .ans_words_q(a_words), .ans_tail_ptr_q(a_tail), .ans_rd_ptr_q(a_rd),
        .ans_rd_inc_x_q(a_inc_x), .ans_head_valid_q(a_hv),
        `MEM16(ans_ax, am_ax), `MEM16(ans_ay, am_ay), `MEM16(ans_bx, am_bx),
        `MEM16(ans_by, am_by), `MEM16(ans_meta, am_meta),
        .ans_ax_read_data(ad_ax), .ans_ay_read_data(ad_ay), .ans_bx_read_data(ad_bx),
        .ans_by_read_data(ad_by), .ans_meta_read_data(ad_meta),
        .ret_words_q(r_words), .ret_tail_ptr_q(r_tail), .ret_rd_ptr_q(r_rd),
        .ret_rd_inc_x_q(r_inc_x), .ret_head_valid_q(r_hv), .ret_full_q(r_full),
        `MEM4(ret_ax, rm_ax), `MEM4(ret_ay, rm_ay), `MEM4(ret_bx, rm_bx), `MEM4(ret_by, rm_by),
        .ret_ax_read_data(rd_ax), .ret_ay_read_data(rd_ay), .ret_bx_read_data(rd_bx),
        .ret_by_read_data(rd_by),
        `MEM4(tag, tm), `MEM4(lane_ax, lm_ax), `MEM4(lane_ay, lm_ay), `MEM4(lane_bx, lm_bx),
        `MEM4(lane_by, lm_by),
        .tag_r1(tag_r1), .lane_ax_r1(ax_r1), .lane_ay_r1(ay_r1), .lane_bx_r1(bx_r1),
        .lane_by_r1(by_r1),
        .tag_collided(tag_col), .lane_ax_collided(ax_col), .lane_ay_collided(ay_col),
        .lane_bx_collided(bx_col), .lane_by_collided(by_col),
        .tag_read_data(tag_rd), .lane_ax_read_data(lax_rd), .lane_ay_read_data(lay_rd),
        .lane_bx_read_data(lbx_rd), .lane_by_read_data(lby_rd)
`endif
    );
    wire [67:0] resp = {resp_ax, resp_ay, resp_bx, resp_by};

    // ---- The client: its outstanding requests, and their ids, oldest at `c_rd`. ----
    reg [5:0]  f_out = 6'd0;
    (* mem2reg *) reg [15:0] c_id [0:15];
    reg [3:0]  c_rd = 4'd0, c_wr = 4'd0;
    reg        f_mv = 1'b0;      // the host answered in the previous cycle
    integer i;
    initial begin
        for (i = 0; i < 16; i = i + 1) c_id[i] = 16'd0;
        for (i = 0; i < 4; i = i + 1) h_id[i] = 16'd0;
    end
    always @(*) begin
        // At most 16 requests outstanding, counting one answered in this cycle as gone.
        if (f_out == DEPTH && !resp_valid) assume(!req);
        // The host answers only requests it has seen (a cycle or more ago).
        if (h_n == 4'd0) assume(!mem_valid);
    end
    always @(posedge clock) begin
        f_out <= f_out + req - resp_valid;
        if (req) begin
            c_id[c_wr] <= addr;
            c_wr <= c_wr + 4'd1;
        end
        if (resp_valid) c_rd <= c_rd + 4'd1;
        if (mem_req) begin
            h_id[h_wr] <= mem_addr;
            h_wr <= h_wr + 2'd1;
        end
        if (mem_valid) h_rd <= h_rd + 2'd1;
        h_n <= h_n + mem_req - mem_valid;
        f_mv <= mem_valid;
    end

    // ---- The followed request. ----
    reg        f_trk = 1'b0;
    reg [15:0] f_id = 16'd0;
    reg [5:0]  f_ahead = 6'd0;    // answers to come before its own
    wire       f_answered = f_trk && f_ahead == 6'd0 && resp_valid;
    always @(posedge clock) begin
        if (!f_trk) begin
            if (req && pick) begin
                f_trk <= 1'b1;
                f_id <= addr;
                f_ahead <= f_out - resp_valid;
            end
        end else if (resp_valid) begin
            if (f_ahead == 6'd0) f_trk <= 1'b0;
            else f_ahead <= f_ahead - 6'd1;
        end
    end

    // ---- The properties. ----
    // `f_asked`: some outstanding client request asked for `mem_addr`; `f_again`: a host
    // request for `mem_addr` is outstanding.
    reg       f_asked, f_again;
    reg [3:0] f_k4;
    reg [1:0] f_k2;
    integer   k;
    always @(*) begin
        f_asked = 1'b0;
        f_again = 1'b0;
        for (k = 0; k < 16; k = k + 1) begin
            f_k4 = k[3:0] - c_rd;
            if ({2'b0, f_k4} < f_out && c_id[k] == mem_addr) f_asked = 1'b1;
        end
        for (k = 0; k < 4; k = k + 1) begin
            f_k2 = h_rd + k[1:0];
            if (k < h_n && h_id[f_k2] == mem_addr) f_again = 1'b1;
        end
    end
    always @(*) begin
        if (resp_valid) a_no_invented: assert(f_out != 6'd0);
        if (f_trk) a_ahead: assert(f_ahead < f_out);
        if (f_answered && f_id == f_c) a_answer: assert(resp == f_d);
        a_host_misses: assert(h_n <= 4'd4);
        if (mem_req) begin
            a_host_asked: assert(f_asked);
            a_host_distinct: assert(!f_again);
        end
    end

`ifdef INDUCTION
    // ---- Invariants over the internal state (the induction's strengthening). ----
    // Answer queue slots, return queue slots and lines as patches; the table as arrays.
    wire [67:0] am [0:15];
    wire [67:0] rm [0:3];
    wire [67:0] lm [0:3];
    wire [15:0] t_id [0:3];
    wire [9:0] t_line [0:3];
    wire [3:0]  t_v = {t_v3, t_v2, t_v1, t_v0};
    assign t_id[0] = t_id0; assign t_id[1] = t_id1; assign t_id[2] = t_id2; assign t_id[3] = t_id3;
    assign t_line[0] = t_line0; assign t_line[1] = t_line1; assign t_line[2] = t_line2;
    assign t_line[3] = t_line3;
    wire [16:0] key_c = {1'b1, f_c};
    wire        tag_hit = match3;

    // The helper: the answer queue slot of each table entry's request, written with it (`miss`:
    // the lookup accepts a miss at this edge, into table entry `t_wp` and answer slot `a_tail`).
    (* mem2reg *) reg [3:0] g_pos [0:3];
    always @(posedge clock) if (miss) g_pos[t_wp] <= a_tail;

    wire [4:0] q_n = wr_ptr - rd_ptr;                // requests not yet accepted
    wire [4:0] q_sp = sp - rd_ptr;                   // requests in S1 to S3
    wire [3:0] q_s3 = rd_ptr[3:0];                   // slots of S3's, S2's and S1's request
    wire [3:0] q_s2 = rd_ptr[3:0] + {3'd0, v3};
    wire [3:0] q_s1 = rd_ptr[3:0] + {3'd0, v3} + {3'd0, v2};
    wire [1:0] t_host = t_rp + r_words[1:0];         // the table entry of the oldest host request
    wire [1:0] t_new = t_host + h_n[1:0];            // the table entry of `mem_req`'s miss
    wire [3:0] c_trk = c_rd + f_ahead[3:0];          // the followed request's slot
    // Each table entry's rank from the oldest, whether it is valid, and the offset of its
    // request in the answer queue.
    wire [1:0] t_rank [0:3];
    wire [3:0] t_off [0:3];
    wire [3:0] t_in;
    genvar gi, gj;
    generate
        for (gi = 0; gi < 4; gi = gi + 1) begin : t_entry
            assign t_rank[gi] = gi - t_rp;
            assign t_in[gi] = {1'b0, t_rank[gi]} < t_n;
            assign t_off[gi] = g_pos[gi] - a_rd;
        end
    endgenerate
    wire [4:0] f_acc = {4'd0, hit_r | mem_req};      // accepted at the last edge

    // The per-slot conditions, one bit per slot (asserted below).
    wire [15:0] ok_c_id, ok_a_id, ok_a_hit, ok_t_miss;
    wire [3:0]  ok_t_v, ok_t_line, ok_t_pos, ok_s_iconf3, ok_s_mi, ok_r_data, ok_r_h_id, ok_line;
    wire [15:0] ok_t_distinct, ok_t_order;
    generate
        for (gi = 0; gi < 16; gi = gi + 1) begin : a_slot
            assign am[gi] = {am_ax[gi], am_ay[gi], am_bx[gi], am_by[gi]};
            wire [3:0] off = gi - a_rd;
            wire       live = {1'b0, off} < a_words;
            // Whether a table entry's request is in this slot.
            wire       at = (t_in[0] && g_pos[0] == gi) || (t_in[1] && g_pos[1] == gi)
                            || (t_in[2] && g_pos[2] == gi) || (t_in[3] && g_pos[3] == gi);
            assign ok_c_id[gi] = c_id[gi] == qm[gi];
            assign ok_a_id[gi] = !live || (am_meta[gi][15:0] == qm[gi]
                                           && am_meta[gi][25:16] == (qm[gi][9:0] & f_mask));
            assign ok_a_hit[gi] = !live || am_meta[gi][26] || qm[gi] != f_c || am[gi] == f_d;
            assign ok_t_miss[gi] = !live || !am_meta[gi][26] || at;
        end
        for (gi = 0; gi < 4; gi = gi + 1) begin : t_slot
            assign rm[gi] = {rm_ax[gi], rm_ay[gi], rm_bx[gi], rm_by[gi]};
            assign lm[gi] = {lm_ax[gi], lm_ay[gi], lm_bx[gi], lm_by[gi]};
            // The return queue slot, table entry and host request of rank gi.
            wire [1:0] r_s = r_rd + gi;
            wire [1:0] t_r = t_rp + gi;
            wire [1:0] h_s = h_rd + gi;
            wire [1:0] t_h = t_host + gi;
            assign ok_t_v[gi] = t_v[gi] == t_in[gi];
            assign ok_t_line[gi] = !t_in[gi] || t_line[gi] == (t_id[gi][9:0] & f_mask);
            assign ok_t_pos[gi] = !t_in[gi] || ({1'b0, t_off[gi]} < a_words
                                                && am_meta[g_pos[gi]] == {1'b1, t_line[gi], t_id[gi]});
            assign ok_s_iconf3[gi] = !(t_in[gi] && v3 && t_id[gi] == id3) || iconf3;
            assign ok_s_mi[gi] = !(t_in[gi] && v2 && t_id[gi] == id2) || mi0 || mi1 || mi2 || mi3 || mis3;
            assign ok_r_data[gi] = !(gi < r_words && t_id[t_r] == f_c) || rm[r_s] == f_d;
            assign ok_r_h_id[gi] = !(gi < h_n) || h_id[h_s] == t_id[t_h];
            assign ok_line[gi] = tm[gi] != key_c || lm[gi] == f_d;
            for (gj = 0; gj < 4; gj = gj + 1) begin : pair
                if (gj == gi) begin : same
                    assign ok_t_distinct[4 * gi + gj] = 1'b1;
                    assign ok_t_order[4 * gi + gj] = 1'b1;
                end else begin : other
                    wire both = t_in[gi] && t_in[gj];
                    assign ok_t_distinct[4 * gi + gj] = !both || t_id[gi] != t_id[gj];
                    assign ok_t_order[4 * gi + gj] = !both || t_rank[gj] >= t_rank[gi]
                                                     || t_off[gj] < t_off[gi];
                end
            end
        end
    endgenerate

    // The invariants, named by group (`cache.sby` checks each group in a task of its own).
    always @(*) begin
        // i_q_*: the client's requests and the request queue. The harness's client queue is
        // the request queue's lane, slot for slot; the outstanding requests are those not yet
        // accepted, those in the answer queue and the one answered in this cycle; the
        // followed request's id is in its slot.
        i_q_c_id: assert(&ok_c_id);
        i_q_c_wr: assert(c_wr == wr_ptr[3:0] && c_wr == c_rd + f_out[3:0]);
        i_q_out: assert(f_out <= DEPTH && f_out == {1'b0, q_n} + {1'b0, a_words} + resp_valid);
        if (f_trk) i_q_trk: assert(f_id == c_id[c_trk]);
        // The queue's pointers: S3, S2 and S1 hold the oldest requests not accepted, in order,
        // the valid ones consecutive from `rd_ptr`; Q's read register holds the request at `sp`
        // when `q_valid`; each stage's line and tag key are its id's.
        i_q_rd_inc: assert(rd_inc_x == ((rd_ptr + 5'd1) ^ 5'd1) && sp_inc_x == ((sp + 5'd1) ^ 5'd1));
        i_q_sp: assert(q_sp == {4'd0, v3} + {4'd0, v2} + {4'd0, v1} && q_sp <= q_n);
        if (q_valid) i_q_read: assert(sp != wr_ptr && q_rd == qm[sp[3:0]]);
        if (v3) i_q_id3: assert(id3 == qm[q_s3]);
        if (v2) i_q_id2: assert(id2 == qm[q_s2]);
        if (v1) i_q_id1: assert(id1 == qm[q_s1]);
        i_q_lines: assert(line1 == (id1[9:0] & f_mask) && line2 == (id2[9:0] & f_mask)
                          && line3 == (id3[9:0] & f_mask));
        // (The tag keys are zero at power-up, before any request is issued.)
        if (v1) i_q_key1: assert(key1 == {1'b1, id1});
        if (v2) i_q_key2: assert(key2 == {1'b1, id2});

        // i_a_*: the answer queue. Its slots are the request queue's (both count
        // acceptances), so an entry has its request's id and line, and a hit its patch; the
        // head valid lags a push by a cycle (`hit_r` and `mem_req` are the previous cycle's
        // hit and miss); the read data are the head's; the response register holds the
        // answered request's patch.
        i_a_ptr: assert(a_tail == rd_ptr[3:0] && a_tail == a_rd + a_words[3:0] && a_words <= DEPTH
                        && a_inc_x == ((a_rd + 4'd1) ^ 4'd1));
        i_a_hv: assert(!(hit_r && mem_req) && f_acc <= a_words && a_hv == (a_words != f_acc));
        if (a_hv) i_a_head: assert(ad_meta == am_meta[a_rd] && {ad_ax, ad_ay, ad_bx, ad_by} == am[a_rd]);
        i_a_id: assert(&ok_a_id);
        i_a_hit: assert(&ok_a_hit);
        if (resp_valid && c_id[c_rd] == f_c) i_a_resp: assert(resp == f_d);

        // i_t_*: the miss table: `t_n` valid entries from `t_rp`, their lines, distinct ids,
        // each a miss in the answer queue at `g_pos` with its id and line (`i_t_pos_*`), in
        // the table's order; every miss in the answer queue is one of them. So the answer
        // queue's head, when a miss, is the oldest entry.
        i_t_n: assert(t_n <= 3'd4 && t_full == (t_n == 3'd4) && t_wp == t_rp + t_n[1:0]);
        i_t_v: assert(&ok_t_v);
        i_t_any: assert(t_any == |t_v);
        i_t_line: assert(&ok_t_line);
        i_t_pos_0: assert(ok_t_pos[0]);
        i_t_pos_1: assert(ok_t_pos[1]);
        i_t_pos_2: assert(ok_t_pos[2]);
        i_t_pos_3: assert(ok_t_pos[3]);
        i_t_distinct: assert(&ok_t_distinct);
        i_t_order: assert(&ok_t_order);
        i_t_miss: assert(&ok_t_miss);
        if (a_words != 5'd0 && am_meta[a_rd][26]) i_t_oldest: assert(t_n != 3'd0 && g_pos[t_rp] == a_rd);
        if (a_hv && ad_meta[26]) i_t_head: assert(t_n != 3'd0 && ad_meta[15:0] == t_id[t_rp]);

        // i_r_*: the return queue and the host. The table's entries in order: answered by the
        // host (their patches in the return queue, head valid a cycle after the answer), at
        // the host (its outstanding requests' ids), and the one whose host request is being
        // made (`mem_req`). The full register, the lanes' write enable, is the queue full: the
        // lanes are written at the tail in every other clock, outside the queue's words.
        i_r_n: assert({1'b0, r_words} + h_n + mem_req == {1'b0, t_n});
        i_r_ptr: assert(r_tail == r_rd + r_words[1:0] && r_inc_x == ((r_rd + 2'd1) ^ 2'd1)
                        && {2'b0, f_mv} <= r_words && r_hv == (r_words != {2'b0, f_mv})
                        && r_full == (r_words == 3'd4));
        if (r_hv) i_r_head: assert({rd_ax, rd_ay, rd_bx, rd_by} == rm[r_rd]);
        i_r_data: assert(&ok_r_data);
        if (r_hv && t_id[t_rp] == f_c) i_r_head_data: assert({rd_ax, rd_ay, rd_bx, rd_by} == f_d);
        i_r_h_ptr: assert(h_wr == h_rd + h_n[1:0]);
        i_r_h_id: assert(&ok_r_h_id);
        if (mem_req) i_r_mreq: assert(mem_addr == t_id[t_new]);

        // i_s_*: the staleness check, for `a_host_distinct`: a request in S3 whose id is in
        // the table is rewound (`iconf3`); one in S2 has a compare set that makes it so, and
        // S2's compare with S3 is set when their ids are equal.
        i_s_iconf3: assert(&ok_s_iconf3);
        i_s_mi: assert(&ok_s_mi);
        if (v2 && v3 && id3 == id2) i_s_mis2: assert(mis2);

        // i_l_*: the lines. A line tagged with `f_c` holds `f_d` (`i_l_line_*`); so do the
        // first read registers (read before the write), and the read data unless the read met
        // a write of its line (then `mlf`, which makes S3's request a miss); so does S3 when
        // it hits. No flush runs.
        i_l_fl: assert(!fl_on);
        i_l_line_0: assert(ok_line[0]);
        i_l_line_1: assert(ok_line[1]);
        i_l_line_2: assert(ok_line[2]);
        i_l_line_3: assert(ok_line[3]);
        if (tag_r1 == key_c) i_l_r1: assert({ax_r1, ay_r1, bx_r1, by_r1} == f_d);
        i_l_col: assert(tag_col == (f_v1 && f_line1 == line1) && ax_col == tag_col
                        && ay_col == tag_col && bx_col == tag_col && by_col == tag_col);
        if (!mlf && tag_rd == key_c) i_l_rd: assert({lax_rd, lay_rd, lbx_rd, lby_rd} == f_d);
        if (v3 && !lconf3 && tag_hit && id3 == f_c) i_l_s3: assert({ax3, ay3, bx3, by3} == f_d);
    end
`endif

    // ---- Covers: the interesting cases are reachable. ----
    // For the followed request: whether a host request for its id was outstanding when it was
    // made (`f_dup`), whether its id had been asked of the host before (`f_was`), whether its
    // id was asked of the host while it was followed (`f_asked_again`: it missed), and whether
    // two host requests were outstanding at once while it was followed (`f_two_host`).
    reg f_dup = 1'b0, f_was = 1'b0, f_asked_again = 1'b0, f_two_host = 1'b0, f_c_asked = 1'b0;
    reg       f_at_host;
    reg [1:0] f_c2;
    integer   kc;
    always @(*) begin
        f_at_host = 1'b0;
        for (kc = 0; kc < 4; kc = kc + 1) begin
            f_c2 = h_rd + kc[1:0];
            if (kc < h_n && h_id[f_c2] == addr) f_at_host = 1'b1;
        end
    end
    always @(posedge clock) begin
        if (mem_req && mem_addr == f_c) f_c_asked <= 1'b1;
        if (!f_trk && req && pick) begin
            f_dup <= f_at_host;
            f_was <= f_c_asked && addr == f_c;
            f_asked_again <= 1'b0;
            f_two_host <= 1'b0;
        end else if (f_trk) begin
            if (mem_req && mem_addr == f_id) f_asked_again <= 1'b1;
            if (h_n >= 4'd2) f_two_host <= 1'b1;
        end
    end
    always @(*) begin
        // The miss table full: four misses at the host at once.
        c_four_at_host: cover(h_n == 4'd4);
        // A request made while its id's miss was at the host waited for that fill, then was
        // answered from the line (no host request for it).
        c_wait_for_fill: cover(f_answered && f_dup && !f_asked_again);
        // A request for an id fetched and filled before, evicted since by another id of its
        // line, missed again and was answered with its patch.
        c_evicted: cover(f_answered && f_id == f_c && f_was && !f_dup && f_asked_again);
        // A hit answered behind two misses at the host.
        c_hit_behind_misses: cover(f_answered && f_two_host && !f_asked_again && !f_dup
                                   && hits >= 32'd1 && misses >= 32'd2);
        // A request made while 16 are outstanding, one of them answered in that cycle.
        c_full: cover(req && resp_valid && f_out == DEPTH);
    end
endmodule
