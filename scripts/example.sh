#!/usr/bin/env bash
# Sets up, builds, then checks and runs the bundled example model.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh" build
export MS_USERDLL_DIR="$root/build"
model="$root/harness/examples/${1:-bevel_gears.xml}"
echo "== usrsub-harness check $model"
"$root/build/usrsub-harness" check "$model"
