// memory_arbiter: exported from rust-hdl by `shelling export-verilog`; do not edit.


module memory_arbiter(clock,pe_req$0,pe_req$1,pe_req$2,pe_req$3,pe_addr$0,pe_addr$1,pe_addr$2,pe_addr$3,pe_valid$0,pe_valid$1,pe_valid$2,pe_valid$3,pe_ax,pe_ay,pe_bx,pe_by,host_req,host_addr,host_valid,host_ax,host_ay,host_bx,host_by,requests);
    
    // Module arguments
    input wire  clock;
    input wire  pe_req$0;
    input wire  pe_req$1;
    input wire  pe_req$2;
    input wire  pe_req$3;
    input wire  [15:0] pe_addr$0;
    input wire  [15:0] pe_addr$1;
    input wire  [15:0] pe_addr$2;
    input wire  [15:0] pe_addr$3;
    output reg  pe_valid$0;
    output reg  pe_valid$1;
    output reg  pe_valid$2;
    output reg  pe_valid$3;
    output reg  [16:0] pe_ax;
    output reg  [16:0] pe_ay;
    output reg  [16:0] pe_bx;
    output reg  [16:0] pe_by;
    output reg  host_req;
    output reg  [15:0] host_addr;
    input wire  host_valid;
    input wire  [16:0] host_ax;
    input wire  [16:0] host_ay;
    input wire  [16:0] host_bx;
    input wire  [16:0] host_by;
    output reg  [31:0] requests;
    
    // Constant declarations
    localparam  zero_id = 16'h0;
    localparam  one = 32'h1;
    localparam  zero_count = 5'b0;
    localparam  one_count = 5'b1;
    localparam  two_count = 5'b10;
    
    // Stub signals
    reg  queues$0$clock;
    reg  queues$0$push;
    reg  [15:0] queues$0$data_in;
    reg  queues$0$pop;
    wire  queues$0$valid;
    wire  [15:0] queues$0$data_out;
    wire  [4:0] queues$0$count;
    reg  queues$1$clock;
    reg  queues$1$push;
    reg  [15:0] queues$1$data_in;
    reg  queues$1$pop;
    wire  queues$1$valid;
    wire  [15:0] queues$1$data_out;
    wire  [4:0] queues$1$count;
    reg  queues$2$clock;
    reg  queues$2$push;
    reg  [15:0] queues$2$data_in;
    reg  queues$2$pop;
    wire  queues$2$valid;
    wire  [15:0] queues$2$data_out;
    wire  [4:0] queues$2$count;
    reg  queues$3$clock;
    reg  queues$3$push;
    reg  [15:0] queues$3$data_in;
    reg  queues$3$pop;
    wire  queues$3$valid;
    wire  [15:0] queues$3$data_out;
    wire  [4:0] queues$3$count;
    reg  rr$clock;
    reg  rr$request$0;
    reg  rr$request$1;
    reg  rr$request$2;
    reg  rr$request$3;
    wire  rr$found;
    wire  [2:0] rr$pick;
    wire  rr$granted$0;
    wire  rr$granted$1;
    wire  rr$granted$2;
    wire  rr$granted$3;
    reg  asks$0$d;
    wire  asks$0$q;
    reg  asks$0$clock;
    reg  asks$1$d;
    wire  asks$1$q;
    reg  asks$1$clock;
    reg  asks$2$d;
    wire  asks$2$q;
    reg  asks$2$clock;
    reg  asks$3$d;
    wire  asks$3$q;
    reg  asks$3$clock;
    reg  grant$0$d;
    wire  grant$0$q;
    reg  grant$0$clock;
    reg  grant$1$d;
    wire  grant$1$q;
    reg  grant$1$clock;
    reg  grant$2$d;
    wire  grant$2$q;
    reg  grant$2$clock;
    reg  grant$3$d;
    wire  grant$3$q;
    reg  grant$3$clock;
    reg  grant_any$d;
    wire  grant_any$q;
    reg  grant_any$clock;
    reg  [31:0] count$d;
    wire  [31:0] count$q;
    reg  count$clock;
    reg  route$clock;
    reg  route$push;
    reg  [2:0] route$data_in;
    reg  route$pop;
    wire  route$valid;
    wire  [2:0] route$data_out;
    wire  [7:0] route$count;
    reg  valid_r$0$d;
    wire  valid_r$0$q;
    reg  valid_r$0$clock;
    reg  valid_r$1$d;
    wire  valid_r$1$q;
    reg  valid_r$1$clock;
    reg  valid_r$2$d;
    wire  valid_r$2$q;
    reg  valid_r$2$clock;
    reg  valid_r$3$d;
    wire  valid_r$3$q;
    reg  valid_r$3$clock;
    reg  [16:0] ax_r$d;
    wire  [16:0] ax_r$q;
    reg  ax_r$clock;
    reg  [16:0] ay_r$d;
    wire  [16:0] ay_r$q;
    reg  ay_r$clock;
    reg  [16:0] bx_r$d;
    wire  [16:0] bx_r$q;
    reg  bx_r$clock;
    reg  [16:0] by_r$d;
    wire  [16:0] by_r$q;
    reg  by_r$clock;
    
    // Local signals
    reg  [15:0] granted;
    
    // Sub module instances
    memory_arbiter$queues$0 queues$0(
        .clock(queues$0$clock),
        .push(queues$0$push),
        .data_in(queues$0$data_in),
        .pop(queues$0$pop),
        .valid(queues$0$valid),
        .data_out(queues$0$data_out),
        .count(queues$0$count)
    );
    memory_arbiter$queues$1 queues$1(
        .clock(queues$1$clock),
        .push(queues$1$push),
        .data_in(queues$1$data_in),
        .pop(queues$1$pop),
        .valid(queues$1$valid),
        .data_out(queues$1$data_out),
        .count(queues$1$count)
    );
    memory_arbiter$queues$2 queues$2(
        .clock(queues$2$clock),
        .push(queues$2$push),
        .data_in(queues$2$data_in),
        .pop(queues$2$pop),
        .valid(queues$2$valid),
        .data_out(queues$2$data_out),
        .count(queues$2$count)
    );
    memory_arbiter$queues$3 queues$3(
        .clock(queues$3$clock),
        .push(queues$3$push),
        .data_in(queues$3$data_in),
        .pop(queues$3$pop),
        .valid(queues$3$valid),
        .data_out(queues$3$data_out),
        .count(queues$3$count)
    );
    memory_arbiter$rr rr(
        .clock(rr$clock),
        .request$0(rr$request$0),
        .request$1(rr$request$1),
        .request$2(rr$request$2),
        .request$3(rr$request$3),
        .found(rr$found),
        .pick(rr$pick),
        .granted$0(rr$granted$0),
        .granted$1(rr$granted$1),
        .granted$2(rr$granted$2),
        .granted$3(rr$granted$3)
    );
    memory_arbiter$asks$0 asks$0(
        .d(asks$0$d),
        .q(asks$0$q),
        .clock(asks$0$clock)
    );
    memory_arbiter$asks$1 asks$1(
        .d(asks$1$d),
        .q(asks$1$q),
        .clock(asks$1$clock)
    );
    memory_arbiter$asks$2 asks$2(
        .d(asks$2$d),
        .q(asks$2$q),
        .clock(asks$2$clock)
    );
    memory_arbiter$asks$3 asks$3(
        .d(asks$3$d),
        .q(asks$3$q),
        .clock(asks$3$clock)
    );
    memory_arbiter$grant$0 grant$0(
        .d(grant$0$d),
        .q(grant$0$q),
        .clock(grant$0$clock)
    );
    memory_arbiter$grant$1 grant$1(
        .d(grant$1$d),
        .q(grant$1$q),
        .clock(grant$1$clock)
    );
    memory_arbiter$grant$2 grant$2(
        .d(grant$2$d),
        .q(grant$2$q),
        .clock(grant$2$clock)
    );
    memory_arbiter$grant$3 grant$3(
        .d(grant$3$d),
        .q(grant$3$q),
        .clock(grant$3$clock)
    );
    memory_arbiter$grant_any grant_any(
        .d(grant_any$d),
        .q(grant_any$q),
        .clock(grant_any$clock)
    );
    memory_arbiter$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    memory_arbiter$route route(
        .clock(route$clock),
        .push(route$push),
        .data_in(route$data_in),
        .pop(route$pop),
        .valid(route$valid),
        .data_out(route$data_out),
        .count(route$count)
    );
    memory_arbiter$valid_r$0 valid_r$0(
        .d(valid_r$0$d),
        .q(valid_r$0$q),
        .clock(valid_r$0$clock)
    );
    memory_arbiter$valid_r$1 valid_r$1(
        .d(valid_r$1$d),
        .q(valid_r$1$q),
        .clock(valid_r$1$clock)
    );
    memory_arbiter$valid_r$2 valid_r$2(
        .d(valid_r$2$d),
        .q(valid_r$2$q),
        .clock(valid_r$2$clock)
    );
    memory_arbiter$valid_r$3 valid_r$3(
        .d(valid_r$3$d),
        .q(valid_r$3$q),
        .clock(valid_r$3$clock)
    );
    memory_arbiter$ax_r ax_r(
        .d(ax_r$d),
        .q(ax_r$q),
        .clock(ax_r$clock)
    );
    memory_arbiter$ay_r ay_r(
        .d(ay_r$d),
        .q(ay_r$q),
        .clock(ay_r$clock)
    );
    memory_arbiter$bx_r bx_r(
        .d(bx_r$d),
        .q(bx_r$q),
        .clock(bx_r$clock)
    );
    memory_arbiter$by_r by_r(
        .d(by_r$d),
        .q(by_r$q),
        .clock(by_r$clock)
    );
    
    // Update code
    always @(*) begin
        grant_any$clock = clock;
        count$clock = clock;
        ax_r$clock = clock;
        ay_r$clock = clock;
        bx_r$clock = clock;
        by_r$clock = clock;
        grant_any$d = grant_any$q;
        count$d = count$q;
        ax_r$d = ax_r$q;
        ay_r$d = ay_r$q;
        bx_r$d = bx_r$q;
        by_r$d = by_r$q;
        rr$clock = clock;
        route$clock = clock;
        granted = zero_id;
        queues$0$clock = clock;
        queues$0$push = pe_req$0;
        queues$0$data_in = pe_addr$0;
        rr$request$0 = asks$0$q;
        asks$0$clock = clock;
        grant$0$clock = clock;
        grant$0$d = rr$granted$0;
        asks$0$d = queues$0$count != zero_count;
        if (grant$0$q) begin
            asks$0$d = queues$0$count != one_count;
        end
        if (rr$granted$0) begin
            if (grant$0$q) begin
                if (queues$0$count == two_count) begin
                    asks$0$d = 1'b0;
                end
            end
            else if (queues$0$count == one_count) begin
                asks$0$d = 1'b0;
            end
        end
        queues$0$pop = grant$0$q;
        if (grant$0$q) begin
            granted = queues$0$data_out;
        end
        queues$1$clock = clock;
        queues$1$push = pe_req$1;
        queues$1$data_in = pe_addr$1;
        rr$request$1 = asks$1$q;
        asks$1$clock = clock;
        grant$1$clock = clock;
        grant$1$d = rr$granted$1;
        asks$1$d = queues$1$count != zero_count;
        if (grant$1$q) begin
            asks$1$d = queues$1$count != one_count;
        end
        if (rr$granted$1) begin
            if (grant$1$q) begin
                if (queues$1$count == two_count) begin
                    asks$1$d = 1'b0;
                end
            end
            else if (queues$1$count == one_count) begin
                asks$1$d = 1'b0;
            end
        end
        queues$1$pop = grant$1$q;
        if (grant$1$q) begin
            granted = queues$1$data_out;
        end
        queues$2$clock = clock;
        queues$2$push = pe_req$2;
        queues$2$data_in = pe_addr$2;
        rr$request$2 = asks$2$q;
        asks$2$clock = clock;
        grant$2$clock = clock;
        grant$2$d = rr$granted$2;
        asks$2$d = queues$2$count != zero_count;
        if (grant$2$q) begin
            asks$2$d = queues$2$count != one_count;
        end
        if (rr$granted$2) begin
            if (grant$2$q) begin
                if (queues$2$count == two_count) begin
                    asks$2$d = 1'b0;
                end
            end
            else if (queues$2$count == one_count) begin
                asks$2$d = 1'b0;
            end
        end
        queues$2$pop = grant$2$q;
        if (grant$2$q) begin
            granted = queues$2$data_out;
        end
        queues$3$clock = clock;
        queues$3$push = pe_req$3;
        queues$3$data_in = pe_addr$3;
        rr$request$3 = asks$3$q;
        asks$3$clock = clock;
        grant$3$clock = clock;
        grant$3$d = rr$granted$3;
        asks$3$d = queues$3$count != zero_count;
        if (grant$3$q) begin
            asks$3$d = queues$3$count != one_count;
        end
        if (rr$granted$3) begin
            if (grant$3$q) begin
                if (queues$3$count == two_count) begin
                    asks$3$d = 1'b0;
                end
            end
            else if (queues$3$count == one_count) begin
                asks$3$d = 1'b0;
            end
        end
        queues$3$pop = grant$3$q;
        if (grant$3$q) begin
            granted = queues$3$data_out;
        end
        grant_any$d = rr$found;
        route$push = rr$found;
        route$data_in = rr$pick;
        if (rr$found) begin
            count$d = count$q + one;
        end
        host_req = grant_any$q;
        host_addr = granted;
        requests = count$q;
        route$pop = host_valid;
        valid_r$0$clock = clock;
        valid_r$0$d = 1'b0;
        if (route$data_out == 0) begin
            valid_r$0$d = host_valid;
        end
        pe_valid$0 = valid_r$0$q;
        valid_r$1$clock = clock;
        valid_r$1$d = 1'b0;
        if (route$data_out == 1) begin
            valid_r$1$d = host_valid;
        end
        pe_valid$1 = valid_r$1$q;
        valid_r$2$clock = clock;
        valid_r$2$d = 1'b0;
        if (route$data_out == 2) begin
            valid_r$2$d = host_valid;
        end
        pe_valid$2 = valid_r$2$q;
        valid_r$3$clock = clock;
        valid_r$3$d = 1'b0;
        if (route$data_out == 3) begin
            valid_r$3$d = host_valid;
        end
        pe_valid$3 = valid_r$3$q;
        if (host_valid) begin
            ax_r$d = host_ax;
            ay_r$d = host_ay;
            bx_r$d = host_bx;
            by_r$d = host_by;
        end
        pe_ax = ax_r$q;
        pe_ay = ay_r$q;
        pe_bx = bx_r$q;
        pe_by = by_r$q;
    end
    
endmodule // memory_arbiter


module memory_arbiter$asks$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$asks$0


module memory_arbiter$asks$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$asks$1


module memory_arbiter$asks$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$asks$2


module memory_arbiter$asks$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$asks$3


module memory_arbiter$ax_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$ax_r


module memory_arbiter$ay_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$ay_r


module memory_arbiter$bx_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$bx_r


module memory_arbiter$by_r(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$by_r


module memory_arbiter$count(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$count


module memory_arbiter$grant$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$grant$0


module memory_arbiter$grant$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$grant$1


module memory_arbiter$grant$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$grant$2


module memory_arbiter$grant$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$grant$3


module memory_arbiter$grant_any(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$grant_any


module memory_arbiter$queues$0(clock,push,data_in,pop,valid,data_out,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  [15:0] data_in;
    input wire  pop;
    output reg  valid;
    output reg  [15:0] data_out;
    output reg  [4:0] count;
    
    // Stub signals
    reg  control$clock;
    reg  control$push;
    reg  control$pop;
    wire  [3:0] control$tail_address;
    wire  [3:0] control$head_address;
    wire  [3:0] control$next_address;
    wire  control$valid;
    wire  [4:0] control$count;
    reg  lane$clock;
    reg  [3:0] lane$write_address;
    reg  [15:0] lane$write_data;
    reg  lane$write_enable;
    reg  [3:0] lane$head_address;
    reg  [3:0] lane$next_address;
    reg  lane$pop;
    wire  [15:0] lane$read_data;
    
    // Sub module instances
    memory_arbiter$queues$0$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    memory_arbiter$queues$0$lane lane(
        .clock(lane$clock),
        .write_address(lane$write_address),
        .write_data(lane$write_data),
        .write_enable(lane$write_enable),
        .head_address(lane$head_address),
        .next_address(lane$next_address),
        .pop(lane$pop),
        .read_data(lane$read_data)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        lane$clock = clock;
        control$push = push;
        control$pop = pop;
        lane$write_address = control$tail_address;
        lane$write_data = data_in;
        lane$write_enable = push;
        lane$head_address = control$head_address;
        lane$next_address = control$next_address;
        lane$pop = pop;
        valid = control$valid;
        data_out = lane$read_data;
        count = control$count;
    end
    
endmodule // memory_arbiter$queues$0


module memory_arbiter$queues$0$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [3:0] tail_address;
    output reg  [3:0] head_address;
    output reg  [3:0] next_address;
    output reg  valid;
    output reg  [4:0] count;
    
    // Constant declarations
    localparam  one_a = 4'h1;
    localparam  one_c = 5'b1;
    localparam  zero_c = 5'b0;
    
    // Stub signals
    reg  [3:0] tail_ptr$d;
    wire  [3:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [3:0] rd_ptr$d;
    wire  [3:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [3:0] rd_inc_x$d;
    wire  [3:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [4:0] words$d;
    wire  [4:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [3:0] rd_inc;
    reg  [3:0] rd_inc2;
    
    // Sub module instances
    memory_arbiter$queues$0$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    memory_arbiter$queues$0$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    memory_arbiter$queues$0$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    memory_arbiter$queues$0$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    memory_arbiter$queues$0$control$head_valid head_valid(
        .d(head_valid$d),
        .q(head_valid$q),
        .clock(head_valid$clock)
    );
    
    // Update code
    always @(*) begin
        tail_ptr$clock = clock;
        rd_ptr$clock = clock;
        rd_inc_x$clock = clock;
        words$clock = clock;
        head_valid$clock = clock;
        tail_ptr$d = tail_ptr$q;
        rd_ptr$d = rd_ptr$q;
        rd_inc_x$d = rd_inc_x$q;
        words$d = words$q;
        head_valid$d = head_valid$q;
        tail_address = tail_ptr$q;
        if (push) begin
            tail_ptr$d = tail_ptr$q + one_a;
        end
        rd_inc = rd_inc_x$q ^ one_a;
        rd_inc2 = rd_inc + one_a;
        head_address = rd_ptr$q;
        next_address = rd_inc;
        if (pop) begin
            rd_ptr$d = rd_inc;
            rd_inc_x$d = rd_inc2 ^ one_a;
        end
        head_valid$d = (words$q != zero_c) & ~(pop & (words$q == one_c));
        valid = head_valid$q;
        if (push & ~pop) begin
            words$d = words$q + one_c;
        end
        if (~push & pop) begin
            words$d = words$q - one_c;
        end
        count = words$q;
    end
    
endmodule // memory_arbiter$queues$0$control


module memory_arbiter$queues$0$control$head_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$0$control$head_valid


module memory_arbiter$queues$0$control$rd_inc_x(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$0$control$rd_inc_x


module memory_arbiter$queues$0$control$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$0$control$rd_ptr


module memory_arbiter$queues$0$control$tail_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$0$control$tail_ptr


module memory_arbiter$queues$0$control$words(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$0$control$words


module memory_arbiter$queues$0$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [15:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [15:0] read_data;
    
    // Update code (custom)
    reg [15:0] mem [0:15];
    reg [15:0] head_r;
    reg [15:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [15:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 16'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 16'd0;
       head_r = 16'd0;
       next_r = 16'd0;
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
endmodule // memory_arbiter$queues$0$lane


module memory_arbiter$queues$1(clock,push,data_in,pop,valid,data_out,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  [15:0] data_in;
    input wire  pop;
    output reg  valid;
    output reg  [15:0] data_out;
    output reg  [4:0] count;
    
    // Stub signals
    reg  control$clock;
    reg  control$push;
    reg  control$pop;
    wire  [3:0] control$tail_address;
    wire  [3:0] control$head_address;
    wire  [3:0] control$next_address;
    wire  control$valid;
    wire  [4:0] control$count;
    reg  lane$clock;
    reg  [3:0] lane$write_address;
    reg  [15:0] lane$write_data;
    reg  lane$write_enable;
    reg  [3:0] lane$head_address;
    reg  [3:0] lane$next_address;
    reg  lane$pop;
    wire  [15:0] lane$read_data;
    
    // Sub module instances
    memory_arbiter$queues$1$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    memory_arbiter$queues$1$lane lane(
        .clock(lane$clock),
        .write_address(lane$write_address),
        .write_data(lane$write_data),
        .write_enable(lane$write_enable),
        .head_address(lane$head_address),
        .next_address(lane$next_address),
        .pop(lane$pop),
        .read_data(lane$read_data)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        lane$clock = clock;
        control$push = push;
        control$pop = pop;
        lane$write_address = control$tail_address;
        lane$write_data = data_in;
        lane$write_enable = push;
        lane$head_address = control$head_address;
        lane$next_address = control$next_address;
        lane$pop = pop;
        valid = control$valid;
        data_out = lane$read_data;
        count = control$count;
    end
    
endmodule // memory_arbiter$queues$1


module memory_arbiter$queues$1$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [3:0] tail_address;
    output reg  [3:0] head_address;
    output reg  [3:0] next_address;
    output reg  valid;
    output reg  [4:0] count;
    
    // Constant declarations
    localparam  one_a = 4'h1;
    localparam  one_c = 5'b1;
    localparam  zero_c = 5'b0;
    
    // Stub signals
    reg  [3:0] tail_ptr$d;
    wire  [3:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [3:0] rd_ptr$d;
    wire  [3:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [3:0] rd_inc_x$d;
    wire  [3:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [4:0] words$d;
    wire  [4:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [3:0] rd_inc;
    reg  [3:0] rd_inc2;
    
    // Sub module instances
    memory_arbiter$queues$1$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    memory_arbiter$queues$1$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    memory_arbiter$queues$1$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    memory_arbiter$queues$1$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    memory_arbiter$queues$1$control$head_valid head_valid(
        .d(head_valid$d),
        .q(head_valid$q),
        .clock(head_valid$clock)
    );
    
    // Update code
    always @(*) begin
        tail_ptr$clock = clock;
        rd_ptr$clock = clock;
        rd_inc_x$clock = clock;
        words$clock = clock;
        head_valid$clock = clock;
        tail_ptr$d = tail_ptr$q;
        rd_ptr$d = rd_ptr$q;
        rd_inc_x$d = rd_inc_x$q;
        words$d = words$q;
        head_valid$d = head_valid$q;
        tail_address = tail_ptr$q;
        if (push) begin
            tail_ptr$d = tail_ptr$q + one_a;
        end
        rd_inc = rd_inc_x$q ^ one_a;
        rd_inc2 = rd_inc + one_a;
        head_address = rd_ptr$q;
        next_address = rd_inc;
        if (pop) begin
            rd_ptr$d = rd_inc;
            rd_inc_x$d = rd_inc2 ^ one_a;
        end
        head_valid$d = (words$q != zero_c) & ~(pop & (words$q == one_c));
        valid = head_valid$q;
        if (push & ~pop) begin
            words$d = words$q + one_c;
        end
        if (~push & pop) begin
            words$d = words$q - one_c;
        end
        count = words$q;
    end
    
endmodule // memory_arbiter$queues$1$control


module memory_arbiter$queues$1$control$head_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$1$control$head_valid


module memory_arbiter$queues$1$control$rd_inc_x(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$1$control$rd_inc_x


module memory_arbiter$queues$1$control$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$1$control$rd_ptr


module memory_arbiter$queues$1$control$tail_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$1$control$tail_ptr


module memory_arbiter$queues$1$control$words(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$1$control$words


module memory_arbiter$queues$1$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [15:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [15:0] read_data;
    
    // Update code (custom)
    reg [15:0] mem [0:15];
    reg [15:0] head_r;
    reg [15:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [15:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 16'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 16'd0;
       head_r = 16'd0;
       next_r = 16'd0;
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
endmodule // memory_arbiter$queues$1$lane


module memory_arbiter$queues$2(clock,push,data_in,pop,valid,data_out,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  [15:0] data_in;
    input wire  pop;
    output reg  valid;
    output reg  [15:0] data_out;
    output reg  [4:0] count;
    
    // Stub signals
    reg  control$clock;
    reg  control$push;
    reg  control$pop;
    wire  [3:0] control$tail_address;
    wire  [3:0] control$head_address;
    wire  [3:0] control$next_address;
    wire  control$valid;
    wire  [4:0] control$count;
    reg  lane$clock;
    reg  [3:0] lane$write_address;
    reg  [15:0] lane$write_data;
    reg  lane$write_enable;
    reg  [3:0] lane$head_address;
    reg  [3:0] lane$next_address;
    reg  lane$pop;
    wire  [15:0] lane$read_data;
    
    // Sub module instances
    memory_arbiter$queues$2$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    memory_arbiter$queues$2$lane lane(
        .clock(lane$clock),
        .write_address(lane$write_address),
        .write_data(lane$write_data),
        .write_enable(lane$write_enable),
        .head_address(lane$head_address),
        .next_address(lane$next_address),
        .pop(lane$pop),
        .read_data(lane$read_data)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        lane$clock = clock;
        control$push = push;
        control$pop = pop;
        lane$write_address = control$tail_address;
        lane$write_data = data_in;
        lane$write_enable = push;
        lane$head_address = control$head_address;
        lane$next_address = control$next_address;
        lane$pop = pop;
        valid = control$valid;
        data_out = lane$read_data;
        count = control$count;
    end
    
endmodule // memory_arbiter$queues$2


module memory_arbiter$queues$2$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [3:0] tail_address;
    output reg  [3:0] head_address;
    output reg  [3:0] next_address;
    output reg  valid;
    output reg  [4:0] count;
    
    // Constant declarations
    localparam  one_a = 4'h1;
    localparam  one_c = 5'b1;
    localparam  zero_c = 5'b0;
    
    // Stub signals
    reg  [3:0] tail_ptr$d;
    wire  [3:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [3:0] rd_ptr$d;
    wire  [3:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [3:0] rd_inc_x$d;
    wire  [3:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [4:0] words$d;
    wire  [4:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [3:0] rd_inc;
    reg  [3:0] rd_inc2;
    
    // Sub module instances
    memory_arbiter$queues$2$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    memory_arbiter$queues$2$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    memory_arbiter$queues$2$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    memory_arbiter$queues$2$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    memory_arbiter$queues$2$control$head_valid head_valid(
        .d(head_valid$d),
        .q(head_valid$q),
        .clock(head_valid$clock)
    );
    
    // Update code
    always @(*) begin
        tail_ptr$clock = clock;
        rd_ptr$clock = clock;
        rd_inc_x$clock = clock;
        words$clock = clock;
        head_valid$clock = clock;
        tail_ptr$d = tail_ptr$q;
        rd_ptr$d = rd_ptr$q;
        rd_inc_x$d = rd_inc_x$q;
        words$d = words$q;
        head_valid$d = head_valid$q;
        tail_address = tail_ptr$q;
        if (push) begin
            tail_ptr$d = tail_ptr$q + one_a;
        end
        rd_inc = rd_inc_x$q ^ one_a;
        rd_inc2 = rd_inc + one_a;
        head_address = rd_ptr$q;
        next_address = rd_inc;
        if (pop) begin
            rd_ptr$d = rd_inc;
            rd_inc_x$d = rd_inc2 ^ one_a;
        end
        head_valid$d = (words$q != zero_c) & ~(pop & (words$q == one_c));
        valid = head_valid$q;
        if (push & ~pop) begin
            words$d = words$q + one_c;
        end
        if (~push & pop) begin
            words$d = words$q - one_c;
        end
        count = words$q;
    end
    
endmodule // memory_arbiter$queues$2$control


module memory_arbiter$queues$2$control$head_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$2$control$head_valid


module memory_arbiter$queues$2$control$rd_inc_x(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$2$control$rd_inc_x


module memory_arbiter$queues$2$control$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$2$control$rd_ptr


module memory_arbiter$queues$2$control$tail_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$2$control$tail_ptr


module memory_arbiter$queues$2$control$words(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$2$control$words


module memory_arbiter$queues$2$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [15:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [15:0] read_data;
    
    // Update code (custom)
    reg [15:0] mem [0:15];
    reg [15:0] head_r;
    reg [15:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [15:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 16'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 16'd0;
       head_r = 16'd0;
       next_r = 16'd0;
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
endmodule // memory_arbiter$queues$2$lane


module memory_arbiter$queues$3(clock,push,data_in,pop,valid,data_out,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  [15:0] data_in;
    input wire  pop;
    output reg  valid;
    output reg  [15:0] data_out;
    output reg  [4:0] count;
    
    // Stub signals
    reg  control$clock;
    reg  control$push;
    reg  control$pop;
    wire  [3:0] control$tail_address;
    wire  [3:0] control$head_address;
    wire  [3:0] control$next_address;
    wire  control$valid;
    wire  [4:0] control$count;
    reg  lane$clock;
    reg  [3:0] lane$write_address;
    reg  [15:0] lane$write_data;
    reg  lane$write_enable;
    reg  [3:0] lane$head_address;
    reg  [3:0] lane$next_address;
    reg  lane$pop;
    wire  [15:0] lane$read_data;
    
    // Sub module instances
    memory_arbiter$queues$3$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    memory_arbiter$queues$3$lane lane(
        .clock(lane$clock),
        .write_address(lane$write_address),
        .write_data(lane$write_data),
        .write_enable(lane$write_enable),
        .head_address(lane$head_address),
        .next_address(lane$next_address),
        .pop(lane$pop),
        .read_data(lane$read_data)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        lane$clock = clock;
        control$push = push;
        control$pop = pop;
        lane$write_address = control$tail_address;
        lane$write_data = data_in;
        lane$write_enable = push;
        lane$head_address = control$head_address;
        lane$next_address = control$next_address;
        lane$pop = pop;
        valid = control$valid;
        data_out = lane$read_data;
        count = control$count;
    end
    
endmodule // memory_arbiter$queues$3


module memory_arbiter$queues$3$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [3:0] tail_address;
    output reg  [3:0] head_address;
    output reg  [3:0] next_address;
    output reg  valid;
    output reg  [4:0] count;
    
    // Constant declarations
    localparam  one_a = 4'h1;
    localparam  one_c = 5'b1;
    localparam  zero_c = 5'b0;
    
    // Stub signals
    reg  [3:0] tail_ptr$d;
    wire  [3:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [3:0] rd_ptr$d;
    wire  [3:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [3:0] rd_inc_x$d;
    wire  [3:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [4:0] words$d;
    wire  [4:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [3:0] rd_inc;
    reg  [3:0] rd_inc2;
    
    // Sub module instances
    memory_arbiter$queues$3$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    memory_arbiter$queues$3$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    memory_arbiter$queues$3$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    memory_arbiter$queues$3$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    memory_arbiter$queues$3$control$head_valid head_valid(
        .d(head_valid$d),
        .q(head_valid$q),
        .clock(head_valid$clock)
    );
    
    // Update code
    always @(*) begin
        tail_ptr$clock = clock;
        rd_ptr$clock = clock;
        rd_inc_x$clock = clock;
        words$clock = clock;
        head_valid$clock = clock;
        tail_ptr$d = tail_ptr$q;
        rd_ptr$d = rd_ptr$q;
        rd_inc_x$d = rd_inc_x$q;
        words$d = words$q;
        head_valid$d = head_valid$q;
        tail_address = tail_ptr$q;
        if (push) begin
            tail_ptr$d = tail_ptr$q + one_a;
        end
        rd_inc = rd_inc_x$q ^ one_a;
        rd_inc2 = rd_inc + one_a;
        head_address = rd_ptr$q;
        next_address = rd_inc;
        if (pop) begin
            rd_ptr$d = rd_inc;
            rd_inc_x$d = rd_inc2 ^ one_a;
        end
        head_valid$d = (words$q != zero_c) & ~(pop & (words$q == one_c));
        valid = head_valid$q;
        if (push & ~pop) begin
            words$d = words$q + one_c;
        end
        if (~push & pop) begin
            words$d = words$q - one_c;
        end
        count = words$q;
    end
    
endmodule // memory_arbiter$queues$3$control


module memory_arbiter$queues$3$control$head_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$3$control$head_valid


module memory_arbiter$queues$3$control$rd_inc_x(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$3$control$rd_inc_x


module memory_arbiter$queues$3$control$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$3$control$rd_ptr


module memory_arbiter$queues$3$control$tail_ptr(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$3$control$tail_ptr


module memory_arbiter$queues$3$control$words(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$queues$3$control$words


module memory_arbiter$queues$3$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [15:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [15:0] read_data;
    
    // Update code (custom)
    reg [15:0] mem [0:15];
    reg [15:0] head_r;
    reg [15:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [15:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 16'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 16'd0;
       head_r = 16'd0;
       next_r = 16'd0;
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
endmodule // memory_arbiter$queues$3$lane


module memory_arbiter$route(clock,push,data_in,pop,valid,data_out,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  [2:0] data_in;
    input wire  pop;
    output reg  valid;
    output reg  [2:0] data_out;
    output reg  [7:0] count;
    
    // Stub signals
    reg  control$clock;
    reg  control$push;
    reg  control$pop;
    wire  [6:0] control$tail_address;
    wire  [6:0] control$head_address;
    wire  [6:0] control$next_address;
    wire  control$valid;
    wire  [7:0] control$count;
    reg  lane$clock;
    reg  [6:0] lane$write_address;
    reg  [2:0] lane$write_data;
    reg  lane$write_enable;
    reg  [6:0] lane$head_address;
    reg  [6:0] lane$next_address;
    reg  lane$pop;
    wire  [2:0] lane$read_data;
    
    // Sub module instances
    memory_arbiter$route$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    memory_arbiter$route$lane lane(
        .clock(lane$clock),
        .write_address(lane$write_address),
        .write_data(lane$write_data),
        .write_enable(lane$write_enable),
        .head_address(lane$head_address),
        .next_address(lane$next_address),
        .pop(lane$pop),
        .read_data(lane$read_data)
    );
    
    // Update code
    always @(*) begin
        control$clock = clock;
        lane$clock = clock;
        control$push = push;
        control$pop = pop;
        lane$write_address = control$tail_address;
        lane$write_data = data_in;
        lane$write_enable = push;
        lane$head_address = control$head_address;
        lane$next_address = control$next_address;
        lane$pop = pop;
        valid = control$valid;
        data_out = lane$read_data;
        count = control$count;
    end
    
endmodule // memory_arbiter$route


module memory_arbiter$route$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [6:0] tail_address;
    output reg  [6:0] head_address;
    output reg  [6:0] next_address;
    output reg  valid;
    output reg  [7:0] count;
    
    // Constant declarations
    localparam  one_a = 7'b1;
    localparam  one_c = 8'h1;
    localparam  zero_c = 8'h0;
    
    // Stub signals
    reg  [6:0] tail_ptr$d;
    wire  [6:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [6:0] rd_ptr$d;
    wire  [6:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [6:0] rd_inc_x$d;
    wire  [6:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [7:0] words$d;
    wire  [7:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [6:0] rd_inc;
    reg  [6:0] rd_inc2;
    
    // Sub module instances
    memory_arbiter$route$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    memory_arbiter$route$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    memory_arbiter$route$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    memory_arbiter$route$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    memory_arbiter$route$control$head_valid head_valid(
        .d(head_valid$d),
        .q(head_valid$q),
        .clock(head_valid$clock)
    );
    
    // Update code
    always @(*) begin
        tail_ptr$clock = clock;
        rd_ptr$clock = clock;
        rd_inc_x$clock = clock;
        words$clock = clock;
        head_valid$clock = clock;
        tail_ptr$d = tail_ptr$q;
        rd_ptr$d = rd_ptr$q;
        rd_inc_x$d = rd_inc_x$q;
        words$d = words$q;
        head_valid$d = head_valid$q;
        tail_address = tail_ptr$q;
        if (push) begin
            tail_ptr$d = tail_ptr$q + one_a;
        end
        rd_inc = rd_inc_x$q ^ one_a;
        rd_inc2 = rd_inc + one_a;
        head_address = rd_ptr$q;
        next_address = rd_inc;
        if (pop) begin
            rd_ptr$d = rd_inc;
            rd_inc_x$d = rd_inc2 ^ one_a;
        end
        head_valid$d = (words$q != zero_c) & ~(pop & (words$q == one_c));
        valid = head_valid$q;
        if (push & ~pop) begin
            words$d = words$q + one_c;
        end
        if (~push & pop) begin
            words$d = words$q - one_c;
        end
        count = words$q;
    end
    
endmodule // memory_arbiter$route$control


module memory_arbiter$route$control$head_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$route$control$head_valid


module memory_arbiter$route$control$rd_inc_x(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$route$control$rd_inc_x


module memory_arbiter$route$control$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$route$control$rd_ptr


module memory_arbiter$route$control$tail_ptr(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$route$control$tail_ptr


module memory_arbiter$route$control$words(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$route$control$words


module memory_arbiter$route$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [6:0] write_address;
    input wire  [2:0] write_data;
    input wire  write_enable;
    input wire  [6:0] head_address;
    input wire  [6:0] next_address;
    input wire  pop;
    output reg  [2:0] read_data;
    
    // Update code (custom)
    reg [2:0] mem [0:127];
    reg [2:0] head_r;
    reg [2:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [2:0] mem_n [0:127];
    initial for (i = 0; i <= 127; i = i + 1) mem_n[i] = 3'd0;
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
       for (i = 0; i <= 127; i = i + 1) mem[i] = 3'd0;
       head_r = 3'd0;
       next_r = 3'd0;
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
endmodule // memory_arbiter$route$lane


module memory_arbiter$rr(clock,request$0,request$1,request$2,request$3,found,pick,granted$0,granted$1,granted$2,granted$3);
    
    // Module arguments
    input wire  clock;
    input wire  request$0;
    input wire  request$1;
    input wire  request$2;
    input wire  request$3;
    output reg  found;
    output reg  [2:0] pick;
    output reg  granted$0;
    output reg  granted$1;
    output reg  granted$2;
    output reg  granted$3;
    
    // Update code (custom)
    reg [2:0] last;
    initial last = 3'd0;
    always @(*) begin
       found = request$0 | request$1 | request$2 | request$3;
       pick = 3'd0;
       case (last)
          3'd0: begin if (request$1) pick = 3'd1; else if (request$2) pick = 3'd2; else if (request$3) pick = 3'd3; else if (request$0) pick = 3'd0; granted$1 = request$1; granted$2 = request$2 & !request$1; granted$3 = request$3 & !request$1 & !request$2; granted$0 = request$0 & !request$1 & !request$2 & !request$3; end
          3'd1: begin if (request$2) pick = 3'd2; else if (request$3) pick = 3'd3; else if (request$0) pick = 3'd0; else if (request$1) pick = 3'd1; granted$2 = request$2; granted$3 = request$3 & !request$2; granted$0 = request$0 & !request$2 & !request$3; granted$1 = request$1 & !request$2 & !request$3 & !request$0; end
          3'd2: begin if (request$3) pick = 3'd3; else if (request$0) pick = 3'd0; else if (request$1) pick = 3'd1; else if (request$2) pick = 3'd2; granted$3 = request$3; granted$0 = request$0 & !request$3; granted$1 = request$1 & !request$3 & !request$0; granted$2 = request$2 & !request$3 & !request$0 & !request$1; end
          3'd3: begin if (request$0) pick = 3'd0; else if (request$1) pick = 3'd1; else if (request$2) pick = 3'd2; else if (request$3) pick = 3'd3; granted$0 = request$0; granted$1 = request$1 & !request$0; granted$2 = request$2 & !request$0 & !request$1; granted$3 = request$3 & !request$0 & !request$1 & !request$2; end
          default: begin pick = 0; granted$0 = 1'b0; granted$1 = 1'b0; granted$2 = 1'b0; granted$3 = 1'b0; end
       endcase
    end
    always @(posedge clock) begin
       if (found) last <= pick;
    end
endmodule // memory_arbiter$rr


module memory_arbiter$valid_r$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$valid_r$0


module memory_arbiter$valid_r$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$valid_r$1


module memory_arbiter$valid_r$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$valid_r$2


module memory_arbiter$valid_r$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // memory_arbiter$valid_r$3
