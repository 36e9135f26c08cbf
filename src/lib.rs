//! # shelling
//!
//! A hardware/software co-design kit for the *shelling* space partitioning of Shen, Deprettere
//! and Dewilde (EGGH 1990): form-factor ray casting of the radiosity method mapped onto a
//! pipelined intersection architecture.
//!
//! This crate is the golden model and the experiments: scenes ([`scene`]), ray bundles
//! ([`rays`]), the grid with macro-regions ([`grid`]), the four tracers ([`trace`]) with the
//! paper's counters ([`counters`]), the analytic model of Section 4 ([`model`]) the
//! reproduction of Section 5's figures ([`figures`]) and the radiosity method the paper serves
//! ([`radiosity`]: form factors and solvers). [`arith`] swaps the golden `f64` hit test
//! for the bit-true fixed-point model of the RTL (`shelling-hdl`). See `ARCHITECTURE.md` for the data flow.

pub mod agreement;
pub mod arith;
pub mod cosim;
pub mod counters;
pub mod d3;
pub mod figures;
pub mod geom;
pub mod grid;
pub mod limits;
pub mod machine;
pub mod model;
pub mod radiosity;
pub mod rays;
pub mod run;
pub mod scene;
pub mod staged;
pub mod trace;
pub mod workstream;
