//! The valid range of every numeric parameter of the command line and of the library's entry
//! points, and the one wording of a range error ([`check_range`]), so that a limit reads the
//! same whichever command or function checks it. `CLI.md` lists the ranges per command.
//!
//! The bounds keep every accepted value away from where the arithmetic of the tracers breaks
//! (a shell depth below the rounding of the distances, a grid too fine to build) and from
//! costs that grow without bound (cycles per patch, VCD windows, workload products).

use std::fmt::Display;
use std::path::Path;

pub use crate::rays::MAX_BUNDLE_RAYS;
pub use crate::scene::COORD_LIMIT;
pub use shelling_testbench::pe::PE_RAY_MEMORY;

/// Smallest `--cells-per-segment` (λ).
pub const MIN_CELLS_PER_SEGMENT: f64 = 1e-3;
/// Largest `--cells-per-segment` (λ).
pub const MAX_CELLS_PER_SEGMENT: f64 = 1024.0;
/// Most cells of a grid (2²²): λ·N must not ask for more.
pub const MAX_GRID_CELLS: usize = 1 << 22;
/// Smallest shell depth, as a fraction of the grid's larger side (2⁻¹⁶).
pub const MIN_SHELL_DEPTH_FRACTION: f64 = 1.0 / 65536.0;
/// Largest shell depth, as a multiple of the grid's larger side.
pub const MAX_SHELL_DEPTH_FACTOR: f64 = 1024.0;
/// Most shells a sector may need across the grid (2²⁰).
pub const MAX_SHELLS: usize = 1 << 20;
/// Most segments of a generated scene (`--count`, 2²⁰).
pub const MAX_COUNT: usize = 1 << 20;
/// Largest `--tc`, host memory cycles per patch.
pub const MAX_TC: u32 = 1024;
/// Largest patch cache (`--cache`, `--cache-lines`), in patches.
pub const MAX_CACHE: u32 = shelling_hdl::cache::LINES as u32;
/// Most cycles of a VCD window (`--vcd-to` − `--vcd-from`).
pub const MAX_VCD_WINDOW: u64 = 1_000_000;
/// Most segment lengths of `figures --lengths`.
pub const MAX_LENGTHS: usize = 64;
/// Most values of `figures --tc`.
pub const MAX_TCS: usize = 16;
/// Most rays a workload traces: seeds × lengths × sources × rays (2³⁰).
pub const MAX_WORKLOAD_RAYS: u64 = 1 << 30;
/// Most segments a workload holds at once: seeds × lengths × count (2²⁴).
pub const MAX_WORKLOAD_SEGMENTS: u64 = 1 << 24;
/// Most co-simulations of `figures`: lengths × cosim sources × T_c values × 2 (2¹²).
pub const MAX_COSIM_RUNS: u64 = 1 << 12;
/// The world of generated scenes is `[0, 1024)²`: a segment length lies in `(0, 1024)`.
pub const MAX_LENGTH: f64 = 1024.0;

/// `"{option} must be between {lo} and {hi}, got {value}"` unless `lo ≤ value ≤ hi` (a NaN
/// is never in range). Every range error of the crate is worded by this function.
pub fn check_range<T: PartialOrd + Display>(option: &str, value: T, lo: T, hi: T) -> Result<T, String> {
    if lo <= value && value <= hi {
        Ok(value)
    } else {
        Err(range_message(option, &value, &lo, &hi, ""))
    }
}

/// [`check_range`] with a note on where the range comes from, e.g. `"(the scene's patches)"`.
pub fn check_range_for<T: PartialOrd + Display>(
    option: &str,
    value: T,
    lo: T,
    hi: T,
    note: &str,
) -> Result<T, String> {
    if lo <= value && value <= hi {
        Ok(value)
    } else {
        Err(range_message(option, &value, &lo, &hi, note))
    }
}

/// `"{option} must be between {lo} and {hi}{ note}, got {value}"`.
pub fn range_message(
    option: &str,
    value: &dyn Display,
    lo: &dyn Display,
    hi: &dyn Display,
    note: &str,
) -> String {
    let note = if note.is_empty() { String::new() } else { format!(" {note}") };
    format!("{option} must be between {lo} and {hi}{note}, got {value}")
}

/// A segment length of a generated scene: in the open range `(0, 1024)`.
pub fn check_length(option: &str, length: f64) -> Result<f64, String> {
    if length.is_finite() && length > 0.0 && length < MAX_LENGTH {
        Ok(length)
    } else {
        Err(format!(
            "{option} must be greater than 0 and less than {MAX_LENGTH} (the world's side), got {length}"
        ))
    }
}

/// A patch cache size: 1 to [`MAX_CACHE`] patches (a size not a power of two is the cache of the
/// next power of two with the host memory map that leaves its last lines unused:
/// `shelling_testbench::pe::MemoryMap`).
pub fn check_cache(option: &str, lines: u32) -> Result<u32, String> {
    check_range(option, lines, 1, MAX_CACHE)
}

/// `--cells-per-segment` against a scene of `segments` segments: within
/// [`MIN_CELLS_PER_SEGMENT`]..[`MAX_CELLS_PER_SEGMENT`], and λ·N at most [`MAX_GRID_CELLS`].
pub fn check_cells_per_segment(option: &str, lambda: f64, segments: usize) -> Result<f64, String> {
    check_range(option, lambda, MIN_CELLS_PER_SEGMENT, MAX_CELLS_PER_SEGMENT)?;
    let cells = lambda * segments as f64;
    if cells > MAX_GRID_CELLS as f64 {
        let most = MAX_GRID_CELLS as f64 / segments as f64;
        return Err(format!(
            "{option} {lambda} asks for {cells} grid cells for {segments} segments, more than the \
             {MAX_GRID_CELLS} a grid holds: give at most {most}"
        ));
    }
    Ok(lambda)
}

/// Smallest shell depth as a fraction of the distance `far` from the source to the farthest
/// corner of the grid (2⁻³²): shell radii keep well above the rounding of distances.
pub const MIN_SHELL_DEPTH_OF_FAR: f64 = 1.0 / 4294967296.0;

/// The range of the shell depth over a grid whose larger side is `width`, for a source whose
/// farthest grid corner lies `far` away: from the larger of `width`/2¹⁶ and `far`/2³² to
/// 1024·`width`.
/// Both ends are rounded inwards to three significant digits, so that the range reads well in
/// a message and every value it shows is accepted.
pub fn shell_depth_range(width: f64, far: f64) -> (f64, f64) {
    let lo = (width * MIN_SHELL_DEPTH_FRACTION).max(far * MIN_SHELL_DEPTH_OF_FAR);
    (three_digits(lo, true), three_digits(width * MAX_SHELL_DEPTH_FACTOR, false))
}

/// A positive `x` rounded up (`up`) or down to three significant digits.
fn three_digits(x: f64, up: bool) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return x;
    }
    let e = x.log10().floor() as i32 - 2;
    let scaled = x / 10f64.powi(e);
    let m = if up { scaled.ceil() } else { scaled.floor().max(1.0) };
    format!("{m}e{e}").parse().unwrap_or(x)
}

/// A shell depth over a grid whose larger side is `width`, for a source `far` from the
/// farthest grid corner ([`shell_depth_range`]).
pub fn check_shell_depth(option: &str, depth: f64, width: f64, far: f64) -> Result<f64, String> {
    let (lo, hi) = shell_depth_range(width, far);
    check_range_for(option, depth, lo, hi, &format!("(for this scene's grid of side {width:.1})"))
}

/// A product of options (the cost of a workload) at most `max`; `what` names the product as
/// the user sees it, e.g. `"--seeds × lengths × --sources × --rays"`.
pub fn check_product(what: &str, factors: &[u64], max: u64) -> Result<u64, String> {
    let product = factors.iter().try_fold(1u64, |p, &f| p.checked_mul(f));
    match product {
        Some(p) if p <= max => Ok(p),
        _ => {
            let shown = factors.iter().map(u64::to_string).collect::<Vec<_>>().join(" × ");
            Err(format!("{what} must be at most {max}, got {shown}"))
        }
    }
}

/// A point given on the command line (`--origin X,Y`): both coordinates within
/// ±[`COORD_LIMIT`], the range scene coordinates are held to.
pub fn check_point(option: &str, x: f64, y: f64) -> Result<(), String> {
    for v in [x, y] {
        if !(v.is_finite() && v.abs() <= COORD_LIMIT) {
            return Err(format!(
                "{option} coordinates must be between -{COORD_LIMIT} and {COORD_LIMIT} (the range of scene \
                 coordinates), got {x},{y}"
            ));
        }
    }
    Ok(())
}

/// An output file's target can be written: its directory exists and the path is not a
/// directory. Checked before any work, so that a long run does not end in an error it could
/// have given at once; `option` is named as typed.
pub fn check_output_file(option: &str, path: &Path) -> Result<(), String> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    if path.is_dir() {
        Err(format!("{option} {}: is a directory, not a file", path.display()))
    } else if !dir.is_dir() {
        Err(format!("{option} {}: the directory {} does not exist", path.display(), dir.display()))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_wording() {
        assert_eq!(
            check_range("--rays", 0usize, 1, MAX_BUNDLE_RAYS),
            Err("--rays must be between 1 and 1048576, got 0".into())
        );
        assert_eq!(check_range("--tc", 5u32, 1, MAX_TC), Ok(5));
        assert!(check_range("--x", f64::NAN, 0.0, 1.0).is_err());
        assert_eq!(check_cache("--cache", 250), Ok(250));
        assert_eq!(check_cache("--cache", 1025), Err("--cache must be between 1 and 1024, got 1025".into()));
        assert_eq!(check_cache("--cache", 1024), Ok(1024));
        assert!(check_cache("--cache", 0).is_err());
        assert!(check_product("a × b", &[u64::MAX, 2], 10).is_err());
        assert!(check_cells_per_segment("--cells-per-segment", 1024.0, 1 << 20).is_err());
        assert!(check_cells_per_segment("--cells-per-segment", 4.0, 1 << 20).is_ok());
        assert!(check_point("--origin", 2e9, 0.0).unwrap_err().contains("--origin"));
        assert_eq!(shell_depth_range(1036.68, 1000.0), (0.0159, 1060000.0));
        assert_eq!(three_digits(0.015818, true), 0.0159);
    }
}
