//! Radiosity in flatland: what the tracers are for.
//!
//! * [`form_factors`]: the form factors `F_ij` of a patch's row from the bundles of `M`
//!   stratified origins along it, by any technique in either arithmetic;
//! * [`solve`]: progressive refinement and a full Gauss–Seidel solve;
//! * [`matrix`]: the versioned form-factor matrix file, its slices and their merge;
//! * [`on_pe`]: rows computed on the RTL processing element, with its cycles;
//! * [`svg`]: the picture of a solve.
//!
//! Closed rooms to solve come from [`crate::scene::room`]. RADIOSITY.md documents the method,
//! the error of the estimates and the commands.

pub mod form_factors;
pub mod matrix;
pub mod on_pe;
pub mod solve;
pub mod svg;

pub use form_factors::{FfError, FfParams, Row};
pub use solve::{Solution, SolveError, Surfaces};
