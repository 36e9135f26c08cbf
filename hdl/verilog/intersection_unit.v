// intersection_unit: exported from rust-hdl by `shelling export-verilog`; do not edit.


module intersection_unit(clock,dir_we,dir_addr,dir_x,dir_y,patch_valid,patch_ready,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,res_re,res_addr,res_hit,res_id,res_key,busy,tests);
    
    // Module arguments
    input wire  clock;
    input wire  dir_we;
    input wire  [9:0] dir_addr;
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
    input wire  [9:0] patch_first;
    input wire  [10:0] patch_count;
    input wire  patch_retire;
    input wire  res_re;
    input wire  [9:0] res_addr;
    output reg  res_hit;
    output reg  [15:0] res_id;
    output reg  [31:0] res_key;
    output reg  busy;
    output reg  [31:0] tests;
    
    // Constant declarations
    localparam  zero11 = 11'b0;
    localparam  one11 = 11'b1;
    localparam  one10 = 10'b1;
    localparam  one32 = 32'h1;
    localparam  zero32 = 32'h0;
    localparam  hit_flag = 17'b10000000000000000;
    localparam  zero17 = 17'b0;
    
    // Stub signals
    reg  [10:0] remaining$d;
    wire  [10:0] remaining$q;
    reg  remaining$clock;
    reg  [9:0] cur$d;
    wire  [9:0] cur$q;
    reg  cur$clock;
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
    reg  [5:0] p_sh$d;
    wire  [5:0] p_sh$q;
    reg  p_sh$clock;
    reg  [15:0] p_id$d;
    wire  [15:0] p_id$q;
    reg  p_id$clock;
    reg  p_retire$d;
    wire  p_retire$q;
    reg  p_retire$clock;
    reg  alive_mem$clock;
    reg  [9:0] alive_mem$read_address;
    wire  alive_mem$read_data;
    reg  [9:0] alive_mem$write_address;
    reg  alive_mem$write_data;
    reg  alive_mem$write_enable;
    reg  [31:0] test_count$d;
    wire  [31:0] test_count$q;
    reg  test_count$clock;
    reg  v1$d;
    wire  v1$q;
    reg  v1$clock;
    reg  [31:0] tag1$d;
    wire  [31:0] tag1$q;
    reg  tag1$clock;
    reg  dir_mem_x$clock;
    reg  [9:0] dir_mem_x$read_address;
    wire  [17:0] dir_mem_x$read_data;
    reg  [9:0] dir_mem_x$write_address;
    reg  [17:0] dir_mem_x$write_data;
    reg  dir_mem_x$write_enable;
    reg  dir_mem_y$clock;
    reg  [9:0] dir_mem_y$read_address;
    wire  [17:0] dir_mem_y$read_data;
    reg  [9:0] dir_mem_y$write_address;
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
    reg  v2$d;
    wire  v2$q;
    reg  v2$clock;
    reg  [31:0] tag2$d;
    wire  [31:0] tag2$q;
    reg  tag2$clock;
    reg  v3$d;
    wire  v3$q;
    reg  v3$clock;
    reg  [31:0] tag3$d;
    wire  [31:0] tag3$q;
    reg  tag3$clock;
    reg  v4$d;
    wire  v4$q;
    reg  v4$clock;
    reg  [9:0] ray4$d;
    wire  [9:0] ray4$q;
    reg  ray4$clock;
    reg  [15:0] id4$d;
    wire  [15:0] id4$q;
    reg  id4$clock;
    reg  key_scale$clock;
    reg  [31:0] key_scale$q;
    reg  [5:0] key_scale$sh;
    wire  [31:0] key_scale$key;
    reg  v5$d;
    wire  v5$q;
    reg  v5$clock;
    reg  [9:0] ray5$d;
    wire  [9:0] ray5$q;
    reg  ray5$clock;
    reg  [15:0] id5$d;
    wire  [15:0] id5$q;
    reg  id5$clock;
    reg  mem_key$clock;
    reg  [9:0] mem_key$read_address;
    wire  [31:0] mem_key$read_data;
    reg  [9:0] mem_key$write_address;
    reg  [31:0] mem_key$write_data;
    reg  mem_key$write_enable;
    reg  mem_meta$clock;
    reg  [9:0] mem_meta$read_address;
    wire  [16:0] mem_meta$read_data;
    reg  [9:0] mem_meta$write_address;
    reg  [16:0] mem_meta$write_data;
    reg  mem_meta$write_enable;
    reg  fw_valid$d;
    wire  fw_valid$q;
    reg  fw_valid$clock;
    reg  [9:0] fw_ray$d;
    wire  [9:0] fw_ray$q;
    reg  fw_ray$clock;
    reg  [31:0] fw_key$d;
    wire  [31:0] fw_key$q;
    reg  fw_key$clock;
    reg  [15:0] fw_id$d;
    wire  [15:0] fw_id$q;
    reg  fw_id$clock;
    
    // Local signals
    reg  live;
    reg  issue;
    reg  take;
    reg  [9:0] ray3;
    reg  [5:0] sh3;
    reg  [15:0] id3;
    reg  [31:0] side_a;
    reg  [31:0] side_b;
    reg  [31:0] q;
    reg  old_hit;
    reg  [31:0] old_key;
    reg  [15:0] old_id;
    reg  meta_hit;
    reg  [15:0] meta_id;
    reg  better;
    reg  [16:0] new_meta;
    
    // Sub module instances
    intersection_unit$remaining remaining(
        .d(remaining$d),
        .q(remaining$q),
        .clock(remaining$clock)
    );
    intersection_unit$cur cur(
        .d(cur$d),
        .q(cur$q),
        .clock(cur$clock)
    );
    intersection_unit$p_ax p_ax(
        .d(p_ax$d),
        .q(p_ax$q),
        .clock(p_ax$clock)
    );
    intersection_unit$p_ay p_ay(
        .d(p_ay$d),
        .q(p_ay$q),
        .clock(p_ay$clock)
    );
    intersection_unit$p_bx p_bx(
        .d(p_bx$d),
        .q(p_bx$q),
        .clock(p_bx$clock)
    );
    intersection_unit$p_by p_by(
        .d(p_by$d),
        .q(p_by$q),
        .clock(p_by$clock)
    );
    intersection_unit$p_wx p_wx(
        .d(p_wx$d),
        .q(p_wx$q),
        .clock(p_wx$clock)
    );
    intersection_unit$p_wy p_wy(
        .d(p_wy$d),
        .q(p_wy$q),
        .clock(p_wy$clock)
    );
    intersection_unit$p_sh p_sh(
        .d(p_sh$d),
        .q(p_sh$q),
        .clock(p_sh$clock)
    );
    intersection_unit$p_id p_id(
        .d(p_id$d),
        .q(p_id$q),
        .clock(p_id$clock)
    );
    intersection_unit$p_retire p_retire(
        .d(p_retire$d),
        .q(p_retire$q),
        .clock(p_retire$clock)
    );
    intersection_unit$alive_mem alive_mem(
        .clock(alive_mem$clock),
        .read_address(alive_mem$read_address),
        .read_data(alive_mem$read_data),
        .write_address(alive_mem$write_address),
        .write_data(alive_mem$write_data),
        .write_enable(alive_mem$write_enable)
    );
    intersection_unit$test_count test_count(
        .d(test_count$d),
        .q(test_count$q),
        .clock(test_count$clock)
    );
    intersection_unit$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    intersection_unit$tag1 tag1(
        .d(tag1$d),
        .q(tag1$q),
        .clock(tag1$clock)
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
    intersection_unit$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    intersection_unit$tag2 tag2(
        .d(tag2$d),
        .q(tag2$q),
        .clock(tag2$clock)
    );
    intersection_unit$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    intersection_unit$tag3 tag3(
        .d(tag3$d),
        .q(tag3$q),
        .clock(tag3$clock)
    );
    intersection_unit$v4 v4(
        .d(v4$d),
        .q(v4$q),
        .clock(v4$clock)
    );
    intersection_unit$ray4 ray4(
        .d(ray4$d),
        .q(ray4$q),
        .clock(ray4$clock)
    );
    intersection_unit$id4 id4(
        .d(id4$d),
        .q(id4$q),
        .clock(id4$clock)
    );
    intersection_unit$key_scale key_scale(
        .clock(key_scale$clock),
        .q(key_scale$q),
        .sh(key_scale$sh),
        .key(key_scale$key)
    );
    intersection_unit$v5 v5(
        .d(v5$d),
        .q(v5$q),
        .clock(v5$clock)
    );
    intersection_unit$ray5 ray5(
        .d(ray5$d),
        .q(ray5$q),
        .clock(ray5$clock)
    );
    intersection_unit$id5 id5(
        .d(id5$d),
        .q(id5$q),
        .clock(id5$clock)
    );
    intersection_unit$mem_key mem_key(
        .clock(mem_key$clock),
        .read_address(mem_key$read_address),
        .read_data(mem_key$read_data),
        .write_address(mem_key$write_address),
        .write_data(mem_key$write_data),
        .write_enable(mem_key$write_enable)
    );
    intersection_unit$mem_meta mem_meta(
        .clock(mem_meta$clock),
        .read_address(mem_meta$read_address),
        .read_data(mem_meta$read_data),
        .write_address(mem_meta$write_address),
        .write_data(mem_meta$write_data),
        .write_enable(mem_meta$write_enable)
    );
    intersection_unit$fw_valid fw_valid(
        .d(fw_valid$d),
        .q(fw_valid$q),
        .clock(fw_valid$clock)
    );
    intersection_unit$fw_ray fw_ray(
        .d(fw_ray$d),
        .q(fw_ray$q),
        .clock(fw_ray$clock)
    );
    intersection_unit$fw_key fw_key(
        .d(fw_key$d),
        .q(fw_key$q),
        .clock(fw_key$clock)
    );
    intersection_unit$fw_id fw_id(
        .d(fw_id$d),
        .q(fw_id$q),
        .clock(fw_id$clock)
    );
    
    // Update code
    always @(*) begin
        remaining$clock = clock;
        cur$clock = clock;
        p_ax$clock = clock;
        p_ay$clock = clock;
        p_bx$clock = clock;
        p_by$clock = clock;
        p_wx$clock = clock;
        p_wy$clock = clock;
        p_sh$clock = clock;
        p_id$clock = clock;
        p_retire$clock = clock;
        test_count$clock = clock;
        v1$clock = clock;
        tag1$clock = clock;
        v2$clock = clock;
        tag2$clock = clock;
        v3$clock = clock;
        tag3$clock = clock;
        v4$clock = clock;
        ray4$clock = clock;
        id4$clock = clock;
        v5$clock = clock;
        ray5$clock = clock;
        id5$clock = clock;
        fw_valid$clock = clock;
        fw_ray$clock = clock;
        fw_key$clock = clock;
        fw_id$clock = clock;
        remaining$d = remaining$q;
        cur$d = cur$q;
        p_ax$d = p_ax$q;
        p_ay$d = p_ay$q;
        p_bx$d = p_bx$q;
        p_by$d = p_by$q;
        p_wx$d = p_wx$q;
        p_wy$d = p_wy$q;
        p_sh$d = p_sh$q;
        p_id$d = p_id$q;
        p_retire$d = p_retire$q;
        test_count$d = test_count$q;
        v1$d = v1$q;
        tag1$d = tag1$q;
        v2$d = v2$q;
        tag2$d = tag2$q;
        v3$d = v3$q;
        tag3$d = tag3$q;
        v4$d = v4$q;
        ray4$d = ray4$q;
        id4$d = id4$q;
        v5$d = v5$q;
        ray5$d = ray5$q;
        id5$d = id5$q;
        fw_valid$d = fw_valid$q;
        fw_ray$d = fw_ray$q;
        fw_key$d = fw_key$q;
        fw_id$d = fw_id$q;
        dir_mem_x$clock = clock;
        alive_mem$clock = clock;
        dir_mem_y$clock = clock;
        mem_key$clock = clock;
        mem_meta$clock = clock;
        products$clock = clock;
        key_scale$clock = clock;
        issue = remaining$q != zero11;
        patch_ready = (remaining$q == zero11) | (remaining$q == one11);
        take = patch_valid & ((remaining$q == zero11) | (remaining$q == one11));
        if (take) begin
            remaining$d = patch_count;
            cur$d = patch_first;
            p_ax$d = patch_ax;
            p_ay$d = patch_ay;
            p_bx$d = patch_bx;
            p_by$d = patch_by;
            p_wx$d = patch_wx;
            p_wy$d = patch_wy;
            p_sh$d = patch_sh;
            p_id$d = patch_id;
            p_retire$d = patch_retire;
        end
        else if (issue) begin
            remaining$d = remaining$q - one11;
            cur$d = cur$q + one10;
        end
        tests = test_count$q;
        dir_mem_x$read_address = cur$q;
        dir_mem_y$read_address = cur$q;
        dir_mem_x$write_address = dir_addr;
        dir_mem_y$write_address = dir_addr;
        dir_mem_x$write_data = dir_x;
        dir_mem_y$write_data = dir_y;
        dir_mem_x$write_enable = dir_we;
        dir_mem_y$write_enable = dir_we;
        alive_mem$read_address = cur$q;
        alive_mem$write_address = cur$q;
        alive_mem$write_data = 1'b0;
        alive_mem$write_enable = issue & p_retire$q;
        if (dir_we) begin
            alive_mem$write_address = dir_addr;
            alive_mem$write_data = 1'b1;
            alive_mem$write_enable = 1'b1;
        end
        v1$d = issue & ~p_retire$q;
        tag1$d = (((cur$q) & 32'hffffffff) << 32'h16) | (((p_sh$q) & 32'hffffffff) << 32'h10) | ((p_id$q) & 32'hffffffff);
        products$ax = p_ax$q;
        products$ay = p_ay$q;
        products$bx = p_bx$q;
        products$by = p_by$q;
        products$wx = p_wx$q;
        products$wy = p_wy$q;
        products$dx = dir_mem_x$read_data;
        products$dy = dir_mem_y$read_data;
        live = v1$q & |alive_mem$read_data;
        if (live) begin
            test_count$d = test_count$q + one32;
        end
        v2$d = live;
        tag2$d = tag1$q;
        v3$d = v2$q;
        tag3$d = tag2$q;
        ray3 = tag3$q[(32'h16)+:(10)];
        sh3 = tag3$q[(32'h10)+:(6)];
        id3 = tag3$q[(32'h0)+:(16)];
        side_a = products$dx_ay - products$dy_ax;
        side_b = products$dx_by - products$dy_bx;
        q = products$dx_wx + products$dy_wy;
        v4$d = v3$q & ((side_a == zero32) | side_a[32'h1f]) & ~side_b[32'h1f];
        ray4$d = ray3;
        id4$d = id3;
        key_scale$q = q;
        key_scale$sh = sh3;
        v5$d = v4$q;
        ray5$d = ray4$q;
        id5$d = id4$q;
        mem_key$read_address = ray4$q;
        mem_meta$read_address = ray4$q;
        if (res_re) begin
            mem_key$read_address = res_addr;
            mem_meta$read_address = res_addr;
        end
        meta_hit = mem_meta$read_data[32'h10];
        meta_id = ((mem_meta$read_data) & 16'hffff);
        old_hit = meta_hit;
        old_key = mem_key$read_data;
        old_id = meta_id;
        if (fw_valid$q & (fw_ray$q == ray5$q)) begin
            old_hit = 1'b1;
            old_key = fw_key$q;
            old_id = fw_id$q;
        end
        better = v5$q & (~old_hit | (key_scale$key > old_key) | ((key_scale$key == old_key) & (id5$q < old_id)));
        new_meta = hit_flag | ((id5$q) & 17'h1ffff);
        mem_key$write_address = ray5$q;
        mem_meta$write_address = ray5$q;
        mem_key$write_data = key_scale$key;
        mem_meta$write_data = new_meta;
        mem_key$write_enable = better;
        mem_meta$write_enable = better;
        if (res_re) begin
            mem_key$write_address = res_addr;
            mem_meta$write_address = res_addr;
            mem_key$write_data = zero32;
            mem_meta$write_data = zero17;
            mem_key$write_enable = 1'b1;
            mem_meta$write_enable = 1'b1;
        end
        fw_valid$d = better;
        fw_ray$d = ray5$q;
        fw_key$d = key_scale$key;
        fw_id$d = id5$q;
        res_hit = meta_hit;
        res_id = meta_id;
        res_key = mem_key$read_data;
        busy = issue | v1$q | v2$q | v3$q | v4$q | v5$q;
    end
    
endmodule // intersection_unit


module intersection_unit$alive_mem(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  read_data;
    input wire  [9:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [0:0] mem [0:1023];
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 1'd0;
       read_data = 1'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // intersection_unit$alive_mem


module intersection_unit$cur(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // intersection_unit$cur


module intersection_unit$dir_mem_x(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [17:0] read_data;
    input wire  [9:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [17:0] mem [0:1023];
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 18'd0;
       read_data = 18'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // intersection_unit$dir_mem_x


module intersection_unit$dir_mem_y(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [17:0] read_data;
    input wire  [9:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [17:0] mem [0:1023];
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 18'd0;
       read_data = 18'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // intersection_unit$dir_mem_y


module intersection_unit$fw_id(d,q,clock);
    
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
          
endmodule // intersection_unit$fw_id


module intersection_unit$fw_key(d,q,clock);
    
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
          
endmodule // intersection_unit$fw_key


module intersection_unit$fw_ray(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // intersection_unit$fw_ray


module intersection_unit$fw_valid(d,q,clock);
    
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
          
endmodule // intersection_unit$fw_valid


module intersection_unit$id4(d,q,clock);
    
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
          
endmodule // intersection_unit$id4


module intersection_unit$id5(d,q,clock);
    
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
          
endmodule // intersection_unit$id5


module intersection_unit$key_scale(clock,q,sh,key);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] q;
    input wire  [5:0] sh;
    output reg  [31:0] key;
    
    // Update code (custom)
    reg [31:0] q_r;
    reg [5:0] sh_r;
    reg [31:0] k;
    wire [31:0] right = q_r >> sh_r[4:0];
    initial begin
       q_r = 32'd0;
       sh_r = 6'd0;
       key = 32'd0;
    end
    always @(*) begin
       if (q_r[31] || q_r == 32'd0) k = 32'd1;
       else if (!sh_r[5]) k = (right == 32'd0) ? 32'd1 : right;
       else if (sh_r == 6'h3f) k = {q_r[30:0], 1'b0};
       else if (sh_r == 6'h3e) k = (q_r[31:30] == 2'd0) ? {q_r[29:0], 2'b0} : 32'hffffffff;
       else k = (q_r[31:29] == 3'd0) ? {q_r[28:0], 3'b0} : 32'hffffffff;
    end
    always @(posedge clock) begin
       q_r <= q;
       sh_r <= sh;
       key <= k;
    end
endmodule // intersection_unit$key_scale


module intersection_unit$mem_key(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [31:0] read_data;
    input wire  [9:0] write_address;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem [0:1023];
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 32'd0;
       read_data = 32'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // intersection_unit$mem_key


module intersection_unit$mem_meta(clock,read_address,read_data,write_address,write_data,write_enable);
    
    // Module arguments
    input wire  clock;
    input wire  [9:0] read_address;
    output reg  [16:0] read_data;
    input wire  [9:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [16:0] mem [0:1023];
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 17'd0;
       read_data = 17'd0;
    end
    always @(posedge clock) begin
       read_data <= mem[read_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // intersection_unit$mem_meta


module intersection_unit$p_ax(d,q,clock);
    
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
          
endmodule // intersection_unit$p_ax


module intersection_unit$p_ay(d,q,clock);
    
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
          
endmodule // intersection_unit$p_ay


module intersection_unit$p_bx(d,q,clock);
    
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
          
endmodule // intersection_unit$p_bx


module intersection_unit$p_by(d,q,clock);
    
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
          
endmodule // intersection_unit$p_by


module intersection_unit$p_id(d,q,clock);
    
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
          
endmodule // intersection_unit$p_id


module intersection_unit$p_retire(d,q,clock);
    
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
          
endmodule // intersection_unit$p_retire


module intersection_unit$p_sh(d,q,clock);
    
    // Module arguments
    input wire  [5:0] d;
    output reg  [5:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 6'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // intersection_unit$p_sh


module intersection_unit$p_wx(d,q,clock);
    
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
          
endmodule // intersection_unit$p_wx


module intersection_unit$p_wy(d,q,clock);
    
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
          
endmodule // intersection_unit$p_wy


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
endmodule // intersection_unit$products


module intersection_unit$ray4(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // intersection_unit$ray4


module intersection_unit$ray5(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // intersection_unit$ray5


module intersection_unit$remaining(d,q,clock);
    
    // Module arguments
    input wire  [10:0] d;
    output reg  [10:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 11'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // intersection_unit$remaining


module intersection_unit$tag1(d,q,clock);
    
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
          
endmodule // intersection_unit$tag1


module intersection_unit$tag2(d,q,clock);
    
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
          
endmodule // intersection_unit$tag2


module intersection_unit$tag3(d,q,clock);
    
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
          
endmodule // intersection_unit$tag3


module intersection_unit$test_count(d,q,clock);
    
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
          
endmodule // intersection_unit$test_count


module intersection_unit$v1(d,q,clock);
    
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
          
endmodule // intersection_unit$v1


module intersection_unit$v2(d,q,clock);
    
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
          
endmodule // intersection_unit$v2


module intersection_unit$v3(d,q,clock);
    
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
          
endmodule // intersection_unit$v3


module intersection_unit$v4(d,q,clock);
    
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
          
endmodule // intersection_unit$v4


module intersection_unit$v5(d,q,clock);
    
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
          
endmodule // intersection_unit$v5
