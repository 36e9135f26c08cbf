//! `shelling scene gen --dim 3`: the 3D generator on the command line.
//!
//! The binary's `main` calls [`intercept`] before it parses its own arguments: `scene gen` with
//! `--dim 3` is run here; `--dim 2` (the default) is removed and the rest goes on to the 2D
//! `scene gen`. This keeps the 3D options out of the 2D parser until the two are merged.
//!
//! ```text
//! shelling scene gen --dim 3 --count N --size L --seed S --out FILE.obj
//! ```
//!
//! writes `FILE.obj` and `FILE.mtl` ([`super::gen::generate`], [`super::obj::save`]).

use super::gen;
use super::obj;
use clap::Parser;
use std::ffi::OsString;
use std::path::PathBuf;
use std::process::ExitCode;

/// `scene gen --dim 3`: N random squares of side L in [0, 1024)³, seeded (SCENES3D.md).
#[derive(Parser, Debug)]
#[command(name = "shelling scene gen --dim 3", bin_name = "shelling scene gen")]
struct Gen3 {
    /// The dimension: 3 here (2 is the 2D `scene gen`).
    #[arg(long)]
    dim: u8,
    /// Number of patches, 1 to 1048576.
    #[arg(long, default_value_t = 1000, allow_negative_numbers = true)]
    count: usize,
    /// Side of every square patch: greater than 0, less than 1024/√3.
    #[arg(long, default_value_t = 32.0, allow_negative_numbers = true)]
    size: f64,
    /// Seed of the random generator: the same seed gives the same scene on every machine.
    #[arg(long, default_value_t = 7)]
    seed: u64,
    /// Output OBJ file; the MTL file is written beside it with the extension .mtl.
    #[arg(long)]
    out: PathBuf,
}

/// The value of `--dim` in `args` and the positions of the tokens that give it.
fn find_dim(args: &[OsString]) -> Option<(String, Vec<usize>)> {
    for (i, a) in args.iter().enumerate() {
        let a = a.to_string_lossy();
        if a == "--" {
            return None;
        }
        if a == "--dim" {
            let value = args.get(i + 1).map(|v| v.to_string_lossy().into_owned()).unwrap_or_default();
            return Some((value, vec![i, i + 1]));
        }
        if let Some(v) = a.strip_prefix("--dim=") {
            return Some((v.to_string(), vec![i]));
        }
    }
    None
}

/// Runs `scene gen --dim 3` from the process's arguments and returns its exit code, or returns
/// the arguments for the 2D parser (without `--dim 2`).
pub fn intercept() -> Result<Vec<OsString>, ExitCode> {
    intercept_from(std::env::args_os().collect())
}

/// [`intercept`] on given arguments (the program name first).
pub fn intercept_from(mut args: Vec<OsString>) -> Result<Vec<OsString>, ExitCode> {
    let is_gen = args.len() >= 3 && args[1] == "scene" && args[2] == "gen";
    if !is_gen {
        return Ok(args);
    }
    let Some((value, tokens)) = find_dim(&args[3..]) else { return Ok(args) };
    match value.as_str() {
        "2" => {
            for &t in tokens.iter().rev() {
                args.remove(3 + t);
            }
            Ok(args)
        }
        "3" => {
            let parsed = match Gen3::try_parse_from(&args[2..]) {
                Ok(p) => p,
                Err(e) => {
                    let _ = e.print();
                    return Err(if e.use_stderr() { ExitCode::from(2) } else { ExitCode::SUCCESS });
                }
            };
            match run(&parsed) {
                Ok(()) => Err(ExitCode::SUCCESS),
                Err(e) => {
                    eprintln!("error: {e}");
                    Err(ExitCode::from(2))
                }
            }
        }
        other => {
            eprintln!("error: --dim must be 2 or 3, got \"{other}\"");
            Err(ExitCode::from(2))
        }
    }
}

fn run(a: &Gen3) -> Result<(), super::Scene3Error> {
    let scene = gen::generate(a.count, a.size, a.seed)?;
    let comment = format!(
        "shelling scene gen --dim 3 --count {} --size {} --seed {}\n{} squares of side {} in [0, {})^3, \
         counter-clockwise seen from the front (SCENES3D.md)",
        a.count,
        a.size,
        a.seed,
        a.count,
        a.size,
        gen::WORLD
    );
    obj::save(&scene, &a.out, &comment)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(s: &str) -> Vec<OsString> {
        s.split_whitespace().map(OsString::from).collect()
    }

    #[test]
    fn dim_2_is_removed_and_other_commands_pass_through() {
        assert_eq!(
            intercept_from(args("shelling scene gen --dim 2 --count 3")),
            Ok(args("shelling scene gen --count 3"))
        );
        assert_eq!(intercept_from(args("shelling scene gen --dim=2")), Ok(args("shelling scene gen")));
        assert_eq!(
            intercept_from(args("shelling scene gen --count 3")),
            Ok(args("shelling scene gen --count 3"))
        );
        assert_eq!(intercept_from(args("shelling trace --dim 3")), Ok(args("shelling trace --dim 3")));
        assert_eq!(intercept_from(args("shelling")), Ok(args("shelling")));
    }

    #[test]
    fn a_bad_dim_is_an_error() {
        assert_eq!(intercept_from(args("shelling scene gen --dim 4")), Err(ExitCode::from(2)));
    }
}
