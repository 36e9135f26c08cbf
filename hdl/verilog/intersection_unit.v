// intersection_unit: exported from rust-hdl by `shelling export-verilog`; do not edit.


module intersection_unit(clock,dir_we,dir_addr,dir_x,dir_y,patch_valid,patch_ready,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,res_re,res_addr,res_hit,res_id,res_key,busy,tests,marks);
    
    // Module arguments
    input wire  clock;
    input wire  dir_we;
    input wire  [10:0] dir_addr;
    input wire  [17:0] dir_x;
    input wire  [17:0] dir_y;
    input wire  patch_valid;
    output reg  patch_ready;
    input wire  [17:0] patch_ax;
    input wire  [17:0] patch_ay;
    input wire  [17:0] patch_bx;
    input wire  [17:0] patch_by;
    input wire  [17:0] patch_wx;
    input wire  [17:0] patch_wy;
    input wire  [5:0] patch_sh;
    input wire  [15:0] patch_id;
    input wire  [10:0] patch_first;
    input wire  [10:0] patch_count;
    input wire  patch_retire;
    input wire  res_re;
    input wire  [10:0] res_addr;
    output reg  res_hit;
    output reg  [15:0] res_id;
    output reg  [31:0] res_key;
    output reg  busy;
    output reg  [31:0] tests;
    output reg  [31:0] marks;
    
    // Constant declarations
    localparam  zero32 = 32'h0;
    localparam  zero16 = 16'h0;
    
    // Stub signals
    reg  seq$clock;
    reg  seq$patch_valid;
    reg  [17:0] seq$patch_ax;
    reg  [17:0] seq$patch_ay;
    reg  [17:0] seq$patch_bx;
    reg  [17:0] seq$patch_by;
    reg  [17:0] seq$patch_wx;
    reg  [17:0] seq$patch_wy;
    reg  [5:0] seq$patch_sh;
    reg  [15:0] seq$patch_id;
    reg  [10:0] seq$patch_first;
    reg  [10:0] seq$patch_count;
    reg  seq$patch_retire;
    wire  seq$full;
    wire  seq$busy;
    wire  seq$kill;
    wire  [10:0] seq$cur;
    wire  seq$v1;
    wire  [32:0] seq$tag1;
    wire  seq$mark1;
    wire  [17:0] seq$o_ax;
    wire  [17:0] seq$o_ay;
    wire  [17:0] seq$o_bx;
    wire  [17:0] seq$o_by;
    wire  [17:0] seq$o_wx;
    wire  [17:0] seq$o_wy;
    reg  alive0$clock;
    reg  [9:0] alive0$read_address;
    wire  alive0$read_data;
    reg  [9:0] alive0$write_address;
    reg  alive0$write_data;
    reg  alive0$write_enable;
    reg  alive1$clock;
    reg  [9:0] alive1$read_address;
    wire  alive1$read_data;
    reg  [9:0] alive1$write_address;
    reg  alive1$write_data;
    reg  alive1$write_enable;
    reg  dir_mem_x$clock;
    reg  [10:0] dir_mem_x$read_address;
    wire  [17:0] dir_mem_x$read_data;
    reg  [10:0] dir_mem_x$write_address;
    reg  [17:0] dir_mem_x$write_data;
    reg  dir_mem_x$write_enable;
    reg  dir_mem_y$clock;
    reg  [10:0] dir_mem_y$read_address;
    wire  [17:0] dir_mem_y$read_data;
    reg  [10:0] dir_mem_y$write_address;
    reg  [17:0] dir_mem_y$write_data;
    reg  dir_mem_y$write_enable;
    reg  products$clock;
    reg  [17:0] products$dx;
    reg  [17:0] products$dy;
    reg  [17:0] products$ax;
    reg  [17:0] products$ay;
    reg  [17:0] products$bx;
    reg  [17:0] products$by;
    reg  [17:0] products$wx;
    reg  [17:0] products$wy;
    wire  [31:0] products$dx_ay;
    wire  [31:0] products$dy_ax;
    wire  [31:0] products$dx_by;
    wire  [31:0] products$dy_bx;
    wire  [31:0] products$dx_wx;
    wire  [31:0] products$dy_wy;
    reg  pipe$clock;
    reg  pipe$v1;
    reg  [32:0] pipe$tag1;
    reg  pipe$mark1;
    reg  pipe$alive0;
    reg  pipe$alive1;
    reg  [31:0] pipe$dx_ay;
    reg  [31:0] pipe$dy_ax;
    reg  [31:0] pipe$dx_by;
    reg  [31:0] pipe$dy_bx;
    wire  [31:0] pipe$tests;
    wire  pipe$busy;
    wire  [5:0] pipe$sh4;
    wire  [10:0] pipe$ray6;
    wire  pipe$v8;
    wire  [26:0] pipe$tag8;
    wire  pipe$mark8;
    reg  key_scale$clock;
    reg  [31:0] key_scale$q;
    reg  [5:0] key_scale$sh;
    wire  [31:0] key_scale$key;
    reg  mem_key0$clock;
    reg  [9:0] mem_key0$read_address;
    wire  [31:0] mem_key0$read_data;
    reg  [9:0] mem_key0$write_address;
    reg  [31:0] mem_key0$write_data;
    reg  mem_key0$write_enable;
    reg  mem_meta0$clock;
    reg  [9:0] mem_meta0$read_address;
    wire  [16:0] mem_meta0$read_data;
    reg  [9:0] mem_meta0$write_address;
    reg  [16:0] mem_meta0$write_data;
    reg  mem_meta0$write_enable;
    reg  mem_key1$clock;
    reg  [9:0] mem_key1$read_address;
    wire  [31:0] mem_key1$read_data;
    reg  [9:0] mem_key1$write_address;
    reg  [31:0] mem_key1$write_data;
    reg  mem_key1$write_enable;
    reg  mem_meta1$clock;
    reg  [9:0] mem_meta1$read_address;
    wire  [16:0] mem_meta1$read_data;
    reg  [9:0] mem_meta1$write_address;
    reg  [16:0] mem_meta1$write_data;
    reg  mem_meta1$write_enable;
    reg  merge$clock;
    reg  merge$v8;
    reg  [26:0] merge$tag8;
    reg  merge$mark8;
    reg  [31:0] merge$key;
    reg  [31:0] merge$mem_key0;
    reg  [16:0] merge$mem_meta0;
    reg  [31:0] merge$mem_key1;
    reg  [16:0] merge$mem_meta1;
    reg  merge$res_re;
    reg  [10:0] merge$res_addr;
    wire  [9:0] merge$write_address0;
    wire  [31:0] merge$write_key0;
    wire  [16:0] merge$write_meta0;
    wire  merge$write_enable0;
    wire  [9:0] merge$write_address1;
    wire  [31:0] merge$write_key1;
    wire  [16:0] merge$write_meta1;
    wire  merge$write_enable1;
    wire  merge$z2;
    wire  merge$res_half;
    wire  merge$busy;
    wire  merge$fw_valid;
    wire  [31:0] merge$marks;
    
    // Local signals
    reg  [9:0] dir_word;
    reg  [9:0] res_word;
    reg  [9:0] cur_word;
    reg  [9:0] ray6_word;
    
    // Sub module instances
    intersection_unit$seq seq(
        .clock(seq$clock),
        .patch_valid(seq$patch_valid),
        .patch_ax(seq$patch_ax),
        .patch_ay(seq$patch_ay),
        .patch_bx(seq$patch_bx),
        .patch_by(seq$patch_by),
        .patch_wx(seq$patch_wx),
        .patch_wy(seq$patch_wy),
        .patch_sh(seq$patch_sh),
        .patch_id(seq$patch_id),
        .patch_first(seq$patch_first),
        .patch_count(seq$patch_count),
        .patch_retire(seq$patch_retire),
        .full(seq$full),
        .busy(seq$busy),
        .kill(seq$kill),
        .cur(seq$cur),
        .v1(seq$v1),
        .tag1(seq$tag1),
        .mark1(seq$mark1),
        .o_ax(seq$o_ax),
        .o_ay(seq$o_ay),
        .o_bx(seq$o_bx),
        .o_by(seq$o_by),
        .o_wx(seq$o_wx),
        .o_wy(seq$o_wy)
    );
    intersection_unit$alive0 alive0(
        .clock(alive0$clock),
        .read_address(alive0$read_address),
        .read_data(alive0$read_data),
        .write_address(alive0$write_address),
        .write_data(alive0$write_data),
        .write_enable(alive0$write_enable)
    );
    intersection_unit$alive1 alive1(
        .clock(alive1$clock),
        .read_address(alive1$read_address),
        .read_data(alive1$read_data),
        .write_address(alive1$write_address),
        .write_data(alive1$write_data),
        .write_enable(alive1$write_enable)
    );
    intersection_unit$dir_mem_x dir_mem_x(
        .clock(dir_mem_x$clock),
        .read_address(dir_mem_x$read_address),
        .read_data(dir_mem_x$read_data),
        .write_address(dir_mem_x$write_address),
        .write_data(dir_mem_x$write_data),
        .write_enable(dir_mem_x$write_enable)
    );
    intersection_unit$dir_mem_y dir_mem_y(
        .clock(dir_mem_y$clock),
        .read_address(dir_mem_y$read_address),
        .read_data(dir_mem_y$read_data),
        .write_address(dir_mem_y$write_address),
        .write_data(dir_mem_y$write_data),
        .write_enable(dir_mem_y$write_enable)
    );
    intersection_unit$products products(
        .clock(products$clock),
        .dx(products$dx),
        .dy(products$dy),
        .ax(products$ax),
        .ay(products$ay),
        .bx(products$bx),
        .by(products$by),
        .wx(products$wx),
        .wy(products$wy),
        .dx_ay(products$dx_ay),
        .dy_ax(products$dy_ax),
        .dx_by(products$dx_by),
        .dy_bx(products$dy_bx),
        .dx_wx(products$dx_wx),
        .dy_wy(products$dy_wy)
    );
    intersection_unit$pipe pipe(
        .clock(pipe$clock),
        .v1(pipe$v1),
        .tag1(pipe$tag1),
        .mark1(pipe$mark1),
        .alive0(pipe$alive0),
        .alive1(pipe$alive1),
        .dx_ay(pipe$dx_ay),
        .dy_ax(pipe$dy_ax),
        .dx_by(pipe$dx_by),
        .dy_bx(pipe$dy_bx),
        .tests(pipe$tests),
        .busy(pipe$busy),
        .sh4(pipe$sh4),
        .ray6(pipe$ray6),
        .v8(pipe$v8),
        .tag8(pipe$tag8),
        .mark8(pipe$mark8)
    );
    intersection_unit$key_scale key_scale(
        .clock(key_scale$clock),
        .q(key_scale$q),
        .sh(key_scale$sh),
        .key(key_scale$key)
    );
    intersection_unit$mem_key0 mem_key0(
        .clock(mem_key0$clock),
        .read_address(mem_key0$read_address),
        .read_data(mem_key0$read_data),
        .write_address(mem_key0$write_address),
        .write_data(mem_key0$write_data),
        .write_enable(mem_key0$write_enable)
    );
    intersection_unit$mem_meta0 mem_meta0(
        .clock(mem_meta0$clock),
        .read_address(mem_meta0$read_address),
        .read_data(mem_meta0$read_data),
        .write_address(mem_meta0$write_address),
        .write_data(mem_meta0$write_data),
        .write_enable(mem_meta0$write_enable)
    );
    intersection_unit$mem_key1 mem_key1(
        .clock(mem_key1$clock),
        .read_address(mem_key1$read_address),
        .read_data(mem_key1$read_data),
        .write_address(mem_key1$write_address),
        .write_data(mem_key1$write_data),
        .write_enable(mem_key1$write_enable)
    );
    intersection_unit$mem_meta1 mem_meta1(
        .clock(mem_meta1$clock),
        .read_address(mem_meta1$read_address),
        .read_data(mem_meta1$read_data),
        .write_address(mem_meta1$write_address),
        .write_data(mem_meta1$write_data),
        .write_enable(mem_meta1$write_enable)
    );
    intersection_unit$merge merge(
        .clock(merge$clock),
        .v8(merge$v8),
        .tag8(merge$tag8),
        .mark8(merge$mark8),
        .key(merge$key),
        .mem_key0(merge$mem_key0),
        .mem_meta0(merge$mem_meta0),
        .mem_key1(merge$mem_key1),
        .mem_meta1(merge$mem_meta1),
        .res_re(merge$res_re),
        .res_addr(merge$res_addr),
        .write_address0(merge$write_address0),
        .write_key0(merge$write_key0),
        .write_meta0(merge$write_meta0),
        .write_enable0(merge$write_enable0),
        .write_address1(merge$write_address1),
        .write_key1(merge$write_key1),
        .write_meta1(merge$write_meta1),
        .write_enable1(merge$write_enable1),
        .z2(merge$z2),
        .res_half(merge$res_half),
        .busy(merge$busy),
        .fw_valid(merge$fw_valid),
        .marks(merge$marks)
    );
    
    // Update code
    always @(*) begin
        seq$clock = clock;
        alive0$clock = clock;
        alive1$clock = clock;
        dir_mem_x$clock = clock;
        dir_mem_y$clock = clock;
        products$clock = clock;
        pipe$clock = clock;
        key_scale$clock = clock;
        mem_key0$clock = clock;
        mem_meta0$clock = clock;
        mem_key1$clock = clock;
        mem_meta1$clock = clock;
        dir_word = ((dir_addr) & 10'h3ff);
        res_word = ((res_addr) & 10'h3ff);
        cur_word = ((seq$cur) & 10'h3ff);
        ray6_word = ((pipe$ray6) & 10'h3ff);
        merge$clock = clock;
        seq$patch_valid = patch_valid;
        seq$patch_ax = patch_ax;
        seq$patch_ay = patch_ay;
        seq$patch_bx = patch_bx;
        seq$patch_by = patch_by;
        seq$patch_wx = patch_wx;
        seq$patch_wy = patch_wy;
        seq$patch_sh = patch_sh;
        seq$patch_id = patch_id;
        seq$patch_first = patch_first;
        seq$patch_count = patch_count;
        seq$patch_retire = patch_retire;
        patch_ready = ~seq$full;
        dir_mem_x$read_address = seq$cur;
        dir_mem_y$read_address = seq$cur;
        dir_mem_x$write_address = dir_addr;
        dir_mem_y$write_address = dir_addr;
        dir_mem_x$write_data = dir_x;
        dir_mem_y$write_data = dir_y;
        dir_mem_x$write_enable = dir_we;
        dir_mem_y$write_enable = dir_we;
        alive0$read_address = cur_word;
        alive0$write_address = cur_word;
        alive0$write_data = 1'b0;
        alive0$write_enable = seq$kill & ~seq$cur[32'ha];
        if (dir_we & ~dir_addr[32'ha]) begin
            alive0$write_address = dir_word;
            alive0$write_data = 1'b1;
            alive0$write_enable = 1'b1;
        end
        alive1$read_address = cur_word;
        alive1$write_address = cur_word;
        alive1$write_data = 1'b0;
        alive1$write_enable = seq$kill & seq$cur[32'ha];
        if (dir_we & dir_addr[32'ha]) begin
            alive1$write_address = dir_word;
            alive1$write_data = 1'b1;
            alive1$write_enable = 1'b1;
        end
        products$ax = seq$o_ax;
        products$ay = seq$o_ay;
        products$bx = seq$o_bx;
        products$by = seq$o_by;
        products$wx = seq$o_wx;
        products$wy = seq$o_wy;
        pipe$v1 = seq$v1;
        pipe$tag1 = seq$tag1;
        pipe$mark1 = seq$mark1;
        products$dx = dir_mem_x$read_data;
        products$dy = dir_mem_y$read_data;
        pipe$alive0 = |alive0$read_data;
        pipe$alive1 = |alive1$read_data;
        tests = pipe$tests;
        pipe$dx_ay = products$dx_ay;
        pipe$dy_ax = products$dy_ax;
        pipe$dx_by = products$dx_by;
        pipe$dy_bx = products$dy_bx;
        key_scale$q = products$dx_wx + products$dy_wy;
        key_scale$sh = pipe$sh4;
        mem_key0$read_address = ray6_word;
        mem_meta0$read_address = ray6_word;
        mem_key1$read_address = ray6_word;
        mem_meta1$read_address = ray6_word;
        if (res_re & ~res_addr[32'ha]) begin
            mem_key0$read_address = res_word;
            mem_meta0$read_address = res_word;
        end
        if (res_re & res_addr[32'ha]) begin
            mem_key1$read_address = res_word;
            mem_meta1$read_address = res_word;
        end
        merge$v8 = pipe$v8;
        merge$tag8 = pipe$tag8;
        merge$mark8 = pipe$mark8;
        merge$key = key_scale$key;
        merge$mem_key0 = mem_key0$read_data;
        merge$mem_meta0 = mem_meta0$read_data;
        merge$mem_key1 = mem_key1$read_data;
        merge$mem_meta1 = mem_meta1$read_data;
        merge$res_re = res_re;
        merge$res_addr = res_addr;
        mem_key0$write_address = merge$write_address0;
        mem_meta0$write_address = merge$write_address0;
        mem_key0$write_data = merge$write_key0;
        mem_meta0$write_data = merge$write_meta0;
        mem_key0$write_enable = merge$write_enable0;
        mem_meta0$write_enable = merge$write_enable0;
        mem_key1$write_address = merge$write_address1;
        mem_meta1$write_address = merge$write_address1;
        mem_key1$write_data = merge$write_key1;
        mem_meta1$write_data = merge$write_meta1;
        mem_key1$write_enable = merge$write_enable1;
        mem_meta1$write_enable = merge$write_enable1;
        marks = merge$marks;
        res_hit = mem_meta0$read_data[32'h10] & ~merge$z2;
        res_id = ((mem_meta0$read_data) & 16'hffff);
        res_key = mem_key0$read_data;
        if (merge$res_half) begin
            res_hit = mem_meta1$read_data[32'h10] & ~merge$z2;
            res_id = ((mem_meta1$read_data) & 16'hffff);
            res_key = mem_key1$read_data;
        end
        if (merge$z2) begin
            res_id = zero16;
            res_key = zero32;
        end
        busy = seq$busy | pipe$busy | merge$busy;
    end
    
endmodule // intersection_unit


module intersection_unit$alive0(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  read_data;
    input wire  [9:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = {17'd0, write_data};
    wire [9:0] bo_ra = read_address;
    wire [9:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(bo_wd[9]), .DOB9(bo_rd[9]),
       .DIA10(bo_wd[10]), .DOB10(bo_rd[10]),
       .DIA11(bo_wd[11]), .DOB11(bo_rd[11]),
       .DIA12(bo_wd[12]), .DOB12(bo_rd[12]),
       .DIA13(bo_wd[13]), .DOB13(bo_rd[13]),
       .DIA14(bo_wd[14]), .DOB14(bo_rd[14]),
       .DIA15(bo_wd[15]), .DOB15(bo_rd[15]),
       .DIA16(bo_wd[16]), .DOB16(bo_rd[16]),
       .DIA17(bo_wd[17]), .DOB17(bo_rd[17]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[0:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 1024;
    `endif
    reg [0:0] mem [0:WORDS-1];
    reg [0:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 1'd0;
       r1 = 1'd0;
       collided = 1'b0;
       read_data = 1'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$alive0


module intersection_unit$alive1(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  read_data;
    input wire  [9:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = {17'd0, write_data};
    wire [9:0] bo_ra = read_address;
    wire [9:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(bo_wd[9]), .DOB9(bo_rd[9]),
       .DIA10(bo_wd[10]), .DOB10(bo_rd[10]),
       .DIA11(bo_wd[11]), .DOB11(bo_rd[11]),
       .DIA12(bo_wd[12]), .DOB12(bo_rd[12]),
       .DIA13(bo_wd[13]), .DOB13(bo_rd[13]),
       .DIA14(bo_wd[14]), .DOB14(bo_rd[14]),
       .DIA15(bo_wd[15]), .DOB15(bo_rd[15]),
       .DIA16(bo_wd[16]), .DOB16(bo_rd[16]),
       .DIA17(bo_wd[17]), .DOB17(bo_rd[17]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[0:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 1024;
    `endif
    reg [0:0] mem [0:WORDS-1];
    reg [0:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 1'd0;
       r1 = 1'd0;
       collided = 1'b0;
       read_data = 1'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$alive1


module intersection_unit$dir_mem_x(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] read_address;
    output reg  [17:0] read_data;
    input wire  [10:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = write_data;
    wire [10:0] bo_ra = read_address;
    wire [10:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(9), .DATA_WIDTH_B(9), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b0),
       .ADA1(1'b0),
       .ADA2(1'b0),
       .ADA3(bo_wa[0]),
       .ADA4(bo_wa[1]),
       .ADA5(bo_wa[2]),
       .ADA6(bo_wa[3]),
       .ADA7(bo_wa[4]),
       .ADA8(bo_wa[5]),
       .ADA9(bo_wa[6]),
       .ADA10(bo_wa[7]),
       .ADA11(bo_wa[8]),
       .ADA12(bo_wa[9]),
       .ADA13(bo_wa[10]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(bo_ra[0]),
       .ADB4(bo_ra[1]),
       .ADB5(bo_ra[2]),
       .ADB6(bo_ra[3]),
       .ADB7(bo_ra[4]),
       .ADB8(bo_ra[5]),
       .ADB9(bo_ra[6]),
       .ADB10(bo_ra[7]),
       .ADB11(bo_ra[8]),
       .ADB12(bo_ra[9]),
       .ADB13(bo_ra[10]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(1'b0),
       .DIA10(1'b0),
       .DIA11(1'b0),
       .DIA12(1'b0),
       .DIA13(1'b0),
       .DIA14(1'b0),
       .DIA15(1'b0),
       .DIA16(1'b0),
       .DIA17(1'b0),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    DP16KD #(.DATA_WIDTH_A(9), .DATA_WIDTH_B(9), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile1 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b0),
       .ADA1(1'b0),
       .ADA2(1'b0),
       .ADA3(bo_wa[0]),
       .ADA4(bo_wa[1]),
       .ADA5(bo_wa[2]),
       .ADA6(bo_wa[3]),
       .ADA7(bo_wa[4]),
       .ADA8(bo_wa[5]),
       .ADA9(bo_wa[6]),
       .ADA10(bo_wa[7]),
       .ADA11(bo_wa[8]),
       .ADA12(bo_wa[9]),
       .ADA13(bo_wa[10]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(bo_ra[0]),
       .ADB4(bo_ra[1]),
       .ADB5(bo_ra[2]),
       .ADB6(bo_ra[3]),
       .ADB7(bo_ra[4]),
       .ADB8(bo_ra[5]),
       .ADB9(bo_ra[6]),
       .ADB10(bo_ra[7]),
       .ADB11(bo_ra[8]),
       .ADB12(bo_ra[9]),
       .ADB13(bo_ra[10]),
       .DIA0(bo_wd[9]), .DOB0(bo_rd[9]),
       .DIA1(bo_wd[10]), .DOB1(bo_rd[10]),
       .DIA2(bo_wd[11]), .DOB2(bo_rd[11]),
       .DIA3(bo_wd[12]), .DOB3(bo_rd[12]),
       .DIA4(bo_wd[13]), .DOB4(bo_rd[13]),
       .DIA5(bo_wd[14]), .DOB5(bo_rd[14]),
       .DIA6(bo_wd[15]), .DOB6(bo_rd[15]),
       .DIA7(bo_wd[16]), .DOB7(bo_rd[16]),
       .DIA8(bo_wd[17]), .DOB8(bo_rd[17]),
       .DIA9(1'b0),
       .DIA10(1'b0),
       .DIA11(1'b0),
       .DIA12(1'b0),
       .DIA13(1'b0),
       .DIA14(1'b0),
       .DIA15(1'b0),
       .DIA16(1'b0),
       .DIA17(1'b0),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[17:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 2048;
    `endif
    reg [17:0] mem [0:WORDS-1];
    reg [17:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 18'd0;
       r1 = 18'd0;
       collided = 1'b0;
       read_data = 18'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$dir_mem_x


module intersection_unit$dir_mem_y(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] read_address;
    output reg  [17:0] read_data;
    input wire  [10:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = write_data;
    wire [10:0] bo_ra = read_address;
    wire [10:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(9), .DATA_WIDTH_B(9), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b0),
       .ADA1(1'b0),
       .ADA2(1'b0),
       .ADA3(bo_wa[0]),
       .ADA4(bo_wa[1]),
       .ADA5(bo_wa[2]),
       .ADA6(bo_wa[3]),
       .ADA7(bo_wa[4]),
       .ADA8(bo_wa[5]),
       .ADA9(bo_wa[6]),
       .ADA10(bo_wa[7]),
       .ADA11(bo_wa[8]),
       .ADA12(bo_wa[9]),
       .ADA13(bo_wa[10]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(bo_ra[0]),
       .ADB4(bo_ra[1]),
       .ADB5(bo_ra[2]),
       .ADB6(bo_ra[3]),
       .ADB7(bo_ra[4]),
       .ADB8(bo_ra[5]),
       .ADB9(bo_ra[6]),
       .ADB10(bo_ra[7]),
       .ADB11(bo_ra[8]),
       .ADB12(bo_ra[9]),
       .ADB13(bo_ra[10]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(1'b0),
       .DIA10(1'b0),
       .DIA11(1'b0),
       .DIA12(1'b0),
       .DIA13(1'b0),
       .DIA14(1'b0),
       .DIA15(1'b0),
       .DIA16(1'b0),
       .DIA17(1'b0),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    DP16KD #(.DATA_WIDTH_A(9), .DATA_WIDTH_B(9), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile1 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b0),
       .ADA1(1'b0),
       .ADA2(1'b0),
       .ADA3(bo_wa[0]),
       .ADA4(bo_wa[1]),
       .ADA5(bo_wa[2]),
       .ADA6(bo_wa[3]),
       .ADA7(bo_wa[4]),
       .ADA8(bo_wa[5]),
       .ADA9(bo_wa[6]),
       .ADA10(bo_wa[7]),
       .ADA11(bo_wa[8]),
       .ADA12(bo_wa[9]),
       .ADA13(bo_wa[10]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(bo_ra[0]),
       .ADB4(bo_ra[1]),
       .ADB5(bo_ra[2]),
       .ADB6(bo_ra[3]),
       .ADB7(bo_ra[4]),
       .ADB8(bo_ra[5]),
       .ADB9(bo_ra[6]),
       .ADB10(bo_ra[7]),
       .ADB11(bo_ra[8]),
       .ADB12(bo_ra[9]),
       .ADB13(bo_ra[10]),
       .DIA0(bo_wd[9]), .DOB0(bo_rd[9]),
       .DIA1(bo_wd[10]), .DOB1(bo_rd[10]),
       .DIA2(bo_wd[11]), .DOB2(bo_rd[11]),
       .DIA3(bo_wd[12]), .DOB3(bo_rd[12]),
       .DIA4(bo_wd[13]), .DOB4(bo_rd[13]),
       .DIA5(bo_wd[14]), .DOB5(bo_rd[14]),
       .DIA6(bo_wd[15]), .DOB6(bo_rd[15]),
       .DIA7(bo_wd[16]), .DOB7(bo_rd[16]),
       .DIA8(bo_wd[17]), .DOB8(bo_rd[17]),
       .DIA9(1'b0),
       .DIA10(1'b0),
       .DIA11(1'b0),
       .DIA12(1'b0),
       .DIA13(1'b0),
       .DIA14(1'b0),
       .DIA15(1'b0),
       .DIA16(1'b0),
       .DIA17(1'b0),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[17:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 2048;
    `endif
    reg [17:0] mem [0:WORDS-1];
    reg [17:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 18'd0;
       r1 = 18'd0;
       collided = 1'b0;
       read_data = 18'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$dir_mem_y


module intersection_unit$key_scale(clock,q,sh,key);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] q;
    input wire  [5:0] sh;
    output reg  [31:0] key;
    
    // Update code (custom)
    reg [31:0] q_r;
    reg [5:0] sh_r;
    reg [31:0] c1;
    reg [2:0] f1;
    reg [31:0] r2;
    reg [31:0] left;
    reg [31:0] coarse;
    initial begin
       q_r = 32'd0;
       sh_r = 6'd0;
       c1 = 32'd0;
       f1 = 3'd0;
       r2 = 32'd0;
       key = 32'd0;
    end
    always @(*) begin
       if (sh_r == 6'h3f) left = {q_r[30:0], 1'b0};
       else if (sh_r == 6'h3e) left = (q_r[31:30] == 2'd0) ? {q_r[29:0], 2'b0} : 32'hffffffff;
       else left = (q_r[31:29] == 3'd0) ? {q_r[28:0], 3'b0} : 32'hffffffff;
       case (sh_r[4:3])
          2'd0: coarse = q_r;
          2'd1: coarse = {8'd0, q_r[31:8]};
          2'd2: coarse = {16'd0, q_r[31:16]};
          default: coarse = {24'd0, q_r[31:24]};
       endcase
    end
    always @(posedge clock) begin
       q_r <= q;
       sh_r <= sh;
       if (q_r[31]) begin
          c1 <= 32'd1;
          f1 <= 3'd0;
       end else if (sh_r[5]) begin
          c1 <= left;
          f1 <= 3'd0;
       end else begin
          c1 <= coarse;
          f1 <= sh_r[2:0];
       end
       r2 <= c1 >> f1;
       key <= (r2 == 32'd0) ? 32'd1 : r2;
    end
endmodule // intersection_unit$key_scale


module intersection_unit$mem_key0(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [31:0] read_data;
    input wire  [9:0] write_address;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] bo_rd;
    wire [35:0] bo_wd = {4'd0, write_data};
    wire [9:0] bo_ra = read_address;
    wire [9:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(bo_wd[9]), .DOB9(bo_rd[9]),
       .DIA10(bo_wd[10]), .DOB10(bo_rd[10]),
       .DIA11(bo_wd[11]), .DOB11(bo_rd[11]),
       .DIA12(bo_wd[12]), .DOB12(bo_rd[12]),
       .DIA13(bo_wd[13]), .DOB13(bo_rd[13]),
       .DIA14(bo_wd[14]), .DOB14(bo_rd[14]),
       .DIA15(bo_wd[15]), .DOB15(bo_rd[15]),
       .DIA16(bo_wd[16]), .DOB16(bo_rd[16]),
       .DIA17(bo_wd[17]), .DOB17(bo_rd[17]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile1 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[18]), .DOB0(bo_rd[18]),
       .DIA1(bo_wd[19]), .DOB1(bo_rd[19]),
       .DIA2(bo_wd[20]), .DOB2(bo_rd[20]),
       .DIA3(bo_wd[21]), .DOB3(bo_rd[21]),
       .DIA4(bo_wd[22]), .DOB4(bo_rd[22]),
       .DIA5(bo_wd[23]), .DOB5(bo_rd[23]),
       .DIA6(bo_wd[24]), .DOB6(bo_rd[24]),
       .DIA7(bo_wd[25]), .DOB7(bo_rd[25]),
       .DIA8(bo_wd[26]), .DOB8(bo_rd[26]),
       .DIA9(bo_wd[27]), .DOB9(bo_rd[27]),
       .DIA10(bo_wd[28]), .DOB10(bo_rd[28]),
       .DIA11(bo_wd[29]), .DOB11(bo_rd[29]),
       .DIA12(bo_wd[30]), .DOB12(bo_rd[30]),
       .DIA13(bo_wd[31]), .DOB13(bo_rd[31]),
       .DIA14(bo_wd[32]), .DOB14(bo_rd[32]),
       .DIA15(bo_wd[33]), .DOB15(bo_rd[33]),
       .DIA16(bo_wd[34]), .DOB16(bo_rd[34]),
       .DIA17(bo_wd[35]), .DOB17(bo_rd[35]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[31:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 1024;
    `endif
    reg [31:0] mem [0:WORDS-1];
    reg [31:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 32'd0;
       r1 = 32'd0;
       collided = 1'b0;
       read_data = 32'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$mem_key0


module intersection_unit$mem_key1(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [31:0] read_data;
    input wire  [9:0] write_address;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] bo_rd;
    wire [35:0] bo_wd = {4'd0, write_data};
    wire [9:0] bo_ra = read_address;
    wire [9:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(bo_wd[9]), .DOB9(bo_rd[9]),
       .DIA10(bo_wd[10]), .DOB10(bo_rd[10]),
       .DIA11(bo_wd[11]), .DOB11(bo_rd[11]),
       .DIA12(bo_wd[12]), .DOB12(bo_rd[12]),
       .DIA13(bo_wd[13]), .DOB13(bo_rd[13]),
       .DIA14(bo_wd[14]), .DOB14(bo_rd[14]),
       .DIA15(bo_wd[15]), .DOB15(bo_rd[15]),
       .DIA16(bo_wd[16]), .DOB16(bo_rd[16]),
       .DIA17(bo_wd[17]), .DOB17(bo_rd[17]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile1 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[18]), .DOB0(bo_rd[18]),
       .DIA1(bo_wd[19]), .DOB1(bo_rd[19]),
       .DIA2(bo_wd[20]), .DOB2(bo_rd[20]),
       .DIA3(bo_wd[21]), .DOB3(bo_rd[21]),
       .DIA4(bo_wd[22]), .DOB4(bo_rd[22]),
       .DIA5(bo_wd[23]), .DOB5(bo_rd[23]),
       .DIA6(bo_wd[24]), .DOB6(bo_rd[24]),
       .DIA7(bo_wd[25]), .DOB7(bo_rd[25]),
       .DIA8(bo_wd[26]), .DOB8(bo_rd[26]),
       .DIA9(bo_wd[27]), .DOB9(bo_rd[27]),
       .DIA10(bo_wd[28]), .DOB10(bo_rd[28]),
       .DIA11(bo_wd[29]), .DOB11(bo_rd[29]),
       .DIA12(bo_wd[30]), .DOB12(bo_rd[30]),
       .DIA13(bo_wd[31]), .DOB13(bo_rd[31]),
       .DIA14(bo_wd[32]), .DOB14(bo_rd[32]),
       .DIA15(bo_wd[33]), .DOB15(bo_rd[33]),
       .DIA16(bo_wd[34]), .DOB16(bo_rd[34]),
       .DIA17(bo_wd[35]), .DOB17(bo_rd[35]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[31:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 1024;
    `endif
    reg [31:0] mem [0:WORDS-1];
    reg [31:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 32'd0;
       r1 = 32'd0;
       collided = 1'b0;
       read_data = 32'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$mem_key1


module intersection_unit$mem_meta0(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [16:0] read_data;
    input wire  [9:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = {1'd0, write_data};
    wire [9:0] bo_ra = read_address;
    wire [9:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(bo_wd[9]), .DOB9(bo_rd[9]),
       .DIA10(bo_wd[10]), .DOB10(bo_rd[10]),
       .DIA11(bo_wd[11]), .DOB11(bo_rd[11]),
       .DIA12(bo_wd[12]), .DOB12(bo_rd[12]),
       .DIA13(bo_wd[13]), .DOB13(bo_rd[13]),
       .DIA14(bo_wd[14]), .DOB14(bo_rd[14]),
       .DIA15(bo_wd[15]), .DOB15(bo_rd[15]),
       .DIA16(bo_wd[16]), .DOB16(bo_rd[16]),
       .DIA17(bo_wd[17]), .DOB17(bo_rd[17]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[16:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 1024;
    `endif
    reg [16:0] mem [0:WORDS-1];
    reg [16:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 17'd0;
       r1 = 17'd0;
       collided = 1'b0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$mem_meta0


module intersection_unit$mem_meta1(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [16:0] read_data;
    input wire  [9:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = {1'd0, write_data};
    wire [9:0] bo_ra = read_address;
    wire [9:0] bo_wa = write_address;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(18), .REGMODE_A("NOREG"), .REGMODE_B("OUTREG"), .RESETMODE("SYNC"), .ASYNC_RESET_RELEASE("SYNC"), .CSDECODE_A("0b000"), .CSDECODE_B("0b000"), .WRITEMODE_A("NORMAL"), .WRITEMODE_B("NORMAL"), .GSR("DISABLED")) bo_tile0 (
       .CLKA(clock), .WEA(write_enable), .CEA(1'b1), .OCEA(1'b1), .RSTA(1'b0),
       .CSA0(1'b0), .CSA1(1'b0), .CSA2(1'b0),
       .CLKB(clock), .WEB(1'b0), .CEB(1'b1), .OCEB(1'b1), .RSTB(1'b0),
       .CSB0(1'b0), .CSB1(1'b0), .CSB2(1'b0),
       .ADA0(1'b1),
       .ADA1(1'b1),
       .ADA2(1'b0),
       .ADA3(1'b0),
       .ADA4(bo_wa[0]),
       .ADA5(bo_wa[1]),
       .ADA6(bo_wa[2]),
       .ADA7(bo_wa[3]),
       .ADA8(bo_wa[4]),
       .ADA9(bo_wa[5]),
       .ADA10(bo_wa[6]),
       .ADA11(bo_wa[7]),
       .ADA12(bo_wa[8]),
       .ADA13(bo_wa[9]),
       .ADB0(1'b0),
       .ADB1(1'b0),
       .ADB2(1'b0),
       .ADB3(1'b0),
       .ADB4(bo_ra[0]),
       .ADB5(bo_ra[1]),
       .ADB6(bo_ra[2]),
       .ADB7(bo_ra[3]),
       .ADB8(bo_ra[4]),
       .ADB9(bo_ra[5]),
       .ADB10(bo_ra[6]),
       .ADB11(bo_ra[7]),
       .ADB12(bo_ra[8]),
       .ADB13(bo_ra[9]),
       .DIA0(bo_wd[0]), .DOB0(bo_rd[0]),
       .DIA1(bo_wd[1]), .DOB1(bo_rd[1]),
       .DIA2(bo_wd[2]), .DOB2(bo_rd[2]),
       .DIA3(bo_wd[3]), .DOB3(bo_rd[3]),
       .DIA4(bo_wd[4]), .DOB4(bo_rd[4]),
       .DIA5(bo_wd[5]), .DOB5(bo_rd[5]),
       .DIA6(bo_wd[6]), .DOB6(bo_rd[6]),
       .DIA7(bo_wd[7]), .DOB7(bo_rd[7]),
       .DIA8(bo_wd[8]), .DOB8(bo_rd[8]),
       .DIA9(bo_wd[9]), .DOB9(bo_rd[9]),
       .DIA10(bo_wd[10]), .DOB10(bo_rd[10]),
       .DIA11(bo_wd[11]), .DOB11(bo_rd[11]),
       .DIA12(bo_wd[12]), .DOB12(bo_rd[12]),
       .DIA13(bo_wd[13]), .DOB13(bo_rd[13]),
       .DIA14(bo_wd[14]), .DOB14(bo_rd[14]),
       .DIA15(bo_wd[15]), .DOB15(bo_rd[15]),
       .DIA16(bo_wd[16]), .DOB16(bo_rd[16]),
       .DIA17(bo_wd[17]), .DOB17(bo_rd[17]),
       .DIB0(1'b0), .DIB1(1'b0), .DIB2(1'b0), .DIB3(1'b0), .DIB4(1'b0), .DIB5(1'b0), .DIB6(1'b0), .DIB7(1'b0), .DIB8(1'b0), .DIB9(1'b0), .DIB10(1'b0), .DIB11(1'b0), .DIB12(1'b0), .DIB13(1'b0), .DIB14(1'b0), .DIB15(1'b0), .DIB16(1'b0), .DIB17(1'b0)
    );
    always @(*) read_data = bo_rd[16:0];
    `else
    // `SHELLING_FORMAL_BRAM_WORDS (formal harnesses only): the memory keeps that many words, the
    // first ones, and a FORMAL build asserts that no address beyond them is used.
    `ifdef SHELLING_FORMAL_BRAM_WORDS
    localparam WORDS = `SHELLING_FORMAL_BRAM_WORDS;
    `else
    localparam WORDS = 1024;
    `endif
    reg [16:0] mem [0:WORDS-1];
    reg [16:0] r1;
    reg collided;
    integer i;
    `ifdef FORMAL
    always @(*) begin
       a_bram_read_address: assert(read_address < WORDS);
       if (write_enable) a_bram_write_address: assert(write_address < WORDS);
    end
    `endif
    initial begin
       for (i = 0; i < WORDS; i = i + 1) mem[i] = 17'd0;
       r1 = 17'd0;
       collided = 1'b0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       // A plain registered read (read before write), so that synthesis infers block RAM; a read
       // and a write of the same address in one clock are poisoned after the read register (see
       // the Rust docs).
       r1 <= mem[read_address];
       collided <= write_enable && write_address == read_address;
       read_data <= collided ? ~r1 : r1;
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
    `endif
endmodule // intersection_unit$mem_meta1


module intersection_unit$merge(clock,v8,tag8,mark8,key,mem_key0,mem_meta0,mem_key1,mem_meta1,res_re,res_addr,write_address0,write_key0,write_meta0,write_enable0,write_address1,write_key1,write_meta1,write_enable1,z2,res_half,busy,fw_valid,marks);
    
    // Module arguments
    input wire  clock;
    input wire  v8;
    input wire  [26:0] tag8;
    input wire  mark8;
    input wire  [31:0] key;
    input wire  [31:0] mem_key0;
    input wire  [16:0] mem_meta0;
    input wire  [31:0] mem_key1;
    input wire  [16:0] mem_meta1;
    input wire  res_re;
    input wire  [10:0] res_addr;
    output reg  [9:0] write_address0;
    output reg  [31:0] write_key0;
    output reg  [16:0] write_meta0;
    output reg  write_enable0;
    output reg  [9:0] write_address1;
    output reg  [31:0] write_key1;
    output reg  [16:0] write_meta1;
    output reg  write_enable1;
    output reg  z2;
    output reg  res_half;
    output reg  busy;
    output reg  fw_valid;
    output reg  [31:0] marks;
    
    // Update code (custom)
    wire [10:0] ray8 = tag8[26:16];
    wire [15:0] id8 = tag8[15:0];
    reg cm0_hit, cm0_gt_hi, cm0_eq_hi, cm0_gt_lo, cm0_eq_lo, cm0_lt;
    reg cm1_hit, cm1_gt_hi, cm1_eq_hi, cm1_gt_lo, cm1_eq_lo, cm1_lt;
    reg c1_gt, c1_eq, c1_lt, c2_gt, c2_eq, c2_lt, c3_gt, c3_eq, c3_lt;
    reg m1, m2, m3;
    reg v9;
    reg [10:0] ray9;
    reg [15:0] id9;
    reg [31:0] key9;
    reg [10:0] fw_ray;
    reg [31:0] fw_key;
    reg [15:0] fw_id;
    reg fw2_valid;
    reg [10:0] fw2_ray;
    reg [31:0] fw2_key;
    reg [15:0] fw2_id;
    reg fw3_valid;
    reg rd_valid;
    reg [10:0] rd_addr;
    reg z1;
    reg mark9;
    reg fwd, fwin, better0, better1;
    initial begin
       cm0_hit = 1'b0;
       cm0_gt_hi = 1'b0;
       cm0_eq_hi = 1'b0;
       cm0_gt_lo = 1'b0;
       cm0_eq_lo = 1'b0;
       cm0_lt = 1'b0;
       cm1_hit = 1'b0;
       cm1_gt_hi = 1'b0;
       cm1_eq_hi = 1'b0;
       cm1_gt_lo = 1'b0;
       cm1_eq_lo = 1'b0;
       cm1_lt = 1'b0;
       m1 = 1'b0;
       m2 = 1'b0;
       m3 = 1'b0;
       v9 = 1'b0;
       fw_valid = 1'b0;
       fw2_valid = 1'b0;
       fw3_valid = 1'b0;
       mark9 = 1'b0;
       res_half = 1'b0;
       c1_gt = 1'b0;
       c1_eq = 1'b0;
       c1_lt = 1'b0;
       c2_gt = 1'b0;
       c2_eq = 1'b0;
       c2_lt = 1'b0;
       c3_gt = 1'b0;
       c3_eq = 1'b0;
       c3_lt = 1'b0;
       ray9 = 11'd0;
       fw_ray = 11'd0;
       fw2_ray = 11'd0;
       rd_addr = 11'd0;
       id9 = 16'd0;
       fw_id = 16'd0;
       fw2_id = 16'd0;
       key9 = 32'd0;
       fw_key = 32'd0;
       fw2_key = 32'd0;
       marks = 32'd0;
       rd_valid = 1'b0;
       z1 = 1'b0;
       z2 = 1'b0;
    end
    always @(*) begin
       fwd = 1'b1;
       if (m1 && fw_valid) fwin = c1_gt || (c1_eq && c1_lt);
       else if (m2 && fw2_valid) fwin = c2_gt || (c2_eq && c2_lt);
       else if (m3 && fw3_valid) fwin = c3_gt || (c3_eq && c3_lt);
       else begin
          fwd = 1'b0;
          fwin = 1'b0;
       end
       better0 = v9 && (fwd ? fwin : (!cm0_hit || cm0_gt_hi || (cm0_eq_hi && (cm0_gt_lo || (cm0_eq_lo && cm0_lt)))));
       better1 = v9 && (fwd ? fwin : (!cm1_hit || cm1_gt_hi || (cm1_eq_hi && (cm1_gt_lo || (cm1_eq_lo && cm1_lt)))));
       if (rd_valid && !rd_addr[10]) begin
          write_address0 = rd_addr[9:0];
          write_key0 = 32'd0;
          write_meta0 = 17'd0;
          write_enable0 = 1'b1;
       end else begin
          write_address0 = ray9[9:0];
          write_key0 = key9;
          write_meta0 = {1'b1, id9};
          write_enable0 = better0 && !ray9[10];
       end
       if (rd_valid && rd_addr[10]) begin
          write_address1 = rd_addr[9:0];
          write_key1 = 32'd0;
          write_meta1 = 17'd0;
          write_enable1 = 1'b1;
       end else begin
          write_address1 = ray9[9:0];
          write_key1 = key9;
          write_meta1 = {1'b1, id9};
          write_enable1 = better1 && ray9[10];
       end
       busy = v9 || mark9;
    end
    always @(posedge clock) begin
       cm0_hit <= mem_meta0[16];
       cm0_gt_hi <= key[31:16] > mem_key0[31:16];
       cm0_eq_hi <= key[31:16] == mem_key0[31:16];
       cm0_gt_lo <= key[15:0] > mem_key0[15:0];
       cm0_eq_lo <= key[15:0] == mem_key0[15:0];
       cm0_lt <= id8 < mem_meta0[15:0];
       cm1_hit <= mem_meta1[16];
       cm1_gt_hi <= key[31:16] > mem_key1[31:16];
       cm1_eq_hi <= key[31:16] == mem_key1[31:16];
       cm1_gt_lo <= key[15:0] > mem_key1[15:0];
       cm1_eq_lo <= key[15:0] == mem_key1[15:0];
       cm1_lt <= id8 < mem_meta1[15:0];
       c1_gt <= key > key9;
       c1_eq <= key == key9;
       c1_lt <= id8 < id9;
       c2_gt <= key > fw_key;
       c2_eq <= key == fw_key;
       c2_lt <= id8 < fw_id;
       c3_gt <= key > fw2_key;
       c3_eq <= key == fw2_key;
       c3_lt <= id8 < fw2_id;
    m1 <= ray8 == ray9;
       m2 <= ray8 == fw_ray;
       m3 <= ray8 == fw2_ray;
       v9 <= v8;
       ray9 <= ray8;
       id9 <= id8;
       key9 <= key;
       fw_valid <= ray9[10] ? better1 : better0;
       fw_ray <= ray9;
       fw_key <= key9;
       fw_id <= id9;
       fw2_valid <= fw_valid;
       fw2_ray <= fw_ray;
       fw2_key <= fw_key;
       fw2_id <= fw_id;
       fw3_valid <= fw2_valid;
       rd_valid <= res_re;
       rd_addr <= res_addr;
       z1 <= res_re && rd_valid && res_addr == rd_addr;
       z2 <= z1;
       res_half <= rd_addr[10];
       mark9 <= mark8;
       if (mark9) marks <= marks + 32'd1;
    end
endmodule // intersection_unit$merge


module intersection_unit$pipe(clock,v1,tag1,mark1,alive0,alive1,dx_ay,dy_ax,dx_by,dy_bx,tests,busy,sh4,ray6,v8,tag8,mark8);
    
    // Module arguments
    input wire  clock;
    input wire  v1;
    input wire  [32:0] tag1;
    input wire  mark1;
    input wire  alive0;
    input wire  alive1;
    input wire  [31:0] dx_ay;
    input wire  [31:0] dy_ax;
    input wire  [31:0] dx_by;
    input wire  [31:0] dy_bx;
    output reg  [31:0] tests;
    output reg  busy;
    output reg  [5:0] sh4;
    output reg  [10:0] ray6;
    output reg  v8;
    output reg  [26:0] tag8;
    output reg  mark8;
    
    // Update code (custom)
    reg v2, v3, v4, v5, v6, v7;
    reg mk2, mk3, mk4, mk5, mk6, mk7;
    reg [32:0] tag2;
    reg [32:0] tag3;
    reg [32:0] tag4;
    reg [31:0] sa5;
    reg [31:0] sb5;
    reg [26:0] t5;
    reg [26:0] t6;
    reg [26:0] t7;
    wire live = v2 && (tag2[32] ? alive1 : alive0);
    initial begin
       v2 = 1'b0;
       v3 = 1'b0;
       v4 = 1'b0;
       v5 = 1'b0;
       v6 = 1'b0;
       v7 = 1'b0;
       v8 = 1'b0;
       mk2 = 1'b0;
       mk3 = 1'b0;
       mk4 = 1'b0;
       mk5 = 1'b0;
       mk6 = 1'b0;
       mk7 = 1'b0;
       mark8 = 1'b0;
       tag2 = 33'd0;
       tag3 = 33'd0;
       tag4 = 33'd0;
       sa5 = 32'd0;
       sb5 = 32'd0;
       t5 = 27'd0;
       t6 = 27'd0;
       t7 = 27'd0;
       tag8 = 27'd0;
       tests = 32'd0;
    end
    always @(*) begin
       busy = v2 || v3 || v4 || v5 || v6 || v7 || v8 || mk2 || mk3 || mk4 || mk5 || mk6 || mk7 || mark8;
       sh4 = tag4[21:16];
       ray6 = t6[26:16];
    end
    always @(posedge clock) begin
       v2 <= v1;
       tag2 <= tag1;
       v3 <= live;
       tag3 <= tag2;
       if (live) tests <= tests + 32'd1;
       v4 <= v3;
       tag4 <= tag3;
       v5 <= v4;
       sa5 <= dx_ay - dy_ax;
       sb5 <= dx_by - dy_bx;
       t5 <= {tag4[32:22], tag4[15:0]};
       v6 <= v5 && (sa5 == 32'd0 || sa5[31]) && !sb5[31];
       t6 <= t5;
       v7 <= v6;
       t7 <= t6;
       v8 <= v7;
       tag8 <= t7;
       mk2 <= mark1;
       mk3 <= mk2;
       mk4 <= mk3;
       mk5 <= mk4;
       mk6 <= mk5;
       mk7 <= mk6;
       mark8 <= mk7;
    end
endmodule // intersection_unit$pipe


module intersection_unit$products(clock,dx,dy,ax,ay,bx,by,wx,wy,dx_ay,dy_ax,dx_by,dy_bx,dx_wx,dy_wy);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] dx;
    input wire  [17:0] dy;
    input wire  [17:0] ax;
    input wire  [17:0] ay;
    input wire  [17:0] bx;
    input wire  [17:0] by;
    input wire  [17:0] wx;
    input wire  [17:0] wy;
    output reg  [31:0] dx_ay;
    output reg  [31:0] dy_ax;
    output reg  [31:0] dx_by;
    output reg  [31:0] dy_bx;
    output reg  [31:0] dx_wx;
    output reg  [31:0] dy_wy;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    reg [17:0] ax_1;
    reg [17:0] ay_1;
    reg [17:0] bx_1;
    reg [17:0] by_1;
    reg [17:0] wx_1;
    reg [17:0] wy_1;
    initial begin
       ax_1 = 18'd0;
       ay_1 = 18'd0;
       bx_1 = 18'd0;
       by_1 = 18'd0;
       wx_1 = 18'd0;
       wy_1 = 18'd0;
    end
    always @(posedge clock) begin
       ax_1 <= ax;
       ay_1 <= ay;
       bx_1 <= bx;
       by_1 <= by;
       wx_1 <= wx;
       wy_1 <= wy;
    end
    wire [35:0] dx_ay_p;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dx_ay_dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(dx[0]), .B0(ay_1[0]), .C0(1'b0),
       .A1(dx[1]), .B1(ay_1[1]), .C1(1'b0),
       .A2(dx[2]), .B2(ay_1[2]), .C2(1'b0),
       .A3(dx[3]), .B3(ay_1[3]), .C3(1'b0),
       .A4(dx[4]), .B4(ay_1[4]), .C4(1'b0),
       .A5(dx[5]), .B5(ay_1[5]), .C5(1'b0),
       .A6(dx[6]), .B6(ay_1[6]), .C6(1'b0),
       .A7(dx[7]), .B7(ay_1[7]), .C7(1'b0),
       .A8(dx[8]), .B8(ay_1[8]), .C8(1'b0),
       .A9(dx[9]), .B9(ay_1[9]), .C9(1'b0),
       .A10(dx[10]), .B10(ay_1[10]), .C10(1'b0),
       .A11(dx[11]), .B11(ay_1[11]), .C11(1'b0),
       .A12(dx[12]), .B12(ay_1[12]), .C12(1'b0),
       .A13(dx[13]), .B13(ay_1[13]), .C13(1'b0),
       .A14(dx[14]), .B14(ay_1[14]), .C14(1'b0),
       .A15(dx[15]), .B15(ay_1[15]), .C15(1'b0),
       .A16(dx[16]), .B16(ay_1[16]), .C16(1'b0),
       .A17(dx[17]), .B17(ay_1[17]), .C17(1'b0),
       .P0(dx_ay_p[0]),
       .P1(dx_ay_p[1]),
       .P2(dx_ay_p[2]),
       .P3(dx_ay_p[3]),
       .P4(dx_ay_p[4]),
       .P5(dx_ay_p[5]),
       .P6(dx_ay_p[6]),
       .P7(dx_ay_p[7]),
       .P8(dx_ay_p[8]),
       .P9(dx_ay_p[9]),
       .P10(dx_ay_p[10]),
       .P11(dx_ay_p[11]),
       .P12(dx_ay_p[12]),
       .P13(dx_ay_p[13]),
       .P14(dx_ay_p[14]),
       .P15(dx_ay_p[15]),
       .P16(dx_ay_p[16]),
       .P17(dx_ay_p[17]),
       .P18(dx_ay_p[18]),
       .P19(dx_ay_p[19]),
       .P20(dx_ay_p[20]),
       .P21(dx_ay_p[21]),
       .P22(dx_ay_p[22]),
       .P23(dx_ay_p[23]),
       .P24(dx_ay_p[24]),
       .P25(dx_ay_p[25]),
       .P26(dx_ay_p[26]),
       .P27(dx_ay_p[27]),
       .P28(dx_ay_p[28]),
       .P29(dx_ay_p[29]),
       .P30(dx_ay_p[30]),
       .P31(dx_ay_p[31]),
       .P32(dx_ay_p[32]),
       .P33(dx_ay_p[33]),
       .P34(dx_ay_p[34]),
       .P35(dx_ay_p[35])
    );
    wire [35:0] dy_ax_p;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dy_ax_dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(dy[0]), .B0(ax_1[0]), .C0(1'b0),
       .A1(dy[1]), .B1(ax_1[1]), .C1(1'b0),
       .A2(dy[2]), .B2(ax_1[2]), .C2(1'b0),
       .A3(dy[3]), .B3(ax_1[3]), .C3(1'b0),
       .A4(dy[4]), .B4(ax_1[4]), .C4(1'b0),
       .A5(dy[5]), .B5(ax_1[5]), .C5(1'b0),
       .A6(dy[6]), .B6(ax_1[6]), .C6(1'b0),
       .A7(dy[7]), .B7(ax_1[7]), .C7(1'b0),
       .A8(dy[8]), .B8(ax_1[8]), .C8(1'b0),
       .A9(dy[9]), .B9(ax_1[9]), .C9(1'b0),
       .A10(dy[10]), .B10(ax_1[10]), .C10(1'b0),
       .A11(dy[11]), .B11(ax_1[11]), .C11(1'b0),
       .A12(dy[12]), .B12(ax_1[12]), .C12(1'b0),
       .A13(dy[13]), .B13(ax_1[13]), .C13(1'b0),
       .A14(dy[14]), .B14(ax_1[14]), .C14(1'b0),
       .A15(dy[15]), .B15(ax_1[15]), .C15(1'b0),
       .A16(dy[16]), .B16(ax_1[16]), .C16(1'b0),
       .A17(dy[17]), .B17(ax_1[17]), .C17(1'b0),
       .P0(dy_ax_p[0]),
       .P1(dy_ax_p[1]),
       .P2(dy_ax_p[2]),
       .P3(dy_ax_p[3]),
       .P4(dy_ax_p[4]),
       .P5(dy_ax_p[5]),
       .P6(dy_ax_p[6]),
       .P7(dy_ax_p[7]),
       .P8(dy_ax_p[8]),
       .P9(dy_ax_p[9]),
       .P10(dy_ax_p[10]),
       .P11(dy_ax_p[11]),
       .P12(dy_ax_p[12]),
       .P13(dy_ax_p[13]),
       .P14(dy_ax_p[14]),
       .P15(dy_ax_p[15]),
       .P16(dy_ax_p[16]),
       .P17(dy_ax_p[17]),
       .P18(dy_ax_p[18]),
       .P19(dy_ax_p[19]),
       .P20(dy_ax_p[20]),
       .P21(dy_ax_p[21]),
       .P22(dy_ax_p[22]),
       .P23(dy_ax_p[23]),
       .P24(dy_ax_p[24]),
       .P25(dy_ax_p[25]),
       .P26(dy_ax_p[26]),
       .P27(dy_ax_p[27]),
       .P28(dy_ax_p[28]),
       .P29(dy_ax_p[29]),
       .P30(dy_ax_p[30]),
       .P31(dy_ax_p[31]),
       .P32(dy_ax_p[32]),
       .P33(dy_ax_p[33]),
       .P34(dy_ax_p[34]),
       .P35(dy_ax_p[35])
    );
    wire [35:0] dx_by_p;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dx_by_dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(dx[0]), .B0(by_1[0]), .C0(1'b0),
       .A1(dx[1]), .B1(by_1[1]), .C1(1'b0),
       .A2(dx[2]), .B2(by_1[2]), .C2(1'b0),
       .A3(dx[3]), .B3(by_1[3]), .C3(1'b0),
       .A4(dx[4]), .B4(by_1[4]), .C4(1'b0),
       .A5(dx[5]), .B5(by_1[5]), .C5(1'b0),
       .A6(dx[6]), .B6(by_1[6]), .C6(1'b0),
       .A7(dx[7]), .B7(by_1[7]), .C7(1'b0),
       .A8(dx[8]), .B8(by_1[8]), .C8(1'b0),
       .A9(dx[9]), .B9(by_1[9]), .C9(1'b0),
       .A10(dx[10]), .B10(by_1[10]), .C10(1'b0),
       .A11(dx[11]), .B11(by_1[11]), .C11(1'b0),
       .A12(dx[12]), .B12(by_1[12]), .C12(1'b0),
       .A13(dx[13]), .B13(by_1[13]), .C13(1'b0),
       .A14(dx[14]), .B14(by_1[14]), .C14(1'b0),
       .A15(dx[15]), .B15(by_1[15]), .C15(1'b0),
       .A16(dx[16]), .B16(by_1[16]), .C16(1'b0),
       .A17(dx[17]), .B17(by_1[17]), .C17(1'b0),
       .P0(dx_by_p[0]),
       .P1(dx_by_p[1]),
       .P2(dx_by_p[2]),
       .P3(dx_by_p[3]),
       .P4(dx_by_p[4]),
       .P5(dx_by_p[5]),
       .P6(dx_by_p[6]),
       .P7(dx_by_p[7]),
       .P8(dx_by_p[8]),
       .P9(dx_by_p[9]),
       .P10(dx_by_p[10]),
       .P11(dx_by_p[11]),
       .P12(dx_by_p[12]),
       .P13(dx_by_p[13]),
       .P14(dx_by_p[14]),
       .P15(dx_by_p[15]),
       .P16(dx_by_p[16]),
       .P17(dx_by_p[17]),
       .P18(dx_by_p[18]),
       .P19(dx_by_p[19]),
       .P20(dx_by_p[20]),
       .P21(dx_by_p[21]),
       .P22(dx_by_p[22]),
       .P23(dx_by_p[23]),
       .P24(dx_by_p[24]),
       .P25(dx_by_p[25]),
       .P26(dx_by_p[26]),
       .P27(dx_by_p[27]),
       .P28(dx_by_p[28]),
       .P29(dx_by_p[29]),
       .P30(dx_by_p[30]),
       .P31(dx_by_p[31]),
       .P32(dx_by_p[32]),
       .P33(dx_by_p[33]),
       .P34(dx_by_p[34]),
       .P35(dx_by_p[35])
    );
    wire [35:0] dy_bx_p;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dy_bx_dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(dy[0]), .B0(bx_1[0]), .C0(1'b0),
       .A1(dy[1]), .B1(bx_1[1]), .C1(1'b0),
       .A2(dy[2]), .B2(bx_1[2]), .C2(1'b0),
       .A3(dy[3]), .B3(bx_1[3]), .C3(1'b0),
       .A4(dy[4]), .B4(bx_1[4]), .C4(1'b0),
       .A5(dy[5]), .B5(bx_1[5]), .C5(1'b0),
       .A6(dy[6]), .B6(bx_1[6]), .C6(1'b0),
       .A7(dy[7]), .B7(bx_1[7]), .C7(1'b0),
       .A8(dy[8]), .B8(bx_1[8]), .C8(1'b0),
       .A9(dy[9]), .B9(bx_1[9]), .C9(1'b0),
       .A10(dy[10]), .B10(bx_1[10]), .C10(1'b0),
       .A11(dy[11]), .B11(bx_1[11]), .C11(1'b0),
       .A12(dy[12]), .B12(bx_1[12]), .C12(1'b0),
       .A13(dy[13]), .B13(bx_1[13]), .C13(1'b0),
       .A14(dy[14]), .B14(bx_1[14]), .C14(1'b0),
       .A15(dy[15]), .B15(bx_1[15]), .C15(1'b0),
       .A16(dy[16]), .B16(bx_1[16]), .C16(1'b0),
       .A17(dy[17]), .B17(bx_1[17]), .C17(1'b0),
       .P0(dy_bx_p[0]),
       .P1(dy_bx_p[1]),
       .P2(dy_bx_p[2]),
       .P3(dy_bx_p[3]),
       .P4(dy_bx_p[4]),
       .P5(dy_bx_p[5]),
       .P6(dy_bx_p[6]),
       .P7(dy_bx_p[7]),
       .P8(dy_bx_p[8]),
       .P9(dy_bx_p[9]),
       .P10(dy_bx_p[10]),
       .P11(dy_bx_p[11]),
       .P12(dy_bx_p[12]),
       .P13(dy_bx_p[13]),
       .P14(dy_bx_p[14]),
       .P15(dy_bx_p[15]),
       .P16(dy_bx_p[16]),
       .P17(dy_bx_p[17]),
       .P18(dy_bx_p[18]),
       .P19(dy_bx_p[19]),
       .P20(dy_bx_p[20]),
       .P21(dy_bx_p[21]),
       .P22(dy_bx_p[22]),
       .P23(dy_bx_p[23]),
       .P24(dy_bx_p[24]),
       .P25(dy_bx_p[25]),
       .P26(dy_bx_p[26]),
       .P27(dy_bx_p[27]),
       .P28(dy_bx_p[28]),
       .P29(dy_bx_p[29]),
       .P30(dy_bx_p[30]),
       .P31(dy_bx_p[31]),
       .P32(dy_bx_p[32]),
       .P33(dy_bx_p[33]),
       .P34(dy_bx_p[34]),
       .P35(dy_bx_p[35])
    );
    wire [35:0] dx_wx_p;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dx_wx_dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(dx[0]), .B0(wx_1[0]), .C0(1'b0),
       .A1(dx[1]), .B1(wx_1[1]), .C1(1'b0),
       .A2(dx[2]), .B2(wx_1[2]), .C2(1'b0),
       .A3(dx[3]), .B3(wx_1[3]), .C3(1'b0),
       .A4(dx[4]), .B4(wx_1[4]), .C4(1'b0),
       .A5(dx[5]), .B5(wx_1[5]), .C5(1'b0),
       .A6(dx[6]), .B6(wx_1[6]), .C6(1'b0),
       .A7(dx[7]), .B7(wx_1[7]), .C7(1'b0),
       .A8(dx[8]), .B8(wx_1[8]), .C8(1'b0),
       .A9(dx[9]), .B9(wx_1[9]), .C9(1'b0),
       .A10(dx[10]), .B10(wx_1[10]), .C10(1'b0),
       .A11(dx[11]), .B11(wx_1[11]), .C11(1'b0),
       .A12(dx[12]), .B12(wx_1[12]), .C12(1'b0),
       .A13(dx[13]), .B13(wx_1[13]), .C13(1'b0),
       .A14(dx[14]), .B14(wx_1[14]), .C14(1'b0),
       .A15(dx[15]), .B15(wx_1[15]), .C15(1'b0),
       .A16(dx[16]), .B16(wx_1[16]), .C16(1'b0),
       .A17(dx[17]), .B17(wx_1[17]), .C17(1'b0),
       .P0(dx_wx_p[0]),
       .P1(dx_wx_p[1]),
       .P2(dx_wx_p[2]),
       .P3(dx_wx_p[3]),
       .P4(dx_wx_p[4]),
       .P5(dx_wx_p[5]),
       .P6(dx_wx_p[6]),
       .P7(dx_wx_p[7]),
       .P8(dx_wx_p[8]),
       .P9(dx_wx_p[9]),
       .P10(dx_wx_p[10]),
       .P11(dx_wx_p[11]),
       .P12(dx_wx_p[12]),
       .P13(dx_wx_p[13]),
       .P14(dx_wx_p[14]),
       .P15(dx_wx_p[15]),
       .P16(dx_wx_p[16]),
       .P17(dx_wx_p[17]),
       .P18(dx_wx_p[18]),
       .P19(dx_wx_p[19]),
       .P20(dx_wx_p[20]),
       .P21(dx_wx_p[21]),
       .P22(dx_wx_p[22]),
       .P23(dx_wx_p[23]),
       .P24(dx_wx_p[24]),
       .P25(dx_wx_p[25]),
       .P26(dx_wx_p[26]),
       .P27(dx_wx_p[27]),
       .P28(dx_wx_p[28]),
       .P29(dx_wx_p[29]),
       .P30(dx_wx_p[30]),
       .P31(dx_wx_p[31]),
       .P32(dx_wx_p[32]),
       .P33(dx_wx_p[33]),
       .P34(dx_wx_p[34]),
       .P35(dx_wx_p[35])
    );
    wire [35:0] dy_wy_p;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dy_wy_dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(dy[0]), .B0(wy_1[0]), .C0(1'b0),
       .A1(dy[1]), .B1(wy_1[1]), .C1(1'b0),
       .A2(dy[2]), .B2(wy_1[2]), .C2(1'b0),
       .A3(dy[3]), .B3(wy_1[3]), .C3(1'b0),
       .A4(dy[4]), .B4(wy_1[4]), .C4(1'b0),
       .A5(dy[5]), .B5(wy_1[5]), .C5(1'b0),
       .A6(dy[6]), .B6(wy_1[6]), .C6(1'b0),
       .A7(dy[7]), .B7(wy_1[7]), .C7(1'b0),
       .A8(dy[8]), .B8(wy_1[8]), .C8(1'b0),
       .A9(dy[9]), .B9(wy_1[9]), .C9(1'b0),
       .A10(dy[10]), .B10(wy_1[10]), .C10(1'b0),
       .A11(dy[11]), .B11(wy_1[11]), .C11(1'b0),
       .A12(dy[12]), .B12(wy_1[12]), .C12(1'b0),
       .A13(dy[13]), .B13(wy_1[13]), .C13(1'b0),
       .A14(dy[14]), .B14(wy_1[14]), .C14(1'b0),
       .A15(dy[15]), .B15(wy_1[15]), .C15(1'b0),
       .A16(dy[16]), .B16(wy_1[16]), .C16(1'b0),
       .A17(dy[17]), .B17(wy_1[17]), .C17(1'b0),
       .P0(dy_wy_p[0]),
       .P1(dy_wy_p[1]),
       .P2(dy_wy_p[2]),
       .P3(dy_wy_p[3]),
       .P4(dy_wy_p[4]),
       .P5(dy_wy_p[5]),
       .P6(dy_wy_p[6]),
       .P7(dy_wy_p[7]),
       .P8(dy_wy_p[8]),
       .P9(dy_wy_p[9]),
       .P10(dy_wy_p[10]),
       .P11(dy_wy_p[11]),
       .P12(dy_wy_p[12]),
       .P13(dy_wy_p[13]),
       .P14(dy_wy_p[14]),
       .P15(dy_wy_p[15]),
       .P16(dy_wy_p[16]),
       .P17(dy_wy_p[17]),
       .P18(dy_wy_p[18]),
       .P19(dy_wy_p[19]),
       .P20(dy_wy_p[20]),
       .P21(dy_wy_p[21]),
       .P22(dy_wy_p[22]),
       .P23(dy_wy_p[23]),
       .P24(dy_wy_p[24]),
       .P25(dy_wy_p[25]),
       .P26(dy_wy_p[26]),
       .P27(dy_wy_p[27]),
       .P28(dy_wy_p[28]),
       .P29(dy_wy_p[29]),
       .P30(dy_wy_p[30]),
       .P31(dy_wy_p[31]),
       .P32(dy_wy_p[32]),
       .P33(dy_wy_p[33]),
       .P34(dy_wy_p[34]),
       .P35(dy_wy_p[35])
    );
    always @(*) begin
       dx_ay = dx_ay_p[35:4];
       dy_ax = dy_ax_p[35:4];
       dx_by = dx_by_p[35:4];
       dy_bx = dy_bx_p[35:4];
       dx_wx = dx_wx_p[35:4];
       dy_wy = dy_wy_p[35:4];
    end
    `else
    reg signed [17:0] dx_r;
    reg signed [17:0] dy_r;
    reg signed [17:0] ax_1;
    reg signed [17:0] ax_r;
    reg signed [17:0] ay_1;
    reg signed [17:0] ay_r;
    reg signed [17:0] bx_1;
    reg signed [17:0] bx_r;
    reg signed [17:0] by_1;
    reg signed [17:0] by_r;
    reg signed [17:0] wx_1;
    reg signed [17:0] wx_r;
    reg signed [17:0] wy_1;
    reg signed [17:0] wy_r;
    wire signed [35:0] dx_ay_m = dx_r * ay_r;
    wire signed [35:0] dy_ax_m = dy_r * ax_r;
    wire signed [35:0] dx_by_m = dx_r * by_r;
    wire signed [35:0] dy_bx_m = dy_r * bx_r;
    wire signed [35:0] dx_wx_m = dx_r * wx_r;
    wire signed [35:0] dy_wy_m = dy_r * wy_r;
    initial begin
       dx_r = 18'sd0;
       dy_r = 18'sd0;
       ax_1 = 18'sd0;
       ax_r = 18'sd0;
       ay_1 = 18'sd0;
       ay_r = 18'sd0;
       bx_1 = 18'sd0;
       bx_r = 18'sd0;
       by_1 = 18'sd0;
       by_r = 18'sd0;
       wx_1 = 18'sd0;
       wx_r = 18'sd0;
       wy_1 = 18'sd0;
       wy_r = 18'sd0;
       dx_ay = 32'd0;
       dy_ax = 32'd0;
       dx_by = 32'd0;
       dy_bx = 32'd0;
       dx_wx = 32'd0;
       dy_wy = 32'd0;
    end
    always @(posedge clock) begin
       dx_r <= dx;
       dy_r <= dy;
       ax_1 <= ax;
       ax_r <= ax_1;
       ay_1 <= ay;
       ay_r <= ay_1;
       bx_1 <= bx;
       bx_r <= bx_1;
       by_1 <= by;
       by_r <= by_1;
       wx_1 <= wx;
       wx_r <= wx_1;
       wy_1 <= wy;
       wy_r <= wy_1;
       dx_ay <= dx_ay_m[35:4];
       dy_ax <= dy_ax_m[35:4];
       dx_by <= dx_by_m[35:4];
       dy_bx <= dy_bx_m[35:4];
       dx_wx <= dx_wx_m[35:4];
       dy_wy <= dy_wy_m[35:4];
    end
    `endif
endmodule // intersection_unit$products


module intersection_unit$seq(clock,patch_valid,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,full,busy,kill,cur,v1,tag1,mark1,o_ax,o_ay,o_bx,o_by,o_wx,o_wy);
    
    // Module arguments
    input wire  clock;
    input wire  patch_valid;
    input wire  [17:0] patch_ax;
    input wire  [17:0] patch_ay;
    input wire  [17:0] patch_bx;
    input wire  [17:0] patch_by;
    input wire  [17:0] patch_wx;
    input wire  [17:0] patch_wy;
    input wire  [5:0] patch_sh;
    input wire  [15:0] patch_id;
    input wire  [10:0] patch_first;
    input wire  [10:0] patch_count;
    input wire  patch_retire;
    output reg  full;
    output reg  busy;
    output reg  kill;
    output reg  [10:0] cur;
    output reg  v1;
    output reg  [32:0] tag1;
    output reg  mark1;
    output reg  [17:0] o_ax;
    output reg  [17:0] o_ay;
    output reg  [17:0] o_bx;
    output reg  [17:0] o_by;
    output reg  [17:0] o_wx;
    output reg  [17:0] o_wy;
    
    // Update code (custom)
    reg [10:0] remaining;
    reg p_retire;
    reg [5:0] p_sh;
    reg [15:0] p_id;
    reg [17:0] p_ax;
    reg [17:0] p_ay;
    reg [17:0] p_bx;
    reg [17:0] p_by;
    reg [17:0] p_wx;
    reg [17:0] p_wy;
    reg issue;
    initial begin
       remaining = 11'd0;
       issue = 1'b0;
       p_retire = 1'b0;
       p_sh = 6'd0;
       p_id = 16'd0;
       full = 1'b0;
       cur = 11'd0;
       v1 = 1'b0;
       tag1 = 33'd0;
       mark1 = 1'b0;
       p_ax = 18'd0;
       o_ax = 18'd0;
       p_ay = 18'd0;
       o_ay = 18'd0;
       p_bx = 18'd0;
       o_bx = 18'd0;
       p_by = 18'd0;
       o_by = 18'd0;
       p_wx = 18'd0;
       o_wx = 18'd0;
       p_wy = 18'd0;
       o_wy = 18'd0;
    end
    always @(*) begin
       busy = issue || v1 || mark1;
       kill = issue && p_retire;
    end
    always @(posedge clock) begin
       v1 <= issue && !p_retire;
       tag1 <= {cur, p_sh, p_id};
       mark1 <= patch_valid && !full && patch_retire && patch_count == 11'd0;
       o_ax <= p_ax;
       o_ay <= p_ay;
       o_bx <= p_bx;
       o_by <= p_by;
       o_wx <= p_wx;
       o_wy <= p_wy;
       if (patch_valid && !full) begin
          remaining <= patch_count;
          issue <= patch_count != 11'd0;
          full <= patch_count[10:1] != 10'd0;
          cur <= patch_first;
          p_ax <= patch_ax;
          p_ay <= patch_ay;
          p_bx <= patch_bx;
          p_by <= patch_by;
          p_wx <= patch_wx;
          p_wy <= patch_wy;
          p_sh <= patch_sh;
          p_id <= patch_id;
          p_retire <= patch_retire;
       end else if (issue) begin
          remaining <= remaining - 11'd1;
          issue <= full;
          full <= remaining[10:2] != 9'd0 || remaining[1:0] == 2'b11;
          cur <= {cur[10], cur[9:0] + 10'd1};
       end
    end
endmodule // intersection_unit$seq
