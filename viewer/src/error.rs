//! Errors and exit codes: bad input exits 2 (like clap's usage errors), I/O and other
//! failures 1, a LUT over its error budget (`viewer compare`) 3.

use std::fmt;
use std::io::{self, Write};
use std::process::ExitCode;

/// Why a command failed.
#[derive(Debug)]
pub enum Error {
    /// Bad input (preset, override, angle, stdin line, preset file): exit code 2.
    Input(String),
    /// Reading or writing failed: exit code 1 (a closed stdout ends the run quietly).
    Io(io::Error),
    /// Anything else that is not the input's fault (e.g. an unwritable profile cache
    /// directory): exit code 1.
    Failure(String),
    /// `viewer compare`: a metric exceeds the budget: exit code 3.
    Budget(String),
}

impl Error {
    /// A bad-input error with this message.
    pub fn input(message: impl fmt::Display) -> Error {
        Error::Input(message.to_string())
    }

    /// Prints the one-line `error: …` message to stderr and returns the exit code.
    pub fn report(self) -> ExitCode {
        let (message, code) = match self {
            Error::Input(m) => (m, 2),
            // `viewer probe --stdin | head`: the reader has gone, nothing left to say.
            Error::Io(e) if e.kind() == io::ErrorKind::BrokenPipe => return ExitCode::SUCCESS,
            Error::Io(e) => (format!("I/O error: {e}"), 1),
            Error::Failure(m) => (m, 1),
            Error::Budget(m) => (m, 3),
        };
        let _ = writeln!(io::stderr().lock(), "error: {message}");
        ExitCode::from(code)
    }
}

impl From<io::Error> for Error {
    fn from(e: io::Error) -> Error {
        Error::Io(e)
    }
}
