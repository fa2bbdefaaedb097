#!/usr/bin/env bash
# compare_test.sh COMPARE_OUTPUTS OUTPUT: the comparison of scripts/windows.sh
# can fail. OUTPUT (an entry_host output) must match itself, a copy with one
# value changed by 1e-15 of its size and one with a zero made 1e-16 (below
# the absolute floor); a copy with one value changed by 1e-10 of its size, a
# zero made 1e-13, one word changed or one line missing must not.
set -u
compare=$1
output=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
complain() { echo "compare_test: $*"; failures=$((failures + 1)); }

# OUTPUT with the first value larger than 1 in size multiplied by 1 + $1
scaled() {
  awk -v f="$1" '!done { eq = 0
                         for (k = 1; k <= NF; ++k) {
                           if ($k == "=") { eq = 1; continue }
                           if (eq && ($k + 0 > 1 || $k + 0 < -1)) {
                             $k = sprintf("%.17g", $k * (1 + f)); done = 1; break } } }
                 { print }' "$output"
}

# OUTPUT with the first zero value made $1
unzeroed() {
  awk -v v="$1" '!done { eq = 0
                         for (k = 1; k <= NF; ++k) {
                           if ($k == "=") { eq = 1; continue }
                           if (eq && ($k == "0" || $k == "-0")) { $k = v; done = 1; break } } }
                 { print }' "$output"
}

expect() { # expect pass|fail NAME FILE
  if "$compare" "$output" "$3" >"$work/log" 2>&1; then result=pass; else result=fail; fi
  [ "$result" = "$1" ] || { complain "$2: expected to $1, did not:"; cat "$work/log"; }
}

[ -s "$output" ] || { echo "compare_test: no output to compare ($output)"; exit 1; }
expect pass "the output against itself" "$output"
scaled 1e-15 >"$work/close"
expect pass "one value changed by 1e-15 of its size" "$work/close"
scaled 1e-10 >"$work/far"
! cmp -s "$output" "$work/far" || complain "found no value to change"
expect fail "one value changed by 1e-10 of its size" "$work/far"
unzeroed 1e-16 >"$work/tiny"
! cmp -s "$output" "$work/tiny" || complain "found no zero to change"
expect pass "a zero made 1e-16" "$work/tiny"
unzeroed 1e-13 >"$work/small"
expect fail "a zero made 1e-13" "$work/small"
sed '0,/ q DISP / s/ q DISP / q TDISP /' "$output" >"$work/word"
! cmp -s "$output" "$work/word" || complain "found no query to change"
expect fail "one query word changed" "$work/word"
sed '$d' "$output" >"$work/short"
expect fail "one line missing" "$work/short"

if [ "$failures" -eq 0 ]; then
  echo "compare_test: a planted difference fails the comparison, rounding does not: 7 passed, 0 failed"
  exit 0
fi
echo "compare_test: $failures problem(s)"
exit 1
