//! The Rust value the installed C library's consumers (`examples/consumer`, README
//! "Installing the C library") are checked against: the far-field S (docs/model.md §1, the
//! baked evaluator of docs/lut.md) of a `.furlut` at (θ_i, θ_r, φ) in radians, evaluated by
//! `bcsdf_core::BakedBcsdf` and printed as the consumers print it, `S` and the bits of the
//! R, G and B values in hex:
//!
//! ```text
//! cargo run --release -p bcsdf-ffi --example eval_far -- LUT THETA_I THETA_R PHI
//! ```

use bcsdf_core::{Angles, BakedBcsdf};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &[String]) -> Result<String, String> {
    let [path, theta_i, theta_r, phi] = args else {
        return Err("usage: eval_far LUT THETA_I THETA_R PHI (radians)".into());
    };
    let bytes = std::fs::read(path).map_err(|e| format!("{path}: {e}"))?;
    let lut = BakedBcsdf::from_bytes(&bytes).map_err(|e| format!("{path}: {e}"))?;
    let angle = |s: &String| {
        s.parse::<f32>()
            .map_err(|e| format!("angle {s:?} is not a number: {e}"))
    };
    let angles =
        Angles::new(angle(theta_i)?, angle(theta_r)?, angle(phi)?).map_err(|e| e.to_string())?;
    let [r, g, b] = lut.eval_far(&angles).total().0;
    Ok(format!(
        "S {:08x} {:08x} {:08x}",
        r.to_bits(),
        g.to_bits(),
        b.to_bits()
    ))
}
