//! The patch loader (in progress).
