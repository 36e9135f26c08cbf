//! The random scene generator of the paper's experiments: [`generate`].

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::{check_world, Bounds, Material, Scene, SceneError, MAX_SEGMENTS};
use crate::geom::{Segment, Vec2};

/// The name that errors of [`generate`] carry in place of a file name.
const GENERATOR_NAME: &str = "generator";

/// How many placements [`generate`] tries for one segment before it gives up. With a length
/// shorter than the world's shorter side at least a few percent of the tries succeed, so this is
/// reached only when the world is too small for the precision of `f64`.
const MAX_ATTEMPTS: u64 = 1_000_000;

/// Generates `count` random segments of length `length` with both endpoints inside `world`.
///
/// Each segment gets a midpoint drawn uniformly in the world and a direction drawn uniformly on
/// the circle (by rejection from the square, so no trigonometry is involved), and is drawn again
/// until both endpoints lie inside the world. The result is a function of the arguments alone,
/// on every platform. Errors carry the name `generator`: `count` is 0 or above
/// [`MAX_SEGMENTS`], `world` is not a valid world, or `length` is not finite, not positive, or
/// not shorter than the shorter side of the world.
pub fn generate(count: usize, length: f64, seed: u64, world: Bounds) -> Result<Scene, SceneError> {
    let name = GENERATOR_NAME;
    check_world(name, &world)?;
    if count == 0 {
        return Err(SceneError::NoSegments { name: name.to_string() });
    }
    if count > MAX_SEGMENTS {
        return Err(SceneError::TooManySegments { name: name.to_string(), count });
    }
    let size = world.size();
    let limit = size.x.min(size.y);
    if !(length.is_finite() && length > 0.0 && length < limit) {
        return Err(SceneError::InvalidLength { name: name.to_string(), length, limit });
    }

    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let half = 0.5 * length;
    let mut segments = Vec::with_capacity(count.min(1 << 20));
    for index in 0..count {
        let mut attempts = 0;
        let segment = loop {
            if attempts == MAX_ATTEMPTS {
                return Err(SceneError::GeneratorStalled {
                    name: name.to_string(),
                    segment: index,
                    length,
                    world,
                    attempts,
                });
            }
            attempts += 1;
            // Four draws per attempt, used or not, so the stream stays simple to reason about.
            let mx = world.min.x + size.x * rng.random::<f64>();
            let my = world.min.y + size.y * rng.random::<f64>();
            let dx = 2.0 * rng.random::<f64>() - 1.0;
            let dy = 2.0 * rng.random::<f64>() - 1.0;
            // A point uniform in the unit disk (away from its centre, where normalising would
            // lose precision) gives a direction uniform on the circle.
            let r2 = dx * dx + dy * dy;
            if !(r2 > 1e-6 && r2 <= 1.0) {
                continue;
            }
            let r = r2.sqrt();
            let (ux, uy) = (dx / r, dy / r);
            let a = Vec2::new(mx - ux * half, my - uy * half);
            let b = Vec2::new(mx + ux * half, my + uy * half);
            let seg = Segment::new(a, b);
            // The length test fails only in worlds too small for f64 to place the endpoints.
            if world.contains(a) && world.contains(b) && (seg.length() - length).abs() <= 1e-9 * length {
                break seg;
            }
        };
        segments.push(segment);
    }
    Ok(Scene { materials: vec![Material::default(); segments.len()], segments, world: Some(world) })
}
