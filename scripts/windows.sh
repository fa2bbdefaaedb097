#!/usr/bin/env bash
# windows.sh: usrsub.dll against libusrsub.so (docs/windows.md). Sets up,
# builds build/ (with the tests) and build-windows/ (mingw-w64:
# cmake/mingw-w64-x86_64.cmake), checks what usrsub.dll exports and imports,
# then runs one test host (tests/windows/entry_host.c) over every element of
# the bundled models: on Linux against libusrsub.so, and under Wine against
# usrsub.dll with the stand-in asutility.dll. The two outputs must agree to
# 1e-12 relative (1e-15 absolute near zero), and a planted difference must
# fail that comparison. Skips, saying so, only when Wine cannot run a
# Windows program on this machine at all.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
start=$SECONDS
"$root/scripts/setup.sh" windows

"$root/scripts/build.sh" build -DUSRSUB_TESTS=ON
"$root/scripts/build.sh" build-windows -DCMAKE_TOOLCHAIN_FILE="$root/cmake/mingw-w64-x86_64.cmake"
linux=$root/build
win=$root/build-windows
utility=$(sed -n 's/^USRSUB_UTILITY_DLL:STRING=//p' "$win/CMakeCache.txt")
"$root/tests/windows/check_dll.sh" x86_64-w64-mingw32-objdump "$win/usrsub.dll" "$utility" \
  "$root/usrsub/entries/host_utilities.def"

out=$win/compare
mkdir -p "$out"
"$linux/entry_host" "$linux/libusrsub.so" "$linux/libasutility.so" "$linux/model_cases.txt" \
  "$root/harness/examples" "$out/linux.txt" | sed 's/^/linux:   /'

# A private Wine prefix beside the build; no Mono or Gecko installers (they
# would ask); Wine's messages kept for a failure. Wine maps / to drive Z:.
export WINEPREFIX=$win/wine WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
windows_path() { printf 'Z:%s' "$1" | tr / '\\'; }
trap 'wineserver -k >/dev/null 2>&1 || true' EXIT
if ! probe=$(wine "$win/entry_host.exe" --probe 2>"$out/wine.log"); then
  echo "windows: SKIPPED: Wine cannot run a Windows program on this machine:"
  tail -5 "$out/wine.log" | sed 's/^/  /'
  exit 0
fi
if [ "${probe//$'\r'/}" != "entry_host runs" ]; then
  echo "windows: the test host under Wine printed '$probe' when probed"
  exit 1
fi
if ! wine "$win/entry_host.exe" "$(windows_path "$win/usrsub.dll")" \
     "$(windows_path "$win/$utility")" "$(windows_path "$linux/model_cases.txt")" \
     "$(windows_path "$root/harness/examples")" "$(windows_path "$out/windows.txt")" \
     2>>"$out/wine.log" | tr -d '\r' | sed 's/^/windows: /'; then
  echo "windows: the test host failed under Wine:"
  tail -20 "$out/wine.log" | sed 's/^/  /'
  exit 1
fi

"$linux/compare_outputs" "$out/linux.txt" "$out/windows.txt"
"$root/tests/windows/compare_test.sh" "$linux/compare_outputs" "$out/windows.txt"
echo "windows: usrsub.dll under Wine matches libusrsub.so ($((SECONDS - start)) s)"
