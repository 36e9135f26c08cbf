//! Rung 1 in 3D: the conventional tracer through the 3D grid returns exactly the brute-force
//! tracer's nearest hit (polygon and `t`, bit for bit) for every ray, on random scenes, the closed
//! box room, the Cornell box and adversarial cases (rays through shared edges and vertices,
//! grazing rays, axis-parallel rays along cell planes, polygons through the source's plane).
//! Everything is seeded; a failure names its seed, scene, source and ray.

use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use shelling::d3::brute;
use shelling::d3::gen::{box_room, generate};
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::hemisphere::{HemisphereRays, Strata};
use shelling::d3::obj;
use shelling::d3::scene::{frame, Material3, Polygon, Scene3};
use shelling::d3::trace::{self, Bundle3, Source3, Trace3};

fn cornell() -> Scene3 {
    obj::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/cornell_box.obj")).unwrap()
}

fn params(lambda: f64) -> Grid3Params {
    Grid3Params { cells_per_polygon: lambda, cells_per_axis: None }
}

/// Traces `bundle` both ways and checks that every ray's nearest hit is the same; returns the
/// brute-force trace.
fn agree(what: &str, scene: &Scene3, grid: &Grid3, bundle: &Bundle3) -> Trace3 {
    let b = trace::brute(scene, bundle);
    let c = trace::conventional(scene, grid, bundle);
    for (i, (hb, hc)) in b.hits.iter().zip(&c.hits).enumerate() {
        assert_eq!(
            hb, hc,
            "{what}: ray {i} from {} direction {} (grid {:?}): brute {hb:?}, conventional {hc:?}",
            bundle.source.origin, bundle.directions[i], grid.n
        );
    }
    assert_eq!(b.hits.len(), bundle.len(), "{what}");
    assert_eq!(b.counters.actual_intersections, c.counters.actual_intersections, "{what}");
    assert_eq!(b.counters.adlc_true, c.counters.adlc_true, "{what}");
    // The mailbox tests a polygon at most once per ray: never more than brute force.
    assert!(c.counters.intersection_computations <= b.counters.intersection_computations, "{what}");
    assert!(c.counters.patches_read_after_screening <= c.counters.patches_read_before_screening, "{what}");
    assert!(b.hits.iter().flatten().all(|h| h.front && Some(h.polygon) != bundle.source.patch), "{what}");
    b
}

/// A random point of polygon `p` (a fan triangle from vertex 0, uniform in it).
fn point_on(p: &Polygon, rng: &mut ChaCha8Rng) -> DVec3 {
    let i = rng.random_range(1..p.vertices.len() - 1);
    let (mut u, mut v) = (rng.random::<f64>(), rng.random::<f64>());
    if u + v > 1.0 {
        (u, v) = (1.0 - u, 1.0 - v);
    }
    let (a, b, c) = (p.vertices[0], p.vertices[i], p.vertices[i + 1]);
    a + (b - a) * u + (c - a) * v
}

/// A hemisphere bundle from a random point of polygon `k`, over its front side.
fn bundle_on(scene: &Scene3, k: usize, rng: &mut ChaCha8Rng, n_theta: usize, n_phi: usize) -> Bundle3 {
    let p = &scene.polygons[k];
    let strata = if rng.random::<bool>() { Strata::Angle } else { Strata::Cosine };
    let rays = HemisphereRays::new(point_on(p, rng), p.normal, n_theta, n_phi, strata).unwrap();
    Bundle3::from_hemisphere(&rays, Some(k))
}

#[test]
fn conventional_matches_brute_on_random_scenes() {
    let cases = [
        (1u64, 200, 32.0, 4.0),
        (2, 1000, 32.0, 4.0),
        (3, 300, 100.0, 2.0),
        (4, 50, 400.0, 8.0),
        (5, 1500, 8.0, 1.0),
        (6, 100, 200.0, 16.0),
        (7, 400, 50.0, 0.5),
    ];
    for (seed, count, size, lambda) in cases {
        let scene = generate(count, size, seed).unwrap();
        let grid = Grid3::build(&scene, params(lambda)).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for s in 0..6 {
            let what = format!("seed {seed}: generate({count}, {size}) λ={lambda}, source {s}");
            let bundle = if s < 4 {
                let k = rng.random_range(0..count);
                bundle_on(&scene, k, &mut rng, 16, 8)
            } else {
                // A point of the world that lies on no patch, with a random normal.
                let o = DVec3::new(rng.random(), rng.random(), rng.random()) * 1024.0;
                let n = DVec3::new(rng.random(), rng.random(), rng.random()) - 0.5;
                let rays = HemisphereRays::new(o, n, 16, 8, Strata::Angle).unwrap();
                Bundle3::from_hemisphere(&rays, None)
            };
            agree(&what, &scene, &grid, &bundle);
        }
    }
}

#[test]
fn conventional_matches_brute_on_the_closed_box_room_and_every_ray_hits() {
    let scene = box_room();
    for (g, lambda) in [(0, 1.0), (1, 4.0), (2, 40.0)] {
        let grid = Grid3::build(&scene, params(lambda)).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(100 + g);
        for k in 0..scene.polygons.len() {
            let what = format!("seed {}: box room λ={lambda}, source on patch {k}", 100 + g);
            let b = agree(&what, &scene, &grid, &bundle_on(&scene, k, &mut rng, 12, 6));
            assert_eq!(b.counters.actual_intersections, 72, "{what}: the room is closed");
        }
    }
}

#[test]
fn conventional_matches_brute_on_the_cornell_box() {
    let scene = cornell();
    let mut rng = ChaCha8Rng::seed_from_u64(200);
    for (lambda, axis) in [(4.0, None), (1.0, Some(40)), (64.0, None)] {
        let grid =
            Grid3::build(&scene, Grid3Params { cells_per_polygon: lambda, cells_per_axis: axis }).unwrap();
        for k in 0..scene.polygons.len() {
            let what = format!("seed 200: cornell box λ={lambda} axis={axis:?}, source on face {k}");
            let bundle = bundle_on(&scene, k, &mut rng, 16, 8);
            let b = agree(&what, &scene, &grid, &bundle);
            // Where the oracle without screening meets a front side first, screening changes
            // nothing. (A ray that meets a polygon from behind first, such as one from the
            // ceiling grazing the back of the light 0.1 mm below it, goes on: screened out.)
            for (i, d) in bundle.directions.iter().enumerate() {
                let o = brute::nearest(&scene, bundle.source.origin, *d, Some(k));
                if o.is_some_and(|h| h.front) {
                    assert_eq!(o, b.hits[i], "{what}: ray {i}: screened and unscreened oracles differ");
                }
            }
        }
    }
}

/// The box room's corners of its 3 × 3 squares: every shared vertex and the midpoint of every
/// shared edge, as targets for rays.
fn room_targets() -> Vec<DVec3> {
    let scene = box_room();
    let mut out = Vec::new();
    for p in &scene.polygons {
        let n = p.vertices.len();
        for i in 0..n {
            out.push(p.vertices[i]);
            out.push((p.vertices[i] + p.vertices[(i + 1) % n]) * 0.5);
        }
    }
    out.sort_by(|a, b| a.to_array().partial_cmp(&b.to_array()).unwrap());
    out.dedup();
    out
}

#[test]
fn rays_through_shared_edges_and_vertices_of_the_box_room_hit_and_agree() {
    let scene = box_room();
    let targets = room_targets();
    let mut rng = ChaCha8Rng::seed_from_u64(300);
    for (lambda, axis) in [(4.0, None), (1.0, Some(3)), (1.0, Some(6)), (1.0, Some(9))] {
        let grid =
            Grid3::build(&scene, Grid3Params { cells_per_polygon: lambda, cells_per_axis: axis }).unwrap();
        for k in 0..scene.polygons.len() {
            let p = &scene.polygons[k];
            // Sources: a random point, the centre, and a shared vertex or edge of the patch.
            let sources = [point_on(p, &mut rng), p.centre, (p.vertices[0] + p.vertices[1]) * 0.5];
            for (s, &o) in sources.iter().enumerate() {
                let directions: Vec<DVec3> =
                    targets.iter().map(|t| *t - o).filter(|d| d.dot(p.normal) > 0.0).collect();
                let bundle = Bundle3 {
                    source: Source3 { origin: o, normal: p.normal, patch: Some(k) },
                    directions,
                    layout: None,
                };
                let what = format!("seed 300: box room λ={lambda} axis={axis:?}, patch {k} source {s}");
                let b = agree(&what, &scene, &grid, &bundle);
                assert_eq!(b.counters.actual_intersections, bundle.len() as u64, "{what}: a ray escaped");
            }
        }
    }
}

#[test]
fn axis_parallel_rays_along_shared_edges_and_cell_planes_agree() {
    let scene = box_room();
    let third = 256.0 / 3.0;
    for axis in [None, Some(3), Some(4), Some(12)] {
        let grid =
            Grid3::build(&scene, Grid3Params { cells_per_polygon: 4.0, cells_per_axis: axis }).unwrap();
        // From the floor (normal +y; the floor's squares are backward), on shared edges and vertices of its squares and on cell
        // planes of the grid, straight up and tilted in one axis only.
        let mut origins = Vec::new();
        for x in [third, 2.0 * third, 128.0, 10.0, grid.origin.x + grid.cell_size] {
            for z in [third, 2.0 * third, 128.0, 200.0, grid.origin.z + 2.0 * grid.cell_size] {
                origins.push(DVec3::new(x, 0.0, z));
            }
        }
        let directions =
            vec![DVec3::Y, DVec3::new(1.0, 1.0, 0.0), DVec3::new(0.0, 1.0, -1.0), DVec3::new(-1.0, 2.0, 0.0)];
        for (s, &o) in origins.iter().enumerate() {
            let bundle = Bundle3 {
                source: Source3 { origin: o, normal: DVec3::Y, patch: None },
                directions: directions.clone(),
                layout: None,
            };
            let what = format!("box room axis={axis:?}, floor source {s} at {o}");
            let b = agree(&what, &scene, &grid, &bundle);
            assert_eq!(b.counters.actual_intersections, directions.len() as u64, "{what}");
        }
    }
}

#[test]
fn grazing_rays_agree() {
    let mut rng = ChaCha8Rng::seed_from_u64(400);
    for (seed, scene) in [(401u64, generate(300, 64.0, 401).unwrap()), (402, box_room()), (403, cornell())] {
        let grid = Grid3::build(&scene, params(4.0)).unwrap();
        for s in 0..20 {
            let k = rng.random_range(0..scene.polygons.len());
            let p = &scene.polygons[k];
            let o = point_on(p, &mut rng);
            let (t, b) = frame(p.normal);
            let mut directions = Vec::new();
            // Nearly in the source's plane, at elevations from 1e-3 down to 1e-15.
            for e in [1e-3, 1e-6, 1e-9, 1e-12, 1e-15] {
                for i in 0..8 {
                    let a = i as f64 * std::f64::consts::TAU / 8.0 + rng.random::<f64>() * 0.1;
                    directions.push(t * a.cos() + b * a.sin() + p.normal * e);
                }
            }
            // Aimed at other polygons' vertices and edges, and within their planes.
            for _ in 0..16 {
                let q = &scene.polygons[rng.random_range(0..scene.polygons.len())];
                let v = q.vertices[rng.random_range(0..q.vertices.len())];
                let w = q.vertices[rng.random_range(0..q.vertices.len())];
                let target = v + (w - v) * rng.random::<f64>();
                let d = target - o;
                directions.push(d);
                // Projected into q's plane (grazing q exactly) and tilted off it by a hair.
                let g = d - q.normal * d.dot(q.normal);
                directions.push(g);
                directions.push(g + q.normal * (1e-10 * g.length()));
            }
            directions.retain(|d| d.dot(p.normal) > 0.0 && d.length() > 0.0);
            let bundle = Bundle3 {
                source: Source3 { origin: o, normal: p.normal, patch: Some(k) },
                directions,
                layout: None,
            };
            agree(&format!("seed {seed}: grazing, source {s} on patch {k}"), &scene, &grid, &bundle);
        }
    }
}

/// Squares through the source's plane `z = 0` (straddling it, touching it with an edge or a
/// vertex, lying in it), facing the source at the origin, plus a few random ones.
fn straddling_scene(rng: &mut ChaCha8Rng) -> Scene3 {
    let m = Material3::grey("m", 0.5, 0.0);
    let mut polygons = Vec::new();
    let mut add = |v: Vec<DVec3>| {
        if let Ok(p) = Polygon::new(v) {
            polygons.push(p.with_material(0, &m));
        }
    };
    for i in 0..24 {
        let a = i as f64 * std::f64::consts::TAU / 24.0;
        let r = 50.0 + 10.0 * (i % 5) as f64;
        let c = DVec3::new(r * a.cos(), r * a.sin(), 0.0);
        let radial = c.normalize();
        let tangent = DVec3::Z.cross(radial);
        let (z0, z1) = match i % 4 {
            0 => (-20.0, 20.0), // straddles the plane
            1 => (0.0, 30.0),   // its lower edge in the plane
            2 => (-30.0, 0.0),  // its upper edge in the plane: backward
            _ => (-5.0, 40.0),
        };
        let h = 8.0 + rng.random::<f64>() * 8.0;
        // Counter-clockwise seen from the origin: the front faces the source.
        add(vec![
            c - tangent * h + DVec3::Z * z0,
            c - tangent * h + DVec3::Z * z1,
            c + tangent * h + DVec3::Z * z1,
            c + tangent * h + DVec3::Z * z0,
        ]);
    }
    // Lying in the source's plane, and a triangle with one vertex on it.
    add(vec![DVec3::new(10.0, 10.0, 0.0), DVec3::new(30.0, 10.0, 0.0), DVec3::new(30.0, 30.0, 0.0)]);
    add(vec![DVec3::new(-20.0, -20.0, 0.0), DVec3::new(-10.0, -30.0, 25.0), DVec3::new(-30.0, -10.0, 25.0)]);
    // A ceiling facing down.
    add(vec![
        DVec3::new(-100.0, -100.0, 60.0),
        DVec3::new(-100.0, 100.0, 60.0),
        DVec3::new(100.0, 100.0, 60.0),
        DVec3::new(100.0, -100.0, 60.0),
    ]);
    Scene3 { polygons, materials: vec![m] }
}

#[test]
fn polygons_through_the_sources_plane_agree() {
    for seed in 500..506u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let scene = straddling_scene(&mut rng);
        for lambda in [1.0, 8.0, 64.0] {
            let grid = Grid3::build(&scene, params(lambda)).unwrap();
            let o = DVec3::new(rng.random::<f64>() - 0.5, rng.random::<f64>() - 0.5, 0.0) * 4.0;
            let rays = HemisphereRays::new(o, DVec3::Z, 48, 16, Strata::Angle).unwrap();
            let mut bundle = Bundle3::from_hemisphere(&rays, None);
            // Plus rays at the polygons' vertices that lie in the plane, lifted by a hair.
            for p in &scene.polygons {
                for v in &p.vertices {
                    bundle.directions.push(*v - o + DVec3::Z * 1e-9);
                }
            }
            agree(&format!("seed {seed}: straddling scene λ={lambda}"), &scene, &grid, &bundle);
        }
    }
}

/// The side of the framed world of the targeted tests below.
const FRAMED: f64 = 1000.0;

/// Two tiny triangles at the corners `0` and `FRAMED·(1, 1, 1)`: they fix the bounds, so that
/// with an explicit resolution the grid's cell planes are known before the polygons under test
/// are placed (inside the world, they do not change the layout).
fn frame_polygons() -> Vec<Polygon> {
    let tri = |c: DVec3, s: f64| Polygon::new(vec![c, c + DVec3::X * s, c + DVec3::Y * s]).unwrap();
    vec![tri(DVec3::ZERO, 1.0), tri(DVec3::splat(FRAMED), -1.0)]
}

fn framed_params() -> Grid3Params {
    Grid3Params { cells_per_polygon: 1.0, cells_per_axis: Some(10) }
}

/// The grid of the frame alone.
fn frame_grid() -> Grid3 {
    let scene = Scene3 { polygons: frame_polygons(), materials: vec![] };
    Grid3::build(&scene, framed_params()).unwrap()
}

/// `polygons` (indices from 0) plus the frame, and its grid, checked to have `layout`'s cells.
fn framed(polygons: Vec<Polygon>, layout: &Grid3) -> (Scene3, Grid3) {
    let mut polygons = polygons;
    polygons.extend(frame_polygons());
    let scene = Scene3 { polygons, materials: vec![] };
    let grid = Grid3::build(&scene, framed_params()).unwrap();
    assert_eq!((grid.origin, grid.cell_size, grid.n), (layout.origin, layout.cell_size, layout.n));
    (scene, grid)
}

/// A square of side `side` centred at `c` in the plane spanned by unit `u`, `v`, facing `u × v`.
fn square(c: DVec3, u: DVec3, v: DVec3, side: f64) -> Polygon {
    let h = side / 2.0;
    Polygon::new(vec![c - u * h - v * h, c + u * h - v * h, c + u * h + v * h, c - u * h + v * h]).unwrap()
}

#[test]
fn a_hit_just_beyond_a_cells_exit_does_not_stop_the_walk_before_a_nearer_polygon() {
    // The ray runs along +x through cell column (·, 5, 5) and crosses the cell plane x = X.
    // Polygon 1 (oblique) reaches back into cell 4 and is hit 3·eps beyond X; polygon 0 lies
    // wholly in cell 5, 2·eps beyond X, so it is nearer. Only a walk that keeps going past a hit
    // within the stopping margin of the exit finds polygon 0.
    let g = frame_grid();
    let (s, eps) = (g.cell_size, g.eps);
    let x = g.origin.x + 5.0 * s;
    let (y, z) = (g.origin.y + 5.5 * s, g.origin.z + 5.5 * s);
    let near = square(DVec3::new(x + 2.0 * eps, y, z), DVec3::Z, DVec3::Y, 0.2 * s); // faces −x
    let tilt = DVec3::new(1.0, -1.0, 0.0).normalize();
    let far = square(DVec3::new(x + 3.0 * eps, y, z), tilt, DVec3::Z, 0.4 * s); // faces (−1, −1, 0)/√2
    let (scene, grid) = framed(vec![near, far], &g);
    assert!(
        grid.cell_items(grid.index([4, 5, 5])).contains(&1)
            && !grid.cell_items(grid.index([4, 5, 5])).contains(&0)
    );
    let o = DVec3::new(g.origin.x + 4.5 * s, y, z);
    let source = Source3 { origin: o, normal: DVec3::X, patch: None };
    for k in 0..2 {
        assert_eq!(trace::screen(&source, k, &scene.polygons[k]), trace::Screen3::Pass, "polygon {k}");
    }
    let bundle = Bundle3 { source, directions: vec![DVec3::X, DVec3::new(1.0, 1e-9, -1e-9)], layout: None };
    let b = agree("stopping margin", &scene, &grid, &bundle);
    assert!(b.hits.iter().all(|h| h.is_some_and(|h| h.polygon == 0)), "{:?}", b.hits);
}

#[test]
fn hits_in_the_margin_beyond_a_sharp_vertex_are_found_in_the_next_cell() {
    // A sliver triangle (apex angle 1e-6) whose apex lies just inside cell 4 of the x axis; the
    // hit rule's inside margin (1e-9 of its size from each edge line) reaches about 0.03 beyond
    // the apex, across the cell plane x = X. A ray through that reach, in cell 5, must find it.
    let g = frame_grid();
    let s = g.cell_size;
    let x = g.origin.x + 5.0 * s;
    let (y, z) = (g.origin.y + 5.5 * s, g.origin.z + 5.5 * s);
    let (len, theta) = (30.0, 1e-6);
    let w = len * (theta / 2.0f64).tan();
    let apex = DVec3::new(x - 0.005, y, z);
    // Counter-clockwise seen from below: faces −z.
    let sliver =
        Polygon::new(vec![apex, apex + DVec3::new(-len, -w, 0.0), apex + DVec3::new(-len, w, 0.0)]).unwrap();
    assert!(sliver.normal.z < 0.0);
    let (scene, grid) = framed(vec![sliver], &g);
    let mut directions = Vec::new();
    let mut origins = Vec::new();
    for k in 0..8 {
        let beyond = 0.002 * (k + 1) as f64; // 0.002 to 0.016 past the cell plane
        origins.push(DVec3::new(x + beyond, y, z - 0.5 * s));
        directions.push(DVec3::Z);
    }
    let mut found = 0;
    for (i, (&o, &d)) in origins.iter().zip(&directions).enumerate() {
        if brute::intersect(o, d, &scene.polygons[0]).is_some() {
            found += 1;
        }
        let bundle = Bundle3 {
            source: Source3 { origin: o, normal: DVec3::Z, patch: None },
            directions: vec![d],
            layout: None,
        };
        agree(&format!("sharp vertex, ray {i}"), &scene, &grid, &bundle);
    }
    assert!(found >= 4, "the construction must put hits beyond the cell plane ({found})");
}

#[test]
fn an_almost_planar_polygons_hits_on_its_plane_are_found() {
    // A twisted quad (corners ±h off its plane, within the planarity tolerance): the hit rule
    // meets the plane through its centre, which at corner 0 lies h below the corner itself. The
    // cell plane z = Z runs between them, and corner 0 sits 10 units inside the corner of its
    // cell column: there the quad's vertices (and their hull) lie only above Z, while the hits
    // lie below it. Only a registration on the hit rule's plane lists the quad there.
    let g = frame_grid();
    let s = g.cell_size;
    let z = g.origin.z + 5.0 * s;
    let side = 300.0;
    let h = 0.4e-5 * side; // within the tolerance 1e-5 of the size (√2·side)
    let a = side / 2.0;
    let corner = DVec3::new(g.origin.x + 5.0 * s - 10.0, g.origin.y + 5.0 * s - 10.0, z + 0.5 * h);
    let c = corner + DVec3::new(a, a, -h);
    let quad = Polygon::new(vec![
        c + DVec3::new(-a, -a, h),
        c + DVec3::new(-a, a, -h),
        c + DVec3::new(a, a, h),
        c + DVec3::new(a, -a, -h),
    ])
    .unwrap(); // clockwise seen from above: faces −z
    assert!(quad.normal.z < -0.999 && (quad.centre.z - (z - 0.5 * h)).abs() < 1e-9);
    let (scene, grid) = framed(vec![quad], &g);
    let mut rng = ChaCha8Rng::seed_from_u64(600);
    for i in 0..64 {
        // From below, straight up, within 10 units of corner 0 (its cell column).
        let o = corner + DVec3::new(rng.random::<f64>() * 9.9, rng.random::<f64>() * 9.9, -10.0 - 0.5 * h);
        let bundle = Bundle3 {
            source: Source3 { origin: o, normal: DVec3::Z, patch: None },
            directions: vec![DVec3::Z],
            layout: None,
        };
        let b = agree(&format!("seed 600: twisted quad, ray {i}"), &scene, &grid, &bundle);
        let hit = b.hits[0].unwrap_or_else(|| panic!("ray {i} from {o} misses the quad"));
        assert!(o.z + hit.t < z, "ray {i}: the hit must lie below the cell plane");
    }
}
