#!/usr/bin/env bash
# Builds motion-bound-c in release and installs it under PREFIX (default /usr/local):
#   PREFIX/include/motion_bound.h
#   PREFIX/lib/libmotion_bound_c.a, PREFIX/lib/libmotion_bound_c.so
#   PREFIX/lib/pkgconfig/motion_bound.pc
#   PREFIX/lib/cmake/motion_bound/motion_boundConfig.cmake
# Usage: motion-bound-c/install.sh [PREFIX]
set -euo pipefail
prefix="$(realpath -m "${1:-/usr/local}")"
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/.."
cargo build --release --quiet -p motion-bound-c
target="$(cargo metadata --format-version 1 --no-deps | python3 -c 'import json,sys; print(json.load(sys.stdin)["target_directory"])')"
version="$(sed -n 's/^version = "\(.*\)"/\1/p' "$here/Cargo.toml" | head -n 1)"
mkdir -p "$prefix/include" "$prefix/lib/pkgconfig" "$prefix/lib/cmake/motion_bound"
cp "$here/include/motion_bound.h" "$prefix/include/"
cp "$target/release/libmotion_bound_c.a" "$target/release/libmotion_bound_c.so" "$prefix/lib/"
sed -e "s|@PREFIX@|$prefix|" -e "s|@VERSION@|$version|" "$here/motion_bound.pc.in" \
  > "$prefix/lib/pkgconfig/motion_bound.pc"
cp "$here/cmake/motion_boundConfig.cmake" "$prefix/lib/cmake/motion_bound/"
echo "installed motion-bound-c $version under $prefix"
