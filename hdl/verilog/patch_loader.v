// patch_loader: exported from rust-hdl by `shelling export-verilog`; do not edit.


module patch_loader(clock,id_valid,id_ready,id,id_ready_next,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,loads);
    
    // Module arguments
    input wire  clock;
    input wire  id_valid;
    output reg  id_ready;
    input wire  [15:0] id;
    output reg  id_ready_next;
    output reg  mem_req;
    output reg  [15:0] mem_addr;
    input wire  mem_valid;
    input wire  [16:0] mem_ax;
    input wire  [16:0] mem_ay;
    input wire  [16:0] mem_bx;
    input wire  [16:0] mem_by;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [15:0] out_id;
    output reg  [16:0] out_ax;
    output reg  [16:0] out_ay;
    output reg  [16:0] out_bx;
    output reg  [16:0] out_by;
    output reg  [31:0] loads;
    
    // Constant declarations
    localparam  depth5 = 5'b10000;
    localparam  almost5 = 5'b1111;
    localparam  almost4 = 5'b1110;
    localparam  one5 = 5'b1;
    localparam  one4 = 4'h1;
    localparam  one32 = 32'h1;
    
    // Stub signals
    reg  [3:0] req_ptr$d;
    wire  [3:0] req_ptr$q;
    reg  req_ptr$clock;
    reg  [4:0] reserved$d;
    wire  [4:0] reserved$q;
    reg  reserved$clock;
    reg  full$d;
    wire  full$q;
    reg  full$clock;
    reg  req_valid$d;
    wire  req_valid$q;
    reg  req_valid$clock;
    reg  [15:0] req_addr$d;
    wire  [15:0] req_addr$q;
    reg  req_addr$clock;
    reg  [31:0] load_count$d;
    wire  [31:0] load_count$q;
    reg  load_count$clock;
    reg  fifo$clock;
    reg  fifo$push;
    reg  fifo$pop;
    wire  [3:0] fifo$tail_address;
    wire  [3:0] fifo$head_address;
    wire  [3:0] fifo$next_address;
    wire  fifo$valid;
    wire  [4:0] fifo$count;
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
    reg  [16:0] lane_ax$write_data;
    reg  lane_ax$write_enable;
    reg  [3:0] lane_ax$head_address;
    reg  [3:0] lane_ax$next_address;
    reg  lane_ax$pop;
    wire  [16:0] lane_ax$read_data;
    reg  lane_ay$clock;
    reg  [3:0] lane_ay$write_address;
    reg  [16:0] lane_ay$write_data;
    reg  lane_ay$write_enable;
    reg  [3:0] lane_ay$head_address;
    reg  [3:0] lane_ay$next_address;
    reg  lane_ay$pop;
    wire  [16:0] lane_ay$read_data;
    reg  lane_bx$clock;
    reg  [3:0] lane_bx$write_address;
    reg  [16:0] lane_bx$write_data;
    reg  lane_bx$write_enable;
    reg  [3:0] lane_bx$head_address;
    reg  [3:0] lane_bx$next_address;
    reg  lane_bx$pop;
    wire  [16:0] lane_bx$read_data;
    reg  lane_by$clock;
    reg  [3:0] lane_by$write_address;
    reg  [16:0] lane_by$write_data;
    reg  lane_by$write_enable;
    reg  [3:0] lane_by$head_address;
    reg  [3:0] lane_by$next_address;
    reg  lane_by$pop;
    wire  [16:0] lane_by$read_data;
    
    // Local signals
    reg  room;
    reg  full_next;
    reg  accept;
    reg  pop;
    reg  [3:0] req_inc;
    reg  [4:0] reserved_inc;
    reg  [4:0] reserved_dec;
    reg  [31:0] load_inc;
    reg  held_all;
    reg  held_almost;
    
    // Sub module instances
    patch_loader$req_ptr req_ptr(
        .d(req_ptr$d),
        .q(req_ptr$q),
        .clock(req_ptr$clock)
    );
    patch_loader$reserved reserved(
        .d(reserved$d),
        .q(reserved$q),
        .clock(reserved$clock)
    );
    patch_loader$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    patch_loader$req_valid req_valid(
        .d(req_valid$d),
        .q(req_valid$q),
        .clock(req_valid$clock)
    );
    patch_loader$req_addr req_addr(
        .d(req_addr$d),
        .q(req_addr$q),
        .clock(req_addr$clock)
    );
    patch_loader$load_count load_count(
        .d(load_count$d),
        .q(load_count$q),
        .clock(load_count$clock)
    );
    patch_loader$fifo fifo(
        .clock(fifo$clock),
        .push(fifo$push),
        .pop(fifo$pop),
        .tail_address(fifo$tail_address),
        .head_address(fifo$head_address),
        .next_address(fifo$next_address),
        .valid(fifo$valid),
        .count(fifo$count)
    );
    patch_loader$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    patch_loader$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    patch_loader$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    patch_loader$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    patch_loader$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    
    // Update code
    always @(*) begin
        req_ptr$clock = clock;
        reserved$clock = clock;
        full$clock = clock;
        req_valid$clock = clock;
        req_addr$clock = clock;
        load_count$clock = clock;
        req_ptr$d = req_ptr$q;
        reserved$d = reserved$q;
        full$d = full$q;
        req_valid$d = req_valid$q;
        req_addr$d = req_addr$q;
        load_count$d = load_count$q;
        fifo$clock = clock;
        lane_id$clock = clock;
        lane_ax$clock = clock;
        lane_ay$clock = clock;
        lane_bx$clock = clock;
        lane_by$clock = clock;
        room = ~full$q;
        id_ready = room;
        accept = id_valid & room;
        pop = fifo$valid & out_ready;
        fifo$pop = pop;
        req_inc = req_ptr$q + one4;
        reserved_inc = reserved$q + one5;
        reserved_dec = reserved$q - one5;
        load_inc = load_count$q + one32;
        lane_id$write_address = req_ptr$q;
        lane_id$write_data = req_addr$q;
        lane_id$write_enable = req_valid$q;
        req_valid$d = accept;
        req_addr$d = id;
        if (req_valid$q) begin
            req_ptr$d = req_inc;
        end
        mem_req = req_valid$q;
        mem_addr = req_addr$q;
        lane_ax$write_address = fifo$tail_address;
        lane_ay$write_address = fifo$tail_address;
        lane_bx$write_address = fifo$tail_address;
        lane_by$write_address = fifo$tail_address;
        lane_ax$write_data = mem_ax;
        lane_ay$write_data = mem_ay;
        lane_bx$write_data = mem_bx;
        lane_by$write_data = mem_by;
        lane_ax$write_enable = mem_valid;
        lane_ay$write_enable = mem_valid;
        lane_bx$write_enable = mem_valid;
        lane_by$write_enable = mem_valid;
        fifo$push = mem_valid;
        if (mem_valid) begin
            load_count$d = load_inc;
        end
        loads = load_count$q;
        lane_id$head_address = fifo$head_address;
        lane_id$next_address = fifo$next_address;
        lane_id$pop = pop;
        lane_ax$head_address = fifo$head_address;
        lane_ax$next_address = fifo$next_address;
        lane_ax$pop = pop;
        lane_ay$head_address = fifo$head_address;
        lane_ay$next_address = fifo$next_address;
        lane_ay$pop = pop;
        lane_bx$head_address = fifo$head_address;
        lane_bx$next_address = fifo$next_address;
        lane_bx$pop = pop;
        lane_by$head_address = fifo$head_address;
        lane_by$next_address = fifo$next_address;
        lane_by$pop = pop;
        out_valid = fifo$valid;
        out_id = lane_id$read_data;
        out_ax = lane_ax$read_data;
        out_ay = lane_ay$read_data;
        out_bx = lane_bx$read_data;
        out_by = lane_by$read_data;
        if (req_valid$q & ~pop) begin
            reserved$d = reserved_inc;
        end
        if (~req_valid$q & pop) begin
            reserved$d = reserved_dec;
        end
        held_all = (reserved$q == depth5) | ((reserved$q == almost5) & req_valid$q);
        held_almost = ((reserved$q == almost5) & ~req_valid$q) | ((reserved$q == almost4) & req_valid$q);
        full_next = (held_all & ~pop) | (held_almost & accept & ~pop);
        full$d = full_next;
        id_ready_next = ~full_next;
    end
    
endmodule // patch_loader


module patch_loader$fifo(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    patch_loader$fifo$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    patch_loader$fifo$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    patch_loader$fifo$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    patch_loader$fifo$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    patch_loader$fifo$head_valid head_valid(
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
    
endmodule // patch_loader$fifo


module patch_loader$fifo$head_valid(d,q,clock);
    
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
          
endmodule // patch_loader$fifo$head_valid


module patch_loader$fifo$rd_inc_x(d,q,clock);
    
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
          
endmodule // patch_loader$fifo$rd_inc_x


module patch_loader$fifo$rd_ptr(d,q,clock);
    
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
          
endmodule // patch_loader$fifo$rd_ptr


module patch_loader$fifo$tail_ptr(d,q,clock);
    
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
          
endmodule // patch_loader$fifo$tail_ptr


module patch_loader$fifo$words(d,q,clock);
    
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
          
endmodule // patch_loader$fifo$words


module patch_loader$full(d,q,clock);
    
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
          
endmodule // patch_loader$full


module patch_loader$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:15];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 17'd0;
       head_r = 17'd0;
       next_r = 17'd0;
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
endmodule // patch_loader$lane_ax


module patch_loader$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:15];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 17'd0;
       head_r = 17'd0;
       next_r = 17'd0;
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
endmodule // patch_loader$lane_ay


module patch_loader$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:15];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 17'd0;
       head_r = 17'd0;
       next_r = 17'd0;
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
endmodule // patch_loader$lane_bx


module patch_loader$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:15];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 17'd0;
       head_r = 17'd0;
       next_r = 17'd0;
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
endmodule // patch_loader$lane_by


module patch_loader$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // patch_loader$lane_id


module patch_loader$load_count(d,q,clock);
    
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
          
endmodule // patch_loader$load_count


module patch_loader$req_addr(d,q,clock);
    
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
          
endmodule // patch_loader$req_addr


module patch_loader$req_ptr(d,q,clock);
    
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
          
endmodule // patch_loader$req_ptr


module patch_loader$req_valid(d,q,clock);
    
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
          
endmodule // patch_loader$req_valid


module patch_loader$reserved(d,q,clock);
    
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
          
endmodule // patch_loader$reserved
