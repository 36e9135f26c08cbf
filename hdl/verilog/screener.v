// screener: exported from rust-hdl by `shelling export-verilog`; do not edit.


module screener(clock,origin_x,origin_y,normal_x,normal_y,first_x,first_y,last_x,last_y,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_bank,sector_read,sector_bank,normal_bank,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_pass,passed,backward,back_facing,outside,near);
    
    // Module arguments
    input wire  clock;
    input wire  [16:0] origin_x;
    input wire  [16:0] origin_y;
    input wire  [17:0] normal_x;
    input wire  [17:0] normal_y;
    input wire  [17:0] first_x;
    input wire  [17:0] first_y;
    input wire  [17:0] last_x;
    input wire  [17:0] last_y;
    input wire  in_valid;
    output reg  in_ready;
    input wire  [15:0] in_id;
    input wire  [16:0] in_ax;
    input wire  [16:0] in_ay;
    input wire  [16:0] in_bx;
    input wire  [16:0] in_by;
    input wire  in_bank;
    output reg  sector_read;
    output reg  sector_bank;
    output reg  normal_bank;
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
    output reg  out_pass;
    output reg  [31:0] passed;
    output reg  [31:0] backward;
    output reg  [31:0] back_facing;
    output reg  [31:0] outside;
    output reg  [31:0] near;
    
    // Constant declarations
    localparam  pass_flag = 7'b1000000;
    localparam  depth_m1_6 = 6'b11111;
    localparam  one6 = 6'b1;
    localparam  one5 = 5'b1;
    localparam  zero32 = 32'h0;
    localparam  one32 = 32'h1;
    localparam  msb32 = 32'h80000000;
    localparam  thr_f_hi = 16'h7fff;
    localparam  thr_f_lo = 16'hff00;
    localparam  thr_l_hi = 16'h8000;
    localparam  thr_l_lo = 16'h100;
    localparam  zero14 = 14'b0;
    localparam  zero3 = 3'b0;
    localparam  sh1 = 32'h1;
    localparam  c2_6 = 6'b10;
    localparam  c3_6 = 6'b11;
    localparam  tag_pass = 3'b1;
    localparam  tag_negx = 3'b10;
    localparam  tag_negy = 3'b100;
    
    // Stub signals
    reg  [5:0] used$d;
    wire  [5:0] used$q;
    reg  used$clock;
    reg  [4:0] res_ptr$d;
    wire  [4:0] res_ptr$q;
    reg  res_ptr$clock;
    reg  fifo$clock;
    reg  fifo$push;
    reg  fifo$pop;
    wire  [4:0] fifo$tail_address;
    wire  [4:0] fifo$head_address;
    wire  [4:0] fifo$next_address;
    wire  fifo$valid;
    wire  [5:0] fifo$count;
    reg  lane_id$clock;
    reg  [4:0] lane_id$write_address;
    reg  [15:0] lane_id$write_data;
    reg  lane_id$write_enable;
    reg  [4:0] lane_id$head_address;
    reg  [4:0] lane_id$next_address;
    reg  lane_id$pop;
    wire  [15:0] lane_id$read_data;
    reg  lane_ax$clock;
    reg  [4:0] lane_ax$write_address;
    reg  [17:0] lane_ax$write_data;
    reg  lane_ax$write_enable;
    reg  [4:0] lane_ax$head_address;
    reg  [4:0] lane_ax$next_address;
    reg  lane_ax$pop;
    wire  [17:0] lane_ax$read_data;
    reg  lane_ay$clock;
    reg  [4:0] lane_ay$write_address;
    reg  [17:0] lane_ay$write_data;
    reg  lane_ay$write_enable;
    reg  [4:0] lane_ay$head_address;
    reg  [4:0] lane_ay$next_address;
    reg  lane_ay$pop;
    wire  [17:0] lane_ay$read_data;
    reg  lane_bx$clock;
    reg  [4:0] lane_bx$write_address;
    reg  [17:0] lane_bx$write_data;
    reg  lane_bx$write_enable;
    reg  [4:0] lane_bx$head_address;
    reg  [4:0] lane_bx$next_address;
    reg  lane_bx$pop;
    wire  [17:0] lane_bx$read_data;
    reg  lane_by$clock;
    reg  [4:0] lane_by$write_address;
    reg  [17:0] lane_by$write_data;
    reg  lane_by$write_enable;
    reg  [4:0] lane_by$head_address;
    reg  [4:0] lane_by$next_address;
    reg  lane_by$pop;
    wire  [17:0] lane_by$read_data;
    reg  lane_sh$clock;
    reg  [4:0] lane_sh$write_address;
    reg  [6:0] lane_sh$write_data;
    reg  lane_sh$write_enable;
    reg  [4:0] lane_sh$head_address;
    reg  [4:0] lane_sh$next_address;
    reg  lane_sh$pop;
    wire  [6:0] lane_sh$read_data;
    reg  lane_wx$clock;
    reg  [4:0] lane_wx$write_address;
    reg  [17:0] lane_wx$write_data;
    reg  lane_wx$write_enable;
    reg  [4:0] lane_wx$head_address;
    reg  [4:0] lane_wx$next_address;
    reg  lane_wx$pop;
    wire  [17:0] lane_wx$read_data;
    reg  lane_wy$clock;
    reg  [4:0] lane_wy$write_address;
    reg  [17:0] lane_wy$write_data;
    reg  lane_wy$write_enable;
    reg  [4:0] lane_wy$head_address;
    reg  [4:0] lane_wy$next_address;
    reg  lane_wy$pop;
    wire  [17:0] lane_wy$read_data;
    reg  full$d;
    wire  full$q;
    reg  full$clock;
    reg  v1$d;
    wire  v1$q;
    reg  v1$clock;
    reg  bank1$d;
    wire  bank1$q;
    reg  bank1$clock;
    reg  [15:0] id1$d;
    wire  [15:0] id1$q;
    reg  id1$clock;
    reg  [17:0] ax1$d;
    wire  [17:0] ax1$q;
    reg  ax1$clock;
    reg  [17:0] ay1$d;
    wire  [17:0] ay1$q;
    reg  ay1$clock;
    reg  [17:0] bx1$d;
    wire  [17:0] bx1$q;
    reg  bx1$clock;
    reg  [17:0] by1$d;
    wire  [17:0] by1$q;
    reg  by1$clock;
    reg  m_nax$clock;
    reg  [17:0] m_nax$a;
    reg  [17:0] m_nax$b;
    wire  [31:0] m_nax$p;
    reg  m_nay$clock;
    reg  [17:0] m_nay$a;
    reg  [17:0] m_nay$b;
    wire  [31:0] m_nay$p;
    reg  m_nbx$clock;
    reg  [17:0] m_nbx$a;
    reg  [17:0] m_nbx$b;
    wire  [31:0] m_nbx$p;
    reg  m_nby$clock;
    reg  [17:0] m_nby$a;
    reg  [17:0] m_nby$b;
    wire  [31:0] m_nby$p;
    reg  m_aby$clock;
    reg  [17:0] m_aby$a;
    reg  [17:0] m_aby$b;
    wire  [31:0] m_aby$p;
    reg  m_abx$clock;
    reg  [17:0] m_abx$a;
    reg  [17:0] m_abx$b;
    wire  [31:0] m_abx$p;
    reg  m_fby$clock;
    reg  [17:0] m_fby$a;
    reg  [17:0] m_fby$b;
    wire  [31:0] m_fby$p;
    reg  m_fbx$clock;
    reg  [17:0] m_fbx$a;
    reg  [17:0] m_fbx$b;
    wire  [31:0] m_fbx$p;
    reg  m_lay$clock;
    reg  [17:0] m_lay$a;
    reg  [17:0] m_lay$b;
    wire  [31:0] m_lay$p;
    reg  m_lax$clock;
    reg  [17:0] m_lax$a;
    reg  [17:0] m_lax$b;
    wire  [31:0] m_lax$p;
    reg  v2$d;
    wire  v2$q;
    reg  v2$clock;
    reg  bank2$d;
    wire  bank2$q;
    reg  bank2$clock;
    reg  [15:0] id2$d;
    wire  [15:0] id2$q;
    reg  id2$clock;
    reg  [17:0] ax2$d;
    wire  [17:0] ax2$q;
    reg  ax2$clock;
    reg  [17:0] ay2$d;
    wire  [17:0] ay2$q;
    reg  ay2$clock;
    reg  [17:0] bx2$d;
    wire  [17:0] bx2$q;
    reg  bx2$clock;
    reg  [17:0] by2$d;
    wire  [17:0] by2$q;
    reg  by2$clock;
    reg  [17:0] absnx2$d;
    wire  [17:0] absnx2$q;
    reg  absnx2$clock;
    reg  [17:0] absny2$d;
    wire  [17:0] absny2$q;
    reg  absny2$clock;
    reg  negx2$d;
    wire  negx2$q;
    reg  negx2$clock;
    reg  negy2$d;
    wire  negy2$q;
    reg  negy2$clock;
    reg  [17:0] normal_x2$d;
    wire  [17:0] normal_x2$q;
    reg  normal_x2$clock;
    reg  [17:0] normal_y2$d;
    wire  [17:0] normal_y2$q;
    reg  normal_y2$clock;
    reg  [17:0] normal_xa2$d;
    wire  [17:0] normal_xa2$q;
    reg  normal_xa2$clock;
    reg  [17:0] normal_ya2$d;
    wire  [17:0] normal_ya2$q;
    reg  normal_ya2$clock;
    reg  v3$d;
    wire  v3$q;
    reg  v3$clock;
    reg  bank3$d;
    wire  bank3$q;
    reg  bank3$clock;
    reg  [15:0] id3$d;
    wire  [15:0] id3$q;
    reg  id3$clock;
    reg  [17:0] ax3$d;
    wire  [17:0] ax3$q;
    reg  ax3$clock;
    reg  [17:0] ay3$d;
    wire  [17:0] ay3$q;
    reg  ay3$clock;
    reg  [17:0] bx3$d;
    wire  [17:0] bx3$q;
    reg  bx3$clock;
    reg  [17:0] by3$d;
    wire  [17:0] by3$q;
    reg  by3$clock;
    reg  [17:0] absnx3$d;
    wire  [17:0] absnx3$q;
    reg  absnx3$clock;
    reg  [17:0] absny3$d;
    wire  [17:0] absny3$q;
    reg  absny3$clock;
    reg  negx3$d;
    wire  negx3$q;
    reg  negx3$clock;
    reg  negy3$d;
    wire  negy3$q;
    reg  negy3$clock;
    reg  [17:0] nmax3$d;
    wire  [17:0] nmax3$q;
    reg  nmax3$clock;
    reg  v4$d;
    wire  v4$q;
    reg  v4$clock;
    reg  [15:0] id4$d;
    wire  [15:0] id4$q;
    reg  id4$clock;
    reg  [31:0] p_aby4$d;
    wire  [31:0] p_aby4$q;
    reg  p_aby4$clock;
    reg  [31:0] p_abx4$d;
    wire  [31:0] p_abx4$q;
    reg  p_abx4$clock;
    reg  v5$d;
    wire  v5$q;
    reg  v5$clock;
    reg  [15:0] id5$d;
    wire  [15:0] id5$q;
    reg  id5$clock;
    reg  [31:0] k5$d;
    wire  [31:0] k5$q;
    reg  k5$clock;
    reg  [31:0] p_nax5$d;
    wire  [31:0] p_nax5$q;
    reg  p_nax5$clock;
    reg  [31:0] p_nay5$d;
    wire  [31:0] p_nay5$q;
    reg  p_nay5$clock;
    reg  [31:0] p_nbx5$d;
    wire  [31:0] p_nbx5$q;
    reg  p_nbx5$clock;
    reg  [31:0] p_nby5$d;
    wire  [31:0] p_nby5$q;
    reg  p_nby5$clock;
    reg  v6$d;
    wire  v6$q;
    reg  v6$clock;
    reg  [15:0] id6$d;
    wire  [15:0] id6$q;
    reg  id6$clock;
    reg  k_nonpos6$d;
    wire  k_nonpos6$q;
    reg  k_nonpos6$clock;
    reg  [31:0] ha6$d;
    wire  [31:0] ha6$q;
    reg  ha6$clock;
    reg  [31:0] hb6$d;
    wire  [31:0] hb6$q;
    reg  hb6$clock;
    reg  [31:0] p_fby6$d;
    wire  [31:0] p_fby6$q;
    reg  p_fby6$clock;
    reg  [31:0] p_fbx6$d;
    wire  [31:0] p_fbx6$q;
    reg  p_fbx6$clock;
    reg  [31:0] p_lay6$d;
    wire  [31:0] p_lay6$q;
    reg  p_lay6$clock;
    reg  [31:0] p_lax6$d;
    wire  [31:0] p_lax6$q;
    reg  p_lax6$clock;
    reg  [5:0] clz_n6$d;
    wire  [5:0] clz_n6$q;
    reg  clz_n6$clock;
    reg  [31:0] norm_n6$d;
    wire  [31:0] norm_n6$q;
    reg  norm_n6$clock;
    reg  v7$d;
    wire  v7$q;
    reg  v7$clock;
    reg  [15:0] id7$d;
    wire  [15:0] id7$q;
    reg  id7$clock;
    reg  [31:0] side_f7$d;
    wire  [31:0] side_f7$q;
    reg  side_f7$clock;
    reg  [31:0] side_l7$d;
    wire  [31:0] side_l7$q;
    reg  side_l7$clock;
    reg  [5:0] clz_n7$d;
    wire  [5:0] clz_n7$q;
    reg  clz_n7$clock;
    reg  [31:0] norm_n7$d;
    wire  [31:0] norm_n7$q;
    reg  norm_n7$clock;
    reg  backward7$d;
    wire  backward7$q;
    reg  backward7$clock;
    reg  back_facing7$d;
    wire  back_facing7$q;
    reg  back_facing7$clock;
    reg  ha_open7$d;
    wire  ha_open7$q;
    reg  ha_open7$clock;
    reg  hb_open7$d;
    wire  hb_open7$q;
    reg  hb_open7$clock;
    reg  f_hi_lt8$d;
    wire  f_hi_lt8$q;
    reg  f_hi_lt8$clock;
    reg  f_hi_eq8$d;
    wire  f_hi_eq8$q;
    reg  f_hi_eq8$clock;
    reg  f_lo_lt8$d;
    wire  f_lo_lt8$q;
    reg  f_lo_lt8$clock;
    reg  l_hi_gt8$d;
    wire  l_hi_gt8$q;
    reg  l_hi_gt8$clock;
    reg  l_hi_eq8$d;
    wire  l_hi_eq8$q;
    reg  l_hi_eq8$clock;
    reg  l_lo_gt8$d;
    wire  l_lo_gt8$q;
    reg  l_lo_gt8$clock;
    reg  ha_open8$d;
    wire  ha_open8$q;
    reg  ha_open8$clock;
    reg  hb_open8$d;
    wire  hb_open8$q;
    reg  hb_open8$clock;
    reg  v8$d;
    wire  v8$q;
    reg  v8$clock;
    reg  [15:0] id8$d;
    wire  [15:0] id8$q;
    reg  id8$clock;
    reg  [5:0] s0_8$d;
    wire  [5:0] s0_8$q;
    reg  s0_8$clock;
    reg  [5:0] s0_m1_8$d;
    wire  [5:0] s0_m1_8$q;
    reg  s0_m1_8$clock;
    reg  below8$d;
    wire  below8$q;
    reg  below8$clock;
    reg  near_a8$d;
    wire  near_a8$q;
    reg  near_a8$clock;
    reg  near_b8$d;
    wire  near_b8$q;
    reg  near_b8$clock;
    reg  [5:0] sp3_8$d;
    wire  [5:0] sp3_8$q;
    reg  sp3_8$clock;
    reg  [5:0] clz_n2_7$d;
    wire  [5:0] clz_n2_7$q;
    reg  clz_n2_7$clock;
    reg  [5:0] clz_n3_7$d;
    wire  [5:0] clz_n3_7$q;
    reg  clz_n3_7$clock;
    reg  backward8$d;
    wire  backward8$q;
    reg  backward8$clock;
    reg  back_facing8$d;
    wire  back_facing8$q;
    reg  back_facing8$clock;
    reg  pass9$d;
    wire  pass9$q;
    reg  pass9$clock;
    reg  backward9$d;
    wire  backward9$q;
    reg  backward9$clock;
    reg  back_facing9$d;
    wire  back_facing9$q;
    reg  back_facing9$clock;
    reg  outside9$d;
    wire  outside9$q;
    reg  outside9$clock;
    reg  near9$d;
    wire  near9$q;
    reg  near9$clock;
    reg  c_ax$clock;
    reg  [17:0] c_ax$d;
    wire  [17:0] c_ax$q;
    reg  c_ay$clock;
    reg  [17:0] c_ay$d;
    wire  [17:0] c_ay$q;
    reg  c_bx$clock;
    reg  [17:0] c_bx$d;
    wire  [17:0] c_bx$q;
    reg  c_by$clock;
    reg  [17:0] c_by$d;
    wire  [17:0] c_by$q;
    reg  c_absnx$clock;
    reg  [17:0] c_absnx$d;
    wire  [17:0] c_absnx$q;
    reg  c_absny$clock;
    reg  [17:0] c_absny$d;
    wire  [17:0] c_absny$q;
    reg  c_negx$clock;
    reg  c_negx$d;
    wire  c_negx$q;
    reg  c_negy$clock;
    reg  c_negy$d;
    wire  c_negy$q;
    reg  c_k$clock;
    reg  [31:0] c_k$d;
    wire  [31:0] c_k$q;
    reg  lz_n$clock;
    reg  [31:0] lz_n$value;
    wire  [31:0] lz_n$norm;
    wire  [5:0] lz_n$clz;
    reg  lz_e$clock;
    reg  [31:0] lz_e$value;
    wire  [31:0] lz_e$norm;
    wire  [5:0] lz_e$clz;
    reg  divider$clock;
    reg  [31:0] divider$rx;
    reg  [31:0] divider$ry;
    reg  [2:0] divider$fx;
    reg  [2:0] divider$fy;
    reg  [31:0] divider$k;
    reg  [2:0] divider$tag;
    wire  [16:0] divider$qx;
    wire  [16:0] divider$qy;
    wire  [17:0] divider$wx;
    wire  [17:0] divider$wy;
    wire  [2:0] divider$tag_out;
    reg  [31:0] c_passed$d;
    wire  [31:0] c_passed$q;
    reg  c_passed$clock;
    reg  [31:0] c_backward$d;
    wire  [31:0] c_backward$q;
    reg  c_backward$clock;
    reg  [31:0] c_back_facing$d;
    wire  [31:0] c_back_facing$q;
    reg  c_back_facing$clock;
    reg  [31:0] c_outside$d;
    wire  [31:0] c_outside$q;
    reg  c_outside$clock;
    reg  [31:0] c_near$d;
    wire  [31:0] c_near$q;
    reg  c_near$clock;
    
    // Local signals
    reg  [6:0] sh_pass;
    reg  room;
    reg  [5:0] used_next;
    reg  take;
    reg  pop;
    reg  reserve;
    reg  fill;
    reg  [5:0] used_inc;
    reg  [5:0] used_dec;
    reg  [4:0] res_inc;
    reg  [17:0] ext_ox;
    reg  [17:0] ext_oy;
    reg  [17:0] ext_ax;
    reg  [17:0] ext_ay;
    reg  [17:0] ext_bx;
    reg  [17:0] ext_by;
    reg  [17:0] nx;
    reg  [17:0] ny;
    reg  [17:0] nx_neg;
    reg  [17:0] ny_neg;
    reg  [17:0] absnx;
    reg  [17:0] absny;
    reg  [17:0] nmax;
    reg  [31:0] kk;
    reg  [31:0] ha;
    reg  [31:0] hb;
    reg  [31:0] k2;
    reg  ha_pos;
    reg  hb_pos;
    reg  is_backward;
    reg  is_back_facing;
    reg  [31:0] side_f;
    reg  [31:0] side_l;
    reg  [5:0] s0;
    reg  [5:0] s0_m1;
    reg  [17:0] n_hi;
    reg  [17:0] e_hi;
    reg  e_lo_nz;
    reg  n_below_e;
    reg  [31:0] side_f_x;
    reg  [31:0] side_l_x;
    reg  [5:0] exp8;
    reg  near8;
    reg  outside8;
    reg  is_near;
    reg  is_pass;
    reg  [35:0] wide_x;
    reg  [35:0] wide_y;
    reg  [34:0] dividend_x;
    reg  [34:0] dividend_y;
    reg  [2:0] tag_p;
    reg  [2:0] tag_x;
    reg  [2:0] tag_y;
    
    // Sub module instances
    screener$used used(
        .d(used$d),
        .q(used$q),
        .clock(used$clock)
    );
    screener$res_ptr res_ptr(
        .d(res_ptr$d),
        .q(res_ptr$q),
        .clock(res_ptr$clock)
    );
    screener$fifo fifo(
        .clock(fifo$clock),
        .push(fifo$push),
        .pop(fifo$pop),
        .tail_address(fifo$tail_address),
        .head_address(fifo$head_address),
        .next_address(fifo$next_address),
        .valid(fifo$valid),
        .count(fifo$count)
    );
    screener$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    screener$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    screener$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    screener$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    screener$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    screener$lane_sh lane_sh(
        .clock(lane_sh$clock),
        .write_address(lane_sh$write_address),
        .write_data(lane_sh$write_data),
        .write_enable(lane_sh$write_enable),
        .head_address(lane_sh$head_address),
        .next_address(lane_sh$next_address),
        .pop(lane_sh$pop),
        .read_data(lane_sh$read_data)
    );
    screener$lane_wx lane_wx(
        .clock(lane_wx$clock),
        .write_address(lane_wx$write_address),
        .write_data(lane_wx$write_data),
        .write_enable(lane_wx$write_enable),
        .head_address(lane_wx$head_address),
        .next_address(lane_wx$next_address),
        .pop(lane_wx$pop),
        .read_data(lane_wx$read_data)
    );
    screener$lane_wy lane_wy(
        .clock(lane_wy$clock),
        .write_address(lane_wy$write_address),
        .write_data(lane_wy$write_data),
        .write_enable(lane_wy$write_enable),
        .head_address(lane_wy$head_address),
        .next_address(lane_wy$next_address),
        .pop(lane_wy$pop),
        .read_data(lane_wy$read_data)
    );
    screener$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    screener$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    screener$bank1 bank1(
        .d(bank1$d),
        .q(bank1$q),
        .clock(bank1$clock)
    );
    screener$id1 id1(
        .d(id1$d),
        .q(id1$q),
        .clock(id1$clock)
    );
    screener$ax1 ax1(
        .d(ax1$d),
        .q(ax1$q),
        .clock(ax1$clock)
    );
    screener$ay1 ay1(
        .d(ay1$d),
        .q(ay1$q),
        .clock(ay1$clock)
    );
    screener$bx1 bx1(
        .d(bx1$d),
        .q(bx1$q),
        .clock(bx1$clock)
    );
    screener$by1 by1(
        .d(by1$d),
        .q(by1$q),
        .clock(by1$clock)
    );
    screener$m_nax m_nax(
        .clock(m_nax$clock),
        .a(m_nax$a),
        .b(m_nax$b),
        .p(m_nax$p)
    );
    screener$m_nay m_nay(
        .clock(m_nay$clock),
        .a(m_nay$a),
        .b(m_nay$b),
        .p(m_nay$p)
    );
    screener$m_nbx m_nbx(
        .clock(m_nbx$clock),
        .a(m_nbx$a),
        .b(m_nbx$b),
        .p(m_nbx$p)
    );
    screener$m_nby m_nby(
        .clock(m_nby$clock),
        .a(m_nby$a),
        .b(m_nby$b),
        .p(m_nby$p)
    );
    screener$m_aby m_aby(
        .clock(m_aby$clock),
        .a(m_aby$a),
        .b(m_aby$b),
        .p(m_aby$p)
    );
    screener$m_abx m_abx(
        .clock(m_abx$clock),
        .a(m_abx$a),
        .b(m_abx$b),
        .p(m_abx$p)
    );
    screener$m_fby m_fby(
        .clock(m_fby$clock),
        .a(m_fby$a),
        .b(m_fby$b),
        .p(m_fby$p)
    );
    screener$m_fbx m_fbx(
        .clock(m_fbx$clock),
        .a(m_fbx$a),
        .b(m_fbx$b),
        .p(m_fbx$p)
    );
    screener$m_lay m_lay(
        .clock(m_lay$clock),
        .a(m_lay$a),
        .b(m_lay$b),
        .p(m_lay$p)
    );
    screener$m_lax m_lax(
        .clock(m_lax$clock),
        .a(m_lax$a),
        .b(m_lax$b),
        .p(m_lax$p)
    );
    screener$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    screener$bank2 bank2(
        .d(bank2$d),
        .q(bank2$q),
        .clock(bank2$clock)
    );
    screener$id2 id2(
        .d(id2$d),
        .q(id2$q),
        .clock(id2$clock)
    );
    screener$ax2 ax2(
        .d(ax2$d),
        .q(ax2$q),
        .clock(ax2$clock)
    );
    screener$ay2 ay2(
        .d(ay2$d),
        .q(ay2$q),
        .clock(ay2$clock)
    );
    screener$bx2 bx2(
        .d(bx2$d),
        .q(bx2$q),
        .clock(bx2$clock)
    );
    screener$by2 by2(
        .d(by2$d),
        .q(by2$q),
        .clock(by2$clock)
    );
    screener$absnx2 absnx2(
        .d(absnx2$d),
        .q(absnx2$q),
        .clock(absnx2$clock)
    );
    screener$absny2 absny2(
        .d(absny2$d),
        .q(absny2$q),
        .clock(absny2$clock)
    );
    screener$negx2 negx2(
        .d(negx2$d),
        .q(negx2$q),
        .clock(negx2$clock)
    );
    screener$negy2 negy2(
        .d(negy2$d),
        .q(negy2$q),
        .clock(negy2$clock)
    );
    screener$normal_x2 normal_x2(
        .d(normal_x2$d),
        .q(normal_x2$q),
        .clock(normal_x2$clock)
    );
    screener$normal_y2 normal_y2(
        .d(normal_y2$d),
        .q(normal_y2$q),
        .clock(normal_y2$clock)
    );
    screener$normal_xa2 normal_xa2(
        .d(normal_xa2$d),
        .q(normal_xa2$q),
        .clock(normal_xa2$clock)
    );
    screener$normal_ya2 normal_ya2(
        .d(normal_ya2$d),
        .q(normal_ya2$q),
        .clock(normal_ya2$clock)
    );
    screener$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    screener$bank3 bank3(
        .d(bank3$d),
        .q(bank3$q),
        .clock(bank3$clock)
    );
    screener$id3 id3(
        .d(id3$d),
        .q(id3$q),
        .clock(id3$clock)
    );
    screener$ax3 ax3(
        .d(ax3$d),
        .q(ax3$q),
        .clock(ax3$clock)
    );
    screener$ay3 ay3(
        .d(ay3$d),
        .q(ay3$q),
        .clock(ay3$clock)
    );
    screener$bx3 bx3(
        .d(bx3$d),
        .q(bx3$q),
        .clock(bx3$clock)
    );
    screener$by3 by3(
        .d(by3$d),
        .q(by3$q),
        .clock(by3$clock)
    );
    screener$absnx3 absnx3(
        .d(absnx3$d),
        .q(absnx3$q),
        .clock(absnx3$clock)
    );
    screener$absny3 absny3(
        .d(absny3$d),
        .q(absny3$q),
        .clock(absny3$clock)
    );
    screener$negx3 negx3(
        .d(negx3$d),
        .q(negx3$q),
        .clock(negx3$clock)
    );
    screener$negy3 negy3(
        .d(negy3$d),
        .q(negy3$q),
        .clock(negy3$clock)
    );
    screener$nmax3 nmax3(
        .d(nmax3$d),
        .q(nmax3$q),
        .clock(nmax3$clock)
    );
    screener$v4 v4(
        .d(v4$d),
        .q(v4$q),
        .clock(v4$clock)
    );
    screener$id4 id4(
        .d(id4$d),
        .q(id4$q),
        .clock(id4$clock)
    );
    screener$p_aby4 p_aby4(
        .d(p_aby4$d),
        .q(p_aby4$q),
        .clock(p_aby4$clock)
    );
    screener$p_abx4 p_abx4(
        .d(p_abx4$d),
        .q(p_abx4$q),
        .clock(p_abx4$clock)
    );
    screener$v5 v5(
        .d(v5$d),
        .q(v5$q),
        .clock(v5$clock)
    );
    screener$id5 id5(
        .d(id5$d),
        .q(id5$q),
        .clock(id5$clock)
    );
    screener$k5 k5(
        .d(k5$d),
        .q(k5$q),
        .clock(k5$clock)
    );
    screener$p_nax5 p_nax5(
        .d(p_nax5$d),
        .q(p_nax5$q),
        .clock(p_nax5$clock)
    );
    screener$p_nay5 p_nay5(
        .d(p_nay5$d),
        .q(p_nay5$q),
        .clock(p_nay5$clock)
    );
    screener$p_nbx5 p_nbx5(
        .d(p_nbx5$d),
        .q(p_nbx5$q),
        .clock(p_nbx5$clock)
    );
    screener$p_nby5 p_nby5(
        .d(p_nby5$d),
        .q(p_nby5$q),
        .clock(p_nby5$clock)
    );
    screener$v6 v6(
        .d(v6$d),
        .q(v6$q),
        .clock(v6$clock)
    );
    screener$id6 id6(
        .d(id6$d),
        .q(id6$q),
        .clock(id6$clock)
    );
    screener$k_nonpos6 k_nonpos6(
        .d(k_nonpos6$d),
        .q(k_nonpos6$q),
        .clock(k_nonpos6$clock)
    );
    screener$ha6 ha6(
        .d(ha6$d),
        .q(ha6$q),
        .clock(ha6$clock)
    );
    screener$hb6 hb6(
        .d(hb6$d),
        .q(hb6$q),
        .clock(hb6$clock)
    );
    screener$p_fby6 p_fby6(
        .d(p_fby6$d),
        .q(p_fby6$q),
        .clock(p_fby6$clock)
    );
    screener$p_fbx6 p_fbx6(
        .d(p_fbx6$d),
        .q(p_fbx6$q),
        .clock(p_fbx6$clock)
    );
    screener$p_lay6 p_lay6(
        .d(p_lay6$d),
        .q(p_lay6$q),
        .clock(p_lay6$clock)
    );
    screener$p_lax6 p_lax6(
        .d(p_lax6$d),
        .q(p_lax6$q),
        .clock(p_lax6$clock)
    );
    screener$clz_n6 clz_n6(
        .d(clz_n6$d),
        .q(clz_n6$q),
        .clock(clz_n6$clock)
    );
    screener$norm_n6 norm_n6(
        .d(norm_n6$d),
        .q(norm_n6$q),
        .clock(norm_n6$clock)
    );
    screener$v7 v7(
        .d(v7$d),
        .q(v7$q),
        .clock(v7$clock)
    );
    screener$id7 id7(
        .d(id7$d),
        .q(id7$q),
        .clock(id7$clock)
    );
    screener$side_f7 side_f7(
        .d(side_f7$d),
        .q(side_f7$q),
        .clock(side_f7$clock)
    );
    screener$side_l7 side_l7(
        .d(side_l7$d),
        .q(side_l7$q),
        .clock(side_l7$clock)
    );
    screener$clz_n7 clz_n7(
        .d(clz_n7$d),
        .q(clz_n7$q),
        .clock(clz_n7$clock)
    );
    screener$norm_n7 norm_n7(
        .d(norm_n7$d),
        .q(norm_n7$q),
        .clock(norm_n7$clock)
    );
    screener$backward7 backward7(
        .d(backward7$d),
        .q(backward7$q),
        .clock(backward7$clock)
    );
    screener$back_facing7 back_facing7(
        .d(back_facing7$d),
        .q(back_facing7$q),
        .clock(back_facing7$clock)
    );
    screener$ha_open7 ha_open7(
        .d(ha_open7$d),
        .q(ha_open7$q),
        .clock(ha_open7$clock)
    );
    screener$hb_open7 hb_open7(
        .d(hb_open7$d),
        .q(hb_open7$q),
        .clock(hb_open7$clock)
    );
    screener$f_hi_lt8 f_hi_lt8(
        .d(f_hi_lt8$d),
        .q(f_hi_lt8$q),
        .clock(f_hi_lt8$clock)
    );
    screener$f_hi_eq8 f_hi_eq8(
        .d(f_hi_eq8$d),
        .q(f_hi_eq8$q),
        .clock(f_hi_eq8$clock)
    );
    screener$f_lo_lt8 f_lo_lt8(
        .d(f_lo_lt8$d),
        .q(f_lo_lt8$q),
        .clock(f_lo_lt8$clock)
    );
    screener$l_hi_gt8 l_hi_gt8(
        .d(l_hi_gt8$d),
        .q(l_hi_gt8$q),
        .clock(l_hi_gt8$clock)
    );
    screener$l_hi_eq8 l_hi_eq8(
        .d(l_hi_eq8$d),
        .q(l_hi_eq8$q),
        .clock(l_hi_eq8$clock)
    );
    screener$l_lo_gt8 l_lo_gt8(
        .d(l_lo_gt8$d),
        .q(l_lo_gt8$q),
        .clock(l_lo_gt8$clock)
    );
    screener$ha_open8 ha_open8(
        .d(ha_open8$d),
        .q(ha_open8$q),
        .clock(ha_open8$clock)
    );
    screener$hb_open8 hb_open8(
        .d(hb_open8$d),
        .q(hb_open8$q),
        .clock(hb_open8$clock)
    );
    screener$v8 v8(
        .d(v8$d),
        .q(v8$q),
        .clock(v8$clock)
    );
    screener$id8 id8(
        .d(id8$d),
        .q(id8$q),
        .clock(id8$clock)
    );
    screener$s0_8 s0_8(
        .d(s0_8$d),
        .q(s0_8$q),
        .clock(s0_8$clock)
    );
    screener$s0_m1_8 s0_m1_8(
        .d(s0_m1_8$d),
        .q(s0_m1_8$q),
        .clock(s0_m1_8$clock)
    );
    screener$below8 below8(
        .d(below8$d),
        .q(below8$q),
        .clock(below8$clock)
    );
    screener$near_a8 near_a8(
        .d(near_a8$d),
        .q(near_a8$q),
        .clock(near_a8$clock)
    );
    screener$near_b8 near_b8(
        .d(near_b8$d),
        .q(near_b8$q),
        .clock(near_b8$clock)
    );
    screener$sp3_8 sp3_8(
        .d(sp3_8$d),
        .q(sp3_8$q),
        .clock(sp3_8$clock)
    );
    screener$clz_n2_7 clz_n2_7(
        .d(clz_n2_7$d),
        .q(clz_n2_7$q),
        .clock(clz_n2_7$clock)
    );
    screener$clz_n3_7 clz_n3_7(
        .d(clz_n3_7$d),
        .q(clz_n3_7$q),
        .clock(clz_n3_7$clock)
    );
    screener$backward8 backward8(
        .d(backward8$d),
        .q(backward8$q),
        .clock(backward8$clock)
    );
    screener$back_facing8 back_facing8(
        .d(back_facing8$d),
        .q(back_facing8$q),
        .clock(back_facing8$clock)
    );
    screener$pass9 pass9(
        .d(pass9$d),
        .q(pass9$q),
        .clock(pass9$clock)
    );
    screener$backward9 backward9(
        .d(backward9$d),
        .q(backward9$q),
        .clock(backward9$clock)
    );
    screener$back_facing9 back_facing9(
        .d(back_facing9$d),
        .q(back_facing9$q),
        .clock(back_facing9$clock)
    );
    screener$outside9 outside9(
        .d(outside9$d),
        .q(outside9$q),
        .clock(outside9$clock)
    );
    screener$near9 near9(
        .d(near9$d),
        .q(near9$q),
        .clock(near9$clock)
    );
    screener$c_ax c_ax(
        .clock(c_ax$clock),
        .d(c_ax$d),
        .q(c_ax$q)
    );
    screener$c_ay c_ay(
        .clock(c_ay$clock),
        .d(c_ay$d),
        .q(c_ay$q)
    );
    screener$c_bx c_bx(
        .clock(c_bx$clock),
        .d(c_bx$d),
        .q(c_bx$q)
    );
    screener$c_by c_by(
        .clock(c_by$clock),
        .d(c_by$d),
        .q(c_by$q)
    );
    screener$c_absnx c_absnx(
        .clock(c_absnx$clock),
        .d(c_absnx$d),
        .q(c_absnx$q)
    );
    screener$c_absny c_absny(
        .clock(c_absny$clock),
        .d(c_absny$d),
        .q(c_absny$q)
    );
    screener$c_negx c_negx(
        .clock(c_negx$clock),
        .d(c_negx$d),
        .q(c_negx$q)
    );
    screener$c_negy c_negy(
        .clock(c_negy$clock),
        .d(c_negy$d),
        .q(c_negy$q)
    );
    screener$c_k c_k(
        .clock(c_k$clock),
        .d(c_k$d),
        .q(c_k$q)
    );
    screener$lz_n lz_n(
        .clock(lz_n$clock),
        .value(lz_n$value),
        .norm(lz_n$norm),
        .clz(lz_n$clz)
    );
    screener$lz_e lz_e(
        .clock(lz_e$clock),
        .value(lz_e$value),
        .norm(lz_e$norm),
        .clz(lz_e$clz)
    );
    screener$divider divider(
        .clock(divider$clock),
        .rx(divider$rx),
        .ry(divider$ry),
        .fx(divider$fx),
        .fy(divider$fy),
        .k(divider$k),
        .tag(divider$tag),
        .qx(divider$qx),
        .qy(divider$qy),
        .wx(divider$wx),
        .wy(divider$wy),
        .tag_out(divider$tag_out)
    );
    screener$c_passed c_passed(
        .d(c_passed$d),
        .q(c_passed$q),
        .clock(c_passed$clock)
    );
    screener$c_backward c_backward(
        .d(c_backward$d),
        .q(c_backward$q),
        .clock(c_backward$clock)
    );
    screener$c_back_facing c_back_facing(
        .d(c_back_facing$d),
        .q(c_back_facing$q),
        .clock(c_back_facing$clock)
    );
    screener$c_outside c_outside(
        .d(c_outside$d),
        .q(c_outside$q),
        .clock(c_outside$clock)
    );
    screener$c_near c_near(
        .d(c_near$d),
        .q(c_near$q),
        .clock(c_near$clock)
    );
    
    // Update code
    always @(*) begin
        used$clock = clock;
        full$clock = clock;
        res_ptr$clock = clock;
        v1$clock = clock;
        bank1$clock = clock;
        id1$clock = clock;
        ax1$clock = clock;
        ay1$clock = clock;
        bx1$clock = clock;
        by1$clock = clock;
        v2$clock = clock;
        bank2$clock = clock;
        id2$clock = clock;
        ax2$clock = clock;
        ay2$clock = clock;
        bx2$clock = clock;
        by2$clock = clock;
        absnx2$clock = clock;
        absny2$clock = clock;
        negx2$clock = clock;
        negy2$clock = clock;
        normal_x2$clock = clock;
        normal_y2$clock = clock;
        normal_xa2$clock = clock;
        normal_ya2$clock = clock;
        v3$clock = clock;
        bank3$clock = clock;
        id3$clock = clock;
        ax3$clock = clock;
        ay3$clock = clock;
        bx3$clock = clock;
        by3$clock = clock;
        absnx3$clock = clock;
        absny3$clock = clock;
        negx3$clock = clock;
        negy3$clock = clock;
        nmax3$clock = clock;
        v4$clock = clock;
        id4$clock = clock;
        p_aby4$clock = clock;
        p_abx4$clock = clock;
        v5$clock = clock;
        id5$clock = clock;
        k5$clock = clock;
        p_nax5$clock = clock;
        p_nay5$clock = clock;
        p_nbx5$clock = clock;
        p_nby5$clock = clock;
        v6$clock = clock;
        id6$clock = clock;
        k_nonpos6$clock = clock;
        ha6$clock = clock;
        hb6$clock = clock;
        p_fby6$clock = clock;
        p_fbx6$clock = clock;
        p_lay6$clock = clock;
        p_lax6$clock = clock;
        clz_n6$clock = clock;
        norm_n6$clock = clock;
        v7$clock = clock;
        id7$clock = clock;
        side_f7$clock = clock;
        side_l7$clock = clock;
        clz_n7$clock = clock;
        norm_n7$clock = clock;
        backward7$clock = clock;
        back_facing7$clock = clock;
        ha_open7$clock = clock;
        hb_open7$clock = clock;
        v8$clock = clock;
        id8$clock = clock;
        s0_8$clock = clock;
        s0_m1_8$clock = clock;
        below8$clock = clock;
        near_a8$clock = clock;
        near_b8$clock = clock;
        sp3_8$clock = clock;
        clz_n2_7$clock = clock;
        clz_n3_7$clock = clock;
        backward8$clock = clock;
        back_facing8$clock = clock;
        f_hi_lt8$clock = clock;
        f_hi_eq8$clock = clock;
        f_lo_lt8$clock = clock;
        l_hi_gt8$clock = clock;
        l_hi_eq8$clock = clock;
        l_lo_gt8$clock = clock;
        ha_open8$clock = clock;
        hb_open8$clock = clock;
        pass9$clock = clock;
        backward9$clock = clock;
        back_facing9$clock = clock;
        outside9$clock = clock;
        near9$clock = clock;
        c_passed$clock = clock;
        c_backward$clock = clock;
        c_back_facing$clock = clock;
        c_outside$clock = clock;
        c_near$clock = clock;
        used$d = used$q;
        full$d = full$q;
        res_ptr$d = res_ptr$q;
        v1$d = v1$q;
        bank1$d = bank1$q;
        id1$d = id1$q;
        ax1$d = ax1$q;
        ay1$d = ay1$q;
        bx1$d = bx1$q;
        by1$d = by1$q;
        v2$d = v2$q;
        bank2$d = bank2$q;
        id2$d = id2$q;
        ax2$d = ax2$q;
        ay2$d = ay2$q;
        bx2$d = bx2$q;
        by2$d = by2$q;
        absnx2$d = absnx2$q;
        absny2$d = absny2$q;
        negx2$d = negx2$q;
        negy2$d = negy2$q;
        normal_x2$d = normal_x2$q;
        normal_y2$d = normal_y2$q;
        normal_xa2$d = normal_xa2$q;
        normal_ya2$d = normal_ya2$q;
        v3$d = v3$q;
        bank3$d = bank3$q;
        id3$d = id3$q;
        ax3$d = ax3$q;
        ay3$d = ay3$q;
        bx3$d = bx3$q;
        by3$d = by3$q;
        absnx3$d = absnx3$q;
        absny3$d = absny3$q;
        negx3$d = negx3$q;
        negy3$d = negy3$q;
        nmax3$d = nmax3$q;
        v4$d = v4$q;
        id4$d = id4$q;
        p_aby4$d = p_aby4$q;
        p_abx4$d = p_abx4$q;
        v5$d = v5$q;
        id5$d = id5$q;
        k5$d = k5$q;
        p_nax5$d = p_nax5$q;
        p_nay5$d = p_nay5$q;
        p_nbx5$d = p_nbx5$q;
        p_nby5$d = p_nby5$q;
        v6$d = v6$q;
        id6$d = id6$q;
        k_nonpos6$d = k_nonpos6$q;
        ha6$d = ha6$q;
        hb6$d = hb6$q;
        p_fby6$d = p_fby6$q;
        p_fbx6$d = p_fbx6$q;
        p_lay6$d = p_lay6$q;
        p_lax6$d = p_lax6$q;
        clz_n6$d = clz_n6$q;
        norm_n6$d = norm_n6$q;
        v7$d = v7$q;
        id7$d = id7$q;
        side_f7$d = side_f7$q;
        side_l7$d = side_l7$q;
        clz_n7$d = clz_n7$q;
        norm_n7$d = norm_n7$q;
        backward7$d = backward7$q;
        back_facing7$d = back_facing7$q;
        ha_open7$d = ha_open7$q;
        hb_open7$d = hb_open7$q;
        v8$d = v8$q;
        id8$d = id8$q;
        s0_8$d = s0_8$q;
        s0_m1_8$d = s0_m1_8$q;
        below8$d = below8$q;
        near_a8$d = near_a8$q;
        near_b8$d = near_b8$q;
        sp3_8$d = sp3_8$q;
        clz_n2_7$d = clz_n2_7$q;
        clz_n3_7$d = clz_n3_7$q;
        backward8$d = backward8$q;
        back_facing8$d = back_facing8$q;
        f_hi_lt8$d = f_hi_lt8$q;
        f_hi_eq8$d = f_hi_eq8$q;
        f_lo_lt8$d = f_lo_lt8$q;
        l_hi_gt8$d = l_hi_gt8$q;
        l_hi_eq8$d = l_hi_eq8$q;
        l_lo_gt8$d = l_lo_gt8$q;
        ha_open8$d = ha_open8$q;
        hb_open8$d = hb_open8$q;
        pass9$d = pass9$q;
        backward9$d = backward9$q;
        back_facing9$d = back_facing9$q;
        outside9$d = outside9$q;
        near9$d = near9$q;
        c_passed$d = c_passed$q;
        c_backward$d = c_backward$q;
        c_back_facing$d = c_back_facing$q;
        c_outside$d = c_outside$q;
        c_near$d = c_near$q;
        fifo$clock = clock;
        m_nax$clock = clock;
        m_nay$clock = clock;
        m_nbx$clock = clock;
        m_nby$clock = clock;
        m_aby$clock = clock;
        m_abx$clock = clock;
        m_fby$clock = clock;
        m_fbx$clock = clock;
        m_lay$clock = clock;
        m_lax$clock = clock;
        c_ax$clock = clock;
        c_ay$clock = clock;
        c_bx$clock = clock;
        c_by$clock = clock;
        c_absnx$clock = clock;
        c_absny$clock = clock;
        c_negx$clock = clock;
        c_negy$clock = clock;
        c_k$clock = clock;
        divider$clock = clock;
        lz_n$clock = clock;
        lz_e$clock = clock;
        lane_id$clock = clock;
        lane_ax$clock = clock;
        lane_ay$clock = clock;
        lane_bx$clock = clock;
        lane_by$clock = clock;
        lane_sh$clock = clock;
        lane_wx$clock = clock;
        lane_wy$clock = clock;
        room = ~full$q;
        in_ready = room;
        take = in_valid & room;
        ext_ox = ((origin_x) & 18'h3ffff);
        ext_oy = ((origin_y) & 18'h3ffff);
        ext_ax = ((in_ax) & 18'h3ffff);
        ext_ay = ((in_ay) & 18'h3ffff);
        ext_bx = ((in_bx) & 18'h3ffff);
        ext_by = ((in_by) & 18'h3ffff);
        v1$d = take;
        bank1$d = in_bank;
        id1$d = in_id;
        ax1$d = ext_ax - ext_ox;
        ay1$d = ext_ay - ext_oy;
        bx1$d = ext_bx - ext_ox;
        by1$d = ext_by - ext_oy;
        m_aby$a = ax1$q;
        m_aby$b = by1$q;
        m_abx$a = ay1$q;
        m_abx$b = bx1$q;
        nx = by1$q - ay1$q;
        ny = ax1$q - bx1$q;
        nx_neg = ay1$q - by1$q;
        ny_neg = bx1$q - ax1$q;
        absnx = nx;
        if (nx[32'h11]) begin
            absnx = nx_neg;
        end
        absny = ny;
        if (ny[32'h11]) begin
            absny = ny_neg;
        end
        v2$d = v1$q;
        bank2$d = bank1$q;
        id2$d = id1$q;
        ax2$d = ax1$q;
        ay2$d = ay1$q;
        bx2$d = bx1$q;
        by2$d = by1$q;
        absnx2$d = absnx;
        absny2$d = absny;
        negx2$d = nx[32'h11];
        negy2$d = ny[32'h11];
        normal_bank = bank1$q;
        normal_x2$d = normal_x;
        normal_y2$d = normal_y;
        normal_xa2$d = normal_x;
        normal_ya2$d = normal_y;
        m_nax$a = normal_xa2$q;
        m_nax$b = ax2$q;
        m_nay$a = normal_ya2$q;
        m_nay$b = ay2$q;
        m_nbx$a = normal_x2$q;
        m_nbx$b = bx2$q;
        m_nby$a = normal_y2$q;
        m_nby$b = by2$q;
        nmax = absny2$q;
        if (absnx2$q > absny2$q) begin
            nmax = absnx2$q;
        end
        v3$d = v2$q;
        bank3$d = bank2$q;
        id3$d = id2$q;
        ax3$d = ax2$q;
        ay3$d = ay2$q;
        bx3$d = bx2$q;
        by3$d = by2$q;
        absnx3$d = absnx2$q;
        absny3$d = absny2$q;
        negx3$d = negx2$q;
        negy3$d = negy2$q;
        nmax3$d = nmax;
        sector_read = v3$q;
        sector_bank = bank3$q;
        m_fby$a = first_x;
        m_fby$b = by3$q;
        m_fbx$a = first_y;
        m_fbx$b = bx3$q;
        m_lay$a = last_x;
        m_lay$b = ay3$q;
        m_lax$a = last_y;
        m_lax$b = ax3$q;
        p_aby4$d = m_aby$p;
        p_abx4$d = m_abx$p;
        lz_n$value = ((nmax3$q) & 32'hffffffff);
        c_ax$d = ax3$q;
        c_ay$d = ay3$q;
        c_bx$d = bx3$q;
        c_by$d = by3$q;
        c_absnx$d = absnx3$q;
        c_absny$d = absny3$q;
        c_negx$d = negx3$q;
        c_negy$d = negy3$q;
        v4$d = v3$q;
        id4$d = id3$q;
        kk = p_aby4$q - p_abx4$q;
        p_nax5$d = m_nax$p;
        p_nay5$d = m_nay$p;
        p_nbx5$d = m_nbx$p;
        p_nby5$d = m_nby$p;
        v5$d = v4$q;
        id5$d = id4$q;
        k5$d = kk;
        k2 = k5$q << sh1;
        lz_e$value = k2;
        c_k$d = k5$q;
        ha = p_nax5$q + p_nay5$q;
        hb = p_nbx5$q + p_nby5$q;
        p_fby6$d = m_fby$p;
        p_fbx6$d = m_fbx$p;
        p_lay6$d = m_lay$p;
        p_lax6$d = m_lax$p;
        v6$d = v5$q;
        id6$d = id5$q;
        k_nonpos6$d = k5$q[32'h1f] | (k5$q == zero32);
        ha6$d = ha;
        hb6$d = hb;
        clz_n6$d = lz_n$clz;
        norm_n6$d = lz_n$norm;
        ha_pos = ~ha6$q[32'h1f] & (ha6$q != zero32);
        hb_pos = ~hb6$q[32'h1f] & (hb6$q != zero32);
        is_backward = ~ha_pos & ~hb_pos;
        is_back_facing = ~is_backward & k_nonpos6$q;
        side_f = p_fby6$q - p_fbx6$q;
        side_l = p_lay6$q - p_lax6$q;
        v7$d = v6$q;
        id7$d = id6$q;
        clz_n7$d = clz_n6$q;
        clz_n2_7$d = clz_n6$q + c2_6;
        clz_n3_7$d = clz_n6$q + c3_6;
        norm_n7$d = norm_n6$q;
        backward7$d = is_backward;
        back_facing7$d = is_back_facing;
        ha_open7$d = ha_pos & ~k_nonpos6$q;
        hb_open7$d = hb_pos & ~k_nonpos6$q;
        side_f7$d = side_f;
        side_l7$d = side_l;
        s0 = clz_n7$q - lz_e$clz;
        s0_m1 = clz_n7$q + ~lz_e$clz;
        n_hi = norm_n7$q[(32'he)+:(18)];
        e_hi = lz_e$norm[(32'he)+:(18)];
        e_lo_nz = lz_e$norm[(32'h0)+:(14)] != zero14;
        n_below_e = (n_hi < e_hi) | ((n_hi == e_hi) & e_lo_nz);
        side_f_x = side_f7$q ^ msb32;
        side_l_x = side_l7$q ^ msb32;
        f_hi_lt8$d = side_f_x[(32'h10)+:(16)] < thr_f_hi;
        f_hi_eq8$d = side_f_x[(32'h10)+:(16)] == thr_f_hi;
        f_lo_lt8$d = side_f_x[(32'h0)+:(16)] < thr_f_lo;
        l_hi_gt8$d = side_l_x[(32'h10)+:(16)] > thr_l_hi;
        l_hi_eq8$d = side_l_x[(32'h10)+:(16)] == thr_l_hi;
        l_lo_gt8$d = side_l_x[(32'h0)+:(16)] > thr_l_lo;
        ha_open8$d = ha_open7$q;
        hb_open8$d = hb_open7$q;
        v8$d = v7$q;
        id8$d = id7$q;
        backward8$d = backward7$q;
        back_facing8$d = back_facing7$q;
        s0_8$d = s0;
        s0_m1_8$d = s0_m1;
        below8$d = n_below_e;
        sp3_8$d = clz_n3_7$q - lz_e$clz;
        near_a8$d = clz_n3_7$q < lz_e$clz;
        near_b8$d = clz_n2_7$q < lz_e$clz;
        outside8 = (hb_open8$q & (f_hi_lt8$q | (f_hi_eq8$q & f_lo_lt8$q))) | (ha_open8$q & (l_hi_gt8$q | (l_hi_eq8$q & l_lo_gt8$q)));
        exp8 = s0_m1_8$q;
        if (below8$q) begin
            exp8 = s0_8$q;
        end
        near8 = near_b8$q;
        if (below8$q) begin
            near8 = near_a8$q;
        end
        is_near = ~backward8$q & ~back_facing8$q & ~outside8 & near8;
        is_pass = ~backward8$q & ~back_facing8$q & ~outside8 & ~is_near;
        reserve = v8$q;
        pass9$d = v8$q & is_pass;
        backward9$d = v8$q & backward8$q;
        back_facing9$d = v8$q & back_facing8$q;
        outside9$d = v8$q & outside8;
        near9$d = v8$q & is_near;
        if (pass9$q) begin
            c_passed$d = c_passed$q + one32;
        end
        if (backward9$q) begin
            c_backward$d = c_backward$q + one32;
        end
        if (back_facing9$q) begin
            c_back_facing$d = c_back_facing$q + one32;
        end
        if (outside9$q) begin
            c_outside$d = c_outside$q + one32;
        end
        if (near9$q) begin
            c_near$d = c_near$q + one32;
        end
        passed = c_passed$q;
        backward = c_backward$q;
        back_facing = c_back_facing$q;
        outside = c_outside$q;
        near = c_near$q;
        wide_x = ((c_absnx$q) & 36'hfffffffff) << sp3_8$q;
        wide_y = ((c_absny$q) & 36'hfffffffff) << sp3_8$q;
        dividend_x = wide_x[(32'h1)+:(35)];
        dividend_y = wide_y[(32'h1)+:(35)];
        if (below8$q) begin
            dividend_x = wide_x[(32'h0)+:(35)];
            dividend_y = wide_y[(32'h0)+:(35)];
        end
        divider$rx = dividend_x[(32'h3)+:(32)];
        divider$ry = dividend_y[(32'h3)+:(32)];
        divider$fx = dividend_x[(32'h0)+:(3)];
        divider$fy = dividend_y[(32'h0)+:(3)];
        divider$k = c_k$q;
        tag_p = zero3;
        if (reserve) begin
            tag_p = tag_pass;
        end
        tag_x = zero3;
        if (c_negx$q) begin
            tag_x = tag_negx;
        end
        tag_y = zero3;
        if (c_negy$q) begin
            tag_y = tag_negy;
        end
        divider$tag = tag_p | tag_x | tag_y;
        lane_id$write_address = res_ptr$q;
        lane_ax$write_address = res_ptr$q;
        lane_ay$write_address = res_ptr$q;
        lane_bx$write_address = res_ptr$q;
        lane_by$write_address = res_ptr$q;
        lane_sh$write_address = res_ptr$q;
        lane_id$write_data = id8$q;
        lane_ax$write_data = c_ax$q;
        lane_ay$write_data = c_ay$q;
        lane_bx$write_data = c_bx$q;
        lane_by$write_data = c_by$q;
        sh_pass = ((exp8) & 7'h7f);
        if (is_pass) begin
            sh_pass = ((exp8) & 7'h7f) | pass_flag;
        end
        lane_sh$write_data = sh_pass;
        lane_id$write_enable = reserve;
        lane_ax$write_enable = reserve;
        lane_ay$write_enable = reserve;
        lane_bx$write_enable = reserve;
        lane_by$write_enable = reserve;
        lane_sh$write_enable = reserve;
        res_inc = res_ptr$q + one5;
        if (reserve) begin
            res_ptr$d = res_inc;
        end
        fill = divider$tag_out[32'h0];
        lane_wx$write_address = fifo$tail_address;
        lane_wy$write_address = fifo$tail_address;
        lane_wx$write_data = divider$wx;
        lane_wy$write_data = divider$wy;
        lane_wx$write_enable = fill;
        lane_wy$write_enable = fill;
        fifo$push = fill;
        pop = fifo$valid & out_ready;
        fifo$pop = pop;
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
        lane_sh$head_address = fifo$head_address;
        lane_sh$next_address = fifo$next_address;
        lane_sh$pop = pop;
        lane_wx$head_address = fifo$head_address;
        lane_wx$next_address = fifo$next_address;
        lane_wx$pop = pop;
        lane_wy$head_address = fifo$head_address;
        lane_wy$next_address = fifo$next_address;
        lane_wy$pop = pop;
        out_valid = fifo$valid;
        out_id = lane_id$read_data;
        out_ax = lane_ax$read_data;
        out_ay = lane_ay$read_data;
        out_bx = lane_bx$read_data;
        out_by = lane_by$read_data;
        out_sh = ((lane_sh$read_data) & 6'h3f);
        out_pass = lane_sh$read_data[32'h6];
        out_wx = lane_wx$read_data;
        out_wy = lane_wy$read_data;
        used_inc = used$q + one6;
        used_dec = used$q - one6;
        used_next = used$q;
        if (take & ~pop) begin
            used_next = used_inc;
        end
        if (~take & pop) begin
            used_next = used_dec;
        end
        used$d = used_next;
        full$d = full$q;
        if (take & ~pop) begin
            full$d = used$q == depth_m1_6;
        end
        if (~take & pop) begin
            full$d = 1'b0;
        end
    end
    
endmodule // screener


module screener$absnx2(d,q,clock);
    
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
          
endmodule // screener$absnx2


module screener$absnx3(d,q,clock);
    
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
          
endmodule // screener$absnx3


module screener$absny2(d,q,clock);
    
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
          
endmodule // screener$absny2


module screener$absny3(d,q,clock);
    
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
          
endmodule // screener$absny3


module screener$ax1(d,q,clock);
    
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
          
endmodule // screener$ax1


module screener$ax2(d,q,clock);
    
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
          
endmodule // screener$ax2


module screener$ax3(d,q,clock);
    
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
          
endmodule // screener$ax3


module screener$ay1(d,q,clock);
    
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
          
endmodule // screener$ay1


module screener$ay2(d,q,clock);
    
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
          
endmodule // screener$ay2


module screener$ay3(d,q,clock);
    
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
          
endmodule // screener$ay3


module screener$back_facing7(d,q,clock);
    
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
          
endmodule // screener$back_facing7


module screener$back_facing8(d,q,clock);
    
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
          
endmodule // screener$back_facing8


module screener$back_facing9(d,q,clock);
    
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
          
endmodule // screener$back_facing9


module screener$backward7(d,q,clock);
    
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
          
endmodule // screener$backward7


module screener$backward8(d,q,clock);
    
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
          
endmodule // screener$backward8


module screener$backward9(d,q,clock);
    
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
          
endmodule // screener$backward9


module screener$bank1(d,q,clock);
    
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
          
endmodule // screener$bank1


module screener$bank2(d,q,clock);
    
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
          
endmodule // screener$bank2


module screener$bank3(d,q,clock);
    
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
          
endmodule // screener$bank3


module screener$below8(d,q,clock);
    
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
          
endmodule // screener$below8


module screener$bx1(d,q,clock);
    
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
          
endmodule // screener$bx1


module screener$bx2(d,q,clock);
    
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
          
endmodule // screener$bx2


module screener$bx3(d,q,clock);
    
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
          
endmodule // screener$bx3


module screener$by1(d,q,clock);
    
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
          
endmodule // screener$by1


module screener$by2(d,q,clock);
    
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
          
endmodule // screener$by2


module screener$by3(d,q,clock);
    
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
          
endmodule // screener$by3


module screener$c_absnx(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] d;
    output reg  [17:0] q;
    
    // Update code (custom)
    reg [17:0] s1;
    reg [17:0] s2;
    reg [17:0] s3;
    reg [17:0] s4;
    initial begin
       s1 = 18'd0;
       s2 = 18'd0;
       s3 = 18'd0;
       s4 = 18'd0;
       q = 18'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_absnx


module screener$c_absny(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] d;
    output reg  [17:0] q;
    
    // Update code (custom)
    reg [17:0] s1;
    reg [17:0] s2;
    reg [17:0] s3;
    reg [17:0] s4;
    initial begin
       s1 = 18'd0;
       s2 = 18'd0;
       s3 = 18'd0;
       s4 = 18'd0;
       q = 18'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_absny


module screener$c_ax(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] d;
    output reg  [17:0] q;
    
    // Update code (custom)
    reg [17:0] s1;
    reg [17:0] s2;
    reg [17:0] s3;
    reg [17:0] s4;
    initial begin
       s1 = 18'd0;
       s2 = 18'd0;
       s3 = 18'd0;
       s4 = 18'd0;
       q = 18'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_ax


module screener$c_ay(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] d;
    output reg  [17:0] q;
    
    // Update code (custom)
    reg [17:0] s1;
    reg [17:0] s2;
    reg [17:0] s3;
    reg [17:0] s4;
    initial begin
       s1 = 18'd0;
       s2 = 18'd0;
       s3 = 18'd0;
       s4 = 18'd0;
       q = 18'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_ay


module screener$c_back_facing(d,q,clock);
    
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
          
endmodule // screener$c_back_facing


module screener$c_backward(d,q,clock);
    
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
          
endmodule // screener$c_backward


module screener$c_bx(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] d;
    output reg  [17:0] q;
    
    // Update code (custom)
    reg [17:0] s1;
    reg [17:0] s2;
    reg [17:0] s3;
    reg [17:0] s4;
    initial begin
       s1 = 18'd0;
       s2 = 18'd0;
       s3 = 18'd0;
       s4 = 18'd0;
       q = 18'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_bx


module screener$c_by(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] d;
    output reg  [17:0] q;
    
    // Update code (custom)
    reg [17:0] s1;
    reg [17:0] s2;
    reg [17:0] s3;
    reg [17:0] s4;
    initial begin
       s1 = 18'd0;
       s2 = 18'd0;
       s3 = 18'd0;
       s4 = 18'd0;
       q = 18'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_by


module screener$c_k(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] d;
    output reg  [31:0] q;
    
    // Update code (custom)
    reg [31:0] s1;
    reg [31:0] s2;
    initial begin
       s1 = 32'd0;
       s2 = 32'd0;
       q = 32'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       q <= s2;
    end
endmodule // screener$c_k


module screener$c_near(d,q,clock);
    
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
          
endmodule // screener$c_near


module screener$c_negx(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  d;
    output reg  q;
    
    // Update code (custom)
    reg s1;
    reg s2;
    reg s3;
    reg s4;
    initial begin
       s1 = 1'd0;
       s2 = 1'd0;
       s3 = 1'd0;
       s4 = 1'd0;
       q = 1'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_negx


module screener$c_negy(clock,d,q);
    
    // Module arguments
    input wire  clock;
    input wire  d;
    output reg  q;
    
    // Update code (custom)
    reg s1;
    reg s2;
    reg s3;
    reg s4;
    initial begin
       s1 = 1'd0;
       s2 = 1'd0;
       s3 = 1'd0;
       s4 = 1'd0;
       q = 1'd0;
    end
    always @(posedge clock) begin
       s1 <= d;
       s2 <= s1;
       s3 <= s2;
       s4 <= s3;
       q <= s4;
    end
endmodule // screener$c_negy


module screener$c_outside(d,q,clock);
    
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
          
endmodule // screener$c_outside


module screener$c_passed(d,q,clock);
    
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
          
endmodule // screener$c_passed


module screener$clz_n2_7(d,q,clock);
    
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
          
endmodule // screener$clz_n2_7


module screener$clz_n3_7(d,q,clock);
    
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
          
endmodule // screener$clz_n3_7


module screener$clz_n6(d,q,clock);
    
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
          
endmodule // screener$clz_n6


module screener$clz_n7(d,q,clock);
    
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
          
endmodule // screener$clz_n7


module screener$divider(clock,rx,ry,fx,fy,k,tag,qx,qy,wx,wy,tag_out);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] rx;
    input wire  [31:0] ry;
    input wire  [2:0] fx;
    input wire  [2:0] fy;
    input wire  [31:0] k;
    input wire  [2:0] tag;
    output reg  [16:0] qx;
    output reg  [16:0] qy;
    output reg  [17:0] wx;
    output reg  [17:0] wy;
    output reg  [2:0] tag_out;
    
    // Update code (custom)
    localparam N = 17;
    reg [32*(N+1)-1:0] kp;
    reg [32*(N+1)-1:0] rxp;
    reg [32*(N+1)-1:0] ryp;
    reg [3*(N+1)-1:0] fxp;
    reg [3*(N+1)-1:0] fyp;
    reg [17*(N+1)-1:0] qxp;
    reg [17*(N+1)-1:0] qyp;
    reg [3*(N+1)-1:0] tgp;
    reg [16:0] nhx;
    reg [16:0] nhy;
    initial begin
       kp = 0;
       rxp = 0;
       ryp = 0;
       fxp = 0;
       fyp = 0;
       qxp = 0;
       qyp = 0;
       tgp = 0;
       nhx = 0;
       nhy = 0;
    end
    always @(posedge clock) begin
       kp[31:0] <= k;
       rxp[31:0] <= rx;
       ryp[31:0] <= ry;
       fxp[2:0] <= fx;
       fyp[2:0] <= fy;
       qxp[16:0] <= 17'd0;
       qyp[16:0] <= 17'd0;
       tgp[2:0] <= tag;
    end
    genvar s;
    generate
       for (s = 1; s <= N; s = s + 1) begin : step
          wire [31:0] dk = kp[32*(s-1) +: 32];
          wire [31:0] ax = rxp[32*(s-1) +: 32];
          wire [31:0] ay = ryp[32*(s-1) +: 32];
          wire [2:0] bx = fxp[3*(s-1) +: 3];
          wire [2:0] by = fyp[3*(s-1) +: 3];
          wire [31:0] tx = (s == 1) ? ax : {ax[30:0], bx[2]};
          wire [31:0] ty = (s == 1) ? ay : {ay[30:0], by[2]};
          wire [32:0] dx = {1'b0, tx} - {1'b0, dk};
          wire [32:0] dy = {1'b0, ty} - {1'b0, dk};
          always @(posedge clock) begin
             kp[32*s +: 32] <= dk;
             rxp[32*s +: 32] <= dx[32] ? tx : dx[31:0];
             ryp[32*s +: 32] <= dy[32] ? ty : dy[31:0];
             fxp[3*s +: 3] <= (s == 1) ? bx : {bx[1:0], 1'b0};
             fyp[3*s +: 3] <= (s == 1) ? by : {by[1:0], 1'b0};
             qxp[17*s +: 17] <= {qxp[17*(s-1) +: 16], ~dx[32]};
             qyp[17*s +: 17] <= {qyp[17*(s-1) +: 16], ~dy[32]};
             tgp[3*s +: 3] <= tgp[3*(s-1) +: 3];
          end
       end
    endgenerate
    always @(posedge clock) begin
       nhx <= 17'd0 - qxp[17*(N-1) +: 17];
       nhy <= 17'd0 - qyp[17*(N-1) +: 17];
    end
    always @(*) begin
       qx = qxp[17*N +: 17];
       qy = qyp[17*N +: 17];
       tag_out = tgp[3*N +: 3];
       wx = !tag_out[1] ? {1'b0, qx} : qx[0] ? {1'b1, ~qx[16:1], 1'b1} : {nhx, 1'b0};
       wy = !tag_out[2] ? {1'b0, qy} : qy[0] ? {1'b1, ~qy[16:1], 1'b1} : {nhy, 1'b0};
    end
endmodule // screener$divider


module screener$f_hi_eq8(d,q,clock);
    
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
          
endmodule // screener$f_hi_eq8


module screener$f_hi_lt8(d,q,clock);
    
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
          
endmodule // screener$f_hi_lt8


module screener$f_lo_lt8(d,q,clock);
    
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
          
endmodule // screener$f_lo_lt8


module screener$fifo(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [4:0] tail_address;
    output reg  [4:0] head_address;
    output reg  [4:0] next_address;
    output reg  valid;
    output reg  [5:0] count;
    
    // Constant declarations
    localparam  one_a = 5'b1;
    localparam  one_c = 6'b1;
    localparam  zero_c = 6'b0;
    
    // Stub signals
    reg  [4:0] tail_ptr$d;
    wire  [4:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [4:0] rd_ptr$d;
    wire  [4:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [4:0] rd_inc_x$d;
    wire  [4:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [5:0] words$d;
    wire  [5:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [4:0] rd_inc;
    reg  [4:0] rd_inc2;
    
    // Sub module instances
    screener$fifo$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    screener$fifo$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    screener$fifo$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    screener$fifo$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    screener$fifo$head_valid head_valid(
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
    
endmodule // screener$fifo


module screener$fifo$head_valid(d,q,clock);
    
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
          
endmodule // screener$fifo$head_valid


module screener$fifo$rd_inc_x(d,q,clock);
    
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
          
endmodule // screener$fifo$rd_inc_x


module screener$fifo$rd_ptr(d,q,clock);
    
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
          
endmodule // screener$fifo$rd_ptr


module screener$fifo$tail_ptr(d,q,clock);
    
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
          
endmodule // screener$fifo$tail_ptr


module screener$fifo$words(d,q,clock);
    
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
          
endmodule // screener$fifo$words


module screener$full(d,q,clock);
    
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
          
endmodule // screener$full


module screener$ha6(d,q,clock);
    
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
          
endmodule // screener$ha6


module screener$ha_open7(d,q,clock);
    
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
          
endmodule // screener$ha_open7


module screener$ha_open8(d,q,clock);
    
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
          
endmodule // screener$ha_open8


module screener$hb6(d,q,clock);
    
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
          
endmodule // screener$hb6


module screener$hb_open7(d,q,clock);
    
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
          
endmodule // screener$hb_open7


module screener$hb_open8(d,q,clock);
    
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
          
endmodule // screener$hb_open8


module screener$id1(d,q,clock);
    
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
          
endmodule // screener$id1


module screener$id2(d,q,clock);
    
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
          
endmodule // screener$id2


module screener$id3(d,q,clock);
    
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
          
endmodule // screener$id3


module screener$id4(d,q,clock);
    
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
          
endmodule // screener$id4


module screener$id5(d,q,clock);
    
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
          
endmodule // screener$id5


module screener$id6(d,q,clock);
    
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
          
endmodule // screener$id6


module screener$id7(d,q,clock);
    
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
          
endmodule // screener$id7


module screener$id8(d,q,clock);
    
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
          
endmodule // screener$id8


module screener$k5(d,q,clock);
    
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
          
endmodule // screener$k5


module screener$k_nonpos6(d,q,clock);
    
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
          
endmodule // screener$k_nonpos6


module screener$l_hi_eq8(d,q,clock);
    
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
          
endmodule // screener$l_hi_eq8


module screener$l_hi_gt8(d,q,clock);
    
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
          
endmodule // screener$l_hi_gt8


module screener$l_lo_gt8(d,q,clock);
    
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
          
endmodule // screener$l_lo_gt8


module screener$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:31];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 18'd0;
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
endmodule // screener$lane_ax


module screener$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:31];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 18'd0;
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
endmodule // screener$lane_ay


module screener$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:31];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 18'd0;
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
endmodule // screener$lane_bx


module screener$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:31];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 18'd0;
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
endmodule // screener$lane_by


module screener$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [15:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [15:0] read_data;
    
    // Update code (custom)
    reg [15:0] mem [0:31];
    reg [15:0] head_r;
    reg [15:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [15:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 16'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 16'd0;
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
endmodule // screener$lane_id


module screener$lane_sh(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [6:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [6:0] read_data;
    
    // Update code (custom)
    reg [6:0] mem [0:31];
    reg [6:0] head_r;
    reg [6:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [6:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 7'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 7'd0;
       head_r = 7'd0;
       next_r = 7'd0;
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
endmodule // screener$lane_sh


module screener$lane_wx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:31];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 18'd0;
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
endmodule // screener$lane_wx


module screener$lane_wy(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [4:0] write_address;
    input wire  [17:0] write_data;
    input wire  write_enable;
    input wire  [4:0] head_address;
    input wire  [4:0] next_address;
    input wire  pop;
    output reg  [17:0] read_data;
    
    // Update code (custom)
    reg [17:0] mem [0:31];
    reg [17:0] head_r;
    reg [17:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [17:0] mem_n [0:31];
    initial for (i = 0; i <= 31; i = i + 1) mem_n[i] = 18'd0;
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
       for (i = 0; i <= 31; i = i + 1) mem[i] = 18'd0;
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
endmodule // screener$lane_wy


module screener$lz_e(clock,value,norm,clz);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] value;
    output reg  [31:0] norm;
    output reg  [5:0] clz;
    
    // Update code (custom)
    reg [31:0] half;
    reg [5:0] half_clz;
    reg [31:0] first;
    reg [5:0] first_clz;
    wire [31:0] s4 = (half[31:28] == 4'd0) ? {half[27:0], 4'd0} : half;
    wire [31:0] s2 = (s4[31:30] == 2'd0) ? {s4[29:0], 2'd0} : s4;
    wire [31:0] s1 = s2[31] ? s2 : {s2[30:0], 1'b0};
    wire [5:0] c421 = {3'd0, half[31:28] == 4'd0, s4[31:30] == 2'd0, !s2[31]};
    initial begin
       half = 32'd0;
       half_clz = 6'd24;
       norm = 32'd0;
       clz = 6'd0;
    end
    always @(*) begin
       if (value[31:16] == 16'd0) begin
          if (value[15:8] == 8'd0) begin
             first = {value[7:0], 24'd0};
             first_clz = 6'd24;
          end else begin
             first = {value[15:0], 16'd0};
             first_clz = 6'd16;
          end
       end else begin
          if (value[31:24] == 8'd0) begin
             first = {value[23:0], 8'd0};
             first_clz = 6'd8;
          end else begin
             first = value;
             first_clz = 6'd0;
          end
       end
    end
    always @(posedge clock) begin
       half <= first;
       half_clz <= first_clz;
       norm <= s1;
       clz <= half_clz | c421;
    end
endmodule // screener$lz_e


module screener$lz_n(clock,value,norm,clz);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] value;
    output reg  [31:0] norm;
    output reg  [5:0] clz;
    
    // Update code (custom)
    reg [31:0] half;
    reg [5:0] half_clz;
    reg [31:0] first;
    reg [5:0] first_clz;
    wire [31:0] s4 = (half[31:28] == 4'd0) ? {half[27:0], 4'd0} : half;
    wire [31:0] s2 = (s4[31:30] == 2'd0) ? {s4[29:0], 2'd0} : s4;
    wire [31:0] s1 = s2[31] ? s2 : {s2[30:0], 1'b0};
    wire [5:0] c421 = {3'd0, half[31:28] == 4'd0, s4[31:30] == 2'd0, !s2[31]};
    initial begin
       half = 32'd0;
       half_clz = 6'd24;
       norm = 32'd0;
       clz = 6'd0;
    end
    always @(*) begin
       if (value[31:16] == 16'd0) begin
          if (value[15:8] == 8'd0) begin
             first = {value[7:0], 24'd0};
             first_clz = 6'd24;
          end else begin
             first = {value[15:0], 16'd0};
             first_clz = 6'd16;
          end
       end else begin
          if (value[31:24] == 8'd0) begin
             first = {value[23:0], 8'd0};
             first_clz = 6'd8;
          end else begin
             first = value;
             first_clz = 6'd0;
          end
       end
    end
    always @(posedge clock) begin
       half <= first;
       half_clz <= first_clz;
       norm <= s1;
       clz <= half_clz | c421;
    end
endmodule // screener$lz_n


module screener$m_abx(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_abx


module screener$m_aby(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_aby


module screener$m_fbx(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_fbx


module screener$m_fby(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_fby


module screener$m_lax(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_lax


module screener$m_lay(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_lay


module screener$m_nax(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_nax


module screener$m_nay(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_nay


module screener$m_nbx(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_nbx


module screener$m_nby(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef SHELLING_ECP5
    wire [35:0] p_w;
    MULT18X18D #(.REG_INPUTA_CLK("CLK0"), .REG_INPUTB_CLK("CLK0"), .REG_OUTPUT_CLK("CLK0"), .GSR("DISABLED"), .RESETMODE("SYNC")) dsp (
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0), .SIGNEDA(1'b1), .SIGNEDB(1'b1), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .A0(a[0]), .B0(b[0]), .C0(1'b0),
       .A1(a[1]), .B1(b[1]), .C1(1'b0),
       .A2(a[2]), .B2(b[2]), .C2(1'b0),
       .A3(a[3]), .B3(b[3]), .C3(1'b0),
       .A4(a[4]), .B4(b[4]), .C4(1'b0),
       .A5(a[5]), .B5(b[5]), .C5(1'b0),
       .A6(a[6]), .B6(b[6]), .C6(1'b0),
       .A7(a[7]), .B7(b[7]), .C7(1'b0),
       .A8(a[8]), .B8(b[8]), .C8(1'b0),
       .A9(a[9]), .B9(b[9]), .C9(1'b0),
       .A10(a[10]), .B10(b[10]), .C10(1'b0),
       .A11(a[11]), .B11(b[11]), .C11(1'b0),
       .A12(a[12]), .B12(b[12]), .C12(1'b0),
       .A13(a[13]), .B13(b[13]), .C13(1'b0),
       .A14(a[14]), .B14(b[14]), .C14(1'b0),
       .A15(a[15]), .B15(b[15]), .C15(1'b0),
       .A16(a[16]), .B16(b[16]), .C16(1'b0),
       .A17(a[17]), .B17(b[17]), .C17(1'b0),
       .P0(p_w[0]),
       .P1(p_w[1]),
       .P2(p_w[2]),
       .P3(p_w[3]),
       .P4(p_w[4]),
       .P5(p_w[5]),
       .P6(p_w[6]),
       .P7(p_w[7]),
       .P8(p_w[8]),
       .P9(p_w[9]),
       .P10(p_w[10]),
       .P11(p_w[11]),
       .P12(p_w[12]),
       .P13(p_w[13]),
       .P14(p_w[14]),
       .P15(p_w[15]),
       .P16(p_w[16]),
       .P17(p_w[17]),
       .P18(p_w[18]),
       .P19(p_w[19]),
       .P20(p_w[20]),
       .P21(p_w[21]),
       .P22(p_w[22]),
       .P23(p_w[23]),
       .P24(p_w[24]),
       .P25(p_w[25]),
       .P26(p_w[26]),
       .P27(p_w[27]),
       .P28(p_w[28]),
       .P29(p_w[29]),
       .P30(p_w[30]),
       .P31(p_w[31]),
       .P32(p_w[32]),
       .P33(p_w[33]),
       .P34(p_w[34]),
       .P35(p_w[35])
    );
    always @(*) begin
       p = p_w[35:4];
    end
    `else
    reg signed [17:0] a_r;
    reg signed [17:0] b_r;
    wire signed [35:0] prod;
    initial begin
       a_r = 18'sd0;
       b_r = 18'sd0;
       p = 32'd0;
    end
    assign prod = a_r * b_r;
    always @(posedge clock) begin
       a_r <= a;
       b_r <= b;
       p <= prod[35:4];
    end
    `endif
endmodule // screener$m_nby


module screener$near9(d,q,clock);
    
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
          
endmodule // screener$near9


module screener$near_a8(d,q,clock);
    
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
          
endmodule // screener$near_a8


module screener$near_b8(d,q,clock);
    
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
          
endmodule // screener$near_b8


module screener$negx2(d,q,clock);
    
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
          
endmodule // screener$negx2


module screener$negx3(d,q,clock);
    
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
          
endmodule // screener$negx3


module screener$negy2(d,q,clock);
    
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
          
endmodule // screener$negy2


module screener$negy3(d,q,clock);
    
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
          
endmodule // screener$negy3


module screener$nmax3(d,q,clock);
    
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
          
endmodule // screener$nmax3


module screener$norm_n6(d,q,clock);
    
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
          
endmodule // screener$norm_n6


module screener$norm_n7(d,q,clock);
    
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
          
endmodule // screener$norm_n7


module screener$normal_x2(d,q,clock);
    
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
          
endmodule // screener$normal_x2


module screener$normal_xa2(d,q,clock);
    
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
          
endmodule // screener$normal_xa2


module screener$normal_y2(d,q,clock);
    
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
          
endmodule // screener$normal_y2


module screener$normal_ya2(d,q,clock);
    
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
          
endmodule // screener$normal_ya2


module screener$outside9(d,q,clock);
    
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
          
endmodule // screener$outside9


module screener$p_abx4(d,q,clock);
    
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
          
endmodule // screener$p_abx4


module screener$p_aby4(d,q,clock);
    
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
          
endmodule // screener$p_aby4


module screener$p_fbx6(d,q,clock);
    
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
          
endmodule // screener$p_fbx6


module screener$p_fby6(d,q,clock);
    
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
          
endmodule // screener$p_fby6


module screener$p_lax6(d,q,clock);
    
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
          
endmodule // screener$p_lax6


module screener$p_lay6(d,q,clock);
    
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
          
endmodule // screener$p_lay6


module screener$p_nax5(d,q,clock);
    
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
          
endmodule // screener$p_nax5


module screener$p_nay5(d,q,clock);
    
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
          
endmodule // screener$p_nay5


module screener$p_nbx5(d,q,clock);
    
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
          
endmodule // screener$p_nbx5


module screener$p_nby5(d,q,clock);
    
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
          
endmodule // screener$p_nby5


module screener$pass9(d,q,clock);
    
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
          
endmodule // screener$pass9


module screener$res_ptr(d,q,clock);
    
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
          
endmodule // screener$res_ptr


module screener$s0_8(d,q,clock);
    
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
          
endmodule // screener$s0_8


module screener$s0_m1_8(d,q,clock);
    
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
          
endmodule // screener$s0_m1_8


module screener$side_f7(d,q,clock);
    
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
          
endmodule // screener$side_f7


module screener$side_l7(d,q,clock);
    
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
          
endmodule // screener$side_l7


module screener$sp3_8(d,q,clock);
    
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
          
endmodule // screener$sp3_8


module screener$used(d,q,clock);
    
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
          
endmodule // screener$used


module screener$v1(d,q,clock);
    
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
          
endmodule // screener$v1


module screener$v2(d,q,clock);
    
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
          
endmodule // screener$v2


module screener$v3(d,q,clock);
    
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
          
endmodule // screener$v3


module screener$v4(d,q,clock);
    
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
          
endmodule // screener$v4


module screener$v5(d,q,clock);
    
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
          
endmodule // screener$v5


module screener$v6(d,q,clock);
    
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
          
endmodule // screener$v6


module screener$v7(d,q,clock);
    
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
          
endmodule // screener$v7


module screener$v8(d,q,clock);
    
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
          
endmodule // screener$v8
