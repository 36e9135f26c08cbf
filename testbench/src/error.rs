//! The crate's error type: a message meant for a human reading a failed test.
//!
//! `Debug` prints the message verbatim (no quoting, real newlines), so a `#[test]` returning
//! `Result<(), Error>` shows a readable multi-line report when it fails. Use
//! [`Error::context`] to prefix what the caller knows (seed, pacing, block name).

use std::fmt;

/// A test-bench failure: a design that does not settle, a failed rust-hdl check, a scoreboard
/// mismatch, a stream protocol violation, a Verilog replay mismatch, an I/O error...
#[derive(Clone, PartialEq, Eq)]
pub struct Error {
    message: String,
}

/// `Result` with the crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// An error with this message.
    pub fn new(message: impl Into<String>) -> Self {
        Self { message: message.into() }
    }

    /// The same error with `context` (for example `"seed 0x2a, pacing idle"`) in front.
    pub fn context(self, context: impl fmt::Display) -> Self {
        Self { message: format!("{context}: {}", self.message) }
    }

    /// The message.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}

impl From<String> for Error {
    fn from(message: String) -> Self {
        Self::new(message)
    }
}

impl From<&str> for Error {
    fn from(message: &str) -> Self {
        Self::new(message)
    }
}
