#!/usr/bin/env bash
# equilibrium_matrix.sh [OUT_DIR]: what the static equilibrium's Newton matrix
# costs by default (run --static: from the Jacobian where that costs less,
# sim/simulation/equilibrium_matrix.h) and by differences (--jacobian fd), on
# every bundled example whose equilibrium takes a Newton iteration: the matrix
# the default took, the iterations, the right-hand sides and the solve's wall
# time (the median of five runs pinned to one processor). When OUT_DIR (default
# docs) holds performance.md, the table goes into its block "equilibrium",
# stamped with the commit, the date and the machine (scripts/stamp.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/docs}
stamp=$("$root/scripts/stamp.sh")
"$root/scripts/setup.sh" main >/dev/null
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$root/build" -j "$(nproc)" --target usrsub-harness usrsub >/dev/null
export MS_USERDLL_DIR="$root/build"
h="$root/build/usrsub-harness"
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0)
# the summary's line: "... in N Newton iterations (R right-hand sides, Newton
# matrix from the Jacobian | by differences, S s), ..." as "N R S Jacobian|differences"
equilibrium() {
  "${pin[@]}" "$h" run "$root/harness/examples/$1" --static --end 1e-9 --quiet \
      --jacobian "$2" 2>&1 |
    sed -n 's/.*the last in \([0-9]*\) Newton iterations (\([0-9]*\) right-hand sides, Newton matrix \([^,]*\), \([0-9.e+-]*\) s).*/\1 \2 \4 \3/p' |
    sed 's/from the Jacobian$/Jacobian/; s/by differences$/differences/'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
table=$(mktemp)
trap 'rm -f "$table"' EXIT
{
  echo "| model | default's matrix | iterations | right-hand sides, default | by differences | time, default (ms) | by differences (ms) |"
  echo "|---|---|---|---|---|---|---|"
  for model in $(cd "$root/harness/examples" && ls *.xml); do
    # a model with no equilibrium (a part nothing holds), or at it from the start: none
    read -r it rhs_a _ matrix < <(equilibrium "$model" analytic) || continue
    [ "$it" -gt 0 ] || continue
    read -r it_f rhs_f _ < <(equilibrium "$model" fd)
    ta=$(for k in 1 2 3 4 5; do equilibrium "$model" analytic | awk '{ print $3 }'; done | median)
    tf=$(for k in 1 2 3 4 5; do equilibrium "$model" fd | awk '{ print $3 }'; done | median)
    iters=$it
    [ "$it" = "$it_f" ] || iters="$it (by differences $it_f)"
    awk -v m="$model" -v k="$matrix" -v i="$iters" -v ra="$rhs_a" -v rf="$rhs_f" -v ta="$ta" \
        -v tf="$tf" 'BEGIN { printf "| `%s` | %s | %s | %s | %s | %.3g | %.3g |\n", m, k, i, ra,
                                    rf, 1000 * ta, 1000 * tf }'
  done
} > "$table"
cat "$table"
if [ -f "$out/performance.md" ]; then
  "$root/scripts/doc_block.sh" "$out/performance.md" equilibrium "scripts/equilibrium_matrix.sh" \
      "$stamp" < "$table"
  echo "wrote the equilibrium table of $out/performance.md"
fi
