// machine: exported from rust-hdl by `shelling export-verilog`; do not edit.


module machine(clock,dir_we$0,dir_we$1,dir_addr$0,dir_addr$1,dir_x$0,dir_x$1,dir_y$0,dir_y$1,origin_x$0,origin_x$1,origin_y$0,origin_y$1,normal_x$0,normal_x$1,normal_y$0,normal_y$1,first_x$0,first_x$1,first_y$0,first_y$1,last_x$0,last_x$1,last_y$0,last_y$1,cmd_valid$0,cmd_valid$1,cmd_retire$0,cmd_retire$1,cmd_sector$0,cmd_sector$1,cmd_id$0,cmd_id$1,cmd_first$0,cmd_first$1,cmd_count$0,cmd_count$1,res_re$0,res_re$1,res_addr$0,res_addr$1,cmd_ready$0,cmd_ready$1,res_hit$0,res_hit$1,res_id$0,res_id$1,res_key$0,res_key$1,busy$0,busy$1,loads$0,loads$1,cache_hits$0,cache_hits$1,cache_misses$0,cache_misses$1,passed$0,passed$1,backward$0,backward$1,back_facing$0,back_facing$1,outside$0,outside$1,near$0,near$1,tests$0,tests$1,marks$0,marks$1,cfg_cache_enable,cfg_cache_mask,cfg_cache_flush,host_req,host_addr,host_valid,host_ax,host_ay,host_bx,host_by,requests);
    
    // Module arguments
    input wire  clock;
    input wire  dir_we$0;
    input wire  dir_we$1;
    input wire  [10:0] dir_addr$0;
    input wire  [10:0] dir_addr$1;
    input wire  [17:0] dir_x$0;
    input wire  [17:0] dir_x$1;
    input wire  [17:0] dir_y$0;
    input wire  [17:0] dir_y$1;
    input wire  [16:0] origin_x$0;
    input wire  [16:0] origin_x$1;
    input wire  [16:0] origin_y$0;
    input wire  [16:0] origin_y$1;
    input wire  [17:0] normal_x$0;
    input wire  [17:0] normal_x$1;
    input wire  [17:0] normal_y$0;
    input wire  [17:0] normal_y$1;
    input wire  [17:0] first_x$0;
    input wire  [17:0] first_x$1;
    input wire  [17:0] first_y$0;
    input wire  [17:0] first_y$1;
    input wire  [17:0] last_x$0;
    input wire  [17:0] last_x$1;
    input wire  [17:0] last_y$0;
    input wire  [17:0] last_y$1;
    input wire  cmd_valid$0;
    input wire  cmd_valid$1;
    input wire  cmd_retire$0;
    input wire  cmd_retire$1;
    input wire  cmd_sector$0;
    input wire  cmd_sector$1;
    input wire  [15:0] cmd_id$0;
    input wire  [15:0] cmd_id$1;
    input wire  [10:0] cmd_first$0;
    input wire  [10:0] cmd_first$1;
    input wire  [10:0] cmd_count$0;
    input wire  [10:0] cmd_count$1;
    input wire  res_re$0;
    input wire  res_re$1;
    input wire  [10:0] res_addr$0;
    input wire  [10:0] res_addr$1;
    output reg  cmd_ready$0;
    output reg  cmd_ready$1;
    output reg  res_hit$0;
    output reg  res_hit$1;
    output reg  [15:0] res_id$0;
    output reg  [15:0] res_id$1;
    output reg  [31:0] res_key$0;
    output reg  [31:0] res_key$1;
    output reg  busy$0;
    output reg  busy$1;
    output reg  [31:0] loads$0;
    output reg  [31:0] loads$1;
    output reg  [31:0] cache_hits$0;
    output reg  [31:0] cache_hits$1;
    output reg  [31:0] cache_misses$0;
    output reg  [31:0] cache_misses$1;
    output reg  [31:0] passed$0;
    output reg  [31:0] passed$1;
    output reg  [31:0] backward$0;
    output reg  [31:0] backward$1;
    output reg  [31:0] back_facing$0;
    output reg  [31:0] back_facing$1;
    output reg  [31:0] outside$0;
    output reg  [31:0] outside$1;
    output reg  [31:0] near$0;
    output reg  [31:0] near$1;
    output reg  [31:0] tests$0;
    output reg  [31:0] tests$1;
    output reg  [31:0] marks$0;
    output reg  [31:0] marks$1;
    input wire  cfg_cache_enable;
    input wire  [9:0] cfg_cache_mask;
    input wire  cfg_cache_flush;
    output reg  host_req;
    output reg  [15:0] host_addr;
    input wire  host_valid;
    input wire  [16:0] host_ax;
    input wire  [16:0] host_ay;
    input wire  [16:0] host_bx;
    input wire  [16:0] host_by;
    output reg  [31:0] requests;
    
    // Stub signals
    reg  pes$0$clock;
    reg  pes$0$dir_we;
    reg  [10:0] pes$0$dir_addr;
    reg  [17:0] pes$0$dir_x;
    reg  [17:0] pes$0$dir_y;
    reg  [16:0] pes$0$origin_x;
    reg  [16:0] pes$0$origin_y;
    reg  [17:0] pes$0$normal_x;
    reg  [17:0] pes$0$normal_y;
    reg  [17:0] pes$0$first_x;
    reg  [17:0] pes$0$first_y;
    reg  [17:0] pes$0$last_x;
    reg  [17:0] pes$0$last_y;
    reg  pes$0$cmd_valid;
    wire  pes$0$cmd_ready;
    reg  pes$0$cmd_retire;
    reg  pes$0$cmd_sector;
    reg  [15:0] pes$0$cmd_id;
    reg  [10:0] pes$0$cmd_first;
    reg  [10:0] pes$0$cmd_count;
    reg  pes$0$cfg_cache_enable;
    reg  [9:0] pes$0$cfg_cache_mask;
    reg  pes$0$cfg_cache_flush;
    wire  pes$0$mem_req;
    wire  [15:0] pes$0$mem_addr;
    reg  pes$0$mem_valid;
    reg  [16:0] pes$0$mem_ax;
    reg  [16:0] pes$0$mem_ay;
    reg  [16:0] pes$0$mem_bx;
    reg  [16:0] pes$0$mem_by;
    reg  pes$0$res_re;
    reg  [10:0] pes$0$res_addr;
    wire  pes$0$res_hit;
    wire  [15:0] pes$0$res_id;
    wire  [31:0] pes$0$res_key;
    wire  pes$0$busy;
    wire  [31:0] pes$0$loads;
    wire  [31:0] pes$0$cache_hits;
    wire  [31:0] pes$0$cache_misses;
    wire  [31:0] pes$0$passed;
    wire  [31:0] pes$0$backward;
    wire  [31:0] pes$0$back_facing;
    wire  [31:0] pes$0$outside;
    wire  [31:0] pes$0$near;
    wire  [31:0] pes$0$tests;
    wire  [31:0] pes$0$marks;
    reg  pes$1$clock;
    reg  pes$1$dir_we;
    reg  [10:0] pes$1$dir_addr;
    reg  [17:0] pes$1$dir_x;
    reg  [17:0] pes$1$dir_y;
    reg  [16:0] pes$1$origin_x;
    reg  [16:0] pes$1$origin_y;
    reg  [17:0] pes$1$normal_x;
    reg  [17:0] pes$1$normal_y;
    reg  [17:0] pes$1$first_x;
    reg  [17:0] pes$1$first_y;
    reg  [17:0] pes$1$last_x;
    reg  [17:0] pes$1$last_y;
    reg  pes$1$cmd_valid;
    wire  pes$1$cmd_ready;
    reg  pes$1$cmd_retire;
    reg  pes$1$cmd_sector;
    reg  [15:0] pes$1$cmd_id;
    reg  [10:0] pes$1$cmd_first;
    reg  [10:0] pes$1$cmd_count;
    reg  pes$1$cfg_cache_enable;
    reg  [9:0] pes$1$cfg_cache_mask;
    reg  pes$1$cfg_cache_flush;
    wire  pes$1$mem_req;
    wire  [15:0] pes$1$mem_addr;
    reg  pes$1$mem_valid;
    reg  [16:0] pes$1$mem_ax;
    reg  [16:0] pes$1$mem_ay;
    reg  [16:0] pes$1$mem_bx;
    reg  [16:0] pes$1$mem_by;
    reg  pes$1$res_re;
    reg  [10:0] pes$1$res_addr;
    wire  pes$1$res_hit;
    wire  [15:0] pes$1$res_id;
    wire  [31:0] pes$1$res_key;
    wire  pes$1$busy;
    wire  [31:0] pes$1$loads;
    wire  [31:0] pes$1$cache_hits;
    wire  [31:0] pes$1$cache_misses;
    wire  [31:0] pes$1$passed;
    wire  [31:0] pes$1$backward;
    wire  [31:0] pes$1$back_facing;
    wire  [31:0] pes$1$outside;
    wire  [31:0] pes$1$near;
    wire  [31:0] pes$1$tests;
    wire  [31:0] pes$1$marks;
    reg  arbiter$clock;
    reg  arbiter$pe_req$0;
    reg  arbiter$pe_req$1;
    reg  [15:0] arbiter$pe_addr$0;
    reg  [15:0] arbiter$pe_addr$1;
    wire  arbiter$pe_valid$0;
    wire  arbiter$pe_valid$1;
    wire  [16:0] arbiter$pe_ax;
    wire  [16:0] arbiter$pe_ay;
    wire  [16:0] arbiter$pe_bx;
    wire  [16:0] arbiter$pe_by;
    wire  arbiter$host_req;
    wire  [15:0] arbiter$host_addr;
    reg  arbiter$host_valid;
    reg  [16:0] arbiter$host_ax;
    reg  [16:0] arbiter$host_ay;
    reg  [16:0] arbiter$host_bx;
    reg  [16:0] arbiter$host_by;
    wire  [31:0] arbiter$requests;
    reg  port_req$0$d;
    wire  port_req$0$q;
    reg  port_req$0$clock;
    reg  port_req$1$d;
    wire  port_req$1$q;
    reg  port_req$1$clock;
    reg  [15:0] port_addr$0$d;
    wire  [15:0] port_addr$0$q;
    reg  port_addr$0$clock;
    reg  [15:0] port_addr$1$d;
    wire  [15:0] port_addr$1$q;
    reg  port_addr$1$clock;
    reg  port_valid$0$d;
    wire  port_valid$0$q;
    reg  port_valid$0$clock;
    reg  port_valid$1$d;
    wire  port_valid$1$q;
    reg  port_valid$1$clock;
    reg  [16:0] port_ax$0$d;
    wire  [16:0] port_ax$0$q;
    reg  port_ax$0$clock;
    reg  [16:0] port_ax$1$d;
    wire  [16:0] port_ax$1$q;
    reg  port_ax$1$clock;
    reg  [16:0] port_ay$0$d;
    wire  [16:0] port_ay$0$q;
    reg  port_ay$0$clock;
    reg  [16:0] port_ay$1$d;
    wire  [16:0] port_ay$1$q;
    reg  port_ay$1$clock;
    reg  [16:0] port_bx$0$d;
    wire  [16:0] port_bx$0$q;
    reg  port_bx$0$clock;
    reg  [16:0] port_bx$1$d;
    wire  [16:0] port_bx$1$q;
    reg  port_bx$1$clock;
    reg  [16:0] port_by$0$d;
    wire  [16:0] port_by$0$q;
    reg  port_by$0$clock;
    reg  [16:0] port_by$1$d;
    wire  [16:0] port_by$1$q;
    reg  port_by$1$clock;
    reg  was_busy$0$d;
    wire  was_busy$0$q;
    reg  was_busy$0$clock;
    reg  was_busy$1$d;
    wire  was_busy$1$q;
    reg  was_busy$1$clock;
    reg  cfg_enable$0$d;
    wire  cfg_enable$0$q;
    reg  cfg_enable$0$clock;
    reg  cfg_enable$1$d;
    wire  cfg_enable$1$q;
    reg  cfg_enable$1$clock;
    reg  [9:0] cfg_mask$0$d;
    wire  [9:0] cfg_mask$0$q;
    reg  cfg_mask$0$clock;
    reg  [9:0] cfg_mask$1$d;
    wire  [9:0] cfg_mask$1$q;
    reg  cfg_mask$1$clock;
    reg  cfg_flush$0$d;
    wire  cfg_flush$0$q;
    reg  cfg_flush$0$clock;
    reg  cfg_flush$1$d;
    wire  cfg_flush$1$q;
    reg  cfg_flush$1$clock;
    
    // Sub module instances
    machine$pes$0 pes$0(
        .clock(pes$0$clock),
        .dir_we(pes$0$dir_we),
        .dir_addr(pes$0$dir_addr),
        .dir_x(pes$0$dir_x),
        .dir_y(pes$0$dir_y),
        .origin_x(pes$0$origin_x),
        .origin_y(pes$0$origin_y),
        .normal_x(pes$0$normal_x),
        .normal_y(pes$0$normal_y),
        .first_x(pes$0$first_x),
        .first_y(pes$0$first_y),
        .last_x(pes$0$last_x),
        .last_y(pes$0$last_y),
        .cmd_valid(pes$0$cmd_valid),
        .cmd_ready(pes$0$cmd_ready),
        .cmd_retire(pes$0$cmd_retire),
        .cmd_sector(pes$0$cmd_sector),
        .cmd_id(pes$0$cmd_id),
        .cmd_first(pes$0$cmd_first),
        .cmd_count(pes$0$cmd_count),
        .cfg_cache_enable(pes$0$cfg_cache_enable),
        .cfg_cache_mask(pes$0$cfg_cache_mask),
        .cfg_cache_flush(pes$0$cfg_cache_flush),
        .mem_req(pes$0$mem_req),
        .mem_addr(pes$0$mem_addr),
        .mem_valid(pes$0$mem_valid),
        .mem_ax(pes$0$mem_ax),
        .mem_ay(pes$0$mem_ay),
        .mem_bx(pes$0$mem_bx),
        .mem_by(pes$0$mem_by),
        .res_re(pes$0$res_re),
        .res_addr(pes$0$res_addr),
        .res_hit(pes$0$res_hit),
        .res_id(pes$0$res_id),
        .res_key(pes$0$res_key),
        .busy(pes$0$busy),
        .loads(pes$0$loads),
        .cache_hits(pes$0$cache_hits),
        .cache_misses(pes$0$cache_misses),
        .passed(pes$0$passed),
        .backward(pes$0$backward),
        .back_facing(pes$0$back_facing),
        .outside(pes$0$outside),
        .near(pes$0$near),
        .tests(pes$0$tests),
        .marks(pes$0$marks)
    );
    machine$pes$1 pes$1(
        .clock(pes$1$clock),
        .dir_we(pes$1$dir_we),
        .dir_addr(pes$1$dir_addr),
        .dir_x(pes$1$dir_x),
        .dir_y(pes$1$dir_y),
        .origin_x(pes$1$origin_x),
        .origin_y(pes$1$origin_y),
        .normal_x(pes$1$normal_x),
        .normal_y(pes$1$normal_y),
        .first_x(pes$1$first_x),
        .first_y(pes$1$first_y),
        .last_x(pes$1$last_x),
        .last_y(pes$1$last_y),
        .cmd_valid(pes$1$cmd_valid),
        .cmd_ready(pes$1$cmd_ready),
        .cmd_retire(pes$1$cmd_retire),
        .cmd_sector(pes$1$cmd_sector),
        .cmd_id(pes$1$cmd_id),
        .cmd_first(pes$1$cmd_first),
        .cmd_count(pes$1$cmd_count),
        .cfg_cache_enable(pes$1$cfg_cache_enable),
        .cfg_cache_mask(pes$1$cfg_cache_mask),
        .cfg_cache_flush(pes$1$cfg_cache_flush),
        .mem_req(pes$1$mem_req),
        .mem_addr(pes$1$mem_addr),
        .mem_valid(pes$1$mem_valid),
        .mem_ax(pes$1$mem_ax),
        .mem_ay(pes$1$mem_ay),
        .mem_bx(pes$1$mem_bx),
        .mem_by(pes$1$mem_by),
        .res_re(pes$1$res_re),
        .res_addr(pes$1$res_addr),
        .res_hit(pes$1$res_hit),
        .res_id(pes$1$res_id),
        .res_key(pes$1$res_key),
        .busy(pes$1$busy),
        .loads(pes$1$loads),
        .cache_hits(pes$1$cache_hits),
        .cache_misses(pes$1$cache_misses),
        .passed(pes$1$passed),
        .backward(pes$1$backward),
        .back_facing(pes$1$back_facing),
        .outside(pes$1$outside),
        .near(pes$1$near),
        .tests(pes$1$tests),
        .marks(pes$1$marks)
    );
    machine$arbiter arbiter(
        .clock(arbiter$clock),
        .pe_req$0(arbiter$pe_req$0),
        .pe_req$1(arbiter$pe_req$1),
        .pe_addr$0(arbiter$pe_addr$0),
        .pe_addr$1(arbiter$pe_addr$1),
        .pe_valid$0(arbiter$pe_valid$0),
        .pe_valid$1(arbiter$pe_valid$1),
        .pe_ax(arbiter$pe_ax),
        .pe_ay(arbiter$pe_ay),
        .pe_bx(arbiter$pe_bx),
        .pe_by(arbiter$pe_by),
        .host_req(arbiter$host_req),
        .host_addr(arbiter$host_addr),
        .host_valid(arbiter$host_valid),
        .host_ax(arbiter$host_ax),
        .host_ay(arbiter$host_ay),
        .host_bx(arbiter$host_bx),
        .host_by(arbiter$host_by),
        .requests(arbiter$requests)
    );
    machine$port_req$0 port_req$0(
        .d(port_req$0$d),
        .q(port_req$0$q),
        .clock(port_req$0$clock)
    );
    machine$port_req$1 port_req$1(
        .d(port_req$1$d),
        .q(port_req$1$q),
        .clock(port_req$1$clock)
    );
    machine$port_addr$0 port_addr$0(
        .d(port_addr$0$d),
        .q(port_addr$0$q),
        .clock(port_addr$0$clock)
    );
    machine$port_addr$1 port_addr$1(
        .d(port_addr$1$d),
        .q(port_addr$1$q),
        .clock(port_addr$1$clock)
    );
    machine$port_valid$0 port_valid$0(
        .d(port_valid$0$d),
        .q(port_valid$0$q),
        .clock(port_valid$0$clock)
    );
    machine$port_valid$1 port_valid$1(
        .d(port_valid$1$d),
        .q(port_valid$1$q),
        .clock(port_valid$1$clock)
    );
    machine$port_ax$0 port_ax$0(
        .d(port_ax$0$d),
        .q(port_ax$0$q),
        .clock(port_ax$0$clock)
    );
    machine$port_ax$1 port_ax$1(
        .d(port_ax$1$d),
        .q(port_ax$1$q),
        .clock(port_ax$1$clock)
    );
    machine$port_ay$0 port_ay$0(
        .d(port_ay$0$d),
        .q(port_ay$0$q),
        .clock(port_ay$0$clock)
    );
    machine$port_ay$1 port_ay$1(
        .d(port_ay$1$d),
        .q(port_ay$1$q),
        .clock(port_ay$1$clock)
    );
    machine$port_bx$0 port_bx$0(
        .d(port_bx$0$d),
        .q(port_bx$0$q),
        .clock(port_bx$0$clock)
    );
    machine$port_bx$1 port_bx$1(
        .d(port_bx$1$d),
        .q(port_bx$1$q),
        .clock(port_bx$1$clock)
    );
    machine$port_by$0 port_by$0(
        .d(port_by$0$d),
        .q(port_by$0$q),
        .clock(port_by$0$clock)
    );
    machine$port_by$1 port_by$1(
        .d(port_by$1$d),
        .q(port_by$1$q),
        .clock(port_by$1$clock)
    );
    machine$was_busy$0 was_busy$0(
        .d(was_busy$0$d),
        .q(was_busy$0$q),
        .clock(was_busy$0$clock)
    );
    machine$was_busy$1 was_busy$1(
        .d(was_busy$1$d),
        .q(was_busy$1$q),
        .clock(was_busy$1$clock)
    );
    machine$cfg_enable$0 cfg_enable$0(
        .d(cfg_enable$0$d),
        .q(cfg_enable$0$q),
        .clock(cfg_enable$0$clock)
    );
    machine$cfg_enable$1 cfg_enable$1(
        .d(cfg_enable$1$d),
        .q(cfg_enable$1$q),
        .clock(cfg_enable$1$clock)
    );
    machine$cfg_mask$0 cfg_mask$0(
        .d(cfg_mask$0$d),
        .q(cfg_mask$0$q),
        .clock(cfg_mask$0$clock)
    );
    machine$cfg_mask$1 cfg_mask$1(
        .d(cfg_mask$1$d),
        .q(cfg_mask$1$q),
        .clock(cfg_mask$1$clock)
    );
    machine$cfg_flush$0 cfg_flush$0(
        .d(cfg_flush$0$d),
        .q(cfg_flush$0$q),
        .clock(cfg_flush$0$clock)
    );
    machine$cfg_flush$1 cfg_flush$1(
        .d(cfg_flush$1$d),
        .q(cfg_flush$1$q),
        .clock(cfg_flush$1$clock)
    );
    
    // Update code
    always @(*) begin
        arbiter$clock = clock;
        pes$0$clock = clock;
        pes$0$dir_we = dir_we$0;
        pes$0$dir_addr = dir_addr$0;
        pes$0$dir_x = dir_x$0;
        pes$0$dir_y = dir_y$0;
        pes$0$origin_x = origin_x$0;
        pes$0$origin_y = origin_y$0;
        pes$0$normal_x = normal_x$0;
        pes$0$normal_y = normal_y$0;
        pes$0$first_x = first_x$0;
        pes$0$first_y = first_y$0;
        pes$0$last_x = last_x$0;
        pes$0$last_y = last_y$0;
        pes$0$cmd_valid = cmd_valid$0;
        pes$0$cmd_retire = cmd_retire$0;
        pes$0$cmd_sector = cmd_sector$0;
        pes$0$cmd_id = cmd_id$0;
        pes$0$cmd_first = cmd_first$0;
        pes$0$cmd_count = cmd_count$0;
        pes$0$res_re = res_re$0;
        pes$0$res_addr = res_addr$0;
        cmd_ready$0 = pes$0$cmd_ready;
        res_hit$0 = pes$0$res_hit;
        res_id$0 = pes$0$res_id;
        res_key$0 = pes$0$res_key;
        busy$0 = pes$0$busy;
        loads$0 = pes$0$loads;
        cache_hits$0 = pes$0$cache_hits;
        cache_misses$0 = pes$0$cache_misses;
        passed$0 = pes$0$passed;
        backward$0 = pes$0$backward;
        back_facing$0 = pes$0$back_facing;
        outside$0 = pes$0$outside;
        near$0 = pes$0$near;
        tests$0 = pes$0$tests;
        marks$0 = pes$0$marks;
        was_busy$0$clock = clock;
        was_busy$0$d = pes$0$busy;
        cfg_enable$0$clock = clock;
        cfg_mask$0$clock = clock;
        cfg_flush$0$clock = clock;
        cfg_enable$0$d = cfg_enable$0$q;
        cfg_mask$0$d = cfg_mask$0$q;
        cfg_flush$0$d = 1'b0;
        if (~was_busy$0$q) begin
            cfg_enable$0$d = cfg_cache_enable;
            cfg_mask$0$d = cfg_cache_mask;
            cfg_flush$0$d = cfg_cache_flush;
        end
        pes$0$cfg_cache_enable = cfg_enable$0$q;
        pes$0$cfg_cache_mask = cfg_mask$0$q;
        pes$0$cfg_cache_flush = cfg_flush$0$q;
        port_req$0$clock = clock;
        port_addr$0$clock = clock;
        port_req$0$d = pes$0$mem_req;
        port_addr$0$d = pes$0$mem_addr;
        arbiter$pe_req$0 = port_req$0$q;
        arbiter$pe_addr$0 = port_addr$0$q;
        port_valid$0$clock = clock;
        port_ax$0$clock = clock;
        port_ay$0$clock = clock;
        port_bx$0$clock = clock;
        port_by$0$clock = clock;
        port_valid$0$d = arbiter$pe_valid$0;
        port_ax$0$d = port_ax$0$q;
        port_ay$0$d = port_ay$0$q;
        port_bx$0$d = port_bx$0$q;
        port_by$0$d = port_by$0$q;
        if (arbiter$pe_valid$0) begin
            port_ax$0$d = arbiter$pe_ax;
            port_ay$0$d = arbiter$pe_ay;
            port_bx$0$d = arbiter$pe_bx;
            port_by$0$d = arbiter$pe_by;
        end
        pes$0$mem_valid = port_valid$0$q;
        pes$0$mem_ax = port_ax$0$q;
        pes$0$mem_ay = port_ay$0$q;
        pes$0$mem_bx = port_bx$0$q;
        pes$0$mem_by = port_by$0$q;
        pes$1$clock = clock;
        pes$1$dir_we = dir_we$1;
        pes$1$dir_addr = dir_addr$1;
        pes$1$dir_x = dir_x$1;
        pes$1$dir_y = dir_y$1;
        pes$1$origin_x = origin_x$1;
        pes$1$origin_y = origin_y$1;
        pes$1$normal_x = normal_x$1;
        pes$1$normal_y = normal_y$1;
        pes$1$first_x = first_x$1;
        pes$1$first_y = first_y$1;
        pes$1$last_x = last_x$1;
        pes$1$last_y = last_y$1;
        pes$1$cmd_valid = cmd_valid$1;
        pes$1$cmd_retire = cmd_retire$1;
        pes$1$cmd_sector = cmd_sector$1;
        pes$1$cmd_id = cmd_id$1;
        pes$1$cmd_first = cmd_first$1;
        pes$1$cmd_count = cmd_count$1;
        pes$1$res_re = res_re$1;
        pes$1$res_addr = res_addr$1;
        cmd_ready$1 = pes$1$cmd_ready;
        res_hit$1 = pes$1$res_hit;
        res_id$1 = pes$1$res_id;
        res_key$1 = pes$1$res_key;
        busy$1 = pes$1$busy;
        loads$1 = pes$1$loads;
        cache_hits$1 = pes$1$cache_hits;
        cache_misses$1 = pes$1$cache_misses;
        passed$1 = pes$1$passed;
        backward$1 = pes$1$backward;
        back_facing$1 = pes$1$back_facing;
        outside$1 = pes$1$outside;
        near$1 = pes$1$near;
        tests$1 = pes$1$tests;
        marks$1 = pes$1$marks;
        was_busy$1$clock = clock;
        was_busy$1$d = pes$1$busy;
        cfg_enable$1$clock = clock;
        cfg_mask$1$clock = clock;
        cfg_flush$1$clock = clock;
        cfg_enable$1$d = cfg_enable$1$q;
        cfg_mask$1$d = cfg_mask$1$q;
        cfg_flush$1$d = 1'b0;
        if (~was_busy$1$q) begin
            cfg_enable$1$d = cfg_cache_enable;
            cfg_mask$1$d = cfg_cache_mask;
            cfg_flush$1$d = cfg_cache_flush;
        end
        pes$1$cfg_cache_enable = cfg_enable$1$q;
        pes$1$cfg_cache_mask = cfg_mask$1$q;
        pes$1$cfg_cache_flush = cfg_flush$1$q;
        port_req$1$clock = clock;
        port_addr$1$clock = clock;
        port_req$1$d = pes$1$mem_req;
        port_addr$1$d = pes$1$mem_addr;
        arbiter$pe_req$1 = port_req$1$q;
        arbiter$pe_addr$1 = port_addr$1$q;
        port_valid$1$clock = clock;
        port_ax$1$clock = clock;
        port_ay$1$clock = clock;
        port_bx$1$clock = clock;
        port_by$1$clock = clock;
        port_valid$1$d = arbiter$pe_valid$1;
        port_ax$1$d = port_ax$1$q;
        port_ay$1$d = port_ay$1$q;
        port_bx$1$d = port_bx$1$q;
        port_by$1$d = port_by$1$q;
        if (arbiter$pe_valid$1) begin
            port_ax$1$d = arbiter$pe_ax;
            port_ay$1$d = arbiter$pe_ay;
            port_bx$1$d = arbiter$pe_bx;
            port_by$1$d = arbiter$pe_by;
        end
        pes$1$mem_valid = port_valid$1$q;
        pes$1$mem_ax = port_ax$1$q;
        pes$1$mem_ay = port_ay$1$q;
        pes$1$mem_bx = port_bx$1$q;
        pes$1$mem_by = port_by$1$q;
        host_req = arbiter$host_req;
        host_addr = arbiter$host_addr;
        arbiter$host_valid = host_valid;
        arbiter$host_ax = host_ax;
        arbiter$host_ay = host_ay;
        arbiter$host_bx = host_bx;
        arbiter$host_by = host_by;
        requests = arbiter$requests;
    end
    
endmodule // machine


module machine$arbiter(clock,pe_req$0,pe_req$1,pe_addr$0,pe_addr$1,pe_valid$0,pe_valid$1,pe_ax,pe_ay,pe_bx,pe_by,host_req,host_addr,host_valid,host_ax,host_ay,host_bx,host_by,requests);
    
    // Module arguments
    input wire  clock;
    input wire  pe_req$0;
    input wire  pe_req$1;
    input wire  [15:0] pe_addr$0;
    input wire  [15:0] pe_addr$1;
    output reg  pe_valid$0;
    output reg  pe_valid$1;
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
    reg  rr$clock;
    reg  rr$request$0;
    reg  rr$request$1;
    wire  rr$found;
    wire  [2:0] rr$pick;
    wire  rr$granted$0;
    wire  rr$granted$1;
    reg  asks$0$d;
    wire  asks$0$q;
    reg  asks$0$clock;
    reg  asks$1$d;
    wire  asks$1$q;
    reg  asks$1$clock;
    reg  grant$0$d;
    wire  grant$0$q;
    reg  grant$0$clock;
    reg  grant$1$d;
    wire  grant$1$q;
    reg  grant$1$clock;
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
    machine$arbiter$queues$0 queues$0(
        .clock(queues$0$clock),
        .push(queues$0$push),
        .data_in(queues$0$data_in),
        .pop(queues$0$pop),
        .valid(queues$0$valid),
        .data_out(queues$0$data_out),
        .count(queues$0$count)
    );
    machine$arbiter$queues$1 queues$1(
        .clock(queues$1$clock),
        .push(queues$1$push),
        .data_in(queues$1$data_in),
        .pop(queues$1$pop),
        .valid(queues$1$valid),
        .data_out(queues$1$data_out),
        .count(queues$1$count)
    );
    machine$arbiter$rr rr(
        .clock(rr$clock),
        .request$0(rr$request$0),
        .request$1(rr$request$1),
        .found(rr$found),
        .pick(rr$pick),
        .granted$0(rr$granted$0),
        .granted$1(rr$granted$1)
    );
    machine$arbiter$asks$0 asks$0(
        .d(asks$0$d),
        .q(asks$0$q),
        .clock(asks$0$clock)
    );
    machine$arbiter$asks$1 asks$1(
        .d(asks$1$d),
        .q(asks$1$q),
        .clock(asks$1$clock)
    );
    machine$arbiter$grant$0 grant$0(
        .d(grant$0$d),
        .q(grant$0$q),
        .clock(grant$0$clock)
    );
    machine$arbiter$grant$1 grant$1(
        .d(grant$1$d),
        .q(grant$1$q),
        .clock(grant$1$clock)
    );
    machine$arbiter$grant_any grant_any(
        .d(grant_any$d),
        .q(grant_any$q),
        .clock(grant_any$clock)
    );
    machine$arbiter$count count(
        .d(count$d),
        .q(count$q),
        .clock(count$clock)
    );
    machine$arbiter$route route(
        .clock(route$clock),
        .push(route$push),
        .data_in(route$data_in),
        .pop(route$pop),
        .valid(route$valid),
        .data_out(route$data_out),
        .count(route$count)
    );
    machine$arbiter$valid_r$0 valid_r$0(
        .d(valid_r$0$d),
        .q(valid_r$0$q),
        .clock(valid_r$0$clock)
    );
    machine$arbiter$valid_r$1 valid_r$1(
        .d(valid_r$1$d),
        .q(valid_r$1$q),
        .clock(valid_r$1$clock)
    );
    machine$arbiter$ax_r ax_r(
        .d(ax_r$d),
        .q(ax_r$q),
        .clock(ax_r$clock)
    );
    machine$arbiter$ay_r ay_r(
        .d(ay_r$d),
        .q(ay_r$q),
        .clock(ay_r$clock)
    );
    machine$arbiter$bx_r bx_r(
        .d(bx_r$d),
        .q(bx_r$q),
        .clock(bx_r$clock)
    );
    machine$arbiter$by_r by_r(
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
    
endmodule // machine$arbiter


module machine$arbiter$asks$0(d,q,clock);
    
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
          
endmodule // machine$arbiter$asks$0


module machine$arbiter$asks$1(d,q,clock);
    
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
          
endmodule // machine$arbiter$asks$1


module machine$arbiter$ax_r(d,q,clock);
    
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
          
endmodule // machine$arbiter$ax_r


module machine$arbiter$ay_r(d,q,clock);
    
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
          
endmodule // machine$arbiter$ay_r


module machine$arbiter$bx_r(d,q,clock);
    
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
          
endmodule // machine$arbiter$bx_r


module machine$arbiter$by_r(d,q,clock);
    
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
          
endmodule // machine$arbiter$by_r


module machine$arbiter$count(d,q,clock);
    
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
          
endmodule // machine$arbiter$count


module machine$arbiter$grant$0(d,q,clock);
    
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
          
endmodule // machine$arbiter$grant$0


module machine$arbiter$grant$1(d,q,clock);
    
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
          
endmodule // machine$arbiter$grant$1


module machine$arbiter$grant_any(d,q,clock);
    
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
          
endmodule // machine$arbiter$grant_any


module machine$arbiter$queues$0(clock,push,data_in,pop,valid,data_out,count);
    
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
    machine$arbiter$queues$0$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    machine$arbiter$queues$0$lane lane(
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
    
endmodule // machine$arbiter$queues$0


module machine$arbiter$queues$0$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$arbiter$queues$0$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$arbiter$queues$0$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$arbiter$queues$0$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$arbiter$queues$0$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$arbiter$queues$0$control$head_valid head_valid(
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
    
endmodule // machine$arbiter$queues$0$control


module machine$arbiter$queues$0$control$head_valid(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$0$control$head_valid


module machine$arbiter$queues$0$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$0$control$rd_inc_x


module machine$arbiter$queues$0$control$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$0$control$rd_ptr


module machine$arbiter$queues$0$control$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$0$control$tail_ptr


module machine$arbiter$queues$0$control$words(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$0$control$words


module machine$arbiter$queues$0$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$arbiter$queues$0$lane


module machine$arbiter$queues$1(clock,push,data_in,pop,valid,data_out,count);
    
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
    machine$arbiter$queues$1$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    machine$arbiter$queues$1$lane lane(
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
    
endmodule // machine$arbiter$queues$1


module machine$arbiter$queues$1$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$arbiter$queues$1$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$arbiter$queues$1$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$arbiter$queues$1$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$arbiter$queues$1$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$arbiter$queues$1$control$head_valid head_valid(
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
    
endmodule // machine$arbiter$queues$1$control


module machine$arbiter$queues$1$control$head_valid(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$1$control$head_valid


module machine$arbiter$queues$1$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$1$control$rd_inc_x


module machine$arbiter$queues$1$control$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$1$control$rd_ptr


module machine$arbiter$queues$1$control$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$1$control$tail_ptr


module machine$arbiter$queues$1$control$words(d,q,clock);
    
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
          
endmodule // machine$arbiter$queues$1$control$words


module machine$arbiter$queues$1$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$arbiter$queues$1$lane


module machine$arbiter$route(clock,push,data_in,pop,valid,data_out,count);
    
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
    machine$arbiter$route$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    machine$arbiter$route$lane lane(
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
    
endmodule // machine$arbiter$route


module machine$arbiter$route$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$arbiter$route$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$arbiter$route$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$arbiter$route$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$arbiter$route$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$arbiter$route$control$head_valid head_valid(
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
    
endmodule // machine$arbiter$route$control


module machine$arbiter$route$control$head_valid(d,q,clock);
    
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
          
endmodule // machine$arbiter$route$control$head_valid


module machine$arbiter$route$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$arbiter$route$control$rd_inc_x


module machine$arbiter$route$control$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$arbiter$route$control$rd_ptr


module machine$arbiter$route$control$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$arbiter$route$control$tail_ptr


module machine$arbiter$route$control$words(d,q,clock);
    
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
          
endmodule // machine$arbiter$route$control$words


module machine$arbiter$route$lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$arbiter$route$lane


module machine$arbiter$rr(clock,request$0,request$1,found,pick,granted$0,granted$1);
    
    // Module arguments
    input wire  clock;
    input wire  request$0;
    input wire  request$1;
    output reg  found;
    output reg  [2:0] pick;
    output reg  granted$0;
    output reg  granted$1;
    
    // Update code (custom)
    reg [2:0] last;
    initial last = 3'd0;
    always @(*) begin
       found = request$0 | request$1;
       pick = 3'd0;
       case (last)
          3'd0: begin if (request$1) pick = 3'd1; else if (request$0) pick = 3'd0; granted$1 = request$1; granted$0 = request$0 & !request$1; end
          3'd1: begin if (request$0) pick = 3'd0; else if (request$1) pick = 3'd1; granted$0 = request$0; granted$1 = request$1 & !request$0; end
          default: begin pick = 0; granted$0 = 1'b0; granted$1 = 1'b0; end
       endcase
    end
    always @(posedge clock) begin
       if (found) last <= pick;
    end
endmodule // machine$arbiter$rr


module machine$arbiter$valid_r$0(d,q,clock);
    
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
          
endmodule // machine$arbiter$valid_r$0


module machine$arbiter$valid_r$1(d,q,clock);
    
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
          
endmodule // machine$arbiter$valid_r$1


module machine$cfg_enable$0(d,q,clock);
    
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
          
endmodule // machine$cfg_enable$0


module machine$cfg_enable$1(d,q,clock);
    
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
          
endmodule // machine$cfg_enable$1


module machine$cfg_flush$0(d,q,clock);
    
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
          
endmodule // machine$cfg_flush$0


module machine$cfg_flush$1(d,q,clock);
    
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
          
endmodule // machine$cfg_flush$1


module machine$cfg_mask$0(d,q,clock);
    
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
          
endmodule // machine$cfg_mask$0


module machine$cfg_mask$1(d,q,clock);
    
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
          
endmodule // machine$cfg_mask$1


module machine$pes$0(clock,dir_we,dir_addr,dir_x,dir_y,origin_x,origin_y,normal_x,normal_y,first_x,first_y,last_x,last_y,cmd_valid,cmd_ready,cmd_retire,cmd_sector,cmd_id,cmd_first,cmd_count,cfg_cache_enable,cfg_cache_mask,cfg_cache_flush,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,res_re,res_addr,res_hit,res_id,res_key,busy,loads,cache_hits,cache_misses,passed,backward,back_facing,outside,near,tests,marks);
    
    // Module arguments
    input wire  clock;
    input wire  dir_we;
    input wire  [10:0] dir_addr;
    input wire  [17:0] dir_x;
    input wire  [17:0] dir_y;
    input wire  [16:0] origin_x;
    input wire  [16:0] origin_y;
    input wire  [17:0] normal_x;
    input wire  [17:0] normal_y;
    input wire  [17:0] first_x;
    input wire  [17:0] first_y;
    input wire  [17:0] last_x;
    input wire  [17:0] last_y;
    input wire  cmd_valid;
    output reg  cmd_ready;
    input wire  cmd_retire;
    input wire  cmd_sector;
    input wire  [15:0] cmd_id;
    input wire  [10:0] cmd_first;
    input wire  [10:0] cmd_count;
    input wire  cfg_cache_enable;
    input wire  [9:0] cfg_cache_mask;
    input wire  cfg_cache_flush;
    output reg  mem_req;
    output reg  [15:0] mem_addr;
    input wire  mem_valid;
    input wire  [16:0] mem_ax;
    input wire  [16:0] mem_ay;
    input wire  [16:0] mem_bx;
    input wire  [16:0] mem_by;
    input wire  res_re;
    input wire  [10:0] res_addr;
    output reg  res_hit;
    output reg  [15:0] res_id;
    output reg  [31:0] res_key;
    output reg  busy;
    output reg  [31:0] loads;
    output reg  [31:0] cache_hits;
    output reg  [31:0] cache_misses;
    output reg  [31:0] passed;
    output reg  [31:0] backward;
    output reg  [31:0] back_facing;
    output reg  [31:0] outside;
    output reg  [31:0] near;
    output reg  [31:0] tests;
    output reg  [31:0] marks;
    
    // Constant declarations
    localparam  one7 = 7'b1;
    localparam  almost_full = 7'b111111;
    localparam  zero1 = 1'b0;
    localparam  one1 = 1'b1;
    localparam  full = 7'b1000000;
    localparam  zero7 = 7'b0;
    
    // Stub signals
    reg  loader$clock;
    reg  loader$id_valid;
    wire  loader$id_ready;
    reg  [15:0] loader$id;
    wire  loader$id_ready_next;
    wire  loader$mem_req;
    wire  [15:0] loader$mem_addr;
    reg  loader$mem_valid;
    reg  [16:0] loader$mem_ax;
    reg  [16:0] loader$mem_ay;
    reg  [16:0] loader$mem_bx;
    reg  [16:0] loader$mem_by;
    wire  loader$out_valid;
    reg  loader$out_ready;
    wire  [15:0] loader$out_id;
    wire  [16:0] loader$out_ax;
    wire  [16:0] loader$out_ay;
    wire  [16:0] loader$out_bx;
    wire  [16:0] loader$out_by;
    wire  [31:0] loader$loads;
    reg  cache$clock;
    reg  cache$cfg_enable;
    reg  [9:0] cache$cfg_mask;
    reg  cache$flush;
    wire  cache$flushing;
    reg  cache$req;
    reg  [15:0] cache$addr;
    wire  cache$resp_valid;
    wire  [16:0] cache$resp_ax;
    wire  [16:0] cache$resp_ay;
    wire  [16:0] cache$resp_bx;
    wire  [16:0] cache$resp_by;
    wire  cache$mem_req;
    wire  [15:0] cache$mem_addr;
    reg  cache$mem_valid;
    reg  [16:0] cache$mem_ax;
    reg  [16:0] cache$mem_ay;
    reg  [16:0] cache$mem_bx;
    reg  [16:0] cache$mem_by;
    wire  [31:0] cache$hits;
    wire  [31:0] cache$misses;
    reg  sc_slice$clock;
    reg  sc_slice$in_valid;
    wire  sc_slice$in_ready;
    reg  [15:0] sc_slice$in_id;
    reg  [17:0] sc_slice$in_ax;
    reg  [17:0] sc_slice$in_ay;
    reg  [17:0] sc_slice$in_bx;
    reg  [17:0] sc_slice$in_by;
    reg  [17:0] sc_slice$in_wx;
    reg  [17:0] sc_slice$in_wy;
    reg  [5:0] sc_slice$in_sh;
    reg  sc_slice$in_pass;
    reg  [9:0] sc_slice$in_first;
    reg  [10:0] sc_slice$in_count;
    reg  sc_slice$in_retire;
    wire  sc_slice$out_valid;
    reg  sc_slice$out_ready;
    wire  [15:0] sc_slice$out_id;
    wire  [17:0] sc_slice$out_ax;
    wire  [17:0] sc_slice$out_ay;
    wire  [17:0] sc_slice$out_bx;
    wire  [17:0] sc_slice$out_by;
    wire  [17:0] sc_slice$out_wx;
    wire  [17:0] sc_slice$out_wy;
    wire  [5:0] sc_slice$out_sh;
    wire  sc_slice$out_pass;
    wire  [9:0] sc_slice$out_first;
    wire  [10:0] sc_slice$out_count;
    wire  sc_slice$out_retire;
    wire  sc_slice$occupied;
    reg  queue$clock;
    reg  queue$in_valid;
    wire  queue$in_ready;
    reg  [15:0] queue$in_id;
    reg  [17:0] queue$in_ax;
    reg  [17:0] queue$in_ay;
    reg  [17:0] queue$in_bx;
    reg  [17:0] queue$in_by;
    reg  [17:0] queue$in_wx;
    reg  [17:0] queue$in_wy;
    reg  [5:0] queue$in_sh;
    reg  [10:0] queue$in_first;
    reg  [10:0] queue$in_count;
    reg  queue$in_retire;
    wire  queue$out_valid;
    reg  queue$out_ready;
    wire  [15:0] queue$out_id;
    wire  [17:0] queue$out_ax;
    wire  [17:0] queue$out_ay;
    wire  [17:0] queue$out_bx;
    wire  [17:0] queue$out_by;
    wire  [17:0] queue$out_wx;
    wire  [17:0] queue$out_wy;
    wire  [5:0] queue$out_sh;
    wire  [10:0] queue$out_first;
    wire  [10:0] queue$out_count;
    wire  queue$out_retire;
    wire  queue$occupied;
    reg  screener$clock;
    reg  [16:0] screener$origin_x;
    reg  [16:0] screener$origin_y;
    reg  [17:0] screener$normal_x;
    reg  [17:0] screener$normal_y;
    reg  [17:0] screener$first_x;
    reg  [17:0] screener$first_y;
    reg  [17:0] screener$last_x;
    reg  [17:0] screener$last_y;
    reg  screener$in_valid;
    wire  screener$in_ready;
    reg  [15:0] screener$in_id;
    reg  [16:0] screener$in_ax;
    reg  [16:0] screener$in_ay;
    reg  [16:0] screener$in_bx;
    reg  [16:0] screener$in_by;
    reg  screener$in_bank;
    wire  screener$sector_read;
    wire  screener$sector_bank;
    wire  screener$normal_bank;
    wire  screener$out_valid;
    reg  screener$out_ready;
    wire  [15:0] screener$out_id;
    wire  [17:0] screener$out_ax;
    wire  [17:0] screener$out_ay;
    wire  [17:0] screener$out_bx;
    wire  [17:0] screener$out_by;
    wire  [17:0] screener$out_wx;
    wire  [17:0] screener$out_wy;
    wire  [5:0] screener$out_sh;
    wire  screener$out_pass;
    wire  [31:0] screener$passed;
    wire  [31:0] screener$backward;
    wire  [31:0] screener$back_facing;
    wire  [31:0] screener$outside;
    wire  [31:0] screener$near;
    reg  unit$clock;
    reg  unit$dir_we;
    reg  [10:0] unit$dir_addr;
    reg  [17:0] unit$dir_x;
    reg  [17:0] unit$dir_y;
    reg  unit$patch_valid;
    wire  unit$patch_ready;
    reg  [17:0] unit$patch_ax;
    reg  [17:0] unit$patch_ay;
    reg  [17:0] unit$patch_bx;
    reg  [17:0] unit$patch_by;
    reg  [17:0] unit$patch_wx;
    reg  [17:0] unit$patch_wy;
    reg  [5:0] unit$patch_sh;
    reg  [15:0] unit$patch_id;
    reg  [10:0] unit$patch_first;
    reg  [10:0] unit$patch_count;
    reg  unit$patch_retire;
    reg  unit$res_re;
    reg  [10:0] unit$res_addr;
    wire  unit$res_hit;
    wire  [15:0] unit$res_id;
    wire  [31:0] unit$res_key;
    wire  unit$busy;
    wire  [31:0] unit$tests;
    wire  [31:0] unit$marks;
    reg  tags$clock;
    reg  tags$push;
    reg  tags$pop;
    wire  [5:0] tags$tail_address;
    wire  [5:0] tags$head_address;
    wire  [5:0] tags$next_address;
    wire  tags$valid;
    wire  [6:0] tags$count;
    reg  tag_lane$clock;
    reg  [5:0] tag_lane$write_address;
    reg  [21:0] tag_lane$write_data;
    reg  tag_lane$write_enable;
    reg  [5:0] tag_lane$head_address;
    reg  [5:0] tag_lane$next_address;
    reg  tag_lane$pop;
    wire  [21:0] tag_lane$read_data;
    reg  tag_kind$clock;
    reg  [5:0] tag_kind$write_address;
    reg  tag_kind$write_data;
    reg  tag_kind$write_enable;
    reg  [5:0] tag_kind$head_address;
    reg  [5:0] tag_kind$next_address;
    reg  tag_kind$pop;
    wire  tag_kind$read_data;
    reg  job_banks$clock;
    reg  job_banks$push;
    reg  job_banks$pop;
    wire  [3:0] job_banks$tail_address;
    wire  [3:0] job_banks$head_address;
    wire  [3:0] job_banks$next_address;
    wire  job_banks$valid;
    wire  [4:0] job_banks$count;
    reg  job_bank$clock;
    reg  [3:0] job_bank$write_address;
    reg  job_bank$write_data;
    reg  job_bank$write_enable;
    reg  [3:0] job_bank$head_address;
    reg  [3:0] job_bank$next_address;
    reg  job_bank$pop;
    wire  job_bank$read_data;
    reg  job_origin_x$clock;
    reg  [3:0] job_origin_x$write_address;
    reg  [16:0] job_origin_x$write_data;
    reg  job_origin_x$write_enable;
    reg  [3:0] job_origin_x$head_address;
    reg  [3:0] job_origin_x$next_address;
    reg  job_origin_x$pop;
    wire  [16:0] job_origin_x$read_data;
    reg  job_origin_y$clock;
    reg  [3:0] job_origin_y$write_address;
    reg  [16:0] job_origin_y$write_data;
    reg  job_origin_y$write_enable;
    reg  [3:0] job_origin_y$head_address;
    reg  [3:0] job_origin_y$next_address;
    reg  job_origin_y$pop;
    wire  [16:0] job_origin_y$read_data;
    reg  bank$d;
    wire  bank$q;
    reg  bank$clock;
    reg  pend$d;
    wire  pend$q;
    reg  pend$clock;
    reg  [17:0] stg_first_x$d;
    wire  [17:0] stg_first_x$q;
    reg  stg_first_x$clock;
    reg  [17:0] stg_first_y$d;
    wire  [17:0] stg_first_y$q;
    reg  stg_first_y$clock;
    reg  [17:0] stg_last_x$d;
    wire  [17:0] stg_last_x$q;
    reg  stg_last_x$clock;
    reg  [17:0] stg_last_y$d;
    wire  [17:0] stg_last_y$q;
    reg  stg_last_y$clock;
    reg  [16:0] stg_origin_x$d;
    wire  [16:0] stg_origin_x$q;
    reg  stg_origin_x$clock;
    reg  [16:0] stg_origin_y$d;
    wire  [16:0] stg_origin_y$q;
    reg  stg_origin_y$clock;
    reg  [17:0] stg_normal_x$d;
    wire  [17:0] stg_normal_x$q;
    reg  stg_normal_x$clock;
    reg  [17:0] stg_normal_y$d;
    wire  [17:0] stg_normal_y$q;
    reg  stg_normal_y$clock;
    reg  load0$d;
    wire  load0$q;
    reg  load0$clock;
    reg  load1$d;
    wire  load1$q;
    reg  load1$clock;
    reg  [16:0] origin0_x$d;
    wire  [16:0] origin0_x$q;
    reg  origin0_x$clock;
    reg  [16:0] origin0_y$d;
    wire  [16:0] origin0_y$q;
    reg  origin0_y$clock;
    reg  [17:0] normal0_x$d;
    wire  [17:0] normal0_x$q;
    reg  normal0_x$clock;
    reg  [17:0] normal0_y$d;
    wire  [17:0] normal0_y$q;
    reg  normal0_y$clock;
    reg  [16:0] origin1_x$d;
    wire  [16:0] origin1_x$q;
    reg  origin1_x$clock;
    reg  [16:0] origin1_y$d;
    wire  [16:0] origin1_y$q;
    reg  origin1_y$clock;
    reg  [17:0] normal1_x$d;
    wire  [17:0] normal1_x$q;
    reg  normal1_x$clock;
    reg  [17:0] normal1_y$d;
    wire  [17:0] normal1_y$q;
    reg  normal1_y$clock;
    reg  [17:0] first0_x$d;
    wire  [17:0] first0_x$q;
    reg  first0_x$clock;
    reg  [17:0] first0_y$d;
    wire  [17:0] first0_y$q;
    reg  first0_y$clock;
    reg  [17:0] last0_x$d;
    wire  [17:0] last0_x$q;
    reg  last0_x$clock;
    reg  [17:0] last0_y$d;
    wire  [17:0] last0_y$q;
    reg  last0_y$clock;
    reg  [17:0] first1_x$d;
    wire  [17:0] first1_x$q;
    reg  first1_x$clock;
    reg  [17:0] first1_y$d;
    wire  [17:0] first1_y$q;
    reg  first1_y$clock;
    reg  [17:0] last1_x$d;
    wire  [17:0] last1_x$q;
    reg  last1_x$clock;
    reg  [17:0] last1_y$d;
    wire  [17:0] last1_y$q;
    reg  last1_y$clock;
    reg  [6:0] jobs0$d;
    wire  [6:0] jobs0$q;
    reg  jobs0$clock;
    reg  [6:0] jobs1$d;
    wire  [6:0] jobs1$q;
    reg  jobs1$clock;
    reg  used0$d;
    wire  used0$q;
    reg  used0$clock;
    reg  used1$d;
    wire  used1$q;
    reg  used1$clock;
    reg  tags_full$d;
    wire  tags_full$q;
    reg  tags_full$clock;
    reg  stall$d;
    wire  stall$q;
    reg  stall$clock;
    reg  other_busy$d;
    wire  other_busy$q;
    reg  other_busy$clock;
    reg  in0$d;
    wire  in0$q;
    reg  in0$clock;
    reg  in1$d;
    wire  in1$q;
    reg  in1$clock;
    
    // Local signals
    reg  head_job;
    reg  head_retire;
    reg  new_job;
    reg  accept;
    reg  pop;
    reg  [21:0] head_tag;
    reg  [10:0] head_first;
    reg  [10:0] head_count;
    reg  [21:0] new_tag;
    reg  job_pop;
    reg  room;
    reg  job;
    reg  tags_full_next;
    reg  bank_next;
    reg  used0_next;
    reg  used1_next;
    reg  sector_in;
    reg  take;
    reg  out0;
    reg  out1;
    reg  pend_next;
    
    // Sub module instances
    machine$pes$0$loader loader(
        .clock(loader$clock),
        .id_valid(loader$id_valid),
        .id_ready(loader$id_ready),
        .id(loader$id),
        .id_ready_next(loader$id_ready_next),
        .mem_req(loader$mem_req),
        .mem_addr(loader$mem_addr),
        .mem_valid(loader$mem_valid),
        .mem_ax(loader$mem_ax),
        .mem_ay(loader$mem_ay),
        .mem_bx(loader$mem_bx),
        .mem_by(loader$mem_by),
        .out_valid(loader$out_valid),
        .out_ready(loader$out_ready),
        .out_id(loader$out_id),
        .out_ax(loader$out_ax),
        .out_ay(loader$out_ay),
        .out_bx(loader$out_bx),
        .out_by(loader$out_by),
        .loads(loader$loads)
    );
    machine$pes$0$cache cache(
        .clock(cache$clock),
        .cfg_enable(cache$cfg_enable),
        .cfg_mask(cache$cfg_mask),
        .flush(cache$flush),
        .flushing(cache$flushing),
        .req(cache$req),
        .addr(cache$addr),
        .resp_valid(cache$resp_valid),
        .resp_ax(cache$resp_ax),
        .resp_ay(cache$resp_ay),
        .resp_bx(cache$resp_bx),
        .resp_by(cache$resp_by),
        .mem_req(cache$mem_req),
        .mem_addr(cache$mem_addr),
        .mem_valid(cache$mem_valid),
        .mem_ax(cache$mem_ax),
        .mem_ay(cache$mem_ay),
        .mem_bx(cache$mem_bx),
        .mem_by(cache$mem_by),
        .hits(cache$hits),
        .misses(cache$misses)
    );
    machine$pes$0$sc_slice sc_slice(
        .clock(sc_slice$clock),
        .in_valid(sc_slice$in_valid),
        .in_ready(sc_slice$in_ready),
        .in_id(sc_slice$in_id),
        .in_ax(sc_slice$in_ax),
        .in_ay(sc_slice$in_ay),
        .in_bx(sc_slice$in_bx),
        .in_by(sc_slice$in_by),
        .in_wx(sc_slice$in_wx),
        .in_wy(sc_slice$in_wy),
        .in_sh(sc_slice$in_sh),
        .in_pass(sc_slice$in_pass),
        .in_first(sc_slice$in_first),
        .in_count(sc_slice$in_count),
        .in_retire(sc_slice$in_retire),
        .out_valid(sc_slice$out_valid),
        .out_ready(sc_slice$out_ready),
        .out_id(sc_slice$out_id),
        .out_ax(sc_slice$out_ax),
        .out_ay(sc_slice$out_ay),
        .out_bx(sc_slice$out_bx),
        .out_by(sc_slice$out_by),
        .out_wx(sc_slice$out_wx),
        .out_wy(sc_slice$out_wy),
        .out_sh(sc_slice$out_sh),
        .out_pass(sc_slice$out_pass),
        .out_first(sc_slice$out_first),
        .out_count(sc_slice$out_count),
        .out_retire(sc_slice$out_retire),
        .occupied(sc_slice$occupied)
    );
    machine$pes$0$queue queue(
        .clock(queue$clock),
        .in_valid(queue$in_valid),
        .in_ready(queue$in_ready),
        .in_id(queue$in_id),
        .in_ax(queue$in_ax),
        .in_ay(queue$in_ay),
        .in_bx(queue$in_bx),
        .in_by(queue$in_by),
        .in_wx(queue$in_wx),
        .in_wy(queue$in_wy),
        .in_sh(queue$in_sh),
        .in_first(queue$in_first),
        .in_count(queue$in_count),
        .in_retire(queue$in_retire),
        .out_valid(queue$out_valid),
        .out_ready(queue$out_ready),
        .out_id(queue$out_id),
        .out_ax(queue$out_ax),
        .out_ay(queue$out_ay),
        .out_bx(queue$out_bx),
        .out_by(queue$out_by),
        .out_wx(queue$out_wx),
        .out_wy(queue$out_wy),
        .out_sh(queue$out_sh),
        .out_first(queue$out_first),
        .out_count(queue$out_count),
        .out_retire(queue$out_retire),
        .occupied(queue$occupied)
    );
    machine$pes$0$screener screener(
        .clock(screener$clock),
        .origin_x(screener$origin_x),
        .origin_y(screener$origin_y),
        .normal_x(screener$normal_x),
        .normal_y(screener$normal_y),
        .first_x(screener$first_x),
        .first_y(screener$first_y),
        .last_x(screener$last_x),
        .last_y(screener$last_y),
        .in_valid(screener$in_valid),
        .in_ready(screener$in_ready),
        .in_id(screener$in_id),
        .in_ax(screener$in_ax),
        .in_ay(screener$in_ay),
        .in_bx(screener$in_bx),
        .in_by(screener$in_by),
        .in_bank(screener$in_bank),
        .sector_read(screener$sector_read),
        .sector_bank(screener$sector_bank),
        .normal_bank(screener$normal_bank),
        .out_valid(screener$out_valid),
        .out_ready(screener$out_ready),
        .out_id(screener$out_id),
        .out_ax(screener$out_ax),
        .out_ay(screener$out_ay),
        .out_bx(screener$out_bx),
        .out_by(screener$out_by),
        .out_wx(screener$out_wx),
        .out_wy(screener$out_wy),
        .out_sh(screener$out_sh),
        .out_pass(screener$out_pass),
        .passed(screener$passed),
        .backward(screener$backward),
        .back_facing(screener$back_facing),
        .outside(screener$outside),
        .near(screener$near)
    );
    machine$pes$0$unit unit(
        .clock(unit$clock),
        .dir_we(unit$dir_we),
        .dir_addr(unit$dir_addr),
        .dir_x(unit$dir_x),
        .dir_y(unit$dir_y),
        .patch_valid(unit$patch_valid),
        .patch_ready(unit$patch_ready),
        .patch_ax(unit$patch_ax),
        .patch_ay(unit$patch_ay),
        .patch_bx(unit$patch_bx),
        .patch_by(unit$patch_by),
        .patch_wx(unit$patch_wx),
        .patch_wy(unit$patch_wy),
        .patch_sh(unit$patch_sh),
        .patch_id(unit$patch_id),
        .patch_first(unit$patch_first),
        .patch_count(unit$patch_count),
        .patch_retire(unit$patch_retire),
        .res_re(unit$res_re),
        .res_addr(unit$res_addr),
        .res_hit(unit$res_hit),
        .res_id(unit$res_id),
        .res_key(unit$res_key),
        .busy(unit$busy),
        .tests(unit$tests),
        .marks(unit$marks)
    );
    machine$pes$0$tags tags(
        .clock(tags$clock),
        .push(tags$push),
        .pop(tags$pop),
        .tail_address(tags$tail_address),
        .head_address(tags$head_address),
        .next_address(tags$next_address),
        .valid(tags$valid),
        .count(tags$count)
    );
    machine$pes$0$tag_lane tag_lane(
        .clock(tag_lane$clock),
        .write_address(tag_lane$write_address),
        .write_data(tag_lane$write_data),
        .write_enable(tag_lane$write_enable),
        .head_address(tag_lane$head_address),
        .next_address(tag_lane$next_address),
        .pop(tag_lane$pop),
        .read_data(tag_lane$read_data)
    );
    machine$pes$0$tag_kind tag_kind(
        .clock(tag_kind$clock),
        .write_address(tag_kind$write_address),
        .write_data(tag_kind$write_data),
        .write_enable(tag_kind$write_enable),
        .head_address(tag_kind$head_address),
        .next_address(tag_kind$next_address),
        .pop(tag_kind$pop),
        .read_data(tag_kind$read_data)
    );
    machine$pes$0$job_banks job_banks(
        .clock(job_banks$clock),
        .push(job_banks$push),
        .pop(job_banks$pop),
        .tail_address(job_banks$tail_address),
        .head_address(job_banks$head_address),
        .next_address(job_banks$next_address),
        .valid(job_banks$valid),
        .count(job_banks$count)
    );
    machine$pes$0$job_bank job_bank(
        .clock(job_bank$clock),
        .write_address(job_bank$write_address),
        .write_data(job_bank$write_data),
        .write_enable(job_bank$write_enable),
        .head_address(job_bank$head_address),
        .next_address(job_bank$next_address),
        .pop(job_bank$pop),
        .read_data(job_bank$read_data)
    );
    machine$pes$0$job_origin_x job_origin_x(
        .clock(job_origin_x$clock),
        .write_address(job_origin_x$write_address),
        .write_data(job_origin_x$write_data),
        .write_enable(job_origin_x$write_enable),
        .head_address(job_origin_x$head_address),
        .next_address(job_origin_x$next_address),
        .pop(job_origin_x$pop),
        .read_data(job_origin_x$read_data)
    );
    machine$pes$0$job_origin_y job_origin_y(
        .clock(job_origin_y$clock),
        .write_address(job_origin_y$write_address),
        .write_data(job_origin_y$write_data),
        .write_enable(job_origin_y$write_enable),
        .head_address(job_origin_y$head_address),
        .next_address(job_origin_y$next_address),
        .pop(job_origin_y$pop),
        .read_data(job_origin_y$read_data)
    );
    machine$pes$0$bank bank(
        .d(bank$d),
        .q(bank$q),
        .clock(bank$clock)
    );
    machine$pes$0$pend pend(
        .d(pend$d),
        .q(pend$q),
        .clock(pend$clock)
    );
    machine$pes$0$stg_first_x stg_first_x(
        .d(stg_first_x$d),
        .q(stg_first_x$q),
        .clock(stg_first_x$clock)
    );
    machine$pes$0$stg_first_y stg_first_y(
        .d(stg_first_y$d),
        .q(stg_first_y$q),
        .clock(stg_first_y$clock)
    );
    machine$pes$0$stg_last_x stg_last_x(
        .d(stg_last_x$d),
        .q(stg_last_x$q),
        .clock(stg_last_x$clock)
    );
    machine$pes$0$stg_last_y stg_last_y(
        .d(stg_last_y$d),
        .q(stg_last_y$q),
        .clock(stg_last_y$clock)
    );
    machine$pes$0$stg_origin_x stg_origin_x(
        .d(stg_origin_x$d),
        .q(stg_origin_x$q),
        .clock(stg_origin_x$clock)
    );
    machine$pes$0$stg_origin_y stg_origin_y(
        .d(stg_origin_y$d),
        .q(stg_origin_y$q),
        .clock(stg_origin_y$clock)
    );
    machine$pes$0$stg_normal_x stg_normal_x(
        .d(stg_normal_x$d),
        .q(stg_normal_x$q),
        .clock(stg_normal_x$clock)
    );
    machine$pes$0$stg_normal_y stg_normal_y(
        .d(stg_normal_y$d),
        .q(stg_normal_y$q),
        .clock(stg_normal_y$clock)
    );
    machine$pes$0$load0 load0(
        .d(load0$d),
        .q(load0$q),
        .clock(load0$clock)
    );
    machine$pes$0$load1 load1(
        .d(load1$d),
        .q(load1$q),
        .clock(load1$clock)
    );
    machine$pes$0$origin0_x origin0_x(
        .d(origin0_x$d),
        .q(origin0_x$q),
        .clock(origin0_x$clock)
    );
    machine$pes$0$origin0_y origin0_y(
        .d(origin0_y$d),
        .q(origin0_y$q),
        .clock(origin0_y$clock)
    );
    machine$pes$0$normal0_x normal0_x(
        .d(normal0_x$d),
        .q(normal0_x$q),
        .clock(normal0_x$clock)
    );
    machine$pes$0$normal0_y normal0_y(
        .d(normal0_y$d),
        .q(normal0_y$q),
        .clock(normal0_y$clock)
    );
    machine$pes$0$origin1_x origin1_x(
        .d(origin1_x$d),
        .q(origin1_x$q),
        .clock(origin1_x$clock)
    );
    machine$pes$0$origin1_y origin1_y(
        .d(origin1_y$d),
        .q(origin1_y$q),
        .clock(origin1_y$clock)
    );
    machine$pes$0$normal1_x normal1_x(
        .d(normal1_x$d),
        .q(normal1_x$q),
        .clock(normal1_x$clock)
    );
    machine$pes$0$normal1_y normal1_y(
        .d(normal1_y$d),
        .q(normal1_y$q),
        .clock(normal1_y$clock)
    );
    machine$pes$0$first0_x first0_x(
        .d(first0_x$d),
        .q(first0_x$q),
        .clock(first0_x$clock)
    );
    machine$pes$0$first0_y first0_y(
        .d(first0_y$d),
        .q(first0_y$q),
        .clock(first0_y$clock)
    );
    machine$pes$0$last0_x last0_x(
        .d(last0_x$d),
        .q(last0_x$q),
        .clock(last0_x$clock)
    );
    machine$pes$0$last0_y last0_y(
        .d(last0_y$d),
        .q(last0_y$q),
        .clock(last0_y$clock)
    );
    machine$pes$0$first1_x first1_x(
        .d(first1_x$d),
        .q(first1_x$q),
        .clock(first1_x$clock)
    );
    machine$pes$0$first1_y first1_y(
        .d(first1_y$d),
        .q(first1_y$q),
        .clock(first1_y$clock)
    );
    machine$pes$0$last1_x last1_x(
        .d(last1_x$d),
        .q(last1_x$q),
        .clock(last1_x$clock)
    );
    machine$pes$0$last1_y last1_y(
        .d(last1_y$d),
        .q(last1_y$q),
        .clock(last1_y$clock)
    );
    machine$pes$0$jobs0 jobs0(
        .d(jobs0$d),
        .q(jobs0$q),
        .clock(jobs0$clock)
    );
    machine$pes$0$jobs1 jobs1(
        .d(jobs1$d),
        .q(jobs1$q),
        .clock(jobs1$clock)
    );
    machine$pes$0$used0 used0(
        .d(used0$d),
        .q(used0$q),
        .clock(used0$clock)
    );
    machine$pes$0$used1 used1(
        .d(used1$d),
        .q(used1$q),
        .clock(used1$clock)
    );
    machine$pes$0$tags_full tags_full(
        .d(tags_full$d),
        .q(tags_full$q),
        .clock(tags_full$clock)
    );
    machine$pes$0$stall stall(
        .d(stall$d),
        .q(stall$q),
        .clock(stall$clock)
    );
    machine$pes$0$other_busy other_busy(
        .d(other_busy$d),
        .q(other_busy$q),
        .clock(other_busy$clock)
    );
    machine$pes$0$in0 in0(
        .d(in0$d),
        .q(in0$q),
        .clock(in0$clock)
    );
    machine$pes$0$in1 in1(
        .d(in1$d),
        .q(in1$q),
        .clock(in1$clock)
    );
    
    // Update code
    always @(*) begin
        bank$clock = clock;
        other_busy$clock = clock;
        pend$clock = clock;
        stg_first_x$clock = clock;
        stg_first_y$clock = clock;
        stg_last_x$clock = clock;
        stg_last_y$clock = clock;
        stg_origin_x$clock = clock;
        stg_origin_y$clock = clock;
        stg_normal_x$clock = clock;
        stg_normal_y$clock = clock;
        load0$clock = clock;
        load1$clock = clock;
        origin0_x$clock = clock;
        origin0_y$clock = clock;
        normal0_x$clock = clock;
        normal0_y$clock = clock;
        origin1_x$clock = clock;
        origin1_y$clock = clock;
        normal1_x$clock = clock;
        normal1_y$clock = clock;
        first0_x$clock = clock;
        first0_y$clock = clock;
        last0_x$clock = clock;
        last0_y$clock = clock;
        first1_x$clock = clock;
        first1_y$clock = clock;
        last1_x$clock = clock;
        last1_y$clock = clock;
        jobs0$clock = clock;
        jobs1$clock = clock;
        used0$clock = clock;
        used1$clock = clock;
        in0$clock = clock;
        in1$clock = clock;
        tags_full$clock = clock;
        stall$clock = clock;
        bank$d = bank$q;
        other_busy$d = other_busy$q;
        pend$d = pend$q;
        stg_first_x$d = stg_first_x$q;
        stg_first_y$d = stg_first_y$q;
        stg_last_x$d = stg_last_x$q;
        stg_last_y$d = stg_last_y$q;
        stg_origin_x$d = stg_origin_x$q;
        stg_origin_y$d = stg_origin_y$q;
        stg_normal_x$d = stg_normal_x$q;
        stg_normal_y$d = stg_normal_y$q;
        load0$d = load0$q;
        load1$d = load1$q;
        origin0_x$d = origin0_x$q;
        origin0_y$d = origin0_y$q;
        normal0_x$d = normal0_x$q;
        normal0_y$d = normal0_y$q;
        origin1_x$d = origin1_x$q;
        origin1_y$d = origin1_y$q;
        normal1_x$d = normal1_x$q;
        normal1_y$d = normal1_y$q;
        first0_x$d = first0_x$q;
        first0_y$d = first0_y$q;
        last0_x$d = last0_x$q;
        last0_y$d = last0_y$q;
        first1_x$d = first1_x$q;
        first1_y$d = first1_y$q;
        last1_x$d = last1_x$q;
        last1_y$d = last1_y$q;
        jobs0$d = jobs0$q;
        jobs1$d = jobs1$q;
        used0$d = used0$q;
        used1$d = used1$q;
        in0$d = in0$q;
        in1$d = in1$q;
        tags_full$d = tags_full$q;
        stall$d = stall$q;
        job_banks$clock = clock;
        job_bank$clock = clock;
        job_origin_x$clock = clock;
        job_origin_y$clock = clock;
        loader$clock = clock;
        cache$clock = clock;
        screener$clock = clock;
        unit$clock = clock;
        sc_slice$clock = clock;
        queue$clock = clock;
        tags$clock = clock;
        tag_lane$clock = clock;
        tag_kind$clock = clock;
        unit$dir_we = dir_we;
        unit$dir_addr = dir_addr;
        unit$dir_x = dir_x;
        unit$dir_y = dir_y;
        unit$res_re = res_re;
        unit$res_addr = res_addr;
        res_hit = unit$res_hit;
        res_id = unit$res_id;
        res_key = unit$res_key;
        screener$origin_x = job_origin_x$read_data;
        screener$origin_y = job_origin_y$read_data;
        screener$normal_x = normal0_x$q;
        screener$normal_y = normal0_y$q;
        if (screener$normal_bank) begin
            screener$normal_x = normal1_x$q;
            screener$normal_y = normal1_y$q;
        end
        screener$first_x = first0_x$q;
        screener$first_y = first0_y$q;
        screener$last_x = last0_x$q;
        screener$last_y = last0_y$q;
        if (screener$sector_bank) begin
            screener$first_x = first1_x$q;
            screener$first_y = first1_y$q;
            screener$last_x = last1_x$q;
            screener$last_y = last1_y$q;
        end
        room = ~stall$q;
        cmd_ready = room;
        accept = cmd_valid & room;
        job = accept & ~cmd_retire & ~cmd_sector;
        loader$id_valid = job;
        loader$id = cmd_id;
        job_banks$push = job;
        job_pop = loader$out_valid & screener$in_ready;
        job_banks$pop = job_pop;
        job_bank$write_data = zero1;
        job_origin_x$write_data = origin0_x$q;
        job_origin_y$write_data = origin0_y$q;
        if (bank$q) begin
            job_bank$write_data = one1;
            job_origin_x$write_data = origin1_x$q;
            job_origin_y$write_data = origin1_y$q;
        end
        if (load0$q | load1$q) begin
            job_origin_x$write_data = stg_origin_x$q;
            job_origin_y$write_data = stg_origin_y$q;
        end
        job_bank$write_address = job_banks$tail_address;
        job_bank$write_enable = job;
        job_bank$head_address = job_banks$head_address;
        job_bank$next_address = job_banks$next_address;
        job_bank$pop = job_pop;
        job_origin_x$write_address = job_banks$tail_address;
        job_origin_x$write_enable = job;
        job_origin_x$head_address = job_banks$head_address;
        job_origin_x$next_address = job_banks$next_address;
        job_origin_x$pop = job_pop;
        job_origin_y$write_address = job_banks$tail_address;
        job_origin_y$write_enable = job;
        job_origin_y$head_address = job_banks$head_address;
        job_origin_y$next_address = job_banks$next_address;
        job_origin_y$pop = job_pop;
        screener$in_bank = job_bank$read_data == one1;
        sector_in = accept & cmd_sector;
        if (~pend$q) begin
            stg_first_x$d = first_x;
            stg_first_y$d = first_y;
            stg_last_x$d = last_x;
            stg_last_y$d = last_y;
            stg_origin_x$d = origin_x;
            stg_origin_y$d = origin_y;
            stg_normal_x$d = normal_x;
            stg_normal_y$d = normal_y;
        end
        pend_next = pend$q;
        if (sector_in & other_busy$q) begin
            pend_next = 1'b1;
        end
        take = (sector_in | pend$q) & ~other_busy$q;
        bank_next = bank$q;
        if (take) begin
            pend_next = 1'b0;
            bank_next = ~bank$q;
        end
        load0$d = take & bank$q;
        load1$d = take & ~bank$q;
        if (load0$q) begin
            first0_x$d = stg_first_x$q;
            first0_y$d = stg_first_y$q;
            last0_x$d = stg_last_x$q;
            last0_y$d = stg_last_y$q;
            origin0_x$d = stg_origin_x$q;
            origin0_y$d = stg_origin_y$q;
            normal0_x$d = stg_normal_x$q;
            normal0_y$d = stg_normal_y$q;
        end
        if (load1$q) begin
            first1_x$d = stg_first_x$q;
            first1_y$d = stg_first_y$q;
            last1_x$d = stg_last_x$q;
            last1_y$d = stg_last_y$q;
            origin1_x$d = stg_origin_x$q;
            origin1_y$d = stg_origin_y$q;
            normal1_x$d = stg_normal_x$q;
            normal1_y$d = stg_normal_y$q;
        end
        pend$d = pend_next;
        bank$d = bank_next;
        in0$d = job & ~bank$q;
        in1$d = job & bank$q;
        out0 = screener$sector_read & ~screener$sector_bank;
        out1 = screener$sector_read & screener$sector_bank;
        if (in0$q & ~out0) begin
            jobs0$d = jobs0$q + one7;
        end
        if (out0 & ~in0$q & (jobs0$q != zero7)) begin
            jobs0$d = jobs0$q - one7;
        end
        if (in1$q & ~out1) begin
            jobs1$d = jobs1$q + one7;
        end
        if (out1 & ~in1$q & (jobs1$q != zero7)) begin
            jobs1$d = jobs1$q - one7;
        end
        used0_next = used0$q;
        if (in0$q & ~out0) begin
            used0_next = 1'b1;
        end
        if (out0 & ~in0$q & (jobs0$q == one7)) begin
            used0_next = 1'b0;
        end
        used1_next = used1$q;
        if (in1$q & ~out1) begin
            used1_next = 1'b1;
        end
        if (out1 & ~in1$q & (jobs1$q == one7)) begin
            used1_next = 1'b0;
        end
        used0$d = used0_next;
        used1$d = used1_next;
        other_busy$d = used1_next;
        if (bank_next) begin
            other_busy$d = used0_next;
        end
        new_tag = (((cmd_first) & 22'h3fffff) << 32'hb) | ((cmd_count) & 22'h3fffff);
        tags$push = accept & ~cmd_sector;
        tag_lane$write_data = new_tag;
        tag_lane$write_enable = ~tags_full$q;
        tag_lane$write_address = tags$tail_address;
        tag_lane$head_address = tags$head_address;
        tag_lane$next_address = tags$next_address;
        new_job = one1;
        if (cmd_retire) begin
            new_job = zero1;
        end
        tag_kind$write_data = new_job;
        tag_kind$write_enable = ~tags_full$q;
        tag_kind$write_address = tags$tail_address;
        tag_kind$head_address = tags$head_address;
        tag_kind$next_address = tags$next_address;
        cache$cfg_enable = cfg_cache_enable;
        cache$cfg_mask = cfg_cache_mask;
        cache$flush = cfg_cache_flush;
        cache$req = loader$mem_req;
        cache$addr = loader$mem_addr;
        loader$mem_valid = cache$resp_valid;
        loader$mem_ax = cache$resp_ax;
        loader$mem_ay = cache$resp_ay;
        loader$mem_bx = cache$resp_bx;
        loader$mem_by = cache$resp_by;
        mem_req = cache$mem_req;
        mem_addr = cache$mem_addr;
        cache$mem_valid = mem_valid;
        cache$mem_ax = mem_ax;
        cache$mem_ay = mem_ay;
        cache$mem_bx = mem_bx;
        cache$mem_by = mem_by;
        screener$in_valid = loader$out_valid;
        loader$out_ready = screener$in_ready;
        screener$in_id = loader$out_id;
        screener$in_ax = loader$out_ax;
        screener$in_ay = loader$out_ay;
        screener$in_bx = loader$out_bx;
        screener$in_by = loader$out_by;
        sc_slice$in_valid = screener$out_valid;
        screener$out_ready = sc_slice$in_ready;
        sc_slice$in_id = screener$out_id;
        sc_slice$in_ax = screener$out_ax;
        sc_slice$in_ay = screener$out_ay;
        sc_slice$in_bx = screener$out_bx;
        sc_slice$in_by = screener$out_by;
        sc_slice$in_wx = screener$out_wx;
        sc_slice$in_wy = screener$out_wy;
        sc_slice$in_sh = screener$out_sh;
        sc_slice$in_pass = screener$out_pass;
        sc_slice$in_first = 32'h0;
        sc_slice$in_count = 32'h0;
        sc_slice$in_retire = 1'b0;
        head_tag = tag_lane$read_data;
        head_job = tags$valid & |tag_kind$read_data;
        head_retire = tags$valid & ~|tag_kind$read_data;
        head_first = head_tag[(32'hb)+:(11)];
        head_count = head_tag[(32'h0)+:(11)];
        queue$in_id = sc_slice$out_id;
        queue$in_ax = sc_slice$out_ax;
        queue$in_ay = sc_slice$out_ay;
        queue$in_bx = sc_slice$out_bx;
        queue$in_by = sc_slice$out_by;
        queue$in_wx = sc_slice$out_wx;
        queue$in_wy = sc_slice$out_wy;
        queue$in_sh = sc_slice$out_sh;
        queue$in_first = head_first;
        queue$in_count = head_count;
        queue$in_retire = head_retire;
        queue$in_valid = 1'b0;
        sc_slice$out_ready = 1'b0;
        pop = 1'b0;
        if (head_retire) begin
            queue$in_valid = 1'b1;
            pop = queue$in_ready;
        end
        if (head_job & sc_slice$out_valid) begin
            if (sc_slice$out_pass) begin
                queue$in_valid = 1'b1;
                sc_slice$out_ready = queue$in_ready;
                pop = queue$in_ready;
            end
            else begin
                sc_slice$out_ready = 1'b1;
                pop = 1'b1;
            end
        end
        unit$patch_valid = queue$out_valid;
        queue$out_ready = unit$patch_ready;
        unit$patch_id = queue$out_id;
        unit$patch_ax = queue$out_ax;
        unit$patch_ay = queue$out_ay;
        unit$patch_bx = queue$out_bx;
        unit$patch_by = queue$out_by;
        unit$patch_wx = queue$out_wx;
        unit$patch_wy = queue$out_wy;
        unit$patch_sh = queue$out_sh;
        unit$patch_first = queue$out_first;
        unit$patch_count = queue$out_count;
        unit$patch_retire = queue$out_retire;
        tags$pop = pop;
        tag_lane$pop = pop;
        tag_kind$pop = pop;
        tags_full_next = ((tags$count == full) & ~pop) | ((tags$count == almost_full) & accept & ~cmd_sector & ~pop);
        tags_full$d = tags_full_next;
        stall$d = tags_full_next | ~loader$id_ready_next | pend_next;
        busy = (tags$count != zero7) | pend$q | queue$occupied | unit$busy | cache$flushing;
        loads = loader$loads;
        cache_hits = cache$hits;
        cache_misses = cache$misses;
        passed = screener$passed;
        backward = screener$backward;
        back_facing = screener$back_facing;
        outside = screener$outside;
        near = screener$near;
        tests = unit$tests;
        marks = unit$marks;
    end
    
endmodule // machine$pes$0


module machine$pes$0$bank(d,q,clock);
    
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
          
endmodule // machine$pes$0$bank


module machine$pes$0$cache(clock,cfg_enable,cfg_mask,flush,flushing,req,addr,resp_valid,resp_ax,resp_ay,resp_bx,resp_by,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,hits,misses);
    
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
    machine$pes$0$cache$q_lane q_lane(
        .clock(q_lane$clock),
        .read_address(q_lane$read_address),
        .read_data(q_lane$read_data),
        .write_address(q_lane$write_address),
        .write_data(q_lane$write_data),
        .write_enable(q_lane$write_enable)
    );
    machine$pes$0$cache$wr_ptr wr_ptr(
        .d(wr_ptr$d),
        .q(wr_ptr$q),
        .clock(wr_ptr$clock)
    );
    machine$pes$0$cache$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$cache$sp sp(
        .d(sp$d),
        .q(sp$q),
        .clock(sp$clock)
    );
    machine$pes$0$cache$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$cache$sp_inc_x sp_inc_x(
        .d(sp_inc_x$d),
        .q(sp_inc_x$q),
        .clock(sp_inc_x$clock)
    );
    machine$pes$0$cache$q_valid q_valid(
        .d(q_valid$d),
        .q(q_valid$q),
        .clock(q_valid$clock)
    );
    machine$pes$0$cache$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    machine$pes$0$cache$id1 id1(
        .d(id1$d),
        .q(id1$q),
        .clock(id1$clock)
    );
    machine$pes$0$cache$key1 key1(
        .d(key1$d),
        .q(key1$q),
        .clock(key1$clock)
    );
    machine$pes$0$cache$line1 line1(
        .d(line1$d),
        .q(line1$q),
        .clock(line1$clock)
    );
    machine$pes$0$cache$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    machine$pes$0$cache$id2 id2(
        .d(id2$d),
        .q(id2$q),
        .clock(id2$clock)
    );
    machine$pes$0$cache$key2 key2(
        .d(key2$d),
        .q(key2$q),
        .clock(key2$clock)
    );
    machine$pes$0$cache$line2 line2(
        .d(line2$d),
        .q(line2$q),
        .clock(line2$clock)
    );
    machine$pes$0$cache$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    machine$pes$0$cache$id3 id3(
        .d(id3$d),
        .q(id3$q),
        .clock(id3$clock)
    );
    machine$pes$0$cache$line3 line3(
        .d(line3$d),
        .q(line3$q),
        .clock(line3$clock)
    );
    machine$pes$0$cache$match3 match3(
        .d(match3$d),
        .q(match3$q),
        .clock(match3$clock)
    );
    machine$pes$0$cache$lconf3 lconf3(
        .d(lconf3$d),
        .q(lconf3$q),
        .clock(lconf3$clock)
    );
    machine$pes$0$cache$iconf3 iconf3(
        .d(iconf3$d),
        .q(iconf3$q),
        .clock(iconf3$clock)
    );
    machine$pes$0$cache$ax3 ax3(
        .d(ax3$d),
        .q(ax3$q),
        .clock(ax3$clock)
    );
    machine$pes$0$cache$ay3 ay3(
        .d(ay3$d),
        .q(ay3$q),
        .clock(ay3$clock)
    );
    machine$pes$0$cache$bx3 bx3(
        .d(bx3$d),
        .q(bx3$q),
        .clock(bx3$clock)
    );
    machine$pes$0$cache$by3 by3(
        .d(by3$d),
        .q(by3$q),
        .clock(by3$clock)
    );
    machine$pes$0$cache$t_id0 t_id0(
        .d(t_id0$d),
        .q(t_id0$q),
        .clock(t_id0$clock)
    );
    machine$pes$0$cache$t_id1 t_id1(
        .d(t_id1$d),
        .q(t_id1$q),
        .clock(t_id1$clock)
    );
    machine$pes$0$cache$t_id2 t_id2(
        .d(t_id2$d),
        .q(t_id2$q),
        .clock(t_id2$clock)
    );
    machine$pes$0$cache$t_id3 t_id3(
        .d(t_id3$d),
        .q(t_id3$q),
        .clock(t_id3$clock)
    );
    machine$pes$0$cache$t_line0 t_line0(
        .d(t_line0$d),
        .q(t_line0$q),
        .clock(t_line0$clock)
    );
    machine$pes$0$cache$t_line1 t_line1(
        .d(t_line1$d),
        .q(t_line1$q),
        .clock(t_line1$clock)
    );
    machine$pes$0$cache$t_line2 t_line2(
        .d(t_line2$d),
        .q(t_line2$q),
        .clock(t_line2$clock)
    );
    machine$pes$0$cache$t_line3 t_line3(
        .d(t_line3$d),
        .q(t_line3$q),
        .clock(t_line3$clock)
    );
    machine$pes$0$cache$t_v0 t_v0(
        .d(t_v0$d),
        .q(t_v0$q),
        .clock(t_v0$clock)
    );
    machine$pes$0$cache$t_v1 t_v1(
        .d(t_v1$d),
        .q(t_v1$q),
        .clock(t_v1$clock)
    );
    machine$pes$0$cache$t_v2 t_v2(
        .d(t_v2$d),
        .q(t_v2$q),
        .clock(t_v2$clock)
    );
    machine$pes$0$cache$t_v3 t_v3(
        .d(t_v3$d),
        .q(t_v3$q),
        .clock(t_v3$clock)
    );
    machine$pes$0$cache$t_any t_any(
        .d(t_any$d),
        .q(t_any$q),
        .clock(t_any$clock)
    );
    machine$pes$0$cache$t_n t_n(
        .d(t_n$d),
        .q(t_n$q),
        .clock(t_n$clock)
    );
    machine$pes$0$cache$t_full t_full(
        .d(t_full$d),
        .q(t_full$q),
        .clock(t_full$clock)
    );
    machine$pes$0$cache$t_wp t_wp(
        .d(t_wp$d),
        .q(t_wp$q),
        .clock(t_wp$clock)
    );
    machine$pes$0$cache$t_rp t_rp(
        .d(t_rp$d),
        .q(t_rp$q),
        .clock(t_rp$clock)
    );
    machine$pes$0$cache$f_id1 f_id1(
        .d(f_id1$d),
        .q(f_id1$q),
        .clock(f_id1$clock)
    );
    machine$pes$0$cache$f_line1 f_line1(
        .d(f_line1$d),
        .q(f_line1$q),
        .clock(f_line1$clock)
    );
    machine$pes$0$cache$f_v1 f_v1(
        .d(f_v1$d),
        .q(f_v1$q),
        .clock(f_v1$clock)
    );
    machine$pes$0$cache$mi0 mi0(
        .d(mi0$d),
        .q(mi0$q),
        .clock(mi0$clock)
    );
    machine$pes$0$cache$mi1 mi1(
        .d(mi1$d),
        .q(mi1$q),
        .clock(mi1$clock)
    );
    machine$pes$0$cache$mi2 mi2(
        .d(mi2$d),
        .q(mi2$q),
        .clock(mi2$clock)
    );
    machine$pes$0$cache$mi3 mi3(
        .d(mi3$d),
        .q(mi3$q),
        .clock(mi3$clock)
    );
    machine$pes$0$cache$mif mif(
        .d(mif$d),
        .q(mif$q),
        .clock(mif$clock)
    );
    machine$pes$0$cache$mis3 mis3(
        .d(mis3$d),
        .q(mis3$q),
        .clock(mis3$clock)
    );
    machine$pes$0$cache$mis2 mis2(
        .d(mis2$d),
        .q(mis2$q),
        .clock(mis2$clock)
    );
    machine$pes$0$cache$ml0 ml0(
        .d(ml0$d),
        .q(ml0$q),
        .clock(ml0$clock)
    );
    machine$pes$0$cache$ml1 ml1(
        .d(ml1$d),
        .q(ml1$q),
        .clock(ml1$clock)
    );
    machine$pes$0$cache$ml2 ml2(
        .d(ml2$d),
        .q(ml2$q),
        .clock(ml2$clock)
    );
    machine$pes$0$cache$ml3 ml3(
        .d(ml3$d),
        .q(ml3$q),
        .clock(ml3$clock)
    );
    machine$pes$0$cache$mlf mlf(
        .d(mlf$d),
        .q(mlf$q),
        .clock(mlf$clock)
    );
    machine$pes$0$cache$mls3 mls3(
        .d(mls3$d),
        .q(mls3$q),
        .clock(mls3$clock)
    );
    machine$pes$0$cache$mls2 mls2(
        .d(mls2$d),
        .q(mls2$q),
        .clock(mls2$clock)
    );
    machine$pes$0$cache$ans ans(
        .clock(ans$clock),
        .push(ans$push),
        .pop(ans$pop),
        .tail_address(ans$tail_address),
        .head_address(ans$head_address),
        .next_address(ans$next_address),
        .valid(ans$valid),
        .count(ans$count)
    );
    machine$pes$0$cache$ans_ax ans_ax(
        .clock(ans_ax$clock),
        .write_address(ans_ax$write_address),
        .write_data(ans_ax$write_data),
        .write_enable(ans_ax$write_enable),
        .head_address(ans_ax$head_address),
        .next_address(ans_ax$next_address),
        .pop(ans_ax$pop),
        .read_data(ans_ax$read_data)
    );
    machine$pes$0$cache$ans_ay ans_ay(
        .clock(ans_ay$clock),
        .write_address(ans_ay$write_address),
        .write_data(ans_ay$write_data),
        .write_enable(ans_ay$write_enable),
        .head_address(ans_ay$head_address),
        .next_address(ans_ay$next_address),
        .pop(ans_ay$pop),
        .read_data(ans_ay$read_data)
    );
    machine$pes$0$cache$ans_bx ans_bx(
        .clock(ans_bx$clock),
        .write_address(ans_bx$write_address),
        .write_data(ans_bx$write_data),
        .write_enable(ans_bx$write_enable),
        .head_address(ans_bx$head_address),
        .next_address(ans_bx$next_address),
        .pop(ans_bx$pop),
        .read_data(ans_bx$read_data)
    );
    machine$pes$0$cache$ans_by ans_by(
        .clock(ans_by$clock),
        .write_address(ans_by$write_address),
        .write_data(ans_by$write_data),
        .write_enable(ans_by$write_enable),
        .head_address(ans_by$head_address),
        .next_address(ans_by$next_address),
        .pop(ans_by$pop),
        .read_data(ans_by$read_data)
    );
    machine$pes$0$cache$ans_meta ans_meta(
        .clock(ans_meta$clock),
        .write_address(ans_meta$write_address),
        .write_data(ans_meta$write_data),
        .write_enable(ans_meta$write_enable),
        .head_address(ans_meta$head_address),
        .next_address(ans_meta$next_address),
        .pop(ans_meta$pop),
        .read_data(ans_meta$read_data)
    );
    machine$pes$0$cache$ret ret(
        .clock(ret$clock),
        .push(ret$push),
        .pop(ret$pop),
        .tail_address(ret$tail_address),
        .head_address(ret$head_address),
        .next_address(ret$next_address),
        .valid(ret$valid),
        .count(ret$count)
    );
    machine$pes$0$cache$ret_ax ret_ax(
        .clock(ret_ax$clock),
        .write_address(ret_ax$write_address),
        .write_data(ret_ax$write_data),
        .write_enable(ret_ax$write_enable),
        .head_address(ret_ax$head_address),
        .next_address(ret_ax$next_address),
        .pop(ret_ax$pop),
        .read_data(ret_ax$read_data)
    );
    machine$pes$0$cache$ret_ay ret_ay(
        .clock(ret_ay$clock),
        .write_address(ret_ay$write_address),
        .write_data(ret_ay$write_data),
        .write_enable(ret_ay$write_enable),
        .head_address(ret_ay$head_address),
        .next_address(ret_ay$next_address),
        .pop(ret_ay$pop),
        .read_data(ret_ay$read_data)
    );
    machine$pes$0$cache$ret_bx ret_bx(
        .clock(ret_bx$clock),
        .write_address(ret_bx$write_address),
        .write_data(ret_bx$write_data),
        .write_enable(ret_bx$write_enable),
        .head_address(ret_bx$head_address),
        .next_address(ret_bx$next_address),
        .pop(ret_bx$pop),
        .read_data(ret_bx$read_data)
    );
    machine$pes$0$cache$ret_by ret_by(
        .clock(ret_by$clock),
        .write_address(ret_by$write_address),
        .write_data(ret_by$write_data),
        .write_enable(ret_by$write_enable),
        .head_address(ret_by$head_address),
        .next_address(ret_by$next_address),
        .pop(ret_by$pop),
        .read_data(ret_by$read_data)
    );
    machine$pes$0$cache$fl_on fl_on(
        .d(fl_on$d),
        .q(fl_on$q),
        .clock(fl_on$clock)
    );
    machine$pes$0$cache$fl_line fl_line(
        .d(fl_line$d),
        .q(fl_line$q),
        .clock(fl_line$clock)
    );
    machine$pes$0$cache$mreq mreq(
        .d(mreq$d),
        .q(mreq$q),
        .clock(mreq$clock)
    );
    machine$pes$0$cache$maddr maddr(
        .d(maddr$d),
        .q(maddr$q),
        .clock(maddr$clock)
    );
    machine$pes$0$cache$rv rv(
        .d(rv$d),
        .q(rv$q),
        .clock(rv$clock)
    );
    machine$pes$0$cache$rax rax(
        .d(rax$d),
        .q(rax$q),
        .clock(rax$clock)
    );
    machine$pes$0$cache$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    machine$pes$0$cache$rbx rbx(
        .d(rbx$d),
        .q(rbx$q),
        .clock(rbx$clock)
    );
    machine$pes$0$cache$rby rby(
        .d(rby$d),
        .q(rby$q),
        .clock(rby$clock)
    );
    machine$pes$0$cache$hit_count hit_count(
        .d(hit_count$d),
        .q(hit_count$q),
        .clock(hit_count$clock)
    );
    machine$pes$0$cache$miss_count miss_count(
        .d(miss_count$d),
        .q(miss_count$q),
        .clock(miss_count$clock)
    );
    machine$pes$0$cache$hit_r hit_r(
        .d(hit_r$d),
        .q(hit_r$q),
        .clock(hit_r$clock)
    );
    machine$pes$0$cache$tag tag(
        .clock(tag$clock),
        .read_address(tag$read_address),
        .read_data(tag$read_data),
        .write_address(tag$write_address),
        .write_data(tag$write_data),
        .write_enable(tag$write_enable)
    );
    machine$pes$0$cache$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .read_address(lane_ax$read_address),
        .read_data(lane_ax$read_data),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable)
    );
    machine$pes$0$cache$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .read_address(lane_ay$read_address),
        .read_data(lane_ay$read_data),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable)
    );
    machine$pes$0$cache$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .read_address(lane_bx$read_address),
        .read_data(lane_bx$read_data),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable)
    );
    machine$pes$0$cache$lane_by lane_by(
        .clock(lane_by$clock),
        .read_address(lane_by$read_address),
        .read_data(lane_by$read_data),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable)
    );
    machine$pes$0$cache$ret_full ret_full(
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
    
endmodule // machine$pes$0$cache


module machine$pes$0$cache$ans(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$0$cache$ans$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$cache$ans$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$cache$ans$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$cache$ans$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$cache$ans$head_valid head_valid(
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
    
endmodule // machine$pes$0$cache$ans


module machine$pes$0$cache$ans$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ans$head_valid


module machine$pes$0$cache$ans$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ans$rd_inc_x


module machine$pes$0$cache$ans$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ans$rd_ptr


module machine$pes$0$cache$ans$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ans$tail_ptr


module machine$pes$0$cache$ans$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ans$words


module machine$pes$0$cache$ans_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ans_ax


module machine$pes$0$cache$ans_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ans_ay


module machine$pes$0$cache$ans_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ans_bx


module machine$pes$0$cache$ans_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ans_by


module machine$pes$0$cache$ans_meta(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ans_meta


module machine$pes$0$cache$ax3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ax3


module machine$pes$0$cache$ay3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ay3


module machine$pes$0$cache$bx3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$bx3


module machine$pes$0$cache$by3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$by3


module machine$pes$0$cache$f_id1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$f_id1


module machine$pes$0$cache$f_line1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$f_line1


module machine$pes$0$cache$f_v1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$f_v1


module machine$pes$0$cache$fl_line(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$fl_line


module machine$pes$0$cache$fl_on(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$fl_on


module machine$pes$0$cache$hit_count(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$hit_count


module machine$pes$0$cache$hit_r(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$hit_r


module machine$pes$0$cache$iconf3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$iconf3


module machine$pes$0$cache$id1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$id1


module machine$pes$0$cache$id2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$id2


module machine$pes$0$cache$id3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$id3


module machine$pes$0$cache$key1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$key1


module machine$pes$0$cache$key2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$key2


module machine$pes$0$cache$lane_ax(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$cache$lane_ax


module machine$pes$0$cache$lane_ay(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$cache$lane_ay


module machine$pes$0$cache$lane_bx(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$cache$lane_bx


module machine$pes$0$cache$lane_by(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$cache$lane_by


module machine$pes$0$cache$lconf3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$lconf3


module machine$pes$0$cache$line1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$line1


module machine$pes$0$cache$line2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$line2


module machine$pes$0$cache$line3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$line3


module machine$pes$0$cache$maddr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$maddr


module machine$pes$0$cache$match3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$match3


module machine$pes$0$cache$mi0(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mi0


module machine$pes$0$cache$mi1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mi1


module machine$pes$0$cache$mi2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mi2


module machine$pes$0$cache$mi3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mi3


module machine$pes$0$cache$mif(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mif


module machine$pes$0$cache$mis2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mis2


module machine$pes$0$cache$mis3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mis3


module machine$pes$0$cache$miss_count(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$miss_count


module machine$pes$0$cache$ml0(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ml0


module machine$pes$0$cache$ml1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ml1


module machine$pes$0$cache$ml2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ml2


module machine$pes$0$cache$ml3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ml3


module machine$pes$0$cache$mlf(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mlf


module machine$pes$0$cache$mls2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mls2


module machine$pes$0$cache$mls3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mls3


module machine$pes$0$cache$mreq(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$mreq


module machine$pes$0$cache$q_lane(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$cache$q_lane


module machine$pes$0$cache$q_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$q_valid


module machine$pes$0$cache$rax(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$rax


module machine$pes$0$cache$ray(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ray


module machine$pes$0$cache$rbx(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$rbx


module machine$pes$0$cache$rby(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$rby


module machine$pes$0$cache$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$rd_inc_x


module machine$pes$0$cache$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$rd_ptr


module machine$pes$0$cache$ret(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$0$cache$ret$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$cache$ret$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$cache$ret$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$cache$ret$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$cache$ret$head_valid head_valid(
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
    
endmodule // machine$pes$0$cache$ret


module machine$pes$0$cache$ret$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ret$head_valid


module machine$pes$0$cache$ret$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ret$rd_inc_x


module machine$pes$0$cache$ret$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ret$rd_ptr


module machine$pes$0$cache$ret$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ret$tail_ptr


module machine$pes$0$cache$ret$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ret$words


module machine$pes$0$cache$ret_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ret_ax


module machine$pes$0$cache$ret_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ret_ay


module machine$pes$0$cache$ret_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ret_bx


module machine$pes$0$cache$ret_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$cache$ret_by


module machine$pes$0$cache$ret_full(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$ret_full


module machine$pes$0$cache$rv(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$rv


module machine$pes$0$cache$sp(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$sp


module machine$pes$0$cache$sp_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$sp_inc_x


module machine$pes$0$cache$t_any(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_any


module machine$pes$0$cache$t_full(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_full


module machine$pes$0$cache$t_id0(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_id0


module machine$pes$0$cache$t_id1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_id1


module machine$pes$0$cache$t_id2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_id2


module machine$pes$0$cache$t_id3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_id3


module machine$pes$0$cache$t_line0(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_line0


module machine$pes$0$cache$t_line1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_line1


module machine$pes$0$cache$t_line2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_line2


module machine$pes$0$cache$t_line3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_line3


module machine$pes$0$cache$t_n(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_n


module machine$pes$0$cache$t_rp(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_rp


module machine$pes$0$cache$t_v0(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_v0


module machine$pes$0$cache$t_v1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_v1


module machine$pes$0$cache$t_v2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_v2


module machine$pes$0$cache$t_v3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_v3


module machine$pes$0$cache$t_wp(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$t_wp


module machine$pes$0$cache$tag(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$cache$tag


module machine$pes$0$cache$v1(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$v1


module machine$pes$0$cache$v2(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$v2


module machine$pes$0$cache$v3(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$v3


module machine$pes$0$cache$wr_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$cache$wr_ptr


module machine$pes$0$first0_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$first0_x


module machine$pes$0$first0_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$first0_y


module machine$pes$0$first1_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$first1_x


module machine$pes$0$first1_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$first1_y


module machine$pes$0$in0(d,q,clock);
    
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
          
endmodule // machine$pes$0$in0


module machine$pes$0$in1(d,q,clock);
    
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
          
endmodule // machine$pes$0$in1


module machine$pes$0$job_bank(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  read_data;
    
    // Update code (custom)
    reg [0:0] mem [0:15];
    reg [0:0] head_r;
    reg [0:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [0:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 1'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 1'd0;
       head_r = 1'd0;
       next_r = 1'd0;
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
endmodule // machine$pes$0$job_bank


module machine$pes$0$job_banks(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$0$job_banks$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$job_banks$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$job_banks$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$job_banks$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$job_banks$head_valid head_valid(
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
    
endmodule // machine$pes$0$job_banks


module machine$pes$0$job_banks$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$job_banks$head_valid


module machine$pes$0$job_banks$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$job_banks$rd_inc_x


module machine$pes$0$job_banks$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$job_banks$rd_ptr


module machine$pes$0$job_banks$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$job_banks$tail_ptr


module machine$pes$0$job_banks$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$job_banks$words


module machine$pes$0$job_origin_x(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$job_origin_x


module machine$pes$0$job_origin_y(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$job_origin_y


module machine$pes$0$jobs0(d,q,clock);
    
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
          
endmodule // machine$pes$0$jobs0


module machine$pes$0$jobs1(d,q,clock);
    
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
          
endmodule // machine$pes$0$jobs1


module machine$pes$0$last0_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$last0_x


module machine$pes$0$last0_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$last0_y


module machine$pes$0$last1_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$last1_x


module machine$pes$0$last1_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$last1_y


module machine$pes$0$load0(d,q,clock);
    
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
          
endmodule // machine$pes$0$load0


module machine$pes$0$load1(d,q,clock);
    
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
          
endmodule // machine$pes$0$load1


module machine$pes$0$loader(clock,id_valid,id_ready,id,id_ready_next,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,loads);
    
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
    machine$pes$0$loader$req_ptr req_ptr(
        .d(req_ptr$d),
        .q(req_ptr$q),
        .clock(req_ptr$clock)
    );
    machine$pes$0$loader$reserved reserved(
        .d(reserved$d),
        .q(reserved$q),
        .clock(reserved$clock)
    );
    machine$pes$0$loader$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    machine$pes$0$loader$req_valid req_valid(
        .d(req_valid$d),
        .q(req_valid$q),
        .clock(req_valid$clock)
    );
    machine$pes$0$loader$req_addr req_addr(
        .d(req_addr$d),
        .q(req_addr$q),
        .clock(req_addr$clock)
    );
    machine$pes$0$loader$load_count load_count(
        .d(load_count$d),
        .q(load_count$q),
        .clock(load_count$clock)
    );
    machine$pes$0$loader$fifo fifo(
        .clock(fifo$clock),
        .push(fifo$push),
        .pop(fifo$pop),
        .tail_address(fifo$tail_address),
        .head_address(fifo$head_address),
        .next_address(fifo$next_address),
        .valid(fifo$valid),
        .count(fifo$count)
    );
    machine$pes$0$loader$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    machine$pes$0$loader$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    machine$pes$0$loader$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    machine$pes$0$loader$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    machine$pes$0$loader$lane_by lane_by(
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
    
endmodule // machine$pes$0$loader


module machine$pes$0$loader$fifo(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$0$loader$fifo$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$loader$fifo$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$loader$fifo$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$loader$fifo$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$loader$fifo$head_valid head_valid(
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
    
endmodule // machine$pes$0$loader$fifo


module machine$pes$0$loader$fifo$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$fifo$head_valid


module machine$pes$0$loader$fifo$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$fifo$rd_inc_x


module machine$pes$0$loader$fifo$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$fifo$rd_ptr


module machine$pes$0$loader$fifo$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$fifo$tail_ptr


module machine$pes$0$loader$fifo$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$fifo$words


module machine$pes$0$loader$full(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$full


module machine$pes$0$loader$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$loader$lane_ax


module machine$pes$0$loader$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$loader$lane_ay


module machine$pes$0$loader$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$loader$lane_bx


module machine$pes$0$loader$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$loader$lane_by


module machine$pes$0$loader$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$loader$lane_id


module machine$pes$0$loader$load_count(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$load_count


module machine$pes$0$loader$req_addr(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$req_addr


module machine$pes$0$loader$req_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$req_ptr


module machine$pes$0$loader$req_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$req_valid


module machine$pes$0$loader$reserved(d,q,clock);
    
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
          
endmodule // machine$pes$0$loader$reserved


module machine$pes$0$normal0_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$normal0_x


module machine$pes$0$normal0_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$normal0_y


module machine$pes$0$normal1_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$normal1_x


module machine$pes$0$normal1_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$normal1_y


module machine$pes$0$origin0_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$origin0_x


module machine$pes$0$origin0_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$origin0_y


module machine$pes$0$origin1_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$origin1_x


module machine$pes$0$origin1_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$origin1_y


module machine$pes$0$other_busy(d,q,clock);
    
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
          
endmodule // machine$pes$0$other_busy


module machine$pes$0$pend(d,q,clock);
    
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
          
endmodule // machine$pes$0$pend


module machine$pes$0$queue(clock,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_wx,in_wy,in_sh,in_first,in_count,in_retire,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_first,out_count,out_retire,occupied);
    
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
    machine$pes$0$queue$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    machine$pes$0$queue$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    machine$pes$0$queue$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    machine$pes$0$queue$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    machine$pes$0$queue$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    machine$pes$0$queue$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    machine$pes$0$queue$lane_wx lane_wx(
        .clock(lane_wx$clock),
        .write_address(lane_wx$write_address),
        .write_data(lane_wx$write_data),
        .write_enable(lane_wx$write_enable),
        .head_address(lane_wx$head_address),
        .next_address(lane_wx$next_address),
        .pop(lane_wx$pop),
        .read_data(lane_wx$read_data)
    );
    machine$pes$0$queue$lane_wy lane_wy(
        .clock(lane_wy$clock),
        .write_address(lane_wy$write_address),
        .write_data(lane_wy$write_data),
        .write_enable(lane_wy$write_enable),
        .head_address(lane_wy$head_address),
        .next_address(lane_wy$next_address),
        .pop(lane_wy$pop),
        .read_data(lane_wy$read_data)
    );
    machine$pes$0$queue$lane_job lane_job(
        .clock(lane_job$clock),
        .write_address(lane_job$write_address),
        .write_data(lane_job$write_data),
        .write_enable(lane_job$write_enable),
        .head_address(lane_job$head_address),
        .next_address(lane_job$next_address),
        .pop(lane_job$pop),
        .read_data(lane_job$read_data)
    );
    machine$pes$0$queue$p_valid p_valid(
        .d(p_valid$d),
        .q(p_valid$q),
        .clock(p_valid$clock)
    );
    machine$pes$0$queue$p_id p_id(
        .d(p_id$d),
        .q(p_id$q),
        .clock(p_id$clock)
    );
    machine$pes$0$queue$p_ax p_ax(
        .d(p_ax$d),
        .q(p_ax$q),
        .clock(p_ax$clock)
    );
    machine$pes$0$queue$p_ay p_ay(
        .d(p_ay$d),
        .q(p_ay$q),
        .clock(p_ay$clock)
    );
    machine$pes$0$queue$p_bx p_bx(
        .d(p_bx$d),
        .q(p_bx$q),
        .clock(p_bx$clock)
    );
    machine$pes$0$queue$p_by p_by(
        .d(p_by$d),
        .q(p_by$q),
        .clock(p_by$clock)
    );
    machine$pes$0$queue$p_wx p_wx(
        .d(p_wx$d),
        .q(p_wx$q),
        .clock(p_wx$clock)
    );
    machine$pes$0$queue$p_wy p_wy(
        .d(p_wy$d),
        .q(p_wy$q),
        .clock(p_wy$clock)
    );
    machine$pes$0$queue$p_job p_job(
        .d(p_job$d),
        .q(p_job$q),
        .clock(p_job$clock)
    );
    machine$pes$0$queue$held held(
        .d(held$d),
        .q(held$q),
        .clock(held$clock)
    );
    machine$pes$0$queue$held_full held_full(
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
    
endmodule // machine$pes$0$queue


module machine$pes$0$queue$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$0$queue$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$queue$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$queue$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$queue$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$queue$control$head_valid head_valid(
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
    
endmodule // machine$pes$0$queue$control


module machine$pes$0$queue$control$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$control$head_valid


module machine$pes$0$queue$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$control$rd_inc_x


module machine$pes$0$queue$control$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$control$rd_ptr


module machine$pes$0$queue$control$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$control$tail_ptr


module machine$pes$0$queue$control$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$control$words


module machine$pes$0$queue$held(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$held


module machine$pes$0$queue$held_full(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$held_full


module machine$pes$0$queue$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_ax


module machine$pes$0$queue$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_ay


module machine$pes$0$queue$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_bx


module machine$pes$0$queue$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_by


module machine$pes$0$queue$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_id


module machine$pes$0$queue$lane_job(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_job


module machine$pes$0$queue$lane_wx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_wx


module machine$pes$0$queue$lane_wy(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$queue$lane_wy


module machine$pes$0$queue$p_ax(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_ax


module machine$pes$0$queue$p_ay(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_ay


module machine$pes$0$queue$p_bx(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_bx


module machine$pes$0$queue$p_by(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_by


module machine$pes$0$queue$p_id(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_id


module machine$pes$0$queue$p_job(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_job


module machine$pes$0$queue$p_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_valid


module machine$pes$0$queue$p_wx(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_wx


module machine$pes$0$queue$p_wy(d,q,clock);
    
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
          
endmodule // machine$pes$0$queue$p_wy


module machine$pes$0$sc_slice(clock,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_wx,in_wy,in_sh,in_pass,in_first,in_count,in_retire,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_pass,out_first,out_count,out_retire,occupied);
    
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
    input wire  in_pass;
    input wire  [9:0] in_first;
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
    output reg  out_pass;
    output reg  [9:0] out_first;
    output reg  [10:0] out_count;
    output reg  out_retire;
    output reg  occupied;
    
    // Stub signals
    reg  m_v$d;
    wire  m_v$q;
    reg  m_v$clock;
    reg  [15:0] m_id$d;
    wire  [15:0] m_id$q;
    reg  m_id$clock;
    reg  [17:0] m_ax$d;
    wire  [17:0] m_ax$q;
    reg  m_ax$clock;
    reg  [17:0] m_ay$d;
    wire  [17:0] m_ay$q;
    reg  m_ay$clock;
    reg  [17:0] m_bx$d;
    wire  [17:0] m_bx$q;
    reg  m_bx$clock;
    reg  [17:0] m_by$d;
    wire  [17:0] m_by$q;
    reg  m_by$clock;
    reg  [17:0] m_wx$d;
    wire  [17:0] m_wx$q;
    reg  m_wx$clock;
    reg  [17:0] m_wy$d;
    wire  [17:0] m_wy$q;
    reg  m_wy$clock;
    reg  [5:0] m_sh$d;
    wire  [5:0] m_sh$q;
    reg  m_sh$clock;
    reg  m_pass$d;
    wire  m_pass$q;
    reg  m_pass$clock;
    reg  [9:0] m_first$d;
    wire  [9:0] m_first$q;
    reg  m_first$clock;
    reg  [10:0] m_count$d;
    wire  [10:0] m_count$q;
    reg  m_count$clock;
    reg  m_retire$d;
    wire  m_retire$q;
    reg  m_retire$clock;
    reg  s_v$d;
    wire  s_v$q;
    reg  s_v$clock;
    reg  [15:0] s_id$d;
    wire  [15:0] s_id$q;
    reg  s_id$clock;
    reg  [17:0] s_ax$d;
    wire  [17:0] s_ax$q;
    reg  s_ax$clock;
    reg  [17:0] s_ay$d;
    wire  [17:0] s_ay$q;
    reg  s_ay$clock;
    reg  [17:0] s_bx$d;
    wire  [17:0] s_bx$q;
    reg  s_bx$clock;
    reg  [17:0] s_by$d;
    wire  [17:0] s_by$q;
    reg  s_by$clock;
    reg  [17:0] s_wx$d;
    wire  [17:0] s_wx$q;
    reg  s_wx$clock;
    reg  [17:0] s_wy$d;
    wire  [17:0] s_wy$q;
    reg  s_wy$clock;
    reg  [5:0] s_sh$d;
    wire  [5:0] s_sh$q;
    reg  s_sh$clock;
    reg  s_pass$d;
    wire  s_pass$q;
    reg  s_pass$clock;
    reg  [9:0] s_first$d;
    wire  [9:0] s_first$q;
    reg  s_first$clock;
    reg  [10:0] s_count$d;
    wire  [10:0] s_count$q;
    reg  s_count$clock;
    reg  s_retire$d;
    wire  s_retire$q;
    reg  s_retire$clock;
    
    // Local signals
    reg  take;
    reg  load_main;
    
    // Sub module instances
    machine$pes$0$sc_slice$m_v m_v(
        .d(m_v$d),
        .q(m_v$q),
        .clock(m_v$clock)
    );
    machine$pes$0$sc_slice$m_id m_id(
        .d(m_id$d),
        .q(m_id$q),
        .clock(m_id$clock)
    );
    machine$pes$0$sc_slice$m_ax m_ax(
        .d(m_ax$d),
        .q(m_ax$q),
        .clock(m_ax$clock)
    );
    machine$pes$0$sc_slice$m_ay m_ay(
        .d(m_ay$d),
        .q(m_ay$q),
        .clock(m_ay$clock)
    );
    machine$pes$0$sc_slice$m_bx m_bx(
        .d(m_bx$d),
        .q(m_bx$q),
        .clock(m_bx$clock)
    );
    machine$pes$0$sc_slice$m_by m_by(
        .d(m_by$d),
        .q(m_by$q),
        .clock(m_by$clock)
    );
    machine$pes$0$sc_slice$m_wx m_wx(
        .d(m_wx$d),
        .q(m_wx$q),
        .clock(m_wx$clock)
    );
    machine$pes$0$sc_slice$m_wy m_wy(
        .d(m_wy$d),
        .q(m_wy$q),
        .clock(m_wy$clock)
    );
    machine$pes$0$sc_slice$m_sh m_sh(
        .d(m_sh$d),
        .q(m_sh$q),
        .clock(m_sh$clock)
    );
    machine$pes$0$sc_slice$m_pass m_pass(
        .d(m_pass$d),
        .q(m_pass$q),
        .clock(m_pass$clock)
    );
    machine$pes$0$sc_slice$m_first m_first(
        .d(m_first$d),
        .q(m_first$q),
        .clock(m_first$clock)
    );
    machine$pes$0$sc_slice$m_count m_count(
        .d(m_count$d),
        .q(m_count$q),
        .clock(m_count$clock)
    );
    machine$pes$0$sc_slice$m_retire m_retire(
        .d(m_retire$d),
        .q(m_retire$q),
        .clock(m_retire$clock)
    );
    machine$pes$0$sc_slice$s_v s_v(
        .d(s_v$d),
        .q(s_v$q),
        .clock(s_v$clock)
    );
    machine$pes$0$sc_slice$s_id s_id(
        .d(s_id$d),
        .q(s_id$q),
        .clock(s_id$clock)
    );
    machine$pes$0$sc_slice$s_ax s_ax(
        .d(s_ax$d),
        .q(s_ax$q),
        .clock(s_ax$clock)
    );
    machine$pes$0$sc_slice$s_ay s_ay(
        .d(s_ay$d),
        .q(s_ay$q),
        .clock(s_ay$clock)
    );
    machine$pes$0$sc_slice$s_bx s_bx(
        .d(s_bx$d),
        .q(s_bx$q),
        .clock(s_bx$clock)
    );
    machine$pes$0$sc_slice$s_by s_by(
        .d(s_by$d),
        .q(s_by$q),
        .clock(s_by$clock)
    );
    machine$pes$0$sc_slice$s_wx s_wx(
        .d(s_wx$d),
        .q(s_wx$q),
        .clock(s_wx$clock)
    );
    machine$pes$0$sc_slice$s_wy s_wy(
        .d(s_wy$d),
        .q(s_wy$q),
        .clock(s_wy$clock)
    );
    machine$pes$0$sc_slice$s_sh s_sh(
        .d(s_sh$d),
        .q(s_sh$q),
        .clock(s_sh$clock)
    );
    machine$pes$0$sc_slice$s_pass s_pass(
        .d(s_pass$d),
        .q(s_pass$q),
        .clock(s_pass$clock)
    );
    machine$pes$0$sc_slice$s_first s_first(
        .d(s_first$d),
        .q(s_first$q),
        .clock(s_first$clock)
    );
    machine$pes$0$sc_slice$s_count s_count(
        .d(s_count$d),
        .q(s_count$q),
        .clock(s_count$clock)
    );
    machine$pes$0$sc_slice$s_retire s_retire(
        .d(s_retire$d),
        .q(s_retire$q),
        .clock(s_retire$clock)
    );
    
    // Update code
    always @(*) begin
        m_v$clock = clock;
        m_id$clock = clock;
        m_ax$clock = clock;
        m_ay$clock = clock;
        m_bx$clock = clock;
        m_by$clock = clock;
        m_wx$clock = clock;
        m_wy$clock = clock;
        m_sh$clock = clock;
        m_pass$clock = clock;
        m_first$clock = clock;
        m_count$clock = clock;
        m_retire$clock = clock;
        s_v$clock = clock;
        s_id$clock = clock;
        s_ax$clock = clock;
        s_ay$clock = clock;
        s_bx$clock = clock;
        s_by$clock = clock;
        s_wx$clock = clock;
        s_wy$clock = clock;
        s_sh$clock = clock;
        s_pass$clock = clock;
        s_first$clock = clock;
        s_count$clock = clock;
        s_retire$clock = clock;
        m_v$d = m_v$q;
        m_id$d = m_id$q;
        m_ax$d = m_ax$q;
        m_ay$d = m_ay$q;
        m_bx$d = m_bx$q;
        m_by$d = m_by$q;
        m_wx$d = m_wx$q;
        m_wy$d = m_wy$q;
        m_sh$d = m_sh$q;
        m_pass$d = m_pass$q;
        m_first$d = m_first$q;
        m_count$d = m_count$q;
        m_retire$d = m_retire$q;
        s_v$d = s_v$q;
        s_id$d = s_id$q;
        s_ax$d = s_ax$q;
        s_ay$d = s_ay$q;
        s_bx$d = s_bx$q;
        s_by$d = s_by$q;
        s_wx$d = s_wx$q;
        s_wy$d = s_wy$q;
        s_sh$d = s_sh$q;
        s_pass$d = s_pass$q;
        s_first$d = s_first$q;
        s_count$d = s_count$q;
        s_retire$d = s_retire$q;
        in_ready = ~s_v$q;
        take = in_valid & ~s_v$q;
        load_main = ~m_v$q | out_ready;
        if (load_main) begin
            m_v$d = s_v$q | take;
            s_v$d = 1'b0;
            if (s_v$q) begin
                m_id$d = s_id$q;
                m_ax$d = s_ax$q;
                m_ay$d = s_ay$q;
                m_bx$d = s_bx$q;
                m_by$d = s_by$q;
                m_wx$d = s_wx$q;
                m_wy$d = s_wy$q;
                m_sh$d = s_sh$q;
                m_pass$d = s_pass$q;
                m_first$d = s_first$q;
                m_count$d = s_count$q;
                m_retire$d = s_retire$q;
            end
            else begin
                m_id$d = in_id;
                m_ax$d = in_ax;
                m_ay$d = in_ay;
                m_bx$d = in_bx;
                m_by$d = in_by;
                m_wx$d = in_wx;
                m_wy$d = in_wy;
                m_sh$d = in_sh;
                m_pass$d = in_pass;
                m_first$d = in_first;
                m_count$d = in_count;
                m_retire$d = in_retire;
            end
        end
        else begin
            s_v$d = s_v$q | take;
        end
        if (~s_v$q) begin
            s_id$d = in_id;
            s_ax$d = in_ax;
            s_ay$d = in_ay;
            s_bx$d = in_bx;
            s_by$d = in_by;
            s_wx$d = in_wx;
            s_wy$d = in_wy;
            s_sh$d = in_sh;
            s_pass$d = in_pass;
            s_first$d = in_first;
            s_count$d = in_count;
            s_retire$d = in_retire;
        end
        out_valid = m_v$q;
        out_id = m_id$q;
        out_ax = m_ax$q;
        out_ay = m_ay$q;
        out_bx = m_bx$q;
        out_by = m_by$q;
        out_wx = m_wx$q;
        out_wy = m_wy$q;
        out_sh = m_sh$q;
        out_pass = m_pass$q;
        out_first = m_first$q;
        out_count = m_count$q;
        out_retire = m_retire$q;
        occupied = m_v$q | s_v$q;
    end
    
endmodule // machine$pes$0$sc_slice


module machine$pes$0$sc_slice$m_ax(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_ax


module machine$pes$0$sc_slice$m_ay(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_ay


module machine$pes$0$sc_slice$m_bx(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_bx


module machine$pes$0$sc_slice$m_by(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_by


module machine$pes$0$sc_slice$m_count(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_count


module machine$pes$0$sc_slice$m_first(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_first


module machine$pes$0$sc_slice$m_id(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_id


module machine$pes$0$sc_slice$m_pass(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_pass


module machine$pes$0$sc_slice$m_retire(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_retire


module machine$pes$0$sc_slice$m_sh(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_sh


module machine$pes$0$sc_slice$m_v(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_v


module machine$pes$0$sc_slice$m_wx(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_wx


module machine$pes$0$sc_slice$m_wy(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$m_wy


module machine$pes$0$sc_slice$s_ax(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_ax


module machine$pes$0$sc_slice$s_ay(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_ay


module machine$pes$0$sc_slice$s_bx(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_bx


module machine$pes$0$sc_slice$s_by(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_by


module machine$pes$0$sc_slice$s_count(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_count


module machine$pes$0$sc_slice$s_first(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_first


module machine$pes$0$sc_slice$s_id(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_id


module machine$pes$0$sc_slice$s_pass(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_pass


module machine$pes$0$sc_slice$s_retire(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_retire


module machine$pes$0$sc_slice$s_sh(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_sh


module machine$pes$0$sc_slice$s_v(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_v


module machine$pes$0$sc_slice$s_wx(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_wx


module machine$pes$0$sc_slice$s_wy(d,q,clock);
    
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
          
endmodule // machine$pes$0$sc_slice$s_wy


module machine$pes$0$screener(clock,origin_x,origin_y,normal_x,normal_y,first_x,first_y,last_x,last_y,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_bank,sector_read,sector_bank,normal_bank,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_pass,passed,backward,back_facing,outside,near);
    
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
    machine$pes$0$screener$used used(
        .d(used$d),
        .q(used$q),
        .clock(used$clock)
    );
    machine$pes$0$screener$res_ptr res_ptr(
        .d(res_ptr$d),
        .q(res_ptr$q),
        .clock(res_ptr$clock)
    );
    machine$pes$0$screener$fifo fifo(
        .clock(fifo$clock),
        .push(fifo$push),
        .pop(fifo$pop),
        .tail_address(fifo$tail_address),
        .head_address(fifo$head_address),
        .next_address(fifo$next_address),
        .valid(fifo$valid),
        .count(fifo$count)
    );
    machine$pes$0$screener$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    machine$pes$0$screener$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    machine$pes$0$screener$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    machine$pes$0$screener$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    machine$pes$0$screener$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    machine$pes$0$screener$lane_sh lane_sh(
        .clock(lane_sh$clock),
        .write_address(lane_sh$write_address),
        .write_data(lane_sh$write_data),
        .write_enable(lane_sh$write_enable),
        .head_address(lane_sh$head_address),
        .next_address(lane_sh$next_address),
        .pop(lane_sh$pop),
        .read_data(lane_sh$read_data)
    );
    machine$pes$0$screener$lane_wx lane_wx(
        .clock(lane_wx$clock),
        .write_address(lane_wx$write_address),
        .write_data(lane_wx$write_data),
        .write_enable(lane_wx$write_enable),
        .head_address(lane_wx$head_address),
        .next_address(lane_wx$next_address),
        .pop(lane_wx$pop),
        .read_data(lane_wx$read_data)
    );
    machine$pes$0$screener$lane_wy lane_wy(
        .clock(lane_wy$clock),
        .write_address(lane_wy$write_address),
        .write_data(lane_wy$write_data),
        .write_enable(lane_wy$write_enable),
        .head_address(lane_wy$head_address),
        .next_address(lane_wy$next_address),
        .pop(lane_wy$pop),
        .read_data(lane_wy$read_data)
    );
    machine$pes$0$screener$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    machine$pes$0$screener$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    machine$pes$0$screener$bank1 bank1(
        .d(bank1$d),
        .q(bank1$q),
        .clock(bank1$clock)
    );
    machine$pes$0$screener$id1 id1(
        .d(id1$d),
        .q(id1$q),
        .clock(id1$clock)
    );
    machine$pes$0$screener$ax1 ax1(
        .d(ax1$d),
        .q(ax1$q),
        .clock(ax1$clock)
    );
    machine$pes$0$screener$ay1 ay1(
        .d(ay1$d),
        .q(ay1$q),
        .clock(ay1$clock)
    );
    machine$pes$0$screener$bx1 bx1(
        .d(bx1$d),
        .q(bx1$q),
        .clock(bx1$clock)
    );
    machine$pes$0$screener$by1 by1(
        .d(by1$d),
        .q(by1$q),
        .clock(by1$clock)
    );
    machine$pes$0$screener$m_nax m_nax(
        .clock(m_nax$clock),
        .a(m_nax$a),
        .b(m_nax$b),
        .p(m_nax$p)
    );
    machine$pes$0$screener$m_nay m_nay(
        .clock(m_nay$clock),
        .a(m_nay$a),
        .b(m_nay$b),
        .p(m_nay$p)
    );
    machine$pes$0$screener$m_nbx m_nbx(
        .clock(m_nbx$clock),
        .a(m_nbx$a),
        .b(m_nbx$b),
        .p(m_nbx$p)
    );
    machine$pes$0$screener$m_nby m_nby(
        .clock(m_nby$clock),
        .a(m_nby$a),
        .b(m_nby$b),
        .p(m_nby$p)
    );
    machine$pes$0$screener$m_aby m_aby(
        .clock(m_aby$clock),
        .a(m_aby$a),
        .b(m_aby$b),
        .p(m_aby$p)
    );
    machine$pes$0$screener$m_abx m_abx(
        .clock(m_abx$clock),
        .a(m_abx$a),
        .b(m_abx$b),
        .p(m_abx$p)
    );
    machine$pes$0$screener$m_fby m_fby(
        .clock(m_fby$clock),
        .a(m_fby$a),
        .b(m_fby$b),
        .p(m_fby$p)
    );
    machine$pes$0$screener$m_fbx m_fbx(
        .clock(m_fbx$clock),
        .a(m_fbx$a),
        .b(m_fbx$b),
        .p(m_fbx$p)
    );
    machine$pes$0$screener$m_lay m_lay(
        .clock(m_lay$clock),
        .a(m_lay$a),
        .b(m_lay$b),
        .p(m_lay$p)
    );
    machine$pes$0$screener$m_lax m_lax(
        .clock(m_lax$clock),
        .a(m_lax$a),
        .b(m_lax$b),
        .p(m_lax$p)
    );
    machine$pes$0$screener$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    machine$pes$0$screener$bank2 bank2(
        .d(bank2$d),
        .q(bank2$q),
        .clock(bank2$clock)
    );
    machine$pes$0$screener$id2 id2(
        .d(id2$d),
        .q(id2$q),
        .clock(id2$clock)
    );
    machine$pes$0$screener$ax2 ax2(
        .d(ax2$d),
        .q(ax2$q),
        .clock(ax2$clock)
    );
    machine$pes$0$screener$ay2 ay2(
        .d(ay2$d),
        .q(ay2$q),
        .clock(ay2$clock)
    );
    machine$pes$0$screener$bx2 bx2(
        .d(bx2$d),
        .q(bx2$q),
        .clock(bx2$clock)
    );
    machine$pes$0$screener$by2 by2(
        .d(by2$d),
        .q(by2$q),
        .clock(by2$clock)
    );
    machine$pes$0$screener$absnx2 absnx2(
        .d(absnx2$d),
        .q(absnx2$q),
        .clock(absnx2$clock)
    );
    machine$pes$0$screener$absny2 absny2(
        .d(absny2$d),
        .q(absny2$q),
        .clock(absny2$clock)
    );
    machine$pes$0$screener$negx2 negx2(
        .d(negx2$d),
        .q(negx2$q),
        .clock(negx2$clock)
    );
    machine$pes$0$screener$negy2 negy2(
        .d(negy2$d),
        .q(negy2$q),
        .clock(negy2$clock)
    );
    machine$pes$0$screener$normal_x2 normal_x2(
        .d(normal_x2$d),
        .q(normal_x2$q),
        .clock(normal_x2$clock)
    );
    machine$pes$0$screener$normal_y2 normal_y2(
        .d(normal_y2$d),
        .q(normal_y2$q),
        .clock(normal_y2$clock)
    );
    machine$pes$0$screener$normal_xa2 normal_xa2(
        .d(normal_xa2$d),
        .q(normal_xa2$q),
        .clock(normal_xa2$clock)
    );
    machine$pes$0$screener$normal_ya2 normal_ya2(
        .d(normal_ya2$d),
        .q(normal_ya2$q),
        .clock(normal_ya2$clock)
    );
    machine$pes$0$screener$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    machine$pes$0$screener$bank3 bank3(
        .d(bank3$d),
        .q(bank3$q),
        .clock(bank3$clock)
    );
    machine$pes$0$screener$id3 id3(
        .d(id3$d),
        .q(id3$q),
        .clock(id3$clock)
    );
    machine$pes$0$screener$ax3 ax3(
        .d(ax3$d),
        .q(ax3$q),
        .clock(ax3$clock)
    );
    machine$pes$0$screener$ay3 ay3(
        .d(ay3$d),
        .q(ay3$q),
        .clock(ay3$clock)
    );
    machine$pes$0$screener$bx3 bx3(
        .d(bx3$d),
        .q(bx3$q),
        .clock(bx3$clock)
    );
    machine$pes$0$screener$by3 by3(
        .d(by3$d),
        .q(by3$q),
        .clock(by3$clock)
    );
    machine$pes$0$screener$absnx3 absnx3(
        .d(absnx3$d),
        .q(absnx3$q),
        .clock(absnx3$clock)
    );
    machine$pes$0$screener$absny3 absny3(
        .d(absny3$d),
        .q(absny3$q),
        .clock(absny3$clock)
    );
    machine$pes$0$screener$negx3 negx3(
        .d(negx3$d),
        .q(negx3$q),
        .clock(negx3$clock)
    );
    machine$pes$0$screener$negy3 negy3(
        .d(negy3$d),
        .q(negy3$q),
        .clock(negy3$clock)
    );
    machine$pes$0$screener$nmax3 nmax3(
        .d(nmax3$d),
        .q(nmax3$q),
        .clock(nmax3$clock)
    );
    machine$pes$0$screener$v4 v4(
        .d(v4$d),
        .q(v4$q),
        .clock(v4$clock)
    );
    machine$pes$0$screener$id4 id4(
        .d(id4$d),
        .q(id4$q),
        .clock(id4$clock)
    );
    machine$pes$0$screener$p_aby4 p_aby4(
        .d(p_aby4$d),
        .q(p_aby4$q),
        .clock(p_aby4$clock)
    );
    machine$pes$0$screener$p_abx4 p_abx4(
        .d(p_abx4$d),
        .q(p_abx4$q),
        .clock(p_abx4$clock)
    );
    machine$pes$0$screener$v5 v5(
        .d(v5$d),
        .q(v5$q),
        .clock(v5$clock)
    );
    machine$pes$0$screener$id5 id5(
        .d(id5$d),
        .q(id5$q),
        .clock(id5$clock)
    );
    machine$pes$0$screener$k5 k5(
        .d(k5$d),
        .q(k5$q),
        .clock(k5$clock)
    );
    machine$pes$0$screener$p_nax5 p_nax5(
        .d(p_nax5$d),
        .q(p_nax5$q),
        .clock(p_nax5$clock)
    );
    machine$pes$0$screener$p_nay5 p_nay5(
        .d(p_nay5$d),
        .q(p_nay5$q),
        .clock(p_nay5$clock)
    );
    machine$pes$0$screener$p_nbx5 p_nbx5(
        .d(p_nbx5$d),
        .q(p_nbx5$q),
        .clock(p_nbx5$clock)
    );
    machine$pes$0$screener$p_nby5 p_nby5(
        .d(p_nby5$d),
        .q(p_nby5$q),
        .clock(p_nby5$clock)
    );
    machine$pes$0$screener$v6 v6(
        .d(v6$d),
        .q(v6$q),
        .clock(v6$clock)
    );
    machine$pes$0$screener$id6 id6(
        .d(id6$d),
        .q(id6$q),
        .clock(id6$clock)
    );
    machine$pes$0$screener$k_nonpos6 k_nonpos6(
        .d(k_nonpos6$d),
        .q(k_nonpos6$q),
        .clock(k_nonpos6$clock)
    );
    machine$pes$0$screener$ha6 ha6(
        .d(ha6$d),
        .q(ha6$q),
        .clock(ha6$clock)
    );
    machine$pes$0$screener$hb6 hb6(
        .d(hb6$d),
        .q(hb6$q),
        .clock(hb6$clock)
    );
    machine$pes$0$screener$p_fby6 p_fby6(
        .d(p_fby6$d),
        .q(p_fby6$q),
        .clock(p_fby6$clock)
    );
    machine$pes$0$screener$p_fbx6 p_fbx6(
        .d(p_fbx6$d),
        .q(p_fbx6$q),
        .clock(p_fbx6$clock)
    );
    machine$pes$0$screener$p_lay6 p_lay6(
        .d(p_lay6$d),
        .q(p_lay6$q),
        .clock(p_lay6$clock)
    );
    machine$pes$0$screener$p_lax6 p_lax6(
        .d(p_lax6$d),
        .q(p_lax6$q),
        .clock(p_lax6$clock)
    );
    machine$pes$0$screener$clz_n6 clz_n6(
        .d(clz_n6$d),
        .q(clz_n6$q),
        .clock(clz_n6$clock)
    );
    machine$pes$0$screener$norm_n6 norm_n6(
        .d(norm_n6$d),
        .q(norm_n6$q),
        .clock(norm_n6$clock)
    );
    machine$pes$0$screener$v7 v7(
        .d(v7$d),
        .q(v7$q),
        .clock(v7$clock)
    );
    machine$pes$0$screener$id7 id7(
        .d(id7$d),
        .q(id7$q),
        .clock(id7$clock)
    );
    machine$pes$0$screener$side_f7 side_f7(
        .d(side_f7$d),
        .q(side_f7$q),
        .clock(side_f7$clock)
    );
    machine$pes$0$screener$side_l7 side_l7(
        .d(side_l7$d),
        .q(side_l7$q),
        .clock(side_l7$clock)
    );
    machine$pes$0$screener$clz_n7 clz_n7(
        .d(clz_n7$d),
        .q(clz_n7$q),
        .clock(clz_n7$clock)
    );
    machine$pes$0$screener$norm_n7 norm_n7(
        .d(norm_n7$d),
        .q(norm_n7$q),
        .clock(norm_n7$clock)
    );
    machine$pes$0$screener$backward7 backward7(
        .d(backward7$d),
        .q(backward7$q),
        .clock(backward7$clock)
    );
    machine$pes$0$screener$back_facing7 back_facing7(
        .d(back_facing7$d),
        .q(back_facing7$q),
        .clock(back_facing7$clock)
    );
    machine$pes$0$screener$ha_open7 ha_open7(
        .d(ha_open7$d),
        .q(ha_open7$q),
        .clock(ha_open7$clock)
    );
    machine$pes$0$screener$hb_open7 hb_open7(
        .d(hb_open7$d),
        .q(hb_open7$q),
        .clock(hb_open7$clock)
    );
    machine$pes$0$screener$f_hi_lt8 f_hi_lt8(
        .d(f_hi_lt8$d),
        .q(f_hi_lt8$q),
        .clock(f_hi_lt8$clock)
    );
    machine$pes$0$screener$f_hi_eq8 f_hi_eq8(
        .d(f_hi_eq8$d),
        .q(f_hi_eq8$q),
        .clock(f_hi_eq8$clock)
    );
    machine$pes$0$screener$f_lo_lt8 f_lo_lt8(
        .d(f_lo_lt8$d),
        .q(f_lo_lt8$q),
        .clock(f_lo_lt8$clock)
    );
    machine$pes$0$screener$l_hi_gt8 l_hi_gt8(
        .d(l_hi_gt8$d),
        .q(l_hi_gt8$q),
        .clock(l_hi_gt8$clock)
    );
    machine$pes$0$screener$l_hi_eq8 l_hi_eq8(
        .d(l_hi_eq8$d),
        .q(l_hi_eq8$q),
        .clock(l_hi_eq8$clock)
    );
    machine$pes$0$screener$l_lo_gt8 l_lo_gt8(
        .d(l_lo_gt8$d),
        .q(l_lo_gt8$q),
        .clock(l_lo_gt8$clock)
    );
    machine$pes$0$screener$ha_open8 ha_open8(
        .d(ha_open8$d),
        .q(ha_open8$q),
        .clock(ha_open8$clock)
    );
    machine$pes$0$screener$hb_open8 hb_open8(
        .d(hb_open8$d),
        .q(hb_open8$q),
        .clock(hb_open8$clock)
    );
    machine$pes$0$screener$v8 v8(
        .d(v8$d),
        .q(v8$q),
        .clock(v8$clock)
    );
    machine$pes$0$screener$id8 id8(
        .d(id8$d),
        .q(id8$q),
        .clock(id8$clock)
    );
    machine$pes$0$screener$s0_8 s0_8(
        .d(s0_8$d),
        .q(s0_8$q),
        .clock(s0_8$clock)
    );
    machine$pes$0$screener$s0_m1_8 s0_m1_8(
        .d(s0_m1_8$d),
        .q(s0_m1_8$q),
        .clock(s0_m1_8$clock)
    );
    machine$pes$0$screener$below8 below8(
        .d(below8$d),
        .q(below8$q),
        .clock(below8$clock)
    );
    machine$pes$0$screener$near_a8 near_a8(
        .d(near_a8$d),
        .q(near_a8$q),
        .clock(near_a8$clock)
    );
    machine$pes$0$screener$near_b8 near_b8(
        .d(near_b8$d),
        .q(near_b8$q),
        .clock(near_b8$clock)
    );
    machine$pes$0$screener$sp3_8 sp3_8(
        .d(sp3_8$d),
        .q(sp3_8$q),
        .clock(sp3_8$clock)
    );
    machine$pes$0$screener$clz_n2_7 clz_n2_7(
        .d(clz_n2_7$d),
        .q(clz_n2_7$q),
        .clock(clz_n2_7$clock)
    );
    machine$pes$0$screener$clz_n3_7 clz_n3_7(
        .d(clz_n3_7$d),
        .q(clz_n3_7$q),
        .clock(clz_n3_7$clock)
    );
    machine$pes$0$screener$backward8 backward8(
        .d(backward8$d),
        .q(backward8$q),
        .clock(backward8$clock)
    );
    machine$pes$0$screener$back_facing8 back_facing8(
        .d(back_facing8$d),
        .q(back_facing8$q),
        .clock(back_facing8$clock)
    );
    machine$pes$0$screener$pass9 pass9(
        .d(pass9$d),
        .q(pass9$q),
        .clock(pass9$clock)
    );
    machine$pes$0$screener$backward9 backward9(
        .d(backward9$d),
        .q(backward9$q),
        .clock(backward9$clock)
    );
    machine$pes$0$screener$back_facing9 back_facing9(
        .d(back_facing9$d),
        .q(back_facing9$q),
        .clock(back_facing9$clock)
    );
    machine$pes$0$screener$outside9 outside9(
        .d(outside9$d),
        .q(outside9$q),
        .clock(outside9$clock)
    );
    machine$pes$0$screener$near9 near9(
        .d(near9$d),
        .q(near9$q),
        .clock(near9$clock)
    );
    machine$pes$0$screener$c_ax c_ax(
        .clock(c_ax$clock),
        .d(c_ax$d),
        .q(c_ax$q)
    );
    machine$pes$0$screener$c_ay c_ay(
        .clock(c_ay$clock),
        .d(c_ay$d),
        .q(c_ay$q)
    );
    machine$pes$0$screener$c_bx c_bx(
        .clock(c_bx$clock),
        .d(c_bx$d),
        .q(c_bx$q)
    );
    machine$pes$0$screener$c_by c_by(
        .clock(c_by$clock),
        .d(c_by$d),
        .q(c_by$q)
    );
    machine$pes$0$screener$c_absnx c_absnx(
        .clock(c_absnx$clock),
        .d(c_absnx$d),
        .q(c_absnx$q)
    );
    machine$pes$0$screener$c_absny c_absny(
        .clock(c_absny$clock),
        .d(c_absny$d),
        .q(c_absny$q)
    );
    machine$pes$0$screener$c_negx c_negx(
        .clock(c_negx$clock),
        .d(c_negx$d),
        .q(c_negx$q)
    );
    machine$pes$0$screener$c_negy c_negy(
        .clock(c_negy$clock),
        .d(c_negy$d),
        .q(c_negy$q)
    );
    machine$pes$0$screener$c_k c_k(
        .clock(c_k$clock),
        .d(c_k$d),
        .q(c_k$q)
    );
    machine$pes$0$screener$lz_n lz_n(
        .clock(lz_n$clock),
        .value(lz_n$value),
        .norm(lz_n$norm),
        .clz(lz_n$clz)
    );
    machine$pes$0$screener$lz_e lz_e(
        .clock(lz_e$clock),
        .value(lz_e$value),
        .norm(lz_e$norm),
        .clz(lz_e$clz)
    );
    machine$pes$0$screener$divider divider(
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
    machine$pes$0$screener$c_passed c_passed(
        .d(c_passed$d),
        .q(c_passed$q),
        .clock(c_passed$clock)
    );
    machine$pes$0$screener$c_backward c_backward(
        .d(c_backward$d),
        .q(c_backward$q),
        .clock(c_backward$clock)
    );
    machine$pes$0$screener$c_back_facing c_back_facing(
        .d(c_back_facing$d),
        .q(c_back_facing$q),
        .clock(c_back_facing$clock)
    );
    machine$pes$0$screener$c_outside c_outside(
        .d(c_outside$d),
        .q(c_outside$q),
        .clock(c_outside$clock)
    );
    machine$pes$0$screener$c_near c_near(
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
    
endmodule // machine$pes$0$screener


module machine$pes$0$screener$absnx2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$absnx2


module machine$pes$0$screener$absnx3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$absnx3


module machine$pes$0$screener$absny2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$absny2


module machine$pes$0$screener$absny3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$absny3


module machine$pes$0$screener$ax1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ax1


module machine$pes$0$screener$ax2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ax2


module machine$pes$0$screener$ax3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ax3


module machine$pes$0$screener$ay1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ay1


module machine$pes$0$screener$ay2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ay2


module machine$pes$0$screener$ay3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ay3


module machine$pes$0$screener$back_facing7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$back_facing7


module machine$pes$0$screener$back_facing8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$back_facing8


module machine$pes$0$screener$back_facing9(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$back_facing9


module machine$pes$0$screener$backward7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$backward7


module machine$pes$0$screener$backward8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$backward8


module machine$pes$0$screener$backward9(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$backward9


module machine$pes$0$screener$bank1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$bank1


module machine$pes$0$screener$bank2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$bank2


module machine$pes$0$screener$bank3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$bank3


module machine$pes$0$screener$below8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$below8


module machine$pes$0$screener$bx1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$bx1


module machine$pes$0$screener$bx2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$bx2


module machine$pes$0$screener$bx3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$bx3


module machine$pes$0$screener$by1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$by1


module machine$pes$0$screener$by2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$by2


module machine$pes$0$screener$by3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$by3


module machine$pes$0$screener$c_absnx(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_absnx


module machine$pes$0$screener$c_absny(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_absny


module machine$pes$0$screener$c_ax(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_ax


module machine$pes$0$screener$c_ay(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_ay


module machine$pes$0$screener$c_back_facing(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$c_back_facing


module machine$pes$0$screener$c_backward(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$c_backward


module machine$pes$0$screener$c_bx(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_bx


module machine$pes$0$screener$c_by(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_by


module machine$pes$0$screener$c_k(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_k


module machine$pes$0$screener$c_near(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$c_near


module machine$pes$0$screener$c_negx(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_negx


module machine$pes$0$screener$c_negy(clock,d,q);
    
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
endmodule // machine$pes$0$screener$c_negy


module machine$pes$0$screener$c_outside(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$c_outside


module machine$pes$0$screener$c_passed(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$c_passed


module machine$pes$0$screener$clz_n2_7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$clz_n2_7


module machine$pes$0$screener$clz_n3_7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$clz_n3_7


module machine$pes$0$screener$clz_n6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$clz_n6


module machine$pes$0$screener$clz_n7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$clz_n7


module machine$pes$0$screener$divider(clock,rx,ry,fx,fy,k,tag,qx,qy,wx,wy,tag_out);
    
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
endmodule // machine$pes$0$screener$divider


module machine$pes$0$screener$f_hi_eq8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$f_hi_eq8


module machine$pes$0$screener$f_hi_lt8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$f_hi_lt8


module machine$pes$0$screener$f_lo_lt8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$f_lo_lt8


module machine$pes$0$screener$fifo(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$0$screener$fifo$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$screener$fifo$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$screener$fifo$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$screener$fifo$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$screener$fifo$head_valid head_valid(
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
    
endmodule // machine$pes$0$screener$fifo


module machine$pes$0$screener$fifo$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$fifo$head_valid


module machine$pes$0$screener$fifo$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$fifo$rd_inc_x


module machine$pes$0$screener$fifo$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$fifo$rd_ptr


module machine$pes$0$screener$fifo$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$fifo$tail_ptr


module machine$pes$0$screener$fifo$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$fifo$words


module machine$pes$0$screener$full(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$full


module machine$pes$0$screener$ha6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ha6


module machine$pes$0$screener$ha_open7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ha_open7


module machine$pes$0$screener$ha_open8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$ha_open8


module machine$pes$0$screener$hb6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$hb6


module machine$pes$0$screener$hb_open7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$hb_open7


module machine$pes$0$screener$hb_open8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$hb_open8


module machine$pes$0$screener$id1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id1


module machine$pes$0$screener$id2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id2


module machine$pes$0$screener$id3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id3


module machine$pes$0$screener$id4(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id4


module machine$pes$0$screener$id5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id5


module machine$pes$0$screener$id6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id6


module machine$pes$0$screener$id7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id7


module machine$pes$0$screener$id8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$id8


module machine$pes$0$screener$k5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$k5


module machine$pes$0$screener$k_nonpos6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$k_nonpos6


module machine$pes$0$screener$l_hi_eq8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$l_hi_eq8


module machine$pes$0$screener$l_hi_gt8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$l_hi_gt8


module machine$pes$0$screener$l_lo_gt8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$l_lo_gt8


module machine$pes$0$screener$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_ax


module machine$pes$0$screener$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_ay


module machine$pes$0$screener$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_bx


module machine$pes$0$screener$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_by


module machine$pes$0$screener$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_id


module machine$pes$0$screener$lane_sh(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_sh


module machine$pes$0$screener$lane_wx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_wx


module machine$pes$0$screener$lane_wy(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$0$screener$lane_wy


module machine$pes$0$screener$lz_e(clock,value,norm,clz);
    
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
endmodule // machine$pes$0$screener$lz_e


module machine$pes$0$screener$lz_n(clock,value,norm,clz);
    
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
endmodule // machine$pes$0$screener$lz_n


module machine$pes$0$screener$m_abx(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_abx


module machine$pes$0$screener$m_aby(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_aby


module machine$pes$0$screener$m_fbx(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_fbx


module machine$pes$0$screener$m_fby(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_fby


module machine$pes$0$screener$m_lax(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_lax


module machine$pes$0$screener$m_lay(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_lay


module machine$pes$0$screener$m_nax(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_nax


module machine$pes$0$screener$m_nay(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_nay


module machine$pes$0$screener$m_nbx(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_nbx


module machine$pes$0$screener$m_nby(clock,a,b,p);
    
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
endmodule // machine$pes$0$screener$m_nby


module machine$pes$0$screener$near9(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$near9


module machine$pes$0$screener$near_a8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$near_a8


module machine$pes$0$screener$near_b8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$near_b8


module machine$pes$0$screener$negx2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$negx2


module machine$pes$0$screener$negx3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$negx3


module machine$pes$0$screener$negy2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$negy2


module machine$pes$0$screener$negy3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$negy3


module machine$pes$0$screener$nmax3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$nmax3


module machine$pes$0$screener$norm_n6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$norm_n6


module machine$pes$0$screener$norm_n7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$norm_n7


module machine$pes$0$screener$normal_x2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$normal_x2


module machine$pes$0$screener$normal_xa2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$normal_xa2


module machine$pes$0$screener$normal_y2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$normal_y2


module machine$pes$0$screener$normal_ya2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$normal_ya2


module machine$pes$0$screener$outside9(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$outside9


module machine$pes$0$screener$p_abx4(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_abx4


module machine$pes$0$screener$p_aby4(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_aby4


module machine$pes$0$screener$p_fbx6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_fbx6


module machine$pes$0$screener$p_fby6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_fby6


module machine$pes$0$screener$p_lax6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_lax6


module machine$pes$0$screener$p_lay6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_lay6


module machine$pes$0$screener$p_nax5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_nax5


module machine$pes$0$screener$p_nay5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_nay5


module machine$pes$0$screener$p_nbx5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_nbx5


module machine$pes$0$screener$p_nby5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$p_nby5


module machine$pes$0$screener$pass9(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$pass9


module machine$pes$0$screener$res_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$res_ptr


module machine$pes$0$screener$s0_8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$s0_8


module machine$pes$0$screener$s0_m1_8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$s0_m1_8


module machine$pes$0$screener$side_f7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$side_f7


module machine$pes$0$screener$side_l7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$side_l7


module machine$pes$0$screener$sp3_8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$sp3_8


module machine$pes$0$screener$used(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$used


module machine$pes$0$screener$v1(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v1


module machine$pes$0$screener$v2(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v2


module machine$pes$0$screener$v3(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v3


module machine$pes$0$screener$v4(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v4


module machine$pes$0$screener$v5(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v5


module machine$pes$0$screener$v6(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v6


module machine$pes$0$screener$v7(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v7


module machine$pes$0$screener$v8(d,q,clock);
    
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
          
endmodule // machine$pes$0$screener$v8


module machine$pes$0$stall(d,q,clock);
    
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
          
endmodule // machine$pes$0$stall


module machine$pes$0$stg_first_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_first_x


module machine$pes$0$stg_first_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_first_y


module machine$pes$0$stg_last_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_last_x


module machine$pes$0$stg_last_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_last_y


module machine$pes$0$stg_normal_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_normal_x


module machine$pes$0$stg_normal_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_normal_y


module machine$pes$0$stg_origin_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_origin_x


module machine$pes$0$stg_origin_y(d,q,clock);
    
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
          
endmodule // machine$pes$0$stg_origin_y


module machine$pes$0$tag_kind(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [5:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    input wire  [5:0] head_address;
    input wire  [5:0] next_address;
    input wire  pop;
    output reg  read_data;
    
    // Update code (custom)
    // Two copies under the same writes, one read each: from one memory, Yosys makes the two reads
    // one port whose address is chosen by `pop` (pop, address, RAM, register: measured 141 MHz).
    reg [0:0] mem [0:63];
    reg [0:0] mem_n [0:63];
    reg [0:0] read_r;
    integer i;
    initial begin
       for (i = 0; i <= 63; i = i + 1) begin
          mem[i] = 1'd0;
          mem_n[i] = 1'd0;
       end
       read_r = 1'd0;
    end
    always @(posedge clock) begin
       read_r <= pop ? mem_n[next_address] : mem[head_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
          mem_n[write_address] <= write_data;
       end
    end
    always @(*) read_data = read_r;
endmodule // machine$pes$0$tag_kind


module machine$pes$0$tag_lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [5:0] write_address;
    input wire  [21:0] write_data;
    input wire  write_enable;
    input wire  [5:0] head_address;
    input wire  [5:0] next_address;
    input wire  pop;
    output reg  [21:0] read_data;
    
    // Update code (custom)
    reg [21:0] mem [0:63];
    reg [21:0] head_r;
    reg [21:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [21:0] mem_n [0:63];
    initial for (i = 0; i <= 63; i = i + 1) mem_n[i] = 22'd0;
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
       for (i = 0; i <= 63; i = i + 1) mem[i] = 22'd0;
       head_r = 22'd0;
       next_r = 22'd0;
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
endmodule // machine$pes$0$tag_lane


module machine$pes$0$tags(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [5:0] tail_address;
    output reg  [5:0] head_address;
    output reg  [5:0] next_address;
    output reg  valid;
    output reg  [6:0] count;
    
    // Constant declarations
    localparam  one_a = 6'b1;
    localparam  one_c = 7'b1;
    localparam  zero_c = 7'b0;
    
    // Stub signals
    reg  [5:0] tail_ptr$d;
    wire  [5:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [5:0] rd_ptr$d;
    wire  [5:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [5:0] rd_inc_x$d;
    wire  [5:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [6:0] words$d;
    wire  [6:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [5:0] rd_inc;
    reg  [5:0] rd_inc2;
    
    // Sub module instances
    machine$pes$0$tags$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$0$tags$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$0$tags$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$0$tags$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$0$tags$head_valid head_valid(
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
    
endmodule // machine$pes$0$tags


module machine$pes$0$tags$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$0$tags$head_valid


module machine$pes$0$tags$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$0$tags$rd_inc_x


module machine$pes$0$tags$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$tags$rd_ptr


module machine$pes$0$tags$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$0$tags$tail_ptr


module machine$pes$0$tags$words(d,q,clock);
    
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
          
endmodule // machine$pes$0$tags$words


module machine$pes$0$tags_full(d,q,clock);
    
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
          
endmodule // machine$pes$0$tags_full


module machine$pes$0$unit(clock,dir_we,dir_addr,dir_x,dir_y,patch_valid,patch_ready,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,res_re,res_addr,res_hit,res_id,res_key,busy,tests,marks);
    
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
    machine$pes$0$unit$seq seq(
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
    machine$pes$0$unit$alive0 alive0(
        .clock(alive0$clock),
        .read_address(alive0$read_address),
        .read_data(alive0$read_data),
        .write_address(alive0$write_address),
        .write_data(alive0$write_data),
        .write_enable(alive0$write_enable)
    );
    machine$pes$0$unit$alive1 alive1(
        .clock(alive1$clock),
        .read_address(alive1$read_address),
        .read_data(alive1$read_data),
        .write_address(alive1$write_address),
        .write_data(alive1$write_data),
        .write_enable(alive1$write_enable)
    );
    machine$pes$0$unit$dir_mem_x dir_mem_x(
        .clock(dir_mem_x$clock),
        .read_address(dir_mem_x$read_address),
        .read_data(dir_mem_x$read_data),
        .write_address(dir_mem_x$write_address),
        .write_data(dir_mem_x$write_data),
        .write_enable(dir_mem_x$write_enable)
    );
    machine$pes$0$unit$dir_mem_y dir_mem_y(
        .clock(dir_mem_y$clock),
        .read_address(dir_mem_y$read_address),
        .read_data(dir_mem_y$read_data),
        .write_address(dir_mem_y$write_address),
        .write_data(dir_mem_y$write_data),
        .write_enable(dir_mem_y$write_enable)
    );
    machine$pes$0$unit$products products(
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
    machine$pes$0$unit$pipe pipe(
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
    machine$pes$0$unit$key_scale key_scale(
        .clock(key_scale$clock),
        .q(key_scale$q),
        .sh(key_scale$sh),
        .key(key_scale$key)
    );
    machine$pes$0$unit$mem_key0 mem_key0(
        .clock(mem_key0$clock),
        .read_address(mem_key0$read_address),
        .read_data(mem_key0$read_data),
        .write_address(mem_key0$write_address),
        .write_data(mem_key0$write_data),
        .write_enable(mem_key0$write_enable)
    );
    machine$pes$0$unit$mem_meta0 mem_meta0(
        .clock(mem_meta0$clock),
        .read_address(mem_meta0$read_address),
        .read_data(mem_meta0$read_data),
        .write_address(mem_meta0$write_address),
        .write_data(mem_meta0$write_data),
        .write_enable(mem_meta0$write_enable)
    );
    machine$pes$0$unit$mem_key1 mem_key1(
        .clock(mem_key1$clock),
        .read_address(mem_key1$read_address),
        .read_data(mem_key1$read_data),
        .write_address(mem_key1$write_address),
        .write_data(mem_key1$write_data),
        .write_enable(mem_key1$write_enable)
    );
    machine$pes$0$unit$mem_meta1 mem_meta1(
        .clock(mem_meta1$clock),
        .read_address(mem_meta1$read_address),
        .read_data(mem_meta1$read_data),
        .write_address(mem_meta1$write_address),
        .write_data(mem_meta1$write_data),
        .write_enable(mem_meta1$write_enable)
    );
    machine$pes$0$unit$merge merge(
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
    
endmodule // machine$pes$0$unit


module machine$pes$0$unit$alive0(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$alive0


module machine$pes$0$unit$alive1(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$alive1


module machine$pes$0$unit$dir_mem_x(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$dir_mem_x


module machine$pes$0$unit$dir_mem_y(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$dir_mem_y


module machine$pes$0$unit$key_scale(clock,q,sh,key);
    
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
endmodule // machine$pes$0$unit$key_scale


module machine$pes$0$unit$mem_key0(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$mem_key0


module machine$pes$0$unit$mem_key1(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$mem_key1


module machine$pes$0$unit$mem_meta0(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$mem_meta0


module machine$pes$0$unit$mem_meta1(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$0$unit$mem_meta1


module machine$pes$0$unit$merge(clock,v8,tag8,mark8,key,mem_key0,mem_meta0,mem_key1,mem_meta1,res_re,res_addr,write_address0,write_key0,write_meta0,write_enable0,write_address1,write_key1,write_meta1,write_enable1,z2,res_half,busy,fw_valid,marks);
    
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
endmodule // machine$pes$0$unit$merge


module machine$pes$0$unit$pipe(clock,v1,tag1,mark1,alive0,alive1,dx_ay,dy_ax,dx_by,dy_bx,tests,busy,sh4,ray6,v8,tag8,mark8);
    
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
endmodule // machine$pes$0$unit$pipe


module machine$pes$0$unit$products(clock,dx,dy,ax,ay,bx,by,wx,wy,dx_ay,dy_ax,dx_by,dy_bx,dx_wx,dy_wy);
    
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
endmodule // machine$pes$0$unit$products


module machine$pes$0$unit$seq(clock,patch_valid,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,full,busy,kill,cur,v1,tag1,mark1,o_ax,o_ay,o_bx,o_by,o_wx,o_wy);
    
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
endmodule // machine$pes$0$unit$seq


module machine$pes$0$used0(d,q,clock);
    
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
          
endmodule // machine$pes$0$used0


module machine$pes$0$used1(d,q,clock);
    
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
          
endmodule // machine$pes$0$used1


module machine$pes$1(clock,dir_we,dir_addr,dir_x,dir_y,origin_x,origin_y,normal_x,normal_y,first_x,first_y,last_x,last_y,cmd_valid,cmd_ready,cmd_retire,cmd_sector,cmd_id,cmd_first,cmd_count,cfg_cache_enable,cfg_cache_mask,cfg_cache_flush,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,res_re,res_addr,res_hit,res_id,res_key,busy,loads,cache_hits,cache_misses,passed,backward,back_facing,outside,near,tests,marks);
    
    // Module arguments
    input wire  clock;
    input wire  dir_we;
    input wire  [10:0] dir_addr;
    input wire  [17:0] dir_x;
    input wire  [17:0] dir_y;
    input wire  [16:0] origin_x;
    input wire  [16:0] origin_y;
    input wire  [17:0] normal_x;
    input wire  [17:0] normal_y;
    input wire  [17:0] first_x;
    input wire  [17:0] first_y;
    input wire  [17:0] last_x;
    input wire  [17:0] last_y;
    input wire  cmd_valid;
    output reg  cmd_ready;
    input wire  cmd_retire;
    input wire  cmd_sector;
    input wire  [15:0] cmd_id;
    input wire  [10:0] cmd_first;
    input wire  [10:0] cmd_count;
    input wire  cfg_cache_enable;
    input wire  [9:0] cfg_cache_mask;
    input wire  cfg_cache_flush;
    output reg  mem_req;
    output reg  [15:0] mem_addr;
    input wire  mem_valid;
    input wire  [16:0] mem_ax;
    input wire  [16:0] mem_ay;
    input wire  [16:0] mem_bx;
    input wire  [16:0] mem_by;
    input wire  res_re;
    input wire  [10:0] res_addr;
    output reg  res_hit;
    output reg  [15:0] res_id;
    output reg  [31:0] res_key;
    output reg  busy;
    output reg  [31:0] loads;
    output reg  [31:0] cache_hits;
    output reg  [31:0] cache_misses;
    output reg  [31:0] passed;
    output reg  [31:0] backward;
    output reg  [31:0] back_facing;
    output reg  [31:0] outside;
    output reg  [31:0] near;
    output reg  [31:0] tests;
    output reg  [31:0] marks;
    
    // Constant declarations
    localparam  one7 = 7'b1;
    localparam  almost_full = 7'b111111;
    localparam  zero1 = 1'b0;
    localparam  one1 = 1'b1;
    localparam  full = 7'b1000000;
    localparam  zero7 = 7'b0;
    
    // Stub signals
    reg  loader$clock;
    reg  loader$id_valid;
    wire  loader$id_ready;
    reg  [15:0] loader$id;
    wire  loader$id_ready_next;
    wire  loader$mem_req;
    wire  [15:0] loader$mem_addr;
    reg  loader$mem_valid;
    reg  [16:0] loader$mem_ax;
    reg  [16:0] loader$mem_ay;
    reg  [16:0] loader$mem_bx;
    reg  [16:0] loader$mem_by;
    wire  loader$out_valid;
    reg  loader$out_ready;
    wire  [15:0] loader$out_id;
    wire  [16:0] loader$out_ax;
    wire  [16:0] loader$out_ay;
    wire  [16:0] loader$out_bx;
    wire  [16:0] loader$out_by;
    wire  [31:0] loader$loads;
    reg  cache$clock;
    reg  cache$cfg_enable;
    reg  [9:0] cache$cfg_mask;
    reg  cache$flush;
    wire  cache$flushing;
    reg  cache$req;
    reg  [15:0] cache$addr;
    wire  cache$resp_valid;
    wire  [16:0] cache$resp_ax;
    wire  [16:0] cache$resp_ay;
    wire  [16:0] cache$resp_bx;
    wire  [16:0] cache$resp_by;
    wire  cache$mem_req;
    wire  [15:0] cache$mem_addr;
    reg  cache$mem_valid;
    reg  [16:0] cache$mem_ax;
    reg  [16:0] cache$mem_ay;
    reg  [16:0] cache$mem_bx;
    reg  [16:0] cache$mem_by;
    wire  [31:0] cache$hits;
    wire  [31:0] cache$misses;
    reg  sc_slice$clock;
    reg  sc_slice$in_valid;
    wire  sc_slice$in_ready;
    reg  [15:0] sc_slice$in_id;
    reg  [17:0] sc_slice$in_ax;
    reg  [17:0] sc_slice$in_ay;
    reg  [17:0] sc_slice$in_bx;
    reg  [17:0] sc_slice$in_by;
    reg  [17:0] sc_slice$in_wx;
    reg  [17:0] sc_slice$in_wy;
    reg  [5:0] sc_slice$in_sh;
    reg  sc_slice$in_pass;
    reg  [9:0] sc_slice$in_first;
    reg  [10:0] sc_slice$in_count;
    reg  sc_slice$in_retire;
    wire  sc_slice$out_valid;
    reg  sc_slice$out_ready;
    wire  [15:0] sc_slice$out_id;
    wire  [17:0] sc_slice$out_ax;
    wire  [17:0] sc_slice$out_ay;
    wire  [17:0] sc_slice$out_bx;
    wire  [17:0] sc_slice$out_by;
    wire  [17:0] sc_slice$out_wx;
    wire  [17:0] sc_slice$out_wy;
    wire  [5:0] sc_slice$out_sh;
    wire  sc_slice$out_pass;
    wire  [9:0] sc_slice$out_first;
    wire  [10:0] sc_slice$out_count;
    wire  sc_slice$out_retire;
    wire  sc_slice$occupied;
    reg  queue$clock;
    reg  queue$in_valid;
    wire  queue$in_ready;
    reg  [15:0] queue$in_id;
    reg  [17:0] queue$in_ax;
    reg  [17:0] queue$in_ay;
    reg  [17:0] queue$in_bx;
    reg  [17:0] queue$in_by;
    reg  [17:0] queue$in_wx;
    reg  [17:0] queue$in_wy;
    reg  [5:0] queue$in_sh;
    reg  [10:0] queue$in_first;
    reg  [10:0] queue$in_count;
    reg  queue$in_retire;
    wire  queue$out_valid;
    reg  queue$out_ready;
    wire  [15:0] queue$out_id;
    wire  [17:0] queue$out_ax;
    wire  [17:0] queue$out_ay;
    wire  [17:0] queue$out_bx;
    wire  [17:0] queue$out_by;
    wire  [17:0] queue$out_wx;
    wire  [17:0] queue$out_wy;
    wire  [5:0] queue$out_sh;
    wire  [10:0] queue$out_first;
    wire  [10:0] queue$out_count;
    wire  queue$out_retire;
    wire  queue$occupied;
    reg  screener$clock;
    reg  [16:0] screener$origin_x;
    reg  [16:0] screener$origin_y;
    reg  [17:0] screener$normal_x;
    reg  [17:0] screener$normal_y;
    reg  [17:0] screener$first_x;
    reg  [17:0] screener$first_y;
    reg  [17:0] screener$last_x;
    reg  [17:0] screener$last_y;
    reg  screener$in_valid;
    wire  screener$in_ready;
    reg  [15:0] screener$in_id;
    reg  [16:0] screener$in_ax;
    reg  [16:0] screener$in_ay;
    reg  [16:0] screener$in_bx;
    reg  [16:0] screener$in_by;
    reg  screener$in_bank;
    wire  screener$sector_read;
    wire  screener$sector_bank;
    wire  screener$normal_bank;
    wire  screener$out_valid;
    reg  screener$out_ready;
    wire  [15:0] screener$out_id;
    wire  [17:0] screener$out_ax;
    wire  [17:0] screener$out_ay;
    wire  [17:0] screener$out_bx;
    wire  [17:0] screener$out_by;
    wire  [17:0] screener$out_wx;
    wire  [17:0] screener$out_wy;
    wire  [5:0] screener$out_sh;
    wire  screener$out_pass;
    wire  [31:0] screener$passed;
    wire  [31:0] screener$backward;
    wire  [31:0] screener$back_facing;
    wire  [31:0] screener$outside;
    wire  [31:0] screener$near;
    reg  unit$clock;
    reg  unit$dir_we;
    reg  [10:0] unit$dir_addr;
    reg  [17:0] unit$dir_x;
    reg  [17:0] unit$dir_y;
    reg  unit$patch_valid;
    wire  unit$patch_ready;
    reg  [17:0] unit$patch_ax;
    reg  [17:0] unit$patch_ay;
    reg  [17:0] unit$patch_bx;
    reg  [17:0] unit$patch_by;
    reg  [17:0] unit$patch_wx;
    reg  [17:0] unit$patch_wy;
    reg  [5:0] unit$patch_sh;
    reg  [15:0] unit$patch_id;
    reg  [10:0] unit$patch_first;
    reg  [10:0] unit$patch_count;
    reg  unit$patch_retire;
    reg  unit$res_re;
    reg  [10:0] unit$res_addr;
    wire  unit$res_hit;
    wire  [15:0] unit$res_id;
    wire  [31:0] unit$res_key;
    wire  unit$busy;
    wire  [31:0] unit$tests;
    wire  [31:0] unit$marks;
    reg  tags$clock;
    reg  tags$push;
    reg  tags$pop;
    wire  [5:0] tags$tail_address;
    wire  [5:0] tags$head_address;
    wire  [5:0] tags$next_address;
    wire  tags$valid;
    wire  [6:0] tags$count;
    reg  tag_lane$clock;
    reg  [5:0] tag_lane$write_address;
    reg  [21:0] tag_lane$write_data;
    reg  tag_lane$write_enable;
    reg  [5:0] tag_lane$head_address;
    reg  [5:0] tag_lane$next_address;
    reg  tag_lane$pop;
    wire  [21:0] tag_lane$read_data;
    reg  tag_kind$clock;
    reg  [5:0] tag_kind$write_address;
    reg  tag_kind$write_data;
    reg  tag_kind$write_enable;
    reg  [5:0] tag_kind$head_address;
    reg  [5:0] tag_kind$next_address;
    reg  tag_kind$pop;
    wire  tag_kind$read_data;
    reg  job_banks$clock;
    reg  job_banks$push;
    reg  job_banks$pop;
    wire  [3:0] job_banks$tail_address;
    wire  [3:0] job_banks$head_address;
    wire  [3:0] job_banks$next_address;
    wire  job_banks$valid;
    wire  [4:0] job_banks$count;
    reg  job_bank$clock;
    reg  [3:0] job_bank$write_address;
    reg  job_bank$write_data;
    reg  job_bank$write_enable;
    reg  [3:0] job_bank$head_address;
    reg  [3:0] job_bank$next_address;
    reg  job_bank$pop;
    wire  job_bank$read_data;
    reg  job_origin_x$clock;
    reg  [3:0] job_origin_x$write_address;
    reg  [16:0] job_origin_x$write_data;
    reg  job_origin_x$write_enable;
    reg  [3:0] job_origin_x$head_address;
    reg  [3:0] job_origin_x$next_address;
    reg  job_origin_x$pop;
    wire  [16:0] job_origin_x$read_data;
    reg  job_origin_y$clock;
    reg  [3:0] job_origin_y$write_address;
    reg  [16:0] job_origin_y$write_data;
    reg  job_origin_y$write_enable;
    reg  [3:0] job_origin_y$head_address;
    reg  [3:0] job_origin_y$next_address;
    reg  job_origin_y$pop;
    wire  [16:0] job_origin_y$read_data;
    reg  bank$d;
    wire  bank$q;
    reg  bank$clock;
    reg  pend$d;
    wire  pend$q;
    reg  pend$clock;
    reg  [17:0] stg_first_x$d;
    wire  [17:0] stg_first_x$q;
    reg  stg_first_x$clock;
    reg  [17:0] stg_first_y$d;
    wire  [17:0] stg_first_y$q;
    reg  stg_first_y$clock;
    reg  [17:0] stg_last_x$d;
    wire  [17:0] stg_last_x$q;
    reg  stg_last_x$clock;
    reg  [17:0] stg_last_y$d;
    wire  [17:0] stg_last_y$q;
    reg  stg_last_y$clock;
    reg  [16:0] stg_origin_x$d;
    wire  [16:0] stg_origin_x$q;
    reg  stg_origin_x$clock;
    reg  [16:0] stg_origin_y$d;
    wire  [16:0] stg_origin_y$q;
    reg  stg_origin_y$clock;
    reg  [17:0] stg_normal_x$d;
    wire  [17:0] stg_normal_x$q;
    reg  stg_normal_x$clock;
    reg  [17:0] stg_normal_y$d;
    wire  [17:0] stg_normal_y$q;
    reg  stg_normal_y$clock;
    reg  load0$d;
    wire  load0$q;
    reg  load0$clock;
    reg  load1$d;
    wire  load1$q;
    reg  load1$clock;
    reg  [16:0] origin0_x$d;
    wire  [16:0] origin0_x$q;
    reg  origin0_x$clock;
    reg  [16:0] origin0_y$d;
    wire  [16:0] origin0_y$q;
    reg  origin0_y$clock;
    reg  [17:0] normal0_x$d;
    wire  [17:0] normal0_x$q;
    reg  normal0_x$clock;
    reg  [17:0] normal0_y$d;
    wire  [17:0] normal0_y$q;
    reg  normal0_y$clock;
    reg  [16:0] origin1_x$d;
    wire  [16:0] origin1_x$q;
    reg  origin1_x$clock;
    reg  [16:0] origin1_y$d;
    wire  [16:0] origin1_y$q;
    reg  origin1_y$clock;
    reg  [17:0] normal1_x$d;
    wire  [17:0] normal1_x$q;
    reg  normal1_x$clock;
    reg  [17:0] normal1_y$d;
    wire  [17:0] normal1_y$q;
    reg  normal1_y$clock;
    reg  [17:0] first0_x$d;
    wire  [17:0] first0_x$q;
    reg  first0_x$clock;
    reg  [17:0] first0_y$d;
    wire  [17:0] first0_y$q;
    reg  first0_y$clock;
    reg  [17:0] last0_x$d;
    wire  [17:0] last0_x$q;
    reg  last0_x$clock;
    reg  [17:0] last0_y$d;
    wire  [17:0] last0_y$q;
    reg  last0_y$clock;
    reg  [17:0] first1_x$d;
    wire  [17:0] first1_x$q;
    reg  first1_x$clock;
    reg  [17:0] first1_y$d;
    wire  [17:0] first1_y$q;
    reg  first1_y$clock;
    reg  [17:0] last1_x$d;
    wire  [17:0] last1_x$q;
    reg  last1_x$clock;
    reg  [17:0] last1_y$d;
    wire  [17:0] last1_y$q;
    reg  last1_y$clock;
    reg  [6:0] jobs0$d;
    wire  [6:0] jobs0$q;
    reg  jobs0$clock;
    reg  [6:0] jobs1$d;
    wire  [6:0] jobs1$q;
    reg  jobs1$clock;
    reg  used0$d;
    wire  used0$q;
    reg  used0$clock;
    reg  used1$d;
    wire  used1$q;
    reg  used1$clock;
    reg  tags_full$d;
    wire  tags_full$q;
    reg  tags_full$clock;
    reg  stall$d;
    wire  stall$q;
    reg  stall$clock;
    reg  other_busy$d;
    wire  other_busy$q;
    reg  other_busy$clock;
    reg  in0$d;
    wire  in0$q;
    reg  in0$clock;
    reg  in1$d;
    wire  in1$q;
    reg  in1$clock;
    
    // Local signals
    reg  head_job;
    reg  head_retire;
    reg  new_job;
    reg  accept;
    reg  pop;
    reg  [21:0] head_tag;
    reg  [10:0] head_first;
    reg  [10:0] head_count;
    reg  [21:0] new_tag;
    reg  job_pop;
    reg  room;
    reg  job;
    reg  tags_full_next;
    reg  bank_next;
    reg  used0_next;
    reg  used1_next;
    reg  sector_in;
    reg  take;
    reg  out0;
    reg  out1;
    reg  pend_next;
    
    // Sub module instances
    machine$pes$1$loader loader(
        .clock(loader$clock),
        .id_valid(loader$id_valid),
        .id_ready(loader$id_ready),
        .id(loader$id),
        .id_ready_next(loader$id_ready_next),
        .mem_req(loader$mem_req),
        .mem_addr(loader$mem_addr),
        .mem_valid(loader$mem_valid),
        .mem_ax(loader$mem_ax),
        .mem_ay(loader$mem_ay),
        .mem_bx(loader$mem_bx),
        .mem_by(loader$mem_by),
        .out_valid(loader$out_valid),
        .out_ready(loader$out_ready),
        .out_id(loader$out_id),
        .out_ax(loader$out_ax),
        .out_ay(loader$out_ay),
        .out_bx(loader$out_bx),
        .out_by(loader$out_by),
        .loads(loader$loads)
    );
    machine$pes$1$cache cache(
        .clock(cache$clock),
        .cfg_enable(cache$cfg_enable),
        .cfg_mask(cache$cfg_mask),
        .flush(cache$flush),
        .flushing(cache$flushing),
        .req(cache$req),
        .addr(cache$addr),
        .resp_valid(cache$resp_valid),
        .resp_ax(cache$resp_ax),
        .resp_ay(cache$resp_ay),
        .resp_bx(cache$resp_bx),
        .resp_by(cache$resp_by),
        .mem_req(cache$mem_req),
        .mem_addr(cache$mem_addr),
        .mem_valid(cache$mem_valid),
        .mem_ax(cache$mem_ax),
        .mem_ay(cache$mem_ay),
        .mem_bx(cache$mem_bx),
        .mem_by(cache$mem_by),
        .hits(cache$hits),
        .misses(cache$misses)
    );
    machine$pes$1$sc_slice sc_slice(
        .clock(sc_slice$clock),
        .in_valid(sc_slice$in_valid),
        .in_ready(sc_slice$in_ready),
        .in_id(sc_slice$in_id),
        .in_ax(sc_slice$in_ax),
        .in_ay(sc_slice$in_ay),
        .in_bx(sc_slice$in_bx),
        .in_by(sc_slice$in_by),
        .in_wx(sc_slice$in_wx),
        .in_wy(sc_slice$in_wy),
        .in_sh(sc_slice$in_sh),
        .in_pass(sc_slice$in_pass),
        .in_first(sc_slice$in_first),
        .in_count(sc_slice$in_count),
        .in_retire(sc_slice$in_retire),
        .out_valid(sc_slice$out_valid),
        .out_ready(sc_slice$out_ready),
        .out_id(sc_slice$out_id),
        .out_ax(sc_slice$out_ax),
        .out_ay(sc_slice$out_ay),
        .out_bx(sc_slice$out_bx),
        .out_by(sc_slice$out_by),
        .out_wx(sc_slice$out_wx),
        .out_wy(sc_slice$out_wy),
        .out_sh(sc_slice$out_sh),
        .out_pass(sc_slice$out_pass),
        .out_first(sc_slice$out_first),
        .out_count(sc_slice$out_count),
        .out_retire(sc_slice$out_retire),
        .occupied(sc_slice$occupied)
    );
    machine$pes$1$queue queue(
        .clock(queue$clock),
        .in_valid(queue$in_valid),
        .in_ready(queue$in_ready),
        .in_id(queue$in_id),
        .in_ax(queue$in_ax),
        .in_ay(queue$in_ay),
        .in_bx(queue$in_bx),
        .in_by(queue$in_by),
        .in_wx(queue$in_wx),
        .in_wy(queue$in_wy),
        .in_sh(queue$in_sh),
        .in_first(queue$in_first),
        .in_count(queue$in_count),
        .in_retire(queue$in_retire),
        .out_valid(queue$out_valid),
        .out_ready(queue$out_ready),
        .out_id(queue$out_id),
        .out_ax(queue$out_ax),
        .out_ay(queue$out_ay),
        .out_bx(queue$out_bx),
        .out_by(queue$out_by),
        .out_wx(queue$out_wx),
        .out_wy(queue$out_wy),
        .out_sh(queue$out_sh),
        .out_first(queue$out_first),
        .out_count(queue$out_count),
        .out_retire(queue$out_retire),
        .occupied(queue$occupied)
    );
    machine$pes$1$screener screener(
        .clock(screener$clock),
        .origin_x(screener$origin_x),
        .origin_y(screener$origin_y),
        .normal_x(screener$normal_x),
        .normal_y(screener$normal_y),
        .first_x(screener$first_x),
        .first_y(screener$first_y),
        .last_x(screener$last_x),
        .last_y(screener$last_y),
        .in_valid(screener$in_valid),
        .in_ready(screener$in_ready),
        .in_id(screener$in_id),
        .in_ax(screener$in_ax),
        .in_ay(screener$in_ay),
        .in_bx(screener$in_bx),
        .in_by(screener$in_by),
        .in_bank(screener$in_bank),
        .sector_read(screener$sector_read),
        .sector_bank(screener$sector_bank),
        .normal_bank(screener$normal_bank),
        .out_valid(screener$out_valid),
        .out_ready(screener$out_ready),
        .out_id(screener$out_id),
        .out_ax(screener$out_ax),
        .out_ay(screener$out_ay),
        .out_bx(screener$out_bx),
        .out_by(screener$out_by),
        .out_wx(screener$out_wx),
        .out_wy(screener$out_wy),
        .out_sh(screener$out_sh),
        .out_pass(screener$out_pass),
        .passed(screener$passed),
        .backward(screener$backward),
        .back_facing(screener$back_facing),
        .outside(screener$outside),
        .near(screener$near)
    );
    machine$pes$1$unit unit(
        .clock(unit$clock),
        .dir_we(unit$dir_we),
        .dir_addr(unit$dir_addr),
        .dir_x(unit$dir_x),
        .dir_y(unit$dir_y),
        .patch_valid(unit$patch_valid),
        .patch_ready(unit$patch_ready),
        .patch_ax(unit$patch_ax),
        .patch_ay(unit$patch_ay),
        .patch_bx(unit$patch_bx),
        .patch_by(unit$patch_by),
        .patch_wx(unit$patch_wx),
        .patch_wy(unit$patch_wy),
        .patch_sh(unit$patch_sh),
        .patch_id(unit$patch_id),
        .patch_first(unit$patch_first),
        .patch_count(unit$patch_count),
        .patch_retire(unit$patch_retire),
        .res_re(unit$res_re),
        .res_addr(unit$res_addr),
        .res_hit(unit$res_hit),
        .res_id(unit$res_id),
        .res_key(unit$res_key),
        .busy(unit$busy),
        .tests(unit$tests),
        .marks(unit$marks)
    );
    machine$pes$1$tags tags(
        .clock(tags$clock),
        .push(tags$push),
        .pop(tags$pop),
        .tail_address(tags$tail_address),
        .head_address(tags$head_address),
        .next_address(tags$next_address),
        .valid(tags$valid),
        .count(tags$count)
    );
    machine$pes$1$tag_lane tag_lane(
        .clock(tag_lane$clock),
        .write_address(tag_lane$write_address),
        .write_data(tag_lane$write_data),
        .write_enable(tag_lane$write_enable),
        .head_address(tag_lane$head_address),
        .next_address(tag_lane$next_address),
        .pop(tag_lane$pop),
        .read_data(tag_lane$read_data)
    );
    machine$pes$1$tag_kind tag_kind(
        .clock(tag_kind$clock),
        .write_address(tag_kind$write_address),
        .write_data(tag_kind$write_data),
        .write_enable(tag_kind$write_enable),
        .head_address(tag_kind$head_address),
        .next_address(tag_kind$next_address),
        .pop(tag_kind$pop),
        .read_data(tag_kind$read_data)
    );
    machine$pes$1$job_banks job_banks(
        .clock(job_banks$clock),
        .push(job_banks$push),
        .pop(job_banks$pop),
        .tail_address(job_banks$tail_address),
        .head_address(job_banks$head_address),
        .next_address(job_banks$next_address),
        .valid(job_banks$valid),
        .count(job_banks$count)
    );
    machine$pes$1$job_bank job_bank(
        .clock(job_bank$clock),
        .write_address(job_bank$write_address),
        .write_data(job_bank$write_data),
        .write_enable(job_bank$write_enable),
        .head_address(job_bank$head_address),
        .next_address(job_bank$next_address),
        .pop(job_bank$pop),
        .read_data(job_bank$read_data)
    );
    machine$pes$1$job_origin_x job_origin_x(
        .clock(job_origin_x$clock),
        .write_address(job_origin_x$write_address),
        .write_data(job_origin_x$write_data),
        .write_enable(job_origin_x$write_enable),
        .head_address(job_origin_x$head_address),
        .next_address(job_origin_x$next_address),
        .pop(job_origin_x$pop),
        .read_data(job_origin_x$read_data)
    );
    machine$pes$1$job_origin_y job_origin_y(
        .clock(job_origin_y$clock),
        .write_address(job_origin_y$write_address),
        .write_data(job_origin_y$write_data),
        .write_enable(job_origin_y$write_enable),
        .head_address(job_origin_y$head_address),
        .next_address(job_origin_y$next_address),
        .pop(job_origin_y$pop),
        .read_data(job_origin_y$read_data)
    );
    machine$pes$1$bank bank(
        .d(bank$d),
        .q(bank$q),
        .clock(bank$clock)
    );
    machine$pes$1$pend pend(
        .d(pend$d),
        .q(pend$q),
        .clock(pend$clock)
    );
    machine$pes$1$stg_first_x stg_first_x(
        .d(stg_first_x$d),
        .q(stg_first_x$q),
        .clock(stg_first_x$clock)
    );
    machine$pes$1$stg_first_y stg_first_y(
        .d(stg_first_y$d),
        .q(stg_first_y$q),
        .clock(stg_first_y$clock)
    );
    machine$pes$1$stg_last_x stg_last_x(
        .d(stg_last_x$d),
        .q(stg_last_x$q),
        .clock(stg_last_x$clock)
    );
    machine$pes$1$stg_last_y stg_last_y(
        .d(stg_last_y$d),
        .q(stg_last_y$q),
        .clock(stg_last_y$clock)
    );
    machine$pes$1$stg_origin_x stg_origin_x(
        .d(stg_origin_x$d),
        .q(stg_origin_x$q),
        .clock(stg_origin_x$clock)
    );
    machine$pes$1$stg_origin_y stg_origin_y(
        .d(stg_origin_y$d),
        .q(stg_origin_y$q),
        .clock(stg_origin_y$clock)
    );
    machine$pes$1$stg_normal_x stg_normal_x(
        .d(stg_normal_x$d),
        .q(stg_normal_x$q),
        .clock(stg_normal_x$clock)
    );
    machine$pes$1$stg_normal_y stg_normal_y(
        .d(stg_normal_y$d),
        .q(stg_normal_y$q),
        .clock(stg_normal_y$clock)
    );
    machine$pes$1$load0 load0(
        .d(load0$d),
        .q(load0$q),
        .clock(load0$clock)
    );
    machine$pes$1$load1 load1(
        .d(load1$d),
        .q(load1$q),
        .clock(load1$clock)
    );
    machine$pes$1$origin0_x origin0_x(
        .d(origin0_x$d),
        .q(origin0_x$q),
        .clock(origin0_x$clock)
    );
    machine$pes$1$origin0_y origin0_y(
        .d(origin0_y$d),
        .q(origin0_y$q),
        .clock(origin0_y$clock)
    );
    machine$pes$1$normal0_x normal0_x(
        .d(normal0_x$d),
        .q(normal0_x$q),
        .clock(normal0_x$clock)
    );
    machine$pes$1$normal0_y normal0_y(
        .d(normal0_y$d),
        .q(normal0_y$q),
        .clock(normal0_y$clock)
    );
    machine$pes$1$origin1_x origin1_x(
        .d(origin1_x$d),
        .q(origin1_x$q),
        .clock(origin1_x$clock)
    );
    machine$pes$1$origin1_y origin1_y(
        .d(origin1_y$d),
        .q(origin1_y$q),
        .clock(origin1_y$clock)
    );
    machine$pes$1$normal1_x normal1_x(
        .d(normal1_x$d),
        .q(normal1_x$q),
        .clock(normal1_x$clock)
    );
    machine$pes$1$normal1_y normal1_y(
        .d(normal1_y$d),
        .q(normal1_y$q),
        .clock(normal1_y$clock)
    );
    machine$pes$1$first0_x first0_x(
        .d(first0_x$d),
        .q(first0_x$q),
        .clock(first0_x$clock)
    );
    machine$pes$1$first0_y first0_y(
        .d(first0_y$d),
        .q(first0_y$q),
        .clock(first0_y$clock)
    );
    machine$pes$1$last0_x last0_x(
        .d(last0_x$d),
        .q(last0_x$q),
        .clock(last0_x$clock)
    );
    machine$pes$1$last0_y last0_y(
        .d(last0_y$d),
        .q(last0_y$q),
        .clock(last0_y$clock)
    );
    machine$pes$1$first1_x first1_x(
        .d(first1_x$d),
        .q(first1_x$q),
        .clock(first1_x$clock)
    );
    machine$pes$1$first1_y first1_y(
        .d(first1_y$d),
        .q(first1_y$q),
        .clock(first1_y$clock)
    );
    machine$pes$1$last1_x last1_x(
        .d(last1_x$d),
        .q(last1_x$q),
        .clock(last1_x$clock)
    );
    machine$pes$1$last1_y last1_y(
        .d(last1_y$d),
        .q(last1_y$q),
        .clock(last1_y$clock)
    );
    machine$pes$1$jobs0 jobs0(
        .d(jobs0$d),
        .q(jobs0$q),
        .clock(jobs0$clock)
    );
    machine$pes$1$jobs1 jobs1(
        .d(jobs1$d),
        .q(jobs1$q),
        .clock(jobs1$clock)
    );
    machine$pes$1$used0 used0(
        .d(used0$d),
        .q(used0$q),
        .clock(used0$clock)
    );
    machine$pes$1$used1 used1(
        .d(used1$d),
        .q(used1$q),
        .clock(used1$clock)
    );
    machine$pes$1$tags_full tags_full(
        .d(tags_full$d),
        .q(tags_full$q),
        .clock(tags_full$clock)
    );
    machine$pes$1$stall stall(
        .d(stall$d),
        .q(stall$q),
        .clock(stall$clock)
    );
    machine$pes$1$other_busy other_busy(
        .d(other_busy$d),
        .q(other_busy$q),
        .clock(other_busy$clock)
    );
    machine$pes$1$in0 in0(
        .d(in0$d),
        .q(in0$q),
        .clock(in0$clock)
    );
    machine$pes$1$in1 in1(
        .d(in1$d),
        .q(in1$q),
        .clock(in1$clock)
    );
    
    // Update code
    always @(*) begin
        bank$clock = clock;
        other_busy$clock = clock;
        pend$clock = clock;
        stg_first_x$clock = clock;
        stg_first_y$clock = clock;
        stg_last_x$clock = clock;
        stg_last_y$clock = clock;
        stg_origin_x$clock = clock;
        stg_origin_y$clock = clock;
        stg_normal_x$clock = clock;
        stg_normal_y$clock = clock;
        load0$clock = clock;
        load1$clock = clock;
        origin0_x$clock = clock;
        origin0_y$clock = clock;
        normal0_x$clock = clock;
        normal0_y$clock = clock;
        origin1_x$clock = clock;
        origin1_y$clock = clock;
        normal1_x$clock = clock;
        normal1_y$clock = clock;
        first0_x$clock = clock;
        first0_y$clock = clock;
        last0_x$clock = clock;
        last0_y$clock = clock;
        first1_x$clock = clock;
        first1_y$clock = clock;
        last1_x$clock = clock;
        last1_y$clock = clock;
        jobs0$clock = clock;
        jobs1$clock = clock;
        used0$clock = clock;
        used1$clock = clock;
        in0$clock = clock;
        in1$clock = clock;
        tags_full$clock = clock;
        stall$clock = clock;
        bank$d = bank$q;
        other_busy$d = other_busy$q;
        pend$d = pend$q;
        stg_first_x$d = stg_first_x$q;
        stg_first_y$d = stg_first_y$q;
        stg_last_x$d = stg_last_x$q;
        stg_last_y$d = stg_last_y$q;
        stg_origin_x$d = stg_origin_x$q;
        stg_origin_y$d = stg_origin_y$q;
        stg_normal_x$d = stg_normal_x$q;
        stg_normal_y$d = stg_normal_y$q;
        load0$d = load0$q;
        load1$d = load1$q;
        origin0_x$d = origin0_x$q;
        origin0_y$d = origin0_y$q;
        normal0_x$d = normal0_x$q;
        normal0_y$d = normal0_y$q;
        origin1_x$d = origin1_x$q;
        origin1_y$d = origin1_y$q;
        normal1_x$d = normal1_x$q;
        normal1_y$d = normal1_y$q;
        first0_x$d = first0_x$q;
        first0_y$d = first0_y$q;
        last0_x$d = last0_x$q;
        last0_y$d = last0_y$q;
        first1_x$d = first1_x$q;
        first1_y$d = first1_y$q;
        last1_x$d = last1_x$q;
        last1_y$d = last1_y$q;
        jobs0$d = jobs0$q;
        jobs1$d = jobs1$q;
        used0$d = used0$q;
        used1$d = used1$q;
        in0$d = in0$q;
        in1$d = in1$q;
        tags_full$d = tags_full$q;
        stall$d = stall$q;
        job_banks$clock = clock;
        job_bank$clock = clock;
        job_origin_x$clock = clock;
        job_origin_y$clock = clock;
        loader$clock = clock;
        cache$clock = clock;
        screener$clock = clock;
        unit$clock = clock;
        sc_slice$clock = clock;
        queue$clock = clock;
        tags$clock = clock;
        tag_lane$clock = clock;
        tag_kind$clock = clock;
        unit$dir_we = dir_we;
        unit$dir_addr = dir_addr;
        unit$dir_x = dir_x;
        unit$dir_y = dir_y;
        unit$res_re = res_re;
        unit$res_addr = res_addr;
        res_hit = unit$res_hit;
        res_id = unit$res_id;
        res_key = unit$res_key;
        screener$origin_x = job_origin_x$read_data;
        screener$origin_y = job_origin_y$read_data;
        screener$normal_x = normal0_x$q;
        screener$normal_y = normal0_y$q;
        if (screener$normal_bank) begin
            screener$normal_x = normal1_x$q;
            screener$normal_y = normal1_y$q;
        end
        screener$first_x = first0_x$q;
        screener$first_y = first0_y$q;
        screener$last_x = last0_x$q;
        screener$last_y = last0_y$q;
        if (screener$sector_bank) begin
            screener$first_x = first1_x$q;
            screener$first_y = first1_y$q;
            screener$last_x = last1_x$q;
            screener$last_y = last1_y$q;
        end
        room = ~stall$q;
        cmd_ready = room;
        accept = cmd_valid & room;
        job = accept & ~cmd_retire & ~cmd_sector;
        loader$id_valid = job;
        loader$id = cmd_id;
        job_banks$push = job;
        job_pop = loader$out_valid & screener$in_ready;
        job_banks$pop = job_pop;
        job_bank$write_data = zero1;
        job_origin_x$write_data = origin0_x$q;
        job_origin_y$write_data = origin0_y$q;
        if (bank$q) begin
            job_bank$write_data = one1;
            job_origin_x$write_data = origin1_x$q;
            job_origin_y$write_data = origin1_y$q;
        end
        if (load0$q | load1$q) begin
            job_origin_x$write_data = stg_origin_x$q;
            job_origin_y$write_data = stg_origin_y$q;
        end
        job_bank$write_address = job_banks$tail_address;
        job_bank$write_enable = job;
        job_bank$head_address = job_banks$head_address;
        job_bank$next_address = job_banks$next_address;
        job_bank$pop = job_pop;
        job_origin_x$write_address = job_banks$tail_address;
        job_origin_x$write_enable = job;
        job_origin_x$head_address = job_banks$head_address;
        job_origin_x$next_address = job_banks$next_address;
        job_origin_x$pop = job_pop;
        job_origin_y$write_address = job_banks$tail_address;
        job_origin_y$write_enable = job;
        job_origin_y$head_address = job_banks$head_address;
        job_origin_y$next_address = job_banks$next_address;
        job_origin_y$pop = job_pop;
        screener$in_bank = job_bank$read_data == one1;
        sector_in = accept & cmd_sector;
        if (~pend$q) begin
            stg_first_x$d = first_x;
            stg_first_y$d = first_y;
            stg_last_x$d = last_x;
            stg_last_y$d = last_y;
            stg_origin_x$d = origin_x;
            stg_origin_y$d = origin_y;
            stg_normal_x$d = normal_x;
            stg_normal_y$d = normal_y;
        end
        pend_next = pend$q;
        if (sector_in & other_busy$q) begin
            pend_next = 1'b1;
        end
        take = (sector_in | pend$q) & ~other_busy$q;
        bank_next = bank$q;
        if (take) begin
            pend_next = 1'b0;
            bank_next = ~bank$q;
        end
        load0$d = take & bank$q;
        load1$d = take & ~bank$q;
        if (load0$q) begin
            first0_x$d = stg_first_x$q;
            first0_y$d = stg_first_y$q;
            last0_x$d = stg_last_x$q;
            last0_y$d = stg_last_y$q;
            origin0_x$d = stg_origin_x$q;
            origin0_y$d = stg_origin_y$q;
            normal0_x$d = stg_normal_x$q;
            normal0_y$d = stg_normal_y$q;
        end
        if (load1$q) begin
            first1_x$d = stg_first_x$q;
            first1_y$d = stg_first_y$q;
            last1_x$d = stg_last_x$q;
            last1_y$d = stg_last_y$q;
            origin1_x$d = stg_origin_x$q;
            origin1_y$d = stg_origin_y$q;
            normal1_x$d = stg_normal_x$q;
            normal1_y$d = stg_normal_y$q;
        end
        pend$d = pend_next;
        bank$d = bank_next;
        in0$d = job & ~bank$q;
        in1$d = job & bank$q;
        out0 = screener$sector_read & ~screener$sector_bank;
        out1 = screener$sector_read & screener$sector_bank;
        if (in0$q & ~out0) begin
            jobs0$d = jobs0$q + one7;
        end
        if (out0 & ~in0$q & (jobs0$q != zero7)) begin
            jobs0$d = jobs0$q - one7;
        end
        if (in1$q & ~out1) begin
            jobs1$d = jobs1$q + one7;
        end
        if (out1 & ~in1$q & (jobs1$q != zero7)) begin
            jobs1$d = jobs1$q - one7;
        end
        used0_next = used0$q;
        if (in0$q & ~out0) begin
            used0_next = 1'b1;
        end
        if (out0 & ~in0$q & (jobs0$q == one7)) begin
            used0_next = 1'b0;
        end
        used1_next = used1$q;
        if (in1$q & ~out1) begin
            used1_next = 1'b1;
        end
        if (out1 & ~in1$q & (jobs1$q == one7)) begin
            used1_next = 1'b0;
        end
        used0$d = used0_next;
        used1$d = used1_next;
        other_busy$d = used1_next;
        if (bank_next) begin
            other_busy$d = used0_next;
        end
        new_tag = (((cmd_first) & 22'h3fffff) << 32'hb) | ((cmd_count) & 22'h3fffff);
        tags$push = accept & ~cmd_sector;
        tag_lane$write_data = new_tag;
        tag_lane$write_enable = ~tags_full$q;
        tag_lane$write_address = tags$tail_address;
        tag_lane$head_address = tags$head_address;
        tag_lane$next_address = tags$next_address;
        new_job = one1;
        if (cmd_retire) begin
            new_job = zero1;
        end
        tag_kind$write_data = new_job;
        tag_kind$write_enable = ~tags_full$q;
        tag_kind$write_address = tags$tail_address;
        tag_kind$head_address = tags$head_address;
        tag_kind$next_address = tags$next_address;
        cache$cfg_enable = cfg_cache_enable;
        cache$cfg_mask = cfg_cache_mask;
        cache$flush = cfg_cache_flush;
        cache$req = loader$mem_req;
        cache$addr = loader$mem_addr;
        loader$mem_valid = cache$resp_valid;
        loader$mem_ax = cache$resp_ax;
        loader$mem_ay = cache$resp_ay;
        loader$mem_bx = cache$resp_bx;
        loader$mem_by = cache$resp_by;
        mem_req = cache$mem_req;
        mem_addr = cache$mem_addr;
        cache$mem_valid = mem_valid;
        cache$mem_ax = mem_ax;
        cache$mem_ay = mem_ay;
        cache$mem_bx = mem_bx;
        cache$mem_by = mem_by;
        screener$in_valid = loader$out_valid;
        loader$out_ready = screener$in_ready;
        screener$in_id = loader$out_id;
        screener$in_ax = loader$out_ax;
        screener$in_ay = loader$out_ay;
        screener$in_bx = loader$out_bx;
        screener$in_by = loader$out_by;
        sc_slice$in_valid = screener$out_valid;
        screener$out_ready = sc_slice$in_ready;
        sc_slice$in_id = screener$out_id;
        sc_slice$in_ax = screener$out_ax;
        sc_slice$in_ay = screener$out_ay;
        sc_slice$in_bx = screener$out_bx;
        sc_slice$in_by = screener$out_by;
        sc_slice$in_wx = screener$out_wx;
        sc_slice$in_wy = screener$out_wy;
        sc_slice$in_sh = screener$out_sh;
        sc_slice$in_pass = screener$out_pass;
        sc_slice$in_first = 32'h0;
        sc_slice$in_count = 32'h0;
        sc_slice$in_retire = 1'b0;
        head_tag = tag_lane$read_data;
        head_job = tags$valid & |tag_kind$read_data;
        head_retire = tags$valid & ~|tag_kind$read_data;
        head_first = head_tag[(32'hb)+:(11)];
        head_count = head_tag[(32'h0)+:(11)];
        queue$in_id = sc_slice$out_id;
        queue$in_ax = sc_slice$out_ax;
        queue$in_ay = sc_slice$out_ay;
        queue$in_bx = sc_slice$out_bx;
        queue$in_by = sc_slice$out_by;
        queue$in_wx = sc_slice$out_wx;
        queue$in_wy = sc_slice$out_wy;
        queue$in_sh = sc_slice$out_sh;
        queue$in_first = head_first;
        queue$in_count = head_count;
        queue$in_retire = head_retire;
        queue$in_valid = 1'b0;
        sc_slice$out_ready = 1'b0;
        pop = 1'b0;
        if (head_retire) begin
            queue$in_valid = 1'b1;
            pop = queue$in_ready;
        end
        if (head_job & sc_slice$out_valid) begin
            if (sc_slice$out_pass) begin
                queue$in_valid = 1'b1;
                sc_slice$out_ready = queue$in_ready;
                pop = queue$in_ready;
            end
            else begin
                sc_slice$out_ready = 1'b1;
                pop = 1'b1;
            end
        end
        unit$patch_valid = queue$out_valid;
        queue$out_ready = unit$patch_ready;
        unit$patch_id = queue$out_id;
        unit$patch_ax = queue$out_ax;
        unit$patch_ay = queue$out_ay;
        unit$patch_bx = queue$out_bx;
        unit$patch_by = queue$out_by;
        unit$patch_wx = queue$out_wx;
        unit$patch_wy = queue$out_wy;
        unit$patch_sh = queue$out_sh;
        unit$patch_first = queue$out_first;
        unit$patch_count = queue$out_count;
        unit$patch_retire = queue$out_retire;
        tags$pop = pop;
        tag_lane$pop = pop;
        tag_kind$pop = pop;
        tags_full_next = ((tags$count == full) & ~pop) | ((tags$count == almost_full) & accept & ~cmd_sector & ~pop);
        tags_full$d = tags_full_next;
        stall$d = tags_full_next | ~loader$id_ready_next | pend_next;
        busy = (tags$count != zero7) | pend$q | queue$occupied | unit$busy | cache$flushing;
        loads = loader$loads;
        cache_hits = cache$hits;
        cache_misses = cache$misses;
        passed = screener$passed;
        backward = screener$backward;
        back_facing = screener$back_facing;
        outside = screener$outside;
        near = screener$near;
        tests = unit$tests;
        marks = unit$marks;
    end
    
endmodule // machine$pes$1


module machine$pes$1$bank(d,q,clock);
    
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
          
endmodule // machine$pes$1$bank


module machine$pes$1$cache(clock,cfg_enable,cfg_mask,flush,flushing,req,addr,resp_valid,resp_ax,resp_ay,resp_bx,resp_by,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,hits,misses);
    
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
    machine$pes$1$cache$q_lane q_lane(
        .clock(q_lane$clock),
        .read_address(q_lane$read_address),
        .read_data(q_lane$read_data),
        .write_address(q_lane$write_address),
        .write_data(q_lane$write_data),
        .write_enable(q_lane$write_enable)
    );
    machine$pes$1$cache$wr_ptr wr_ptr(
        .d(wr_ptr$d),
        .q(wr_ptr$q),
        .clock(wr_ptr$clock)
    );
    machine$pes$1$cache$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$cache$sp sp(
        .d(sp$d),
        .q(sp$q),
        .clock(sp$clock)
    );
    machine$pes$1$cache$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$cache$sp_inc_x sp_inc_x(
        .d(sp_inc_x$d),
        .q(sp_inc_x$q),
        .clock(sp_inc_x$clock)
    );
    machine$pes$1$cache$q_valid q_valid(
        .d(q_valid$d),
        .q(q_valid$q),
        .clock(q_valid$clock)
    );
    machine$pes$1$cache$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    machine$pes$1$cache$id1 id1(
        .d(id1$d),
        .q(id1$q),
        .clock(id1$clock)
    );
    machine$pes$1$cache$key1 key1(
        .d(key1$d),
        .q(key1$q),
        .clock(key1$clock)
    );
    machine$pes$1$cache$line1 line1(
        .d(line1$d),
        .q(line1$q),
        .clock(line1$clock)
    );
    machine$pes$1$cache$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    machine$pes$1$cache$id2 id2(
        .d(id2$d),
        .q(id2$q),
        .clock(id2$clock)
    );
    machine$pes$1$cache$key2 key2(
        .d(key2$d),
        .q(key2$q),
        .clock(key2$clock)
    );
    machine$pes$1$cache$line2 line2(
        .d(line2$d),
        .q(line2$q),
        .clock(line2$clock)
    );
    machine$pes$1$cache$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    machine$pes$1$cache$id3 id3(
        .d(id3$d),
        .q(id3$q),
        .clock(id3$clock)
    );
    machine$pes$1$cache$line3 line3(
        .d(line3$d),
        .q(line3$q),
        .clock(line3$clock)
    );
    machine$pes$1$cache$match3 match3(
        .d(match3$d),
        .q(match3$q),
        .clock(match3$clock)
    );
    machine$pes$1$cache$lconf3 lconf3(
        .d(lconf3$d),
        .q(lconf3$q),
        .clock(lconf3$clock)
    );
    machine$pes$1$cache$iconf3 iconf3(
        .d(iconf3$d),
        .q(iconf3$q),
        .clock(iconf3$clock)
    );
    machine$pes$1$cache$ax3 ax3(
        .d(ax3$d),
        .q(ax3$q),
        .clock(ax3$clock)
    );
    machine$pes$1$cache$ay3 ay3(
        .d(ay3$d),
        .q(ay3$q),
        .clock(ay3$clock)
    );
    machine$pes$1$cache$bx3 bx3(
        .d(bx3$d),
        .q(bx3$q),
        .clock(bx3$clock)
    );
    machine$pes$1$cache$by3 by3(
        .d(by3$d),
        .q(by3$q),
        .clock(by3$clock)
    );
    machine$pes$1$cache$t_id0 t_id0(
        .d(t_id0$d),
        .q(t_id0$q),
        .clock(t_id0$clock)
    );
    machine$pes$1$cache$t_id1 t_id1(
        .d(t_id1$d),
        .q(t_id1$q),
        .clock(t_id1$clock)
    );
    machine$pes$1$cache$t_id2 t_id2(
        .d(t_id2$d),
        .q(t_id2$q),
        .clock(t_id2$clock)
    );
    machine$pes$1$cache$t_id3 t_id3(
        .d(t_id3$d),
        .q(t_id3$q),
        .clock(t_id3$clock)
    );
    machine$pes$1$cache$t_line0 t_line0(
        .d(t_line0$d),
        .q(t_line0$q),
        .clock(t_line0$clock)
    );
    machine$pes$1$cache$t_line1 t_line1(
        .d(t_line1$d),
        .q(t_line1$q),
        .clock(t_line1$clock)
    );
    machine$pes$1$cache$t_line2 t_line2(
        .d(t_line2$d),
        .q(t_line2$q),
        .clock(t_line2$clock)
    );
    machine$pes$1$cache$t_line3 t_line3(
        .d(t_line3$d),
        .q(t_line3$q),
        .clock(t_line3$clock)
    );
    machine$pes$1$cache$t_v0 t_v0(
        .d(t_v0$d),
        .q(t_v0$q),
        .clock(t_v0$clock)
    );
    machine$pes$1$cache$t_v1 t_v1(
        .d(t_v1$d),
        .q(t_v1$q),
        .clock(t_v1$clock)
    );
    machine$pes$1$cache$t_v2 t_v2(
        .d(t_v2$d),
        .q(t_v2$q),
        .clock(t_v2$clock)
    );
    machine$pes$1$cache$t_v3 t_v3(
        .d(t_v3$d),
        .q(t_v3$q),
        .clock(t_v3$clock)
    );
    machine$pes$1$cache$t_any t_any(
        .d(t_any$d),
        .q(t_any$q),
        .clock(t_any$clock)
    );
    machine$pes$1$cache$t_n t_n(
        .d(t_n$d),
        .q(t_n$q),
        .clock(t_n$clock)
    );
    machine$pes$1$cache$t_full t_full(
        .d(t_full$d),
        .q(t_full$q),
        .clock(t_full$clock)
    );
    machine$pes$1$cache$t_wp t_wp(
        .d(t_wp$d),
        .q(t_wp$q),
        .clock(t_wp$clock)
    );
    machine$pes$1$cache$t_rp t_rp(
        .d(t_rp$d),
        .q(t_rp$q),
        .clock(t_rp$clock)
    );
    machine$pes$1$cache$f_id1 f_id1(
        .d(f_id1$d),
        .q(f_id1$q),
        .clock(f_id1$clock)
    );
    machine$pes$1$cache$f_line1 f_line1(
        .d(f_line1$d),
        .q(f_line1$q),
        .clock(f_line1$clock)
    );
    machine$pes$1$cache$f_v1 f_v1(
        .d(f_v1$d),
        .q(f_v1$q),
        .clock(f_v1$clock)
    );
    machine$pes$1$cache$mi0 mi0(
        .d(mi0$d),
        .q(mi0$q),
        .clock(mi0$clock)
    );
    machine$pes$1$cache$mi1 mi1(
        .d(mi1$d),
        .q(mi1$q),
        .clock(mi1$clock)
    );
    machine$pes$1$cache$mi2 mi2(
        .d(mi2$d),
        .q(mi2$q),
        .clock(mi2$clock)
    );
    machine$pes$1$cache$mi3 mi3(
        .d(mi3$d),
        .q(mi3$q),
        .clock(mi3$clock)
    );
    machine$pes$1$cache$mif mif(
        .d(mif$d),
        .q(mif$q),
        .clock(mif$clock)
    );
    machine$pes$1$cache$mis3 mis3(
        .d(mis3$d),
        .q(mis3$q),
        .clock(mis3$clock)
    );
    machine$pes$1$cache$mis2 mis2(
        .d(mis2$d),
        .q(mis2$q),
        .clock(mis2$clock)
    );
    machine$pes$1$cache$ml0 ml0(
        .d(ml0$d),
        .q(ml0$q),
        .clock(ml0$clock)
    );
    machine$pes$1$cache$ml1 ml1(
        .d(ml1$d),
        .q(ml1$q),
        .clock(ml1$clock)
    );
    machine$pes$1$cache$ml2 ml2(
        .d(ml2$d),
        .q(ml2$q),
        .clock(ml2$clock)
    );
    machine$pes$1$cache$ml3 ml3(
        .d(ml3$d),
        .q(ml3$q),
        .clock(ml3$clock)
    );
    machine$pes$1$cache$mlf mlf(
        .d(mlf$d),
        .q(mlf$q),
        .clock(mlf$clock)
    );
    machine$pes$1$cache$mls3 mls3(
        .d(mls3$d),
        .q(mls3$q),
        .clock(mls3$clock)
    );
    machine$pes$1$cache$mls2 mls2(
        .d(mls2$d),
        .q(mls2$q),
        .clock(mls2$clock)
    );
    machine$pes$1$cache$ans ans(
        .clock(ans$clock),
        .push(ans$push),
        .pop(ans$pop),
        .tail_address(ans$tail_address),
        .head_address(ans$head_address),
        .next_address(ans$next_address),
        .valid(ans$valid),
        .count(ans$count)
    );
    machine$pes$1$cache$ans_ax ans_ax(
        .clock(ans_ax$clock),
        .write_address(ans_ax$write_address),
        .write_data(ans_ax$write_data),
        .write_enable(ans_ax$write_enable),
        .head_address(ans_ax$head_address),
        .next_address(ans_ax$next_address),
        .pop(ans_ax$pop),
        .read_data(ans_ax$read_data)
    );
    machine$pes$1$cache$ans_ay ans_ay(
        .clock(ans_ay$clock),
        .write_address(ans_ay$write_address),
        .write_data(ans_ay$write_data),
        .write_enable(ans_ay$write_enable),
        .head_address(ans_ay$head_address),
        .next_address(ans_ay$next_address),
        .pop(ans_ay$pop),
        .read_data(ans_ay$read_data)
    );
    machine$pes$1$cache$ans_bx ans_bx(
        .clock(ans_bx$clock),
        .write_address(ans_bx$write_address),
        .write_data(ans_bx$write_data),
        .write_enable(ans_bx$write_enable),
        .head_address(ans_bx$head_address),
        .next_address(ans_bx$next_address),
        .pop(ans_bx$pop),
        .read_data(ans_bx$read_data)
    );
    machine$pes$1$cache$ans_by ans_by(
        .clock(ans_by$clock),
        .write_address(ans_by$write_address),
        .write_data(ans_by$write_data),
        .write_enable(ans_by$write_enable),
        .head_address(ans_by$head_address),
        .next_address(ans_by$next_address),
        .pop(ans_by$pop),
        .read_data(ans_by$read_data)
    );
    machine$pes$1$cache$ans_meta ans_meta(
        .clock(ans_meta$clock),
        .write_address(ans_meta$write_address),
        .write_data(ans_meta$write_data),
        .write_enable(ans_meta$write_enable),
        .head_address(ans_meta$head_address),
        .next_address(ans_meta$next_address),
        .pop(ans_meta$pop),
        .read_data(ans_meta$read_data)
    );
    machine$pes$1$cache$ret ret(
        .clock(ret$clock),
        .push(ret$push),
        .pop(ret$pop),
        .tail_address(ret$tail_address),
        .head_address(ret$head_address),
        .next_address(ret$next_address),
        .valid(ret$valid),
        .count(ret$count)
    );
    machine$pes$1$cache$ret_ax ret_ax(
        .clock(ret_ax$clock),
        .write_address(ret_ax$write_address),
        .write_data(ret_ax$write_data),
        .write_enable(ret_ax$write_enable),
        .head_address(ret_ax$head_address),
        .next_address(ret_ax$next_address),
        .pop(ret_ax$pop),
        .read_data(ret_ax$read_data)
    );
    machine$pes$1$cache$ret_ay ret_ay(
        .clock(ret_ay$clock),
        .write_address(ret_ay$write_address),
        .write_data(ret_ay$write_data),
        .write_enable(ret_ay$write_enable),
        .head_address(ret_ay$head_address),
        .next_address(ret_ay$next_address),
        .pop(ret_ay$pop),
        .read_data(ret_ay$read_data)
    );
    machine$pes$1$cache$ret_bx ret_bx(
        .clock(ret_bx$clock),
        .write_address(ret_bx$write_address),
        .write_data(ret_bx$write_data),
        .write_enable(ret_bx$write_enable),
        .head_address(ret_bx$head_address),
        .next_address(ret_bx$next_address),
        .pop(ret_bx$pop),
        .read_data(ret_bx$read_data)
    );
    machine$pes$1$cache$ret_by ret_by(
        .clock(ret_by$clock),
        .write_address(ret_by$write_address),
        .write_data(ret_by$write_data),
        .write_enable(ret_by$write_enable),
        .head_address(ret_by$head_address),
        .next_address(ret_by$next_address),
        .pop(ret_by$pop),
        .read_data(ret_by$read_data)
    );
    machine$pes$1$cache$fl_on fl_on(
        .d(fl_on$d),
        .q(fl_on$q),
        .clock(fl_on$clock)
    );
    machine$pes$1$cache$fl_line fl_line(
        .d(fl_line$d),
        .q(fl_line$q),
        .clock(fl_line$clock)
    );
    machine$pes$1$cache$mreq mreq(
        .d(mreq$d),
        .q(mreq$q),
        .clock(mreq$clock)
    );
    machine$pes$1$cache$maddr maddr(
        .d(maddr$d),
        .q(maddr$q),
        .clock(maddr$clock)
    );
    machine$pes$1$cache$rv rv(
        .d(rv$d),
        .q(rv$q),
        .clock(rv$clock)
    );
    machine$pes$1$cache$rax rax(
        .d(rax$d),
        .q(rax$q),
        .clock(rax$clock)
    );
    machine$pes$1$cache$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    machine$pes$1$cache$rbx rbx(
        .d(rbx$d),
        .q(rbx$q),
        .clock(rbx$clock)
    );
    machine$pes$1$cache$rby rby(
        .d(rby$d),
        .q(rby$q),
        .clock(rby$clock)
    );
    machine$pes$1$cache$hit_count hit_count(
        .d(hit_count$d),
        .q(hit_count$q),
        .clock(hit_count$clock)
    );
    machine$pes$1$cache$miss_count miss_count(
        .d(miss_count$d),
        .q(miss_count$q),
        .clock(miss_count$clock)
    );
    machine$pes$1$cache$hit_r hit_r(
        .d(hit_r$d),
        .q(hit_r$q),
        .clock(hit_r$clock)
    );
    machine$pes$1$cache$tag tag(
        .clock(tag$clock),
        .read_address(tag$read_address),
        .read_data(tag$read_data),
        .write_address(tag$write_address),
        .write_data(tag$write_data),
        .write_enable(tag$write_enable)
    );
    machine$pes$1$cache$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .read_address(lane_ax$read_address),
        .read_data(lane_ax$read_data),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable)
    );
    machine$pes$1$cache$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .read_address(lane_ay$read_address),
        .read_data(lane_ay$read_data),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable)
    );
    machine$pes$1$cache$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .read_address(lane_bx$read_address),
        .read_data(lane_bx$read_data),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable)
    );
    machine$pes$1$cache$lane_by lane_by(
        .clock(lane_by$clock),
        .read_address(lane_by$read_address),
        .read_data(lane_by$read_data),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable)
    );
    machine$pes$1$cache$ret_full ret_full(
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
    
endmodule // machine$pes$1$cache


module machine$pes$1$cache$ans(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$1$cache$ans$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$cache$ans$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$cache$ans$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$cache$ans$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$cache$ans$head_valid head_valid(
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
    
endmodule // machine$pes$1$cache$ans


module machine$pes$1$cache$ans$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ans$head_valid


module machine$pes$1$cache$ans$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ans$rd_inc_x


module machine$pes$1$cache$ans$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ans$rd_ptr


module machine$pes$1$cache$ans$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ans$tail_ptr


module machine$pes$1$cache$ans$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ans$words


module machine$pes$1$cache$ans_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ans_ax


module machine$pes$1$cache$ans_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ans_ay


module machine$pes$1$cache$ans_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ans_bx


module machine$pes$1$cache$ans_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ans_by


module machine$pes$1$cache$ans_meta(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ans_meta


module machine$pes$1$cache$ax3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ax3


module machine$pes$1$cache$ay3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ay3


module machine$pes$1$cache$bx3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$bx3


module machine$pes$1$cache$by3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$by3


module machine$pes$1$cache$f_id1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$f_id1


module machine$pes$1$cache$f_line1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$f_line1


module machine$pes$1$cache$f_v1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$f_v1


module machine$pes$1$cache$fl_line(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$fl_line


module machine$pes$1$cache$fl_on(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$fl_on


module machine$pes$1$cache$hit_count(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$hit_count


module machine$pes$1$cache$hit_r(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$hit_r


module machine$pes$1$cache$iconf3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$iconf3


module machine$pes$1$cache$id1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$id1


module machine$pes$1$cache$id2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$id2


module machine$pes$1$cache$id3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$id3


module machine$pes$1$cache$key1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$key1


module machine$pes$1$cache$key2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$key2


module machine$pes$1$cache$lane_ax(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$cache$lane_ax


module machine$pes$1$cache$lane_ay(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$cache$lane_ay


module machine$pes$1$cache$lane_bx(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$cache$lane_bx


module machine$pes$1$cache$lane_by(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$cache$lane_by


module machine$pes$1$cache$lconf3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$lconf3


module machine$pes$1$cache$line1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$line1


module machine$pes$1$cache$line2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$line2


module machine$pes$1$cache$line3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$line3


module machine$pes$1$cache$maddr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$maddr


module machine$pes$1$cache$match3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$match3


module machine$pes$1$cache$mi0(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mi0


module machine$pes$1$cache$mi1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mi1


module machine$pes$1$cache$mi2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mi2


module machine$pes$1$cache$mi3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mi3


module machine$pes$1$cache$mif(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mif


module machine$pes$1$cache$mis2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mis2


module machine$pes$1$cache$mis3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mis3


module machine$pes$1$cache$miss_count(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$miss_count


module machine$pes$1$cache$ml0(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ml0


module machine$pes$1$cache$ml1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ml1


module machine$pes$1$cache$ml2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ml2


module machine$pes$1$cache$ml3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ml3


module machine$pes$1$cache$mlf(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mlf


module machine$pes$1$cache$mls2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mls2


module machine$pes$1$cache$mls3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mls3


module machine$pes$1$cache$mreq(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$mreq


module machine$pes$1$cache$q_lane(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$cache$q_lane


module machine$pes$1$cache$q_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$q_valid


module machine$pes$1$cache$rax(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$rax


module machine$pes$1$cache$ray(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ray


module machine$pes$1$cache$rbx(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$rbx


module machine$pes$1$cache$rby(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$rby


module machine$pes$1$cache$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$rd_inc_x


module machine$pes$1$cache$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$rd_ptr


module machine$pes$1$cache$ret(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$1$cache$ret$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$cache$ret$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$cache$ret$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$cache$ret$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$cache$ret$head_valid head_valid(
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
    
endmodule // machine$pes$1$cache$ret


module machine$pes$1$cache$ret$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ret$head_valid


module machine$pes$1$cache$ret$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ret$rd_inc_x


module machine$pes$1$cache$ret$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ret$rd_ptr


module machine$pes$1$cache$ret$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ret$tail_ptr


module machine$pes$1$cache$ret$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ret$words


module machine$pes$1$cache$ret_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ret_ax


module machine$pes$1$cache$ret_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ret_ay


module machine$pes$1$cache$ret_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ret_bx


module machine$pes$1$cache$ret_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$cache$ret_by


module machine$pes$1$cache$ret_full(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$ret_full


module machine$pes$1$cache$rv(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$rv


module machine$pes$1$cache$sp(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$sp


module machine$pes$1$cache$sp_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$sp_inc_x


module machine$pes$1$cache$t_any(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_any


module machine$pes$1$cache$t_full(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_full


module machine$pes$1$cache$t_id0(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_id0


module machine$pes$1$cache$t_id1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_id1


module machine$pes$1$cache$t_id2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_id2


module machine$pes$1$cache$t_id3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_id3


module machine$pes$1$cache$t_line0(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_line0


module machine$pes$1$cache$t_line1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_line1


module machine$pes$1$cache$t_line2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_line2


module machine$pes$1$cache$t_line3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_line3


module machine$pes$1$cache$t_n(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_n


module machine$pes$1$cache$t_rp(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_rp


module machine$pes$1$cache$t_v0(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_v0


module machine$pes$1$cache$t_v1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_v1


module machine$pes$1$cache$t_v2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_v2


module machine$pes$1$cache$t_v3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_v3


module machine$pes$1$cache$t_wp(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$t_wp


module machine$pes$1$cache$tag(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$cache$tag


module machine$pes$1$cache$v1(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$v1


module machine$pes$1$cache$v2(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$v2


module machine$pes$1$cache$v3(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$v3


module machine$pes$1$cache$wr_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$cache$wr_ptr


module machine$pes$1$first0_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$first0_x


module machine$pes$1$first0_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$first0_y


module machine$pes$1$first1_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$first1_x


module machine$pes$1$first1_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$first1_y


module machine$pes$1$in0(d,q,clock);
    
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
          
endmodule // machine$pes$1$in0


module machine$pes$1$in1(d,q,clock);
    
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
          
endmodule // machine$pes$1$in1


module machine$pes$1$job_bank(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [3:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    input wire  [3:0] head_address;
    input wire  [3:0] next_address;
    input wire  pop;
    output reg  read_data;
    
    // Update code (custom)
    reg [0:0] mem [0:15];
    reg [0:0] head_r;
    reg [0:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [0:0] mem_n [0:15];
    initial for (i = 0; i <= 15; i = i + 1) mem_n[i] = 1'd0;
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
       for (i = 0; i <= 15; i = i + 1) mem[i] = 1'd0;
       head_r = 1'd0;
       next_r = 1'd0;
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
endmodule // machine$pes$1$job_bank


module machine$pes$1$job_banks(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$1$job_banks$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$job_banks$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$job_banks$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$job_banks$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$job_banks$head_valid head_valid(
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
    
endmodule // machine$pes$1$job_banks


module machine$pes$1$job_banks$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$job_banks$head_valid


module machine$pes$1$job_banks$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$job_banks$rd_inc_x


module machine$pes$1$job_banks$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$job_banks$rd_ptr


module machine$pes$1$job_banks$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$job_banks$tail_ptr


module machine$pes$1$job_banks$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$job_banks$words


module machine$pes$1$job_origin_x(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$job_origin_x


module machine$pes$1$job_origin_y(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$job_origin_y


module machine$pes$1$jobs0(d,q,clock);
    
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
          
endmodule // machine$pes$1$jobs0


module machine$pes$1$jobs1(d,q,clock);
    
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
          
endmodule // machine$pes$1$jobs1


module machine$pes$1$last0_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$last0_x


module machine$pes$1$last0_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$last0_y


module machine$pes$1$last1_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$last1_x


module machine$pes$1$last1_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$last1_y


module machine$pes$1$load0(d,q,clock);
    
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
          
endmodule // machine$pes$1$load0


module machine$pes$1$load1(d,q,clock);
    
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
          
endmodule // machine$pes$1$load1


module machine$pes$1$loader(clock,id_valid,id_ready,id,id_ready_next,mem_req,mem_addr,mem_valid,mem_ax,mem_ay,mem_bx,mem_by,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,loads);
    
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
    machine$pes$1$loader$req_ptr req_ptr(
        .d(req_ptr$d),
        .q(req_ptr$q),
        .clock(req_ptr$clock)
    );
    machine$pes$1$loader$reserved reserved(
        .d(reserved$d),
        .q(reserved$q),
        .clock(reserved$clock)
    );
    machine$pes$1$loader$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    machine$pes$1$loader$req_valid req_valid(
        .d(req_valid$d),
        .q(req_valid$q),
        .clock(req_valid$clock)
    );
    machine$pes$1$loader$req_addr req_addr(
        .d(req_addr$d),
        .q(req_addr$q),
        .clock(req_addr$clock)
    );
    machine$pes$1$loader$load_count load_count(
        .d(load_count$d),
        .q(load_count$q),
        .clock(load_count$clock)
    );
    machine$pes$1$loader$fifo fifo(
        .clock(fifo$clock),
        .push(fifo$push),
        .pop(fifo$pop),
        .tail_address(fifo$tail_address),
        .head_address(fifo$head_address),
        .next_address(fifo$next_address),
        .valid(fifo$valid),
        .count(fifo$count)
    );
    machine$pes$1$loader$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    machine$pes$1$loader$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    machine$pes$1$loader$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    machine$pes$1$loader$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    machine$pes$1$loader$lane_by lane_by(
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
    
endmodule // machine$pes$1$loader


module machine$pes$1$loader$fifo(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$1$loader$fifo$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$loader$fifo$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$loader$fifo$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$loader$fifo$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$loader$fifo$head_valid head_valid(
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
    
endmodule // machine$pes$1$loader$fifo


module machine$pes$1$loader$fifo$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$fifo$head_valid


module machine$pes$1$loader$fifo$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$fifo$rd_inc_x


module machine$pes$1$loader$fifo$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$fifo$rd_ptr


module machine$pes$1$loader$fifo$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$fifo$tail_ptr


module machine$pes$1$loader$fifo$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$fifo$words


module machine$pes$1$loader$full(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$full


module machine$pes$1$loader$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$loader$lane_ax


module machine$pes$1$loader$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$loader$lane_ay


module machine$pes$1$loader$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$loader$lane_bx


module machine$pes$1$loader$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$loader$lane_by


module machine$pes$1$loader$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$loader$lane_id


module machine$pes$1$loader$load_count(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$load_count


module machine$pes$1$loader$req_addr(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$req_addr


module machine$pes$1$loader$req_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$req_ptr


module machine$pes$1$loader$req_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$req_valid


module machine$pes$1$loader$reserved(d,q,clock);
    
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
          
endmodule // machine$pes$1$loader$reserved


module machine$pes$1$normal0_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$normal0_x


module machine$pes$1$normal0_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$normal0_y


module machine$pes$1$normal1_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$normal1_x


module machine$pes$1$normal1_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$normal1_y


module machine$pes$1$origin0_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$origin0_x


module machine$pes$1$origin0_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$origin0_y


module machine$pes$1$origin1_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$origin1_x


module machine$pes$1$origin1_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$origin1_y


module machine$pes$1$other_busy(d,q,clock);
    
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
          
endmodule // machine$pes$1$other_busy


module machine$pes$1$pend(d,q,clock);
    
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
          
endmodule // machine$pes$1$pend


module machine$pes$1$queue(clock,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_wx,in_wy,in_sh,in_first,in_count,in_retire,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_first,out_count,out_retire,occupied);
    
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
    machine$pes$1$queue$control control(
        .clock(control$clock),
        .push(control$push),
        .pop(control$pop),
        .tail_address(control$tail_address),
        .head_address(control$head_address),
        .next_address(control$next_address),
        .valid(control$valid),
        .count(control$count)
    );
    machine$pes$1$queue$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    machine$pes$1$queue$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    machine$pes$1$queue$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    machine$pes$1$queue$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    machine$pes$1$queue$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    machine$pes$1$queue$lane_wx lane_wx(
        .clock(lane_wx$clock),
        .write_address(lane_wx$write_address),
        .write_data(lane_wx$write_data),
        .write_enable(lane_wx$write_enable),
        .head_address(lane_wx$head_address),
        .next_address(lane_wx$next_address),
        .pop(lane_wx$pop),
        .read_data(lane_wx$read_data)
    );
    machine$pes$1$queue$lane_wy lane_wy(
        .clock(lane_wy$clock),
        .write_address(lane_wy$write_address),
        .write_data(lane_wy$write_data),
        .write_enable(lane_wy$write_enable),
        .head_address(lane_wy$head_address),
        .next_address(lane_wy$next_address),
        .pop(lane_wy$pop),
        .read_data(lane_wy$read_data)
    );
    machine$pes$1$queue$lane_job lane_job(
        .clock(lane_job$clock),
        .write_address(lane_job$write_address),
        .write_data(lane_job$write_data),
        .write_enable(lane_job$write_enable),
        .head_address(lane_job$head_address),
        .next_address(lane_job$next_address),
        .pop(lane_job$pop),
        .read_data(lane_job$read_data)
    );
    machine$pes$1$queue$p_valid p_valid(
        .d(p_valid$d),
        .q(p_valid$q),
        .clock(p_valid$clock)
    );
    machine$pes$1$queue$p_id p_id(
        .d(p_id$d),
        .q(p_id$q),
        .clock(p_id$clock)
    );
    machine$pes$1$queue$p_ax p_ax(
        .d(p_ax$d),
        .q(p_ax$q),
        .clock(p_ax$clock)
    );
    machine$pes$1$queue$p_ay p_ay(
        .d(p_ay$d),
        .q(p_ay$q),
        .clock(p_ay$clock)
    );
    machine$pes$1$queue$p_bx p_bx(
        .d(p_bx$d),
        .q(p_bx$q),
        .clock(p_bx$clock)
    );
    machine$pes$1$queue$p_by p_by(
        .d(p_by$d),
        .q(p_by$q),
        .clock(p_by$clock)
    );
    machine$pes$1$queue$p_wx p_wx(
        .d(p_wx$d),
        .q(p_wx$q),
        .clock(p_wx$clock)
    );
    machine$pes$1$queue$p_wy p_wy(
        .d(p_wy$d),
        .q(p_wy$q),
        .clock(p_wy$clock)
    );
    machine$pes$1$queue$p_job p_job(
        .d(p_job$d),
        .q(p_job$q),
        .clock(p_job$clock)
    );
    machine$pes$1$queue$held held(
        .d(held$d),
        .q(held$q),
        .clock(held$clock)
    );
    machine$pes$1$queue$held_full held_full(
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
    
endmodule // machine$pes$1$queue


module machine$pes$1$queue$control(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$1$queue$control$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$queue$control$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$queue$control$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$queue$control$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$queue$control$head_valid head_valid(
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
    
endmodule // machine$pes$1$queue$control


module machine$pes$1$queue$control$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$control$head_valid


module machine$pes$1$queue$control$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$control$rd_inc_x


module machine$pes$1$queue$control$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$control$rd_ptr


module machine$pes$1$queue$control$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$control$tail_ptr


module machine$pes$1$queue$control$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$control$words


module machine$pes$1$queue$held(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$held


module machine$pes$1$queue$held_full(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$held_full


module machine$pes$1$queue$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_ax


module machine$pes$1$queue$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_ay


module machine$pes$1$queue$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_bx


module machine$pes$1$queue$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_by


module machine$pes$1$queue$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_id


module machine$pes$1$queue$lane_job(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_job


module machine$pes$1$queue$lane_wx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_wx


module machine$pes$1$queue$lane_wy(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$queue$lane_wy


module machine$pes$1$queue$p_ax(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_ax


module machine$pes$1$queue$p_ay(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_ay


module machine$pes$1$queue$p_bx(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_bx


module machine$pes$1$queue$p_by(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_by


module machine$pes$1$queue$p_id(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_id


module machine$pes$1$queue$p_job(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_job


module machine$pes$1$queue$p_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_valid


module machine$pes$1$queue$p_wx(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_wx


module machine$pes$1$queue$p_wy(d,q,clock);
    
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
          
endmodule // machine$pes$1$queue$p_wy


module machine$pes$1$sc_slice(clock,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_wx,in_wy,in_sh,in_pass,in_first,in_count,in_retire,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_pass,out_first,out_count,out_retire,occupied);
    
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
    input wire  in_pass;
    input wire  [9:0] in_first;
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
    output reg  out_pass;
    output reg  [9:0] out_first;
    output reg  [10:0] out_count;
    output reg  out_retire;
    output reg  occupied;
    
    // Stub signals
    reg  m_v$d;
    wire  m_v$q;
    reg  m_v$clock;
    reg  [15:0] m_id$d;
    wire  [15:0] m_id$q;
    reg  m_id$clock;
    reg  [17:0] m_ax$d;
    wire  [17:0] m_ax$q;
    reg  m_ax$clock;
    reg  [17:0] m_ay$d;
    wire  [17:0] m_ay$q;
    reg  m_ay$clock;
    reg  [17:0] m_bx$d;
    wire  [17:0] m_bx$q;
    reg  m_bx$clock;
    reg  [17:0] m_by$d;
    wire  [17:0] m_by$q;
    reg  m_by$clock;
    reg  [17:0] m_wx$d;
    wire  [17:0] m_wx$q;
    reg  m_wx$clock;
    reg  [17:0] m_wy$d;
    wire  [17:0] m_wy$q;
    reg  m_wy$clock;
    reg  [5:0] m_sh$d;
    wire  [5:0] m_sh$q;
    reg  m_sh$clock;
    reg  m_pass$d;
    wire  m_pass$q;
    reg  m_pass$clock;
    reg  [9:0] m_first$d;
    wire  [9:0] m_first$q;
    reg  m_first$clock;
    reg  [10:0] m_count$d;
    wire  [10:0] m_count$q;
    reg  m_count$clock;
    reg  m_retire$d;
    wire  m_retire$q;
    reg  m_retire$clock;
    reg  s_v$d;
    wire  s_v$q;
    reg  s_v$clock;
    reg  [15:0] s_id$d;
    wire  [15:0] s_id$q;
    reg  s_id$clock;
    reg  [17:0] s_ax$d;
    wire  [17:0] s_ax$q;
    reg  s_ax$clock;
    reg  [17:0] s_ay$d;
    wire  [17:0] s_ay$q;
    reg  s_ay$clock;
    reg  [17:0] s_bx$d;
    wire  [17:0] s_bx$q;
    reg  s_bx$clock;
    reg  [17:0] s_by$d;
    wire  [17:0] s_by$q;
    reg  s_by$clock;
    reg  [17:0] s_wx$d;
    wire  [17:0] s_wx$q;
    reg  s_wx$clock;
    reg  [17:0] s_wy$d;
    wire  [17:0] s_wy$q;
    reg  s_wy$clock;
    reg  [5:0] s_sh$d;
    wire  [5:0] s_sh$q;
    reg  s_sh$clock;
    reg  s_pass$d;
    wire  s_pass$q;
    reg  s_pass$clock;
    reg  [9:0] s_first$d;
    wire  [9:0] s_first$q;
    reg  s_first$clock;
    reg  [10:0] s_count$d;
    wire  [10:0] s_count$q;
    reg  s_count$clock;
    reg  s_retire$d;
    wire  s_retire$q;
    reg  s_retire$clock;
    
    // Local signals
    reg  take;
    reg  load_main;
    
    // Sub module instances
    machine$pes$1$sc_slice$m_v m_v(
        .d(m_v$d),
        .q(m_v$q),
        .clock(m_v$clock)
    );
    machine$pes$1$sc_slice$m_id m_id(
        .d(m_id$d),
        .q(m_id$q),
        .clock(m_id$clock)
    );
    machine$pes$1$sc_slice$m_ax m_ax(
        .d(m_ax$d),
        .q(m_ax$q),
        .clock(m_ax$clock)
    );
    machine$pes$1$sc_slice$m_ay m_ay(
        .d(m_ay$d),
        .q(m_ay$q),
        .clock(m_ay$clock)
    );
    machine$pes$1$sc_slice$m_bx m_bx(
        .d(m_bx$d),
        .q(m_bx$q),
        .clock(m_bx$clock)
    );
    machine$pes$1$sc_slice$m_by m_by(
        .d(m_by$d),
        .q(m_by$q),
        .clock(m_by$clock)
    );
    machine$pes$1$sc_slice$m_wx m_wx(
        .d(m_wx$d),
        .q(m_wx$q),
        .clock(m_wx$clock)
    );
    machine$pes$1$sc_slice$m_wy m_wy(
        .d(m_wy$d),
        .q(m_wy$q),
        .clock(m_wy$clock)
    );
    machine$pes$1$sc_slice$m_sh m_sh(
        .d(m_sh$d),
        .q(m_sh$q),
        .clock(m_sh$clock)
    );
    machine$pes$1$sc_slice$m_pass m_pass(
        .d(m_pass$d),
        .q(m_pass$q),
        .clock(m_pass$clock)
    );
    machine$pes$1$sc_slice$m_first m_first(
        .d(m_first$d),
        .q(m_first$q),
        .clock(m_first$clock)
    );
    machine$pes$1$sc_slice$m_count m_count(
        .d(m_count$d),
        .q(m_count$q),
        .clock(m_count$clock)
    );
    machine$pes$1$sc_slice$m_retire m_retire(
        .d(m_retire$d),
        .q(m_retire$q),
        .clock(m_retire$clock)
    );
    machine$pes$1$sc_slice$s_v s_v(
        .d(s_v$d),
        .q(s_v$q),
        .clock(s_v$clock)
    );
    machine$pes$1$sc_slice$s_id s_id(
        .d(s_id$d),
        .q(s_id$q),
        .clock(s_id$clock)
    );
    machine$pes$1$sc_slice$s_ax s_ax(
        .d(s_ax$d),
        .q(s_ax$q),
        .clock(s_ax$clock)
    );
    machine$pes$1$sc_slice$s_ay s_ay(
        .d(s_ay$d),
        .q(s_ay$q),
        .clock(s_ay$clock)
    );
    machine$pes$1$sc_slice$s_bx s_bx(
        .d(s_bx$d),
        .q(s_bx$q),
        .clock(s_bx$clock)
    );
    machine$pes$1$sc_slice$s_by s_by(
        .d(s_by$d),
        .q(s_by$q),
        .clock(s_by$clock)
    );
    machine$pes$1$sc_slice$s_wx s_wx(
        .d(s_wx$d),
        .q(s_wx$q),
        .clock(s_wx$clock)
    );
    machine$pes$1$sc_slice$s_wy s_wy(
        .d(s_wy$d),
        .q(s_wy$q),
        .clock(s_wy$clock)
    );
    machine$pes$1$sc_slice$s_sh s_sh(
        .d(s_sh$d),
        .q(s_sh$q),
        .clock(s_sh$clock)
    );
    machine$pes$1$sc_slice$s_pass s_pass(
        .d(s_pass$d),
        .q(s_pass$q),
        .clock(s_pass$clock)
    );
    machine$pes$1$sc_slice$s_first s_first(
        .d(s_first$d),
        .q(s_first$q),
        .clock(s_first$clock)
    );
    machine$pes$1$sc_slice$s_count s_count(
        .d(s_count$d),
        .q(s_count$q),
        .clock(s_count$clock)
    );
    machine$pes$1$sc_slice$s_retire s_retire(
        .d(s_retire$d),
        .q(s_retire$q),
        .clock(s_retire$clock)
    );
    
    // Update code
    always @(*) begin
        m_v$clock = clock;
        m_id$clock = clock;
        m_ax$clock = clock;
        m_ay$clock = clock;
        m_bx$clock = clock;
        m_by$clock = clock;
        m_wx$clock = clock;
        m_wy$clock = clock;
        m_sh$clock = clock;
        m_pass$clock = clock;
        m_first$clock = clock;
        m_count$clock = clock;
        m_retire$clock = clock;
        s_v$clock = clock;
        s_id$clock = clock;
        s_ax$clock = clock;
        s_ay$clock = clock;
        s_bx$clock = clock;
        s_by$clock = clock;
        s_wx$clock = clock;
        s_wy$clock = clock;
        s_sh$clock = clock;
        s_pass$clock = clock;
        s_first$clock = clock;
        s_count$clock = clock;
        s_retire$clock = clock;
        m_v$d = m_v$q;
        m_id$d = m_id$q;
        m_ax$d = m_ax$q;
        m_ay$d = m_ay$q;
        m_bx$d = m_bx$q;
        m_by$d = m_by$q;
        m_wx$d = m_wx$q;
        m_wy$d = m_wy$q;
        m_sh$d = m_sh$q;
        m_pass$d = m_pass$q;
        m_first$d = m_first$q;
        m_count$d = m_count$q;
        m_retire$d = m_retire$q;
        s_v$d = s_v$q;
        s_id$d = s_id$q;
        s_ax$d = s_ax$q;
        s_ay$d = s_ay$q;
        s_bx$d = s_bx$q;
        s_by$d = s_by$q;
        s_wx$d = s_wx$q;
        s_wy$d = s_wy$q;
        s_sh$d = s_sh$q;
        s_pass$d = s_pass$q;
        s_first$d = s_first$q;
        s_count$d = s_count$q;
        s_retire$d = s_retire$q;
        in_ready = ~s_v$q;
        take = in_valid & ~s_v$q;
        load_main = ~m_v$q | out_ready;
        if (load_main) begin
            m_v$d = s_v$q | take;
            s_v$d = 1'b0;
            if (s_v$q) begin
                m_id$d = s_id$q;
                m_ax$d = s_ax$q;
                m_ay$d = s_ay$q;
                m_bx$d = s_bx$q;
                m_by$d = s_by$q;
                m_wx$d = s_wx$q;
                m_wy$d = s_wy$q;
                m_sh$d = s_sh$q;
                m_pass$d = s_pass$q;
                m_first$d = s_first$q;
                m_count$d = s_count$q;
                m_retire$d = s_retire$q;
            end
            else begin
                m_id$d = in_id;
                m_ax$d = in_ax;
                m_ay$d = in_ay;
                m_bx$d = in_bx;
                m_by$d = in_by;
                m_wx$d = in_wx;
                m_wy$d = in_wy;
                m_sh$d = in_sh;
                m_pass$d = in_pass;
                m_first$d = in_first;
                m_count$d = in_count;
                m_retire$d = in_retire;
            end
        end
        else begin
            s_v$d = s_v$q | take;
        end
        if (~s_v$q) begin
            s_id$d = in_id;
            s_ax$d = in_ax;
            s_ay$d = in_ay;
            s_bx$d = in_bx;
            s_by$d = in_by;
            s_wx$d = in_wx;
            s_wy$d = in_wy;
            s_sh$d = in_sh;
            s_pass$d = in_pass;
            s_first$d = in_first;
            s_count$d = in_count;
            s_retire$d = in_retire;
        end
        out_valid = m_v$q;
        out_id = m_id$q;
        out_ax = m_ax$q;
        out_ay = m_ay$q;
        out_bx = m_bx$q;
        out_by = m_by$q;
        out_wx = m_wx$q;
        out_wy = m_wy$q;
        out_sh = m_sh$q;
        out_pass = m_pass$q;
        out_first = m_first$q;
        out_count = m_count$q;
        out_retire = m_retire$q;
        occupied = m_v$q | s_v$q;
    end
    
endmodule // machine$pes$1$sc_slice


module machine$pes$1$sc_slice$m_ax(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_ax


module machine$pes$1$sc_slice$m_ay(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_ay


module machine$pes$1$sc_slice$m_bx(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_bx


module machine$pes$1$sc_slice$m_by(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_by


module machine$pes$1$sc_slice$m_count(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_count


module machine$pes$1$sc_slice$m_first(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_first


module machine$pes$1$sc_slice$m_id(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_id


module machine$pes$1$sc_slice$m_pass(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_pass


module machine$pes$1$sc_slice$m_retire(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_retire


module machine$pes$1$sc_slice$m_sh(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_sh


module machine$pes$1$sc_slice$m_v(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_v


module machine$pes$1$sc_slice$m_wx(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_wx


module machine$pes$1$sc_slice$m_wy(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$m_wy


module machine$pes$1$sc_slice$s_ax(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_ax


module machine$pes$1$sc_slice$s_ay(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_ay


module machine$pes$1$sc_slice$s_bx(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_bx


module machine$pes$1$sc_slice$s_by(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_by


module machine$pes$1$sc_slice$s_count(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_count


module machine$pes$1$sc_slice$s_first(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_first


module machine$pes$1$sc_slice$s_id(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_id


module machine$pes$1$sc_slice$s_pass(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_pass


module machine$pes$1$sc_slice$s_retire(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_retire


module machine$pes$1$sc_slice$s_sh(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_sh


module machine$pes$1$sc_slice$s_v(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_v


module machine$pes$1$sc_slice$s_wx(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_wx


module machine$pes$1$sc_slice$s_wy(d,q,clock);
    
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
          
endmodule // machine$pes$1$sc_slice$s_wy


module machine$pes$1$screener(clock,origin_x,origin_y,normal_x,normal_y,first_x,first_y,last_x,last_y,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,in_bank,sector_read,sector_bank,normal_bank,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,out_pass,passed,backward,back_facing,outside,near);
    
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
    machine$pes$1$screener$used used(
        .d(used$d),
        .q(used$q),
        .clock(used$clock)
    );
    machine$pes$1$screener$res_ptr res_ptr(
        .d(res_ptr$d),
        .q(res_ptr$q),
        .clock(res_ptr$clock)
    );
    machine$pes$1$screener$fifo fifo(
        .clock(fifo$clock),
        .push(fifo$push),
        .pop(fifo$pop),
        .tail_address(fifo$tail_address),
        .head_address(fifo$head_address),
        .next_address(fifo$next_address),
        .valid(fifo$valid),
        .count(fifo$count)
    );
    machine$pes$1$screener$lane_id lane_id(
        .clock(lane_id$clock),
        .write_address(lane_id$write_address),
        .write_data(lane_id$write_data),
        .write_enable(lane_id$write_enable),
        .head_address(lane_id$head_address),
        .next_address(lane_id$next_address),
        .pop(lane_id$pop),
        .read_data(lane_id$read_data)
    );
    machine$pes$1$screener$lane_ax lane_ax(
        .clock(lane_ax$clock),
        .write_address(lane_ax$write_address),
        .write_data(lane_ax$write_data),
        .write_enable(lane_ax$write_enable),
        .head_address(lane_ax$head_address),
        .next_address(lane_ax$next_address),
        .pop(lane_ax$pop),
        .read_data(lane_ax$read_data)
    );
    machine$pes$1$screener$lane_ay lane_ay(
        .clock(lane_ay$clock),
        .write_address(lane_ay$write_address),
        .write_data(lane_ay$write_data),
        .write_enable(lane_ay$write_enable),
        .head_address(lane_ay$head_address),
        .next_address(lane_ay$next_address),
        .pop(lane_ay$pop),
        .read_data(lane_ay$read_data)
    );
    machine$pes$1$screener$lane_bx lane_bx(
        .clock(lane_bx$clock),
        .write_address(lane_bx$write_address),
        .write_data(lane_bx$write_data),
        .write_enable(lane_bx$write_enable),
        .head_address(lane_bx$head_address),
        .next_address(lane_bx$next_address),
        .pop(lane_bx$pop),
        .read_data(lane_bx$read_data)
    );
    machine$pes$1$screener$lane_by lane_by(
        .clock(lane_by$clock),
        .write_address(lane_by$write_address),
        .write_data(lane_by$write_data),
        .write_enable(lane_by$write_enable),
        .head_address(lane_by$head_address),
        .next_address(lane_by$next_address),
        .pop(lane_by$pop),
        .read_data(lane_by$read_data)
    );
    machine$pes$1$screener$lane_sh lane_sh(
        .clock(lane_sh$clock),
        .write_address(lane_sh$write_address),
        .write_data(lane_sh$write_data),
        .write_enable(lane_sh$write_enable),
        .head_address(lane_sh$head_address),
        .next_address(lane_sh$next_address),
        .pop(lane_sh$pop),
        .read_data(lane_sh$read_data)
    );
    machine$pes$1$screener$lane_wx lane_wx(
        .clock(lane_wx$clock),
        .write_address(lane_wx$write_address),
        .write_data(lane_wx$write_data),
        .write_enable(lane_wx$write_enable),
        .head_address(lane_wx$head_address),
        .next_address(lane_wx$next_address),
        .pop(lane_wx$pop),
        .read_data(lane_wx$read_data)
    );
    machine$pes$1$screener$lane_wy lane_wy(
        .clock(lane_wy$clock),
        .write_address(lane_wy$write_address),
        .write_data(lane_wy$write_data),
        .write_enable(lane_wy$write_enable),
        .head_address(lane_wy$head_address),
        .next_address(lane_wy$next_address),
        .pop(lane_wy$pop),
        .read_data(lane_wy$read_data)
    );
    machine$pes$1$screener$full full(
        .d(full$d),
        .q(full$q),
        .clock(full$clock)
    );
    machine$pes$1$screener$v1 v1(
        .d(v1$d),
        .q(v1$q),
        .clock(v1$clock)
    );
    machine$pes$1$screener$bank1 bank1(
        .d(bank1$d),
        .q(bank1$q),
        .clock(bank1$clock)
    );
    machine$pes$1$screener$id1 id1(
        .d(id1$d),
        .q(id1$q),
        .clock(id1$clock)
    );
    machine$pes$1$screener$ax1 ax1(
        .d(ax1$d),
        .q(ax1$q),
        .clock(ax1$clock)
    );
    machine$pes$1$screener$ay1 ay1(
        .d(ay1$d),
        .q(ay1$q),
        .clock(ay1$clock)
    );
    machine$pes$1$screener$bx1 bx1(
        .d(bx1$d),
        .q(bx1$q),
        .clock(bx1$clock)
    );
    machine$pes$1$screener$by1 by1(
        .d(by1$d),
        .q(by1$q),
        .clock(by1$clock)
    );
    machine$pes$1$screener$m_nax m_nax(
        .clock(m_nax$clock),
        .a(m_nax$a),
        .b(m_nax$b),
        .p(m_nax$p)
    );
    machine$pes$1$screener$m_nay m_nay(
        .clock(m_nay$clock),
        .a(m_nay$a),
        .b(m_nay$b),
        .p(m_nay$p)
    );
    machine$pes$1$screener$m_nbx m_nbx(
        .clock(m_nbx$clock),
        .a(m_nbx$a),
        .b(m_nbx$b),
        .p(m_nbx$p)
    );
    machine$pes$1$screener$m_nby m_nby(
        .clock(m_nby$clock),
        .a(m_nby$a),
        .b(m_nby$b),
        .p(m_nby$p)
    );
    machine$pes$1$screener$m_aby m_aby(
        .clock(m_aby$clock),
        .a(m_aby$a),
        .b(m_aby$b),
        .p(m_aby$p)
    );
    machine$pes$1$screener$m_abx m_abx(
        .clock(m_abx$clock),
        .a(m_abx$a),
        .b(m_abx$b),
        .p(m_abx$p)
    );
    machine$pes$1$screener$m_fby m_fby(
        .clock(m_fby$clock),
        .a(m_fby$a),
        .b(m_fby$b),
        .p(m_fby$p)
    );
    machine$pes$1$screener$m_fbx m_fbx(
        .clock(m_fbx$clock),
        .a(m_fbx$a),
        .b(m_fbx$b),
        .p(m_fbx$p)
    );
    machine$pes$1$screener$m_lay m_lay(
        .clock(m_lay$clock),
        .a(m_lay$a),
        .b(m_lay$b),
        .p(m_lay$p)
    );
    machine$pes$1$screener$m_lax m_lax(
        .clock(m_lax$clock),
        .a(m_lax$a),
        .b(m_lax$b),
        .p(m_lax$p)
    );
    machine$pes$1$screener$v2 v2(
        .d(v2$d),
        .q(v2$q),
        .clock(v2$clock)
    );
    machine$pes$1$screener$bank2 bank2(
        .d(bank2$d),
        .q(bank2$q),
        .clock(bank2$clock)
    );
    machine$pes$1$screener$id2 id2(
        .d(id2$d),
        .q(id2$q),
        .clock(id2$clock)
    );
    machine$pes$1$screener$ax2 ax2(
        .d(ax2$d),
        .q(ax2$q),
        .clock(ax2$clock)
    );
    machine$pes$1$screener$ay2 ay2(
        .d(ay2$d),
        .q(ay2$q),
        .clock(ay2$clock)
    );
    machine$pes$1$screener$bx2 bx2(
        .d(bx2$d),
        .q(bx2$q),
        .clock(bx2$clock)
    );
    machine$pes$1$screener$by2 by2(
        .d(by2$d),
        .q(by2$q),
        .clock(by2$clock)
    );
    machine$pes$1$screener$absnx2 absnx2(
        .d(absnx2$d),
        .q(absnx2$q),
        .clock(absnx2$clock)
    );
    machine$pes$1$screener$absny2 absny2(
        .d(absny2$d),
        .q(absny2$q),
        .clock(absny2$clock)
    );
    machine$pes$1$screener$negx2 negx2(
        .d(negx2$d),
        .q(negx2$q),
        .clock(negx2$clock)
    );
    machine$pes$1$screener$negy2 negy2(
        .d(negy2$d),
        .q(negy2$q),
        .clock(negy2$clock)
    );
    machine$pes$1$screener$normal_x2 normal_x2(
        .d(normal_x2$d),
        .q(normal_x2$q),
        .clock(normal_x2$clock)
    );
    machine$pes$1$screener$normal_y2 normal_y2(
        .d(normal_y2$d),
        .q(normal_y2$q),
        .clock(normal_y2$clock)
    );
    machine$pes$1$screener$normal_xa2 normal_xa2(
        .d(normal_xa2$d),
        .q(normal_xa2$q),
        .clock(normal_xa2$clock)
    );
    machine$pes$1$screener$normal_ya2 normal_ya2(
        .d(normal_ya2$d),
        .q(normal_ya2$q),
        .clock(normal_ya2$clock)
    );
    machine$pes$1$screener$v3 v3(
        .d(v3$d),
        .q(v3$q),
        .clock(v3$clock)
    );
    machine$pes$1$screener$bank3 bank3(
        .d(bank3$d),
        .q(bank3$q),
        .clock(bank3$clock)
    );
    machine$pes$1$screener$id3 id3(
        .d(id3$d),
        .q(id3$q),
        .clock(id3$clock)
    );
    machine$pes$1$screener$ax3 ax3(
        .d(ax3$d),
        .q(ax3$q),
        .clock(ax3$clock)
    );
    machine$pes$1$screener$ay3 ay3(
        .d(ay3$d),
        .q(ay3$q),
        .clock(ay3$clock)
    );
    machine$pes$1$screener$bx3 bx3(
        .d(bx3$d),
        .q(bx3$q),
        .clock(bx3$clock)
    );
    machine$pes$1$screener$by3 by3(
        .d(by3$d),
        .q(by3$q),
        .clock(by3$clock)
    );
    machine$pes$1$screener$absnx3 absnx3(
        .d(absnx3$d),
        .q(absnx3$q),
        .clock(absnx3$clock)
    );
    machine$pes$1$screener$absny3 absny3(
        .d(absny3$d),
        .q(absny3$q),
        .clock(absny3$clock)
    );
    machine$pes$1$screener$negx3 negx3(
        .d(negx3$d),
        .q(negx3$q),
        .clock(negx3$clock)
    );
    machine$pes$1$screener$negy3 negy3(
        .d(negy3$d),
        .q(negy3$q),
        .clock(negy3$clock)
    );
    machine$pes$1$screener$nmax3 nmax3(
        .d(nmax3$d),
        .q(nmax3$q),
        .clock(nmax3$clock)
    );
    machine$pes$1$screener$v4 v4(
        .d(v4$d),
        .q(v4$q),
        .clock(v4$clock)
    );
    machine$pes$1$screener$id4 id4(
        .d(id4$d),
        .q(id4$q),
        .clock(id4$clock)
    );
    machine$pes$1$screener$p_aby4 p_aby4(
        .d(p_aby4$d),
        .q(p_aby4$q),
        .clock(p_aby4$clock)
    );
    machine$pes$1$screener$p_abx4 p_abx4(
        .d(p_abx4$d),
        .q(p_abx4$q),
        .clock(p_abx4$clock)
    );
    machine$pes$1$screener$v5 v5(
        .d(v5$d),
        .q(v5$q),
        .clock(v5$clock)
    );
    machine$pes$1$screener$id5 id5(
        .d(id5$d),
        .q(id5$q),
        .clock(id5$clock)
    );
    machine$pes$1$screener$k5 k5(
        .d(k5$d),
        .q(k5$q),
        .clock(k5$clock)
    );
    machine$pes$1$screener$p_nax5 p_nax5(
        .d(p_nax5$d),
        .q(p_nax5$q),
        .clock(p_nax5$clock)
    );
    machine$pes$1$screener$p_nay5 p_nay5(
        .d(p_nay5$d),
        .q(p_nay5$q),
        .clock(p_nay5$clock)
    );
    machine$pes$1$screener$p_nbx5 p_nbx5(
        .d(p_nbx5$d),
        .q(p_nbx5$q),
        .clock(p_nbx5$clock)
    );
    machine$pes$1$screener$p_nby5 p_nby5(
        .d(p_nby5$d),
        .q(p_nby5$q),
        .clock(p_nby5$clock)
    );
    machine$pes$1$screener$v6 v6(
        .d(v6$d),
        .q(v6$q),
        .clock(v6$clock)
    );
    machine$pes$1$screener$id6 id6(
        .d(id6$d),
        .q(id6$q),
        .clock(id6$clock)
    );
    machine$pes$1$screener$k_nonpos6 k_nonpos6(
        .d(k_nonpos6$d),
        .q(k_nonpos6$q),
        .clock(k_nonpos6$clock)
    );
    machine$pes$1$screener$ha6 ha6(
        .d(ha6$d),
        .q(ha6$q),
        .clock(ha6$clock)
    );
    machine$pes$1$screener$hb6 hb6(
        .d(hb6$d),
        .q(hb6$q),
        .clock(hb6$clock)
    );
    machine$pes$1$screener$p_fby6 p_fby6(
        .d(p_fby6$d),
        .q(p_fby6$q),
        .clock(p_fby6$clock)
    );
    machine$pes$1$screener$p_fbx6 p_fbx6(
        .d(p_fbx6$d),
        .q(p_fbx6$q),
        .clock(p_fbx6$clock)
    );
    machine$pes$1$screener$p_lay6 p_lay6(
        .d(p_lay6$d),
        .q(p_lay6$q),
        .clock(p_lay6$clock)
    );
    machine$pes$1$screener$p_lax6 p_lax6(
        .d(p_lax6$d),
        .q(p_lax6$q),
        .clock(p_lax6$clock)
    );
    machine$pes$1$screener$clz_n6 clz_n6(
        .d(clz_n6$d),
        .q(clz_n6$q),
        .clock(clz_n6$clock)
    );
    machine$pes$1$screener$norm_n6 norm_n6(
        .d(norm_n6$d),
        .q(norm_n6$q),
        .clock(norm_n6$clock)
    );
    machine$pes$1$screener$v7 v7(
        .d(v7$d),
        .q(v7$q),
        .clock(v7$clock)
    );
    machine$pes$1$screener$id7 id7(
        .d(id7$d),
        .q(id7$q),
        .clock(id7$clock)
    );
    machine$pes$1$screener$side_f7 side_f7(
        .d(side_f7$d),
        .q(side_f7$q),
        .clock(side_f7$clock)
    );
    machine$pes$1$screener$side_l7 side_l7(
        .d(side_l7$d),
        .q(side_l7$q),
        .clock(side_l7$clock)
    );
    machine$pes$1$screener$clz_n7 clz_n7(
        .d(clz_n7$d),
        .q(clz_n7$q),
        .clock(clz_n7$clock)
    );
    machine$pes$1$screener$norm_n7 norm_n7(
        .d(norm_n7$d),
        .q(norm_n7$q),
        .clock(norm_n7$clock)
    );
    machine$pes$1$screener$backward7 backward7(
        .d(backward7$d),
        .q(backward7$q),
        .clock(backward7$clock)
    );
    machine$pes$1$screener$back_facing7 back_facing7(
        .d(back_facing7$d),
        .q(back_facing7$q),
        .clock(back_facing7$clock)
    );
    machine$pes$1$screener$ha_open7 ha_open7(
        .d(ha_open7$d),
        .q(ha_open7$q),
        .clock(ha_open7$clock)
    );
    machine$pes$1$screener$hb_open7 hb_open7(
        .d(hb_open7$d),
        .q(hb_open7$q),
        .clock(hb_open7$clock)
    );
    machine$pes$1$screener$f_hi_lt8 f_hi_lt8(
        .d(f_hi_lt8$d),
        .q(f_hi_lt8$q),
        .clock(f_hi_lt8$clock)
    );
    machine$pes$1$screener$f_hi_eq8 f_hi_eq8(
        .d(f_hi_eq8$d),
        .q(f_hi_eq8$q),
        .clock(f_hi_eq8$clock)
    );
    machine$pes$1$screener$f_lo_lt8 f_lo_lt8(
        .d(f_lo_lt8$d),
        .q(f_lo_lt8$q),
        .clock(f_lo_lt8$clock)
    );
    machine$pes$1$screener$l_hi_gt8 l_hi_gt8(
        .d(l_hi_gt8$d),
        .q(l_hi_gt8$q),
        .clock(l_hi_gt8$clock)
    );
    machine$pes$1$screener$l_hi_eq8 l_hi_eq8(
        .d(l_hi_eq8$d),
        .q(l_hi_eq8$q),
        .clock(l_hi_eq8$clock)
    );
    machine$pes$1$screener$l_lo_gt8 l_lo_gt8(
        .d(l_lo_gt8$d),
        .q(l_lo_gt8$q),
        .clock(l_lo_gt8$clock)
    );
    machine$pes$1$screener$ha_open8 ha_open8(
        .d(ha_open8$d),
        .q(ha_open8$q),
        .clock(ha_open8$clock)
    );
    machine$pes$1$screener$hb_open8 hb_open8(
        .d(hb_open8$d),
        .q(hb_open8$q),
        .clock(hb_open8$clock)
    );
    machine$pes$1$screener$v8 v8(
        .d(v8$d),
        .q(v8$q),
        .clock(v8$clock)
    );
    machine$pes$1$screener$id8 id8(
        .d(id8$d),
        .q(id8$q),
        .clock(id8$clock)
    );
    machine$pes$1$screener$s0_8 s0_8(
        .d(s0_8$d),
        .q(s0_8$q),
        .clock(s0_8$clock)
    );
    machine$pes$1$screener$s0_m1_8 s0_m1_8(
        .d(s0_m1_8$d),
        .q(s0_m1_8$q),
        .clock(s0_m1_8$clock)
    );
    machine$pes$1$screener$below8 below8(
        .d(below8$d),
        .q(below8$q),
        .clock(below8$clock)
    );
    machine$pes$1$screener$near_a8 near_a8(
        .d(near_a8$d),
        .q(near_a8$q),
        .clock(near_a8$clock)
    );
    machine$pes$1$screener$near_b8 near_b8(
        .d(near_b8$d),
        .q(near_b8$q),
        .clock(near_b8$clock)
    );
    machine$pes$1$screener$sp3_8 sp3_8(
        .d(sp3_8$d),
        .q(sp3_8$q),
        .clock(sp3_8$clock)
    );
    machine$pes$1$screener$clz_n2_7 clz_n2_7(
        .d(clz_n2_7$d),
        .q(clz_n2_7$q),
        .clock(clz_n2_7$clock)
    );
    machine$pes$1$screener$clz_n3_7 clz_n3_7(
        .d(clz_n3_7$d),
        .q(clz_n3_7$q),
        .clock(clz_n3_7$clock)
    );
    machine$pes$1$screener$backward8 backward8(
        .d(backward8$d),
        .q(backward8$q),
        .clock(backward8$clock)
    );
    machine$pes$1$screener$back_facing8 back_facing8(
        .d(back_facing8$d),
        .q(back_facing8$q),
        .clock(back_facing8$clock)
    );
    machine$pes$1$screener$pass9 pass9(
        .d(pass9$d),
        .q(pass9$q),
        .clock(pass9$clock)
    );
    machine$pes$1$screener$backward9 backward9(
        .d(backward9$d),
        .q(backward9$q),
        .clock(backward9$clock)
    );
    machine$pes$1$screener$back_facing9 back_facing9(
        .d(back_facing9$d),
        .q(back_facing9$q),
        .clock(back_facing9$clock)
    );
    machine$pes$1$screener$outside9 outside9(
        .d(outside9$d),
        .q(outside9$q),
        .clock(outside9$clock)
    );
    machine$pes$1$screener$near9 near9(
        .d(near9$d),
        .q(near9$q),
        .clock(near9$clock)
    );
    machine$pes$1$screener$c_ax c_ax(
        .clock(c_ax$clock),
        .d(c_ax$d),
        .q(c_ax$q)
    );
    machine$pes$1$screener$c_ay c_ay(
        .clock(c_ay$clock),
        .d(c_ay$d),
        .q(c_ay$q)
    );
    machine$pes$1$screener$c_bx c_bx(
        .clock(c_bx$clock),
        .d(c_bx$d),
        .q(c_bx$q)
    );
    machine$pes$1$screener$c_by c_by(
        .clock(c_by$clock),
        .d(c_by$d),
        .q(c_by$q)
    );
    machine$pes$1$screener$c_absnx c_absnx(
        .clock(c_absnx$clock),
        .d(c_absnx$d),
        .q(c_absnx$q)
    );
    machine$pes$1$screener$c_absny c_absny(
        .clock(c_absny$clock),
        .d(c_absny$d),
        .q(c_absny$q)
    );
    machine$pes$1$screener$c_negx c_negx(
        .clock(c_negx$clock),
        .d(c_negx$d),
        .q(c_negx$q)
    );
    machine$pes$1$screener$c_negy c_negy(
        .clock(c_negy$clock),
        .d(c_negy$d),
        .q(c_negy$q)
    );
    machine$pes$1$screener$c_k c_k(
        .clock(c_k$clock),
        .d(c_k$d),
        .q(c_k$q)
    );
    machine$pes$1$screener$lz_n lz_n(
        .clock(lz_n$clock),
        .value(lz_n$value),
        .norm(lz_n$norm),
        .clz(lz_n$clz)
    );
    machine$pes$1$screener$lz_e lz_e(
        .clock(lz_e$clock),
        .value(lz_e$value),
        .norm(lz_e$norm),
        .clz(lz_e$clz)
    );
    machine$pes$1$screener$divider divider(
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
    machine$pes$1$screener$c_passed c_passed(
        .d(c_passed$d),
        .q(c_passed$q),
        .clock(c_passed$clock)
    );
    machine$pes$1$screener$c_backward c_backward(
        .d(c_backward$d),
        .q(c_backward$q),
        .clock(c_backward$clock)
    );
    machine$pes$1$screener$c_back_facing c_back_facing(
        .d(c_back_facing$d),
        .q(c_back_facing$q),
        .clock(c_back_facing$clock)
    );
    machine$pes$1$screener$c_outside c_outside(
        .d(c_outside$d),
        .q(c_outside$q),
        .clock(c_outside$clock)
    );
    machine$pes$1$screener$c_near c_near(
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
    
endmodule // machine$pes$1$screener


module machine$pes$1$screener$absnx2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$absnx2


module machine$pes$1$screener$absnx3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$absnx3


module machine$pes$1$screener$absny2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$absny2


module machine$pes$1$screener$absny3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$absny3


module machine$pes$1$screener$ax1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ax1


module machine$pes$1$screener$ax2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ax2


module machine$pes$1$screener$ax3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ax3


module machine$pes$1$screener$ay1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ay1


module machine$pes$1$screener$ay2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ay2


module machine$pes$1$screener$ay3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ay3


module machine$pes$1$screener$back_facing7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$back_facing7


module machine$pes$1$screener$back_facing8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$back_facing8


module machine$pes$1$screener$back_facing9(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$back_facing9


module machine$pes$1$screener$backward7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$backward7


module machine$pes$1$screener$backward8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$backward8


module machine$pes$1$screener$backward9(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$backward9


module machine$pes$1$screener$bank1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$bank1


module machine$pes$1$screener$bank2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$bank2


module machine$pes$1$screener$bank3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$bank3


module machine$pes$1$screener$below8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$below8


module machine$pes$1$screener$bx1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$bx1


module machine$pes$1$screener$bx2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$bx2


module machine$pes$1$screener$bx3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$bx3


module machine$pes$1$screener$by1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$by1


module machine$pes$1$screener$by2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$by2


module machine$pes$1$screener$by3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$by3


module machine$pes$1$screener$c_absnx(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_absnx


module machine$pes$1$screener$c_absny(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_absny


module machine$pes$1$screener$c_ax(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_ax


module machine$pes$1$screener$c_ay(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_ay


module machine$pes$1$screener$c_back_facing(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$c_back_facing


module machine$pes$1$screener$c_backward(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$c_backward


module machine$pes$1$screener$c_bx(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_bx


module machine$pes$1$screener$c_by(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_by


module machine$pes$1$screener$c_k(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_k


module machine$pes$1$screener$c_near(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$c_near


module machine$pes$1$screener$c_negx(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_negx


module machine$pes$1$screener$c_negy(clock,d,q);
    
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
endmodule // machine$pes$1$screener$c_negy


module machine$pes$1$screener$c_outside(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$c_outside


module machine$pes$1$screener$c_passed(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$c_passed


module machine$pes$1$screener$clz_n2_7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$clz_n2_7


module machine$pes$1$screener$clz_n3_7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$clz_n3_7


module machine$pes$1$screener$clz_n6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$clz_n6


module machine$pes$1$screener$clz_n7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$clz_n7


module machine$pes$1$screener$divider(clock,rx,ry,fx,fy,k,tag,qx,qy,wx,wy,tag_out);
    
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
endmodule // machine$pes$1$screener$divider


module machine$pes$1$screener$f_hi_eq8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$f_hi_eq8


module machine$pes$1$screener$f_hi_lt8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$f_hi_lt8


module machine$pes$1$screener$f_lo_lt8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$f_lo_lt8


module machine$pes$1$screener$fifo(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
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
    machine$pes$1$screener$fifo$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$screener$fifo$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$screener$fifo$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$screener$fifo$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$screener$fifo$head_valid head_valid(
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
    
endmodule // machine$pes$1$screener$fifo


module machine$pes$1$screener$fifo$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$fifo$head_valid


module machine$pes$1$screener$fifo$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$fifo$rd_inc_x


module machine$pes$1$screener$fifo$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$fifo$rd_ptr


module machine$pes$1$screener$fifo$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$fifo$tail_ptr


module machine$pes$1$screener$fifo$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$fifo$words


module machine$pes$1$screener$full(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$full


module machine$pes$1$screener$ha6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ha6


module machine$pes$1$screener$ha_open7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ha_open7


module machine$pes$1$screener$ha_open8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$ha_open8


module machine$pes$1$screener$hb6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$hb6


module machine$pes$1$screener$hb_open7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$hb_open7


module machine$pes$1$screener$hb_open8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$hb_open8


module machine$pes$1$screener$id1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id1


module machine$pes$1$screener$id2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id2


module machine$pes$1$screener$id3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id3


module machine$pes$1$screener$id4(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id4


module machine$pes$1$screener$id5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id5


module machine$pes$1$screener$id6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id6


module machine$pes$1$screener$id7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id7


module machine$pes$1$screener$id8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$id8


module machine$pes$1$screener$k5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$k5


module machine$pes$1$screener$k_nonpos6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$k_nonpos6


module machine$pes$1$screener$l_hi_eq8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$l_hi_eq8


module machine$pes$1$screener$l_hi_gt8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$l_hi_gt8


module machine$pes$1$screener$l_lo_gt8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$l_lo_gt8


module machine$pes$1$screener$lane_ax(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_ax


module machine$pes$1$screener$lane_ay(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_ay


module machine$pes$1$screener$lane_bx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_bx


module machine$pes$1$screener$lane_by(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_by


module machine$pes$1$screener$lane_id(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_id


module machine$pes$1$screener$lane_sh(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_sh


module machine$pes$1$screener$lane_wx(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_wx


module machine$pes$1$screener$lane_wy(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
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
endmodule // machine$pes$1$screener$lane_wy


module machine$pes$1$screener$lz_e(clock,value,norm,clz);
    
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
endmodule // machine$pes$1$screener$lz_e


module machine$pes$1$screener$lz_n(clock,value,norm,clz);
    
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
endmodule // machine$pes$1$screener$lz_n


module machine$pes$1$screener$m_abx(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_abx


module machine$pes$1$screener$m_aby(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_aby


module machine$pes$1$screener$m_fbx(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_fbx


module machine$pes$1$screener$m_fby(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_fby


module machine$pes$1$screener$m_lax(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_lax


module machine$pes$1$screener$m_lay(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_lay


module machine$pes$1$screener$m_nax(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_nax


module machine$pes$1$screener$m_nay(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_nay


module machine$pes$1$screener$m_nbx(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_nbx


module machine$pes$1$screener$m_nby(clock,a,b,p);
    
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
endmodule // machine$pes$1$screener$m_nby


module machine$pes$1$screener$near9(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$near9


module machine$pes$1$screener$near_a8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$near_a8


module machine$pes$1$screener$near_b8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$near_b8


module machine$pes$1$screener$negx2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$negx2


module machine$pes$1$screener$negx3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$negx3


module machine$pes$1$screener$negy2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$negy2


module machine$pes$1$screener$negy3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$negy3


module machine$pes$1$screener$nmax3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$nmax3


module machine$pes$1$screener$norm_n6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$norm_n6


module machine$pes$1$screener$norm_n7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$norm_n7


module machine$pes$1$screener$normal_x2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$normal_x2


module machine$pes$1$screener$normal_xa2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$normal_xa2


module machine$pes$1$screener$normal_y2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$normal_y2


module machine$pes$1$screener$normal_ya2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$normal_ya2


module machine$pes$1$screener$outside9(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$outside9


module machine$pes$1$screener$p_abx4(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_abx4


module machine$pes$1$screener$p_aby4(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_aby4


module machine$pes$1$screener$p_fbx6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_fbx6


module machine$pes$1$screener$p_fby6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_fby6


module machine$pes$1$screener$p_lax6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_lax6


module machine$pes$1$screener$p_lay6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_lay6


module machine$pes$1$screener$p_nax5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_nax5


module machine$pes$1$screener$p_nay5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_nay5


module machine$pes$1$screener$p_nbx5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_nbx5


module machine$pes$1$screener$p_nby5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$p_nby5


module machine$pes$1$screener$pass9(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$pass9


module machine$pes$1$screener$res_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$res_ptr


module machine$pes$1$screener$s0_8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$s0_8


module machine$pes$1$screener$s0_m1_8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$s0_m1_8


module machine$pes$1$screener$side_f7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$side_f7


module machine$pes$1$screener$side_l7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$side_l7


module machine$pes$1$screener$sp3_8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$sp3_8


module machine$pes$1$screener$used(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$used


module machine$pes$1$screener$v1(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v1


module machine$pes$1$screener$v2(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v2


module machine$pes$1$screener$v3(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v3


module machine$pes$1$screener$v4(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v4


module machine$pes$1$screener$v5(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v5


module machine$pes$1$screener$v6(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v6


module machine$pes$1$screener$v7(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v7


module machine$pes$1$screener$v8(d,q,clock);
    
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
          
endmodule // machine$pes$1$screener$v8


module machine$pes$1$stall(d,q,clock);
    
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
          
endmodule // machine$pes$1$stall


module machine$pes$1$stg_first_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_first_x


module machine$pes$1$stg_first_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_first_y


module machine$pes$1$stg_last_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_last_x


module machine$pes$1$stg_last_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_last_y


module machine$pes$1$stg_normal_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_normal_x


module machine$pes$1$stg_normal_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_normal_y


module machine$pes$1$stg_origin_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_origin_x


module machine$pes$1$stg_origin_y(d,q,clock);
    
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
          
endmodule // machine$pes$1$stg_origin_y


module machine$pes$1$tag_kind(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [5:0] write_address;
    input wire  write_data;
    input wire  write_enable;
    input wire  [5:0] head_address;
    input wire  [5:0] next_address;
    input wire  pop;
    output reg  read_data;
    
    // Update code (custom)
    // Two copies under the same writes, one read each: from one memory, Yosys makes the two reads
    // one port whose address is chosen by `pop` (pop, address, RAM, register: measured 141 MHz).
    reg [0:0] mem [0:63];
    reg [0:0] mem_n [0:63];
    reg [0:0] read_r;
    integer i;
    initial begin
       for (i = 0; i <= 63; i = i + 1) begin
          mem[i] = 1'd0;
          mem_n[i] = 1'd0;
       end
       read_r = 1'd0;
    end
    always @(posedge clock) begin
       read_r <= pop ? mem_n[next_address] : mem[head_address];
       if (write_enable) begin
          mem[write_address] <= write_data;
          mem_n[write_address] <= write_data;
       end
    end
    always @(*) read_data = read_r;
endmodule // machine$pes$1$tag_kind


module machine$pes$1$tag_lane(clock,write_address,write_data,write_enable,head_address,next_address,pop,read_data);
    
    // Module arguments
    input wire  clock;
    input wire  [5:0] write_address;
    input wire  [21:0] write_data;
    input wire  write_enable;
    input wire  [5:0] head_address;
    input wire  [5:0] next_address;
    input wire  pop;
    output reg  [21:0] read_data;
    
    // Update code (custom)
    reg [21:0] mem [0:63];
    reg [21:0] head_r;
    reg [21:0] next_r;
    reg popped;
    integer i;
    `ifdef SHELLING_ICE40
    // A copy for the second read (the same writes): one read port per memory.
    reg [21:0] mem_n [0:63];
    initial for (i = 0; i <= 63; i = i + 1) mem_n[i] = 22'd0;
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
       for (i = 0; i <= 63; i = i + 1) mem[i] = 22'd0;
       head_r = 22'd0;
       next_r = 22'd0;
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
endmodule // machine$pes$1$tag_lane


module machine$pes$1$tags(clock,push,pop,tail_address,head_address,next_address,valid,count);
    
    // Module arguments
    input wire  clock;
    input wire  push;
    input wire  pop;
    output reg  [5:0] tail_address;
    output reg  [5:0] head_address;
    output reg  [5:0] next_address;
    output reg  valid;
    output reg  [6:0] count;
    
    // Constant declarations
    localparam  one_a = 6'b1;
    localparam  one_c = 7'b1;
    localparam  zero_c = 7'b0;
    
    // Stub signals
    reg  [5:0] tail_ptr$d;
    wire  [5:0] tail_ptr$q;
    reg  tail_ptr$clock;
    reg  [5:0] rd_ptr$d;
    wire  [5:0] rd_ptr$q;
    reg  rd_ptr$clock;
    reg  [5:0] rd_inc_x$d;
    wire  [5:0] rd_inc_x$q;
    reg  rd_inc_x$clock;
    reg  [6:0] words$d;
    wire  [6:0] words$q;
    reg  words$clock;
    reg  head_valid$d;
    wire  head_valid$q;
    reg  head_valid$clock;
    
    // Local signals
    reg  [5:0] rd_inc;
    reg  [5:0] rd_inc2;
    
    // Sub module instances
    machine$pes$1$tags$tail_ptr tail_ptr(
        .d(tail_ptr$d),
        .q(tail_ptr$q),
        .clock(tail_ptr$clock)
    );
    machine$pes$1$tags$rd_ptr rd_ptr(
        .d(rd_ptr$d),
        .q(rd_ptr$q),
        .clock(rd_ptr$clock)
    );
    machine$pes$1$tags$rd_inc_x rd_inc_x(
        .d(rd_inc_x$d),
        .q(rd_inc_x$q),
        .clock(rd_inc_x$clock)
    );
    machine$pes$1$tags$words words(
        .d(words$d),
        .q(words$q),
        .clock(words$clock)
    );
    machine$pes$1$tags$head_valid head_valid(
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
    
endmodule // machine$pes$1$tags


module machine$pes$1$tags$head_valid(d,q,clock);
    
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
          
endmodule // machine$pes$1$tags$head_valid


module machine$pes$1$tags$rd_inc_x(d,q,clock);
    
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
          
endmodule // machine$pes$1$tags$rd_inc_x


module machine$pes$1$tags$rd_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$tags$rd_ptr


module machine$pes$1$tags$tail_ptr(d,q,clock);
    
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
          
endmodule // machine$pes$1$tags$tail_ptr


module machine$pes$1$tags$words(d,q,clock);
    
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
          
endmodule // machine$pes$1$tags$words


module machine$pes$1$tags_full(d,q,clock);
    
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
          
endmodule // machine$pes$1$tags_full


module machine$pes$1$unit(clock,dir_we,dir_addr,dir_x,dir_y,patch_valid,patch_ready,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,res_re,res_addr,res_hit,res_id,res_key,busy,tests,marks);
    
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
    machine$pes$1$unit$seq seq(
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
    machine$pes$1$unit$alive0 alive0(
        .clock(alive0$clock),
        .read_address(alive0$read_address),
        .read_data(alive0$read_data),
        .write_address(alive0$write_address),
        .write_data(alive0$write_data),
        .write_enable(alive0$write_enable)
    );
    machine$pes$1$unit$alive1 alive1(
        .clock(alive1$clock),
        .read_address(alive1$read_address),
        .read_data(alive1$read_data),
        .write_address(alive1$write_address),
        .write_data(alive1$write_data),
        .write_enable(alive1$write_enable)
    );
    machine$pes$1$unit$dir_mem_x dir_mem_x(
        .clock(dir_mem_x$clock),
        .read_address(dir_mem_x$read_address),
        .read_data(dir_mem_x$read_data),
        .write_address(dir_mem_x$write_address),
        .write_data(dir_mem_x$write_data),
        .write_enable(dir_mem_x$write_enable)
    );
    machine$pes$1$unit$dir_mem_y dir_mem_y(
        .clock(dir_mem_y$clock),
        .read_address(dir_mem_y$read_address),
        .read_data(dir_mem_y$read_data),
        .write_address(dir_mem_y$write_address),
        .write_data(dir_mem_y$write_data),
        .write_enable(dir_mem_y$write_enable)
    );
    machine$pes$1$unit$products products(
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
    machine$pes$1$unit$pipe pipe(
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
    machine$pes$1$unit$key_scale key_scale(
        .clock(key_scale$clock),
        .q(key_scale$q),
        .sh(key_scale$sh),
        .key(key_scale$key)
    );
    machine$pes$1$unit$mem_key0 mem_key0(
        .clock(mem_key0$clock),
        .read_address(mem_key0$read_address),
        .read_data(mem_key0$read_data),
        .write_address(mem_key0$write_address),
        .write_data(mem_key0$write_data),
        .write_enable(mem_key0$write_enable)
    );
    machine$pes$1$unit$mem_meta0 mem_meta0(
        .clock(mem_meta0$clock),
        .read_address(mem_meta0$read_address),
        .read_data(mem_meta0$read_data),
        .write_address(mem_meta0$write_address),
        .write_data(mem_meta0$write_data),
        .write_enable(mem_meta0$write_enable)
    );
    machine$pes$1$unit$mem_key1 mem_key1(
        .clock(mem_key1$clock),
        .read_address(mem_key1$read_address),
        .read_data(mem_key1$read_data),
        .write_address(mem_key1$write_address),
        .write_data(mem_key1$write_data),
        .write_enable(mem_key1$write_enable)
    );
    machine$pes$1$unit$mem_meta1 mem_meta1(
        .clock(mem_meta1$clock),
        .read_address(mem_meta1$read_address),
        .read_data(mem_meta1$read_data),
        .write_address(mem_meta1$write_address),
        .write_data(mem_meta1$write_data),
        .write_enable(mem_meta1$write_enable)
    );
    machine$pes$1$unit$merge merge(
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
    
endmodule // machine$pes$1$unit


module machine$pes$1$unit$alive0(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$alive0


module machine$pes$1$unit$alive1(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$alive1


module machine$pes$1$unit$dir_mem_x(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$dir_mem_x


module machine$pes$1$unit$dir_mem_y(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$dir_mem_y


module machine$pes$1$unit$key_scale(clock,q,sh,key);
    
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
endmodule // machine$pes$1$unit$key_scale


module machine$pes$1$unit$mem_key0(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$mem_key0


module machine$pes$1$unit$mem_key1(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$mem_key1


module machine$pes$1$unit$mem_meta0(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$mem_meta0


module machine$pes$1$unit$mem_meta1(clock,read_address,read_data,write_address,write_data,write_enable);
    
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
endmodule // machine$pes$1$unit$mem_meta1


module machine$pes$1$unit$merge(clock,v8,tag8,mark8,key,mem_key0,mem_meta0,mem_key1,mem_meta1,res_re,res_addr,write_address0,write_key0,write_meta0,write_enable0,write_address1,write_key1,write_meta1,write_enable1,z2,res_half,busy,fw_valid,marks);
    
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
endmodule // machine$pes$1$unit$merge


module machine$pes$1$unit$pipe(clock,v1,tag1,mark1,alive0,alive1,dx_ay,dy_ax,dx_by,dy_bx,tests,busy,sh4,ray6,v8,tag8,mark8);
    
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
endmodule // machine$pes$1$unit$pipe


module machine$pes$1$unit$products(clock,dx,dy,ax,ay,bx,by,wx,wy,dx_ay,dy_ax,dx_by,dy_bx,dx_wx,dy_wy);
    
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
endmodule // machine$pes$1$unit$products


module machine$pes$1$unit$seq(clock,patch_valid,patch_ax,patch_ay,patch_bx,patch_by,patch_wx,patch_wy,patch_sh,patch_id,patch_first,patch_count,patch_retire,full,busy,kill,cur,v1,tag1,mark1,o_ax,o_ay,o_bx,o_by,o_wx,o_wy);
    
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
endmodule // machine$pes$1$unit$seq


module machine$pes$1$used0(d,q,clock);
    
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
          
endmodule // machine$pes$1$used0


module machine$pes$1$used1(d,q,clock);
    
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
          
endmodule // machine$pes$1$used1


module machine$port_addr$0(d,q,clock);
    
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
          
endmodule // machine$port_addr$0


module machine$port_addr$1(d,q,clock);
    
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
          
endmodule // machine$port_addr$1


module machine$port_ax$0(d,q,clock);
    
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
          
endmodule // machine$port_ax$0


module machine$port_ax$1(d,q,clock);
    
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
          
endmodule // machine$port_ax$1


module machine$port_ay$0(d,q,clock);
    
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
          
endmodule // machine$port_ay$0


module machine$port_ay$1(d,q,clock);
    
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
          
endmodule // machine$port_ay$1


module machine$port_bx$0(d,q,clock);
    
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
          
endmodule // machine$port_bx$0


module machine$port_bx$1(d,q,clock);
    
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
          
endmodule // machine$port_bx$1


module machine$port_by$0(d,q,clock);
    
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
          
endmodule // machine$port_by$0


module machine$port_by$1(d,q,clock);
    
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
          
endmodule // machine$port_by$1


module machine$port_req$0(d,q,clock);
    
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
          
endmodule // machine$port_req$0


module machine$port_req$1(d,q,clock);
    
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
          
endmodule // machine$port_req$1


module machine$port_valid$0(d,q,clock);
    
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
          
endmodule // machine$port_valid$0


module machine$port_valid$1(d,q,clock);
    
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
          
endmodule // machine$port_valid$1


module machine$was_busy$0(d,q,clock);
    
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
          
endmodule // machine$was_busy$0


module machine$was_busy$1(d,q,clock);
    
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
          
endmodule // machine$was_busy$1
