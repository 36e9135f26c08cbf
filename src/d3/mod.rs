//! Shelling in 3D: scenes of convex planar polygons, the hemisphere ray sets shot from a point
//! on them, the 3D grid with macro-regions and four tracers: brute force, the conventional
//! technique and the paper's two extensions, polar and sweep. `shelling scene gen --dim 3` (in
//! `main.rs`) writes the 3D workload, and `shelling figures --dim 3` measures it
//! (`crate::figures::d3`).
//!
//! Everything else in the crate is 2D (segments in the plane); this module tree is its 3D
//! counterpart, built with `glam`'s [`DVec3`](glam::DVec3):
//!
//! * [`scene`]: the types ([`Scene3`], [`Polygon`], [`Material3`]), the rules of a valid polygon
//!   (convex, planar, non-degenerate, finite, within [`COORD_LIMIT`]) and the errors
//!   ([`Scene3Error`], [`PolygonProblem`]).
//! * [`obj`]: the Wavefront OBJ + MTL loader (through the `tobj` crate, faces kept as polygons)
//!   and the writer, so that generated scenes round-trip.
//! * [`gen`]: the seeded generator of the paper's workload lifted to 3D (random squares) and the
//!   closed box room shipped as `scenes/box_room.obj`.
//! * [`hemisphere`]: the ray sets over a point with a unit normal, stratified in Def. 2.5's
//!   angles (Θ, Φ), with solid-angle form-factor weights or the cosine-weighted (Nusselt) set.
//! * [`brute`]: the brute-force ray–convex-polygon intersection, the 3D oracle.
//! * [`grid`]: the uniform 3D grid with macro-regions (issue 18 part 3), and [`walk`], its 3D-DDA
//!   traversal.
//! * [`trace`]: the tracers' entry point ([`trace::trace`], [`trace::Method3`]), the brute-force
//!   and conventional 3D tracers with backface screening and the paper's counters.
//! * [`polar`]: the direct extension (sectors in (Θ, Φ), shells of constant depth, tracking S),
//!   with [`span`], a polygon's spanning angles computed exactly.
//! * [`sweep`]: the sweep-plane extension, each plane a 2D scene traced by the 2D deterministic
//!   tracer with hits decided in 3D.
//! * [`form_factors`]: the 3D form factors `F_ij` of a polygon's row from cosine-weighted
//!   hemisphere sets shot from `M` origins spread over it, by any tracer (issue 18 part 6).
//! * [`radiosity`]: the 2D solvers on those rows, once per colour channel (`Kd`, `Ke`).
//!
//! Conventions, the errors and the shipped scenes are documented in `SCENES3D.md`.

pub mod brute;
pub mod form_factors;
pub mod gen;
pub mod grid;
pub mod hemisphere;
pub mod obj;
pub mod on_pe;
pub mod polar;
pub mod radiosity;
pub mod scene;
pub mod span;
pub mod sweep;
pub mod trace;
pub mod walk;

pub use scene::{Material3, Polygon, PolygonProblem, Scene3, Scene3Error, COORD_LIMIT};
