// fwft_fifo: exported from rust-hdl by `shelling export-verilog`; do not edit.


module fwft_fifo(clock,push,data_in,pop,valid,data_out,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  [7:0] data_in;
    input wire  pop;
    output reg  valid;
    output reg  [7:0] data_out;
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
    reg  [7:0] lane$write_data;
    reg  lane$write_enable;
    reg  [3:0] lane$head_address;
    reg  [3:0] lane$next_address;
    reg  lane$pop;
    wire  [7:0] lane$read_data;
    
    // Sub module instances
    fwft_fifo$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    fwft_fifo$lane lane(
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
    
endmodule // fwft_fifo


module fwft_fifo$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    fwft_fifo$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    fwft_fifo$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    fwft_fifo$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    fwft_fifo$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    fwft_fifo$control$head_valid head_valid(
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
    
endmodule // fwft_fifo$control


module fwft_fifo$control$head_valid(d,q,clock);
    
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
          
endmodule // fwft_fifo$control$head_valid


module fwft_fifo$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // fwft_fifo$control$rd_inc_x


module fwft_fifo$control$rd_ptr(d,q,clock);
    
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
          
endmodule // fwft_fifo$control$rd_ptr


module fwft_fifo$control$tail_ptr(d,q,clock);
    
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
          
endmodule // fwft_fifo$control$tail_ptr


module fwft_fifo$control$words(d,q,clock);
    
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
          
endmodule // fwft_fifo$control$words


module fwft_fifo$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [7:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [7:0] read_data;
    
    // Update code (custom)
    reg [7:0] mem [0:15];
    reg [7:0] head_r;
    reg [7:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [7:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 8'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 8'd0;
       head_r = 8'd0;
       next_r = 8'd0;
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
endmodule // fwft_fifo$lane
