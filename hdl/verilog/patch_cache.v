// patch_cache: exported from rust-hdl by `shelling export-verilog`; do not edit.


module patch_cache(clock,cfg_enable,cfg_mask,flush,flushing,req,addr,resp_valid,resp_ax,resp_ay,resp_bx,resp_by,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,hits,misses);
    
    // Module arguments
    input wire  clock;
    input wire  cfg_enable;
    input wire  [11:0] cfg_mask;
    input wire  flush;
    output reg  flushing;
    input wire  req;
    input wire  [15:0] addr;
    output reg  resp_valid;
    output reg  [16:0] resp_ax;
    output reg  [16:0] resp_ay;
    output reg  [16:0] resp_bx;
    output reg  [16:0] resp_by;
    output reg  mem_req;
    output reg  [15:0] mem_addr;
    input wire  mem_valid;
    input wire  [16:0] mem_ax;
    input wire  [16:0] mem_ay;
    input wire  [16:0] mem_bx;
    input wire  [16:0] mem_by;
    output reg  [31:0] hits;
    output reg  [31:0] misses;
    
    // Constant declarations
    localparam  valid_flag = 17'b10000000000000000;
    localparam  zero5 = 5'b0;
    localparam  one5 = 5'b1;
    localparam  one4 = 4'h1;
    localparam  one32 = 32'h1;
    localparam  one12 = 12'h1;
    localparam  last_line = 12'hfff;
    localparam  zero12 = 12'h0;
    localparam  zero17 = 17'b0;
    
    // Stub signals
    reg  q_lane$clock;
    reg  [3:0] q_lane$read_address;
    wire  [15:0] q_lane$read_data;
    reg  [3:0] q_lane$write_address;
    reg  [15:0] q_lane$write_data;
    reg  q_lane$write_enable;
    reg  [3:0] wr_ptr$d;
    wire  [3:0] wr_ptr$q;
    reg  wr_ptr$clock;
    reg  [3:0] rd_ptr$d;
    wire  [3:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [4:0] count$d;
    wire  [4:0] count$q;
    reg  count$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    reg  b_valid$d;
    wire  b_valid$q;
    reg  b_valid$clock;
    reg  [15:0] b_id$d;
    wire  [15:0] b_id$q;
    reg  b_id$clock;
    reg  [16:0] b_key$d;
    wire  [16:0] b_key$q;
    reg  b_key$clock;
    reg  [11:0] b_line$d;
    wire  [11:0] b_line$q;
    reg  b_line$clock;
    reg  w_valid$d;
    wire  w_valid$q;
    reg  w_valid$clock;
    reg  fl_on$d;
    wire  fl_on$q;
    reg  fl_on$clock;
    reg  [11:0] fl_line$d;
    wire  [11:0] fl_line$q;
    reg  fl_line$clock;
    reg  mreq$d;
    wire  mreq$q;
    reg  mreq$clock;
    reg  rv$d;
    wire  rv$q;
    reg  rv$clock;
    reg  [16:0] rax$d;
    wire  [16:0] rax$q;
    reg  rax$clock;
    reg  [16:0] ray$d;
    wire  [16:0] ray$q;
    reg  ray$clock;
    reg  [16:0] rbx$d;
    wire  [16:0] rbx$q;
    reg  rbx$clock;
    reg  [16:0] rby$d;
    wire  [16:0] rby$q;
    reg  rby$clock;
    reg  [31:0] hit_count$d;
    wire  [31:0] hit_count$q;
    reg  hit_count$clock;
    reg  [31:0] miss_count$d;
    wire  [31:0] miss_count$q;
    reg  miss_count$clock;
    reg  tag$clock;
    reg  [11:0] tag$read_address;
    wire  [16:0] tag$read_data;
    reg  [11:0] tag$write_address;
    reg  [16:0] tag$write_data;
    reg  tag$write_enable;
    reg  lane_ax$clock;
    reg  [11:0] lane_ax$read_address;
    wire  [16:0] lane_ax$read_data;
    reg  [11:0] lane_ax$write_address;
    reg  [16:0] lane_ax$write_data;
    reg  lane_ax$write_enable;
    reg  lane_ay$clock;
    reg  [11:0] lane_ay$read_address;
    wire  [16:0] lane_ay$read_data;
    reg  [11:0] lane_ay$write_address;
    reg  [16:0] lane_ay$write_data;
    reg  lane_ay$write_enable;
    reg  lane_bx$clock;
    reg  [11:0] lane_bx$read_address;
    wire  [16:0] lane_bx$read_data;
    reg  [11:0] lane_bx$write_address;
    reg  [16:0] lane_bx$write_data;
    reg  lane_bx$write_enable;
    reg  lane_by$clock;
    reg  [11:0] lane_by$read_address;
    wire  [16:0] lane_by$read_data;
    reg  [11:0] lane_by$write_address;
    reg  [16:0] lane_by$write_data;
    reg  lane_by$write_enable;
    
    // Local signals
    reg  push;
    reg  tag_match;
    reg  hit;
    reg  miss;
    reg  fill;
    reg  advance;
    reg  [3:0] wr_inc;
    reg  [3:0] rd_inc;
    reg  [3:0] rd_addr;
    reg  [4:0] count_inc;
    reg  [4:0] count_dec;
    reg  [4:0] count_left;
    reg  [11:0] head_low;
    reg  [11:0] head_line;
    reg  [16:0] head_key;
    reg  [31:0] hit_inc;
    reg  [31:0] miss_inc;
    reg  [11:0] fl_inc;
    
    // Sub module instances
    patch_cache$q_lane q_lane(
        .clock(q_lane$clock),
        .read_address(q_lane$read_address),
        .read_data(q_lane$read_data),
        .write_address(q_lane$write_address),
        .write_data(q_lane$write_data),
        .write_enable(q_lane$write_enable)
    );
    patch_cache$wr_ptr wr_ptr(
        .d(wr_ptr$d),
        .q(wr_ptr$q),
        .clock(wr_ptr$clock)
    );
    patch_cache$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    patch_cache$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    patch_cache$head_valid head_valid(
        .d(head_valid$d),
        .q(head_valid$q),
        .clock(head_valid$clock)
    );
    patch_cache$b_valid b_valid(
        .d(b_valid$d),
        .q(b_valid$q),
        .clock(b_valid$clock)
    );
    patch_cache$b_id b_id(
        .d(b_id$d),
        .q(b_id$q),
        .clock(b_id$clock)
    );
    patch_cache$b_key b_key(
        .d(b_key$d),
        .q(b_key$q),
        .clock(b_key$clock)
    );
    patch_cache$b_line b_line(
        .d(b_line$d),
        .q(b_line$q),
        .clock(b_line$clock)
    );
    patch_cache$w_valid w_valid(
        .d(w_valid$d),
        .q(w_valid$q),
        .clock(w_valid$clock)
    );
    patch_cache$fl_on fl_on(
        .d(fl_on$d),
        .q(fl_on$q),
        .clock(fl_on$clock)
    );
    patch_cache$fl_line fl_line(
        .d(fl_line$d),
        .q(fl_line$q),
        .clock(fl_line$clock)
    );
    patch_cache$mreq mreq(
        .d(mreq$d),
        .q(mreq$q),
        .clock(mreq$clock)
    );
    patch_cache$rv rv(
        .d(rv$d),
        .q(rv$q),
        .clock(rv$clock)
    );
    patch_cache$rax rax(
        .d(rax$d),
        .q(rax$q),
        .clock(rax$clock)
    );
    patch_cache$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    patch_cache$rbx rbx(
        .d(rbx$d),
        .q(rbx$q),
        .clock(rbx$clock)
    );
    patch_cache$rby rby(
        .d(rby$d),
        .q(rby$q),
        .clock(rby$clock)
    );
    patch_cache$hit_count hit_count(
        .d(hit_count$d),
        .q(hit_count$q),
        .clock(hit_count$clock)
    );
    patch_cache$miss_count miss_count(
        .d(miss_count$d),
        .q(miss_count$q),
        .clock(miss_count$clock)
    );
    patch_cache$tag tag(
        .clock(tag$clock),
        .read_address(tag$read_address),
        .read_data(tag$read_data),
        .write_address(tag$write_address),
        .write_data(tag$write_data),
        .write_enable(tag$write_enable)
    );
    patch_cache$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .read_address(lane_ax$read_address),
        .read_data(lane_ax$read_data),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable)
    );
    patch_cache$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .read_address(lane_ay$read_address),
        .read_data(lane_ay$read_data),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable)
    );
    patch_cache$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .read_address(lane_bx$read_address),
        .read_data(lane_bx$read_data),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable)
    );
    patch_cache$lane_by lane_by(
        .clock(lane_by$clock),
        .read_address(lane_by$read_address),
        .read_data(lane_by$read_data),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable)
    );
    
    // Update code
    always @(*) begin
        wr_ptr$clock = clock;
        rd_ptr$clock = clock;
        count$clock = clock;
        head_valid$clock = clock;
        b_valid$clock = clock;
        b_id$clock = clock;
        b_key$clock = clock;
        b_line$clock = clock;
        w_valid$clock = clock;
        fl_on$clock = clock;
        fl_line$clock = clock;
        mreq$clock = clock;
        rv$clock = clock;
        rax$clock = clock;
        ray$clock = clock;
        rbx$clock = clock;
        rby$clock = clock;
        hit_count$clock = clock;
        miss_count$clock = clock;
        wr_ptr$d = wr_ptr$q;
        rd_ptr$d = rd_ptr$q;
        count$d = count$q;
        head_valid$d = head_valid$q;
        b_valid$d = b_valid$q;
        b_id$d = b_id$q;
        b_key$d = b_key$q;
        b_line$d = b_line$q;
        w_valid$d = w_valid$q;
        fl_on$d = fl_on$q;
        fl_line$d = fl_line$q;
        mreq$d = mreq$q;
        rv$d = rv$q;
        rax$d = rax$q;
        ray$d = ray$q;
        rbx$d = rbx$q;
        rby$d = rby$q;
        hit_count$d = hit_count$q;
        miss_count$d = miss_count$q;
        q_lane$clock = clock;
        tag$clock = clock;
        lane_ax$clock = clock;
        lane_ay$clock = clock;
        lane_bx$clock = clock;
        lane_by$clock = clock;
        wr_inc = wr_ptr$q + one4;
        rd_inc = rd_ptr$q + one4;
        count_inc = count$q + one5;
        count_dec = count$q - one5;
        hit_inc = hit_count$q + one32;
        miss_inc = miss_count$q + one32;
        tag_match = tag$read_data == b_key$q;
        hit = b_valid$q & tag_match;
        miss = b_valid$q & ~tag_match;
        fill = w_valid$q & mem_valid;
        advance = head_valid$q & ~w_valid$q & ~miss;
        push = cfg_enable & req;
        q_lane$write_address = wr_ptr$q;
        q_lane$write_data = addr;
        q_lane$write_enable = push;
        if (push) begin
            wr_ptr$d = wr_inc;
        end
        rd_addr = rd_ptr$q;
        count_left = count$q;
        if (advance) begin
            rd_addr = rd_inc;
            rd_ptr$d = rd_inc;
            count_left = count_dec;
        end
        q_lane$read_address = rd_addr;
        head_valid$d = count_left != zero5;
        if (push & ~advance) begin
            count$d = count_inc;
        end
        if (~push & advance) begin
            count$d = count_dec;
        end
        head_low = ((q_lane$read_data) & 12'hfff);
        head_line = head_low & cfg_mask;
        head_key = valid_flag | ((q_lane$read_data) & 17'h1ffff);
        tag$read_address = head_line;
        lane_ax$read_address = head_line;
        lane_ay$read_address = head_line;
        lane_bx$read_address = head_line;
        lane_by$read_address = head_line;
        b_valid$d = advance;
        if (advance) begin
            b_id$d = q_lane$read_data;
            b_key$d = head_key;
            b_line$d = head_line;
        end
        mreq$d = miss;
        w_valid$d = (w_valid$q & ~mem_valid) | miss;
        tag$write_address = b_line$q;
        lane_ax$write_address = b_line$q;
        lane_ay$write_address = b_line$q;
        lane_bx$write_address = b_line$q;
        lane_by$write_address = b_line$q;
        tag$write_data = b_key$q;
        lane_ax$write_data = mem_ax;
        lane_ay$write_data = mem_ay;
        lane_bx$write_data = mem_bx;
        lane_by$write_data = mem_by;
        tag$write_enable = fill;
        fl_inc = fl_line$q + one12;
        if (fl_on$q) begin
            tag$write_address = fl_line$q;
            tag$write_data = zero17;
            tag$write_enable = 1'b1;
            fl_line$d = fl_inc;
            if (fl_line$q == last_line) begin
                fl_on$d = 1'b0;
            end
        end
        if (flush & ~fl_on$q) begin
            fl_on$d = 1'b1;
            fl_line$d = zero12;
        end
        flushing = fl_on$q;
        lane_ax$write_enable = fill;
        lane_ay$write_enable = fill;
        lane_bx$write_enable = fill;
        lane_by$write_enable = fill;
        rv$d = hit | fill;
        if (hit) begin
            rax$d = lane_ax$read_data;
            ray$d = lane_ay$read_data;
            rbx$d = lane_bx$read_data;
            rby$d = lane_by$read_data;
        end
        if (fill) begin
            rax$d = mem_ax;
            ray$d = mem_ay;
            rbx$d = mem_bx;
            rby$d = mem_by;
        end
        if (hit) begin
            hit_count$d = hit_inc;
        end
        if (miss) begin
            miss_count$d = miss_inc;
        end
        hits = hit_count$q;
        misses = miss_count$q;
        mem_req = req;
        mem_addr = addr;
        resp_valid = mem_valid;
        resp_ax = mem_ax;
        resp_ay = mem_ay;
        resp_bx = mem_bx;
        resp_by = mem_by;
        if (cfg_enable) begin
            mem_req = mreq$q;
            mem_addr = b_id$q;
            resp_valid = rv$q;
            resp_ax = rax$q;
            resp_ay = ray$q;
            resp_bx = rbx$q;
            resp_by = rby$q;
        end
    end
    
endmodule // patch_cache


module patch_cache$b_id(d,q,clock);
    
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
          
endmodule // patch_cache$b_id


module patch_cache$b_key(d,q,clock);
    
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
          
endmodule // patch_cache$b_key


module patch_cache$b_line(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$b_line


module patch_cache$b_valid(d,q,clock);
    
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
          
endmodule // patch_cache$b_valid


module patch_cache$count(d,q,clock);
    
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
          
endmodule // patch_cache$count


module patch_cache$fl_line(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$fl_line


module patch_cache$fl_on(d,q,clock);
    
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
          
endmodule // patch_cache$fl_on


module patch_cache$head_valid(d,q,clock);
    
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
          
endmodule // patch_cache$head_valid


module patch_cache$hit_count(d,q,clock);
    
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
          
endmodule // patch_cache$hit_count


module patch_cache$lane_ax(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] read_address;
    output reg  [16:0] read_data;
    input wire  [11:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [16:0] mem [0:4095];
    integer i;
    initial begin
       for (i = 0; i <= 4095; i = i + 1) mem[i] = 17'd0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // patch_cache$lane_ax


module patch_cache$lane_ay(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] read_address;
    output reg  [16:0] read_data;
    input wire  [11:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [16:0] mem [0:4095];
    integer i;
    initial begin
       for (i = 0; i <= 4095; i = i + 1) mem[i] = 17'd0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // patch_cache$lane_ay


module patch_cache$lane_bx(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] read_address;
    output reg  [16:0] read_data;
    input wire  [11:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [16:0] mem [0:4095];
    integer i;
    initial begin
       for (i = 0; i <= 4095; i = i + 1) mem[i] = 17'd0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // patch_cache$lane_bx


module patch_cache$lane_by(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] read_address;
    output reg  [16:0] read_data;
    input wire  [11:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [16:0] mem [0:4095];
    integer i;
    initial begin
       for (i = 0; i <= 4095; i = i + 1) mem[i] = 17'd0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // patch_cache$lane_by


module patch_cache$miss_count(d,q,clock);
    
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
          
endmodule // patch_cache$miss_count


module patch_cache$mreq(d,q,clock);
    
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
          
endmodule // patch_cache$mreq


module patch_cache$q_lane(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] read_address;
    output reg  [15:0] read_data;
    input wire  [3:0] write_address;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem [0:15];
    integer i;
    initial begin
       for (i = 0; i <= 15; i = i + 1) mem[i] = 16'd0;
       read_data = 16'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // patch_cache$q_lane


module patch_cache$rax(d,q,clock);
    
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
          
endmodule // patch_cache$rax


module patch_cache$ray(d,q,clock);
    
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
          
endmodule // patch_cache$ray


module patch_cache$rbx(d,q,clock);
    
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
          
endmodule // patch_cache$rbx


module patch_cache$rby(d,q,clock);
    
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
          
endmodule // patch_cache$rby


module patch_cache$rd_ptr(d,q,clock);
    
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
          
endmodule // patch_cache$rd_ptr


module patch_cache$rv(d,q,clock);
    
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
          
endmodule // patch_cache$rv


module patch_cache$tag(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [11:0] read_address;
    output reg  [16:0] read_data;
    input wire  [11:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [16:0] mem [0:4095];
    integer i;
    initial begin
       for (i = 0; i <= 4095; i = i + 1) mem[i] = 17'd0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // patch_cache$tag


module patch_cache$w_valid(d,q,clock);
    
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
          
endmodule // patch_cache$w_valid


module patch_cache$wr_ptr(d,q,clock);
    
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
          
endmodule // patch_cache$wr_ptr
