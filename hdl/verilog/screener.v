// screener: exported from rust-hdl by `shelling export-verilog`; do not edit.


module screener(clock,origin_x,origin_y,normal_x,normal_y,first_x,first_y,last_x,last_y,in_valid,in_ready,in_id,in_ax,in_ay,in_bx,in_by,out_valid,out_ready,out_id,out_ax,out_ay,out_bx,out_by,out_wx,out_wy,out_sh,passed,backward,back_facing,outside,near);
    
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
    output reg  [31:0] passed;
    output reg  [31:0] backward;
    output reg  [31:0] back_facing;
    output reg  [31:0] outside;
    output reg  [31:0] near;
    
    // Constant declarations
    localparam  st_idle = 3'b0;
    localparam  st_m1 = 3'b1;
    localparam  st_m2 = 3'b10;
    localparam  st_verdict = 3'b11;
    localparam  st_div = 3'b100;
    localparam  st_out = 3'b101;
    localparam  zero18 = 18'b0;
    localparam  zero32 = 32'h0;
    localparam  one32 = 32'h1;
    localparam  msb32 = 32'h80000000;
    localparam  thr_f = 32'h7fffff00;
    localparam  thr_l = 32'h80000100;
    localparam  zero6 = 6'b0;
    localparam  zero16 = 16'h0;
    localparam  zero8 = 8'h0;
    localparam  zero4 = 4'h0;
    localparam  zero2 = 2'b0;
    localparam  sh16 = 32'h10;
    localparam  sh8 = 32'h8;
    localparam  sh4 = 32'h4;
    localparam  sh2 = 32'h2;
    localparam  sh1 = 32'h1;
    localparam  sh3 = 32'h3;
    localparam  sh13 = 16'hd;
    localparam  sh14 = 16'he;
    localparam  sh15 = 16'hf;
    localparam  one6 = 6'b1;
    localparam  c16_6 = 6'b10000;
    localparam  c8_6 = 6'b1000;
    localparam  c4_6 = 6'b100;
    localparam  c2_6 = 6'b10;
    localparam  c1_6 = 6'b1;
    localparam  sh_lo = 6'b111101;
    localparam  sh_m1 = 6'b111111;
    localparam  sh_m2 = 6'b111110;
    localparam  zero5 = 5'b0;
    localparam  one5 = 5'b1;
    localparam  last_step = 5'b10000;
    localparam  one18 = 18'b1;
    
    // Stub signals
    reg  [2:0] state$d;
    wire  [2:0] state$q;
    reg  state$clock;
    reg  [15:0] id$d;
    wire  [15:0] id$q;
    reg  id$clock;
    reg  [17:0] ax$d;
    wire  [17:0] ax$q;
    reg  ax$clock;
    reg  [17:0] ay$d;
    wire  [17:0] ay$q;
    reg  ay$clock;
    reg  [17:0] bx$d;
    wire  [17:0] bx$q;
    reg  bx$clock;
    reg  [17:0] by$d;
    wire  [17:0] by$q;
    reg  by$clock;
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
    reg  [31:0] k$d;
    wire  [31:0] k$q;
    reg  k$clock;
    reg  [5:0] sh_r$d;
    wire  [5:0] sh_r$q;
    reg  sh_r$clock;
    reg  [4:0] step$d;
    wire  [4:0] step$q;
    reg  step$clock;
    reg  neg_x$d;
    wire  neg_x$q;
    reg  neg_x$clock;
    reg  neg_y$d;
    wire  neg_y$q;
    reg  neg_y$clock;
    reg  [31:0] rx$d;
    wire  [31:0] rx$q;
    reg  rx$clock;
    reg  [31:0] ry$d;
    wire  [31:0] ry$q;
    reg  ry$clock;
    reg  [15:0] fx$d;
    wire  [15:0] fx$q;
    reg  fx$clock;
    reg  [15:0] fy$d;
    wire  [15:0] fy$q;
    reg  fy$clock;
    reg  [17:0] qx$d;
    wire  [17:0] qx$q;
    reg  qx$clock;
    reg  [17:0] qy$d;
    wire  [17:0] qy$q;
    reg  qy$clock;
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
    reg  is_idle;
    reg  is_m1;
    reg  is_m2;
    reg  is_verdict;
    reg  is_div;
    reg  is_out;
    reg  take;
    reg  [17:0] ext_ox;
    reg  [17:0] ext_oy;
    reg  [17:0] ext_ax;
    reg  [17:0] ext_ay;
    reg  [17:0] ext_bx;
    reg  [17:0] ext_by;
    reg  [31:0] ha;
    reg  [31:0] hb;
    reg  [31:0] kk;
    reg  [31:0] side_f;
    reg  [31:0] side_l;
    reg  [31:0] side_f_x;
    reg  [31:0] side_l_x;
    reg  ha_pos;
    reg  hb_pos;
    reg  is_backward;
    reg  is_back_facing;
    reg  is_outside;
    reg  is_near;
    reg  is_pass;
    reg  [17:0] nx;
    reg  [17:0] ny;
    reg  [17:0] nx_neg;
    reg  [17:0] ny_neg;
    reg  [17:0] absnx;
    reg  [17:0] absny;
    reg  [17:0] nmax;
    reg  [31:0] absnx32;
    reg  [31:0] absny32;
    reg  [31:0] nmax32;
    reg  [31:0] k2;
    reg  [31:0] zn0;
    reg  [31:0] zn1;
    reg  [31:0] zn2;
    reg  [31:0] zn3;
    reg  [31:0] zn4;
    reg  [31:0] zn5;
    reg  [5:0] cn16_n;
    reg  [5:0] cn8_n;
    reg  [5:0] cn4_n;
    reg  [5:0] cn2_n;
    reg  [5:0] cn1_n;
    reg  [5:0] clz_n;
    reg  [31:0] ze0;
    reg  [31:0] ze1;
    reg  [31:0] ze2;
    reg  [31:0] ze3;
    reg  [31:0] ze4;
    reg  [31:0] ze5;
    reg  [5:0] ce16_e;
    reg  [5:0] ce8_e;
    reg  [5:0] ce4_e;
    reg  [5:0] ce2_e;
    reg  [5:0] ce1_e;
    reg  [5:0] clz_e;
    reg  [15:0] top16_n;
    reg  [7:0] top8_n;
    reg  [3:0] top4_n;
    reg  [1:0] top2_n;
    reg  [15:0] top16_e;
    reg  [7:0] top8_e;
    reg  [3:0] top4_e;
    reg  [1:0] top2_e;
    reg  [5:0] s0;
    reg  [5:0] s0_m1;
    reg  [5:0] sh;
    reg  [4:0] sh5;
    reg  [15:0] low_nx;
    reg  [15:0] low_ny;
    reg  [31:0] r0x;
    reg  [31:0] r0y;
    reg  [15:0] f0x;
    reg  [15:0] f0y;
    reg  [31:0] rx2;
    reg  [31:0] ry2;
    reg  [31:0] tx;
    reg  [31:0] ty;
    reg  [31:0] tx_k;
    reg  [31:0] ty_k;
    reg  [17:0] qx2;
    reg  [17:0] qy2;
    reg  [17:0] wx_neg;
    reg  [17:0] wy_neg;
    
    // Sub module instances
    screener$state state(
        .d(state$d),
        .q(state$q),
        .clock(state$clock)
    );
    screener$id id(
        .d(id$d),
        .q(id$q),
        .clock(id$clock)
    );
    screener$ax ax(
        .d(ax$d),
        .q(ax$q),
        .clock(ax$clock)
    );
    screener$ay ay(
        .d(ay$d),
        .q(ay$q),
        .clock(ay$clock)
    );
    screener$bx bx(
        .d(bx$d),
        .q(bx$q),
        .clock(bx$clock)
    );
    screener$by by(
        .d(by$d),
        .q(by$q),
        .clock(by$clock)
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
    screener$k k(
        .d(k$d),
        .q(k$q),
        .clock(k$clock)
    );
    screener$sh_r sh_r(
        .d(sh_r$d),
        .q(sh_r$q),
        .clock(sh_r$clock)
    );
    screener$step step(
        .d(step$d),
        .q(step$q),
        .clock(step$clock)
    );
    screener$neg_x neg_x(
        .d(neg_x$d),
        .q(neg_x$q),
        .clock(neg_x$clock)
    );
    screener$neg_y neg_y(
        .d(neg_y$d),
        .q(neg_y$q),
        .clock(neg_y$clock)
    );
    screener$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    screener$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    screener$fx fx(
        .d(fx$d),
        .q(fx$q),
        .clock(fx$clock)
    );
    screener$fy fy(
        .d(fy$d),
        .q(fy$q),
        .clock(fy$clock)
    );
    screener$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    screener$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
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
        state$clock = clock;
        id$clock = clock;
        ax$clock = clock;
        ay$clock = clock;
        bx$clock = clock;
        by$clock = clock;
        k$clock = clock;
        sh_r$clock = clock;
        step$clock = clock;
        neg_x$clock = clock;
        neg_y$clock = clock;
        rx$clock = clock;
        ry$clock = clock;
        fx$clock = clock;
        fy$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        c_passed$clock = clock;
        c_backward$clock = clock;
        c_back_facing$clock = clock;
        c_outside$clock = clock;
        c_near$clock = clock;
        state$d = state$q;
        id$d = id$q;
        ax$d = ax$q;
        ay$d = ay$q;
        bx$d = bx$q;
        by$d = by$q;
        k$d = k$q;
        sh_r$d = sh_r$q;
        step$d = step$q;
        neg_x$d = neg_x$q;
        neg_y$d = neg_y$q;
        rx$d = rx$q;
        ry$d = ry$q;
        fx$d = fx$q;
        fy$d = fy$q;
        qx$d = qx$q;
        qy$d = qy$q;
        c_passed$d = c_passed$q;
        c_backward$d = c_backward$q;
        c_back_facing$d = c_back_facing$q;
        c_outside$d = c_outside$q;
        c_near$d = c_near$q;
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
        is_idle = state$q == st_idle;
        is_m1 = state$q == st_m1;
        is_m2 = state$q == st_m2;
        is_verdict = state$q == st_verdict;
        is_div = state$q == st_div;
        is_out = state$q == st_out;
        ext_ox = ((origin_x) & 18'h3ffff);
        ext_oy = ((origin_y) & 18'h3ffff);
        ext_ax = ((in_ax) & 18'h3ffff);
        ext_ay = ((in_ay) & 18'h3ffff);
        ext_bx = ((in_bx) & 18'h3ffff);
        ext_by = ((in_by) & 18'h3ffff);
        m_nax$a = normal_x;
        m_nax$b = ax$q;
        m_nay$a = normal_y;
        m_nay$b = ay$q;
        m_nbx$a = normal_x;
        m_nbx$b = bx$q;
        m_nby$a = normal_y;
        m_nby$b = by$q;
        m_aby$a = ax$q;
        m_aby$b = by$q;
        m_abx$a = ay$q;
        m_abx$b = bx$q;
        m_fby$a = first_x;
        m_fby$b = by$q;
        m_fbx$a = first_y;
        m_fbx$b = bx$q;
        m_lay$a = last_x;
        m_lay$b = ay$q;
        m_lax$a = last_y;
        m_lax$b = ax$q;
        ha = m_nax$p + m_nay$p;
        hb = m_nbx$p + m_nby$p;
        kk = m_aby$p - m_abx$p;
        side_f = m_fby$p - m_fbx$p;
        side_l = m_lay$p - m_lax$p;
        side_f_x = side_f ^ msb32;
        side_l_x = side_l ^ msb32;
        ha_pos = ~ha[32'h1f] & (ha != zero32);
        hb_pos = ~hb[32'h1f] & (hb != zero32);
        nx = by$q - ay$q;
        ny = ax$q - bx$q;
        nx_neg = zero18 - nx;
        ny_neg = zero18 - ny;
        absnx = nx;
        if (nx[32'h11]) begin
            absnx = nx_neg;
        end
        absny = ny;
        if (ny[32'h11]) begin
            absny = ny_neg;
        end
        nmax = absny;
        if (absnx > absny) begin
            nmax = absnx;
        end
        absnx32 = ((absnx) & 32'hffffffff);
        absny32 = ((absny) & 32'hffffffff);
        nmax32 = ((nmax) & 32'hffffffff);
        k2 = kk << sh1;
        zn0 = nmax32;
        top16_n = zn0[(32'h10)+:(16)];
        zn1 = zn0;
        cn16_n = zero6;
        if (top16_n == zero16) begin
            zn1 = zn0 << sh16;
            cn16_n = c16_6;
        end
        top8_n = zn1[(32'h18)+:(8)];
        zn2 = zn1;
        cn8_n = zero6;
        if (top8_n == zero8) begin
            zn2 = zn1 << sh8;
            cn8_n = c8_6;
        end
        top4_n = zn2[(32'h1c)+:(4)];
        zn3 = zn2;
        cn4_n = zero6;
        if (top4_n == zero4) begin
            zn3 = zn2 << sh4;
            cn4_n = c4_6;
        end
        top2_n = zn3[(32'h1e)+:(2)];
        zn4 = zn3;
        cn2_n = zero6;
        if (top2_n == zero2) begin
            zn4 = zn3 << sh2;
            cn2_n = c2_6;
        end
        zn5 = zn4;
        cn1_n = zero6;
        if (~zn4[32'h1f]) begin
            zn5 = zn4 << sh1;
            cn1_n = c1_6;
        end
        clz_n = cn16_n | cn8_n | cn4_n | cn2_n | cn1_n;
        ze0 = k2;
        top16_e = ze0[(32'h10)+:(16)];
        ze1 = ze0;
        ce16_e = zero6;
        if (top16_e == zero16) begin
            ze1 = ze0 << sh16;
            ce16_e = c16_6;
        end
        top8_e = ze1[(32'h18)+:(8)];
        ze2 = ze1;
        ce8_e = zero6;
        if (top8_e == zero8) begin
            ze2 = ze1 << sh8;
            ce8_e = c8_6;
        end
        top4_e = ze2[(32'h1c)+:(4)];
        ze3 = ze2;
        ce4_e = zero6;
        if (top4_e == zero4) begin
            ze3 = ze2 << sh4;
            ce4_e = c4_6;
        end
        top2_e = ze3[(32'h1e)+:(2)];
        ze4 = ze3;
        ce2_e = zero6;
        if (top2_e == zero2) begin
            ze4 = ze3 << sh2;
            ce2_e = c2_6;
        end
        ze5 = ze4;
        ce1_e = zero6;
        if (~ze4[32'h1f]) begin
            ze5 = ze4 << sh1;
            ce1_e = c1_6;
        end
        clz_e = ce16_e | ce8_e | ce4_e | ce2_e | ce1_e;
        s0 = clz_n - clz_e;
        s0_m1 = s0 - one6;
        sh = s0_m1;
        if (zn5 < ze5) begin
            sh = s0;
        end
        sh5 = sh[(32'h0)+:(5)];
        low_nx = absnx32[(32'h0)+:(16)];
        low_ny = absny32[(32'h0)+:(16)];
        r0x = absnx32 << sh5;
        r0y = absny32 << sh5;
        f0x = zero16;
        f0y = zero16;
        if (sh == sh_m1) begin
            r0x = absnx32 >> sh1;
            r0y = absny32 >> sh1;
            f0x = low_nx << sh15;
            f0y = low_ny << sh15;
        end
        else if (sh == sh_m2) begin
            r0x = absnx32 >> sh2;
            r0y = absny32 >> sh2;
            f0x = low_nx << sh14;
            f0y = low_ny << sh14;
        end
        else if (sh == sh_lo) begin
            r0x = absnx32 >> sh3;
            r0y = absny32 >> sh3;
            f0x = low_nx << sh13;
            f0y = low_ny << sh13;
        end
        is_backward = ~ha_pos & ~hb_pos;
        is_back_facing = ~is_backward & (kk[32'h1f] | (kk == zero32));
        is_outside = ~is_backward & ~is_back_facing & ((hb_pos & (side_f_x < thr_f)) | (ha_pos & (side_l_x > thr_l)));
        is_near = ~is_backward & ~is_back_facing & ~is_outside & sh[32'h5] & (sh < sh_lo);
        is_pass = ~is_backward & ~is_back_facing & ~is_outside & ~is_near;
        rx2 = rx$q << sh1;
        ry2 = ry$q << sh1;
        tx = rx2;
        if (fx$q[32'hf]) begin
            tx = rx2 | one32;
        end
        ty = ry2;
        if (fy$q[32'hf]) begin
            ty = ry2 | one32;
        end
        if (step$q == zero5) begin
            tx = rx$q;
            ty = ry$q;
        end
        tx_k = tx - k$q;
        ty_k = ty - k$q;
        qx2 = qx$q << one18;
        qy2 = qy$q << one18;
        if (is_div) begin
            step$d = step$q + one5;
            if (step$q != zero5) begin
                fx$d = fx$q << sh1;
                fy$d = fy$q << sh1;
            end
            rx$d = tx;
            qx$d = qx2;
            if (tx >= k$q) begin
                rx$d = tx_k;
                qx$d = qx2 | one18;
            end
            ry$d = ty;
            qy$d = qy2;
            if (ty >= k$q) begin
                ry$d = ty_k;
                qy$d = qy2 | one18;
            end
        end
        wx_neg = zero18 - qx$q;
        wy_neg = zero18 - qy$q;
        out_valid = is_out;
        out_id = id$q;
        out_ax = ax$q;
        out_ay = ay$q;
        out_bx = bx$q;
        out_by = by$q;
        out_wx = qx$q;
        if (neg_x$q) begin
            out_wx = wx_neg;
        end
        out_wy = qy$q;
        if (neg_y$q) begin
            out_wy = wy_neg;
        end
        out_sh = sh_r$q;
        in_ready = is_idle | (is_verdict & ~is_pass) | (is_out & out_ready);
        take = in_valid & (is_idle | (is_verdict & ~is_pass) | (is_out & out_ready));
        if (is_m1) begin
            state$d = st_m2;
        end
        if (is_m2) begin
            state$d = st_verdict;
        end
        if (is_verdict) begin
            state$d = st_idle;
            if (is_pass) begin
                state$d = st_div;
                step$d = zero5;
                k$d = kk;
                sh_r$d = sh;
                neg_x$d = nx[32'h11];
                neg_y$d = ny[32'h11];
                rx$d = r0x;
                ry$d = r0y;
                fx$d = f0x;
                fy$d = f0y;
                qx$d = zero18;
                qy$d = zero18;
                c_passed$d = c_passed$q + one32;
            end
            if (is_backward) begin
                c_backward$d = c_backward$q + one32;
            end
            if (is_back_facing) begin
                c_back_facing$d = c_back_facing$q + one32;
            end
            if (is_outside) begin
                c_outside$d = c_outside$q + one32;
            end
            if (is_near) begin
                c_near$d = c_near$q + one32;
            end
        end
        if (is_div & (step$q == last_step)) begin
            state$d = st_out;
        end
        if (is_out & out_ready) begin
            state$d = st_idle;
        end
        if (take) begin
            state$d = st_m1;
            id$d = in_id;
            ax$d = ext_ax - ext_ox;
            ay$d = ext_ay - ext_oy;
            bx$d = ext_bx - ext_ox;
            by$d = ext_by - ext_oy;
        end
        passed = c_passed$q;
        backward = c_backward$q;
        back_facing = c_back_facing$q;
        outside = c_outside$q;
        near = c_near$q;
    end
    
endmodule // screener


module screener$ax(d,q,clock);
    
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
          
endmodule // screener$ax


module screener$ay(d,q,clock);
    
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
          
endmodule // screener$ay


module screener$bx(d,q,clock);
    
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
          
endmodule // screener$bx


module screener$by(d,q,clock);
    
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
          
endmodule // screener$by


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


module screener$fx(d,q,clock);
    
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
          
endmodule // screener$fx


module screener$fy(d,q,clock);
    
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
          
endmodule // screener$fy


module screener$id(d,q,clock);
    
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
          
endmodule // screener$id


module screener$k(d,q,clock);
    
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
          
endmodule // screener$k


module screener$m_abx(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_abx


module screener$m_aby(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_aby


module screener$m_fbx(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_fbx


module screener$m_fby(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_fby


module screener$m_lax(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_lax


module screener$m_lay(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_lay


module screener$m_nax(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_nax


module screener$m_nay(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_nay


module screener$m_nbx(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_nbx


module screener$m_nby(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [17:0] a;
    input wire  [17:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
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
endmodule // screener$m_nby


module screener$neg_x(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // screener$neg_x


module screener$neg_y(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // screener$neg_y


module screener$qx(d,q,clock);
    
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
          
endmodule // screener$qx


module screener$qy(d,q,clock);
    
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
          
endmodule // screener$qy


module screener$rx(d,q,clock);
    
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
          
endmodule // screener$rx


module screener$ry(d,q,clock);
    
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
          
endmodule // screener$ry


module screener$sh_r(d,q,clock);
    
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
          
endmodule // screener$sh_r


module screener$state(d,q,clock);
    
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
          
endmodule // screener$state


module screener$step(d,q,clock);
    
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
          
endmodule // screener$step
