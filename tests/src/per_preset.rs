//! One `#[test]` per built-in preset, so that the harness runs the presets in parallel and a
//! failure names its preset, plus a test that fails when `bcsdf_core::presets::PRESETS` gains a
//! preset the list does not name.
//!
//! The everyday run (`cargo test --workspace`) checks the [`CORE_PRESETS`]: between them they
//! take every code path the presets differ by (no medulla; an air medulla with η_m ≠ η_c; the
//! narrowest lobes; a layered cuticle with l = 2 and a medulla). The other species are the
//! *full sweep*: the same check, `#[ignore]`d, in a module named after the test with one
//! function `full_sweep` (`ball_cat::full_sweep`), which CI runs with the second test command,
//! `cargo test --workspace -- --ignored full_sweep`.

/// The presets every per-preset test checks in the everyday run; the rest run in the full sweep.
pub const CORE_PRESETS: [&str; 4] = ["human-hair", "air-medulla", "human-fur", "raccoon"];

/// The built-in presets a test that loops over presets checks in the everyday run (the
/// [`CORE_PRESETS`]) or in the full sweep (every other one): the same split as
/// [`per_preset_tests!`](crate::per_preset_tests), for a test whose check spans several
/// presets at once.
#[must_use]
pub fn presets_of(sweep: bool) -> Vec<&'static bcsdf_core::presets::Preset> {
    bcsdf_core::presets::PRESETS
        .iter()
        .filter(|p| CORE_PRESETS.contains(&p.name) != sweep)
        .collect()
}

/// `per_preset_tests!(check, completeness_test; test_a: "preset-a", test_b: "preset-b", …)`
/// defines, for each core preset, `#[test] fn test_a() { check("preset-a") }`, for every other
/// one `mod test_b { #[test] #[ignore] fn full_sweep() { check("preset-b") } }`, and
/// `#[test] fn completeness_test()`, which asserts that every built-in preset is listed and
/// that every core preset is among them.
#[macro_export]
macro_rules! per_preset_tests {
    ($check:path, $complete:ident; $($test:ident: $name:tt),* $(,)?) => {
        $(
            $crate::__per_preset_test!($check, $test, $name);
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
            for core in $crate::per_preset::CORE_PRESETS {
                assert!(
                    bcsdf_core::presets::PRESETS.iter().any(|p| p.name == core),
                    "core preset {core} is not a built-in preset"
                );
            }
        }
    };
}

/// One test of [`per_preset_tests!`]: a plain `#[test]` for a core preset (the literals below
/// are [`CORE_PRESETS`]; a test checks they agree), an ignored `full_sweep` test otherwise.
#[doc(hidden)]
#[macro_export]
macro_rules! __per_preset_test {
    ($check:path, $test:ident, "human-hair") => {
        $crate::__per_preset_test!(@core $check, $test, "human-hair");
    };
    ($check:path, $test:ident, "air-medulla") => {
        $crate::__per_preset_test!(@core $check, $test, "air-medulla");
    };
    ($check:path, $test:ident, "human-fur") => {
        $crate::__per_preset_test!(@core $check, $test, "human-fur");
    };
    ($check:path, $test:ident, "raccoon") => {
        $crate::__per_preset_test!(@core $check, $test, "raccoon");
    };
    (@core $check:path, $test:ident, $name:tt) => {
        #[test]
        fn $test() {
            $check($name);
        }
    };
    ($check:path, $test:ident, $name:tt) => {
        mod $test {
            #[allow(unused_imports)]
            use super::*;

            #[test]
            #[ignore = "full sweep: cargo test --workspace -- --ignored full_sweep"]
            pub(super) fn full_sweep() {
                $check($name);
            }
        }
    };
}

#[cfg(test)]
mod tests {
    /// The macro expanded over every built-in preset: the core presets become plain
    /// functions, the others modules with an ignored `full_sweep` (each reference below only
    /// compiles if the macro produced that form).
    mod expansion {
        pub fn check(name: &str) {
            assert!(bcsdf_core::presets::find(name).is_some(), "{name}");
        }

        crate::per_preset_tests! {
            check, all_listed;
            t_bobcat: "bobcat",
            t_cat: "cat",
            t_deer: "deer",
            t_dog: "dog",
            t_mouse: "mouse",
            t_rabbit: "rabbit",
            t_raccoon: "raccoon",
            t_red_fox: "red-fox",
            t_springbok: "springbok",
            t_human_fur: "human-fur",
            t_human_hair: "human-hair",
            t_air_medulla: "air-medulla",
        }

        #[test]
        fn the_macros_core_arms_are_the_core_presets() {
            let core: [(&str, fn()); 4] = [
                ("raccoon", t_raccoon),
                ("human-fur", t_human_fur),
                ("human-hair", t_human_hair),
                ("air-medulla", t_air_medulla),
            ];
            let sweep: [fn(); 8] = [
                t_bobcat::full_sweep,
                t_cat::full_sweep,
                t_deer::full_sweep,
                t_dog::full_sweep,
                t_mouse::full_sweep,
                t_rabbit::full_sweep,
                t_red_fox::full_sweep,
                t_springbok::full_sweep,
            ];
            assert_eq!(core.len() + sweep.len(), bcsdf_core::presets::PRESETS.len());
            let mut by_macro: Vec<&str> = core.iter().map(|(n, _)| *n).collect();
            let mut listed = super::super::CORE_PRESETS.to_vec();
            by_macro.sort_unstable();
            listed.sort_unstable();
            assert_eq!(
                by_macro, listed,
                "CORE_PRESETS and the macro's literal arms differ"
            );
        }
    }
}
