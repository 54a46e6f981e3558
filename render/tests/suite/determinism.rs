//! Determinism (docs/model.md §11): the same render.exr bytes for 1 and 2 threads.

use crate::common;

use render::scatter::One;
use render::{integrator, output, scenes, SceneKind, SceneOptions, Settings};

#[test]
fn the_exr_is_the_same_bytes_for_one_and_two_threads() {
    let scene = scenes::build(&SceneOptions {
        kind: SceneKind::Patch,
        fibers: Some(1000),
        seed: 9,
        aspect: 1.0,
    });
    common::with_model(&common::plain().input, |hair| {
        let bytes = |threads| {
            let settings = Settings {
                threads: Some(threads),
                ..Settings::new(24, 16, 4)
            };
            let r = integrator::render(&scene, &One(hair), &settings).unwrap();
            output::exr_bytes(&r.image).unwrap()
        };
        let one = bytes(1);
        assert!(one == bytes(2), "1 and 2 threads gave different EXR bytes");
        // The seed matters (the comparison above is not between two constant images).
        assert!(
            one != {
                let settings = Settings {
                    threads: Some(2),
                    seed: 2,
                    ..Settings::new(24, 16, 4)
                };
                output::exr_bytes(
                    &integrator::render(&scene, &One(hair), &settings)
                        .unwrap()
                        .image,
                )
                .unwrap()
            }
        );
    });
}
