//! `viewer`: command-line access to the fur BCSDF (`viewer --help`).

mod catalog;
mod cli;
mod compare;
mod error;
mod figures;
mod gpu;
mod json;
mod plot;
mod probe;
mod render;
mod render_cmd;
mod report;
mod sample;
mod source;
mod strand_cmd;
mod summary;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    // Mesa's Vulkan driver complains on stderr when XDG_RUNTIME_DIR is unset; for --gpu, give
    // it the temporary directory, here, before any thread exists.
    if std::env::args_os().any(|a| a == "--gpu") && std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
    }
    let result = match cli::Cli::parse().command {
        cli::Command::Presets(args) => catalog::list(&args),
        cli::Command::Probe(args) => probe::run(&args),
        cli::Command::Sample(args) => sample::run(&args),
        cli::Command::Compare(args) => compare::run(&args),
        cli::Command::Render(args) => render_cmd::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => e.report(),
    }
}
