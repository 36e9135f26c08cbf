//! Tier 2: `figures/stalls.md`, where the PE's cycles go (`shelling::figures::stalls`),
//! recomputed on rust-hdl's simulation and compared with the committed file (the cycles are
//! exact, so any change to the RTL, the scheduler or the host's commands shows).
//! `SHELLING_BLESS=1` rewrites the file instead.

#[test]
fn the_committed_stall_table_is_that_of_the_current_code() {
    let table = shelling::figures::stalls::committed_table().unwrap_or_else(|e| panic!("{e}"));
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/figures/stalls.md");
    if std::env::var_os("SHELLING_BLESS").is_some() {
        std::fs::write(path, &table).unwrap();
        return;
    }
    let old = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    assert!(
        old == table,
        "figures/stalls.md is stale: run SHELLING_BLESS=1 cargo test --release --features tier2 --test tier2 stalls"
    );
}
