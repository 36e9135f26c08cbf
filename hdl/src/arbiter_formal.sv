// Formal harness of the memory arbiter (`arbiter.rs`: `MemoryArbiter<4>`), run by `arbiter.sby`
// on the exported Verilog (`hdl/verilog/memory_arbiter.v`, top module `memory_arbiter`). See
// `hdl/FORMAL.md`.
//
// The environment: four PEs that request freely (any pulse pattern, any id), each keeping at
// most 16 requests unanswered (the patch loader's reservations, the arbiter's contract); a
// host memory that answers every request once, in request order, after any delay
// (`host_valid_in` free), with any words (free inputs) except for the followed request's:
// the harness follows one request, chosen freely (`pick`), and the host answers it with a
// function of its id (four different functions for the four words). PE `i`'s ids carry `i` in
// their top two bits (the arbiter never reads an id, so the ids' values cannot matter; the tag
// only lets the harness tell whose request is at the host).
//
// Checked in every cycle of every such sequence, to the depth in `arbiter.sby`:
//
// * every answer goes to a PE with a request at the host, at most one PE per cycle, and the
//   followed request's answer goes to its PE, after exactly the answers to that PE's older
//   requests, with its own words: no answer lost to another PE, duplicated, reordered or with
//   another's words (the followed request being any);
// * every request reaches the host once, in its PE's order (the followed request after exactly
//   its PE's older requests, with its id);
// * no PE waits: while PE `i` has a request not yet at the host, the host sees one of PE
//   `i`'s requests within `WAIT` cycles (round-robin: each other PE at most once before it);
// * `requests` counts the host requests (the one on `host_req` included).

`default_nettype none

module arbiter_formal (
    input wire        clock,
    input wire [3:0]  req,
    input wire [15:0] addr0,
    input wire [15:0] addr1,
    input wire [15:0] addr2,
    input wire [15:0] addr3,
    input wire        host_valid_in,
    input wire [16:0] any_ax,
    input wire [16:0] any_ay,
    input wire [16:0] any_bx,
    input wire [16:0] any_by,
    // Chooses the followed request: the first asked for while `pick` is high and none is
    // followed (of the lowest-numbered PE asking).
    input wire        pick
);
    localparam N = 4;
    // Cycles a PE's waiting request may go without one of its requests at the host: N - 1
    // other PEs' turns, the clock into its queue's head register and the clock into the grant
    // register (whose queue's head is on the host port).
    localparam WAIT = N + 1;

    wire [15:0] addr [0:N-1];
    assign addr[0] = addr0;
    assign addr[1] = addr1;
    assign addr[2] = addr2;
    assign addr[3] = addr3;

    function [16:0] fx(input [15:0] id); fx = {1'b0, id}; endfunction
    function [16:0] fy(input [15:0] id); fy = {1'b1, ~id}; endfunction
    function [16:0] gx(input [15:0] id); gx = {id, 1'b1}; endfunction
    function [16:0] gy(input [15:0] id); gy = {id[7:0], id[15:8], 1'b0}; endfunction

    // The followed request: its PE, id, and where it is.
    reg        f_on = 0, f_sent = 0;       // followed; at the host (or answered)
    reg [1:0]  f_pe = 0;
    reg [15:0] f_id = 0;
    reg [4:0]  f_unsent = 0;                // its PE's older requests not yet at the host
    reg [4:0]  f_unanswered = 0;            // its PE's older requests not yet answered
    reg [7:0]  f_host = 0;                  // answers the host gives before its

    // The host memory: requests outstanding.
    reg [7:0]  h_out = 0;
    wire       host_valid = host_valid_in && h_out != 0;
    wire       h_followed = f_on && f_sent && f_host == 0;
    wire [16:0] host_ax = h_followed ? fx(f_id) : any_ax;
    wire [16:0] host_ay = h_followed ? fy(f_id) : any_ay;
    wire [16:0] host_bx = h_followed ? gx(f_id) : any_bx;
    wire [16:0] host_by = h_followed ? gy(f_id) : any_by;

    wire [N-1:0] pe_valid;
    wire [16:0]  pe_ax, pe_ay, pe_bx, pe_by;
    wire         host_req;
    wire [15:0]  host_addr;
    wire [31:0]  requests;

    memory_arbiter dut (
        .clock(clock),
        .pe_req$0(req[0]), .pe_req$1(req[1]), .pe_req$2(req[2]), .pe_req$3(req[3]),
        .pe_addr$0(addr0), .pe_addr$1(addr1), .pe_addr$2(addr2), .pe_addr$3(addr3),
        .pe_valid$0(pe_valid[0]), .pe_valid$1(pe_valid[1]), .pe_valid$2(pe_valid[2]),
        .pe_valid$3(pe_valid[3]),
        .pe_ax(pe_ax), .pe_ay(pe_ay), .pe_bx(pe_bx), .pe_by(pe_by),
        .host_req(host_req), .host_addr(host_addr),
        .host_valid(host_valid), .host_ax(host_ax), .host_ay(host_ay), .host_bx(host_bx),
        .host_by(host_by),
        .requests(requests)
    );

    // Per PE: requests unanswered, of them at the host, and the wait.
    reg [4:0]  a_n [0:N-1];
    reg [4:0]  s_n [0:N-1];
    reg [3:0]  wait_n [0:N-1];
    reg [31:0] sent = 0;
    // One loop variable per process (a variable two processes assign is a driver conflict).
    integer i, j, k;
    initial begin
        for (k = 0; k < N; k = k + 1) begin
            a_n[k] = 0;
            s_n[k] = 0;
            wait_n[k] = 0;
        end
    end

    wire [1:0] h_pe = host_addr[15:14];
    // The PE whose request is followed from this cycle on, if any.
    reg        f_new;
    reg [1:0]  f_new_pe;
    always @(*) begin
        f_new = 0;
        f_new_pe = 0;
        for (j = N - 1; j >= 0; j = j - 1) begin
            if (req[j]) begin
                assume (addr[j][15:14] == j);
                assume (a_n[j] < 16 || pe_valid[j]);
                if (pick && !f_on) begin
                    f_new = 1;
                    f_new_pe = j;
                end
            end
        end
    end

    always @(posedge clock) begin
        h_out <= h_out + host_req - host_valid;
        if (host_req) sent <= sent + 1;
        for (i = 0; i < N; i = i + 1) begin
            if (host_req && h_pe == i) assert (s_n[i] < a_n[i]);
            if (pe_valid[i]) assert (s_n[i] > 0);
            a_n[i] <= a_n[i] + req[i] - pe_valid[i];
            s_n[i] <= s_n[i] + (host_req && h_pe == i) - pe_valid[i];
            // Waiting: a request of PE i not yet at the host and none of its at the host now.
            wait_n[i] <= (a_n[i] > s_n[i] && !(host_req && h_pe == i)) ? wait_n[i] + 1 : 0;
            assert (wait_n[i] <= WAIT);
        end
        // The followed request.
        if (f_new) begin
            f_on <= 1;
            f_pe <= f_new_pe;
            f_id <= addr[f_new_pe];
            f_unsent <= a_n[f_new_pe] - s_n[f_new_pe] - (host_req && h_pe == f_new_pe);
            f_unanswered <= a_n[f_new_pe] - pe_valid[f_new_pe];
        end
        if (f_on && !f_sent && host_req && h_pe == f_pe) begin
            if (f_unsent == 0) begin
                assert (host_addr == f_id);
                f_sent <= 1;
                f_host <= h_out - host_valid;
            end else f_unsent <= f_unsent - 1;
        end
        if (f_on && f_sent && host_valid && f_host != 0) f_host <= f_host - 1;
        if (f_on && pe_valid[f_pe]) begin
            if (f_unanswered == 0) begin
                assert (f_sent);
                assert (pe_ax == fx(f_id) && pe_ay == fy(f_id));
                assert (pe_bx == gx(f_id) && pe_by == gy(f_id));
                f_on <= 0;
                f_sent <= 0;
            end else f_unanswered <= f_unanswered - 1;
        end
    end

    always @(*) begin
        assert ((pe_valid & (pe_valid - 1)) == 0);
        assert (requests == sent + host_req);
    end

`ifdef COVER
    // A PE waits the longest (the bound is tight), a PE holds sixteen requests unanswered, and
    // a followed request answered behind others.
    always @(*) begin
        cover (wait_n[3] == WAIT);
        cover (a_n[2] == 16);
        cover (f_on && f_sent && f_unanswered == 2 && pe_valid[f_pe]);
    end
`endif
endmodule
