#!/usr/bin/env bash
# Bullet's CCD with and without motion-bound's certified pass (examples/bullet/bullet_worlds.cpp),
# from a clean checkout: installs Debian's libbullet-dev with apt-get when missing, builds the
# library in release, compiles the C++ example against it and runs it.
# Usage: motion-bound-c/examples/bullet.sh [launches per world, default 40]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
launches="${1:-40}"
if ! pkg-config --exists bullet 2>/dev/null; then
  sudo_=""; [ "$(id -u)" -ne 0 ] && sudo_="sudo"
  $sudo_ apt-get update -q
  $sudo_ apt-get install -y -q libbullet-dev pkg-config g++
fi
cd "$here/.."
cargo build --release --quiet -p motion-bound-c
target="$(cargo metadata --format-version 1 --no-deps | python3 -c 'import json,sys; print(json.load(sys.stdin)["target_directory"])')"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# shellcheck disable=SC2046
c++ -std=c++17 -O2 -Wall -Wextra -I "$here/include" $(pkg-config --cflags bullet) \
  "$here/examples/bullet/bullet_worlds.cpp" "$target/release/libmotion_bound_c.a" \
  $(pkg-config --libs bullet) -lpthread -ldl -lm -o "$out/bullet_worlds"
"$out/bullet_worlds" "$launches"
