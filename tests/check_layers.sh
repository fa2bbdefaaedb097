#!/usr/bin/env bash
# The architecture, checked (docs/architecture.md, "Layers"):
#  - arrows run one way: a file includes only headers of its own layer or a
#    lower one (library: entries -> readers -> core; harness: cmd -> tools ->
#    sim/simulation -> sim/newton -> sim/dynamics -> sim/ode -> host -> expr
#    -> frames -> model -> base; the ODE solvers know nothing of the model);
#  - the harness shares no code with the library it verifies: of the
#    library's headers it includes only the solver ABI;
#  - the harness has one global, the ABI's binding (host/abi.c);
#  - nothing refers to files outside the repository, and every repository
#    path a source, script or document names exists.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
failures=0
complain() { echo "check_layers: $*"; failures=$((failures + 1)); }

rank_of() { # layer rank of a path inside a tree, or empty
  case "$1" in
    usrsub/core/*|usrsub/core/*) echo 0 ;;
    usrsub/readers/*) echo 1 ;;
    usrsub/entries/*) echo 2 ;;
    harness/base/*) echo 0 ;;
    harness/model/*) echo 1 ;;
    harness/frames/*) echo 2 ;;
    harness/expr/*) echo 3 ;;
    harness/host/*) echo 4 ;;
    harness/sim/ode/*) echo 5 ;;
    harness/sim/dynamics/*) echo 6 ;;
    harness/sim/newton/*) echo 7 ;;
    harness/sim/simulation/*) echo 8 ;;
    harness/tools/*) echo 9 ;;
    harness/cmd/*) echo 10 ;;
  esac
}

[ "$(git ls-files include)" = "include/usrsub/solver_abi.h" ] ||
  complain "include/ holds more than the one public header, the solver ABI: $(git ls-files include)"

for f in $(git ls-files 'usrsub/*.c' 'usrsub/*.h'); do
  mine=$(rank_of "$f")
  while read -r inc; do
    case "$inc" in
      usrsub/solver_abi.h) [ "$mine" -ge 1 ] || complain "$f includes the ABI header (core knows no host)" ;;
      usrsub/core/*) ;;
      usrsub/readers/*) [ "$mine" -ge 1 ] || complain "$f (core) includes $inc (a reader)" ;;
      *.h) [ "$mine" -ge 2 ] || complain "$f includes $inc (an entries header)" ;;
    esac
  done < <(grep -oE '^#include "[^"]+"' "$f" | sed 's/#include "//; s/"$//')
done

for f in $(git ls-files 'harness/*.c' 'harness/*.h'); do
  mine=$(rank_of "$f")
  [ -n "$mine" ] || { complain "$f is in no layer folder"; continue; }
  while read -r inc; do
    case "$inc" in
      usrsub/solver_abi.h) continue ;;
      usrsub/*) complain "$f includes $inc: the harness uses no code of the library it verifies"; continue ;;
    esac
    theirs=$(rank_of "harness/$inc")
    if [ -z "$theirs" ]; then
      complain "$f includes $inc, which is in no layer folder"
    elif [ "$theirs" -gt "$mine" ]; then
      complain "$f includes $inc: an arrow pointing up"
    fi
  done < <(grep -oE '^#include "[^"]+"' "$f" | sed 's/#include "//; s/"$//')
done

# file-scope variables that are not constant: only the ABI's binding
globals=$(git ls-files 'harness/*.c' | xargs grep -nE '^(static )?(_Thread_local )?[A-Za-z_][A-Za-z0-9_ ]*[ *][A-Za-z_][A-Za-z0-9_]*(\[[^]]*\])*( = [^;]*)?;$' \
          | grep -v 'const ' | grep -v '^harness/host/abi.c:.*bound;$')
[ -z "$globals" ] || complain "harness globals besides the ABI's binding: $globals"

refs=$(git grep -nE '\.\./shared|INTERFACE\.md|seed 00[0-9]' -- '*.c' '*.h' '*.txt' 'CMakeLists.txt' '*.sh' \
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
           -- '*.c' '*.h' '*.sh' '*.md' 'CMakeLists.txt' '*.cmake' '*.xml' '*.f' \
         | sed -E 's/^([^:]+):[^A-Za-z0-9_.-]?/\1:/' | sort -u)


if [ "$failures" -ne 0 ]; then
  echo "check_layers: $failures problem(s)"
  exit 1
fi
echo "check_layers: the layers, the verifier's independence and the references hold"
