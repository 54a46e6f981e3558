//! Snapshot of the shader translations: regenerate every file of
//! `bcsdf-core/shaders/generated/` with naga and compare with the committed copy
//! (`FUR_BLESS_SHADERS=1` rewrites them). Then validate them with the Khronos tools when they
//! are installed (`spirv-val` from spirv-tools, `glslangValidator` from glslang-tools; `.ci/run`
//! installs both and sets `FUR_BCSDF_REQUIRE_TOOLS=1`, which makes a missing tool a failure).

use bcsdf_gpu::translate::translations;
use std::path::PathBuf;
use std::process::Command;

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../bcsdf-core/shaders/generated")
}

#[test]
fn committed_translations_are_current() {
    let files = translations().unwrap();
    let bless = std::env::var_os("FUR_BLESS_SHADERS").is_some();
    if bless {
        std::fs::create_dir_all(dir()).unwrap();
    }
    let mut stale = Vec::new();
    for t in &files {
        let path = dir().join(&t.name);
        if bless {
            std::fs::write(&path, &t.bytes).unwrap();
        }
        if std::fs::read(&path).ok().as_deref() != Some(&t.bytes[..]) {
            stale.push(t.name.clone());
        }
    }
    assert!(
        stale.is_empty(),
        "stale shader translations {stale:?}: run `FUR_BLESS_SHADERS=1 cargo test -p bcsdf-gpu --test suite translations::` and commit them"
    );
    // Nothing else in the folder: a removed entry point does not leave an orphan behind.
    let mut names: Vec<String> = std::fs::read_dir(dir())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let mut want: Vec<String> = files.iter().map(|t| t.name.clone()).collect();
    want.sort();
    assert_eq!(names, want);
}

fn tool(name: &str) -> bool {
    let found = Command::new(name).arg("--version").output().is_ok();
    if !found {
        if std::env::var("FUR_BCSDF_REQUIRE_TOOLS").as_deref() == Ok("1") {
            panic!("FUR_BCSDF_REQUIRE_TOOLS=1 but {name} is not installed");
        }
        println!("skipped: {name} not installed");
    }
    found
}

#[test]
fn translations_pass_the_khronos_validators() {
    let files = translations().unwrap();
    let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("shaders");
    std::fs::create_dir_all(&tmp).unwrap();
    for t in &files {
        std::fs::write(tmp.join(&t.name), &t.bytes).unwrap();
    }
    if tool("spirv-val") {
        let out = Command::new("spirv-val")
            .arg(tmp.join("fur_bcsdf.spv"))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "spirv-val: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    if tool("glslangValidator") {
        for t in files.iter().filter(|t| t.name.ends_with(".comp")) {
            let out = Command::new("glslangValidator")
                .arg(tmp.join(&t.name))
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "glslangValidator {}: {}",
                t.name,
                String::from_utf8_lossy(&out.stdout)
            );
        }
    }
}
