//! What the residual simulations of a LUT's absorption planes cost (docs/model.md §12,
//! "Common random numbers across colours"): per plane (the RGB σ_ca of nodes 3j, 3j + 1,
//! 3j + 2, as `bake::tables::absorption_planes`), the photons walked, the beams and the time
//! on one thread, each plane walked alone; then all planes in the bake's shared walks
//! (`generate_residuals`), with a check that they gave the same bits.
//! `cargo run --release -p bake --example colour_cost -- deer`
use bake::profiles::{
    build_model, default_cache_dir, generate_residual, generate_residuals, ProfileOptions,
};
use bcsdf_core::lut::{self, LutResolution};
use bcsdf_core::residual::ResidualLayout;
use bcsdf_core::{presets, Absorption, FurParams, Rgb};
use std::time::Instant;

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "deer".to_owned());
    let preset = presets::find(&name).unwrap();
    let opts = ProfileOptions {
        cache_dir: default_cache_dir(),
        ..ProfileOptions::default()
    };
    let params = FurParams::new(&preset.input).unwrap();
    let (model, _) = build_model(params, &opts).unwrap();
    let n_abs = LutResolution::DEFAULT.n_abs;
    let scale = lut::absorption_scale(params.kappa());
    let (mut photons, mut seconds) = (0u64, 0.0f64);
    let mut planes = Vec::new();
    let mut alone = Vec::new();
    for j in 0..(n_abs as usize).div_ceil(3) {
        let sigma = Rgb([0, 1, 2].map(|c| lut::absorption_node(3 * j + c, n_abs, scale)));
        let colour = Absorption::from_sigma(sigma).unwrap();
        let plane = model.at_sigma(&colour).unwrap();
        let start = Instant::now();
        let (table, stats) = generate_residual(
            &plane.model_without_residual(),
            &ResidualLayout::DEFAULT,
            opts.seed,
            Some(1),
        )
        .unwrap();
        let t = start.elapsed().as_secs_f64();
        let p: u64 = stats.iter().map(|s| s.photons).sum();
        let b: u64 = stats.iter().map(|s| s.beams).sum();
        println!("{name} plane {j} σ_ca {sigma:?}: {p} photons, {b} beams, {t:.2} s");
        photons += p;
        seconds += t;
        planes.push(plane);
        alone.push(table);
    }
    println!("{name}: {photons} photons, {seconds:.2} s on one thread, each plane alone");
    let views: Vec<_> = planes.iter().map(|p| p.model_without_residual()).collect();
    let refs: Vec<_> = views.iter().collect();
    let start = Instant::now();
    let shared = generate_residuals(&refs, &ResidualLayout::DEFAULT, opts.seed, Some(1)).unwrap();
    let t = start.elapsed().as_secs_f64();
    let same = shared.iter().zip(&alone).all(|(a, b)| {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
    });
    println!(
        "{name}: {t:.2} s on one thread in shared walks ({:.1}x), the same bits: {same}",
        seconds / t
    );
}
