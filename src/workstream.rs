//! The work stream: what the shell scheduler sends the hardware, one item after another, and
//! its bit-true execution.
//!
//! The tracers of [`crate::trace`] are the scheduler: they decide which patches are loaded for
//! which sector and which rays each one is tested against, and they announce it through the
//! hooks of [`HitTest`]. A [`Recorder`] wraps any backend and writes those announcements down as
//! a [`WorkStream`], the one input every backend consumes (the seam between scheduler and backends):
//!
//! * [`Item::Sector`]: a new sector (its rays bound the screener's angular test);
//! * [`Item::Job`]: one patch loaded from host memory, screened, and tested against the rays of
//!   a range that are still in the bundle; a patch the scheduler screened out itself is still
//!   loaded (the hardware screens it again) and gets an empty range;
//! * [`Item::Retire`]: a ray leaves the bundle (tracking); later jobs do not test it.
//!
//! Every load is one job, so the stream has exactly `patches_read_before_screening` jobs. Within
//! a shell the jobs come in the order the technique tests them (radial subshells for S, angle
//! for D) with the retirements between, followed by the shell's patches that were loaded but
//! not tested. The scheduler's decisions (which rays retire, when the conventional walk stops)
//! follow the answers of the backend it ran with; the stream is recorded with the bit-true
//! backend, so that the hardware, which computes the same answers, is handed the same decisions.
//!
//! [`commands`] turns a stream into what the host sends a processing element; [`execute`] runs
//! those through the bit-true models of the screener and the intersection unit, as the PE does:
//! its hits are what the RTL must return.

use crate::arith::FixedBundle;
use crate::geom::Segment;
use crate::rays::Bundle;
use crate::trace::HitTest;
use shelling_hdl::formats::Nearest;
use shelling_testbench::pe::{model, Command, ModelCounts, PeSetup, PE_RAY_MEMORY};
use std::cell::RefCell;
use std::ops::Range;

/// One item of the work stream.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Item {
    /// A sector starts: rays `rays` (non-empty) of the bundle.
    Sector { rays: Range<u32> },
    /// Patch `patch` is loaded and, if the screener passes it, tested against the rays of
    /// `rays` still in the bundle (`rays` may be empty).
    Job { patch: u32, rays: Range<u32> },
    /// Ray `ray` leaves the bundle.
    Retire { ray: u32 },
}

/// A whole source's work stream.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct WorkStream {
    /// Rays in the bundle.
    pub rays: usize,
    pub items: Vec<Item>,
}

impl WorkStream {
    /// Jobs, i.e. patch loads.
    pub fn jobs(&self) -> usize {
        self.items.iter().filter(|i| matches!(i, Item::Job { .. })).count()
    }
}

#[derive(Default)]
struct Recording {
    items: Vec<Item>,
    /// Patches loaded and not yet made a job, in load order.
    pending: Vec<u32>,
    /// Whether a job or a retirement came after the last load (the next load opens a new shell).
    worked: bool,
}

impl Recording {
    fn flush(&mut self) {
        for p in self.pending.drain(..) {
            self.items.push(Item::Job { patch: p, rays: 0..0 });
        }
    }
}

/// Wraps a backend: answers as it does and records the work stream the tracer announces.
pub struct Recorder<'a, H> {
    inner: &'a H,
    rays: usize,
    rec: RefCell<Recording>,
}

impl<'a, H: HitTest> Recorder<'a, H> {
    pub fn new(inner: &'a H, bundle: &Bundle) -> Self {
        Recorder { inner, rays: bundle.len(), rec: RefCell::default() }
    }

    /// The stream recorded so far (pending loads become empty jobs).
    pub fn finish(self) -> WorkStream {
        let mut rec = self.rec.into_inner();
        rec.flush();
        WorkStream { rays: self.rays, items: rec.items }
    }
}

impl<H: HitTest> HitTest for Recorder<'_, H> {
    #[inline]
    fn hit(&self, bundle: &Bundle, i: usize, p: u32, seg: &Segment) -> Option<f64> {
        self.inner.hit(bundle, i, p, seg)
    }

    #[inline]
    fn hit_rays(
        &self,
        bundle: &Bundle,
        p: u32,
        seg: &Segment,
        base: usize,
        rays: u64,
        found: impl FnMut(usize, f64),
    ) {
        self.inner.hit_rays(bundle, p, seg, base, rays, found)
    }

    fn sector(&self, rays: Range<usize>) {
        let mut rec = self.rec.borrow_mut();
        rec.flush();
        rec.items.push(Item::Sector { rays: rays.start as u32..rays.end as u32 });
        rec.worked = false;
    }

    fn load(&self, p: u32) {
        let mut rec = self.rec.borrow_mut();
        if rec.worked {
            rec.flush();
            rec.worked = false;
        }
        rec.pending.push(p);
    }

    fn span(&self, p: u32, rays: Range<usize>) {
        let mut rec = self.rec.borrow_mut();
        // A patch is tested in the shell that loaded it, so it is pending (the last few loads).
        if let Some(k) = rec.pending.iter().rposition(|&q| q == p) {
            rec.pending.remove(k);
        }
        rec.items.push(Item::Job { patch: p, rays: rays.start as u32..rays.end as u32 });
        rec.worked = true;
    }

    fn retire(&self, i: usize) {
        let mut rec = self.rec.borrow_mut();
        rec.items.push(Item::Retire { ray: i as u32 });
        rec.worked = true;
    }
}

/// What a stream is inconsistent about.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum StreamError {
    #[error("entry {item} of the work stream (counted from 0): {what}")]
    Invalid { item: usize, what: String },
    #[error("the bundle has {0} rays; a processing element holds 1 to {PE_RAY_MEMORY}")]
    TooManyRays(usize),
}

/// Checks that the bundle fits a processing element, that every index in the stream is in range
/// for `fixed` (patches and rays) and that every job comes after a sector.
pub fn validate(stream: &WorkStream, fixed: &FixedBundle) -> Result<(), StreamError> {
    let bad = |item: usize, what: String| Err(StreamError::Invalid { item, what });
    if stream.rays == 0 || stream.rays > PE_RAY_MEMORY || stream.rays > fixed.dirs.len() {
        return Err(StreamError::TooManyRays(stream.rays));
    }
    let rays = stream.rays as u32;
    let mut sector = false;
    for (k, it) in stream.items.iter().enumerate() {
        match it {
            Item::Sector { rays: r } => {
                if r.start >= r.end || r.end > rays {
                    return bad(k, format!("sector {r:?} is empty or beyond the {rays} rays"));
                }
                sector = true;
            }
            Item::Job { patch, rays: r } => {
                if !sector {
                    return bad(k, "a job before any sector".into());
                }
                if *patch as usize >= fixed.patches.len() {
                    return bad(k, format!("patch {patch} of {}", fixed.patches.len()));
                }
                if r.start > r.end || r.end > rays {
                    return bad(k, format!("ray range {r:?} beyond the {rays} rays"));
                }
            }
            Item::Retire { ray } => {
                if *ray >= rays {
                    return bad(k, format!("retires ray {ray} of {rays}"));
                }
            }
        }
    }
    Ok(())
}

/// The source and the command stream the host sends a processing element for `stream`: the
/// quantised directions and patches of `fixed`, a command per sector and per job, a job's range
/// trimmed to its live rays (`live_span`). Retirements are sent late: a retired ray is told to
/// the PE only just before the first job whose (trimmed) range holds it, neighbouring rays as
/// one range, so that inside every job's range the PE's live bits are the tracker's and the
/// same rays are tested, while a retirement that no later range needs costs the intersection
/// unit no slot (it retires one ray per clock).
pub fn commands(
    stream: &WorkStream,
    fixed: &FixedBundle,
) -> Result<(PeSetup, Vec<[i32; 4]>, Vec<Command>), StreamError> {
    validate(stream, fixed)?;
    let setup = PeSetup {
        origin: fixed.setup.origin,
        normal: fixed.setup.normal,
        dirs: fixed.dirs[..stream.rays].to_vec(),
    };
    let patches = fixed.patches.iter().map(|p| [p.a[0], p.a[1], p.b[0], p.b[1]]).collect();
    let mut cmds: Vec<Command> = Vec::with_capacity(stream.items.len());
    let mut live = vec![true; stream.rays];
    // Retired by the tracker, not yet told to the PE.
    let mut unsent = vec![false; stream.rays];
    for it in &stream.items {
        match *it {
            Item::Sector { ref rays } => cmds.push(Command::Sector {
                first: fixed.dirs[rays.start as usize],
                last: fixed.dirs[rays.end as usize - 1],
            }),
            Item::Job { patch, ref rays } => {
                let span = live_span(&live, rays);
                let mut r = span.start as usize;
                while r < span.end as usize {
                    let first = r;
                    while r < span.end as usize && unsent[r] {
                        unsent[r] = false;
                        r += 1;
                    }
                    if r > first {
                        cmds.push(Command::Retire { first: first as u16, count: (r - first) as u16 });
                    }
                    r += 1;
                }
                cmds.push(Command::Job {
                    id: patch as u16,
                    first: span.start as u16,
                    count: span.len() as u16,
                })
            }
            Item::Retire { ray } => {
                live[ray as usize] = false;
                unsent[ray as usize] = true;
            }
        }
    }
    Ok((setup, patches, cmds))
}

/// What the host hands a processing element for one source: the setup, the host memory's patches
/// (`[ax, ay, bx, by]`, Q11.6 after the quantiser's offset) and the commands.
pub type PeWork = (PeSetup, Vec<[i32; 4]>, Vec<Command>);

/// The work of several bundles shot from one ray origin with one source normal (the sweep planes
/// of a 3D bundle, `crate::d3::on_pe`) as one source of the PE: their directions one after
/// another, their patches one after another in the host memory, each bundle's commands with its
/// rays and patches moved past those before it (its jobs then test only its own rays against its
/// own patches, so every ray's hit is the one it has alone). Each bundle's coordinates are moved
/// onto the lowest of the bundles' quantiser offsets by whole world units, exactly (the datapath's
/// coordinates relative to the origin do not depend on the offset). Fails when the bundles'
/// origins or normals differ, when the directions exceed the PE's ray memory or a moved
/// coordinate its window.
pub fn pack(parts: &[(&WorkStream, &FixedBundle)]) -> Result<PeWork, StreamError> {
    let bad = |what: String| Err(StreamError::Invalid { item: 0, what });
    let lowest = |k: usize| parts.iter().map(|(_, f)| f.quantizer.offset[k]).fold(f64::INFINITY, f64::min);
    let offset = [lowest(0), lowest(1)];
    let scale = f64::from(1u32 << shelling_hdl::formats::COORD_FRAC);
    let top = (shelling_hdl::formats::WORLD_SPAN * scale) as i64;
    let (mut setup, mut patches, mut cmds) = (None::<PeSetup>, Vec::new(), Vec::new());
    for (i, (stream, fixed)) in parts.iter().enumerate() {
        let (s, p, c) = commands(stream, fixed)?;
        let shift = [0, 1].map(|k| ((fixed.quantizer.offset[k] - offset[k]) * scale) as i32);
        let moved = |x: i32, k: usize| x + shift[k];
        let origin = [moved(s.origin[0], 0), moved(s.origin[1], 1)];
        let (rays, base, count) = (setup.as_ref().map_or(0, |s| s.dirs.len()), patches.len(), s.dirs.len());
        match &mut setup {
            None => setup = Some(PeSetup { origin, ..s }),
            Some(t) if t.origin == origin && t.normal == s.normal => t.dirs.extend_from_slice(&s.dirs),
            Some(_) => {
                return bad(format!("bundle {i} of a pack has another ray origin or normal than bundle 0"))
            }
        }
        for q in p {
            let q = [moved(q[0], 0), moved(q[1], 1), moved(q[2], 0), moved(q[3], 1)];
            if q.iter().any(|&x| i64::from(x) >= top) {
                return bad(format!(
                    "bundle {i}'s patches lie beyond the datapath's window from bundle 0's origin"
                ));
            }
            patches.push(q);
        }
        if rays + count > PE_RAY_MEMORY {
            return Err(StreamError::TooManyRays(rays + count));
        }
        if patches.len() > 1 << shelling_hdl::formats::ID_BITS {
            return bad(format!("a pack of {} patches: the patch ids are 16 bits", patches.len()));
        }
        cmds.extend(c.into_iter().map(|c| match c {
            Command::Job { id, first, count } => {
                Command::Job { id: id + base as u16, first: first + rays as u16, count }
            }
            Command::Retire { first, count } => Command::Retire { first: first + rays as u16, count },
            sector => sector,
        }));
    }
    match setup {
        Some(setup) => Ok((setup, patches, cmds)),
        None => bad("a pack of no bundle".to_string()),
    }
}

/// The part of `rays` from its first live ray to its last (empty, at `rays.start`, if none is
/// live): a job's range as the host sends it, so that the intersection unit spends no slot on the
/// retired rays at either end of it (those between, it still issues: `ModelCounts::live_runs`
/// counts what splitting the range at them would cost in commands).
fn live_span(live: &[bool], rays: &Range<u32>) -> Range<u32> {
    let r = rays.start as usize..rays.end as usize;
    match live[r.clone()].iter().position(|&l| l) {
        None => rays.start..rays.start,
        Some(lo) => {
            let hi = live[r.clone()].iter().rposition(|&l| l).expect("a live ray");
            (r.start + lo) as u32..(r.start + hi + 1) as u32
        }
    }
}

/// Executes a stream in the bit-true models, command by command as the processing element does
/// ([`shelling_testbench::pe::model`]): each sector's screener setup, each job's screener
/// verdict under it and the intersection unit's test of every live ray of its range. Returns
/// every ray's nearest hit and the counts.
pub fn execute(
    stream: &WorkStream,
    fixed: &FixedBundle,
) -> Result<(Vec<Option<Nearest>>, ModelCounts), StreamError> {
    let (setup, patches, cmds) = commands(stream, fixed)?;
    Ok(model(&setup, &patches, &cmds))
}
