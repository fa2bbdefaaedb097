#!/usr/bin/env bash
# check_dll.sh OBJDUMP usrsub.dll UTILITY_DLL DEF: what usrsub.dll exports and
# imports (docs/windows.md), read from its PE tables with mingw-w64's objdump:
#  - exports: exactly the entries of tests/library_entries.txt, each under NAME
#    and name_, both at one address;
#  - imports: from UTILITY_DLL only the utilities DEF lists, and otherwise only
#    from Windows' own DLLs (kernel32, the C runtime), so that nothing but the
#    solver's utility DLL has to be found beside it.
set -u
objdump=$1
dll=$2
utility=$3
def=$4
entries=$(grep -v '^#' "$(dirname "$0")/../library_entries.txt")
failures=0
complain() { echo "check_dll: $*"; failures=$((failures + 1)); }

tables=$("$objdump" -p "$dll") || { echo "check_dll: cannot read $dll"; exit 1; }
# "index address" of the export address table, "index name" of the name table
addresses=$(echo "$tables" | sed -n 's/^\s*\[ *\([0-9]*\)\] +base\[ *[0-9]*\] *\([0-9a-f]*\) Export RVA$/\1 \2/p')
names=$(echo "$tables" | sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/s/^\s*\[ *\([0-9]*\)\] \(.*\)$/\1 \2/p')
expected=$(for e in $entries; do echo "$e"; echo "$(echo "$e" | tr 'A-Z' 'a-z')_"; done | sort)
actual=$(echo "$names" | awk '{print $2}' | sort)
extra=$(comm -13 <(echo "$expected") <(echo "$actual") | tr '\n' ' ')
missing=$(comm -23 <(echo "$expected") <(echo "$actual") | tr '\n' ' ')
[ -z "$extra" ] || complain "$dll exports what is no entry: $extra"
[ -z "$missing" ] || complain "$dll does not export: $missing"
address_of() { # address of the export NAME
  local index
  index=$(echo "$names" | awk -v n="$1" '$2 == n {print $1}')
  echo "$addresses" | awk -v i="$index" '$1 == i {print $2}'
}
for e in $entries; do
  lower="$(echo "$e" | tr 'A-Z' 'a-z')_"
  a=$(address_of "$e")
  b=$(address_of "$lower")
  [ -n "$a" ] && [ "$a" = "$b" ] || complain "$lower is not the same function as $e ($b, $a)"
done

# imports: "DLL function" per imported function
imports=$(echo "$tables" | awk '/^\tDLL Name: / {dll = $3; next}
                                 /^$/ {dll = ""}
                                 dll != "" && $1 ~ /^[0-9a-f]+$/ && NF >= 3 {print dll, $3}')
dlls=$(echo "$imports" | awk '{print $1}' | sort -u)
for d in $dlls; do
  case "$(echo "$d" | tr 'A-Z' 'a-z')" in
    "$(echo "$utility" | tr 'A-Z' 'a-z')") ;;
    kernel32.dll | msvcrt.dll | ucrtbase.dll | api-ms-win-*.dll) ;;
    *) complain "$dll imports from $d, which is neither $utility nor Windows' own" ;;
  esac
done
allowed=$(sed -n 's/^ *\(c_[a-z]*\) *$/\1/p' "$def" | sort)
used=$(echo "$imports" | awk -v u="$utility" 'tolower($1) == tolower(u) {print $2}' | sort)
[ -n "$used" ] || complain "$dll imports nothing from $utility"
unknown=$(comm -13 <(echo "$allowed") <(echo "$used") | tr '\n' ' ' | sed 's/ *$//')
[ -z "$unknown" ] || complain "$dll imports from $utility what $def does not list: $unknown"

if [ "$failures" -eq 0 ]; then
  echo "check_dll: $(echo "$actual" | wc -l) exports, each entry under both names; imports from" \
       "$(echo "$dlls" | tr '\n' ' ')only"
  exit 0
fi
exit 1
