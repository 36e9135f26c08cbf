// patch_cache: exported from rust-hdl by `shelling export-verilog`; do not edit.


module patch_cache(clock,cfg_enable,cfg_mask,flush,flushing,req,addr,resp_valid,resp_ax,resp_ay,resp_bx,resp_by,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,hits,misses);
    
    // Module arguments
    input wire  clock;
    input wire  cfg_enable;
    input wire  [9:0] cfg_mask;
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
    localparam  miss_flag = 27'h4000000;
    localparam  one5 = 5'b1;
    localparam  one32 = 32'h1;
    localparam  one_line = 10'b1;
    localparam  one3 = 3'b1;
    localparam  misses3 = 3'b100;
    localparam  almost3 = 3'b11;
    localparam  one2 = 2'b1;
    localparam  slot0 = 2'b0;
    localparam  slot1 = 2'b1;
    localparam  slot2 = 2'b10;
    localparam  slot3 = 2'b11;
    localparam  last_line = 10'b1111111111;
    localparam  zero_line = 10'b0;
    localparam  zero17 = 17'b0;
    
    // Stub signals
    reg  q_lane$clock;
    reg  [3:0] q_lane$read_address;
    wire  [15:0] q_lane$read_data;
    reg  [3:0] q_lane$write_address;
    reg  [15:0] q_lane$write_data;
    reg  q_lane$write_enable;
    reg  [4:0] wr_ptr$d;
    wire  [4:0] wr_ptr$q;
    reg  wr_ptr$clock;
    reg  [4:0] rd_ptr$d;
    wire  [4:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [4:0] sp$d;
    wire  [4:0] sp$q;
    reg  sp$clock;
    reg  [4:0] rd_inc_x$d;
    wire  [4:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [4:0] sp_inc_x$d;
    wire  [4:0] sp_inc_x$q;
    reg  sp_inc_x$clock;
    reg  q_valid$d;
    wire  q_valid$q;
    reg  q_valid$clock;
    reg  v1$d;
    wire  v1$q;
    reg  v1$clock;
    reg  [15:0] id1$d;
    wire  [15:0] id1$q;
    reg  id1$clock;
    reg  [16:0] key1$d;
    wire  [16:0] key1$q;
    reg  key1$clock;
    reg  [9:0] line1$d;
    wire  [9:0] line1$q;
    reg  line1$clock;
    reg  v2$d;
    wire  v2$q;
    reg  v2$clock;
    reg  [15:0] id2$d;
    wire  [15:0] id2$q;
    reg  id2$clock;
    reg  [16:0] key2$d;
    wire  [16:0] key2$q;
    reg  key2$clock;
    reg  [9:0] line2$d;
    wire  [9:0] line2$q;
    reg  line2$clock;
    reg  v3$d;
    wire  v3$q;
    reg  v3$clock;
    reg  [15:0] id3$d;
    wire  [15:0] id3$q;
    reg  id3$clock;
    reg  [9:0] line3$d;
    wire  [9:0] line3$q;
    reg  line3$clock;
    reg  match3$d;
    wire  match3$q;
    reg  match3$clock;
    reg  lconf3$d;
    wire  lconf3$q;
    reg  lconf3$clock;
    reg  iconf3$d;
    wire  iconf3$q;
    reg  iconf3$clock;
    reg  [16:0] ax3$d;
    wire  [16:0] ax3$q;
    reg  ax3$clock;
    reg  [16:0] ay3$d;
    wire  [16:0] ay3$q;
    reg  ay3$clock;
    reg  [16:0] bx3$d;
    wire  [16:0] bx3$q;
    reg  bx3$clock;
    reg  [16:0] by3$d;
    wire  [16:0] by3$q;
    reg  by3$clock;
    reg  [15:0] t_id0$d;
    wire  [15:0] t_id0$q;
    reg  t_id0$clock;
    reg  [15:0] t_id1$d;
    wire  [15:0] t_id1$q;
    reg  t_id1$clock;
    reg  [15:0] t_id2$d;
    wire  [15:0] t_id2$q;
    reg  t_id2$clock;
    reg  [15:0] t_id3$d;
    wire  [15:0] t_id3$q;
    reg  t_id3$clock;
    reg  [9:0] t_line0$d;
    wire  [9:0] t_line0$q;
    reg  t_line0$clock;
    reg  [9:0] t_line1$d;
    wire  [9:0] t_line1$q;
    reg  t_line1$clock;
    reg  [9:0] t_line2$d;
    wire  [9:0] t_line2$q;
    reg  t_line2$clock;
    reg  [9:0] t_line3$d;
    wire  [9:0] t_line3$q;
    reg  t_line3$clock;
    reg  t_v0$d;
    wire  t_v0$q;
    reg  t_v0$clock;
    reg  t_v1$d;
    wire  t_v1$q;
    reg  t_v1$clock;
    reg  t_v2$d;
    wire  t_v2$q;
    reg  t_v2$clock;
    reg  t_v3$d;
    wire  t_v3$q;
    reg  t_v3$clock;
    reg  t_any$d;
    wire  t_any$q;
    reg  t_any$clock;
    reg  [2:0] t_n$d;
    wire  [2:0] t_n$q;
    reg  t_n$clock;
    reg  t_full$d;
    wire  t_full$q;
    reg  t_full$clock;
    reg  [1:0] t_wp$d;
    wire  [1:0] t_wp$q;
    reg  t_wp$clock;
    reg  [1:0] t_rp$d;
    wire  [1:0] t_rp$q;
    reg  t_rp$clock;
    reg  [15:0] f_id1$d;
    wire  [15:0] f_id1$q;
    reg  f_id1$clock;
    reg  [9:0] f_line1$d;
    wire  [9:0] f_line1$q;
    reg  f_line1$clock;
    reg  f_v1$d;
    wire  f_v1$q;
    reg  f_v1$clock;
    reg  mi0$d;
    wire  mi0$q;
    reg  mi0$clock;
    reg  mi1$d;
    wire  mi1$q;
    reg  mi1$clock;
    reg  mi2$d;
    wire  mi2$q;
    reg  mi2$clock;
    reg  mi3$d;
    wire  mi3$q;
    reg  mi3$clock;
    reg  mif$d;
    wire  mif$q;
    reg  mif$clock;
    reg  mis3$d;
    wire  mis3$q;
    reg  mis3$clock;
    reg  mis2$d;
    wire  mis2$q;
    reg  mis2$clock;
    reg  ml0$d;
    wire  ml0$q;
    reg  ml0$clock;
    reg  ml1$d;
    wire  ml1$q;
    reg  ml1$clock;
    reg  ml2$d;
    wire  ml2$q;
    reg  ml2$clock;
    reg  ml3$d;
    wire  ml3$q;
    reg  ml3$clock;
    reg  mlf$d;
    wire  mlf$q;
    reg  mlf$clock;
    reg  mls3$d;
    wire  mls3$q;
    reg  mls3$clock;
    reg  mls2$d;
    wire  mls2$q;
    reg  mls2$clock;
    reg  ans$clock;
    reg  ans$push;
    reg  ans$pop;
    wire  [3:0] ans$tail_address;
    wire  [3:0] ans$head_address;
    wire  [3:0] ans$next_address;
    wire  ans$valid;
    wire  [4:0] ans$count;
    reg  ans_ax$clock;
    reg  [3:0] ans_ax$write_address;
    reg  [16:0] ans_ax$write_data;
    reg  ans_ax$write_enable;
    reg  [3:0] ans_ax$head_address;
    reg  [3:0] ans_ax$next_address;
    reg  ans_ax$pop;
    wire  [16:0] ans_ax$read_data;
    reg  ans_ay$clock;
    reg  [3:0] ans_ay$write_address;
    reg  [16:0] ans_ay$write_data;
    reg  ans_ay$write_enable;
    reg  [3:0] ans_ay$head_address;
    reg  [3:0] ans_ay$next_address;
    reg  ans_ay$pop;
    wire  [16:0] ans_ay$read_data;
    reg  ans_bx$clock;
    reg  [3:0] ans_bx$write_address;
    reg  [16:0] ans_bx$write_data;
    reg  ans_bx$write_enable;
    reg  [3:0] ans_bx$head_address;
    reg  [3:0] ans_bx$next_address;
    reg  ans_bx$pop;
    wire  [16:0] ans_bx$read_data;
    reg  ans_by$clock;
    reg  [3:0] ans_by$write_address;
    reg  [16:0] ans_by$write_data;
    reg  ans_by$write_enable;
    reg  [3:0] ans_by$head_address;
    reg  [3:0] ans_by$next_address;
    reg  ans_by$pop;
    wire  [16:0] ans_by$read_data;
    reg  ans_meta$clock;
    reg  [3:0] ans_meta$write_address;
    reg  [26:0] ans_meta$write_data;
    reg  ans_meta$write_enable;
    reg  [3:0] ans_meta$head_address;
    reg  [3:0] ans_meta$next_address;
    reg  ans_meta$pop;
    wire  [26:0] ans_meta$read_data;
    reg  ret$clock;
    reg  ret$push;
    reg  ret$pop;
    wire  [1:0] ret$tail_address;
    wire  [1:0] ret$head_address;
    wire  [1:0] ret$next_address;
    wire  ret$valid;
    wire  [2:0] ret$count;
    reg  ret_ax$clock;
    reg  [1:0] ret_ax$write_address;
    reg  [16:0] ret_ax$write_data;
    reg  ret_ax$write_enable;
    reg  [1:0] ret_ax$head_address;
    reg  [1:0] ret_ax$next_address;
    reg  ret_ax$pop;
    wire  [16:0] ret_ax$read_data;
    reg  ret_ay$clock;
    reg  [1:0] ret_ay$write_address;
    reg  [16:0] ret_ay$write_data;
    reg  ret_ay$write_enable;
    reg  [1:0] ret_ay$head_address;
    reg  [1:0] ret_ay$next_address;
    reg  ret_ay$pop;
    wire  [16:0] ret_ay$read_data;
    reg  ret_bx$clock;
    reg  [1:0] ret_bx$write_address;
    reg  [16:0] ret_bx$write_data;
    reg  ret_bx$write_enable;
    reg  [1:0] ret_bx$head_address;
    reg  [1:0] ret_bx$next_address;
    reg  ret_bx$pop;
    wire  [16:0] ret_bx$read_data;
    reg  ret_by$clock;
    reg  [1:0] ret_by$write_address;
    reg  [16:0] ret_by$write_data;
    reg  ret_by$write_enable;
    reg  [1:0] ret_by$head_address;
    reg  [1:0] ret_by$next_address;
    reg  ret_by$pop;
    wire  [16:0] ret_by$read_data;
    reg  fl_on$d;
    wire  fl_on$q;
    reg  fl_on$clock;
    reg  [9:0] fl_line$d;
    wire  [9:0] fl_line$q;
    reg  fl_line$clock;
    reg  mreq$d;
    wire  mreq$q;
    reg  mreq$clock;
    reg  [15:0] maddr$d;
    wire  [15:0] maddr$q;
    reg  maddr$clock;
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
    reg  hit_r$d;
    wire  hit_r$q;
    reg  hit_r$clock;
    reg  tag$clock;
    reg  [9:0] tag$read_address;
    wire  [16:0] tag$read_data;
    reg  [9:0] tag$write_address;
    reg  [16:0] tag$write_data;
    reg  tag$write_enable;
    reg  lane_ax$clock;
    reg  [9:0] lane_ax$read_address;
    wire  [16:0] lane_ax$read_data;
    reg  [9:0] lane_ax$write_address;
    reg  [16:0] lane_ax$write_data;
    reg  lane_ax$write_enable;
    reg  lane_ay$clock;
    reg  [9:0] lane_ay$read_address;
    wire  [16:0] lane_ay$read_data;
    reg  [9:0] lane_ay$write_address;
    reg  [16:0] lane_ay$write_data;
    reg  lane_ay$write_enable;
    reg  lane_bx$clock;
    reg  [9:0] lane_bx$read_address;
    wire  [16:0] lane_bx$read_data;
    reg  [9:0] lane_bx$write_address;
    reg  [16:0] lane_bx$write_data;
    reg  lane_bx$write_enable;
    reg  lane_by$clock;
    reg  [9:0] lane_by$read_address;
    wire  [16:0] lane_by$read_data;
    reg  [9:0] lane_by$write_address;
    reg  [16:0] lane_by$write_data;
    reg  lane_by$write_enable;
    reg  ret_full$d;
    wire  ret_full$q;
    reg  ret_full$clock;
    
    // Local signals
    reg  push;
    reg  issue;
    reg  table_full;
    reg  ret_push;
    reg  waiting_any;
    reg  tv0_next;
    reg  tv1_next;
    reg  tv2_next;
    reg  tv3_next;
    reg  rewind;
    reg  accept;
    reg  tag_hit;
    reg  hit;
    reg  miss;
    reg  line_conflict;
    reg  id_conflict;
    reg  miss3;
    reg  [15:0] head_id_fill;
    reg  head_miss;
    reg  answer;
    reg  fill;
    reg  [26:0] meta_in;
    reg  [16:0] head_key_fill;
    reg  [9:0] head_line_fill;
    reg  [4:0] wr_inc;
    reg  [4:0] rd_inc;
    reg  [4:0] rd_next;
    reg  [4:0] rd_inc2;
    reg  [4:0] rd_next_inc;
    reg  [4:0] sp_inc;
    reg  [4:0] sp_inc2;
    reg  [4:0] read_ptr;
    reg  [4:0] read_inc;
    reg  ne_sp;
    reg  ne_sp_inc;
    reg  ne_rd;
    reg  read_new;
    reg  [9:0] head_low;
    reg  [9:0] head_line;
    reg  [16:0] head_key;
    reg  [31:0] hit_inc;
    reg  [31:0] miss_inc;
    reg  [9:0] fl_inc;
    reg  [1:0] t_wp_inc;
    reg  [1:0] t_rp_inc;
    
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
    patch_cache$sp sp(
        .d(sp$d),
        .q(sp$q),
        .clock(sp$clock)
    );
    patch_cache$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    patch_cache$sp_inc_x sp_inc_x(
        .d(sp_inc_x$d),
        .q(sp_inc_x$q),
        .clock(sp_inc_x$clock)
    );
    patch_cache$q_valid q_valid(
        .d(q_valid$d),
        .q(q_valid$q),
        .clock(q_valid$clock)
    );
    patch_cache$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    patch_cache$id1 id1(
        .d(id1$d),
        .q(id1$q),
        .clock(id1$clock)
    );
    patch_cache$key1 key1(
        .d(key1$d),
        .q(key1$q),
        .clock(key1$clock)
    );
    patch_cache$line1 line1(
        .d(line1$d),
        .q(line1$q),
        .clock(line1$clock)
    );
    patch_cache$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    patch_cache$id2 id2(
        .d(id2$d),
        .q(id2$q),
        .clock(id2$clock)
    );
    patch_cache$key2 key2(
        .d(key2$d),
        .q(key2$q),
        .clock(key2$clock)
    );
    patch_cache$line2 line2(
        .d(line2$d),
        .q(line2$q),
        .clock(line2$clock)
    );
    patch_cache$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    patch_cache$id3 id3(
        .d(id3$d),
        .q(id3$q),
        .clock(id3$clock)
    );
    patch_cache$line3 line3(
        .d(line3$d),
        .q(line3$q),
        .clock(line3$clock)
    );
    patch_cache$match3 match3(
        .d(match3$d),
        .q(match3$q),
        .clock(match3$clock)
    );
    patch_cache$lconf3 lconf3(
        .d(lconf3$d),
        .q(lconf3$q),
        .clock(lconf3$clock)
    );
    patch_cache$iconf3 iconf3(
        .d(iconf3$d),
        .q(iconf3$q),
        .clock(iconf3$clock)
    );
    patch_cache$ax3 ax3(
        .d(ax3$d),
        .q(ax3$q),
        .clock(ax3$clock)
    );
    patch_cache$ay3 ay3(
        .d(ay3$d),
        .q(ay3$q),
        .clock(ay3$clock)
    );
    patch_cache$bx3 bx3(
        .d(bx3$d),
        .q(bx3$q),
        .clock(bx3$clock)
    );
    patch_cache$by3 by3(
        .d(by3$d),
        .q(by3$q),
        .clock(by3$clock)
    );
    patch_cache$t_id0 t_id0(
        .d(t_id0$d),
        .q(t_id0$q),
        .clock(t_id0$clock)
    );
    patch_cache$t_id1 t_id1(
        .d(t_id1$d),
        .q(t_id1$q),
        .clock(t_id1$clock)
    );
    patch_cache$t_id2 t_id2(
        .d(t_id2$d),
        .q(t_id2$q),
        .clock(t_id2$clock)
    );
    patch_cache$t_id3 t_id3(
        .d(t_id3$d),
        .q(t_id3$q),
        .clock(t_id3$clock)
    );
    patch_cache$t_line0 t_line0(
        .d(t_line0$d),
        .q(t_line0$q),
        .clock(t_line0$clock)
    );
    patch_cache$t_line1 t_line1(
        .d(t_line1$d),
        .q(t_line1$q),
        .clock(t_line1$clock)
    );
    patch_cache$t_line2 t_line2(
        .d(t_line2$d),
        .q(t_line2$q),
        .clock(t_line2$clock)
    );
    patch_cache$t_line3 t_line3(
        .d(t_line3$d),
        .q(t_line3$q),
        .clock(t_line3$clock)
    );
    patch_cache$t_v0 t_v0(
        .d(t_v0$d),
        .q(t_v0$q),
        .clock(t_v0$clock)
    );
    patch_cache$t_v1 t_v1(
        .d(t_v1$d),
        .q(t_v1$q),
        .clock(t_v1$clock)
    );
    patch_cache$t_v2 t_v2(
        .d(t_v2$d),
        .q(t_v2$q),
        .clock(t_v2$clock)
    );
    patch_cache$t_v3 t_v3(
        .d(t_v3$d),
        .q(t_v3$q),
        .clock(t_v3$clock)
    );
    patch_cache$t_any t_any(
        .d(t_any$d),
        .q(t_any$q),
        .clock(t_any$clock)
    );
    patch_cache$t_n t_n(
        .d(t_n$d),
        .q(t_n$q),
        .clock(t_n$clock)
    );
    patch_cache$t_full t_full(
        .d(t_full$d),
        .q(t_full$q),
        .clock(t_full$clock)
    );
    patch_cache$t_wp t_wp(
        .d(t_wp$d),
        .q(t_wp$q),
        .clock(t_wp$clock)
    );
    patch_cache$t_rp t_rp(
        .d(t_rp$d),
        .q(t_rp$q),
        .clock(t_rp$clock)
    );
    patch_cache$f_id1 f_id1(
        .d(f_id1$d),
        .q(f_id1$q),
        .clock(f_id1$clock)
    );
    patch_cache$f_line1 f_line1(
        .d(f_line1$d),
        .q(f_line1$q),
        .clock(f_line1$clock)
    );
    patch_cache$f_v1 f_v1(
        .d(f_v1$d),
        .q(f_v1$q),
        .clock(f_v1$clock)
    );
    patch_cache$mi0 mi0(
        .d(mi0$d),
        .q(mi0$q),
        .clock(mi0$clock)
    );
    patch_cache$mi1 mi1(
        .d(mi1$d),
        .q(mi1$q),
        .clock(mi1$clock)
    );
    patch_cache$mi2 mi2(
        .d(mi2$d),
        .q(mi2$q),
        .clock(mi2$clock)
    );
    patch_cache$mi3 mi3(
        .d(mi3$d),
        .q(mi3$q),
        .clock(mi3$clock)
    );
    patch_cache$mif mif(
        .d(mif$d),
        .q(mif$q),
        .clock(mif$clock)
    );
    patch_cache$mis3 mis3(
        .d(mis3$d),
        .q(mis3$q),
        .clock(mis3$clock)
    );
    patch_cache$mis2 mis2(
        .d(mis2$d),
        .q(mis2$q),
        .clock(mis2$clock)
    );
    patch_cache$ml0 ml0(
        .d(ml0$d),
        .q(ml0$q),
        .clock(ml0$clock)
    );
    patch_cache$ml1 ml1(
        .d(ml1$d),
        .q(ml1$q),
        .clock(ml1$clock)
    );
    patch_cache$ml2 ml2(
        .d(ml2$d),
        .q(ml2$q),
        .clock(ml2$clock)
    );
    patch_cache$ml3 ml3(
        .d(ml3$d),
        .q(ml3$q),
        .clock(ml3$clock)
    );
    patch_cache$mlf mlf(
        .d(mlf$d),
        .q(mlf$q),
        .clock(mlf$clock)
    );
    patch_cache$mls3 mls3(
        .d(mls3$d),
        .q(mls3$q),
        .clock(mls3$clock)
    );
    patch_cache$mls2 mls2(
        .d(mls2$d),
        .q(mls2$q),
        .clock(mls2$clock)
    );
    patch_cache$ans ans(
        .clock(ans$clock),
        .push(ans$push),
        .pop(ans$pop),
        .tail_address(ans$tail_address),
        .head_address(ans$head_address),
        .next_address(ans$next_address),
        .valid(ans$valid),
        .count(ans$count)
    );
    patch_cache$ans_ax ans_ax(
        .clock(ans_ax$clock),
        .write_address(ans_ax$write_address),
        .write_data(ans_ax$write_data),
        .write_enable(ans_ax$write_enable),
        .head_address(ans_ax$head_address),
        .next_address(ans_ax$next_address),
        .pop(ans_ax$pop),
        .read_data(ans_ax$read_data)
    );
    patch_cache$ans_ay ans_ay(
        .clock(ans_ay$clock),
        .write_address(ans_ay$write_address),
        .write_data(ans_ay$write_data),
        .write_enable(ans_ay$write_enable),
        .head_address(ans_ay$head_address),
        .next_address(ans_ay$next_address),
        .pop(ans_ay$pop),
        .read_data(ans_ay$read_data)
    );
    patch_cache$ans_bx ans_bx(
        .clock(ans_bx$clock),
        .write_address(ans_bx$write_address),
        .write_data(ans_bx$write_data),
        .write_enable(ans_bx$write_enable),
        .head_address(ans_bx$head_address),
        .next_address(ans_bx$next_address),
        .pop(ans_bx$pop),
        .read_data(ans_bx$read_data)
    );
    patch_cache$ans_by ans_by(
        .clock(ans_by$clock),
        .write_address(ans_by$write_address),
        .write_data(ans_by$write_data),
        .write_enable(ans_by$write_enable),
        .head_address(ans_by$head_address),
        .next_address(ans_by$next_address),
        .pop(ans_by$pop),
        .read_data(ans_by$read_data)
    );
    patch_cache$ans_meta ans_meta(
        .clock(ans_meta$clock),
        .write_address(ans_meta$write_address),
        .write_data(ans_meta$write_data),
        .write_enable(ans_meta$write_enable),
        .head_address(ans_meta$head_address),
        .next_address(ans_meta$next_address),
        .pop(ans_meta$pop),
        .read_data(ans_meta$read_data)
    );
    patch_cache$ret ret(
        .clock(ret$clock),
        .push(ret$push),
        .pop(ret$pop),
        .tail_address(ret$tail_address),
        .head_address(ret$head_address),
        .next_address(ret$next_address),
        .valid(ret$valid),
        .count(ret$count)
    );
    patch_cache$ret_ax ret_ax(
        .clock(ret_ax$clock),
        .write_address(ret_ax$write_address),
        .write_data(ret_ax$write_data),
        .write_enable(ret_ax$write_enable),
        .head_address(ret_ax$head_address),
        .next_address(ret_ax$next_address),
        .pop(ret_ax$pop),
        .read_data(ret_ax$read_data)
    );
    patch_cache$ret_ay ret_ay(
        .clock(ret_ay$clock),
        .write_address(ret_ay$write_address),
        .write_data(ret_ay$write_data),
        .write_enable(ret_ay$write_enable),
        .head_address(ret_ay$head_address),
        .next_address(ret_ay$next_address),
        .pop(ret_ay$pop),
        .read_data(ret_ay$read_data)
    );
    patch_cache$ret_bx ret_bx(
        .clock(ret_bx$clock),
        .write_address(ret_bx$write_address),
        .write_data(ret_bx$write_data),
        .write_enable(ret_bx$write_enable),
        .head_address(ret_bx$head_address),
        .next_address(ret_bx$next_address),
        .pop(ret_bx$pop),
        .read_data(ret_bx$read_data)
    );
    patch_cache$ret_by ret_by(
        .clock(ret_by$clock),
        .write_address(ret_by$write_address),
        .write_data(ret_by$write_data),
        .write_enable(ret_by$write_enable),
        .head_address(ret_by$head_address),
        .next_address(ret_by$next_address),
        .pop(ret_by$pop),
        .read_data(ret_by$read_data)
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
    patch_cache$maddr maddr(
        .d(maddr$d),
        .q(maddr$q),
        .clock(maddr$clock)
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
    patch_cache$hit_r hit_r(
        .d(hit_r$d),
        .q(hit_r$q),
        .clock(hit_r$clock)
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
    patch_cache$ret_full ret_full(
        .d(ret_full$d),
        .q(ret_full$q),
        .clock(ret_full$clock)
    );
    
    // Update code
    always @(*) begin
        wr_ptr$clock = clock;
        rd_ptr$clock = clock;
        sp$clock = clock;
        rd_inc_x$clock = clock;
        sp_inc_x$clock = clock;
        q_valid$clock = clock;
        v1$clock = clock;
        id1$clock = clock;
        key1$clock = clock;
        line1$clock = clock;
        v2$clock = clock;
        id2$clock = clock;
        key2$clock = clock;
        line2$clock = clock;
        v3$clock = clock;
        id3$clock = clock;
        line3$clock = clock;
        match3$clock = clock;
        lconf3$clock = clock;
        iconf3$clock = clock;
        ax3$clock = clock;
        ay3$clock = clock;
        bx3$clock = clock;
        by3$clock = clock;
        t_id0$clock = clock;
        t_id1$clock = clock;
        t_id2$clock = clock;
        t_id3$clock = clock;
        t_line0$clock = clock;
        t_line1$clock = clock;
        t_line2$clock = clock;
        t_line3$clock = clock;
        t_v0$clock = clock;
        t_v1$clock = clock;
        t_v2$clock = clock;
        t_v3$clock = clock;
        t_any$clock = clock;
        t_n$clock = clock;
        t_full$clock = clock;
        t_wp$clock = clock;
        t_rp$clock = clock;
        f_id1$clock = clock;
        f_line1$clock = clock;
        f_v1$clock = clock;
        mi0$clock = clock;
        mi1$clock = clock;
        mi2$clock = clock;
        mi3$clock = clock;
        mif$clock = clock;
        mis3$clock = clock;
        mis2$clock = clock;
        ml0$clock = clock;
        ml1$clock = clock;
        ml2$clock = clock;
        ml3$clock = clock;
        mlf$clock = clock;
        mls3$clock = clock;
        mls2$clock = clock;
        fl_on$clock = clock;
        fl_line$clock = clock;
        mreq$clock = clock;
        maddr$clock = clock;
        rv$clock = clock;
        rax$clock = clock;
        ray$clock = clock;
        rbx$clock = clock;
        rby$clock = clock;
        hit_count$clock = clock;
        miss_count$clock = clock;
        hit_r$clock = clock;
        ret_full$clock = clock;
        wr_ptr$d = wr_ptr$q;
        rd_ptr$d = rd_ptr$q;
        sp$d = sp$q;
        rd_inc_x$d = rd_inc_x$q;
        sp_inc_x$d = sp_inc_x$q;
        q_valid$d = q_valid$q;
        v1$d = v1$q;
        id1$d = id1$q;
        key1$d = key1$q;
        line1$d = line1$q;
        v2$d = v2$q;
        id2$d = id2$q;
        key2$d = key2$q;
        line2$d = line2$q;
        v3$d = v3$q;
        id3$d = id3$q;
        line3$d = line3$q;
        match3$d = match3$q;
        lconf3$d = lconf3$q;
        iconf3$d = iconf3$q;
        ax3$d = ax3$q;
        ay3$d = ay3$q;
        bx3$d = bx3$q;
        by3$d = by3$q;
        t_id0$d = t_id0$q;
        t_id1$d = t_id1$q;
        t_id2$d = t_id2$q;
        t_id3$d = t_id3$q;
        t_line0$d = t_line0$q;
        t_line1$d = t_line1$q;
        t_line2$d = t_line2$q;
        t_line3$d = t_line3$q;
        t_v0$d = t_v0$q;
        t_v1$d = t_v1$q;
        t_v2$d = t_v2$q;
        t_v3$d = t_v3$q;
        t_any$d = t_any$q;
        t_n$d = t_n$q;
        t_full$d = t_full$q;
        t_wp$d = t_wp$q;
        t_rp$d = t_rp$q;
        f_id1$d = f_id1$q;
        f_line1$d = f_line1$q;
        f_v1$d = f_v1$q;
        mi0$d = mi0$q;
        mi1$d = mi1$q;
        mi2$d = mi2$q;
        mi3$d = mi3$q;
        mif$d = mif$q;
        mis3$d = mis3$q;
        mis2$d = mis2$q;
        ml0$d = ml0$q;
        ml1$d = ml1$q;
        ml2$d = ml2$q;
        ml3$d = ml3$q;
        mlf$d = mlf$q;
        mls3$d = mls3$q;
        mls2$d = mls2$q;
        fl_on$d = fl_on$q;
        fl_line$d = fl_line$q;
        mreq$d = mreq$q;
        maddr$d = maddr$q;
        rv$d = rv$q;
        rax$d = rax$q;
        ray$d = ray$q;
        rbx$d = rbx$q;
        rby$d = rby$q;
        hit_count$d = hit_count$q;
        miss_count$d = miss_count$q;
        hit_r$d = hit_r$q;
        ret_full$d = ret_full$q;
        q_lane$clock = clock;
        tag$clock = clock;
        lane_ax$clock = clock;
        lane_ay$clock = clock;
        lane_bx$clock = clock;
        lane_by$clock = clock;
        ans$clock = clock;
        ans_ax$clock = clock;
        ans_ay$clock = clock;
        ans_bx$clock = clock;
        ans_by$clock = clock;
        ans_meta$clock = clock;
        ret$clock = clock;
        ret_ax$clock = clock;
        ret_ay$clock = clock;
        ret_bx$clock = clock;
        ret_by$clock = clock;
        wr_inc = wr_ptr$q + one5;
        rd_inc = rd_inc_x$q ^ one5;
        rd_inc2 = rd_inc + one5;
        sp_inc = sp_inc_x$q ^ one5;
        sp_inc2 = sp_inc + one5;
        hit_inc = hit_count$q + one32;
        miss_inc = miss_count$q + one32;
        t_wp_inc = t_wp$q + one2;
        t_rp_inc = t_rp$q + one2;
        table_full = t_full$q;
        waiting_any = t_any$q;
        rewind = v3$q & (iconf3$q | table_full);
        accept = v3$q & ~iconf3$q & ~table_full;
        tag_hit = match3$q;
        miss3 = lconf3$q | ~tag_hit;
        hit = accept & ~miss3;
        miss = accept & miss3;
        v3$d = v2$q & ~rewind;
        id3$d = id2$q;
        line3$d = line2$q;
        match3$d = tag$read_data == key2$q;
        ax3$d = lane_ax$read_data;
        ay3$d = lane_ay$read_data;
        bx3$d = lane_bx$read_data;
        by3$d = lane_by$read_data;
        mi0$d = t_v0$q & (t_id0$q == id1$q);
        mi1$d = t_v1$q & (t_id1$q == id1$q);
        mi2$d = t_v2$q & (t_id2$q == id1$q);
        mi3$d = t_v3$q & (t_id3$q == id1$q);
        mif$d = f_v1$q & (f_id1$q == id1$q);
        mis3$d = v3$q & miss3 & (id3$q == id1$q);
        mis2$d = v2$q & (id2$q == id1$q);
        ml0$d = t_v0$q & (t_line0$q == line1$q);
        ml1$d = t_v1$q & (t_line1$q == line1$q);
        ml2$d = t_v2$q & (t_line2$q == line1$q);
        ml3$d = t_v3$q & (t_line3$q == line1$q);
        mlf$d = f_v1$q & (f_line1$q == line1$q);
        mls3$d = v3$q & miss3 & (line3$q == line1$q);
        mls2$d = v2$q & (line2$q == line1$q);
        id_conflict = mi0$q | mi1$q | mi2$q | mi3$q | mif$q | mis3$q | (mis2$q & v3$q & miss3);
        line_conflict = ml0$q | ml1$q | ml2$q | ml3$q | mlf$q | mls3$q | (mls2$q & v3$q & miss3);
        lconf3$d = line_conflict;
        iconf3$d = id_conflict;
        push = cfg_enable & req;
        q_lane$write_address = wr_ptr$q[(32'h0)+:(4)];
        q_lane$write_data = addr;
        q_lane$write_enable = push;
        if (push) begin
            wr_ptr$d = wr_inc;
        end
        rd_next = rd_ptr$q;
        rd_next_inc = rd_inc;
        if (accept) begin
            rd_next = rd_inc;
            rd_next_inc = rd_inc2;
        end
        rd_ptr$d = rd_next;
        rd_inc_x$d = rd_next_inc ^ one5;
        issue = q_valid$q & ~rewind;
        ne_sp = sp$q != wr_ptr$q;
        ne_sp_inc = sp_inc != wr_ptr$q;
        ne_rd = rd_ptr$q != wr_ptr$q;
        read_ptr = sp$q;
        read_inc = sp_inc;
        read_new = ne_sp;
        if (issue) begin
            read_ptr = sp_inc;
            read_inc = sp_inc2;
            read_new = ne_sp_inc;
        end
        if (rewind) begin
            read_ptr = rd_ptr$q;
            read_inc = rd_inc;
            read_new = ne_rd;
        end
        sp$d = read_ptr;
        sp_inc_x$d = read_inc ^ one5;
        q_lane$read_address = read_ptr[(32'h0)+:(4)];
        q_valid$d = read_new;
        head_low = ((q_lane$read_data) & 10'h3ff);
        head_line = head_low & cfg_mask;
        head_key = valid_flag | ((q_lane$read_data) & 17'h1ffff);
        tag$read_address = head_line;
        lane_ax$read_address = head_line;
        lane_ay$read_address = head_line;
        lane_bx$read_address = head_line;
        lane_by$read_address = head_line;
        v1$d = issue;
        id1$d = q_lane$read_data;
        key1$d = head_key;
        line1$d = head_line;
        v2$d = v1$q & ~rewind;
        id2$d = id1$q;
        key2$d = key1$q;
        line2$d = line1$q;
        meta_in = (((line3$q) & 27'h7ffffff) << 32'h10) | ((id3$q) & 27'h7ffffff);
        if (miss3) begin
            meta_in = meta_in | miss_flag;
        end
        ans$push = accept;
        ans_ax$write_data = ax3$q;
        ans_ay$write_data = ay3$q;
        ans_bx$write_data = bx3$q;
        ans_by$write_data = by3$q;
        ans_meta$write_data = meta_in;
        mreq$d = miss;
        maddr$d = id3$q;
        if (miss) begin
            t_wp$d = t_wp_inc;
        end
        if (~t_v0$q & (t_wp$q == slot0)) begin
            t_id0$d = id3$q;
            t_line0$d = line3$q;
        end
        if (~t_v1$q & (t_wp$q == slot1)) begin
            t_id1$d = id3$q;
            t_line1$d = line3$q;
        end
        if (~t_v2$q & (t_wp$q == slot2)) begin
            t_id2$d = id3$q;
            t_line2$d = line3$q;
        end
        if (~t_v3$q & (t_wp$q == slot3)) begin
            t_id3$d = id3$q;
            t_line3$d = line3$q;
        end
        ret_push = cfg_enable & mem_valid & waiting_any;
        ret$push = ret_push;
        ret_ax$write_data = mem_ax;
        ret_ay$write_data = mem_ay;
        ret_bx$write_data = mem_bx;
        ret_by$write_data = mem_by;
        head_miss = ans_meta$read_data[32'h1a];
        answer = ans$valid & (~head_miss | ret$valid);
        fill = answer & head_miss;
        ans$pop = answer;
        ret$pop = fill;
        rv$d = answer;
        rax$d = ans_ax$read_data;
        ray$d = ans_ay$read_data;
        rbx$d = ans_bx$read_data;
        rby$d = ans_by$read_data;
        if (head_miss) begin
            rax$d = ret_ax$read_data;
            ray$d = ret_ay$read_data;
            rbx$d = ret_bx$read_data;
            rby$d = ret_by$read_data;
        end
        if (miss & ~fill) begin
            t_n$d = t_n$q + one3;
        end
        if (fill & ~miss) begin
            t_n$d = t_n$q - one3;
        end
        t_full$d = ((t_n$q == misses3) & ~fill) | ((t_n$q == almost3) & miss & ~fill);
        if (fill) begin
            t_rp$d = t_rp_inc;
        end
        tv0_next = t_v0$q;
        if (miss & (t_wp$q == slot0)) begin
            tv0_next = 1'b1;
        end
        if (fill & (t_rp$q == slot0)) begin
            tv0_next = 1'b0;
        end
        t_v0$d = tv0_next;
        tv1_next = t_v1$q;
        if (miss & (t_wp$q == slot1)) begin
            tv1_next = 1'b1;
        end
        if (fill & (t_rp$q == slot1)) begin
            tv1_next = 1'b0;
        end
        t_v1$d = tv1_next;
        tv2_next = t_v2$q;
        if (miss & (t_wp$q == slot2)) begin
            tv2_next = 1'b1;
        end
        if (fill & (t_rp$q == slot2)) begin
            tv2_next = 1'b0;
        end
        t_v2$d = tv2_next;
        tv3_next = t_v3$q;
        if (miss & (t_wp$q == slot3)) begin
            tv3_next = 1'b1;
        end
        if (fill & (t_rp$q == slot3)) begin
            tv3_next = 1'b0;
        end
        t_v3$d = tv3_next;
        t_any$d = tv0_next | tv1_next | tv2_next | tv3_next;
        head_line_fill = ans_meta$read_data[(32'h10)+:(10)];
        head_id_fill = ans_meta$read_data[(32'h0)+:(16)];
        head_key_fill = valid_flag | ((head_id_fill) & 17'h1ffff);
        f_v1$d = fill;
        f_id1$d = head_id_fill;
        f_line1$d = head_line_fill;
        ans_ax$write_address = ans$tail_address;
        ans_ay$write_address = ans$tail_address;
        ans_bx$write_address = ans$tail_address;
        ans_by$write_address = ans$tail_address;
        ans_meta$write_address = ans$tail_address;
        ans_ax$write_enable = accept;
        ans_ay$write_enable = accept;
        ans_bx$write_enable = accept;
        ans_by$write_enable = accept;
        ans_meta$write_enable = accept;
        ans_ax$head_address = ans$head_address;
        ans_ay$head_address = ans$head_address;
        ans_bx$head_address = ans$head_address;
        ans_by$head_address = ans$head_address;
        ans_meta$head_address = ans$head_address;
        ans_ax$next_address = ans$next_address;
        ans_ay$next_address = ans$next_address;
        ans_bx$next_address = ans$next_address;
        ans_by$next_address = ans$next_address;
        ans_meta$next_address = ans$next_address;
        ans_ax$pop = answer;
        ans_ay$pop = answer;
        ans_bx$pop = answer;
        ans_by$pop = answer;
        ans_meta$pop = answer;
        ret_ax$write_address = ret$tail_address;
        ret_ay$write_address = ret$tail_address;
        ret_bx$write_address = ret$tail_address;
        ret_by$write_address = ret$tail_address;
        ret_full$d = ((ret$count == misses3) & ~fill) | ((ret$count == almost3) & ret_push & ~fill);
        ret_ax$write_enable = ~ret_full$q;
        ret_ay$write_enable = ~ret_full$q;
        ret_bx$write_enable = ~ret_full$q;
        ret_by$write_enable = ~ret_full$q;
        ret_ax$head_address = ret$head_address;
        ret_ay$head_address = ret$head_address;
        ret_bx$head_address = ret$head_address;
        ret_by$head_address = ret$head_address;
        ret_ax$next_address = ret$next_address;
        ret_ay$next_address = ret$next_address;
        ret_bx$next_address = ret$next_address;
        ret_by$next_address = ret$next_address;
        ret_ax$pop = fill;
        ret_ay$pop = fill;
        ret_bx$pop = fill;
        ret_by$pop = fill;
        tag$write_address = head_line_fill;
        lane_ax$write_address = head_line_fill;
        lane_ay$write_address = head_line_fill;
        lane_bx$write_address = head_line_fill;
        lane_by$write_address = head_line_fill;
        tag$write_data = head_key_fill;
        lane_ax$write_data = ret_ax$read_data;
        lane_ay$write_data = ret_ay$read_data;
        lane_bx$write_data = ret_bx$read_data;
        lane_by$write_data = ret_by$read_data;
        tag$write_enable = fill;
        fl_inc = fl_line$q + one_line;
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
            fl_line$d = zero_line;
        end
        flushing = fl_on$q;
        lane_ax$write_enable = fill;
        lane_ay$write_enable = fill;
        lane_bx$write_enable = fill;
        lane_by$write_enable = fill;
        hit_r$d = hit;
        if (hit_r$q) begin
            hit_count$d = hit_inc;
        end
        if (mreq$q) begin
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
            mem_addr = maddr$q;
            resp_valid = rv$q;
            resp_ax = rax$q;
            resp_ay = ray$q;
            resp_bx = rbx$q;
            resp_by = rby$q;
        end
    end
    
endmodule // patch_cache


module patch_cache$ans(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    patch_cache$ans$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    patch_cache$ans$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    patch_cache$ans$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    patch_cache$ans$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    patch_cache$ans$head_valid head_valid(
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
    
endmodule // patch_cache$ans


module patch_cache$ans$head_valid(d,q,clock);
    
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
          
endmodule // patch_cache$ans$head_valid


module patch_cache$ans$rd_inc_x(d,q,clock);
    
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
          
endmodule // patch_cache$ans$rd_inc_x


module patch_cache$ans$rd_ptr(d,q,clock);
    
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
          
endmodule // patch_cache$ans$rd_ptr


module patch_cache$ans$tail_ptr(d,q,clock);
    
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
          
endmodule // patch_cache$ans$tail_ptr


module patch_cache$ans$words(d,q,clock);
    
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
          
endmodule // patch_cache$ans$words


module patch_cache$ans_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // patch_cache$ans_ax


module patch_cache$ans_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // patch_cache$ans_ay


module patch_cache$ans_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // patch_cache$ans_bx


module patch_cache$ans_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // patch_cache$ans_by


module patch_cache$ans_meta(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  [26:0] write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  [26:0] read_data;
    
    // Update code (custom)
    reg [26:0] mem [0:15];
    reg [26:0] head_r;
    reg [26:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [26:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 27'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 27'd0;
       head_r = 27'd0;
       next_r = 27'd0;
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
endmodule // patch_cache$ans_meta


module patch_cache$ax3(d,q,clock);
    
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
          
endmodule // patch_cache$ax3


module patch_cache$ay3(d,q,clock);
    
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
          
endmodule // patch_cache$ay3


module patch_cache$bx3(d,q,clock);
    
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
          
endmodule // patch_cache$bx3


module patch_cache$by3(d,q,clock);
    
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
          
endmodule // patch_cache$by3


module patch_cache$f_id1(d,q,clock);
    
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
          
endmodule // patch_cache$f_id1


module patch_cache$f_line1(d,q,clock);
    
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
          
endmodule // patch_cache$f_line1


module patch_cache$f_v1(d,q,clock);
    
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
          
endmodule // patch_cache$f_v1


module patch_cache$fl_line(d,q,clock);
    
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


module patch_cache$hit_r(d,q,clock);
    
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
          
endmodule // patch_cache$hit_r


module patch_cache$iconf3(d,q,clock);
    
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
          
endmodule // patch_cache$iconf3


module patch_cache$id1(d,q,clock);
    
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
          
endmodule // patch_cache$id1


module patch_cache$id2(d,q,clock);
    
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
          
endmodule // patch_cache$id2


module patch_cache$id3(d,q,clock);
    
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
          
endmodule // patch_cache$id3


module patch_cache$key1(d,q,clock);
    
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
          
endmodule // patch_cache$key1


module patch_cache$key2(d,q,clock);
    
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
          
endmodule // patch_cache$key2


module patch_cache$lane_ax(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // patch_cache$lane_ax


module patch_cache$lane_ay(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // patch_cache$lane_ay


module patch_cache$lane_bx(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // patch_cache$lane_bx


module patch_cache$lane_by(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // patch_cache$lane_by


module patch_cache$lconf3(d,q,clock);
    
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
          
endmodule // patch_cache$lconf3


module patch_cache$line1(d,q,clock);
    
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
          
endmodule // patch_cache$line1


module patch_cache$line2(d,q,clock);
    
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
          
endmodule // patch_cache$line2


module patch_cache$line3(d,q,clock);
    
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
          
endmodule // patch_cache$line3


module patch_cache$maddr(d,q,clock);
    
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
          
endmodule // patch_cache$maddr


module patch_cache$match3(d,q,clock);
    
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
          
endmodule // patch_cache$match3


module patch_cache$mi0(d,q,clock);
    
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
          
endmodule // patch_cache$mi0


module patch_cache$mi1(d,q,clock);
    
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
          
endmodule // patch_cache$mi1


module patch_cache$mi2(d,q,clock);
    
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
          
endmodule // patch_cache$mi2


module patch_cache$mi3(d,q,clock);
    
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
          
endmodule // patch_cache$mi3


module patch_cache$mif(d,q,clock);
    
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
          
endmodule // patch_cache$mif


module patch_cache$mis2(d,q,clock);
    
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
          
endmodule // patch_cache$mis2


module patch_cache$mis3(d,q,clock);
    
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
          
endmodule // patch_cache$mis3


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


module patch_cache$ml0(d,q,clock);
    
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
          
endmodule // patch_cache$ml0


module patch_cache$ml1(d,q,clock);
    
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
          
endmodule // patch_cache$ml1


module patch_cache$ml2(d,q,clock);
    
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
          
endmodule // patch_cache$ml2


module patch_cache$ml3(d,q,clock);
    
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
          
endmodule // patch_cache$ml3


module patch_cache$mlf(d,q,clock);
    
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
          
endmodule // patch_cache$mlf


module patch_cache$mls2(d,q,clock);
    
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
          
endmodule // patch_cache$mls2


module patch_cache$mls3(d,q,clock);
    
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
          
endmodule // patch_cache$mls3


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


module patch_cache$q_valid(d,q,clock);
    
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
          
endmodule // patch_cache$q_valid


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


module patch_cache$rd_inc_x(d,q,clock);
    
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
          
endmodule // patch_cache$rd_inc_x


module patch_cache$rd_ptr(d,q,clock);
    
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
          
endmodule // patch_cache$rd_ptr


module patch_cache$ret(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [1:0] tail_address;
    output reg  [1:0] head_address;
    output reg  [1:0] next_address;
    output reg  valid;
    output reg  [2:0] count;
    
    // Constant declarations
    localparam  one_a = 2'b1;
    localparam  one_c = 3'b1;
    localparam  zero_c = 3'b0;
    
    // Stub signals
    reg  [1:0] tail_ptr$d;
    wire  [1:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [1:0] rd_ptr$d;
    wire  [1:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [1:0] rd_inc_x$d;
    wire  [1:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [2:0] words$d;
    wire  [2:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [1:0] rd_inc;
    reg  [1:0] rd_inc2;
    
    // Sub module instances
    patch_cache$ret$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    patch_cache$ret$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    patch_cache$ret$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    patch_cache$ret$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    patch_cache$ret$head_valid head_valid(
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
    
endmodule // patch_cache$ret


module patch_cache$ret$head_valid(d,q,clock);
    
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
          
endmodule // patch_cache$ret$head_valid


module patch_cache$ret$rd_inc_x(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$ret$rd_inc_x


module patch_cache$ret$rd_ptr(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$ret$rd_ptr


module patch_cache$ret$tail_ptr(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$ret$tail_ptr


module patch_cache$ret$words(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$ret$words


module patch_cache$ret_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [1:0] head_address;
    input wire  [1:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:3];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:3];
    initial for (i = 0; i <= 3; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 3; i = i + 1) mem[i] = 17'd0;
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
endmodule // patch_cache$ret_ax


module patch_cache$ret_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [1:0] head_address;
    input wire  [1:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:3];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:3];
    initial for (i = 0; i <= 3; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 3; i = i + 1) mem[i] = 17'd0;
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
endmodule // patch_cache$ret_ay


module patch_cache$ret_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [1:0] head_address;
    input wire  [1:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:3];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:3];
    initial for (i = 0; i <= 3; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 3; i = i + 1) mem[i] = 17'd0;
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
endmodule // patch_cache$ret_bx


module patch_cache$ret_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [1:0] write_address;
    input wire  [16:0] write_data;
    input wire  write_enable;
    input wire  [1:0] head_address;
    input wire  [1:0] next_address;
    input wire  pop;
    output reg  [16:0] read_data;
    
    // Update code (custom)
    reg [16:0] mem [0:3];
    reg [16:0] head_r;
    reg [16:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [16:0] mem_n [0:3];
    initial for (i = 0; i <= 3; i = i + 1) mem_n[i] = 17'd0;
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
       for (i = 0; i <= 3; i = i + 1) mem[i] = 17'd0;
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
endmodule // patch_cache$ret_by


module patch_cache$ret_full(d,q,clock);
    
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
          
endmodule // patch_cache$ret_full


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


module patch_cache$sp(d,q,clock);
    
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
          
endmodule // patch_cache$sp


module patch_cache$sp_inc_x(d,q,clock);
    
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
          
endmodule // patch_cache$sp_inc_x


module patch_cache$t_any(d,q,clock);
    
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
          
endmodule // patch_cache$t_any


module patch_cache$t_full(d,q,clock);
    
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
          
endmodule // patch_cache$t_full


module patch_cache$t_id0(d,q,clock);
    
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
          
endmodule // patch_cache$t_id0


module patch_cache$t_id1(d,q,clock);
    
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
          
endmodule // patch_cache$t_id1


module patch_cache$t_id2(d,q,clock);
    
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
          
endmodule // patch_cache$t_id2


module patch_cache$t_id3(d,q,clock);
    
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
          
endmodule // patch_cache$t_id3


module patch_cache$t_line0(d,q,clock);
    
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
          
endmodule // patch_cache$t_line0


module patch_cache$t_line1(d,q,clock);
    
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
          
endmodule // patch_cache$t_line1


module patch_cache$t_line2(d,q,clock);
    
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
          
endmodule // patch_cache$t_line2


module patch_cache$t_line3(d,q,clock);
    
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
          
endmodule // patch_cache$t_line3


module patch_cache$t_n(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$t_n


module patch_cache$t_rp(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$t_rp


module patch_cache$t_v0(d,q,clock);
    
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
          
endmodule // patch_cache$t_v0


module patch_cache$t_v1(d,q,clock);
    
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
          
endmodule // patch_cache$t_v1


module patch_cache$t_v2(d,q,clock);
    
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
          
endmodule // patch_cache$t_v2


module patch_cache$t_v3(d,q,clock);
    
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
          
endmodule // patch_cache$t_v3


module patch_cache$t_wp(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // patch_cache$t_wp


module patch_cache$tag(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // patch_cache$tag


module patch_cache$v1(d,q,clock);
    
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
          
endmodule // patch_cache$v1


module patch_cache$v2(d,q,clock);
    
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
          
endmodule // patch_cache$v2


module patch_cache$v3(d,q,clock);
    
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
          
endmodule // patch_cache$v3


module patch_cache$wr_ptr(d,q,clock);
    
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
          
endmodule // patch_cache$wr_ptr
