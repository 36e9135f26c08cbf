//! Orchestration shared by the CLI, the figures and the tests: a scene with its grid, a source's
//! bundle traced by one technique, and the trace's JSON form.

use crate::arith::{Arith, FixedBundle};
use crate::geom::Vec2;
use crate::grid::{Grid, GridParams};
use crate::rays::{Bundle, RaySet, Source, SourceError};
use crate::scene::Scene;
use crate::trace::{trace, trace_with, Method, SceneView, ShellParams, TraceError, TraceResult};
use crate::workstream::{Recorder, WorkStream};
use serde::Serialize;
use shelling_hdl::formats::FormatError;

/// A scene with the grid built over it, ready to trace.
#[derive(Clone, Debug)]
pub struct GriddedScene {
    pub scene: Scene,
    pub grid: Grid,
}

impl GriddedScene {
    pub fn new(scene: Scene, params: GridParams) -> GriddedScene {
        let grid = Grid::build(&scene.segments, scene.bounds(), params);
        GriddedScene { scene, grid }
    }

    pub fn view(&self) -> SceneView<'_> {
        SceneView { segments: &self.scene.segments, grid: &self.grid }
    }

    /// The bundle of `rays` rays from the centre of patch `k`.
    pub fn patch_bundle(&self, k: usize, set: RaySet, rays: usize) -> Result<Bundle, SourceError> {
        Bundle::new(Source::from_patch(&self.scene.segments, k)?, set, rays)
    }

    /// Traces a bundle with one technique.
    pub fn trace(
        &self,
        method: Method,
        bundle: &Bundle,
        params: &ShellParams,
    ) -> Result<TraceResult, TraceError> {
        trace(method, self.view(), bundle, params)
    }

    /// Traces a bundle with one technique in the chosen arithmetic.
    pub fn trace_in(
        &self,
        arith: Arith,
        method: Method,
        bundle: &Bundle,
        params: &ShellParams,
    ) -> Result<TraceResult, RunError> {
        Ok(match arith {
            Arith::Float => self.trace(method, bundle, params)?,
            Arith::Fixed => {
                let fixed = FixedBundle::new(&self.scene.segments, bundle)?;
                trace_with(method, self.view(), bundle, params, &fixed)?
            }
        })
    }
}

/// A bundle traced in the bit-true arithmetic with its work stream recorded: what the hardware
/// is handed ([`GriddedScene::schedule`]).
#[derive(Clone, Debug)]
pub struct Scheduled {
    /// The bit-true trace (its hits are what the hardware must return).
    pub trace: TraceResult,
    pub stream: WorkStream,
    pub fixed: FixedBundle,
}

impl GriddedScene {
    /// Runs the shell scheduler of `method` on the bit-true backend and records its work stream.
    pub fn schedule(
        &self,
        method: Method,
        bundle: &Bundle,
        params: &ShellParams,
    ) -> Result<Scheduled, RunError> {
        let fixed = FixedBundle::new(&self.scene.segments, bundle)?;
        let recorder = Recorder::new(&fixed, bundle);
        let trace = trace_with(method, self.view(), bundle, params, &recorder)?;
        let stream = recorder.finish();
        Ok(Scheduled { trace, stream, fixed })
    }
}

/// What keeps a trace in a chosen arithmetic from running.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    Trace(#[from] TraceError),
    #[error("the scene does not fit the fixed-point datapath: {0}")]
    Format(#[from] FormatError),
}

/// One ray of the `trace` JSON output.
#[derive(Serialize)]
pub struct RayJson {
    pub index: usize,
    pub direction: [f64; 2],
    pub hit: Option<u32>,
    pub t: Option<f64>,
}

/// The `trace` JSON output: `{"method", "rays": [...], "counters": {...}}` plus the arithmetic,
/// the source and the shell statistics.
#[derive(Serialize)]
pub struct TraceJson {
    pub method: Method,
    pub arith: Arith,
    pub source: SourceJson,
    pub rays: Vec<RayJson>,
    pub counters: crate::counters::Counters,
    pub shell_stats: crate::trace::ShellStats,
}

#[derive(Serialize)]
pub struct SourceJson {
    pub origin: [f64; 2],
    pub normal: [f64; 2],
    pub patch: Option<u32>,
    pub ray_set: RaySet,
}

impl TraceJson {
    pub fn new(result: &TraceResult, bundle: &Bundle, arith: Arith) -> TraceJson {
        let to = |v: Vec2| [v.x, v.y];
        TraceJson {
            method: result.method,
            arith,
            source: SourceJson {
                origin: to(bundle.source.origin),
                normal: to(bundle.source.normal),
                patch: bundle.source.patch,
                ray_set: bundle.set,
            },
            rays: bundle
                .rays
                .iter()
                .zip(&result.hits)
                .enumerate()
                .map(|(index, (ray, hit))| RayJson {
                    index,
                    direction: to(ray.dir),
                    hit: hit.map(|h| h.segment),
                    t: hit.map(|h| h.t),
                })
                .collect(),
            counters: result.counters,
            shell_stats: result.stats,
        }
    }
}
