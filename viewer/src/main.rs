//! `viewer`: command-line access to the fur BCSDF (`viewer --help`).

mod catalog;
mod cli;
mod compare;
mod error;
mod figures;
mod json;
mod plot;
mod probe;
mod render;
mod sample;
mod source;
mod summary;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let result = match cli::Cli::parse().command {
        cli::Command::Presets(args) => catalog::list(&args),
        cli::Command::Probe(args) => probe::run(&args),
        cli::Command::Sample(args) => sample::run(&args),
        cli::Command::Compare(args) => compare::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => e.report(),
    }
}
