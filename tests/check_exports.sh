#!/usr/bin/env bash
# check_exports.sh LIBRARY: the library exports exactly its entries
# (docs/interface.md §1), each under NAME and under the lower-case name with a
# trailing underscore that a Linux solver looks up, both at one address.
set -u
lib=$1
entries=$(grep -v '^#' "$(dirname "$0")/library_entries.txt")
failures=0
complain() { echo "check_exports: $*"; failures=$((failures + 1)); }

# "address name" of every function the library defines and exports
table=$(nm -D --defined-only "$lib" | awk '$2 == "T" || $2 == "W" || $2 == "i" {print $1, $3}')
expected=$(for e in $entries; do echo "$e"; echo "$(echo "$e" | tr 'A-Z' 'a-z')_"; done | sort)
actual=$(echo "$table" | awk '{print $2}' | sort)
extra=$(comm -13 <(echo "$expected") <(echo "$actual") | tr '\n' ' ')
missing=$(comm -23 <(echo "$expected") <(echo "$actual") | tr '\n' ' ')
[ -z "$extra" ] || complain "$lib exports what is no entry: $extra"
[ -z "$missing" ] || complain "$lib does not export: $missing"
others=$(nm -D --defined-only "$lib" | awk '$2 != "T" && $2 != "W" && $2 != "i" {print $3}' | tr '\n' ' ')
[ -z "$others" ] || complain "$lib exports data or other symbols: $others"
for e in $entries; do
  lower="$(echo "$e" | tr 'A-Z' 'a-z')_"
  a=$(echo "$table" | awk -v n="$e" '$2 == n {print $1}')
  b=$(echo "$table" | awk -v n="$lower" '$2 == n {print $1}')
  [ -n "$a" ] && [ "$a" = "$b" ] || complain "$lower is not the same function as $e ($b, $a)"
done
if [ "$failures" -eq 0 ]; then
  echo "check_exports: $(echo "$actual" | wc -l) entries, each under both names: 1 passed, 0 failed"
  exit 0
fi
echo "check_exports: 0 passed, 1 failed"
exit 1
