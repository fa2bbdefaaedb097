#!/usr/bin/env bash
# Sets up, then builds and runs every test: the normal build; the Debug and
# Release builds (built, not run: the others are RelWithDebInfo); usrsub.dll
# under Wine against the Linux library (scripts/windows.sh); the
# AddressSanitizer + UndefinedBehaviorSanitizer build; the ThreadSanitizer
# build; valgrind on unloading and reloading the
# library; and a brief, reproducible run of each libFuzzer target (a fixed
# seed and number of inputs: scripts/fuzz.sh --fixed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" test
cores=$(nproc)

echo "== build and test (RelWithDebInfo)"
# tests on explicitly: example.sh and plots.sh configure build/ without them
"$root/scripts/build.sh" build -DUSRSUB_TESTS=ON
(cd "$root/build" && ctest --output-on-failure -j "$cores")

echo "== build (Debug, Release): warnings are errors in every build type"
# every other build here is RelWithDebInfo, and the compiler's analyses differ
# by type (Debug once failed on a format truncation the others did not see):
# the other two are built, not run. Debug builds everything (-O0 is cheap);
# Release the library and the harness, without the tests, whose link-time
# optimization of some fifty test programs would cost five times as much.
"$root/scripts/build.sh" build-debug -DCMAKE_BUILD_TYPE=Debug -DUSRSUB_TESTS=ON
"$root/scripts/build.sh" build-release -DCMAKE_BUILD_TYPE=Release -DUSRSUB_TESTS=OFF

echo "== Windows: usrsub.dll (mingw-w64) under Wine against libusrsub.so"
"$root/scripts/windows.sh"

echo "== build and test (AddressSanitizer + UndefinedBehaviorSanitizer)"
"$root/scripts/build.sh" build-asan -DUSRSUB_SANITIZE=ON
(cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure -j "$cores")

echo "== build and test (ThreadSanitizer, every test; test_concurrency sets up and calls every entry from four threads)"
"$root/scripts/build.sh" build-tsan -DUSRSUB_THREAD_SANITIZER=ON
# handle_segv=0: check's own crash report (a user library that crashes, in a
# child process) is what the tests look for, not the sanitizer's
(cd "$root/build-tsan" && TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 handle_segv=0" \
   ctest --output-on-failure -j "$cores")

echo "== valgrind: unload and reload leak nothing"
(cd "$root/build" && MS_USERDLL_DIR="$root/build" valgrind -q --leak-check=full \
   --errors-for-leak-kinds=definite,indirect --error-exitcode=1 ./test_reload >/dev/null)

echo "== fuzz (brief and reproducible: a fixed seed and number of inputs per target)"
"$root/scripts/fuzz.sh" --fixed
echo "== all tests passed"
