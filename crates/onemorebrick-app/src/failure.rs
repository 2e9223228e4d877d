//! Why a subcommand failed.

use std::fmt;
use std::io;

use onemorebrick::GameError;

/// A subcommand's failure: the rules refused something (a bug or a bad setting), or
/// standard output could not be written.
#[derive(Debug)]
pub enum Failure {
    /// The rules returned an error.
    Game(GameError),
    /// Writing the output failed.
    Io(io::Error),
    /// Anything else, already worded for the user (a PNG that cannot be written, no
    /// display).
    Message(String),
    /// A bad input the user gave (a file that is not a save): exit code 2, as for a bad
    /// argument.
    Usage(String),
}

impl Failure {
    /// Whether the reader of standard output went away (`onemorebrick sim ... | head`):
    /// not an error, the output is simply no longer wanted.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, Failure::Io(e) if e.kind() == io::ErrorKind::BrokenPipe)
    }

    /// The exit code: 2 for the user's bad input, 1 for anything else.
    pub fn exit_code(&self) -> u8 {
        match self {
            Failure::Usage(_) => 2,
            _ => 1,
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Game(e) => write!(f, "{e}"),
            Failure::Io(e) => write!(f, "cannot write the output: {e}"),
            Failure::Message(m) | Failure::Usage(m) => f.write_str(m),
        }
    }
}

impl From<GameError> for Failure {
    fn from(e: GameError) -> Self {
        Failure::Game(e)
    }
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Self {
        Failure::Io(e)
    }
}
