//! Generated 3D scenes: the paper's workload lifted to 3D ([`generate`]) and the closed box room
//! ([`box_room`], shipped as `scenes/box_room.obj`).

use super::scene::{frame, Material3, Polygon, Scene3, Scene3Error, MAX_POLYGONS};
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The name that errors of the generators carry in place of a file name.
const GENERATOR_NAME: &str = "generator";

/// The side of the world cube `[0, WORLD)³` of [`generate`], the 2D workload's 1024.
pub const WORLD: f64 = 1024.0;

/// The reflectance of the generated patches (the 2D scenes' default, 0.5).
pub const PATCH_REFLECTANCE: f64 = 0.5;

/// How many placements [`generate`] tries for one patch before it gives up.
const MAX_ATTEMPTS: u64 = 1_000_000;

/// A direction uniform on the unit sphere, by rejection from the cube `[−1, 1]³` (no
/// trigonometry, so the same on every platform); points too near the centre are rejected too.
fn unit_vector(rng: &mut ChaCha8Rng) -> DVec3 {
    loop {
        let p = DVec3::new(
            2.0 * rng.random::<f64>() - 1.0,
            2.0 * rng.random::<f64>() - 1.0,
            2.0 * rng.random::<f64>() - 1.0,
        );
        let r2 = p.length_squared();
        if r2 > 1e-6 && r2 <= 1.0 {
            return p / r2.sqrt();
        }
    }
}

/// `count` random squares of side `size` inside the cube `[0, WORLD)³`, seeded: the same
/// arguments give the same scene on every machine.
///
/// Each square gets a centre uniform in the cube, a normal uniform on the sphere and an edge
/// direction uniform on the circle of the plane (both by rejection, see `unit_vector`), and is
/// drawn again until its four corners lie inside the cube. The corners are
/// `c − h·e₁ − h·e₂, c + h·e₁ − h·e₂, c + h·e₁ + h·e₂, c − h·e₁ + h·e₂` (`h = size / 2`,
/// `e₂ = n × e₁`): counter-clockwise seen from the front. Every patch has one material, `patch`,
/// of reflectance [`PATCH_REFLECTANCE`] and no emission. Errors: `count` not in
/// `1..=`[`MAX_POLYGONS`], `size` not finite or not in `(0, WORLD/√3)` (a square's diagonal fits
/// the cube in any orientation), or a patch that cannot be placed (not reached in practice).
pub fn generate(count: usize, size: f64, seed: u64) -> Result<Scene3, Scene3Error> {
    let name = GENERATOR_NAME.to_string();
    if !(1..=MAX_POLYGONS).contains(&count) {
        return Err(Scene3Error::BadParameter {
            name,
            what: "the number of patches",
            range: format!("1 to {MAX_POLYGONS}"),
            value: count.to_string(),
        });
    }
    let limit = WORLD / 3f64.sqrt();
    if !(size.is_finite() && size > 0.0 && size < limit) {
        return Err(Scene3Error::BadParameter {
            name,
            what: "the side of a patch",
            range: format!("greater than 0 and less than {limit:.3} (1024/√3)"),
            value: size.to_string(),
        });
    }
    let material = Material3::grey("patch", PATCH_REFLECTANCE, 0.0);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let h = 0.5 * size;
    let inside = |p: &DVec3| p.cmpge(DVec3::ZERO).all() && p.cmplt(DVec3::splat(WORLD)).all();
    let mut polygons = Vec::with_capacity(count);
    for patch in 0..count {
        let mut attempts = 0;
        let polygon = loop {
            if attempts == MAX_ATTEMPTS {
                return Err(Scene3Error::GeneratorStalled { name, patch, attempts });
            }
            attempts += 1;
            let c = DVec3::new(rng.random::<f64>(), rng.random::<f64>(), rng.random::<f64>()) * WORLD;
            let n = unit_vector(&mut rng);
            // An edge direction uniform on the circle of the plane, from the plane's frame.
            let (t, b) = frame(n);
            let (x, y) = loop {
                let (x, y) = (2.0 * rng.random::<f64>() - 1.0, 2.0 * rng.random::<f64>() - 1.0);
                let r2 = x * x + y * y;
                if r2 > 1e-6 && r2 <= 1.0 {
                    break (x / r2.sqrt(), y / r2.sqrt());
                }
            };
            let e1 = (t * x + b * y).normalize();
            let e2 = n.cross(e1);
            let corners =
                vec![c - h * e1 - h * e2, c + h * e1 - h * e2, c + h * e1 + h * e2, c - h * e1 + h * e2];
            if corners.iter().all(inside) {
                if let Ok(p) = Polygon::new(corners) {
                    break p;
                }
            }
        };
        polygons.push(polygon.with_material(0, &material));
    }
    Ok(Scene3 { polygons, materials: vec![material] })
}

/// The side of [`box_room`]'s cube (the 2D rooms' default 256).
pub const BOX_SIDE: f64 = 256.0;

/// Each wall of [`box_room`] is split into `BOX_SPLIT × BOX_SPLIT` equal squares.
pub const BOX_SPLIT: usize = 3;

/// The closed box room shipped as `scenes/box_room.obj`: the cube `[0, BOX_SIDE]³`, each of its
/// six walls split into [`BOX_SPLIT`]² squares facing in, y up. Material `wall` (reflectance
/// 0.5, no emission) everywhere but the middle square of the ceiling (`y = BOX_SIDE`), material
/// `light` (reflectance 0.5, emission 1). Squares share their vertices exactly, so the surface is
/// closed: [`Scene3::open_edges`] is empty. Walls in the order floor, ceiling, x = 0, x = side,
/// z = 0, z = side; squares row by row within a wall.
pub fn box_room() -> Scene3 {
    let wall = Material3::grey("wall", 0.5, 0.0);
    let light = Material3::grey("light", 0.5, 1.0);
    let n = BOX_SPLIT;
    let step = BOX_SIDE / n as f64;
    let at = |i: usize| if i == n { BOX_SIDE } else { i as f64 * step };
    // Each wall: an origin corner and two axes (u, v) with u × v pointing into the room.
    let x = DVec3::X;
    let y = DVec3::Y;
    let z = DVec3::Z;
    let s = BOX_SIDE;
    let walls: [(DVec3, DVec3, DVec3, bool); 6] = [
        (DVec3::ZERO, z, x, false),             // floor, normal +y
        (DVec3::new(0.0, s, 0.0), x, z, true),  // ceiling, normal −y
        (DVec3::ZERO, y, z, false),             // x = 0, normal +x
        (DVec3::new(s, 0.0, 0.0), z, y, false), // x = side, normal −x
        (DVec3::ZERO, x, y, false),             // z = 0, normal +z
        (DVec3::new(0.0, 0.0, s), y, x, false), // z = side, normal −z
    ];
    let mut polygons = Vec::new();
    for (origin, u, v, is_ceiling) in walls {
        for j in 0..n {
            for i in 0..n {
                let p = |a: usize, b: usize| origin + u * at(a) + v * at(b);
                let corners = vec![p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)];
                let polygon = Polygon::new(corners).expect("the box room's squares are valid");
                let is_light = is_ceiling && i == n / 2 && j == n / 2;
                polygons.push(if is_light {
                    polygon.with_material(1, &light)
                } else {
                    polygon.with_material(0, &wall)
                });
            }
        }
    }
    Scene3 { polygons, materials: vec![wall, light] }
}
