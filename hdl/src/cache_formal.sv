// Formal harness of the patch cache (`cache.rs`), run by `cache.sby` on the exported Verilog
// (`hdl/verilog/patch_cache.v`, top module `patch_cache`). See `hdl/FORMAL.md`.
//
// A bounded check (mode bmc), not a proof for all time: from power-up, for every input
// sequence the protocol allows up to the depth in `cache.sby`:
//
// * the client (free) keeps at most 16 requests outstanding and asks for ids 0..7, so that
//   hits, misses, several misses at the host and ids sharing a line all occur; the cache is
//   enabled with 1, 2 or 4 lines (`cfg_mask` a free constant of 0, 1 or 3); no flush;
// * the host (free) answers its requests in order, each any number >= 1 of cycles later, with
//   the patch of the requested id: the coordinates `g(id)` below;
// * asserted: a response only while a request is outstanding (no answer invented); at most
//   four host requests outstanding (the miss table's size); a host request only for an id a
//   client request still outstanding asked for; and the followed request (chosen freely by
//   `pick`) is answered with `g` of its own id when its turn in request order comes: no answer
//   lost, duplicated, reordered or carrying another patch, through hits, misses, hits behind
//   misses, ids evicting each other and the staleness rewinds.
//
// The covers show the interesting cases are reached within the depth.

`default_nettype none

module cache_formal (
    input wire        clock,
    input wire        req,
    input wire [2:0]  addr_lo,
    input wire        mem_valid,
    input wire        pick
);
    localparam DEPTH = 16;
    (* anyconst *) reg [1:0] f_mask_sel;
    wire [11:0] cfg_mask = f_mask_sel == 2'd0 ? 12'd0 : f_mask_sel == 2'd1 ? 12'd1 : 12'd3;
    wire [15:0] addr = {13'd0, addr_lo};

    // The patch of id a.
    function [67:0] g(input [15:0] a);
        g = {1'b0, a, 1'b1, ~a, 1'b0, a ^ 16'h5a5a, 1'b1, a + 16'd1};
    endfunction

    // The host: its outstanding requests' ids, oldest first.
    reg [15:0] h_id [0:15];
    reg [3:0]  h_rd = 4'd0, h_wr = 4'd0;
    reg [4:0]  h_n = 5'd0;
    wire [67:0] mem_data = g(h_id[h_rd]);

    wire        flushing, resp_valid, mem_req;
    wire [16:0] resp_ax, resp_ay, resp_bx, resp_by;
    wire [15:0] mem_addr;
    wire [31:0] hits, misses;
    patch_cache dut (
        .clock(clock), .cfg_enable(1'b1), .cfg_mask(cfg_mask), .flush(1'b0), .flushing(flushing),
        .req(req), .addr(addr), .resp_valid(resp_valid), .resp_ax(resp_ax), .resp_ay(resp_ay),
        .resp_bx(resp_bx), .resp_by(resp_by), .mem_req(mem_req), .mem_addr(mem_addr),
        .mem_valid(mem_valid), .mem_ax(mem_data[67:51]), .mem_ay(mem_data[50:34]),
        .mem_bx(mem_data[33:17]), .mem_by(mem_data[16:0]), .hits(hits), .misses(misses)
    );
    wire [67:0] resp = {resp_ax, resp_ay, resp_bx, resp_by};

    // The client: outstanding requests, and their ids (for the host-request check).
    reg [4:0]  f_out = 5'd0;
    reg [15:0] c_id [0:15];
    reg [3:0]  c_rd = 4'd0, c_wr = 4'd0;
    reg        f_past = 1'b0;
    always @(*) begin
        if (f_out == DEPTH) assume(!req);
        // The host answers only requests it has seen (a cycle or more ago).
        if (h_n == 5'd0) assume(!mem_valid);
    end
    always @(posedge clock) begin
        f_past <= 1'b1;
        f_out <= f_out + req - resp_valid;
        if (req) begin
            c_id[c_wr] <= addr;
            c_wr <= c_wr + 4'd1;
        end
        if (resp_valid) c_rd <= c_rd + 4'd1;
        if (mem_req) begin
            h_id[h_wr] <= mem_addr;
            h_wr <= h_wr + 4'd1;
        end
        if (mem_valid) h_rd <= h_rd + 4'd1;
        h_n <= h_n + mem_req - mem_valid;
    end

    // The followed request.
    reg        f_trk = 1'b0, f_done = 1'b0;
    reg [15:0] f_id = 16'd0;
    reg [4:0]  f_ahead = 5'd0;
    always @(posedge clock) begin
        if (!f_trk && !f_done) begin
            if (req && pick) begin
                f_trk <= 1'b1;
                f_id <= addr;
                f_ahead <= f_out - resp_valid;
            end
        end else if (f_trk && resp_valid) begin
            if (f_ahead == 5'd0) begin
                f_trk <= 1'b0;
                f_done <= 1'b1;
            end else f_ahead <= f_ahead - 5'd1;
        end
    end

    // A host request names an id some outstanding client request asked for.
    reg f_asked;
    integer k;
    always @(*) begin
        f_asked = 1'b0;
        for (k = 0; k < 16; k = k + 1)
            if (((k[3:0] - c_rd) & 4'hf) < f_out[3:0] || f_out == 5'd16)
                if (c_id[k] == mem_addr) f_asked = 1'b1;
    end

    always @(*) begin
        if (resp_valid) a_no_invented: assert(f_out != 5'd0);
        a_host_misses: assert(h_n <= 5'd4);
        if (mem_req) a_host_asked: assert(f_asked);
        if (f_trk && f_ahead == 5'd0 && resp_valid) a_answer: assert(resp == g(f_id));
        if (f_trk) a_ahead: assert(f_ahead < f_out);
    end

    // Covers.
    reg f_two_host = 1'b0;
    always @(posedge clock) if (h_n >= 5'd2) f_two_host <= 1'b1;
    always @(*) begin
        c_answer_after_two_misses: cover(f_done && f_two_host && hits != 32'd0);
        c_three_at_host: cover(h_n == 5'd3);
        c_followed_hit: cover(f_trk && f_ahead == 5'd0 && resp_valid && misses >= 32'd2 && hits >= 32'd2);
    end
endmodule
