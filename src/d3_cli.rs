//! The 3D forms of `trace` and `form-factors` (CLI.md): an OBJ scene (SCENES3D.md), a source
//! polygon by index or a free origin and normal in 3D, any 3D technique. Options that belong to
//! 2D scenes only are refused by name.

use super::{print_counters, Out, TraceArgs, TuneArgs};
use anyhow::{bail, Context, Result};
use glam::DVec3;
use shelling::d3::form_factors::{self as ff3, Ff3Params};
use shelling::d3::grid::{Grid3, Grid3Params};
use shelling::d3::hemisphere::{HemisphereRays, Strata};
use shelling::d3::trace::{self as trace3, Bundle3, Method3};
use shelling::d3::{obj, Scene3, COORD_LIMIT};
use shelling::geom::Vec2;
use shelling::limits;
use shelling::radiosity::form_factors::{Entry, MAX_ORIGINS};
use shelling::rays::RaySet;
use shelling::trace::{Method, ShellParams, ShellStats};
use std::io::Read;
use std::path::Path;

/// The numbers of `--origin` or `--normal`: two in 2D, three in 3D.
#[derive(Clone, Debug, PartialEq)]
pub struct Coords(pub Vec<f64>);

/// `X,Y` or `X,Y,Z`, each a finite number.
pub fn parse_coords(s: &str) -> Result<Coords, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if !(2..=3).contains(&parts.len()) {
        return Err(format!("expected two numbers X,Y (2D) or three X,Y,Z (3D), got {s:?}"));
    }
    parts
        .iter()
        .map(|p| match p.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(format!("{p:?} is not a finite number")),
            Err(_) => Err(format!("{p:?} is not a number")),
        })
        .collect::<Result<Vec<f64>, String>>()
        .map(Coords)
}

impl Coords {
    fn text(&self) -> String {
        self.0.iter().map(f64::to_string).collect::<Vec<_>>().join(",")
    }

    /// The 2D point, or an error naming `option` when three numbers were given.
    pub fn vec2(&self, option: &str) -> Result<Vec2> {
        match self.0[..] {
            [x, y] => Ok(Vec2::new(x, y)),
            _ => bail!("{option} has three coordinates ({}) but the scene is 2D: give X,Y", self.text()),
        }
    }

    /// The 3D point, or an error naming `option` when two numbers were given.
    pub fn vec3(&self, option: &str) -> Result<DVec3> {
        match self.0[..] {
            [x, y, z] => Ok(DVec3::new(x, y, z)),
            _ => bail!("{option} has two coordinates ({}) but the scene is 3D: give X,Y,Z", self.text()),
        }
    }
}

/// Checks `--origin` (coordinates within the scenes' range) and `--normal` (finite, non-zero,
/// as many coordinates as the origin).
pub fn check_origin_normal(origin: Option<&Coords>, normal: Option<&Coords>) -> Result<()> {
    if let Some(o) = origin {
        if o.0.iter().any(|v| !(v.is_finite() && v.abs() <= COORD_LIMIT)) {
            bail!(
                "--origin coordinates must be between -{COORD_LIMIT} and {COORD_LIMIT} (the range of scene \
                 coordinates), got {}",
                o.text()
            );
        }
    }
    if let Some(n) = normal {
        let len = n.0.iter().map(|v| v * v).sum::<f64>().sqrt();
        if !(len.is_finite() && len > 0.0) {
            bail!("--normal must be a finite, non-zero vector, got {}", n.text());
        }
        if let Some(o) = origin.filter(|o| o.0.len() != n.0.len()) {
            bail!("--origin {} and --normal {} must have as many coordinates", o.text(), n.text());
        }
    }
    Ok(())
}

/// A technique's name as typed, resolved against the scene's dimension.
#[derive(Clone, Debug, PartialEq)]
pub struct MethodArg(pub String);

/// Any 2D or 3D technique's name.
pub fn parse_method(s: &str) -> Result<MethodArg, String> {
    let known = || Method::ALL.iter().map(|m| m.name()).chain(Method3::ALL.iter().map(|m| m.name()));
    if known().any(|n| n == s) {
        return Ok(MethodArg(s.to_string()));
    }
    Err(format!("unknown technique {s:?}: 2D {}; 3D {}", two_d_names(), three_d_names()))
}

fn two_d_names() -> String {
    Method::ALL.iter().map(|m| m.name()).collect::<Vec<_>>().join(", ")
}

fn three_d_names() -> String {
    Method3::ALL.iter().map(|m| m.name()).collect::<Vec<_>>().join(", ")
}

impl MethodArg {
    /// The 2D technique named, or `default`; a 3D-only name is an error.
    pub fn two_d(arg: Option<&MethodArg>, default: Method) -> Result<Method> {
        let Some(MethodArg(name)) = arg else { return Ok(default) };
        match Method::ALL.iter().find(|m| m.name() == name) {
            Some(&m) => Ok(m),
            None => bail!("--method {name} is a 3D technique but the scene is 2D: use {}", two_d_names()),
        }
    }

    /// The 3D technique named, or `default`; a 2D-only name is an error.
    pub fn three_d(arg: Option<&MethodArg>, default: Method3) -> Result<Method3> {
        let Some(MethodArg(name)) = arg else { return Ok(default) };
        match Method3::ALL.iter().find(|m| m.name() == name) {
            Some(&m) => Ok(m),
            None => bail!("--method {name} belongs to 2D scenes; the 3D techniques are {}", three_d_names()),
        }
    }
}

/// Whether the scene file at `path` is a 3D (OBJ) scene: a `.obj` name, a `.json` name is 2D,
/// and any other file is 2D when its first non-blank character is `{` (JSON), 3D otherwise.
pub fn is_3d(path: &Path) -> Result<bool> {
    match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
        Some("obj") => return Ok(true),
        Some("json") => return Ok(false),
        _ => {}
    }
    let mut head = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(4096).read_to_end(&mut head))
        .with_context(|| format!("{}: cannot read the file", path.display()))?;
    Ok(head.iter().find(|b| !b.is_ascii_whitespace()) != Some(&b'{'))
}

/// The 2D-only options among the grid and shell options: `--shell-depth` and `--max-sector`
/// (the 3D tracers build no shells). `--cells-per-segment` is the 3D grid's λ, cells per polygon.
fn check_tune(tune: &TuneArgs) -> Result<()> {
    let given = [("--shell-depth", tune.shell_depth.is_some()), ("--max-sector", tune.max_sector.is_some())];
    if let Some((option, _)) = given.iter().find(|(_, g)| *g) {
        bail!("{option} belongs to 2D scenes (the shells of the 2D shelling techniques)");
    }
    Ok(())
}

/// The shell parameters of the 3D tracers: the defaults with `--phi-cells` (checked).
pub fn polar_params(tune: &TuneArgs) -> Result<ShellParams> {
    let phi_cells = tune.phi_cells.unwrap_or(ShellParams::default().phi_cells);
    limits::check_range("--phi-cells", phi_cells, 1, limits::MAX_BUNDLE_RAYS).map_err(anyhow::Error::msg)?;
    Ok(ShellParams { phi_cells, ..ShellParams::default() })
}

/// Loads the OBJ scene and builds its grid (`--cells-per-segment` as λ, checked as in 2D).
pub fn load(path: &Path, tune: &TuneArgs) -> Result<(Scene3, Grid3)> {
    check_tune(tune)?;
    let scene = obj::load(path)?;
    limits::check_cells_per_segment("--cells-per-segment", tune.cells_per_segment, scene.polygons.len())
        .map_err(anyhow::Error::msg)?;
    let grid =
        Grid3::build(&scene, Grid3Params { cells_per_polygon: tune.cells_per_segment, cells_per_axis: None })
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    Ok((scene, grid))
}

/// `--source K` within the scene's polygons.
fn check_source(k: usize, scene: &Scene3) -> Result<()> {
    let n = scene.polygons.len();
    limits::check_range_for("--source", k, 0, n - 1, &format!("(the scene has {n} polygons)"))
        .map_err(anyhow::Error::msg)?;
    Ok(())
}

/// The hemisphere set of `--ray-set`: `sine` is the cosine-weighted set.
pub fn strata(set: RaySet) -> Strata {
    match set {
        RaySet::Angle => Strata::Angle,
        RaySet::Sine => Strata::Cosine,
    }
}

#[derive(serde::Serialize)]
struct SourceJson {
    origin: [f64; 3],
    normal: [f64; 3],
    patch: Option<usize>,
    ray_set: RaySet,
    n_theta: usize,
    n_phi: usize,
}

#[derive(serde::Serialize)]
struct RayJson {
    index: usize,
    direction: [f64; 3],
    hit: Option<usize>,
    t: Option<f64>,
}

/// `trace`'s JSON in 3D: the 2D shape (`method`, `arith`, `source`, `rays`, `counters`,
/// `shell_stats`) with three coordinates.
#[derive(serde::Serialize)]
struct TraceJson {
    method: &'static str,
    arith: &'static str,
    source: SourceJson,
    rays: Vec<RayJson>,
    counters: shelling::counters::Counters,
    shell_stats: ShellStats,
}

/// `trace` on an OBJ scene.
pub fn trace_cmd(a: &TraceArgs) -> Result<()> {
    if a.arith != shelling::arith::Arith::Float {
        bail!("--arith {} belongs to 2D scenes (the RTL datapath's fixed point is 2D)", a.arith);
    }
    let method = MethodArg::three_d(a.method.as_ref(), Method3::Conventional)?;
    let (n_theta, n_phi) = ff3::split_rays(a.from.rays)?;
    let (scene, grid) = load(&a.from.scene, &a.tune)?;
    let (origin, normal, patch) = match (a.from.source, &a.from.origin, &a.from.normal) {
        (Some(k), _, _) => {
            check_source(k, &scene)?;
            let p = &scene.polygons[k];
            (p.centre, p.normal, Some(k))
        }
        (None, Some(o), Some(n)) => (o.vec3("--origin")?, n.vec3("--normal")?, None),
        _ => bail!("give either --source K or both --origin X,Y,Z and --normal NX,NY,NZ"),
    };
    let set = HemisphereRays::new(origin, normal, n_theta, n_phi, strata(a.from.ray_set))?;
    let bundle = Bundle3::from_hemisphere(&set, patch);
    let result = trace3::trace(method, &scene, &grid, &bundle, &polar_params(&a.tune)?)?;
    let mut out = Out::new();
    if a.json {
        let json = TraceJson {
            method: method.name(),
            arith: "float",
            source: SourceJson {
                origin: set.origin.to_array(),
                normal: set.normal.to_array(),
                patch,
                ray_set: a.from.ray_set,
                n_theta,
                n_phi,
            },
            rays: set
                .rays
                .iter()
                .zip(&result.hits)
                .enumerate()
                .map(|(index, (ray, hit))| RayJson {
                    index,
                    direction: ray.direction.to_array(),
                    hit: hit.map(|h| h.polygon),
                    t: hit.map(|h| h.t),
                })
                .collect(),
            counters: result.counters,
            shell_stats: ShellStats::default(),
        };
        say!(out, "{}", serde_json::to_string_pretty(&json).context("serialising the trace")?);
    } else {
        let hits = result.hits.iter().flatten().count();
        say!(
            out,
            "{} rays ({n_theta} × {n_phi}) from ({:.3}, {:.3}, {:.3}) traced with {method}: {} hit a polygon, {} escaped",
            bundle.len(),
            origin.x,
            origin.y,
            origin.z,
            hits,
            bundle.len() - hits
        );
        print_counters(&mut out, &[(method.name(), result.counters)])?;
    }
    out.flush()
}

/// What `form-factors` on an OBJ scene needs of its options.
pub struct FormFactors3<'a> {
    pub scene: &'a Path,
    pub source: Option<usize>,
    pub origin: Option<&'a Coords>,
    pub normal: Option<&'a Coords>,
    pub rays: Option<usize>,
    pub origins: Option<usize>,
    pub ray_set: RaySet,
    pub method: Option<&'a MethodArg>,
    pub json: bool,
    pub tune: &'a TuneArgs,
}

#[derive(serde::Serialize)]
struct RowJson<'a> {
    source: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    origin: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal: Option<[f64; 3]>,
    rays: usize,
    origins: usize,
    ray_set: RaySet,
    method: &'static str,
    arith: &'static str,
    #[serde(rename = "form_factors")]
    entries: &'a [Entry],
    sum: f64,
}

/// `form-factors` on an OBJ scene: the row of `--source K` (M origins over the polygon), or the
/// differential form factors of a free `--origin` and `--normal` (one origin, nothing excluded).
pub fn form_factors_cmd(a: FormFactors3) -> Result<()> {
    let method = MethodArg::three_d(a.method, Method3::Conventional)?;
    let rays = a.rays.unwrap_or(ff3::DEFAULT_RAYS);
    limits::check_range("--rays", rays, 1, shelling::d3::hemisphere::MAX_HEMISPHERE_RAYS)
        .map_err(anyhow::Error::msg)?;
    if let Some(m) = a.origins {
        if a.source.is_none() {
            bail!("--origins belongs to --source (a free --origin is one point)");
        }
        limits::check_range("--origins", m, 1, MAX_ORIGINS).map_err(anyhow::Error::msg)?;
    }
    check_origin_normal(a.origin, a.normal)?;
    let (scene, grid) = load(a.scene, a.tune)?;
    let params = Ff3Params {
        rays,
        origins: a.origins.unwrap_or(ff3::DEFAULT_ORIGINS),
        strata: strata(a.ray_set),
        method,
        shells: polar_params(a.tune)?,
        ..Ff3Params::default()
    };
    let (row, free) = match (a.source, a.origin, a.normal) {
        (Some(k), _, _) => {
            check_source(k, &scene)?;
            (ff3::row(&scene, &grid, k, &params)?, None)
        }
        (None, Some(o), Some(n)) => {
            let (origin, normal) = (o.vec3("--origin")?, n.vec3("--normal")?);
            (ff3::point_row(&scene, &grid, origin, normal, &params)?, Some((origin, normal)))
        }
        _ => bail!("give either --source K or both --origin X,Y,Z and --normal NX,NY,NZ"),
    };
    let origins = if free.is_some() { 1 } else { params.origins };
    let mut out = Out::new();
    if a.json {
        let json = RowJson {
            source: a.source,
            origin: free.map(|f| f.0.to_array()),
            normal: free.map(|f| f.1.normalize().to_array()),
            rays,
            origins,
            ray_set: a.ray_set,
            method: method.name(),
            arith: "float",
            entries: &row.entries,
            sum: row.sum(),
        };
        say!(out, "{}", serde_json::to_string_pretty(&json)?);
        return out.flush();
    }
    let from = match (a.source, free) {
        (Some(k), _) => format!("polygon {k}"),
        (None, Some((o, _))) => format!("the point ({}, {}, {})", o.x, o.y, o.z),
        _ => unreachable!("one of --source and --origin was checked above"),
    };
    say!(
        out,
        "form factors from {from} ({origins} origins × {rays} {} rays, {method}): {} polygons seen, sum {:.6}",
        a.ray_set,
        row.entries.len(),
        row.sum()
    );
    let mut top = row.entries.clone();
    top.sort_by(|x, y| y.ff.total_cmp(&x.ff));
    say!(out, "{:>8}{:>14}", "polygon", "F");
    for e in top.iter().take(10) {
        say!(out, "{:>8}{:>14.6}", e.patch, e.ff);
    }
    out.flush()
}
