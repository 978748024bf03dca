#!/usr/bin/env bash
# Builds motion-bound-c (debug), compiles tests/c/test_motion_bound.c against its static
# library with AddressSanitizer and UndefinedBehaviorSanitizer, and runs it with
# LeakSanitizer on, and tests/c/test_chain.c (chains) likewise: any sanitizer report, leak or
# failed check fails the script. Also checks that the C tests call every function the header declares. Usage: tests/run_c_tests.sh
# (from anywhere; CC overrides the compiler, default cc). Installs cmake and pkg-config with apt-get
# when missing.
set -euo pipefail
# The installed files' check below needs CMake and pkg-config: installed with apt-get when missing
# (as examples/bullet.sh and examples/ompl.sh do for theirs).
if ! command -v cmake >/dev/null || ! command -v pkg-config >/dev/null; then
  sudo_=""; [ "$(id -u)" -ne 0 ] && sudo_="sudo"
  $sudo_ apt-get update -q
  $sudo_ apt-get install -y -q cmake pkg-config
fi
here="$(cd "$(dirname "$0")/.." && pwd)"
root="$(cd "$here/.." && pwd)"
cd "$root"
cargo build --quiet -p motion-bound-c
target="$(cargo metadata --format-version 1 --no-deps | python3 -c 'import json,sys; print(json.load(sys.stdin)["target_directory"])')"
lib="$target/debug/libmotion_bound_c.a"
test -f "$lib" || { echo "FAILED: no $lib"; exit 1; }

# Every declared function is exercised by the C test.
missing=$(grep -oE '^[a-z][a-z_ ]*[ *](mb_[a-z0-9_]+)\(' "$here/include/motion_bound.h" \
  | sed -E 's/.*(mb_[a-z0-9_]+)\(/\1/' | sort -u \
  | while read -r f; do grep -q "\b$f(" "$here"/tests/c/*.c || echo "$f"; done)
if [ -n "$missing" ]; then echo "FAILED: the C test never calls: $missing"; exit 1; fi

out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"${CC:-cc}" -std=c11 -D_DEFAULT_SOURCE -Wall -Wextra -Werror -pedantic \
  -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g \
  -I "$here/include" "$here/tests/c/test_motion_bound.c" "$lib" \
  -lpthread -ldl -lm -o "$out/test_motion_bound"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
"$out/test_motion_bound"

# The chains (tests/c/test_chain.c), with the Panda read from data/.
"${CC:-cc}" -std=c11 -D_DEFAULT_SOURCE -Wall -Wextra -Werror -pedantic \
  -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g \
  -DMB_DATA_DIR="\"$root/data\"" -I "$here/include" "$here/tests/c/test_chain.c" "$lib" \
  -lpthread -ldl -lm -o "$out/test_chain"

# Symmetric spins (tests/c/test_symmetric.c): motion that moves no surface costs nothing.
"${CC:-cc}" -std=c11 -D_DEFAULT_SOURCE -Wall -Wextra -Werror -pedantic \
  -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g \
  -I "$here/include" "$here/tests/c/test_symmetric.c" "$lib" \
  -lpthread -ldl -lm -o "$out/test_symmetric"
"$out/test_symmetric"
"$out/test_chain"

# The README's example, as written there: it must build cleanly, run and print the closed-form
# time (2 - 0.25) / 3 = 0.58333 (reported up to the contact distance over the speed earlier).
sed -n '/^```c$/,/^```$/p' "$here/README.md" | sed '1d;$d' > "$out/readme.c"
"${CC:-cc}" -std=c11 -Wall -Wextra -Werror -pedantic -fsanitize=address,undefined \
  -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -I "$here/include" \
  "$out/readme.c" "$lib" -lpthread -ldl -lm -o "$out/readme"
readme_out="$("$out/readme")"
echo "README example: $readme_out"
case "$readme_out" in
  "outcome 0 at t = 0.5833"*) ;;
  *) echo "FAILED: the README example printed '$readme_out'"; exit 1 ;;
esac

# The installed files, as a CMake or pkg-config user meets them (install.sh with the debug build
# made above): find_package(motion_bound 0.1 REQUIRED) finds it and refuses 0.2 and 1.0; a
# program passing `mb_shape *parts[]` to mb_shape_compound builds with -Wall -Wextra -Werror
# and runs; the .pc file's comment is as written (the prefix only where it belongs).
prefix="$out/prefix"
MB_PROFILE=debug "$here/install.sh" "$prefix" > /dev/null
pc="$prefix/lib/pkgconfig/motion_bound.pc"
if head -n 1 "$pc" | grep -q "$prefix"; then echo "FAILED: the .pc comment names the prefix: $(head -n 1 "$pc")"; exit 1; fi
pc_version="$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --modversion motion_bound)"
[ "$pc_version" = "$(sed -n 's/^version = "\(.*\)"/\1/p' "$here/Cargo.toml" | head -n 1)" ] \
  || { echo "FAILED: pkg-config says version '$pc_version'"; exit 1; }
mkdir -p "$out/cmake"
cat > "$out/cmake/main.c" <<'C'
#include "motion_bound.h"
#include <stdio.h>
int main(void) {
    mb_shape *parts[2] = {NULL, NULL};
    mb_pose poses[2] = {{{-1, 0, 0}, {1, 0, 0, 0}}, {{1, 0, 0}, {1, 0, 0, 0}}};
    mb_shape *dumbbell = NULL;
    mb_shape_kind kind = MB_SHAPE_KIND_BALL;
    if (mb_shape_ball(0.3, &parts[0]) || mb_shape_ball(0.3, &parts[1]) ||
        mb_shape_compound(parts, poses, 2, &dumbbell) || mb_shape_get_kind(dumbbell, &kind))
        return 1;
    printf("kind %d\n", (int)kind);
    mb_shape_free(parts[0]);
    mb_shape_free(parts[1]);
    mb_shape_free(dumbbell);
    return kind == MB_SHAPE_KIND_COMPOUND ? 0 : 1;
}
C
for want in 0.1 0.2 1.0; do
  cat > "$out/cmake/CMakeLists.txt" <<C
cmake_minimum_required(VERSION 3.10)
project(uses_motion_bound C)
find_package(motion_bound $want REQUIRED)
add_executable(app main.c)
target_compile_options(app PRIVATE -std=c11 -Wall -Wextra -Werror -pedantic)
target_link_libraries(app PRIVATE motion_bound::motion_bound)
C
  rm -rf "$out/cmake/build"
  if cmake -S "$out/cmake" -B "$out/cmake/build" -DCMAKE_PREFIX_PATH="$prefix" > "$out/cmake/log" 2>&1; then
    [ "$want" = 0.1 ] || { echo "FAILED: find_package(motion_bound $want) accepted $pc_version"; exit 1; }
    cmake --build "$out/cmake/build" > "$out/cmake/log" 2>&1 || { cat "$out/cmake/log"; echo "FAILED: the CMake build"; exit 1; }
    "$out/cmake/build/app" > /dev/null || { echo "FAILED: the CMake-built program"; exit 1; }
  else
    [ "$want" != 0.1 ] || { cat "$out/cmake/log"; echo "FAILED: find_package(motion_bound 0.1 REQUIRED)"; exit 1; }
  fi
done
echo "installed files: pkg-config $pc_version, find_package(motion_bound 0.1) found (0.2 and 1.0 refused), mb_shape *parts[] builds with -Werror"
