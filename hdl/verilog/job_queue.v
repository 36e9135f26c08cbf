// job_queue: exported from rust-hdl by `shelling export-verilog`; do not edit.


module job_queue(clock,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_wx,in_wy,in_sh,in_first,in_count,in_retire,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_first,out_count,out_retire,occupied);
    
    // Module arguments
    input wire  clock;
    input wire  in_valid;
    output reg  in_ready;
    input wire  [15:0] in_id;
    input wire  [17:0] in_ax;
    input wire  [17:0] in_ay;
    input wire  [17:0] in_bx;
    input wire  [17:0] in_by;
    input wire  [17:0] in_wx;
    input wire  [17:0] in_wy;
    input wire  [5:0] in_sh;
    input wire  [10:0] in_first;
    input wire  [10:0] in_count;
    input wire  in_retire;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [15:0] out_id;
    output reg  [17:0] out_ax;
    output reg  [17:0] out_ay;
    output reg  [17:0] out_bx;
    output reg  [17:0] out_by;
    output reg  [17:0] out_wx;
    output reg  [17:0] out_wy;
    output reg  [5:0] out_sh;
    output reg  [10:0] out_first;
    output reg  [10:0] out_count;
    output reg  out_retire;
    output reg  occupied;
    
    // Constant declarations
    localparam  retire_bit = 29'h400000;
    localparam  one5 = 5'b1;
    localparam  almost_full = 5'b1111;
    localparam  full = 5'b10000;
    localparam  empty = 5'b0;
    
    // Stub signals
    reg  control$clock;
    reg  control$push;
    reg  control$pop;
    wire  [3:0] control$tail_address;
    wire  [3:0] control$head_address;
    wire  [3:0] control$next_address;
    wire  control$valid;
    wire  [4:0] control$count;
    reg  lane_id$clock;
    reg  [3:0] lane_id$write_address;
    reg  [15:0] lane_id$write_data;
    reg  lane_id$write_enable;
    reg  [3:0] lane_id$head_address;
    reg  [3:0] lane_id$next_address;
    reg  lane_id$pop;
    wire  [15:0] lane_id$read_data;
    reg  lane_ax$clock;
    reg  [3:0] lane_ax$write_address;
    reg  [17:0] lane_ax$write_data;
    reg  lane_ax$write_enable;
    reg  [3:0] lane_ax$head_address;
    reg  [3:0] lane_ax$next_address;
    reg  lane_ax$pop;
    wire  [17:0] lane_ax$read_data;
    reg  lane_ay$clock;
    reg  [3:0] lane_ay$write_address;
    reg  [17:0] lane_ay$write_data;
    reg  lane_ay$write_enable;
    reg  [3:0] lane_ay$head_address;
    reg  [3:0] lane_ay$next_address;
    reg  lane_ay$pop;
    wire  [17:0] lane_ay$read_data;
    reg  lane_bx$clock;
    reg  [3:0] lane_bx$write_address;
    reg  [17:0] lane_bx$write_data;
    reg  lane_bx$write_enable;
    reg  [3:0] lane_bx$head_address;
    reg  [3:0] lane_bx$next_address;
    reg  lane_bx$pop;
    wire  [17:0] lane_bx$read_data;
    reg  lane_by$clock;
    reg  [3:0] lane_by$write_address;
    reg  [17:0] lane_by$write_data;
    reg  lane_by$write_enable;
    reg  [3:0] lane_by$head_address;
    reg  [3:0] lane_by$next_address;
    reg  lane_by$pop;
    wire  [17:0] lane_by$read_data;
    reg  lane_wx$clock;
    reg  [3:0] lane_wx$write_address;
    reg  [17:0] lane_wx$write_data;
    reg  lane_wx$write_enable;
    reg  [3:0] lane_wx$head_address;
    reg  [3:0] lane_wx$next_address;
    reg  lane_wx$pop;
    wire  [17:0] lane_wx$read_data;
    reg  lane_wy$clock;
    reg  [3:0] lane_wy$write_address;
    reg  [17:0] lane_wy$write_data;
    reg  lane_wy$write_enable;
    reg  [3:0] lane_wy$head_address;
    reg  [3:0] lane_wy$next_address;
    reg  lane_wy$pop;
    wire  [17:0] lane_wy$read_data;
    reg  lane_job$clock;
    reg  [3:0] lane_job$write_address;
    reg  [28:0] lane_job$write_data;
    reg  lane_job$write_enable;
    reg  [3:0] lane_job$head_address;
    reg  [3:0] lane_job$next_address;
    reg  lane_job$pop;
    wire  [28:0] lane_job$read_data;
    reg  p_valid$d;
    wire  p_valid$q;
    reg  p_valid$clock;
    reg  [15:0] p_id$d;
    wire  [15:0] p_id$q;
    reg  p_id$clock;
    reg  [17:0] p_ax$d;
    wire  [17:0] p_ax$q;
    reg  p_ax$clock;
    reg  [17:0] p_ay$d;
    wire  [17:0] p_ay$q;
    reg  p_ay$clock;
    reg  [17:0] p_bx$d;
    wire  [17:0] p_bx$q;
    reg  p_bx$clock;
    reg  [17:0] p_by$d;
    wire  [17:0] p_by$q;
    reg  p_by$clock;
    reg  [17:0] p_wx$d;
    wire  [17:0] p_wx$q;
    reg  p_wx$clock;
    reg  [17:0] p_wy$d;
    wire  [17:0] p_wy$q;
    reg  p_wy$clock;
    reg  [28:0] p_job$d;
    wire  [28:0] p_job$q;
    reg  p_job$clock;
    reg  [4:0] held$d;
    wire  [4:0] held$q;
    reg  held$clock;
    reg  held_full$d;
    wire  held_full$q;
    reg  held_full$clock;
    
    // Local signals
    reg  take;
    reg  push;
    reg  pop;
    reg  [28:0] sh_lane;
    reg  [28:0] first_lane;
    reg  [28:0] count_lane;
    reg  [28:0] job_in;
    reg  [28:0] job_out;
    
    // Sub module instances
    job_queue$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    job_queue$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    job_queue$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    job_queue$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    job_queue$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    job_queue$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    job_queue$lane_wx lane_wx(
        .clock(lane_wx$clock),
        .write_address(lane_wx$write_address),
        .write_data(lane_wx$write_data),
        .write_enable(lane_wx$write_enable),
        .head_address(lane_wx$head_address),
        .next_address(lane_wx$next_address),
        .pop(lane_wx$pop),
        .read_data(lane_wx$read_data)
    );
    job_queue$lane_wy lane_wy(
        .clock(lane_wy$clock),
        .write_address(lane_wy$write_address),
        .write_data(lane_wy$write_data),
        .write_enable(lane_wy$write_enable),
        .head_address(lane_wy$head_address),
        .next_address(lane_wy$next_address),
        .pop(lane_wy$pop),
        .read_data(lane_wy$read_data)
    );
    job_queue$lane_job lane_job(
        .clock(lane_job$clock),
        .write_address(lane_job$write_address),
        .write_data(lane_job$write_data),
        .write_enable(lane_job$write_enable),
        .head_address(lane_job$head_address),
        .next_address(lane_job$next_address),
        .pop(lane_job$pop),
        .read_data(lane_job$read_data)
    );
    job_queue$p_valid p_valid(
        .d(p_valid$d),
        .q(p_valid$q),
        .clock(p_valid$clock)
    );
    job_queue$p_id p_id(
        .d(p_id$d),
        .q(p_id$q),
        .clock(p_id$clock)
    );
    job_queue$p_ax p_ax(
        .d(p_ax$d),
        .q(p_ax$q),
        .clock(p_ax$clock)
    );
    job_queue$p_ay p_ay(
        .d(p_ay$d),
        .q(p_ay$q),
        .clock(p_ay$clock)
    );
    job_queue$p_bx p_bx(
        .d(p_bx$d),
        .q(p_bx$q),
        .clock(p_bx$clock)
    );
    job_queue$p_by p_by(
        .d(p_by$d),
        .q(p_by$q),
        .clock(p_by$clock)
    );
    job_queue$p_wx p_wx(
        .d(p_wx$d),
        .q(p_wx$q),
        .clock(p_wx$clock)
    );
    job_queue$p_wy p_wy(
        .d(p_wy$d),
        .q(p_wy$q),
        .clock(p_wy$clock)
    );
    job_queue$p_job p_job(
        .d(p_job$d),
        .q(p_job$q),
        .clock(p_job$clock)
    );
    job_queue$held held(
        .d(held$d),
        .q(held$q),
        .clock(held$clock)
    );
    job_queue$held_full held_full(
        .d(held_full$d),
        .q(held_full$q),
        .clock(held_full$clock)
    );
    
    // Update code
    always @(*) begin
        p_valid$clock = clock;
        p_id$clock = clock;
        p_ax$clock = clock;
        p_ay$clock = clock;
        p_bx$clock = clock;
        p_by$clock = clock;
        p_wx$clock = clock;
        p_wy$clock = clock;
        p_job$clock = clock;
        held$clock = clock;
        held_full$clock = clock;
        p_valid$d = p_valid$q;
        p_id$d = p_id$q;
        p_ax$d = p_ax$q;
        p_ay$d = p_ay$q;
        p_bx$d = p_bx$q;
        p_by$d = p_by$q;
        p_wx$d = p_wx$q;
        p_wy$d = p_wy$q;
        p_job$d = p_job$q;
        held$d = held$q;
        held_full$d = held_full$q;
        control$clock = clock;
        lane_id$clock = clock;
        lane_ax$clock = clock;
        lane_ay$clock = clock;
        lane_bx$clock = clock;
        lane_by$clock = clock;
        lane_wx$clock = clock;
        lane_wy$clock = clock;
        lane_job$clock = clock;
        in_ready = ~held_full$q;
        take = in_valid & ~held_full$q;
        push = p_valid$q;
        control$push = push;
        sh_lane = ((in_sh) & 29'h1fffffff);
        first_lane = ((in_first) & 29'h1fffffff);
        count_lane = ((in_count) & 29'h1fffffff);
        job_in = (sh_lane << 32'h17) | (first_lane << 32'hb) | count_lane;
        if (in_retire) begin
            job_in = job_in | retire_bit;
        end
        p_valid$d = take;
        p_id$d = in_id;
        p_ax$d = in_ax;
        p_ay$d = in_ay;
        p_bx$d = in_bx;
        p_by$d = in_by;
        p_wx$d = in_wx;
        p_wy$d = in_wy;
        p_job$d = job_in;
        lane_id$write_data = p_id$q;
        lane_ax$write_data = p_ax$q;
        lane_ay$write_data = p_ay$q;
        lane_bx$write_data = p_bx$q;
        lane_by$write_data = p_by$q;
        lane_wx$write_data = p_wx$q;
        lane_wy$write_data = p_wy$q;
        lane_job$write_data = p_job$q;
        pop = control$valid & out_ready;
        control$pop = pop;
        out_valid = control$valid;
        occupied = held$q != empty;
        if (take & ~pop) begin
            held$d = held$q + one5;
        end
        if (~take & pop) begin
            held$d = held$q - one5;
        end
        held_full$d = ((held$q == full) & ~pop) | ((held$q == almost_full) & take & ~pop);
        out_id = lane_id$read_data;
        out_ax = lane_ax$read_data;
        out_ay = lane_ay$read_data;
        out_bx = lane_bx$read_data;
        out_by = lane_by$read_data;
        out_wx = lane_wx$read_data;
        out_wy = lane_wy$read_data;
        job_out = lane_job$read_data;
        out_sh = job_out[(32'h17)+:(6)];
        out_retire = job_out[32'h16];
        out_first = job_out[(32'hb)+:(11)];
        out_count = job_out[(32'h0)+:(11)];
        lane_id$write_address = control$tail_address;
        lane_id$write_enable = push;
        lane_id$head_address = control$head_address;
        lane_id$next_address = control$next_address;
        lane_id$pop = pop;
        lane_ax$write_address = control$tail_address;
        lane_ax$write_enable = push;
        lane_ax$head_address = control$head_address;
        lane_ax$next_address = control$next_address;
        lane_ax$pop = pop;
        lane_ay$write_address = control$tail_address;
        lane_ay$write_enable = push;
        lane_ay$head_address = control$head_address;
        lane_ay$next_address = control$next_address;
        lane_ay$pop = pop;
        lane_bx$write_address = control$tail_address;
        lane_bx$write_enable = push;
        lane_bx$head_address = control$head_address;
        lane_bx$next_address = control$next_address;
        lane_bx$pop = pop;
        lane_by$write_address = control$tail_address;
        lane_by$write_enable = push;
        lane_by$head_address = control$head_address;
        lane_by$next_address = control$next_address;
        lane_by$pop = pop;
        lane_wx$write_address = control$tail_address;
        lane_wx$write_enable = push;
        lane_wx$head_address = control$head_address;
        lane_wx$next_address = control$next_address;
        lane_wx$pop = pop;
        lane_wy$write_address = control$tail_address;
        lane_wy$write_enable = push;
        lane_wy$head_address = control$head_address;
        lane_wy$next_address = control$next_address;
        lane_wy$pop = pop;
        lane_job$write_address = control$tail_address;
        lane_job$write_enable = push;
        lane_job$head_address = control$head_address;
        lane_job$next_address = control$next_address;
        lane_job$pop = pop;
    end
    
endmodule // job_queue


module job_queue$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    job_queue$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    job_queue$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    job_queue$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    job_queue$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    job_queue$control$head_valid head_valid(
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
    
endmodule // job_queue$control


module job_queue$control$head_valid(d,q,clock);
    
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
          
endmodule // job_queue$control$head_valid


module job_queue$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // job_queue$control$rd_inc_x


module job_queue$control$rd_ptr(d,q,clock);
    
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
          
endmodule // job_queue$control$rd_ptr


module job_queue$control$tail_ptr(d,q,clock);
    
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
          
endmodule // job_queue$control$tail_ptr


module job_queue$control$words(d,q,clock);
    
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
          
endmodule // job_queue$control$words


module job_queue$held(d,q,clock);
    
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
          
endmodule // job_queue$held


module job_queue$held_full(d,q,clock);
    
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
          
endmodule // job_queue$held_full


module job_queue$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:15];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 18'd0;
       head_r = 18'd0;
       next_r = 18'd0;
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
endmodule // job_queue$lane_ax


module job_queue$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:15];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 18'd0;
       head_r = 18'd0;
       next_r = 18'd0;
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
endmodule // job_queue$lane_ay


module job_queue$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:15];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 18'd0;
       head_r = 18'd0;
       next_r = 18'd0;
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
endmodule // job_queue$lane_bx


module job_queue$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:15];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 18'd0;
       head_r = 18'd0;
       next_r = 18'd0;
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
endmodule // job_queue$lane_by


module job_queue$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // job_queue$lane_id


module job_queue$lane_job(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [28:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [28:0] read_data;
    
    // Update code (custom)
    reg [28:0] mem [0:15];
    reg [28:0] head_r;
    reg [28:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [28:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 29'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 29'd0;
       head_r = 29'd0;
       next_r = 29'd0;
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
endmodule // job_queue$lane_job


module job_queue$lane_wx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:15];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 18'd0;
       head_r = 18'd0;
       next_r = 18'd0;
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
endmodule // job_queue$lane_wx


module job_queue$lane_wy(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:15];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 18'd0;
       head_r = 18'd0;
       next_r = 18'd0;
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
endmodule // job_queue$lane_wy


module job_queue$p_ax(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_ax


module job_queue$p_ay(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_ay


module job_queue$p_bx(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_bx


module job_queue$p_by(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_by


module job_queue$p_id(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_id


module job_queue$p_job(d,q,clock);
    
    // Module arguments
    input wire  [28:0] d;
    output reg  [28:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 29'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_job


module job_queue$p_valid(d,q,clock);
    
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
          
endmodule // job_queue$p_valid


module job_queue$p_wx(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_wx


module job_queue$p_wy(d,q,clock);
    
    // Module arguments
    input wire  [17:0] d;
    output reg  [17:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 18'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // job_queue$p_wy
