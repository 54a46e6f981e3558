#!/usr/bin/env bash
# Installs the C library into a temporary prefix (bcsdf-ffi/CMakeLists.txt), builds the two
# consumer projects against it (CMake find_package, and cc with pkg-config), runs them on a
# .furlut and requires the line they print to equal the Rust value (examples/eval_far.rs).
# Needs cargo, cmake, pkg-config and a C compiler.  Usage: check.sh LUT.furlut
set -euo pipefail
lut=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
angles=(0.5 -0.35 0.785) # theta_i, theta_r, phi in radians

echo "-- install into a temporary prefix"
cmake -S "$root/bcsdf-ffi" -B "$work/build" >/dev/null
cmake --build "$work/build"
cmake --install "$work/build" --prefix "$prefix"
pc=$(find "$prefix" -name fur_bcsdf.pc)
libdir=$(dirname "$(dirname "$pc")")
for f in "$libdir/libfur_bcsdf.a" "$libdir/libfur_bcsdf.so" "$prefix/include/fur_bcsdf.h" \
         "$libdir/cmake/fur_bcsdf/fur_bcsdfConfig.cmake"; do
  [ -e "$f" ] || { echo "error: the install did not write $f" >&2; exit 1; }
done
readelf -d "$libdir/libfur_bcsdf.so" | grep SONAME

# The test profile (optimised): after `cargo test --workspace` its dependencies are built, so
# this compiles the example alone; --release would build the crate's dev-dependencies again.
expected=$(cargo run --quiet --profile test --manifest-path "$root/Cargo.toml" -p bcsdf-ffi \
  --example eval_far -- "$lut" "${angles[@]}")
echo "Rust (bcsdf_core::BakedBcsdf):          $expected"
same() { # NAME OUTPUT
  echo "$1: $2"
  [ "$2" = "$expected" ] || { echo "error: $1 printed another value than Rust" >&2; exit 1; }
}

echo "-- consumer 1: CMake, find_package(fur_bcsdf)"
cmake -S "$here" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/consumer"
same "CMake, fur_bcsdf::fur_bcsdf        " "$("$work/consumer/consumer" "$lut" "${angles[@]}")"
same "CMake, fur_bcsdf::fur_bcsdf_static " "$("$work/consumer/consumer_static" "$lut" "${angles[@]}")"

echo "-- consumer 2: cc \$(pkg-config --cflags --libs fur_bcsdf)"
export PKG_CONFIG_PATH="$libdir/pkgconfig"
# shellcheck disable=SC2046 # the flags are words
cc -std=c99 -Wall -Wextra -Werror -pedantic "$here/consumer.c" \
  $(pkg-config --cflags --libs fur_bcsdf) -o "$work/consumer-pc"
same "cc + pkg-config (shared)           " \
  "$(LD_LIBRARY_PATH="$libdir" "$work/consumer-pc" "$lut" "${angles[@]}")"
echo "the installed library gives the Rust value"
