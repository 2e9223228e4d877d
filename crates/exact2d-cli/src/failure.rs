//! Why a command failed, and the exit code that says so.

use std::fmt;

/// A failed command: its message (one line, naming the file) and its kind.
#[derive(Debug)]
pub enum Failure {
    /// The input is wrong (an invalid scene): exit code 2.
    BadInput(String),
    /// Anything else (a file that cannot be read or written): exit code 1.
    Other(String),
}

impl Failure {
    /// 2 for bad input, 1 for anything else.
    pub fn exit_code(&self) -> u8 {
        match self {
            Failure::BadInput(_) => 2,
            Failure::Other(_) => 1,
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::BadInput(message) | Failure::Other(message) => f.write_str(message),
        }
    }
}
