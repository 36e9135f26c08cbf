//! Driving the intersection unit ([`IntersectionUnit`]): bundle setup, a paced patch stream and
//! the readout of the ray memory, with the bit-true model's answer beside it.
//!
//! A [`Job`] is one patch set up by the screener plus the range of rays it is tested against
//! (the scheduler's decision). [`run_bundle`] loads the directions, streams the jobs (random idle
//! cycles on request), waits until the unit is idle and reads every ray's nearest hit back
//! (read-and-clear, so the unit is ready for the next bundle). [`model_bundle`] computes what it
//! must return.

use crate::{impl_clocked, Driver, Error, Pacing, Result, Source};
use rust_hdl::prelude::*;
use shelling_hdl::formats::to_bits;
use shelling_hdl::formats::{Nearest, PatchSetup};
use shelling_hdl::intersection::model::{replaces, test};
use shelling_hdl::intersection::{IntersectionUnit, RAY_BITS, READOUT_LATENCY};
use shelling_hdl::pe::ProcessingElement;

impl_clocked!(IntersectionUnit);

/// Rays a bundle may hold.
pub const MAX_BUNDLE: usize = 1 << RAY_BITS;

/// One patch and the rays `first .. first + count` (modulo the bundle memory) it is tested
/// against, or, with `retire`, the rays to retire (the patch is ignored).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Job {
    pub patch: PatchSetup,
    pub first: u16,
    pub count: u16,
    pub retire: bool,
}

impl Job {
    /// A test job.
    pub fn test(patch: PatchSetup, first: u16, count: u16) -> Job {
        Job { patch, first, count, retire: false }
    }

    /// A retire job for rays `first .. first + count`.
    pub fn retire(first: u16, count: u16) -> Job {
        Job { first, count, retire: true, ..Job::default() }
    }
}

fn field<const N: usize>(v: i64) -> Bits<N> {
    Bits::from(to_bits(v, N as u32))
}

/// The rays a bundle's readout must cover: the loaded directions and every ray a job touches
/// (a job may run past the loaded ones and wrap around the ray memory; the unit's direction
/// memory is zero at power-up).
pub fn rays_touched(dirs: &[[i32; 2]], jobs: &[Job]) -> usize {
    jobs.iter()
        .map(|j| j.first as usize + j.count as usize)
        .max()
        .unwrap_or(0)
        .max(dirs.len())
        .min(MAX_BUNDLE)
}

/// What a unit fresh from power-up holds after `dirs` were written and the jobs ran: every ray's
/// nearest hit for rays `0..rays_touched`, and the number of tests of live rays (the bit-true
/// model). The written rays start live, the others dead.
pub fn model_bundle_counted(dirs: &[[i32; 2]], jobs: &[Job]) -> (Vec<Option<Nearest>>, u64) {
    let mut best = vec![None; MAX_BUNDLE];
    let mut live: Vec<bool> = (0..MAX_BUNDLE).map(|r| r < dirs.len()).collect();
    let mut tests = 0;
    for j in jobs {
        for k in 0..j.count as usize {
            let r = (j.first as usize + k) % MAX_BUNDLE;
            if j.retire {
                live[r] = false;
                continue;
            }
            if !live[r] {
                continue;
            }
            tests += 1;
            if let Some(key) = test(&j.patch, dirs[r]) {
                if replaces(key, j.patch.id, best[r]) {
                    best[r] = Some(Nearest { key, id: j.patch.id });
                }
            }
        }
    }
    best.truncate(rays_touched(dirs, jobs));
    (best, tests)
}

/// [`model_bundle_counted`]'s hits.
pub fn model_bundle(dirs: &[[i32; 2]], jobs: &[Job]) -> Vec<Option<Nearest>> {
    model_bundle_counted(dirs, jobs).0
}

/// The ray ports the intersection unit and the processing element share, by the same names and
/// protocol: direction writes (`dir_we`, `dir_addr`, `dir_x`, `dir_y`), the read-and-clear
/// readout (`res_re`, `res_addr` in; `res_hit`, `res_id`, `res_key` [`READOUT_LATENCY`] = 2
/// cycles after) and `busy`.
pub trait RayPorts: Block {
    /// Drives a direction write of ray `i`, or none.
    fn write_direction(&mut self, write: Option<(usize, [i32; 2])>);
    /// Drives a readout of ray `i`, or none.
    fn request_readout(&mut self, ray: Option<usize>);
    /// The ray whose readout was requested [`READOUT_LATENCY`] cycles before.
    fn readout(&self) -> Option<Nearest>;
    fn is_busy(&self) -> bool;
}

/// Implements [`RayPorts`] for blocks with the ports it names.
macro_rules! impl_ray_ports {
    ($($block:ty),+) => {
        $(
            impl RayPorts for $block {
                fn write_direction(&mut self, write: Option<(usize, [i32; 2])>) {
                    self.dir_we.next = write.is_some();
                    if let Some((i, d)) = write {
                        self.dir_addr.next = (i as u64).into();
                        self.dir_x.next = field(d[0] as i64);
                        self.dir_y.next = field(d[1] as i64);
                    }
                }

                fn request_readout(&mut self, ray: Option<usize>) {
                    self.res_re.next = ray.is_some();
                    if let Some(i) = ray {
                        self.res_addr.next = (i as u64).into();
                    }
                }

                fn readout(&self) -> Option<Nearest> {
                    self.res_hit
                        .val()
                        .then(|| Nearest { key: self.res_key.val().to_u32(), id: self.res_id.val().to_u16() })
                }

                fn is_busy(&self) -> bool {
                    self.busy.val()
                }
            }
        )+
    };
}

impl_ray_ports!(IntersectionUnit, ProcessingElement);

/// A simulator of a block with [`RayPorts`], one cycle at a time: a [`Driver`] of the block, or
/// a whole PE under any simulator ([`crate::pe_sim::PeRays`]).
pub trait RayBench {
    /// One cycle with a direction write and a readout request (or none of either).
    fn cycle_rays(&mut self, write: Option<(usize, [i32; 2])>, read: Option<usize>) -> Result<()>;
    /// The ray whose readout was requested [`READOUT_LATENCY`] cycles before.
    fn readout(&self) -> Option<Nearest>;
    fn is_busy(&self) -> bool;
}

impl<B: RayPorts> RayBench for Driver<B> {
    fn cycle_rays(&mut self, write: Option<(usize, [i32; 2])>, read: Option<usize>) -> Result<()> {
        self.cycle(|u| {
            u.write_direction(write);
            u.request_readout(read);
        })
    }

    fn readout(&self) -> Option<Nearest> {
        self.uut().readout()
    }

    fn is_busy(&self) -> bool {
        self.uut().is_busy()
    }
}

/// Writes the bundle's ray directions (one per cycle).
pub fn load_directions(drv: &mut impl RayBench, dirs: &[[i32; 2]]) -> Result<()> {
    if dirs.len() > MAX_BUNDLE {
        return Err(Error::new(format!("a bundle holds at most {MAX_BUNDLE} rays, got {}", dirs.len())));
    }
    for (i, d) in dirs.iter().enumerate() {
        drv.cycle_rays(Some((i, *d)), None)?;
    }
    drv.cycle_rays(None, None)
}

/// Streams the jobs (random idle cycles if `pacing.idle`), then waits until the unit is idle.
/// Returns the number of cycles from the first offer to idle.
pub fn stream_jobs(
    drv: &mut Driver<IntersectionUnit>,
    jobs: &[Job],
    pacing: Pacing,
    seed: u64,
) -> Result<u64> {
    let start = drv.cycles();
    let tests: u64 = jobs.iter().map(|j| j.count as u64).sum();
    let limit = start + 16 + 2 * (tests + jobs.len() as u64) * if pacing.idle { 4 } else { 1 };
    let mut src = Source::new(jobs.iter().copied(), pacing, seed);
    loop {
        drv.drive(|u| present_job(u, src.present(true).map(|&j| (j, 0))))?;
        let u = drv.uut();
        src.accepted(u.patch_valid.val() && u.patch_ready.val())?;
        drv.tick()?;
        if src.is_done() && !drv.uut().busy.val() && !drv.uut().patch_valid.val() {
            break;
        }
        if drv.cycles() > limit {
            return Err(Error::new(format!(
                "no progress after {} cycles: {} of {} jobs accepted",
                drv.cycles() - start,
                src.sent(),
                jobs.len()
            )));
        }
    }
    Ok(drv.cycles() - start)
}

/// Reads and clears the nearest hits of rays `0..rays`, one per cycle: each hit arrives
/// [`READOUT_LATENCY`] cycles after its request, so the readout takes `rays + 1` cycles (the
/// last one also clears the last ray).
pub fn read_hits(drv: &mut impl RayBench, rays: usize) -> Result<Vec<Option<Nearest>>> {
    let mut out = Vec::with_capacity(rays);
    for i in 0..rays + READOUT_LATENCY as usize - 1 {
        if i < rays && drv.is_busy() {
            return Err(Error::new("readout while the unit is busy"));
        }
        drv.cycle_rays(None, (i < rays).then_some(i))?;
        if i + 1 >= READOUT_LATENCY as usize {
            out.push(drv.readout());
        }
    }
    Ok(out)
}

/// A whole bundle on a unit fresh from power-up or a previous readout: directions, jobs, readout
/// of [`rays_touched`] rays. Returns the hits and the streaming cycles.
pub fn run_bundle(
    drv: &mut Driver<IntersectionUnit>,
    dirs: &[[i32; 2]],
    jobs: &[Job],
    pacing: Pacing,
    seed: u64,
) -> Result<(Vec<Option<Nearest>>, u64)> {
    load_directions(drv, dirs)?;
    let cycles = stream_jobs(drv, jobs, pacing, seed)?;
    Ok((read_hits(drv, rays_touched(dirs, jobs))?, cycles))
}

/// The rays of the ray memory's half `half` (0 or 1): ray `r` of a bundle there is ray
/// `half · MAX_BUNDLE + r` of the unit.
fn in_half(half: usize, r: usize) -> u64 {
    (half * MAX_BUNDLE + r % MAX_BUNDLE) as u64
}

/// Drives job `j` of a bundle in half `half` on the unit's patch port (or none).
fn present_job(u: &mut IntersectionUnit, job: Option<(Job, usize)>) {
    u.patch_valid.next = job.is_some();
    if let Some((j, half)) = job {
        let p = j.patch;
        u.patch_ax.next = field(p.a[0] as i64);
        u.patch_ay.next = field(p.a[1] as i64);
        u.patch_bx.next = field(p.b[0] as i64);
        u.patch_by.next = field(p.b[1] as i64);
        u.patch_wx.next = field(p.w[0] as i64);
        u.patch_wy.next = field(p.w[1] as i64);
        u.patch_sh.next = field(p.sh as i64);
        u.patch_id.next = (p.id as u64).into();
        u.patch_first.next = in_half(half, j.first as usize).into();
        u.patch_count.next = (j.count as u64).into();
        u.patch_retire.next = j.retire;
    }
}

/// Bundles overlapped in the two halves of the ray memory, as a PE's host runs its sources:
/// bundle `b` lives in half `b mod 2`; its jobs stream as soon as its directions are written and
/// the bundle before has sent all of its own, and end with a marker (a retire of no rays); it is
/// read out as soon as the unit's `marks` counts that marker, while the next bundle's jobs run
/// in the other half; bundle `b + 2`'s directions are written into the half as it is read out.
/// Every cycle carries a direction write, a readout request and a patch offer where one is due.
/// Returns each bundle's hits (of [`rays_touched`] rays) and the cycles of the whole run.
pub fn run_overlapped(
    drv: &mut Driver<IntersectionUnit>,
    bundles: &[(Vec<[i32; 2]>, Vec<Job>)],
) -> Result<(Vec<Vec<Option<Nearest>>>, u64)> {
    let n = bundles.len();
    let start = drv.cycles();
    let marks_before = drv.uut().marks.val().to_u32();
    let rays: Vec<usize> = bundles.iter().map(|(d, j)| rays_touched(d, j)).collect();
    // Per bundle: directions written, jobs sent (the marker last), readout requests and hits.
    let (mut written, mut sent, mut requested) = (vec![0usize; n], vec![0usize; n], vec![0usize; n]);
    let mut hits: Vec<Vec<Option<Nearest>>> = vec![Vec::new(); n];
    // The readouts in flight: (bundle, cycles since the request).
    let mut in_flight: Vec<(usize, u64)> = Vec::new();
    let total: u64 =
        bundles.iter().map(|(d, j)| d.len() as u64 + j.iter().map(|j| j.count as u64 + 1).sum::<u64>()).sum();
    let limit = start + 64 + 4 * total + 4 * rays.iter().sum::<usize>() as u64;
    while hits.iter().zip(&rays).any(|(h, &r)| h.len() < r) {
        let marks = drv.uut().marks.val().to_u32().wrapping_sub(marks_before) as usize;
        // The bundle being written: the first not fully written, once the bundle two before it
        // (the same half) has been read out.
        let w = (0..n).find(|&b| written[b] < bundles[b].0.len());
        let w = w.filter(|&b| b < 2 || requested[b - 2] == rays[b - 2]);
        // The bundle streaming: the first with jobs left, once written and the one before sent.
        let s = (0..n).find(|&b| sent[b] <= bundles[b].1.len());
        let s = s.filter(|&b| written[b] == bundles[b].0.len());
        // The bundle read out: the first with readouts left, once its marker is counted.
        let r = (0..n).find(|&b| requested[b] < rays[b]).filter(|&b| marks > b);
        let write = w.map(|b| (in_half(b % 2, written[b]) as usize, bundles[b].0[written[b]]));
        let read = r.map(|b| in_half(b % 2, requested[b]) as usize);
        let job = s.map(|b| {
            let j = bundles[b].1.get(sent[b]).copied().unwrap_or(Job::retire(0, 0));
            (j, b % 2)
        });
        drv.drive(|u| {
            u.write_direction(write);
            u.request_readout(read);
            present_job(u, job);
        })?;
        let taken = drv.uut().patch_valid.val() && drv.uut().patch_ready.val();
        drv.tick()?;
        if let Some(b) = w {
            written[b] += 1;
        }
        if let (Some(b), true) = (s, taken) {
            sent[b] += 1;
        }
        in_flight.iter_mut().for_each(|f| f.1 += 1);
        if let Some((b, _)) = in_flight.first().copied().filter(|f| f.1 == READOUT_LATENCY - 1) {
            hits[b].push(drv.uut().readout());
            in_flight.remove(0);
        }
        if let Some(b) = r {
            requested[b] += 1;
            in_flight.push((b, 0));
        }
        if drv.cycles() > limit {
            return Err(Error::new(format!(
                "overlapped bundles: no end after {} cycles (written {written:?}, sent {sent:?}, read {requested:?}, marks {marks})",
                drv.cycles() - start
            )));
        }
    }
    Ok((hits, drv.cycles() - start))
}
