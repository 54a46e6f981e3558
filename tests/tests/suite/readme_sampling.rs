//! The README's "Sampling" example, compiled and run (human-hair: no medulla profiles).

use bake::profiles::{build_model, ProfileOptions};
use bcsdf_core::baked::BakedBcsdf;
use bcsdf_core::lut::LutResolution;
use bcsdf_core::{presets, Absorption, Bcsdf, FurParams, Rgb, Vec3};

/// One bounce of a path tracer: the next direction and the path throughput factor.
fn scatter<B: Bcsdf>(fur: &B, to_viewer: Vec3, tangent: Vec3, u: [f32; 3]) -> Option<(Vec3, Rgb)> {
    let s = fur.sample_dirs(to_viewer, tangent, u)?; // None: zero albedo or bad input
    Some((s.wi?, s.weight)) // world-space ω_i, S·cos θ_i / pdf
}

#[test]
fn readme_sampling_example() {
    let preset = presets::find("human-hair").unwrap();
    let params = FurParams::new(&preset.input).unwrap();
    let (owned, _) = build_model(params, &ProfileOptions::default()).unwrap();
    let fur = owned.model();
    let blob = bake::tables::bake(&owned, &preset.input, LutResolution::DEFAULT);
    #[allow(non_snake_case)]
    let LUT: &[u8] = &blob;
    let (view_dir, fiber_tangent) = ([0.3f32, 0.9, 0.1], [0.0f32, 0.2, 1.0]);
    let (u0, u1, u2) = (0.25f32, 0.5, 0.75);
    let theta_r = 0.3f32;

    let lut = BakedBcsdf::from_bytes(LUT).unwrap(); // 1.5 MB, sampling data included
    let next = scatter(&lut, view_dir, fiber_tangent, [u0, u1, u2]);
    let (wi, weight) = next.unwrap();
    assert!((wi.iter().map(|c| c * c).sum::<f32>() - 1.0).abs() < 1e-5);
    assert!(weight.max_channel() > 0.0);
    let next = scatter(&fur, view_dir, fiber_tangent, [u0, u1, u2]); // the analytic model
    assert!(next.is_some());
    // Angles in, angles out; MIS weights from pdf, or eval and pdf at once:
    let s = lut.sample(theta_r, [u0, u1, u2]).unwrap();
    assert_eq!(s.pdf, lut.pdf(&s.angles));
    let (value, pdf) = fur.eval_with_pdf(&s.angles); // Families (per lobe family) and p_ω
    assert!(value.total().max_channel() > 0.0 && pdf > 0.0);
    // Any colour from the same LUT, per strand or per query (σ_ca per channel, or melanin):
    let strand = lut.at(&Absorption::from_melanin(0.4, 1.5).unwrap()); // implements Bcsdf too
    let next = scatter(&strand, view_dir, fiber_tangent, [u0, u1, u2]);
    let (wi_c, weight_c) = next.unwrap();
    assert_eq!(
        wi_c, wi,
        "the sampled direction does not depend on the colour"
    );
    assert!(
        weight_c.0[2] < weight.0[2],
        "a redder strand keeps less blue"
    );
    assert_eq!(LUT.len(), 1_572_008, "the README's 1.5 MB");
}
