#!/usr/bin/env bash
# example.sh [MODEL.xml]: sets up, builds, then runs the main job on a bundled
# example model (default: the powertrain on three mounts with limits): the
# checks of every user element (partials against finite differences,
# dependency audit), a 1 s simulation with its summary, and the costs per call.
# It installs only what this needs (setup.sh main) and builds without the
# tests (no cmocka); scripts/test.sh builds and runs those.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" main
"$root/scripts/build.sh" build -DUSRSUB_TESTS=OFF
export MS_USERDLL_DIR="$root/build"
model="$root/harness/examples/${1:-powertrain.xml}"
mkdir -p "$root/out"
echo "== usrsub-harness check $model"
"$root/build/usrsub-harness" check "$model"
echo "== usrsub-harness run $model (1 s, DOPRI5) -> out/run.csv"
"$root/build/usrsub-harness" run "$model" --end 1 --integrator dopri5 --out "$root/out/run.csv" --quiet
echo "== usrsub-harness bench $model"
"$root/build/usrsub-harness" bench "$model" --repeats 11
