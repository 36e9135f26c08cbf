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
    localparam  zero16 = 16'h0;
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
    reg  [17:0] o_ax$d;
    wire  [17:0] o_ax$q;
    reg  o_ax$clock;
    reg  [17:0] o_ay$d;
    wire  [17:0] o_ay$q;
    reg  o_ay$clock;
    reg  [17:0] o_bx$d;
    wire  [17:0] o_bx$q;
    reg  o_bx$clock;
    reg  [17:0] o_by$d;
    wire  [17:0] o_by$q;
    reg  o_by$clock;
    reg  [17:0] o_wx$d;
    wire  [17:0] o_wx$q;
    reg  o_wx$clock;
    reg  [17:0] o_wy$d;
    wire  [17:0] o_wy$q;
    reg  o_wy$clock;
    reg  v2$d;
    wire  v2$q;
    reg  v2$clock;
    reg  [31:0] tag2$d;
    wire  [31:0] tag2$q;
    reg  tag2$clock;
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
    reg  v3$d;
    wire  v3$q;
    reg  v3$clock;
    reg  [31:0] tag3$d;
    wire  [31:0] tag3$q;
    reg  tag3$clock;
    reg  v4$d;
    wire  v4$q;
    reg  v4$clock;
    reg  [31:0] tag4$d;
    wire  [31:0] tag4$q;
    reg  tag4$clock;
    reg  v5$d;
    wire  v5$q;
    reg  v5$clock;
    reg  [31:0] sa5$d;
    wire  [31:0] sa5$q;
    reg  sa5$clock;
    reg  [31:0] sb5$d;
    wire  [31:0] sb5$q;
    reg  sb5$clock;
    reg  [9:0] ray5$d;
    wire  [9:0] ray5$q;
    reg  ray5$clock;
    reg  [15:0] id5$d;
    wire  [15:0] id5$q;
    reg  id5$clock;
    reg  key_scale$clock;
    reg  [31:0] key_scale$q;
    reg  [5:0] key_scale$sh;
    wire  [31:0] key_scale$key;
    reg  v6$d;
    wire  v6$q;
    reg  v6$clock;
    reg  [9:0] ray6$d;
    wire  [9:0] ray6$q;
    reg  ray6$clock;
    reg  [15:0] id6$d;
    wire  [15:0] id6$q;
    reg  id6$clock;
    reg  v7$d;
    wire  v7$q;
    reg  v7$clock;
    reg  [9:0] ray7$d;
    wire  [9:0] ray7$q;
    reg  ray7$clock;
    reg  [15:0] id7$d;
    wire  [15:0] id7$q;
    reg  id7$clock;
    reg  v8$d;
    wire  v8$q;
    reg  v8$clock;
    reg  [9:0] ray8$d;
    wire  [9:0] ray8$q;
    reg  ray8$clock;
    reg  [15:0] id8$d;
    wire  [15:0] id8$q;
    reg  id8$clock;
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
    reg  cm_hit$d;
    wire  cm_hit$q;
    reg  cm_hit$clock;
    reg  cm_gt$d;
    wire  cm_gt$q;
    reg  cm_gt$clock;
    reg  cm_eq$d;
    wire  cm_eq$q;
    reg  cm_eq$clock;
    reg  cm_lt$d;
    wire  cm_lt$q;
    reg  cm_lt$clock;
    reg  c1_gt$d;
    wire  c1_gt$q;
    reg  c1_gt$clock;
    reg  c1_eq$d;
    wire  c1_eq$q;
    reg  c1_eq$clock;
    reg  c1_lt$d;
    wire  c1_lt$q;
    reg  c1_lt$clock;
    reg  c2_gt$d;
    wire  c2_gt$q;
    reg  c2_gt$clock;
    reg  c2_eq$d;
    wire  c2_eq$q;
    reg  c2_eq$clock;
    reg  c2_lt$d;
    wire  c2_lt$q;
    reg  c2_lt$clock;
    reg  c3_gt$d;
    wire  c3_gt$q;
    reg  c3_gt$clock;
    reg  c3_eq$d;
    wire  c3_eq$q;
    reg  c3_eq$clock;
    reg  c3_lt$d;
    wire  c3_lt$q;
    reg  c3_lt$clock;
    reg  m1$d;
    wire  m1$q;
    reg  m1$clock;
    reg  m2$d;
    wire  m2$q;
    reg  m2$clock;
    reg  m3$d;
    wire  m3$q;
    reg  m3$clock;
    reg  v9$d;
    wire  v9$q;
    reg  v9$clock;
    reg  [9:0] ray9$d;
    wire  [9:0] ray9$q;
    reg  ray9$clock;
    reg  [15:0] id9$d;
    wire  [15:0] id9$q;
    reg  id9$clock;
    reg  [31:0] key9$d;
    wire  [31:0] key9$q;
    reg  key9$clock;
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
    reg  fw2_valid$d;
    wire  fw2_valid$q;
    reg  fw2_valid$clock;
    reg  [9:0] fw2_ray$d;
    wire  [9:0] fw2_ray$q;
    reg  fw2_ray$clock;
    reg  [31:0] fw2_key$d;
    wire  [31:0] fw2_key$q;
    reg  fw2_key$clock;
    reg  [15:0] fw2_id$d;
    wire  [15:0] fw2_id$q;
    reg  fw2_id$clock;
    reg  fw3_valid$d;
    wire  fw3_valid$q;
    reg  fw3_valid$clock;
    reg  rd_valid$d;
    wire  rd_valid$q;
    reg  rd_valid$clock;
    reg  [9:0] rd_addr$d;
    wire  [9:0] rd_addr$q;
    reg  rd_addr$clock;
    reg  z1$d;
    wire  z1$q;
    reg  z1$clock;
    reg  z2$d;
    wire  z2$q;
    reg  z2$clock;
    
    // Local signals
    reg  live;
    reg  issue;
    reg  take;
    reg  [9:0] ray4;
    reg  [5:0] sh4;
    reg  [15:0] id4;
    reg  [31:0] side_a;
    reg  [31:0] side_b;
    reg  [31:0] q;
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
    intersection_unit$o_ax o_ax(
        .d(o_ax$d),
        .q(o_ax$q),
        .clock(o_ax$clock)
    );
    intersection_unit$o_ay o_ay(
        .d(o_ay$d),
        .q(o_ay$q),
        .clock(o_ay$clock)
    );
    intersection_unit$o_bx o_bx(
        .d(o_bx$d),
        .q(o_bx$q),
        .clock(o_bx$clock)
    );
    intersection_unit$o_by o_by(
        .d(o_by$d),
        .q(o_by$q),
        .clock(o_by$clock)
    );
    intersection_unit$o_wx o_wx(
        .d(o_wx$d),
        .q(o_wx$q),
        .clock(o_wx$clock)
    );
    intersection_unit$o_wy o_wy(
        .d(o_wy$d),
        .q(o_wy$q),
        .clock(o_wy$clock)
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
    intersection_unit$tag4 tag4(
        .d(tag4$d),
        .q(tag4$q),
        .clock(tag4$clock)
    );
    intersection_unit$v5 v5(
        .d(v5$d),
        .q(v5$q),
        .clock(v5$clock)
    );
    intersection_unit$sa5 sa5(
        .d(sa5$d),
        .q(sa5$q),
        .clock(sa5$clock)
    );
    intersection_unit$sb5 sb5(
        .d(sb5$d),
        .q(sb5$q),
        .clock(sb5$clock)
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
    intersection_unit$key_scale key_scale(
        .clock(key_scale$clock),
        .q(key_scale$q),
        .sh(key_scale$sh),
        .key(key_scale$key)
    );
    intersection_unit$v6 v6(
        .d(v6$d),
        .q(v6$q),
        .clock(v6$clock)
    );
    intersection_unit$ray6 ray6(
        .d(ray6$d),
        .q(ray6$q),
        .clock(ray6$clock)
    );
    intersection_unit$id6 id6(
        .d(id6$d),
        .q(id6$q),
        .clock(id6$clock)
    );
    intersection_unit$v7 v7(
        .d(v7$d),
        .q(v7$q),
        .clock(v7$clock)
    );
    intersection_unit$ray7 ray7(
        .d(ray7$d),
        .q(ray7$q),
        .clock(ray7$clock)
    );
    intersection_unit$id7 id7(
        .d(id7$d),
        .q(id7$q),
        .clock(id7$clock)
    );
    intersection_unit$v8 v8(
        .d(v8$d),
        .q(v8$q),
        .clock(v8$clock)
    );
    intersection_unit$ray8 ray8(
        .d(ray8$d),
        .q(ray8$q),
        .clock(ray8$clock)
    );
    intersection_unit$id8 id8(
        .d(id8$d),
        .q(id8$q),
        .clock(id8$clock)
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
    intersection_unit$cm_hit cm_hit(
        .d(cm_hit$d),
        .q(cm_hit$q),
        .clock(cm_hit$clock)
    );
    intersection_unit$cm_gt cm_gt(
        .d(cm_gt$d),
        .q(cm_gt$q),
        .clock(cm_gt$clock)
    );
    intersection_unit$cm_eq cm_eq(
        .d(cm_eq$d),
        .q(cm_eq$q),
        .clock(cm_eq$clock)
    );
    intersection_unit$cm_lt cm_lt(
        .d(cm_lt$d),
        .q(cm_lt$q),
        .clock(cm_lt$clock)
    );
    intersection_unit$c1_gt c1_gt(
        .d(c1_gt$d),
        .q(c1_gt$q),
        .clock(c1_gt$clock)
    );
    intersection_unit$c1_eq c1_eq(
        .d(c1_eq$d),
        .q(c1_eq$q),
        .clock(c1_eq$clock)
    );
    intersection_unit$c1_lt c1_lt(
        .d(c1_lt$d),
        .q(c1_lt$q),
        .clock(c1_lt$clock)
    );
    intersection_unit$c2_gt c2_gt(
        .d(c2_gt$d),
        .q(c2_gt$q),
        .clock(c2_gt$clock)
    );
    intersection_unit$c2_eq c2_eq(
        .d(c2_eq$d),
        .q(c2_eq$q),
        .clock(c2_eq$clock)
    );
    intersection_unit$c2_lt c2_lt(
        .d(c2_lt$d),
        .q(c2_lt$q),
        .clock(c2_lt$clock)
    );
    intersection_unit$c3_gt c3_gt(
        .d(c3_gt$d),
        .q(c3_gt$q),
        .clock(c3_gt$clock)
    );
    intersection_unit$c3_eq c3_eq(
        .d(c3_eq$d),
        .q(c3_eq$q),
        .clock(c3_eq$clock)
    );
    intersection_unit$c3_lt c3_lt(
        .d(c3_lt$d),
        .q(c3_lt$q),
        .clock(c3_lt$clock)
    );
    intersection_unit$m1 m1(
        .d(m1$d),
        .q(m1$q),
        .clock(m1$clock)
    );
    intersection_unit$m2 m2(
        .d(m2$d),
        .q(m2$q),
        .clock(m2$clock)
    );
    intersection_unit$m3 m3(
        .d(m3$d),
        .q(m3$q),
        .clock(m3$clock)
    );
    intersection_unit$v9 v9(
        .d(v9$d),
        .q(v9$q),
        .clock(v9$clock)
    );
    intersection_unit$ray9 ray9(
        .d(ray9$d),
        .q(ray9$q),
        .clock(ray9$clock)
    );
    intersection_unit$id9 id9(
        .d(id9$d),
        .q(id9$q),
        .clock(id9$clock)
    );
    intersection_unit$key9 key9(
        .d(key9$d),
        .q(key9$q),
        .clock(key9$clock)
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
    intersection_unit$fw2_valid fw2_valid(
        .d(fw2_valid$d),
        .q(fw2_valid$q),
        .clock(fw2_valid$clock)
    );
    intersection_unit$fw2_ray fw2_ray(
        .d(fw2_ray$d),
        .q(fw2_ray$q),
        .clock(fw2_ray$clock)
    );
    intersection_unit$fw2_key fw2_key(
        .d(fw2_key$d),
        .q(fw2_key$q),
        .clock(fw2_key$clock)
    );
    intersection_unit$fw2_id fw2_id(
        .d(fw2_id$d),
        .q(fw2_id$q),
        .clock(fw2_id$clock)
    );
    intersection_unit$fw3_valid fw3_valid(
        .d(fw3_valid$d),
        .q(fw3_valid$q),
        .clock(fw3_valid$clock)
    );
    intersection_unit$rd_valid rd_valid(
        .d(rd_valid$d),
        .q(rd_valid$q),
        .clock(rd_valid$clock)
    );
    intersection_unit$rd_addr rd_addr(
        .d(rd_addr$d),
        .q(rd_addr$q),
        .clock(rd_addr$clock)
    );
    intersection_unit$z1 z1(
        .d(z1$d),
        .q(z1$q),
        .clock(z1$clock)
    );
    intersection_unit$z2 z2(
        .d(z2$d),
        .q(z2$q),
        .clock(z2$clock)
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
        o_ax$clock = clock;
        o_ay$clock = clock;
        o_bx$clock = clock;
        o_by$clock = clock;
        o_wx$clock = clock;
        o_wy$clock = clock;
        v2$clock = clock;
        tag2$clock = clock;
        v3$clock = clock;
        tag3$clock = clock;
        v4$clock = clock;
        tag4$clock = clock;
        v5$clock = clock;
        sa5$clock = clock;
        sb5$clock = clock;
        ray5$clock = clock;
        id5$clock = clock;
        v6$clock = clock;
        ray6$clock = clock;
        id6$clock = clock;
        v7$clock = clock;
        ray7$clock = clock;
        id7$clock = clock;
        v8$clock = clock;
        ray8$clock = clock;
        id8$clock = clock;
        cm_hit$clock = clock;
        cm_gt$clock = clock;
        cm_eq$clock = clock;
        cm_lt$clock = clock;
        c1_gt$clock = clock;
        c1_eq$clock = clock;
        c1_lt$clock = clock;
        c2_gt$clock = clock;
        c2_eq$clock = clock;
        c2_lt$clock = clock;
        c3_gt$clock = clock;
        c3_eq$clock = clock;
        c3_lt$clock = clock;
        m1$clock = clock;
        m2$clock = clock;
        m3$clock = clock;
        v9$clock = clock;
        ray9$clock = clock;
        id9$clock = clock;
        key9$clock = clock;
        fw_valid$clock = clock;
        fw_ray$clock = clock;
        fw_key$clock = clock;
        fw_id$clock = clock;
        fw2_valid$clock = clock;
        fw2_ray$clock = clock;
        fw2_key$clock = clock;
        fw2_id$clock = clock;
        fw3_valid$clock = clock;
        rd_valid$clock = clock;
        rd_addr$clock = clock;
        z1$clock = clock;
        z2$clock = clock;
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
        o_ax$d = o_ax$q;
        o_ay$d = o_ay$q;
        o_bx$d = o_bx$q;
        o_by$d = o_by$q;
        o_wx$d = o_wx$q;
        o_wy$d = o_wy$q;
        v2$d = v2$q;
        tag2$d = tag2$q;
        v3$d = v3$q;
        tag3$d = tag3$q;
        v4$d = v4$q;
        tag4$d = tag4$q;
        v5$d = v5$q;
        sa5$d = sa5$q;
        sb5$d = sb5$q;
        ray5$d = ray5$q;
        id5$d = id5$q;
        v6$d = v6$q;
        ray6$d = ray6$q;
        id6$d = id6$q;
        v7$d = v7$q;
        ray7$d = ray7$q;
        id7$d = id7$q;
        v8$d = v8$q;
        ray8$d = ray8$q;
        id8$d = id8$q;
        cm_hit$d = cm_hit$q;
        cm_gt$d = cm_gt$q;
        cm_eq$d = cm_eq$q;
        cm_lt$d = cm_lt$q;
        c1_gt$d = c1_gt$q;
        c1_eq$d = c1_eq$q;
        c1_lt$d = c1_lt$q;
        c2_gt$d = c2_gt$q;
        c2_eq$d = c2_eq$q;
        c2_lt$d = c2_lt$q;
        c3_gt$d = c3_gt$q;
        c3_eq$d = c3_eq$q;
        c3_lt$d = c3_lt$q;
        m1$d = m1$q;
        m2$d = m2$q;
        m3$d = m3$q;
        v9$d = v9$q;
        ray9$d = ray9$q;
        id9$d = id9$q;
        key9$d = key9$q;
        fw_valid$d = fw_valid$q;
        fw_ray$d = fw_ray$q;
        fw_key$d = fw_key$q;
        fw_id$d = fw_id$q;
        fw2_valid$d = fw2_valid$q;
        fw2_ray$d = fw2_ray$q;
        fw2_key$d = fw2_key$q;
        fw2_id$d = fw2_id$q;
        fw3_valid$d = fw3_valid$q;
        rd_valid$d = rd_valid$q;
        rd_addr$d = rd_addr$q;
        z1$d = z1$q;
        z2$d = z2$q;
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
        o_ax$d = p_ax$q;
        o_ay$d = p_ay$q;
        o_bx$d = p_bx$q;
        o_by$d = p_by$q;
        o_wx$d = p_wx$q;
        o_wy$d = p_wy$q;
        products$ax = o_ax$q;
        products$ay = o_ay$q;
        products$bx = o_bx$q;
        products$by = o_by$q;
        products$wx = o_wx$q;
        products$wy = o_wy$q;
        v2$d = v1$q;
        tag2$d = tag1$q;
        products$dx = dir_mem_x$read_data;
        products$dy = dir_mem_y$read_data;
        live = v2$q & |alive_mem$read_data;
        if (live) begin
            test_count$d = test_count$q + one32;
        end
        v3$d = live;
        tag3$d = tag2$q;
        v4$d = v3$q;
        tag4$d = tag3$q;
        ray4 = tag4$q[(32'h16)+:(10)];
        sh4 = tag4$q[(32'h10)+:(6)];
        id4 = tag4$q[(32'h0)+:(16)];
        side_a = products$dx_ay - products$dy_ax;
        side_b = products$dx_by - products$dy_bx;
        q = products$dx_wx + products$dy_wy;
        v5$d = v4$q;
        sa5$d = side_a;
        sb5$d = side_b;
        ray5$d = ray4;
        id5$d = id4;
        key_scale$q = q;
        key_scale$sh = sh4;
        v6$d = v5$q & ((sa5$q == zero32) | sa5$q[32'h1f]) & ~sb5$q[32'h1f];
        ray6$d = ray5$q;
        id6$d = id5$q;
        v7$d = v6$q;
        ray7$d = ray6$q;
        id7$d = id6$q;
        v8$d = v7$q;
        ray8$d = ray7$q;
        id8$d = id7$q;
        mem_key$read_address = ray6$q;
        mem_meta$read_address = ray6$q;
        if (res_re) begin
            mem_key$read_address = res_addr;
            mem_meta$read_address = res_addr;
        end
        meta_hit = mem_meta$read_data[32'h10];
        meta_id = ((mem_meta$read_data) & 16'hffff);
        cm_hit$d = meta_hit;
        cm_gt$d = key_scale$key > mem_key$read_data;
        cm_eq$d = key_scale$key == mem_key$read_data;
        cm_lt$d = id8$q < meta_id;
        c1_gt$d = key_scale$key > key9$q;
        c1_eq$d = key_scale$key == key9$q;
        c1_lt$d = id8$q < id9$q;
        c2_gt$d = key_scale$key > fw_key$q;
        c2_eq$d = key_scale$key == fw_key$q;
        c2_lt$d = id8$q < fw_id$q;
        c3_gt$d = key_scale$key > fw2_key$q;
        c3_eq$d = key_scale$key == fw2_key$q;
        c3_lt$d = id8$q < fw2_id$q;
        m1$d = ray8$q == ray9$q;
        m2$d = ray8$q == fw_ray$q;
        m3$d = ray8$q == fw2_ray$q;
        v9$d = v8$q;
        ray9$d = ray8$q;
        id9$d = id8$q;
        key9$d = key_scale$key;
        if (m1$q & fw_valid$q) begin
            better = v9$q & (c1_gt$q | (c1_eq$q & c1_lt$q));
        end
        else if (m2$q & fw2_valid$q) begin
            better = v9$q & (c2_gt$q | (c2_eq$q & c2_lt$q));
        end
        else if (m3$q & fw3_valid$q) begin
            better = v9$q & (c3_gt$q | (c3_eq$q & c3_lt$q));
        end
        else begin
            better = v9$q & (~cm_hit$q | cm_gt$q | (cm_eq$q & cm_lt$q));
        end
        new_meta = hit_flag | ((id9$q) & 17'h1ffff);
        mem_key$write_address = ray9$q;
        mem_meta$write_address = ray9$q;
        mem_key$write_data = key9$q;
        mem_meta$write_data = new_meta;
        mem_key$write_enable = better;
        mem_meta$write_enable = better;
        if (rd_valid$q) begin
            mem_key$write_address = rd_addr$q;
            mem_meta$write_address = rd_addr$q;
            mem_key$write_data = zero32;
            mem_meta$write_data = zero17;
            mem_key$write_enable = 1'b1;
            mem_meta$write_enable = 1'b1;
        end
        fw_valid$d = better;
        fw_ray$d = ray9$q;
        fw_key$d = key9$q;
        fw_id$d = id9$q;
        fw2_valid$d = fw_valid$q;
        fw2_ray$d = fw_ray$q;
        fw2_key$d = fw_key$q;
        fw2_id$d = fw_id$q;
        fw3_valid$d = fw2_valid$q;
        rd_valid$d = res_re;
        rd_addr$d = res_addr;
        z1$d = res_re & rd_valid$q & (res_addr == rd_addr$q);
        z2$d = z1$q;
        res_hit = meta_hit & ~z2$q;
        res_id = meta_id;
        res_key = mem_key$read_data;
        if (z2$q) begin
            res_id = zero16;
            res_key = zero32;
        end
        busy = issue | v1$q | v2$q | v3$q | v4$q | v5$q | v6$q | v7$q | v8$q | v9$q;
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
    reg [0:0] mem [0:1023];
    reg [0:0] r1;
    reg collided;
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 1'd0;
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
endmodule // intersection_unit$alive_mem


module intersection_unit$c1_eq(d,q,clock);
    
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
          
endmodule // intersection_unit$c1_eq


module intersection_unit$c1_gt(d,q,clock);
    
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
          
endmodule // intersection_unit$c1_gt


module intersection_unit$c1_lt(d,q,clock);
    
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
          
endmodule // intersection_unit$c1_lt


module intersection_unit$c2_eq(d,q,clock);
    
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
          
endmodule // intersection_unit$c2_eq


module intersection_unit$c2_gt(d,q,clock);
    
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
          
endmodule // intersection_unit$c2_gt


module intersection_unit$c2_lt(d,q,clock);
    
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
          
endmodule // intersection_unit$c2_lt


module intersection_unit$c3_eq(d,q,clock);
    
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
          
endmodule // intersection_unit$c3_eq


module intersection_unit$c3_gt(d,q,clock);
    
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
          
endmodule // intersection_unit$c3_gt


module intersection_unit$c3_lt(d,q,clock);
    
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
          
endmodule // intersection_unit$c3_lt


module intersection_unit$cm_eq(d,q,clock);
    
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
          
endmodule // intersection_unit$cm_eq


module intersection_unit$cm_gt(d,q,clock);
    
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
          
endmodule // intersection_unit$cm_gt


module intersection_unit$cm_hit(d,q,clock);
    
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
          
endmodule // intersection_unit$cm_hit


module intersection_unit$cm_lt(d,q,clock);
    
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
          
endmodule // intersection_unit$cm_lt


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
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = write_data;
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
    always @(*) read_data = bo_rd[17:0];
    `else
    reg [17:0] mem [0:1023];
    reg [17:0] r1;
    reg collided;
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 18'd0;
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
    input wire  [9:0] read_address;
    output reg  [17:0] read_data;
    input wire  [9:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [17:0] bo_rd;
    wire [17:0] bo_wd = write_data;
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
    always @(*) read_data = bo_rd[17:0];
    `else
    reg [17:0] mem [0:1023];
    reg [17:0] r1;
    reg collided;
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 18'd0;
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


module intersection_unit$fw2_id(d,q,clock);
    
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
          
endmodule // intersection_unit$fw2_id


module intersection_unit$fw2_key(d,q,clock);
    
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
          
endmodule // intersection_unit$fw2_key


module intersection_unit$fw2_ray(d,q,clock);
    
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
          
endmodule // intersection_unit$fw2_ray


module intersection_unit$fw2_valid(d,q,clock);
    
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
          
endmodule // intersection_unit$fw2_valid


module intersection_unit$fw3_valid(d,q,clock);
    
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
          
endmodule // intersection_unit$fw3_valid


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


module intersection_unit$id6(d,q,clock);
    
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
          
endmodule // intersection_unit$id6


module intersection_unit$id7(d,q,clock);
    
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
          
endmodule // intersection_unit$id7


module intersection_unit$id8(d,q,clock);
    
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
          
endmodule // intersection_unit$id8


module intersection_unit$id9(d,q,clock);
    
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
          
endmodule // intersection_unit$id9


module intersection_unit$key9(d,q,clock);
    
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
          
endmodule // intersection_unit$key9


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


module intersection_unit$m1(d,q,clock);
    
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
          
endmodule // intersection_unit$m1


module intersection_unit$m2(d,q,clock);
    
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
          
endmodule // intersection_unit$m2


module intersection_unit$m3(d,q,clock);
    
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
          
endmodule // intersection_unit$m3


module intersection_unit$mem_key(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
    reg [31:0] mem [0:1023];
    reg [31:0] r1;
    reg collided;
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 32'd0;
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
    reg [16:0] mem [0:1023];
    reg [16:0] r1;
    reg collided;
    integer i;
    initial begin
       for (i = 0; i <= 1023; i = i + 1) mem[i] = 17'd0;
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
endmodule // intersection_unit$mem_meta


module intersection_unit$o_ax(d,q,clock);
    
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
          
endmodule // intersection_unit$o_ax


module intersection_unit$o_ay(d,q,clock);
    
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
          
endmodule // intersection_unit$o_ay


module intersection_unit$o_bx(d,q,clock);
    
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
          
endmodule // intersection_unit$o_bx


module intersection_unit$o_by(d,q,clock);
    
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
          
endmodule // intersection_unit$o_by


module intersection_unit$o_wx(d,q,clock);
    
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
          
endmodule // intersection_unit$o_wx


module intersection_unit$o_wy(d,q,clock);
    
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
          
endmodule // intersection_unit$o_wy


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


module intersection_unit$ray6(d,q,clock);
    
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
          
endmodule // intersection_unit$ray6


module intersection_unit$ray7(d,q,clock);
    
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
          
endmodule // intersection_unit$ray7


module intersection_unit$ray8(d,q,clock);
    
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
          
endmodule // intersection_unit$ray8


module intersection_unit$ray9(d,q,clock);
    
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
          
endmodule // intersection_unit$ray9


module intersection_unit$rd_addr(d,q,clock);
    
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
          
endmodule // intersection_unit$rd_addr


module intersection_unit$rd_valid(d,q,clock);
    
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
          
endmodule // intersection_unit$rd_valid


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


module intersection_unit$sa5(d,q,clock);
    
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
          
endmodule // intersection_unit$sa5


module intersection_unit$sb5(d,q,clock);
    
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
          
endmodule // intersection_unit$sb5


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


module intersection_unit$tag4(d,q,clock);
    
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
          
endmodule // intersection_unit$tag4


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


module intersection_unit$v6(d,q,clock);
    
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
          
endmodule // intersection_unit$v6


module intersection_unit$v7(d,q,clock);
    
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
          
endmodule // intersection_unit$v7


module intersection_unit$v8(d,q,clock);
    
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
          
endmodule // intersection_unit$v8


module intersection_unit$v9(d,q,clock);
    
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
          
endmodule // intersection_unit$v9


module intersection_unit$z1(d,q,clock);
    
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
          
endmodule // intersection_unit$z1


module intersection_unit$z2(d,q,clock);
    
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
          
endmodule // intersection_unit$z2
