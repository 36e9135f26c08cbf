//! Output that appears whole or not at all: a file or a directory is written under a temporary
//! name beside its target ([`Staged::path`]) and moved into place by [`Staged::commit`]; dropped
//! without a commit (the command failed), the temporary is removed. So a failed command leaves
//! no partial VCD, figure directory, Verilog export or scene file behind.
//!
//! A file is renamed over its target. A directory is renamed onto a target that does not exist;
//! into an existing directory its files are moved one by one (replacing files of the same
//! name), after everything has been written.

use std::io;
use std::path::{Path, PathBuf};

/// A file or directory being written under a temporary name.
#[derive(Debug)]
pub struct Staged {
    target: PathBuf,
    temp: PathBuf,
    dir: bool,
    done: bool,
}

impl Staged {
    /// A file to be written at `target`: write it at [`Staged::path`].
    pub fn file(target: &Path) -> io::Result<Staged> {
        Staged::new(target, false)
    }

    /// A directory to be filled at `target`: the temporary directory [`Staged::path`] is created
    /// (with the target's missing parents). A `target` that exists and is not a directory is an
    /// error.
    pub fn dir(target: &Path) -> io::Result<Staged> {
        if target.exists() && !target.is_dir() {
            return Err(io::Error::new(
                io::ErrorKind::AlreadyExists,
                format!("{} exists and is not a directory", target.display()),
            ));
        }
        let s = Staged::new(target, true)?;
        std::fs::create_dir(&s.temp)?;
        Ok(s)
    }

    fn new(target: &Path, dir: bool) -> io::Result<Staged> {
        let name = target.file_name().ok_or_else(|| {
            io::Error::new(io::ErrorKind::InvalidInput, format!("{} names no file", target.display()))
        })?;
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if dir {
            std::fs::create_dir_all(&parent)?;
        }
        let mut temp_name = std::ffi::OsString::from(".");
        temp_name.push(name);
        temp_name.push(format!(".partial-{}", std::process::id()));
        let temp = parent.join(temp_name);
        remove(&temp);
        Ok(Staged { target: target.to_path_buf(), temp, dir, done: false })
    }

    /// Where to write: the temporary name beside the target.
    pub fn path(&self) -> &Path {
        &self.temp
    }

    /// The final path.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// `path` (a path under the temporary name) as it will be once committed.
    pub fn final_path(&self, path: &Path) -> PathBuf {
        match path.strip_prefix(&self.temp) {
            Ok(rest) if rest.as_os_str().is_empty() => self.target.clone(),
            Ok(rest) => self.target.join(rest),
            Err(_) => path.to_path_buf(),
        }
    }

    /// Moves the output into place.
    pub fn commit(mut self) -> io::Result<PathBuf> {
        if self.dir && self.target.is_dir() {
            for entry in std::fs::read_dir(&self.temp)? {
                let entry = entry?;
                std::fs::rename(entry.path(), self.target.join(entry.file_name()))?;
            }
            std::fs::remove_dir(&self.temp)?;
        } else {
            std::fs::rename(&self.temp, &self.target)?;
        }
        self.done = true;
        Ok(self.target.clone())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.done {
            remove(&self.temp);
        }
    }
}

/// Removes a file or directory, if there is one.
fn remove(path: &Path) {
    if path.is_dir() {
        let _ = std::fs::remove_dir_all(path);
    } else {
        let _ = std::fs::remove_file(path);
    }
}
