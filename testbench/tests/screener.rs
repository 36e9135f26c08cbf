//! Block-level tests of the backface screener RTL (`shelling_hdl::screener::Screener`) against its
//! bit-true model `model::screen`: seeded random bundles and patches plus corner cases, every
//! pacing of the two streams, the counters, the credit limit, the exact cycle counts of unstalled
//! streams (one patch per clock), and the rung-4 replays under Icarus Verilog of the whole block
//! and of its divider leaf.

use std::path::PathBuf;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rust_hdl::prelude::*;
use shelling_hdl::formats::PatchSetup;
use shelling_hdl::formats::{cross, direction, dot, from_bits, to_bits};
use shelling_hdl::prim::{Delay, FifoRam};
use shelling_hdl::screener::divider::{restoring_quotient, PipeDivider, DIV_LATENCY};
use shelling_hdl::screener::model::{
    accept_cycles, output_cycles, screen, unstalled_cycles, BundleSetup, Patch, Verdict,
};
use shelling_hdl::screener::normaliser::{normalise, Normaliser, NORMALISER_LATENCY};
use shelling_hdl::screener::{Screener, COUNT_LATENCY, DEPTH, LATENCY, VERDICT_LATENCY};
use shelling_testbench::{Driver, Error, Monitor, Pacing, Result, Scoreboard, Simulator, Source};

const COORD_MAX: i32 = (1 << 17) - 1;

/// One bundle and the patches screened for it.
#[derive(Clone, Debug)]
struct Segment {
    bundle: BundleSetup,
    patches: Vec<Patch>,
}

fn b<const N: usize>(v: i64) -> Bits<N> {
    Bits::from(to_bits(v, N as u32))
}

fn dir(angle: f64) -> [i32; 2] {
    direction(|| "test direction".into(), [angle.cos(), angle.sin()]).unwrap()
}

fn clamp_coord(v: i64) -> i32 {
    v.clamp(0, COORD_MAX as i64) as i32
}

/// A realistic bundle: origin anywhere, unit normal and sector edges within ±90° of it.
fn random_bundle(rng: &mut ChaCha8Rng) -> BundleSetup {
    let theta = rng.random_range(0.0..std::f64::consts::TAU);
    let half = std::f64::consts::FRAC_PI_2;
    let edge = |rng: &mut ChaCha8Rng| rng.random_range(0.0..half);
    let (alpha, beta) = (edge(rng), edge(rng));
    let origin = match rng.random_range(0..8) {
        0 => [0, rng.random_range(0..=COORD_MAX)],
        1 => [COORD_MAX, rng.random_range(0..=COORD_MAX)],
        2 => [rng.random_range(0..=COORD_MAX), 0],
        3 => [rng.random_range(0..=COORD_MAX), COORD_MAX],
        _ => [rng.random_range(0..=COORD_MAX), rng.random_range(0..=COORD_MAX)],
    };
    BundleSetup { origin, normal: dir(theta), first: dir(theta - alpha), last: dir(theta + beta) }
}

/// A point: anywhere in the window, near the origin, or on the window's edge.
fn random_point(rng: &mut ChaCha8Rng, o: [i32; 2]) -> [i32; 2] {
    match rng.random_range(0..10) {
        0..=3 => [rng.random_range(0..=COORD_MAX), rng.random_range(0..=COORD_MAX)],
        4..=5 => {
            let r = 1i64 << rng.random_range(0..12);
            [0, 1].map(|k| clamp_coord(o[k] as i64 + rng.random_range(-r..=r)))
        }
        6 => {
            let r = 1i64 << rng.random_range(12..17);
            [0, 1].map(|k| clamp_coord(o[k] as i64 + rng.random_range(-r..=r)))
        }
        7 => [[0, COORD_MAX][rng.random_range(0..2)], rng.random_range(0..=COORD_MAX)],
        8 => [rng.random_range(0..=COORD_MAX), [0, COORD_MAX][rng.random_range(0..2)]],
        _ => [[0, COORD_MAX][rng.random_range(0..2)], [0, COORD_MAX][rng.random_range(0..2)]],
    }
}

/// A random patch; a short one near the origin, with its line passing close to it, one time in
/// four (to reach `Near` and negative exponents).
fn random_patch(rng: &mut ChaCha8Rng, bundle: &BundleSetup, id: u16) -> Patch {
    let o = bundle.origin;
    if rng.random_range(0..4) == 0 {
        // A short segment whose line passes within a few LSBs of the origin.
        let c = [0, 1].map(|k| o[k] as i64 + rng.random_range(-4i64..=4));
        let len = 1i64 << rng.random_range(0..10);
        let d = [rng.random_range(-len..=len), rng.random_range(-len..=len)];
        let a = [0, 1].map(|k| clamp_coord(c[k] - d[k]));
        let p = [0, 1].map(|k| clamp_coord(c[k] + d[k]));
        return Patch { id, a, b: p };
    }
    Patch { id, a: random_point(rng, o), b: random_point(rng, o) }
}

/// Corner-case patches for `bundle` (some of them adjust nothing and are screened any way).
fn corner_patches(rng: &mut ChaCha8Rng, bundle: &BundleSetup, first_id: u16) -> Vec<Patch> {
    let o = bundle.origin;
    let n = bundle.normal;
    let mut out = vec![];
    let at = |d: [i64; 2]| [clamp_coord(o[0] as i64 + d[0]), clamp_coord(o[1] as i64 + d[1])];
    // Endpoints on the source plane (along the tangent t = (−n.y, n.x), rounded: near the plane).
    let t = [-(n[1] as i64), n[0] as i64];
    for s in [-3i64, -1, 0, 1, 5] {
        let u = rng.random_range(1i64..2000);
        out.push((at([t[0] * s / 64, t[1] * s / 64]), at([t[0] * u / 65536, t[1] * u / 65536])));
        out.push((at([-t[0] * u / 65536, -t[1] * u / 65536]), at([t[0] * s / 64, t[1] * s / 64])));
    }
    // Endpoints exactly on the plane for axis-aligned normals are in `corner_segments`.
    // Collinear with the origin (K = 0) and nearly so.
    let v = [rng.random_range(-300i64..300), rng.random_range(-300i64..300)];
    for (s, u) in [(1i64, 2i64), (-1, 3), (2, 7), (0, 1)] {
        out.push((at([v[0] * s, v[1] * s]), at([v[0] * u, v[1] * u])));
        out.push((at([v[0] * s, v[1] * s + 1]), at([v[0] * u, v[1] * u])));
    }
    // K = 1 and K small: a = (1, 0)/(0, ±1) from the origin.
    for bx in [0i64, 1, 17, 1000, -1000] {
        out.push((at([1, 0]), at([bx, 16])));
        out.push((at([0, -1]), at([16, bx])));
        out.push((at([-16, bx]), at([0, -1])));
    }
    // Zero length, and extreme coordinates.
    let p = random_point(rng, o);
    out.push((p, p));
    out.push((o, o));
    for (a, bb) in [
        ([0, 0], [COORD_MAX, COORD_MAX]),
        ([COORD_MAX, COORD_MAX], [0, 0]),
        ([0, COORD_MAX], [COORD_MAX, 0]),
        ([COORD_MAX, 0], [0, COORD_MAX]),
        ([0, 0], [COORD_MAX, 0]),
        ([COORD_MAX, 0], [0, 0]),
    ] {
        out.push((a, bb));
    }
    // Backward: both endpoints behind the plane.
    let back = [-(n[0] as i64), -(n[1] as i64)];
    let k = rng.random_range(1i64..40000);
    out.push((
        at([back[0] * k / 65536 + t[0] / 64, back[1] * k / 65536 + t[1] / 64]),
        at([back[0] / 64, back[1] / 64]),
    ));
    out.into_iter()
        .enumerate()
        .map(|(i, (a, bb))| Patch { id: first_id.wrapping_add(i as u16), a, b: bb })
        .collect()
}

/// Bundles built for exact corner cases: axis-aligned normals (endpoints exactly on the plane)
/// and sector edges with small components, so that `cross` with them hits the margin ±256
/// exactly.
fn corner_segments(rng: &mut ChaCha8Rng) -> Vec<Segment> {
    let mut out = vec![];
    for s in 1..=16i32 {
        let o = [rng.random_range(20000..100000), rng.random_range(20000..100000)];
        // Normal +x; first = (1, −s/65536)-ish, last = (1, +s/65536)-ish: a nearly empty sector.
        let bundle = BundleSetup { origin: o, normal: [65536, 0], first: [65536, -s], last: [65536, s] };
        let mut patches = vec![];
        let mut id = (s as u16) << 8;
        // cross(first, p) = mul(65536, p.y) + mul(s, p.x) = 4096·p.y + floor(s·p.x/16).
        for px in 1..20000 {
            for py in [-1i32, 0, 1] {
                let p = [px, py];
                let c = cross(bundle.first, p) as i64;
                let cl = cross(bundle.last, p) as i64;
                if (-258..=-254).contains(&c) || (254..=258).contains(&cl) {
                    let q = [o[0] + px, o[1] + py];
                    // The endpoint is b for the first edge, a for the last edge; the other
                    // endpoint makes K > 0 (the origin in front).
                    let other_b = [o[0] + px, o[1] + py + 500];
                    let other_a = [o[0] + px, o[1] + py - 500];
                    patches.push(Patch { id, a: other_a, b: q });
                    id = id.wrapping_add(1);
                    patches.push(Patch { id, a: q, b: other_b });
                    id = id.wrapping_add(1);
                }
            }
        }
        // Endpoints exactly on the plane (x = origin x), in front, behind.
        for dy in [-700, -1, 0, 1, 700] {
            for dx in [0, 0, 1, -1, 50] {
                let a = [o[0] + dx.min(0), o[1] + dy];
                let bb = [o[0], o[1] + dy + 300];
                patches.push(Patch { id, a, b: bb });
                id = id.wrapping_add(1);
                patches.push(Patch { id, a: [o[0] + dx, o[1] - 300], b: [o[0], o[1] + 2] });
                id = id.wrapping_add(1);
            }
        }
        let in_window =
            patches.iter().all(|p| p.a.iter().chain(p.b.iter()).all(|&c| (0..=COORD_MAX).contains(&c)));
        assert!(in_window);
        out.push(Segment { bundle, patches });
    }
    out.push(exponent_ties(rng));
    out
}

/// `nmax = max(|n_x|, |n_y|)` of the patch `a`, `b` (relative coordinates): its normal
/// `n = (b.y − a.y, a.x − b.x)`, as the screener's stage 2 takes it.
fn nmax_of(a: [i32; 2], b: [i32; 2]) -> u64 {
    (b[1] - a[1]).unsigned_abs().max((a[0] - b[0]).unsigned_abs()) as u64
}

/// How `nmax` and `2K` compare once both are normalised to a leading one at bit 31 (the
/// screener's stage 7): `Some(true)` when they agree in their top 18 bits (all of the
/// normalised `nmax`) and `2K` has more bits below, `Some(false)` when they are equal, `None`
/// otherwise.
fn exponent_tie(nmax: u64, k2: u64) -> Option<bool> {
    let norm = |v: u64| (v << (v as u32).leading_zeros()) & 0xffff_ffff;
    let (n, e) = (norm(nmax), norm(k2));
    (n >> 14 == e >> 14).then_some(e != n)
}

/// Patches whose exponent hangs on the low bits of `2K`: `2K` and `nmax` agree in their top 18
/// normalised bits and `2K` has more below them (so `nmax·2^s0 < 2K`). About one random patch
/// in 2^18 is one, so they are searched for (seeded) among long patches in front of the origin.
fn exponent_ties(rng: &mut ChaCha8Rng) -> Segment {
    let o = [0, 65536];
    let bundle = BundleSetup { origin: o, normal: [65536, 0], first: [0, -65536], last: [0, 65536] };
    let mut patches = vec![];
    while patches.len() < 12 {
        let p = Patch {
            id: patches.len() as u16,
            a: [rng.random_range(1..=COORD_MAX), rng.random_range(0..=COORD_MAX)],
            b: [rng.random_range(1..=COORD_MAX), rng.random_range(0..=COORD_MAX)],
        };
        let (a, bb) = ([p.a[0] - o[0], p.a[1] - o[1]], [p.b[0] - o[0], p.b[1] - o[1]]);
        let k = cross(a, bb) as i64;
        let nmax = nmax_of(a, bb);
        if k > 0
            && exponent_tie(nmax, 2 * k as u64) == Some(true)
            && matches!(screen(&bundle, &p), Verdict::Pass(_))
        {
            patches.push(p);
        }
    }
    Segment { bundle, patches }
}

/// `count` random patches in segments of random bundles, a corner-case batch with each bundle.
fn random_segments(rng: &mut ChaCha8Rng, count: usize) -> Vec<Segment> {
    let mut out = vec![];
    let mut total = 0;
    let mut id = 0u16;
    while total < count {
        let bundle = random_bundle(rng);
        let per = rng.random_range(50..400).min(count - total).max(1);
        let mut patches: Vec<Patch> = (0..per)
            .map(|_| {
                id = id.wrapping_add(1);
                random_patch(rng, &bundle, id)
            })
            .collect();
        let corners = corner_patches(rng, &bundle, id);
        id = id.wrapping_add(corners.len() as u16);
        patches.extend(corners);
        total += patches.len();
        out.push(Segment { bundle, patches });
    }
    out
}

/// Verdict tallies: passed, backward, back-facing, outside, near.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Tally([u64; 5]);

impl Tally {
    fn add(&mut self, v: &Verdict) {
        let i = match v {
            Verdict::Pass(_) => 0,
            Verdict::Backward => 1,
            Verdict::BackFacing => 2,
            Verdict::OutsideSector => 3,
            Verdict::Near => 4,
        };
        self.0[i] += 1;
    }
}

fn counters(u: &Screener) -> Tally {
    Tally(
        [u.passed.val(), u.backward.val(), u.back_facing.val(), u.outside.val(), u.near.val()]
            .map(|c| c.to_u64()),
    )
}

/// What leaves the screener for one patch: its setup if it passed, else only its id (in order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Out {
    Pass(PatchSetup),
    Drop(u16),
}

/// What the model says leaves for patch `p`.
fn expect(bundle: &BundleSetup, p: &Patch) -> Out {
    match screen(bundle, p) {
        Verdict::Pass(s) => Out::Pass(s),
        _ => Out::Drop(p.id),
    }
}

fn read_out(u: &Screener) -> Out {
    let s = |v: u64| from_bits(v, 18) as i32;
    let id = u.out_id.val().to_u16();
    if !u.out_pass.val() {
        return Out::Drop(id);
    }
    Out::Pass(PatchSetup {
        id,
        a: [s(u.out_ax.val().to_u64()), s(u.out_ay.val().to_u64())],
        b: [s(u.out_bx.val().to_u64()), s(u.out_by.val().to_u64())],
        w: [s(u.out_wx.val().to_u64()), s(u.out_wy.val().to_u64())],
        sh: from_bits(u.out_sh.val().to_u64(), 6) as i8,
    })
}

/// Streams every segment through the screener under `pacing` and checks every passing patch and
/// the counters against the model. Returns the model's tally, the number of negative exponents
/// seen and the cycles taken.
fn run(drv: &mut Driver<Screener>, segments: &[Segment], pacing: Pacing, seed: u64) -> Result<(Tally, u64)> {
    let mut expected_tally = Tally::default();
    let mut expected = vec![];
    let mut negative_sh = 0u64;
    for seg in segments {
        for p in &seg.patches {
            let v = screen(&seg.bundle, p);
            expected_tally.add(&v);
            if let Verdict::Pass(s) = v {
                negative_sh += u64::from(s.sh < 0);
            }
            expected.push(expect(&seg.bundle, p));
        }
    }
    let base = counters(drv.uut());
    let mut board =
        Scoreboard::new("screener", seed, expected.iter().copied()).with_context(pacing.to_string());
    let mut mon = Monitor::new(pacing, seed);
    let mut sent = 0usize;
    let start = drv.cycles();
    for (k, seg) in segments.iter().enumerate() {
        let bundle = seg.bundle;
        let mut src = Source::new(seg.patches.iter().copied(), pacing, seed.wrapping_add(k as u64));
        sent += seg.patches.len();
        let limit = drv.cycles() + 200 + 60 * seg.patches.len() as u64;
        loop {
            let done = counters(drv.uut()).0.iter().zip(base.0.iter()).map(|(c, b)| c - b).sum::<u64>()
                == sent as u64;
            if done && src.is_done() && board.matched() == sent {
                break;
            }
            drv.drive(|u| {
                set_bundle(u, &bundle);
                set_patch(u, src.present(true));
                u.out_ready.next = mon.ready();
            })?;
            let u = drv.uut();
            check_credits(u, drv.cycles())?;
            src.accepted(u.in_valid.val() && u.in_ready.val())?;
            let cycle = drv.cycles();
            if mon.observe(cycle, u.out_valid.val(), || read_out(u)) {
                board.check(cycle, read_out(u))?;
            }
            drv.tick()?;
            if drv.cycles() > limit {
                return Err(Error::new(format!(
                    "no progress in segment {k}: {} of {} patches counted, {} of them out",
                    counters(drv.uut()).0.iter().zip(base.0.iter()).map(|(c, b)| c - b).sum::<u64>(),
                    sent,
                    board.matched()
                )));
            }
        }
    }
    board.finish()?;
    let got = counters(drv.uut());
    let delta = Tally([0, 1, 2, 3, 4].map(|i| got.0[i] - base.0[i]));
    if delta != expected_tally {
        return Err(Error::new(format!(
            "counters {delta:?} differ from the model's {expected_tally:?} (seed {seed:#x}, {pacing})"
        )));
    }
    assert_eq!(delta.0.iter().sum::<u64>(), sent as u64);
    println!(
        "{pacing}: {sent} patches in {} cycles, tally {expected_tally:?}, {negative_sh} with sh < 0",
        drv.cycles() - start
    );
    Ok((expected_tally, negative_sh))
}

/// The credit invariants, every cycle: never more than `DEPTH` patches in flight, `in_ready`
/// exactly while fewer are, and no more complete slots than patches in flight.
fn check_credits(u: &Screener, cycle: u64) -> Result<()> {
    let (used, done) = (u.in_flight(), u.buffered());
    if used > DEPTH || u.in_ready.val() != (used < DEPTH) || done > used {
        return Err(Error::new(format!(
            "cycle {cycle}: {used} in flight, {done} buffered, in_ready {} (DEPTH {DEPTH})",
            u.in_ready.val()
        )));
    }
    Ok(())
}

fn new_driver() -> Result<Driver<Screener>> {
    Driver::with_clock(Screener::default(), |s| &mut s.clock)
}

/// The model's results on the test vectors themselves cover every verdict and both signs of sh.
fn assert_coverage(t: Tally, negative_sh: u64, what: &str) {
    assert!(t.0.iter().all(|&c| c > 0), "{what}: some verdict never occurs: {t:?}");
    assert!(negative_sh > 0, "{what}: no negative exponent");
}

/// The corner cases the vectors must reach (counted on the model's side).
fn corner_coverage(segments: &[Segment]) {
    let mut hits = [0u64; 11];
    for seg in segments {
        let bd = &seg.bundle;
        for p in &seg.patches {
            let o = bd.origin;
            let a = [p.a[0] - o[0], p.a[1] - o[1]];
            let bb = [p.b[0] - o[0], p.b[1] - o[1]];
            let k = cross(a, bb);
            let v = screen(bd, p);
            let pass = matches!(v, Verdict::Pass(_));
            hits[0] += u64::from(dot(bd.normal, a) == 0 || dot(bd.normal, bb) == 0);
            hits[1] += u64::from(k == 0 && a != bb);
            hits[2] += u64::from(k == 1 && pass);
            hits[3] += u64::from(cross(bd.first, bb) == -256 && pass);
            hits[4] += u64::from(cross(bd.first, bb) == -257 && v == Verdict::OutsideSector);
            hits[5] += u64::from(cross(bd.last, a) == 256 && pass);
            hits[6] += u64::from(cross(bd.last, a) == 257 && v == Verdict::OutsideSector);
            hits[7] += u64::from(a == bb);
            hits[8] += u64::from(matches!(v, Verdict::Pass(s) if s.sh == -3));
            let tie = if k > 0 && pass { exponent_tie(nmax_of(a, bb), 2 * k as u64) } else { None };
            hits[9] += u64::from(tie == Some(true));
            hits[10] += u64::from(tie == Some(false));
        }
    }
    println!(
        "corner hits (on plane, K = 0, K = 1, first ±256/257, last ±256/257, zero length, sh = -3, \
         2K above nmax in its low bits only, 2K = nmax normalised): {hits:?}"
    );
    assert!(hits.iter().all(|&h| h > 0), "a corner case is never reached: {hits:?}");
}

#[test]
fn screener_matches_model_on_random_and_corner_patches() -> Result<()> {
    // The bulk: 10^5 patches with no stalls.
    let seed = 0x5c4e_e000u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut segments = corner_segments(&mut rng);
    segments.extend(random_segments(&mut rng, 100_000));
    corner_coverage(&segments);
    let mut drv = new_driver()?;
    let (t, neg) =
        run(&mut drv, &segments, Pacing::NONE, seed).map_err(|e| e.context(format!("seed {seed:#x}")))?;
    assert!(t.0.iter().sum::<u64>() >= 100_000);
    assert_coverage(t, neg, "bulk");
    Ok(())
}

#[test]
fn screener_matches_model_under_all_pacings() -> Result<()> {
    for (k, pacing) in Pacing::ALL.into_iter().enumerate() {
        let seed = 0x5c4e_e100u64 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut segments = random_segments(&mut rng, 3000);
        segments.extend(corner_segments(&mut rng).into_iter().take(2));
        let mut drv = new_driver()?;
        let (t, neg) = run(&mut drv, &segments, pacing, seed)
            .map_err(|e| e.context(format!("seed {seed:#x}, {pacing}")))?;
        assert_coverage(t, neg, &pacing.to_string());
    }
    Ok(())
}

#[test]
fn screener_verilog_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0x5c4e_e200u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut segments = random_segments(&mut rng, 2000);
    segments.extend(corner_segments(&mut rng).into_iter().take(1));
    let mut drv = new_driver()?;
    drv.record_ports()?;
    let pacing = Pacing { idle: true, backpressure: true };
    let (t, _) = run(&mut drv, &segments, pacing, seed).map_err(|e| e.context(format!("seed {seed:#x}")))?;
    assert!(t.0.iter().sum::<u64>() >= 2000);
    replay_under_icarus(&mut drv, "screener", seed)?;
    Ok(())
}

/// Replays `drv`'s recording (its ports, every clock) on the exported Verilog under Icarus in
/// `target/tmp/replay/NAME`, naming `seed` in a failure, and prints the report.
fn replay_under_icarus<U: Block>(drv: &mut Driver<U>, name: &str, seed: u64) -> Result<()> {
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join(name);
    let report =
        rec.replay(drv.uut(), &dir, Simulator::Icarus).map_err(|e| e.context(format!("seed {seed:#x}")))?;
    println!("{report}");
    Ok(())
}

/// Drives the bundle inputs.
fn set_bundle(u: &mut Screener, bundle: &BundleSetup) {
    u.origin_x.next = b(bundle.origin[0] as i64);
    u.origin_y.next = b(bundle.origin[1] as i64);
    u.normal_x.next = b(bundle.normal[0] as i64);
    u.normal_y.next = b(bundle.normal[1] as i64);
    u.first_x.next = b(bundle.first[0] as i64);
    u.first_y.next = b(bundle.first[1] as i64);
    u.last_x.next = b(bundle.last[0] as i64);
    u.last_y.next = b(bundle.last[1] as i64);
}

/// Drives one patch offer (or none).
fn set_patch(u: &mut Screener, p: Option<&Patch>) {
    u.in_valid.next = p.is_some();
    let p = p.copied().unwrap_or_default();
    u.in_id.next = (p.id as u64).into();
    u.in_ax.next = b(p.a[0] as i64);
    u.in_ay.next = b(p.a[1] as i64);
    u.in_bx.next = b(p.b[0] as i64);
    u.in_by.next = b(p.b[1] as i64);
}

/// What an unstalled run shows: the cycles of acceptance and output, and the cycles until every
/// patch was counted and every passing one had left.
#[derive(Debug)]
struct Timing {
    accepted: Vec<u64>,
    out: Vec<u64>,
    cycles: u64,
}

/// Offers `patches` back to back from cycle 0 of a fresh screener with the output always ready;
/// checks every output against the model.
fn unstalled_run(bundle: &BundleSetup, patches: &[Patch], seed: u64) -> Result<Timing> {
    let verdicts: Vec<Verdict> = patches.iter().map(|p| screen(bundle, p)).collect();
    let expected: Vec<Out> = patches.iter().map(|p| expect(bundle, p)).collect();
    let mut board = Scoreboard::new("screener", seed, expected.iter().copied()).with_context("unstalled");
    let mut drv = new_driver()?;
    let (mut accepted, mut out) = (vec![], vec![]);
    loop {
        let counted = counters(drv.uut()).0.iter().sum::<u64>();
        // A patch accepted in cycle a is counted in cycle a + COUNT_LATENCY: the counters show
        // it from the next cycle on, not earlier.
        let due = accepted.iter().filter(|&&a| a + COUNT_LATENCY < drv.cycles()).count() as u64;
        if counted != due {
            return Err(Error::new(format!(
                "cycle {}: {counted} patches counted, {due} due (seed {seed:#x})",
                drv.cycles()
            )));
        }
        if counted == patches.len() as u64 && board.matched() == expected.len() {
            break;
        }
        let next = patches.get(accepted.len());
        drv.drive(|u| {
            set_bundle(u, bundle);
            set_patch(u, next);
            u.out_ready.next = true;
        })?;
        let u = drv.uut();
        check_credits(u, drv.cycles())?;
        if next.is_some() && u.in_ready.val() {
            accepted.push(drv.cycles());
        }
        if u.out_valid.val() {
            out.push(drv.cycles());
            board.check(drv.cycles(), read_out(u))?;
        }
        drv.tick()?;
        if drv.cycles() > 10 * patches.len() as u64 + 1000 {
            return Err(Error::new(format!("no progress (seed {seed:#x})")));
        }
    }
    board.finish()?;
    let mut tally = Tally::default();
    verdicts.iter().for_each(|v| tally.add(v));
    if counters(drv.uut()) != tally {
        return Err(Error::new(format!("counters {:?}, model {tally:?}", counters(drv.uut()))));
    }
    Ok(Timing { accepted, out, cycles: drv.cycles() })
}

/// Random patches for one bundle, sorted into those that pass and those screened out.
fn passing_and_screened(rng: &mut ChaCha8Rng, bundle: &BundleSetup, each: usize) -> (Vec<Patch>, Vec<Patch>) {
    let (mut pass, mut out) = (vec![], vec![]);
    let mut id = 0u16;
    while pass.len() < each || out.len() < each {
        id = id.wrapping_add(1);
        let p = random_patch(rng, bundle, id);
        match screen(bundle, &p) {
            Verdict::Pass(_) if pass.len() < each => pass.push(p),
            Verdict::Pass(_) => {}
            _ if out.len() < each => out.push(p),
            _ => {}
        }
    }
    (pass, out)
}

/// One patch per clock: with no idle cycles and no backpressure, `N` patches are accepted in
/// cycles 0..N and every patch, passed or screened out, accepted in cycle `a` leaves in cycle
/// `a + LATENCY`, so the run takes `N + LATENCY` cycles (28): all-pass, all-screened and mixed
/// streams. The pinned latencies are those the module documentation states (verdict in stage
/// 8, counted in stage 9, then the divider's 18 clocks and the FIFO's write and registered
/// read); every patch is counted exactly `COUNT_LATENCY` cycles after its acceptance.
#[test]
fn screener_accepts_one_patch_per_clock_without_backpressure() -> Result<()> {
    assert_eq!((VERDICT_LATENCY, COUNT_LATENCY, LATENCY), (8, 9, 28));
    assert_eq!(LATENCY, VERDICT_LATENCY + DIV_LATENCY + 2);
    assert!(DEPTH as u64 > LATENCY, "II = 1 needs a credit for every cycle a patch is held");
    let seed = 0x5c4e_e300u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // A bundle that passes a fair share of random patches.
    let bundle = loop {
        let bd = random_bundle(&mut rng);
        let passing = (0..200u16)
            .filter(|&i| matches!(screen(&bd, &random_patch(&mut rng, &bd, i)), Verdict::Pass(_)))
            .count();
        if passing > 40 {
            break bd;
        }
    };
    let n = 600;
    let (pass, out) = passing_and_screened(&mut rng, &bundle, n);
    let mut mixed: Vec<Patch> = (0..n).map(|i| if rng.random_bool(0.5) { pass[i] } else { out[i] }).collect();
    // The mixed stream ends with a screened-out patch after the last passing one.
    mixed.push(out[n - 1]);
    for (name, patches) in [("all pass", pass), ("all screened out", out), ("mixed", mixed)] {
        let n_pass = patches.iter().filter(|p| matches!(screen(&bundle, p), Verdict::Pass(_))).count();
        let t = unstalled_run(&bundle, &patches, seed).map_err(|e| e.context(name))?;
        let len = patches.len() as u64;
        // Accepted in cycles 0..N (II = 1) whatever the verdicts, each out LATENCY later.
        assert_eq!(t.accepted, (0..len).collect::<Vec<_>>(), "{name}");
        assert_eq!(t.accepted, accept_cycles(patches.len()), "{name}");
        assert_eq!(t.out, output_cycles(patches.len()), "{name}");
        assert_eq!(t.cycles, unstalled_cycles(patches.len()), "{name}");
        assert_eq!(t.cycles, len + LATENCY, "{name}");
        match name {
            "all pass" => assert_eq!(n_pass, patches.len()),
            "all screened out" => assert_eq!(n_pass, 0),
            _ => assert!(n_pass > n / 4 && n_pass < 3 * n / 4),
        }
        println!("{name}: {len} patches in {} cycles", t.cycles);
    }
    Ok(())
}

/// Sustained backpressure: the screener takes patches until `DEPTH` are in flight (screened-out
/// ones return their credit at the verdict, so it takes more of a mixed stream), then holds
/// `in_ready` low; when the output is released every patch comes out, in order, none lost. The
/// mixed run is replayed under Icarus too (the random pacings rarely reach the limit).
#[test]
fn screener_stops_at_the_credit_limit_under_sustained_backpressure() -> Result<()> {
    let seed = 0x5c4e_e400u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let bundle = random_bundle(&mut rng);
    let (pass, out) = passing_and_screened(&mut rng, &bundle, 200);
    let mixed: Vec<Patch> = (0..200).map(|i| if i % 3 == 0 { pass[i] } else { out[i] }).collect();
    for (name, patches) in [("all pass", &pass), ("mixed", &mixed)] {
        let expected: Vec<Out> = patches.iter().map(|p| expect(&bundle, p)).collect();
        let mut board = Scoreboard::new("screener", seed, expected.iter().copied()).with_context(name);
        let mut drv = new_driver()?;
        if name == "mixed" {
            drv.record_ports()?;
        }
        let mut sent = 0usize;
        let stall = 300u64;
        while board.matched() < expected.len() {
            let ready = drv.cycles() >= stall;
            let next = patches.get(sent);
            drv.drive(|u| {
                set_bundle(u, &bundle);
                set_patch(u, next);
                u.out_ready.next = ready;
            })?;
            let u = drv.uut();
            check_credits(u, drv.cycles())?;
            if drv.cycles() == stall - 1 {
                // Stalled long enough: exactly DEPTH patches hold credits, all decided.
                assert_eq!(sent, DEPTH, "{name}");
                assert_eq!((u.in_flight(), u.buffered(), u.in_ready.val()), (DEPTH, DEPTH, false), "{name}");
                assert_eq!(counters(u).0.iter().sum::<u64>(), DEPTH as u64, "{name}");
            }
            sent += usize::from(next.is_some() && u.in_ready.val());
            if u.out_valid.val() && u.out_ready.val() {
                board.check(drv.cycles(), read_out(u))?;
            }
            drv.tick()?;
            assert!(drv.cycles() < 10_000, "{name}: no progress");
        }
        board.finish()?;
        assert_eq!(sent, patches.len());
        if let Some(rec) = drv.take_recording() {
            let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("screener_credits");
            let report = rec
                .replay(drv.uut(), &dir, Simulator::Icarus)
                .map_err(|e| e.context(format!("seed {seed:#x}")))?;
            println!("{report}");
        }
    }
    Ok(())
}

/// The divider leaf alone: its Rust model against `restoring_quotient` delayed by
/// `DIV_LATENCY`, and its Verilog against its Rust model under Icarus, on random inputs that
/// mostly break the divider's preconditions (the pipeline divides whatever reaches it).
#[test]
fn divider_leaf_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0x5c4e_e500u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut drv = Driver::with_clock(PipeDivider::default(), |d| &mut d.clock)?;
    drv.record_ports()?;
    let mut sent: Vec<[u32; 3]> = vec![];
    for cycle in 0..3000u64 {
        let k: u32 = match rng.random_range(0..4) {
            0 => rng.random(),
            1 => rng.random_range(0..4),
            _ => rng.random::<u32>() >> rng.random_range(0..32),
        };
        let r: u32 =
            if rng.random_bool(0.5) { rng.random() } else { rng.random_range(0..=k.saturating_mul(2)) };
        let (r2, f, f2, tag) = (
            rng.random::<u32>() >> rng.random_range(0..32),
            rng.random_range(0..8u32),
            rng.random_range(0..8u32),
            rng.random_range(0..8u32),
        );
        drv.drive(|d| {
            d.rx.next = (r as u64).into();
            d.ry.next = (r2 as u64).into();
            d.fx.next = (f as u64).into();
            d.fy.next = (f2 as u64).into();
            d.k.next = (k as u64).into();
            d.tag.next = (tag as u64).into();
        })?;
        sent.push([restoring_quotient(r, f, k), restoring_quotient(r2, f2, k), tag]);
        if cycle >= DIV_LATENCY {
            let d = drv.uut();
            let got = [d.qx.val().to_u32(), d.qy.val().to_u32(), d.tag_out.val().to_u32()];
            assert_eq!(got, sent[(cycle - DIV_LATENCY) as usize], "cycle {cycle}");
        }
        drv.tick()?;
    }
    replay_under_icarus(&mut drv, "pipe_divider", seed)?;
    Ok(())
}

/// The normaliser leaf alone: its Rust model against `normalise` delayed by
/// `NORMALISER_LATENCY`, and its Verilog against its Rust model under Icarus, on words with
/// every count of leading zeros (zero among them).
#[test]
fn normaliser_leaf_replays_bit_exactly_under_icarus() -> Result<()> {
    let seed = 0x2a11_7e55u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut drv = Driver::with_clock(Normaliser::default(), |d| &mut d.clock)?;
    drv.record_ports()?;
    let mut sent: Vec<(u32, u32)> = vec![];
    for cycle in 0..2000u64 {
        let v: u32 = if rng.random_bool(0.05) { 0 } else { rng.random::<u32>() >> rng.random_range(0..32) };
        drv.drive(|d| d.value.next = (v as u64).into())?;
        sent.push(normalise(v));
        if cycle >= NORMALISER_LATENCY {
            let d = drv.uut();
            let got = (d.norm.val().to_u32(), d.clz.val().to_u32());
            assert_eq!(got, sent[(cycle - NORMALISER_LATENCY) as usize], "cycle {cycle}, seed {seed:#x}");
        }
        drv.tick()?;
    }
    replay_under_icarus(&mut drv, "normaliser", seed)?;
    Ok(())
}

/// The [`Delay`] leaf alone (the screener's stage-to-stage carry), words and flags, one stage and
/// several: its Rust half against the word of `D` clocks before, its Verilog against its Rust
/// half under Icarus.
#[test]
fn delay_leaf_replays_bit_exactly_under_icarus() -> Result<()> {
    fn run<T: Synth, const D: usize>(name: &str, word: impl Fn(&mut ChaCha8Rng) -> T) -> Result<()> {
        let seed = 0xde1a_0000u64 + D as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut drv = Driver::with_clock(Delay::<T, D>::default(), |d| &mut d.clock)?;
        drv.record_ports()?;
        let mut sent: Vec<T> = vec![];
        for cycle in 0..500usize {
            let w = word(&mut rng);
            drv.drive(|d| d.d.next = w)?;
            sent.push(w);
            drv.tick()?;
            let want = if cycle + 1 >= D { sent[cycle + 1 - D] } else { T::default() };
            assert_eq!(drv.uut().q.val(), want, "{name}: after edge {cycle}, seed {seed:#x}");
        }
        replay_under_icarus(&mut drv, name, seed)?;
        Ok(())
    }
    run::<Bits<18>, 5>("delay_word5", |r| Bits::from(r.random::<u64>() & 0x3ffff))?;
    run::<Bits<32>, 1>("delay_word1", |r| Bits::from(r.random::<u32>() as u64))?;
    run::<bool, 3>("delay_flag3", |r| r.random_bool(0.5))
}

/// A bare [`FifoRam`] (the output FIFO's lanes) behind ports, for its own test.
#[derive(LogicBlock, Default)]
struct FifoRamBench {
    clock: Signal<In, Clock>,
    write_address: Signal<In, Bits<5>>,
    write_data: Signal<In, Bits<18>>,
    write_enable: Signal<In, bool>,
    head_address: Signal<In, Bits<5>>,
    next_address: Signal<In, Bits<5>>,
    pop: Signal<In, bool>,
    read_data: Signal<rust_hdl::prelude::Out, Bits<18>>,
    ram: FifoRam<18, 5>,
}

impl Logic for FifoRamBench {
    #[hdl_gen]
    fn update(&mut self) {
        self.ram.clock.next = self.clock.val();
        self.ram.write_address.next = self.write_address.val();
        self.ram.write_data.next = self.write_data.val();
        self.ram.write_enable.next = self.write_enable.val();
        self.ram.head_address.next = self.head_address.val();
        self.ram.next_address.next = self.next_address.val();
        self.ram.pop.next = self.pop.val();
        self.read_data.next = self.ram.read_data.val();
    }
}

/// The `FifoRam` leaf: after each edge `read_data` is the word the memory held before that
/// edge's write at `next_address` if `pop` was high, else at `head_address` (zero at power-up),
/// on random traffic over 32 words (reads of the word being written included); its Verilog
/// (two read registers and a registered pop) replays the recorded run bit-exactly under Icarus.
#[test]
fn fifo_ram_model_and_verilog_agree() -> Result<()> {
    let seed = 0xf1f0;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut drv = Driver::with_clock(FifoRamBench::default(), |b| &mut b.clock)?;
    drv.record_ports()?;
    let mut mem = [0u64; 32];
    let mut same = 0;
    for cycle in 0..2000 {
        let head = rng.random_range(0..32u64);
        let next = rng.random_range(0..32u64);
        let pop = rng.random_bool(0.5);
        let we = rng.random_bool(0.6);
        let wa = rng.random_range(0..32u64);
        let wd = rng.random_range(0..1u64 << 18);
        drv.cycle(|b| {
            b.write_address.next = wa.into();
            b.write_data.next = wd.into();
            b.write_enable.next = we;
            b.head_address.next = head.into();
            b.next_address.next = next.into();
            b.pop.next = pop;
        })?;
        let read = if pop { next } else { head };
        same += usize::from(we && wa == read);
        let want = mem[read as usize];
        if we {
            mem[wa as usize] = wd;
        }
        let got = drv.uut().read_data.val().to_u64();
        assert_eq!(got, want, "cycle {cycle}, seed {seed:#x}");
    }
    assert!(same > 20, "{same} reads of the word being written");
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("fifo_ram");
    let report = rec.replay(drv.uut(), &dir, Simulator::Icarus)?;
    assert_eq!(report.cycles, rec.cycles());
    println!("{report}");
    // The same run on the iCE40 body (a second memory copy for the second read).
    let ice40 =
        rec.replay_with_defines(drv.uut(), &dir.join("ice40"), Simulator::Icarus, &["SHELLING_ICE40"])?;
    assert_eq!(ice40.cycles, rec.cycles());
    println!("SHELLING_ICE40: {ice40}");
    Ok(())
}

/// Patches tagged with one of two sectors (`in_bank`), the sector presented from the bank the
/// screener shows for its stage 3 (`sector_bank`), as the processing element does when it
/// overlaps sectors: every patch leaves with its own bank's verdict and setup, in order, under
/// random backpressure; the run's Verilog replays under Icarus.
#[test]
fn each_patch_is_screened_for_the_sector_of_its_bank() -> Result<()> {
    let seed = 0xba4c_5ec7u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let b0 = random_bundle(&mut rng);
    let theta = (b0.normal[1] as f64).atan2(b0.normal[0] as f64);
    let half = std::f64::consts::FRAC_PI_2;
    let (alpha, beta) = (rng.random_range(0.0..half), rng.random_range(0.0..half));
    let b1 = BundleSetup { first: dir(theta - alpha), last: dir(theta + beta), ..b0 };
    let banks = [b0, b1];
    let patches: Vec<(Patch, usize)> = (0..3000)
        .map(|i| {
            let bank = rng.random_range(0..2);
            (random_patch(&mut rng, &banks[bank], i as u16), bank)
        })
        .collect();
    let differ = patches.iter().filter(|(p, _)| expect(&b0, p) != expect(&b1, p)).count();
    assert!(differ > 100, "seed {seed:#x}: only {differ} patches tell the two sectors apart");
    let expected = patches.iter().map(|(p, bank)| expect(&banks[*bank], p));
    let mut board = Scoreboard::new("two sectors", seed, expected).with_context("random backpressure");
    let mut drv = new_driver()?;
    drv.record_ports()?;
    let mut next = 0;
    while board.matched() < patches.len() {
        let offer = (rng.random_range(0..4) != 0).then(|| patches.get(next)).flatten();
        let ready = rng.random_range(0..3) != 0;
        drv.drive(|u| {
            set_bundle(u, &banks[u.sector_bank.val() as usize]);
            set_patch(u, offer.map(|(p, _)| p));
            u.in_bank.next = offer.is_some_and(|&(_, bank)| bank == 1);
            u.out_ready.next = ready;
        })?;
        let u = drv.uut();
        next += (u.in_valid.val() && u.in_ready.val()) as usize;
        let cycle = drv.cycles();
        if u.out_valid.val() && u.out_ready.val() {
            board.check(cycle, read_out(u))?;
        }
        drv.tick()?;
        if cycle > 20 * patches.len() as u64 {
            return Err(Error::new(format!("seed {seed:#x}: {} of {} out", board.matched(), patches.len())));
        }
    }
    board.finish()?;
    let rec = drv.take_recording().ok_or("recording was on")?;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("replay").join("screener-banks");
    let report =
        rec.replay(drv.uut(), &dir, Simulator::Icarus).map_err(|e| e.context(format!("seed {seed:#x}")))?;
    println!("{differ} patches tell the sectors apart; {report}");
    Ok(())
}
