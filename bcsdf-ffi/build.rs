//! Records the compiler and the target for the build tag of an open `fur_lut`
//! (`src/handle.rs`, `BUILD_TAG`): a `fur_lut` is only meaningful to the build that opened it.

use std::process::Command;

fn main() {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    // `rustc -vV` names the release, the commit and the host; an unreadable answer still
    // gives a tag (the library version and the layout are hashed too).
    let version = Command::new(&rustc)
        .arg("-vV")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .unwrap_or_default();
    let version = version.lines().collect::<Vec<_>>().join("; ");
    println!("cargo:rustc-env=FUR_BCSDF_RUSTC={version}");
    let target = std::env::var("TARGET").unwrap_or_default();
    println!("cargo:rustc-env=FUR_BCSDF_TARGET={target}");
    println!("cargo:rerun-if-changed=build.rs");
}
