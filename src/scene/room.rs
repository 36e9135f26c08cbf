//! The closed-room generator of the radiosity experiments: [`room`].
//!
//! A room is the rectangle `[0, width] × [0, height]`, its four walls split into patches of
//! equal length no longer than the requested patch length, front sides facing in (the walls run
//! counter-clockwise, so the inside is on their left). Optionally `boxes` square boxes stand
//! inside, placed at random (seeded) without touching each other or the walls, their sides split
//! the same way, front sides facing out. The `lights` patches of the ceiling (the top wall)
//! nearest its middle emit; every patch reflects `reflectance`. Every ray from a point of a wall
//! or a box side hits a patch, so the form factors of every patch sum to 1.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::{Material, Scene, SceneError};
use crate::geom::{Segment, Vec2};

/// What [`room`] builds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoomSpec {
    /// Inner width of the room, in world units.
    pub width: f64,
    /// Inner height of the room.
    pub height: f64,
    /// Longest patch: every wall and box side is split into equal patches no longer than this.
    pub patch_length: f64,
    /// Square boxes inside the room.
    pub boxes: usize,
    /// Side of each box.
    pub box_size: f64,
    /// Emissive patches, the ones of the ceiling nearest its middle.
    pub lights: usize,
    /// Emission (radiant exitance) of each light.
    pub emission: f64,
    /// Reflectance of every patch.
    pub reflectance: f64,
    /// Seed of the box placement.
    pub seed: u64,
}

impl Default for RoomSpec {
    /// The default room of the radiosity experiments: 256 × 256 with patches of 8 (128 wall
    /// patches), two boxes of side 48 (48 patches), two lights of emission 1, reflectance 0.5.
    fn default() -> Self {
        RoomSpec {
            width: 256.0,
            height: 256.0,
            patch_length: 8.0,
            boxes: 2,
            box_size: 48.0,
            lights: 2,
            emission: 1.0,
            reflectance: 0.5,
            seed: 7,
        }
    }
}

/// The most patches a room may have (a scene of this size traces in seconds per row).
pub const MAX_ROOM_PATCHES: usize = 1 << 20;

/// How many positions [`room`] draws for one box before it gives up.
const MAX_ATTEMPTS: u32 = 10_000;

/// What is wrong with a room request.
#[derive(Debug, thiserror::Error)]
pub enum RoomError {
    #[error("{option} must be {range}, got {value}")]
    OutOfRange { option: &'static str, range: String, value: f64 },
    #[error(
        "the room would have {count} patches, more than {MAX_ROOM_PATCHES}: choose a longer --patch-length"
    )]
    TooManyPatches { count: usize },
    #[error("box {index} of side {size} found no free place in the {width} × {height} room after {MAX_ATTEMPTS} tries: choose fewer or smaller boxes")]
    NoRoomForBox { index: usize, size: f64, width: f64, height: f64 },
    #[error(transparent)]
    Scene(#[from] SceneError),
}

/// Builds the room of `spec`; see the module documentation.
pub fn room(spec: &RoomSpec) -> Result<Scene, RoomError> {
    let range = |option, value: f64, ok: bool, range: &str| {
        if ok {
            Ok(())
        } else {
            Err(RoomError::OutOfRange { option, range: range.to_string(), value })
        }
    };
    let RoomSpec { width, height, patch_length: pl, boxes, box_size, lights, emission, reflectance, seed } =
        *spec;
    let finite_pos = |v: f64| v.is_finite() && v > 0.0 && v <= 1e6;
    range("--width", width, finite_pos(width), "a positive number up to 1e6")?;
    range("--height", height, finite_pos(height), "a positive number up to 1e6")?;
    range(
        "--patch-length",
        pl,
        finite_pos(pl) && pl <= width.min(height),
        "positive and at most the shorter side of the room",
    )?;
    range("--emission", emission, emission.is_finite() && emission > 0.0, "a positive number")?;
    range("--reflectance", reflectance, (0.0..1.0).contains(&reflectance), "in [0, 1)")?;
    if boxes > 0 {
        range(
            "--box-size",
            box_size,
            finite_pos(box_size) && box_size < width.min(height) / 2.0,
            "positive and less than half the shorter side of the room",
        )?;
    }
    let splits = |len: f64| ((len / pl).ceil() as usize).max(1);
    let ceiling = splits(width);
    range(
        "--lights",
        lights as f64,
        (1..=ceiling).contains(&lights),
        &format!("between 1 and {ceiling} (the ceiling's patches)"),
    )?;
    let count = 2 * (splits(width) + splits(height)) + boxes * 4 * splits(box_size);
    if count > MAX_ROOM_PATCHES {
        return Err(RoomError::TooManyPatches { count });
    }

    let mut segments = Vec::with_capacity(count);
    // The walls, counter-clockwise from the origin: floor, right wall, ceiling, left wall.
    let corners =
        [Vec2::new(0.0, 0.0), Vec2::new(width, 0.0), Vec2::new(width, height), Vec2::new(0.0, height)];
    let ceiling_start = splits(width) + splits(height);
    let (nw, nh) = (splits(width), splits(height));
    polygon(&corners, &[nw, nh, nw, nh], &mut segments);
    // The boxes: clockwise, so that their front sides face out.
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let gap = pl.max(box_size / 4.0);
    let mut placed: Vec<Vec2> = Vec::with_capacity(boxes);
    for index in 0..boxes {
        let free = |p: Vec2, placed: &[Vec2]| {
            placed.iter().all(|q| (p.x - q.x).abs() >= box_size + gap || (p.y - q.y).abs() >= box_size + gap)
        };
        let (lo_x, lo_y) = (gap, gap);
        let (hi_x, hi_y) = (width - gap - box_size, height - gap - box_size);
        let mut attempts = 0;
        let corner = loop {
            if attempts == MAX_ATTEMPTS || hi_x <= lo_x || hi_y <= lo_y {
                return Err(RoomError::NoRoomForBox { index, size: box_size, width, height });
            }
            attempts += 1;
            let p = Vec2::new(
                lo_x + (hi_x - lo_x) * rng.random::<f64>(),
                lo_y + (hi_y - lo_y) * rng.random::<f64>(),
            );
            if free(p, &placed) {
                break p;
            }
        };
        placed.push(corner);
        let s = box_size;
        let c = corner;
        polygon(
            &[c, Vec2::new(c.x, c.y + s), Vec2::new(c.x + s, c.y + s), Vec2::new(c.x + s, c.y)],
            &[splits(box_size); 4],
            &mut segments,
        );
    }
    let mut materials = vec![Material { reflectance: Some(reflectance), emission: None }; segments.len()];
    // The lights: the ceiling's patches nearest its middle (the ceiling runs right to left).
    let first = ceiling_start + (ceiling - lights) / 2;
    for m in &mut materials[first..first + lights] {
        m.emission = Some(emission);
    }
    let scene = Scene { segments, materials, world: None };
    scene.validate("room")?;
    Ok(scene)
}

/// Appends the closed polygon through `corners` (in order, back to the first), side `k` split
/// into `counts[k]` equal patches.
fn polygon(corners: &[Vec2], counts: &[usize], out: &mut Vec<Segment>) {
    for (k, &a) in corners.iter().enumerate() {
        let b = corners[(k + 1) % corners.len()];
        let n = counts[k];
        let point = |i: usize| if i == n { b } else { a + (b - a) * (i as f64 / n as f64) };
        out.extend((0..n).map(|i| Segment::new(point(i), point(i + 1))));
    }
}
