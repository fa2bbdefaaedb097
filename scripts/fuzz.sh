#!/usr/bin/env bash
# fuzz.sh [SECONDS]: builds the libFuzzer targets with clang (build-fuzz/) and
# runs each on its seed corpus (fuzz/corpus/) for SECONDS (default 20). A
# crash, a leak or a sanitizer report fails the script; the input that caused
# it is kept in build-fuzz/artifacts/ (add it to the corpus and to a test).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-20}
"$root/scripts/setup.sh" fuzz
CC=clang "$root/scripts/build.sh" build-fuzz -DUSRSUB_FUZZ=ON -DUSRSUB_TESTS=OFF
mkdir -p "$root/build-fuzz/artifacts"
for target in teimorbit user_lists model_xml; do
  work="$root/build-fuzz/corpus/$target"
  mkdir -p "$work"
  echo "== fuzz_$target for $seconds s"
  status=0
  "$root/build-fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=4096 \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$root/build-fuzz/artifacts/$target-" \
      "$work" "$root/fuzz/corpus/$target" >"$root/build-fuzz/fuzz_$target.log" 2>&1 || status=$?
  grep -E "^stat::(number_of_executed_units|peak_rss_mb)|^#[0-9]+ +DONE" "$root/build-fuzz/fuzz_$target.log" || true
  if [ "$status" -ne 0 ]; then
    tail -40 "$root/build-fuzz/fuzz_$target.log"
    echo "fuzz_$target failed (exit $status); its log: build-fuzz/fuzz_$target.log"
    exit 1
  fi
  if ls "$root/build-fuzz/artifacts/$target-"* >/dev/null 2>&1; then
    echo "fuzz_$target found a failing input: $(ls "$root/build-fuzz/artifacts/$target-"*)"
    exit 1
  fi
done
echo "== fuzzing found nothing"
