//! Stream pacing on a write/full, read/empty FIFO: every item arrives once, in order, under all
//! four pacings, and the producer never writes while the FIFO is full.

use rust_hdl::prelude::*;
use shelling_testbench::{Driver, Error, Monitor, Pacing, Result, Scoreboard, Source};

use crate::toy::Fifo;

/// Pushes `items` through the FIFO; returns how many cycles the FIFO was full.
pub fn run_fifo(drv: &mut Driver<Fifo>, items: &[u16], pacing: Pacing, seed: u64) -> Result<u64> {
    let mut src = Source::new(items.iter().copied(), pacing, seed);
    let mut mon = Monitor::new(pacing, seed);
    let mut full_cycles = 0;
    while mon.items().len() < items.len() {
        drv.drive(|u| {
            let item = src.present(!u.full.val());
            u.write.next = item.is_some();
            u.data_in.next = bits(item.copied().unwrap_or_default().into());
            u.read.next = mon.ready() && !u.empty.val();
        })?;
        let u = drv.uut();
        if u.write.val() && u.full.val() {
            return Err(Error::new(format!("cycle {}: write while full", drv.cycles())));
        }
        full_cycles += u64::from(u.full.val());
        src.accepted(u.write.val())?;
        mon.observe(drv.cycles(), !u.empty.val(), || u.data_out.val().to_u16());
        drv.tick()?;
        if drv.uut().overflow.val() || drv.uut().underflow.val() {
            return Err(Error::new(format!("cycle {}: overflow or underflow", drv.cycles())));
        }
        if drv.cycles() > 20 * items.len() as u64 {
            return Err(Error::new(format!(
                "no progress: {} of {} items out",
                mon.items().len(),
                items.len()
            )));
        }
    }
    let mut board = Scoreboard::new("fifo", seed, items.iter().copied()).with_context(pacing.to_string());
    board.check_all(mon.items().iter().map(|r| (r.cycle, r.item)))?;
    board.finish()?;
    Ok(full_cycles)
}

#[test]
fn fifo_keeps_every_item_in_order_under_all_pacings() -> Result<()> {
    let items: Vec<u16> = (0..3000u32).map(|i| (i.wrapping_mul(40503) >> 3) as u16).collect();
    for (k, pacing) in Pacing::ALL.into_iter().enumerate() {
        let seed = 0xf1f0 + k as u64;
        let mut drv = Driver::new(Fifo::default())?;
        let full_cycles = run_fifo(&mut drv, &items, pacing, seed)
            .map_err(|e| e.context(format!("seed {seed:#x}, {pacing}")))?;
        println!("{pacing}: {} cycles, FIFO full in {full_cycles}", drv.cycles());
        if pacing.backpressure && !pacing.idle {
            assert!(full_cycles > 0, "{pacing}: the FIFO never filled, `full` was not exercised");
        }
    }
    Ok(())
}
