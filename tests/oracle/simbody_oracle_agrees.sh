#!/usr/bin/env bash
# The harness judged by Simbody (docs/testing.md, "The Simbody oracle").
#
#   simbody_oracle_agrees.sh ORACLE COMPARE WORKDIR HARNESS
#     each model of this folder: Simbody's trajectory (simbody_oracle) against
#     `usrsub-harness run` with DOPRI5 and with BDF over 1 s, at every 0.01 s,
#     within the tolerances below (oracle_compare); then the negative control:
#     mutant_double_spherical.xml (the lower link 1 % heavier) must disagree
#     with the oracle's double_spherical.
#   simbody_oracle_agrees.sh --converged ORACLE COMPARE WORKDIR
#     the oracle's own precision: each model at Simbody's accuracy 1e-12
#     against 1e-14, within 1e-9 in every quantity.
#   simbody_oracle_agrees.sh --chain N ORACLE COMPARE WORKDIR HARNESS
#     the chain of N bars on spherical joints (scripts/joint_chain_model.sh N
#     for the harness, `simbody_oracle chain --bodies N` for Simbody) over
#     0.5 s, at every 0.01 s, DOPRI5 and BDF, at the tight tolerances below;
#     then its negative control: the same chain with the last bar 1 % heavier
#     must disagree. Also the oracle's --time line (read by
#     scripts/oracle_speed.sh) and its refusals of a bad --bodies.
#
# Tolerances, per model of size L (its largest reach): position 1e-6 L,
# orientation 1e-6 rad, velocity 1e-5 L/s, angular velocity 1e-5 rad/s.
# The oracle is within 1e-11 of its converged trajectory; the harness's runs
# (rtol 1e-10, atol 1e-12) are asked for far less than the tolerances, which
# leave room for the integrators' global error and the CSV's 12 digits and
# are still a thousandth of what a 1 % error of a mass moves (the control).
set -u
converged=0
if [ "${1:-}" = --converged ]; then
  converged=1
  shift
fi
chain=0
if [ "${1:-}" = --chain ]; then
  chain=$2
  shift 2
fi
oracle=$1 compare=$2 work=$3 harness=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
end=1 interval=0.01

# The chain: size L = 0.2 N (its length). Tolerances a hundred times tighter
# in position and velocity than the mechanisms' below (1e-8 L, 1e-7 rad,
# 1e-7 L/s, 1e-6 rad/s): at N = 8 over 0.5 s DOPRI5 is within 2e-11 m and BDF
# within 5e-10 m, 2e-8 rad, 4e-7 rad/s of the oracle; a 1 % heavier last bar
# moves it by millimetres.
if [ "$chain" != 0 ]; then
  L=$(awk -v n="$chain" 'BEGIN { printf "%.3g", 0.2 * n }')
  tight=$(awk -v L="$L" 'BEGIN { printf "--position-tol %.3g --angle-tol 1e-7 --velocity-tol %.3g --angular-velocity-tol 1e-6", 1e-8 * L, 1e-7 * L }')
  end=0.5
  failures=0
  sh "$here/../../scripts/joint_chain_model.sh" "$chain" "$work/chain$chain.xml" || exit 1
  # the control: bar N (body N + 1) 1 % heavier, nothing else changed
  sed "s/<Body_Rigid id=\"$((chain + 1))\" \(.*\) mass=\"1\"/<Body_Rigid id=\"$((chain + 1))\" \1 mass=\"1.01\"/" \
    "$work/chain$chain.xml" >"$work/mutant_chain$chain.xml"
  if cmp -s "$work/chain$chain.xml" "$work/mutant_chain$chain.xml"; then
    echo "FAIL chain $chain: the control's mass was not changed"
    exit 1
  fi
  "$oracle" chain --bodies "$chain" --out "$work/chain$chain.oracle.csv" --end $end --interval $interval \
    --time >"$work/chain$chain.oracle.txt" || { echo "FAIL chain $chain: the oracle did not run"; exit 1; }
  cat "$work/chain$chain.oracle.txt"
  # --time, in the words scripts/oracle_speed.sh reads: a positive time, and
  # realizations of Runge-Kutta-Merson's 5 stages per attempted step (4 to 6)
  if ! awk '/^simbody_oracle time: integration / { t = $4; r = $7; a = $11; sub(/,/, "", r); sub(/,/, "", a)
            ok = t > 0 && r >= 4 * a && r <= 6 * a && a > 0 }
            END { exit !ok }' "$work/chain$chain.oracle.txt"; then
    echo "FAIL chain $chain: the oracle's --time line is missing or its counts do not fit"
    failures=$((failures + 1))
  fi
  for bad in "chain --out x" "chain --bodies 0 --out x" "chain --bodies 1025 --out x" "double_spherical --bodies 2 --out x"; do
    # shellcheck disable=SC2086 # the words of a command line
    "$oracle" $bad 2>"$work/bad.txt" >/dev/null
    status=$?
    if [ "$status" != 2 ] || ! grep -q -- "--bodies" "$work/bad.txt"; then
      echo "FAIL simbody_oracle $bad: exit $status, not 2 with a message naming --bodies"
      failures=$((failures + 1))
    fi
  done
  for integrator in dopri5 bdf mutant; do
    model="$work/chain$chain.xml" method=$integrator
    if [ "$integrator" = mutant ]; then model="$work/mutant_chain$chain.xml" method=dopri5; fi
    run="$work/chain$chain.$integrator.csv"
    if ! "$harness" run "$model" --end $end --output-interval $interval --integrator $method \
         --rtol 1e-10 --atol 1e-12 --out "$run" --quiet >"$work/chain$chain.$integrator.log" 2>&1; then
      echo "FAIL chain $chain ($integrator): the harness did not run it:"
      sed 's/^/  /' "$work/chain$chain.$integrator.log" | head -5
      failures=$((failures + 1))
      continue
    fi
    # shellcheck disable=SC2086 # the options are words
    "$compare" "$work/chain$chain.oracle.csv" "$run" --label "chain $chain ($integrator)" $tight
    status=$?
    if [ "$integrator" = mutant ]; then
      if [ "$status" = 1 ]; then
        echo "negative control: the chain with its last bar 1 % heavier disagrees with the oracle, as it must"
      else
        echo "FAIL negative control: the 1 % heavier last bar was not told apart (oracle_compare exit $status)"
        failures=$((failures + 1))
      fi
    elif [ "$status" != 0 ]; then
      echo "FAIL chain $chain ($integrator)"
      failures=$((failures + 1))
    fi
  done
  if [ "$failures" -ne 0 ]; then
    echo "simbody_oracle_agrees: chain $chain: $failures failure(s)"
    exit 1
  fi
  echo "simbody_oracle_agrees: chain $chain agrees"
  exit 0
fi

# model, size L (m): the largest reach of its bodies from the origin over the run
models="pendulum_i_ground 0.3
double_spherical 0.9
revolute_universal 0.55
slider_crank 0.45
cylindrical_on_moving 1.8"

failures=0
tolerances() { # size -> the compare options
  awk -v L="$1" 'BEGIN { printf "--position-tol %.3g --angle-tol 1e-6 --velocity-tol %.3g --angular-velocity-tol 1e-5\n", 1e-6 * L, 1e-5 * L }'
}

while read -r name size; do
  if ! "$oracle" "$name" --out "$work/$name.oracle.csv" --end $end --interval $interval; then
    echo "FAIL $name: the oracle did not run"
    failures=$((failures + 1))
    continue
  fi
  if [ "$converged" = 1 ]; then
    "$oracle" "$name" --out "$work/$name.oracle14.csv" --end $end --interval $interval --accuracy 1e-14 >/dev/null &&
    "$compare" "$work/$name.oracle14.csv" "$work/$name.oracle.csv" --label "$name oracle 1e-12 vs 1e-14" \
      --position-tol 1e-9 --angle-tol 1e-9 --velocity-tol 1e-9 --angular-velocity-tol 1e-9 ||
      { echo "FAIL $name: the oracle has not converged"; failures=$((failures + 1)); }
    continue
  fi
  for integrator in dopri5 bdf; do
    run="$work/$name.$integrator.csv"
    if ! "$harness" run "$here/$name.xml" --end $end --output-interval $interval --integrator $integrator \
         --rtol 1e-10 --atol 1e-12 --out "$run" --quiet >"$work/$name.$integrator.log" 2>&1; then
      echo "FAIL $name ($integrator): the harness did not run it:"
      sed 's/^/  /' "$work/$name.$integrator.log" | head -5
      failures=$((failures + 1))
      continue
    fi
    # shellcheck disable=SC2046 # the options are words
    "$compare" "$work/$name.oracle.csv" "$run" --label "$name ($integrator)" $(tolerances "$size") ||
      { echo "FAIL $name ($integrator)"; failures=$((failures + 1)); }
  done
done <<<"$models"

if [ "$converged" = 0 ]; then
  # The negative control: a model 1 % off in one mass must be told apart.
  mutant="$work/mutant_double_spherical.dopri5.csv"
  if "$harness" run "$here/mutant_double_spherical.xml" --end $end --output-interval $interval \
       --rtol 1e-10 --atol 1e-12 --out "$mutant" --quiet >"$work/mutant.log" 2>&1; then
    # shellcheck disable=SC2046
    "$compare" "$work/double_spherical.oracle.csv" "$mutant" --label "mutant_double_spherical (dopri5)" \
      $(tolerances 0.9)
    status=$?
    if [ "$status" = 1 ]; then
      echo "negative control: the 1 % heavier lower link disagrees with the oracle, as it must"
    else
      echo "FAIL negative control: the 1 % heavier lower link was not told apart (oracle_compare exit $status)"
      failures=$((failures + 1))
    fi
  else
    echo "FAIL negative control: the harness did not run mutant_double_spherical.xml:"
    sed 's/^/  /' "$work/mutant.log" | head -5
    failures=$((failures + 1))
  fi
fi

if [ "$failures" -ne 0 ]; then
  echo "simbody_oracle_agrees: $failures failure(s)"
  exit 1
fi
echo "simbody_oracle_agrees: all agree"
