//! The shared host memory of the paper, as a cycle-accurate model (plain Rust, not RTL): the
//! patches of the scene, served through one port, one patch at a time, each load taking `T_c`
//! cycles (the data arrival time per patch).
//!
//! # Protocol
//!
//! The port is the memory side of the patch loader's memory port (`shelling_hdl::loader`, "The
//! memory port"), also served by the patch cache (`shelling_hdl::cache`): the requester raises
//! `mem_req` for one cycle per patch with the patch id on `mem_addr`; the memory answers every
//! request exactly once, in request order, by raising `mem_valid` for one cycle with the
//! patch's four coordinates.
//!
//! Per cycle, with a [`Driver`](crate::Driver): drive `mem_valid` and the data from the
//! response the previous call returned, read `mem_req` / `mem_addr` in the settled pre-edge
//! state, pass them to [`HostMemory::cycle`], keep its answer for the next cycle, tick.
//!
//! # Timing
//!
//! Requests are queued without limit (the requesters limit themselves) and served in order,
//! one at a time. Request `k`, seen in cycle `r_k`, starts service in cycle
//! `s_k = max(r_k, e_{k−1})` and is answered (its response presented) in cycle
//! `e_k = s_k + T_c`, where `e_{k−1}` is the cycle its predecessor's response is presented
//! (`e_{−1} = 0`). So:
//!
//! * a request that finds the port idle, seen in cycle `r`, is answered in cycle `r + T_c`;
//! * a back-to-back stream of `N` requests from cycle `r` is answered in cycles
//!   `r + T_c, r + 2·T_c, …, r + N·T_c`: exactly `T_c` cycles apart;
//! * the port is busy (serving) in the `T_c` cycles `s_k … e_k − 1` of each load: after every
//!   load has been answered, [`HostMemory::busy_cycles`] is `T_c ×` [`HostMemory::loads`].
//!
//! With `T_c = 1` a request every cycle is answered every cycle, one cycle later.
//! [`answer_cycles`] is the same rule as a plain function of the request cycles.

use std::collections::VecDeque;

use crate::{Error, Result};

/// Coordinates are 17-bit unsigned (world coordinates, Q11.6).
pub const COORD_BITS: u32 = 17;

/// The host memory (see the [module docs](self)).
#[derive(Clone, Debug)]
pub struct HostMemory {
    patches: Vec<[i32; 4]>,
    tc: u64,
    /// Requests not yet answered, oldest first: (id, cycle seen).
    queue: VecDeque<(u16, u64)>,
    /// The cycle the last response was presented in (`e_{k−1}`), 0 before the first.
    last_answer: u64,
    /// The cycle the next call to [`HostMemory::cycle`] stands for.
    now: u64,
    loads: u64,
    busy: u64,
}

impl HostMemory {
    /// A memory holding `patches[id] = [ax, ay, bx, by]` (17-bit unsigned world coordinates,
    /// Q11.6), answering each request in `tc ≥ 1` cycles. Fails on `tc = 0`, on more than
    /// 2^16 patches and on a coordinate outside `0..2^17`, naming it.
    pub fn new(patches: Vec<[i32; 4]>, tc: u32) -> Result<Self> {
        if tc == 0 {
            return Err(Error::new("host memory: T_c must be at least 1 cycle (got tc = 0)"));
        }
        if patches.len() > 1 << 16 {
            return Err(Error::new(format!(
                "host memory: {} patches, but ids are 16 bits (at most 65536 patches)",
                patches.len()
            )));
        }
        for (id, p) in patches.iter().enumerate() {
            for (c, name) in p.iter().zip(["ax", "ay", "bx", "by"]) {
                if !(0..1 << COORD_BITS).contains(c) {
                    return Err(Error::new(format!(
                        "host memory: patch {id} coordinate {name} = {c} is not a 17-bit unsigned value"
                    )));
                }
            }
        }
        Ok(Self { patches, tc: tc.into(), queue: VecDeque::new(), last_answer: 0, now: 0, loads: 0, busy: 0 })
    }

    /// The data arrival time per patch, in cycles.
    pub fn tc(&self) -> u32 {
        self.tc as u32
    }

    /// The number of patches held (valid ids are `0..len`).
    pub fn len(&self) -> usize {
        self.patches.len()
    }

    /// Whether the memory holds no patch.
    pub fn is_empty(&self) -> bool {
        self.patches.is_empty()
    }

    /// The coordinates of patch `id`, or `None` if it is out of range.
    pub fn patch(&self, id: u16) -> Option<[i32; 4]> {
        self.patches.get(id as usize).copied()
    }

    /// One clock cycle. `request` is the address on the port in this cycle (the requester's
    /// `mem_req` high, read in the settled pre-edge state), or `None`. Returns the response to
    /// present during the *next* cycle (`mem_valid` high with these coordinates), or `None`.
    /// Fails on an id beyond the memory, naming it; the request is then not queued.
    pub fn cycle(&mut self, request: Option<u16>) -> Result<Option<[i32; 4]>> {
        let now = self.now;
        if let Some(id) = request {
            if id as usize >= self.patches.len() {
                return Err(Error::new(format!(
                    "host memory: cycle {now}: request for patch id {id}, but the memory holds {} \
                     patches (ids 0..{})",
                    self.patches.len(),
                    self.patches.len()
                )));
            }
            self.queue.push_back((id, now));
        }
        self.now += 1;
        let Some(&(id, seen)) = self.queue.front() else {
            return Ok(None);
        };
        let start = seen.max(self.last_answer);
        if start <= now {
            self.busy += 1;
        }
        if start + self.tc != now + 1 {
            return Ok(None);
        }
        self.queue.pop_front();
        self.last_answer = now + 1;
        self.loads += 1;
        Ok(Some(self.patches[id as usize]))
    }

    /// Responses given so far.
    pub fn loads(&self) -> u64 {
        self.loads
    }

    /// Cycles the port spent serving so far (`T_c` per load once it is answered).
    pub fn busy_cycles(&self) -> u64 {
        self.busy
    }

    /// Requests queued or in service (seen, not yet answered).
    pub fn pending(&self) -> usize {
        self.queue.len()
    }
}

/// The cycles in which requests seen in cycles `requests` (non-decreasing) are answered by a
/// [`HostMemory`] with latency `tc`: `e_k = max(r_k, e_{k−1}) + tc`.
pub fn answer_cycles(requests: &[u64], tc: u64) -> Vec<u64> {
    let mut last = 0u64;
    requests
        .iter()
        .map(|&r| {
            last = r.max(last) + tc;
            last
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn memory(n: usize, tc: u32) -> HostMemory {
        let patches = (0..n as i32).map(|i| [i, i + 1, 2 * i, (7 * i) & 0x1ffff]).collect();
        HostMemory::new(patches, tc).unwrap()
    }

    /// Runs `requests` (one optional id per cycle, then idle) until everything is answered;
    /// returns (cycle, data) of every response.
    fn run(mem: &mut HostMemory, requests: &[Option<u16>]) -> Vec<(u64, [i32; 4])> {
        let mut out = vec![];
        let mut presented = None;
        let mut cycle = 0u64;
        loop {
            if let Some(d) = presented.take() {
                out.push((cycle, d));
            }
            let req = requests.get(cycle as usize).copied().flatten();
            presented = mem.cycle(req).unwrap();
            cycle += 1;
            if cycle as usize >= requests.len() && mem.pending() == 0 && presented.is_none() {
                return out;
            }
        }
    }

    #[test]
    fn isolated_request_is_answered_tc_cycles_later() {
        for tc in [1u32, 2, 3, 8] {
            let mut mem = memory(10, tc);
            let got = run(&mut mem, &[None, None, Some(7)]);
            assert_eq!(got, vec![(2 + tc as u64, mem.patch(7).unwrap())], "tc = {tc}");
            assert_eq!((mem.loads(), mem.busy_cycles(), mem.pending()), (1, tc as u64, 0));
        }
    }

    #[test]
    fn back_to_back_requests_are_answered_tc_apart_in_order() {
        for tc in [1u32, 3, 8] {
            let mut mem = memory(100, tc);
            let ids: Vec<Option<u16>> = (0..20u16).map(|i| Some((i * 37) % 100)).collect();
            let got = run(&mut mem, &ids);
            let cycles: Vec<u64> = got.iter().map(|g| g.0).collect();
            let expect: Vec<u64> = (1..=20).map(|k| k * tc as u64).collect();
            assert_eq!(cycles, expect, "tc = {tc}");
            for (k, (_, d)) in got.iter().enumerate() {
                assert_eq!(*d, mem.patch((k as u16 * 37) % 100).unwrap());
            }
            assert_eq!(mem.loads(), 20);
            assert_eq!(mem.busy_cycles(), 20 * tc as u64);
            assert_eq!(cycles, answer_cycles(&(0..20).collect::<Vec<_>>(), tc as u64));
        }
    }

    #[test]
    fn gaps_and_bursts_follow_the_answer_rule() {
        let mut mem = memory(50, 4);
        // Requests in cycles 0, 1, 2, 20, 21, 40.
        let mut req = vec![None; 41];
        for (c, id) in [(0, 1u16), (1, 2), (2, 3), (20, 4), (21, 5), (40, 6)] {
            req[c] = Some(id);
        }
        let got = run(&mut mem, &req);
        let cycles: Vec<u64> = got.iter().map(|g| g.0).collect();
        assert_eq!(cycles, vec![4, 8, 12, 24, 28, 44]);
        assert_eq!(cycles, answer_cycles(&[0, 1, 2, 20, 21, 40], 4));
        assert_eq!(mem.busy_cycles(), 6 * 4);
    }

    #[test]
    fn pending_counts_queued_and_in_service() {
        let mut mem = memory(4, 3);
        assert_eq!(mem.cycle(Some(0)).unwrap(), None);
        assert_eq!(mem.cycle(Some(1)).unwrap(), None);
        assert_eq!(mem.pending(), 2);
        assert_eq!(mem.cycle(None).unwrap(), Some(mem.patch(0).unwrap()));
        assert_eq!(mem.pending(), 1);
    }

    #[test]
    fn bad_arguments_are_errors_that_name_them() {
        let err = HostMemory::new(vec![[0; 4]], 0).unwrap_err();
        assert!(err.message().contains("T_c") && err.message().contains("tc = 0"), "{err}");
        let err = HostMemory::new(vec![[0; 4], [1, 2, 1 << 17, 3]], 1).unwrap_err();
        assert!(err.message().contains("patch 1 coordinate bx = 131072"), "{err}");
        let err = HostMemory::new(vec![[0, -1, 0, 0]], 1).unwrap_err();
        assert!(err.message().contains("ay = -1"), "{err}");
        let mut mem = memory(10, 2);
        let err = mem.cycle(Some(10)).unwrap_err();
        assert!(err.message().contains("patch id 10") && err.message().contains("10 patches"), "{err}");
        assert_eq!(mem.pending(), 0);
        let mut full = memory(1 << 16, 1);
        assert_eq!(full.cycle(Some(0xFFFF)).unwrap(), Some(full.patch(0xFFFF).unwrap()));
    }
}
