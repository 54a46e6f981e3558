//! `viewer --version` prints the crate's version (the workspace's, which CHANGELOG.md's latest
//! release must equal: tests/tests/suite/changelog.rs).

use std::process::Command;

#[test]
fn version_flag_prints_the_crate_version() {
    let out = Command::new(env!("CARGO_BIN_EXE_viewer"))
        .arg("--version")
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        concat!("viewer ", env!("CARGO_PKG_VERSION"), "\n")
    );
}
