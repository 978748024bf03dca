#!/usr/bin/env bash
# Builds motion-bound-c in release and installs it under PREFIX (default /usr/local):
#   PREFIX/include/motion_bound.h
#   PREFIX/lib/libmotion_bound_c.a, PREFIX/lib/libmotion_bound_c.so
#   PREFIX/lib/pkgconfig/motion_bound.pc
#   PREFIX/lib/cmake/motion_bound/motion_boundConfig.cmake and motion_boundConfigVersion.cmake
# Usage: motion-bound-c/install.sh [PREFIX] (MB_PROFILE=debug installs the debug build instead,
# as tests/run_c_tests.sh does to check the installed files).
set -euo pipefail
prefix="$(realpath -m "${1:-/usr/local}")"
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/.."
profile="${MB_PROFILE:-release}"
if [ "$profile" = release ]; then cargo build --release --quiet -p motion-bound-c
else cargo build --quiet -p motion-bound-c; fi
target="$(cargo metadata --format-version 1 --no-deps | python3 -c 'import json,sys; print(json.load(sys.stdin)["target_directory"])')"
version="$(sed -n 's/^version = "\(.*\)"/\1/p' "$here/Cargo.toml" | head -n 1)"
mkdir -p "$prefix/include" "$prefix/lib/pkgconfig" "$prefix/lib/cmake/motion_bound"
cp "$here/include/motion_bound.h" "$prefix/include/"
cp "$target/$profile/libmotion_bound_c.a" "$target/$profile/libmotion_bound_c.so" "$prefix/lib/"
# The placeholders are filled in outside comments only.
sed -e "/^#/!s|@PREFIX@|$prefix|" -e "/^#/!s|@VERSION@|$version|" "$here/motion_bound.pc.in" \
  > "$prefix/lib/pkgconfig/motion_bound.pc"
cp "$here/cmake/motion_boundConfig.cmake" "$prefix/lib/cmake/motion_bound/"
sed -e "/^#/!s|@VERSION@|$version|" "$here/cmake/motion_boundConfigVersion.cmake.in" \
  > "$prefix/lib/cmake/motion_bound/motion_boundConfigVersion.cmake"
echo "installed motion-bound-c $version under $prefix"
