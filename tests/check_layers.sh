#!/usr/bin/env bash
# The architecture, checked against its document (docs/architecture.md,
# "Layers"), so that the two cannot part:
#  - the table of layers between the document's layers markers gives each
#    layer's folder and the layers it uses; every row's folder exists, every
#    source file of usrsub/ and harness/ lies in one row's folder, and a file
#    includes only headers of its own layer or of the layers its layer uses,
#    directly or through them (tests/, fuzz/ and scripts/ are no layer: they
#    use the layers from outside);
#  - C++ only in tests/oracle/ (the Simbody oracle; the project is C);
#  - every backticked folder name in the document (`sim/ode/`) exists;
#  - every harness header's guard is HX_<PATH>_H;
#  - the harness shares no code with the library it verifies: of the
#    library's headers it includes only the solver ABI, and include/ holds
#    only that one;
#  - the harness has one global, the ABI's binding (host/abi.c);
#  - nothing refers to files outside the repository, and every repository
#    path a source, script or document names exists.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
failures=0
complain() { echo "check_layers: $*"; failures=$((failures + 1)); }
doc=docs/architecture.md

# ---- the table: name | `folder/` | uses ----
declare -A folder_of uses_of
names=()
while IFS= read -r row; do
  IFS='|' read -r _ name folder uses _ <<<"$row"
  name=$(echo "$name" | xargs)
  folder=$(echo "$folder" | tr -d '` ' )
  uses=$(echo "$uses" | tr ',' ' ' | xargs)
  case "$name" in ""|layer|---) continue ;; esac
  names+=("$name")
  folder_of[$name]=$folder
  uses_of[$name]=$uses
done < <(sed -n '/<!-- layers/,/<!-- \/layers -->/p' "$doc" | grep '^|' | grep -v '^|---')
[ "${#names[@]}" -gt 0 ] || complain "$doc has no table of layers between its layers markers"
for name in "${names[@]}"; do
  [ -d "${folder_of[$name]}" ] || complain "$doc names layer $name in ${folder_of[$name]}, which does not exist"
  for used in ${uses_of[$name]}; do
    [ -n "${folder_of[$used]:-}" ] || complain "$doc: layer $name uses $used, which is no layer of the table"
  done
done

# what a layer may include: itself and, transitively, what it uses
declare -A allowed
closure() {
  local seen=" $1 " todo="${uses_of[$1]}" next
  while [ -n "$todo" ]; do
    next=""
    for l in $todo; do
      case "$seen" in *" $l "*) continue ;; esac
      seen="$seen$l "
      next="$next ${uses_of[$l]:-}"
    done
    todo=$(echo "$next" | xargs)
  done
  echo "$seen"
}
for name in "${names[@]}"; do allowed[$name]=$(closure "$name"); done

layer_of() { # the layer whose folder holds a path (the longest folder wins)
  local best="" len=0
  for name in "${names[@]}"; do
    case "$1" in
      "${folder_of[$name]}"*) [ "${#folder_of[$name]}" -gt "$len" ] && best=$name && len=${#folder_of[$name]} ;;
    esac
  done
  echo "$best"
}

[ "$(git ls-files include)" = "include/usrsub/solver_abi.h" ] ||
  complain "include/ holds more than the one public header, the solver ABI: $(git ls-files include)"

check_includes() { # tree prefix (usrsub or harness), how includes are written
  local tree=$1
  for f in $(git ls-files "$tree/*.c" "$tree/*.h"); do
    local mine
    mine=$(layer_of "$f")
    [ -n "$mine" ] || { complain "$f is in no layer's folder ($doc)"; continue; }
    while read -r inc; do
      local target theirs
      case "$inc" in
        usrsub/solver_abi.h)
          [ "$tree" = harness ] || [ "$mine" != core ] || complain "$f includes the ABI header (core knows no host)"
          continue ;;
        usrsub/*) target=$inc
          [ "$tree" = usrsub ] || { complain "$f includes $inc: the harness uses no code of the library it verifies"; continue; } ;;
        *) if [ "$tree" = harness ]; then target=harness/$inc; else target=$(dirname "$f")/$inc; fi ;;
      esac
      theirs=$(layer_of "$target")
      if [ -z "$theirs" ]; then
        complain "$f includes $inc, which is in no layer's folder"
      else
        case "${allowed[$mine]}" in
          *" $theirs "*) ;;
          *) complain "$f ($mine) includes $inc ($theirs): $doc does not let $mine use $theirs" ;;
        esac
      fi
    done < <(grep -oE '^#include "[^"]+"' "$f" | sed 's/#include "//; s/"$//')
  done
}
check_includes usrsub
check_includes harness

# ---- C++ only in the Simbody oracle (tests/oracle/, Simbody's language) ----
cxx=$(git ls-files '*.cpp' '*.cc' '*.cxx' '*.hpp' | grep -v '^tests/oracle/' || true)
[ -z "$cxx" ] || complain "C++ outside tests/oracle/ (the project is C; only the Simbody oracle is C++): $cxx"

# ---- every backticked folder the document names exists ----
while read -r name; do
  found=0
  for base in . harness usrsub tests; do
    [ -d "$base/$name" ] && found=1 && break
  done
  [ "$found" = 1 ] || complain "$doc names the folder $name, which does not exist"
done < <(grep -oE '`[a-z_]+(/[a-z_]+)*/`' "$doc" | tr -d '`' | sort -u)

# ---- header guards ----
for f in $(git ls-files 'harness/*.h'); do
  want=$(echo "${f#harness/}" | tr 'a-z/.' 'A-Z__')
  want=HX_$want
  grep -q "^#ifndef $want\$" "$f" || complain "$f: its guard is not $want"
done

# file-scope variables that are not constant: only the ABI's binding
globals=$(git ls-files 'harness/*.c' | xargs grep -nE '^(static )?(_Thread_local )?[A-Za-z_][A-Za-z0-9_ ]*[ *][A-Za-z_][A-Za-z0-9_]*(\[[^]]*\])*( = [^;]*)?;$' \
          | grep -v 'const ' | grep -v '^harness/host/abi.c:.*bound;$')
[ -z "$globals" ] || complain "harness globals besides the ABI's binding: $globals"

refs=$(git grep -nE '\.\./shared|INTERFACE\.md|seed 00[0-9]' -- '*.c' '*.h' '*.cpp' '*.txt' 'CMakeLists.txt' '*.sh' \
       ':!tests/check_layers.sh' || true)
[ -z "$refs" ] || complain "references to files outside the repository: $refs"

# Every path a source, script, build file or document names (a word with a
# folder and an extension, such as harness/host/abi.c or docs/interface.md)
# must exist: from the repository's root, from the naming file's folder, or
# as the harness and the library name them (from harness/, include/, usrsub/).
# Not paths of the repository: system headers (<sys/wait.h>), the outputs of
# commands (out/, outputs/) and placeholders in capitals (MODEL.xml, DIR/).
exists() { # path, naming file
  local dir
  dir=$(dirname "$2")
  case "$1" in
    out/*|outputs/*|*[A-Z][A-Z][A-Z]*) return 0 ;;
  esac
  for base in . "$dir" harness include usrsub usrsub/entries; do
    [ -e "$base/$1" ] && return 0
  done
  return 1
}
while IFS=: read -r f path; do
  exists "$path" "$f" || complain "$f names $path, which does not exist"
done < <(git grep -oE '(^|[^A-Za-z0-9_./%$*{<-])[A-Za-z0-9_.-]+(/[A-Za-z0-9_.-]+)+\.(c|h|md|sh|xml|txt|cmake|def|gbs|gbi|gfj|tbl|csv|png|f)\b' \
           -- '*.c' '*.h' '*.cpp' '*.sh' '*.md' 'CMakeLists.txt' '*.cmake' '*.xml' '*.f' \
         | sed -E 's/^([^:]+):[^A-Za-z0-9_.-]?/\1:/' | sort -u)

if [ "$failures" -ne 0 ]; then
  echo "check_layers: $failures problem(s)"
  exit 1
fi
echo "check_layers: the layers as $doc tables them, the verifier's independence and the references hold"
