#!/usr/bin/env bash
# Builds motion-bound-c (debug), compiles tests/c/test_motion_bound.c against its static
# library with AddressSanitizer and UndefinedBehaviorSanitizer, and runs it with
# LeakSanitizer on, and tests/c/test_chain.c (chains) likewise: any sanitizer report, leak or
# failed check fails the script. Also checks that the C tests call every function the header declares. Usage: tests/run_c_tests.sh
# (from anywhere; CC overrides the compiler, default cc).
set -euo pipefail
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
