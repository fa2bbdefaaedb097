#!/usr/bin/env bash
# fuzz.sh [SECONDS]: builds the libFuzzer targets with clang (build-fuzz/) and
# runs each on its seed corpus (fuzz/corpus/) for SECONDS (default 20),
# growing build-fuzz/corpus/ from run to run.
# fuzz.sh --fixed: what the tests run: each target from the seed corpus alone,
# with a fixed seed and a fixed number of inputs (about 20 s each here), so
# that a machine's speed does not change what is tried.
# A crash, a leak or a sanitizer report fails the script; the input that caused
# it is kept in build-fuzz/artifacts/ (add it to fuzz/corpus/ and to a test).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fixed=0
seconds=20
if [ "${1:-}" = "--fixed" ]; then fixed=1; else seconds=${1:-20}; fi
"$root/scripts/setup.sh" fuzz
CC=clang "$root/scripts/build.sh" build-fuzz -DUSRSUB_FUZZ=ON -DUSRSUB_TESTS=OFF
mkdir -p "$root/build-fuzz/artifacts"
# inputs per target in --fixed mode (about 20 s each on the reference machine)
declare -A fixed_runs=([teimorbit]=50000 [user_lists]=1500000 [model_xml]=500000 [expr]=500000 [model_adm]=150000)
for target in teimorbit user_lists model_xml expr model_adm; do
  if [ "$fixed" -eq 1 ]; then
    work=$(mktemp -d)
    limits=(-seed=1 -runs="${fixed_runs[$target]}" -max_total_time=300)
    echo "== fuzz_$target: ${fixed_runs[$target]} inputs from seed 1"
  else
    work="$root/build-fuzz/corpus/$target"
    mkdir -p "$work"
    limits=(-max_total_time="$seconds")
    echo "== fuzz_$target for $seconds s"
  fi
  status=0
  "$root/build-fuzz/fuzz_$target" "${limits[@]}" -max_len=4096 \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$root/build-fuzz/artifacts/$target-" \
      "$work" "$root/fuzz/corpus/$target" >"$root/build-fuzz/fuzz_$target.log" 2>&1 || status=$?
  if [ "$fixed" -eq 1 ]; then rm -rf "$work"; fi
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
