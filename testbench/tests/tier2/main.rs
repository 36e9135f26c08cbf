//! Tier 2 of the block tests (`cargo test --release --workspace --features tier2 --test tier2`): the
//! formal tasks, which take minutes each.

mod formal;
