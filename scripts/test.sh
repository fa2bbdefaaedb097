#!/usr/bin/env bash
# Sets up, then builds and runs every test: the normal build and the
# AddressSanitizer + UndefinedBehaviorSanitizer build.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
cores=$(nproc)

echo "== build and test (RelWithDebInfo)"
"$root/scripts/build.sh" build
(cd "$root/build" && ctest --output-on-failure -j "$cores")

echo "== build and test (AddressSanitizer + UndefinedBehaviorSanitizer)"
"$root/scripts/build.sh" build-asan -DUSRSUB_SANITIZE=ON
(cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure -j "$cores")
echo "== all tests passed"
