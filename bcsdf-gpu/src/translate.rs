//! The WGSL evaluator translated with naga (as a library) to the shading languages engines
//! use. `tests/translations.rs` regenerates every file and compares it with the committed
//! copy under `bcsdf-core/shaders/generated/` (set `FUR_BLESS_SHADERS=1` to rewrite them), and
//! runs `spirv-val` and `glslangValidator` on them when those are installed.

use crate::{ENTRY_DUAL, ENTRY_DUAL_DIRS};
use bcsdf_core::shader::{
    ENTRY_ABSORPTION, ENTRY_EVAL, ENTRY_EVAL_DIRS, ENTRY_PDF, ENTRY_SAMPLE, FUR_BCSDF_WGSL,
};
use naga::back::{glsl, hlsl, msl, spv};
use naga::valid::{Capabilities, ValidationFlags, Validator};

/// One generated file: its name (under `bcsdf-core/shaders/generated/`) and contents.
pub struct Translation {
    /// File name, e.g. `fur_bcsdf.hlsl` or `fur_eval_main.450.comp`.
    pub name: String,
    /// The file's bytes (text, or SPIR-V words little-endian).
    pub bytes: Vec<u8>,
}

/// Parses and validates the WGSL, then writes every translation. An error names the stage.
pub fn translations() -> Result<Vec<Translation>, String> {
    let module = naga::front::wgsl::parse_str(FUR_BCSDF_WGSL)
        .map_err(|e| format!("WGSL: {}", e.emit_to_string(FUR_BCSDF_WGSL)))?;
    let info = Validator::new(ValidationFlags::all(), Capabilities::all())
        .validate(&module)
        .map_err(|e| format!("validation: {e:?}"))?;
    let mut out = Vec::new();

    // SPIR-V, one module with every entry point. naga's default adds debug names only in
    // builds with debug assertions; set it explicitly so that the output does not depend on
    // the build profile (names help shader debuggers).
    let mut spv_options = spv::Options::default();
    spv_options.flags.insert(spv::WriterFlags::DEBUG);
    let words =
        spv::write_vec(&module, &info, &spv_options, None).map_err(|e| format!("SPIR-V: {e}"))?;
    out.push(Translation {
        name: "fur_bcsdf.spv".into(),
        bytes: words.iter().flat_map(|w| w.to_le_bytes()).collect(),
    });

    // HLSL, shader model 6.0, every entry point.
    let mut text = String::new();
    let options = hlsl::Options {
        shader_model: hlsl::ShaderModel::V6_0,
        ..Default::default()
    };
    hlsl::Writer::new(&mut text, &options, &Default::default())
        .write(&module, &info, None)
        .map_err(|e| format!("HLSL: {e}"))?;
    out.push(Translation {
        name: "fur_bcsdf.hlsl".into(),
        bytes: text.into_bytes(),
    });

    // MSL 2.1, every entry point.
    let mut text = String::new();
    let options = msl::Options {
        lang_version: (2, 1),
        ..Default::default()
    };
    msl::Writer::new(&mut text)
        .write(&module, &info, &options, &msl::PipelineOptions::default())
        .map_err(|e| format!("MSL: {e}"))?;
    out.push(Translation {
        name: "fur_bcsdf.metal".into(),
        bytes: text.into_bytes(),
    });

    // GLSL: one file per entry point and version (450 core, ES 310).
    for (version, suffix) in [
        (glsl::Version::Desktop(450), "450"),
        (
            glsl::Version::Embedded {
                version: 310,
                is_webgl: false,
            },
            "es310",
        ),
    ] {
        for entry in [
            ENTRY_EVAL,
            ENTRY_EVAL_DIRS,
            ENTRY_SAMPLE,
            ENTRY_PDF,
            ENTRY_DUAL,
            ENTRY_DUAL_DIRS,
            ENTRY_ABSORPTION,
        ] {
            let mut text = String::new();
            let options = glsl::Options {
                version,
                ..Default::default()
            };
            let pipeline = glsl::PipelineOptions {
                shader_stage: naga::ShaderStage::Compute,
                entry_point: entry.into(),
                multiview: None,
            };
            glsl::Writer::new(
                &mut text,
                &module,
                &info,
                &options,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .and_then(|mut w| w.write())
            .map_err(|e| format!("GLSL {suffix} {entry}: {e}"))?;
            out.push(Translation {
                name: format!("{entry}.{suffix}.comp"),
                bytes: text.into_bytes(),
            });
        }
    }
    Ok(out)
}
