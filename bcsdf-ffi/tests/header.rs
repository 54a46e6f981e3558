//! `include/fur_bcsdf.h` is what cbindgen generates from `src/lib.rs` with `cbindgen.toml`:
//! regenerate and compare (a changed API without a regenerated header fails here). Set
//! `FUR_BLESS_HEADER=1` to rewrite the committed header instead.

use std::path::PathBuf;

#[test]
fn header_is_current() {
    let crate_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).unwrap();
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen")
        .write(&mut generated);
    let path = crate_dir.join("include/fur_bcsdf.h");
    if std::env::var_os("FUR_BLESS_HEADER").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/fur_bcsdf.h is stale: run `FUR_BLESS_HEADER=1 cargo test -p bcsdf-ffi --test header` and commit it"
    );
}
