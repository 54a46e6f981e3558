//! One `#[test]` per built-in preset, so that the harness runs the presets in parallel and a
//! failure names its preset, plus a test that fails when `bcsdf_core::presets::PRESETS` gains a
//! preset the list does not name.

/// `per_preset_tests!(check, completeness_test; test_a: "preset-a", test_b: "preset-b", …)`
/// defines `#[test] fn test_a() { check("preset-a") }` … and
/// `#[test] fn completeness_test()`, which asserts that every built-in preset is listed.
#[macro_export]
macro_rules! per_preset_tests {
    ($check:path, $complete:ident; $($test:ident: $name:literal),* $(,)?) => {
        $(
            #[test]
            fn $test() {
                $check($name);
            }
        )*

        #[test]
        fn $complete() {
            let tested = [$($name),*];
            for p in bcsdf_core::presets::PRESETS.iter() {
                assert!(
                    tested.contains(&p.name),
                    "{} has no test calling {}",
                    p.name,
                    stringify!($check)
                );
            }
        }
    };
}
