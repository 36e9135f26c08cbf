//! Arithmetic backends of the per-ray hit test: the golden model's `f64` ([`Arith::Float`]) and
//! the hardware's bit-true fixed point ([`Arith::Fixed`], the models of `shelling-hdl`).
//!
//! The fixed backend quantises the bundle once (`hdl/FORMATS.md`): the scene's coordinates into
//! a window of 2048 world units at 1/64 resolution, the ray directions and the source normal to
//! Q2.16. Every patch then goes through the screener's bit-true model (relative coordinates,
//! facing, the inverse-distance vector) and every ray-patch pair the tracer asks about through the
//! intersection unit's. The key `U ≈ 2²⁶/t` comes back as the distance `2²⁶/U`, which orders and
//! ties exactly as the keys do, so the tracers' nearest-hit rule (smaller `t`, then lower index)
//! is the hardware's (larger key, then lower id).
//!
//! The tracers still decide *which* pairs are tested (screening, spans, shells) in `f64`: the
//! scheduler's work stream is the same for both backends, only the answers differ.

use crate::geom::Segment;
use crate::rays::Bundle;
use crate::trace::HitTest;
use shelling_hdl::formats::PatchSetup;
use shelling_hdl::formats::{direction, key_distance, FormatError, Quantizer, ID_BITS};
use shelling_hdl::intersection::model::test;
use shelling_hdl::screener::model::{screen, BundleSetup, Patch, Verdict};

/// Which arithmetic answers the per-ray hit tests.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize, clap::ValueEnum,
)]
#[serde(rename_all = "lowercase")]
pub enum Arith {
    /// The golden model: exact predicates, `f64` distances.
    #[default]
    Float,
    /// The bit-true model of the RTL datapath (fixed point, `hdl/FORMATS.md`).
    Fixed,
}

impl std::fmt::Display for Arith {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Arith::Float => "float",
            Arith::Fixed => "fixed",
        })
    }
}

/// A bundle quantised for the fixed-point datapath: every patch's screener verdict and setup and
/// every ray's direction.
#[derive(Clone, Debug)]
pub struct FixedBundle {
    pub quantizer: Quantizer,
    /// The bundle setup of the whole bundle (its first and last rays bound the sector).
    pub setup: BundleSetup,
    /// Every patch as the host memory holds it (world coordinates quantised).
    pub patches: Vec<Patch>,
    /// Every patch's verdict under [`FixedBundle::setup`].
    pub verdicts: Vec<Verdict>,
    pub dirs: Vec<[i32; 2]>,
}

impl FixedBundle {
    /// Quantises the scene and the bundle; an error names the first value that does not fit.
    pub fn new(segments: &[Segment], bundle: &Bundle) -> Result<FixedBundle, FormatError> {
        let max = 1usize << ID_BITS;
        if segments.len() > max {
            return Err(FormatError::TooManyPatches { count: segments.len(), bits: ID_BITS, max });
        }
        let o = bundle.source.origin;
        let quantizer = Quantizer::covering(
            segments.iter().flat_map(|s| [s.a.to_array(), s.b.to_array()]).chain([o.to_array()]),
        );
        let origin = quantizer.point(|| "the ray origin".to_string(), o.to_array())?;
        let dirs = bundle
            .rays
            .iter()
            .enumerate()
            .map(|(i, r)| direction(|| format!("ray {i} direction"), r.dir.to_array()))
            .collect::<Result<Vec<_>, _>>()?;
        let normal = direction(|| "the source normal".to_string(), bundle.source.normal.to_array())?;
        let setup = BundleSetup {
            origin,
            normal,
            first: dirs.first().copied().unwrap_or_default(),
            last: dirs.last().copied().unwrap_or_default(),
        };
        let patches = segments
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let a = quantizer.point(|| format!("segment {i} endpoint a"), s.a.to_array())?;
                let b = quantizer.point(|| format!("segment {i} endpoint b"), s.b.to_array())?;
                Ok(Patch { id: i as u16, a, b })
            })
            .collect::<Result<Vec<_>, FormatError>>()?;
        let verdicts = patches.iter().map(|p| screen(&setup, p)).collect();
        Ok(FixedBundle { quantizer, setup, patches, verdicts, dirs })
    }

    /// The bundle setup of the sector of rays `rays` (non-empty): the screener's first and last
    /// ray are the sector's.
    pub fn sector_setup(&self, rays: std::ops::Range<usize>) -> BundleSetup {
        BundleSetup { first: self.dirs[rays.start], last: self.dirs[rays.end - 1], ..self.setup }
    }

    /// The set-up patch `p`, if the screener passes it.
    pub fn patch(&self, p: u32) -> Option<&PatchSetup> {
        match &self.verdicts[p as usize] {
            Verdict::Pass(s) => Some(s),
            _ => None,
        }
    }
}

impl HitTest for FixedBundle {
    const HOOKS: bool = false;

    #[inline]
    fn hit(&self, _bundle: &Bundle, i: usize, p: u32, _seg: &Segment) -> Option<f64> {
        test(self.patch(p)?, self.dirs[i]).map(key_distance)
    }
}
