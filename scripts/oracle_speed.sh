#!/bin/sh
# oracle_speed.sh BUILD_DIR [WORKDIR]: the harness against Simbody on the same
# constrained models, side by side in one run (docs/performance.md, "Against
# Simbody"). Needs a build with the Simbody oracle (tests/oracle/, built when
# libsimbody-dev is found and USRSUB_TESTS is on).
#
# Per model (the chain of scripts/joint_chain_model.sh at N = 8, 32, 128; the
# oracle's slider_crank and double_spherical):
#   - the reference: Simbody at accuracy REF (1e-10), a row every INTERVAL;
#   - Simbody at accuracy A (1e-6): its error, the median wall time of its
#     integration over 3 runs (`simbody_oracle --time`: the calls of stepTo),
#     its realizations of accelerations (its right-hand sides);
#   - the harness with DOPRI5 and with BDF: the loosest rtol of the ladder
#     RTOLS (atol = rtol / 100) whose error is at most Simbody's ("equal
#     error"), then the median over 3 runs of its stepping time (the run's
#     right-hand sides times its time per right-hand side: neither reading
#     the model nor writing rows) and its right-hand sides.
# The error of a run: the largest distance between a body's centre of mass
# and the reference's, over the bodies and the rows, divided by the model's
# size L (its reach: 0.2 N for the chain). Both engines write a row every
# INTERVAL; Simbody ends a step at each (no interpolation), the harness
# interpolates.
#
# Environment: END (0.5 s), INTERVAL (0.05 s), A (1e-6), REF (1e-10),
# RTOLS (1e-3 .. 1e-10 by half decades), CHAINS ("8 32 128"), BDF_MAX_N (32:
# BDF's constraint blocks make it slow on long chains, docs/performance.md),
# COUNT (1: also the instructions of the integration alone under callgrind,
# per right-hand side and per simulated second, deterministic where the wall
# times wander with the machine's load; 0 without valgrind).
# Prints a Markdown table, with the machine's load and the command.
#
# oracle_speed.sh --joints BUILD_DIR [WORKDIR]: the table of docs/performance.md,
# "Joints between bodies": for the chain at N = 8 .. 256 (NS), `bench`'s
# right-hand side (its median, --repeats 5), the time per right-hand side of
# `run --integrator rk4 --step 1e-4 --end 0.005` (50 steps, with the
# projection after each), and, deterministic whatever the machine's load, the
# instructions per right-hand side under callgrind (`run --integrator rk4
# --step 1e-4 --end 0.001`: the inclusive count of the integrator's rhs in
# sim/simulation/simulation.c over its calls, and of hx_integrate, which adds
# the projection and the step, over the same calls); then the exponent p of a
# least-squares fit cost ~ N^p over the N given, per column.
set -eu

if [ "${1:-}" = --joints ]; then
    shift
    [ $# -ge 1 ] || { echo "usage: $0 --joints BUILD_DIR [WORKDIR]" >&2; exit 2; }
    harness=$1/usrsub-harness
    work=${2:-${TMPDIR:-/tmp}/oracle_speed.$$}
    root=$(cd "$(dirname "$0")/.." && pwd)
    [ -x "$harness" ] || { echo "$0: no $harness" >&2; exit 2; }
    command -v callgrind_annotate >/dev/null || { echo "$0: no valgrind (callgrind_annotate)" >&2; exit 2; }
    NS=${NS:-"8 16 32 64 128 256"}
    mkdir -p "$work"
    echo "Load: $(uptime | sed 's/.*load average/load average/'), $(nproc) processors."
    echo
    echo "| N | rows | \`bench\`: right-hand side | RK4 run: per right-hand side, with the projection | callgrind: instructions per right-hand side | the same with the projection and the step |"
    echo "|---|---|---|---|---|---|"
    for n in $NS; do
        xml=$work/chain$n.xml
        sh "$root/scripts/joint_chain_model.sh" "$n" "$xml"
        bench=$("$harness" bench "$xml" --repeats 5 2>&1 | awk '/^right-hand side: / { print $3 / 1000 }')
        rk4=$("$harness" run "$xml" --integrator rk4 --step 1e-4 --end 0.005 --quiet 2>&1 |
              awk '/us per right-hand side/ { v = $0; sub(/.*\(/, "", v); sub(/ us.*/, "", v); print v }')
        valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.$n" "$harness" run "$xml" \
            --integrator rk4 --step 1e-4 --end 0.001 --quiet >/dev/null 2>&1
        callgrind_annotate --inclusive=yes --tree=caller "$work/callgrind.$n" >"$work/annotate.$n" 2>/dev/null
        # the rhs's calls from its callers' lines ("< ...simulation.c:rhs (40x)"), its inclusive count
        # from its own line ("* ...simulation.c:rhs"); hx_integrate's inclusive count likewise
        awk -v n="$n" -v bench="$bench" -v rk4="$rk4" '
            function count(line) { sub(/^ +/, "", line); sub(/ .*/, "", line); gsub(/,/, "", line); return line + 0 }
            /\* .*simulation\.c:rhs / { rhs = count($0) }
            /< .*simulation\.c:rhs \(/ && !calls { v = $0; sub(/.*\(/, "", v); sub(/x\).*/, "", v); calls = v + 0 }
            /\* .*ode\/integrator\.c:hx_integrate / { integ = count($0) }
            END {
                if (!calls) { print "| " n " | (no rhs in the profile) |"; exit }
                printf "| %d | %d | %.3g us | %.3g us | %.4g | %.4g |\n", n, 3 * n, bench, rk4, rhs / calls, integ / calls
            }' "$work/annotate.$n"
    done | tee "$work/joints.txt"
    # the fitted exponents: least squares of log cost on log N, per column
    awk -F'|' '{ n = $2 + 0; if (n <= 0) next
                 for (c = 4; c <= 7; c++) { v = $c; gsub(/[^0-9.e+-]/, "", v); if (v + 0 > 0) {
                     x = log(n); y = log(v + 0); sx[c] += x; sy[c] += y; sxx[c] += x * x; sxy[c] += x * y; k[c]++ } } }
               END { split("bench rk4-run callgrind callgrind-with-projection-and-step", name, " ")
                     printf "\nFitted exponent p (cost ~ N^p, least squares over the rows):"
                     for (c = 4; c <= 7; c++) if (k[c] > 1)
                         printf " %s %.3f;", name[c - 3], (k[c] * sxy[c] - sx[c] * sy[c]) / (k[c] * sxx[c] - sx[c] * sx[c])
                     printf "\n" }' "$work/joints.txt"
    echo "Load after: $(uptime | sed 's/.*load average/load average/')."
    exit 0
fi

[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [WORKDIR]" >&2; exit 2; }
build=$1
work=${2:-${TMPDIR:-/tmp}/oracle_speed.$$}
root=$(cd "$(dirname "$0")/.." && pwd)
harness=$build/usrsub-harness oracle=$build/simbody_oracle compare=$build/oracle_compare
for tool in "$harness" "$oracle" "$compare"; do
    [ -x "$tool" ] || { echo "$0: no $tool (build with -DUSRSUB_TESTS=ON and libsimbody-dev)" >&2; exit 2; }
done
END=${END:-0.5} INTERVAL=${INTERVAL:-0.05} A=${A:-1e-6} REF=${REF:-1e-10}
RTOLS=${RTOLS:-"1e-3 3e-4 1e-4 3e-5 1e-5 3e-6 1e-6 3e-7 1e-7 3e-8 1e-8 3e-9 1e-9 3e-10 1e-10"}
CHAINS=${CHAINS:-"8 32 128"} BDF_MAX_N=${BDF_MAX_N:-32}
COUNT=${COUNT:-1}
command -v callgrind_annotate >/dev/null || COUNT=0
mkdir -p "$work"

# error FILE L: the largest position difference from the reference over L
error() {
    "$compare" "$work/ref.csv" "$1" --label x --position-tol 1e-4 --angle-tol 1 --velocity-tol 1 \
        --angular-velocity-tol 1 >"$work/compare.txt" 2>&1 || true
    awk -v L="$2" '/position +largest difference/ { for (k = 1; k <= NF; k++) if ($k == "difference") { printf "%.3g\n", $(k + 1) / L; f = 1 } }
                   END { if (!f) print "nan" }' "$work/compare.txt"
}

# median of three numbers
median3() { printf '%s\n%s\n%s\n' "$1" "$2" "$3" | sort -g | sed -n 2p; }

# run_simbody ARGS...: one timed run at accuracy A; sets s_time s_rhs
run_simbody() {
    "$oracle" "$@" --out "$work/simbody.csv" --end "$END" --interval "$INTERVAL" --accuracy "$A" --time \
        >"$work/simbody.txt"
    s_time=$(awk '/^simbody_oracle time:/ { print $4 }' "$work/simbody.txt")
    s_rhs=$(awk '/^simbody_oracle time:/ { v = $7; sub(/,/, "", v); print v }' "$work/simbody.txt")
}

# run_harness XML METHOD RTOL: one run; sets h_time h_rhs (0 0 when it fails)
run_harness() {
    atol=$(awk -v r="$3" 'BEGIN { printf "%.3g", r / 100 }')
    if "$harness" run "$1" --end "$END" --output-interval "$INTERVAL" --integrator "$2" --rtol "$3" \
        --atol "$atol" --out "$work/harness.csv" >"$work/harness.txt" 2>&1; then
        h_rhs=$(awk '/right-hand sides [0-9]/ { for (k = 1; k <= NF; k++) if ($k == "sides") { v = $(k + 1); sub(/,/, "", v); print v } }' "$work/harness.txt")
        h_time=$(awk -v n="$h_rhs" '/us per right-hand side/ { v = $0; sub(/.*\(/, "", v); sub(/ us.*/, "", v); printf "%.6f\n", v * n * 1e-6 }' "$work/harness.txt")
    else
        h_time=0 h_rhs=0
    fi
}

# instructions COMMAND...: the inclusive instruction count, under callgrind, of
# the integration alone (Simbody's Integrator::stepTo, the harness's
# hx_integrate): deterministic, whatever the machine's load ("-" without COUNT)
instructions() {
    if [ "$COUNT" != 1 ]; then echo -; return; fi
    valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" "$@" >/dev/null 2>&1 || { echo -; return; }
    callgrind_annotate --inclusive=yes "$work/callgrind.out" 2>/dev/null | awk '
        /SimTK::Integrator::stepTo\(|ode\/integrator\.c:hx_integrate / && !found {
            v = $1; gsub(/,/, "", v); print v; found = 1 }
        END { if (!found) print "-" }'
}

row() { # engine setting error time rhs instructions
    awk -v m="$model" -v e="$1" -v s="$2" -v err="$3" -v t="$4" -v n="$5" -v ir="$6" -v end="$END" 'BEGIN {
        printf "| %s | %s | %s | %s | %.3g s | %d | %.3g us | %.3g s |", m, e, s, err, t, n,
               (n > 0 ? 1e6 * t / n : 0), t / end
        if (ir == "-") printf " - | - |\n"
        else printf " %.3g | %.3g |\n", (n > 0 ? ir / n : 0), ir / end }'
}

# one model: NAME L XML ORACLE-ARGS...
measure() {
    model=$1 L=$2 xml=$3 nbodies=$4
    shift 4
    "$oracle" "$@" --out "$work/ref.csv" --end "$END" --interval "$INTERVAL" --accuracy "$REF" >/dev/null
    run_simbody "$@"; t1=$s_time
    run_simbody "$@"; t2=$s_time
    run_simbody "$@"; t3=$s_time
    s_err=$(error "$work/simbody.csv" "$L")
    ir=$(instructions "$oracle" "$@" --out "$work/simbody.csv" --end "$END" --interval "$INTERVAL" --accuracy "$A")
    row "Simbody RK-Merson" "accuracy $A" "$s_err" "$(median3 "$t1" "$t2" "$t3")" "$s_rhs" "$ir"
    for method in dopri5 bdf; do
        if [ "$method" = bdf ] && [ "$nbodies" -gt "$BDF_MAX_N" ]; then
            echo "| $model | harness BDF | (not run: more than $BDF_MAX_N bodies) | | | | | | | |"
            continue
        fi
        found=""
        for rtol in $RTOLS; do
            run_harness "$xml" "$method" "$rtol"
            [ "$h_rhs" != 0 ] || continue
            err=$(error "$work/harness.csv" "$L")
            if awk -v a="$err" -v b="$s_err" 'BEGIN { exit !(a <= b) }'; then
                found=$rtol
                break
            fi
        done
        if [ -z "$found" ]; then
            echo "| $model | harness $method | (no rtol of the ladder reaches $s_err) | | | | | | | |"
            continue
        fi
        t1=$h_time
        run_harness "$xml" "$method" "$found"; t2=$h_time
        run_harness "$xml" "$method" "$found"; t3=$h_time
        ir=$(instructions "$harness" run "$xml" --end "$END" --output-interval "$INTERVAL" --integrator "$method" \
            --rtol "$found" --atol "$(awk -v r="$found" 'BEGIN { printf "%.3g", r / 100 }')" --out "$work/harness.csv" --quiet)
        row "harness $(echo "$method" | tr "[:lower:]" "[:upper:]")" "rtol $found" "$err" "$(median3 "$t1" "$t2" "$t3")" "$h_rhs" "$ir"
    done
}

echo "Load: $(uptime | sed 's/.*load average/load average/'), $(nproc) processors."
echo "Command: END=$END INTERVAL=$INTERVAL A=$A REF=$REF CHAINS=\"$CHAINS\" BDF_MAX_N=$BDF_MAX_N COUNT=$COUNT scripts/oracle_speed.sh BUILD_DIR"
echo "Error: the largest position error over the run / the model's size L, against Simbody at accuracy $REF."
echo
echo "| model | engine | setting | error / L | wall time (median of 3) | right-hand sides | per right-hand side | per simulated second | instructions per right-hand side | instructions per simulated second |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for n in $CHAINS; do
    sh "$root/scripts/joint_chain_model.sh" "$n" "$work/chain$n.xml"
    L=$(awk -v n="$n" 'BEGIN { print 0.2 * n }')
    measure "chain $n" "$L" "$work/chain$n.xml" "$n" chain --bodies "$n"
done
# the oracle's mechanisms: L as in tests/oracle/simbody_oracle_agrees.sh
measure slider_crank 0.45 "$root/tests/oracle/slider_crank.xml" 3 slider_crank
measure double_spherical 0.9 "$root/tests/oracle/double_spherical.xml" 2 double_spherical
echo
echo "Load after: $(uptime | sed 's/.*load average/load average/')."
