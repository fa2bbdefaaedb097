#!/usr/bin/env bash
# setup.sh [PURPOSE...]: installs the Debian packages a purpose needs, when
# they are missing (apt-get install -y; sudo when not root). Purposes:
#   main    the build and the main job (example.sh, plots.sh): build, check,
#           run, bench, plots
#             cmake gcc make libc6-dev   the build
#             libexpat1-dev              the harness's XML model reader
#             libsundials-dev            the SUNDIALS integrators
#             gnuplot-nox                plots of rig and bench results
#   test    main, and what every test needs (test.sh)
#             libcmocka-dev              unit tests
#             clang libclang-rt-14-dev   libFuzzer targets
#             valgrind                   the unload/reload leak check
#             gfortran                   Fortran user libraries the harness hosts
#             gcc-mingw-w64-x86-64       usrsub.dll, cross-compiled
#             wine64 wine                Wine, to run it (windows.sh)
#             libsimbody-dev g++         Simbody, the independent engine that
#                                        judges the joints (tests/oracle/, C++)
#   windows main, cmocka and the two above: usrsub.dll against the Linux
#           library (windows.sh)
#   fuzz    the libFuzzer build (fuzz.sh): the build's packages, clang and
#           libclang-rt-14-dev
# Without a purpose: test (everything). A package apt cannot install is named,
# with the reason, and the script fails.
set -euo pipefail

windows_packages="gcc-mingw-w64-x86-64 wine64 wine"
packages_of() {
  case "$1" in
    main) echo cmake gcc make libc6-dev libexpat1-dev libsundials-dev libsuitesparse-dev gnuplot-nox ;;
    test) echo "$(packages_of main) libcmocka-dev clang libclang-rt-14-dev valgrind gfortran $windows_packages libsimbody-dev g++" ;;
    windows) echo "$(packages_of main) libcmocka-dev $windows_packages" ;;
    fuzz) echo cmake gcc make libc6-dev libexpat1-dev libsundials-dev libsuitesparse-dev clang libclang-rt-14-dev ;;
    *) return 1 ;;
  esac
}

purposes=("$@")
((${#purposes[@]})) || purposes=(test)
packages=()
for purpose in "${purposes[@]}"; do
  if ! list=$(packages_of "$purpose"); then
    echo "setup: unknown purpose '$purpose' (main, test, windows or fuzz)" >&2
    exit 2
  fi
  for p in $list; do
    [[ " ${packages[*]} " == *" $p "* ]] || packages+=("$p")
  done
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "setup (${purposes[*]}): installed already: ${packages[*]}"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null; then
    echo "setup: cannot install ${missing[*]}: not root and no sudo" >&2
    exit 1
  fi
  sudo=sudo
fi
echo "setup (${purposes[*]}): installing ${missing[*]}"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
update_failed=0
if ! $sudo apt-get update -qq >"$log" 2>&1 || grep -qE '^(W|E): (Failed to fetch|Some index files)' "$log"; then
  update_failed=1
  echo "setup: warning: apt-get update could not refresh the package lists (no network?):" >&2
  grep -E '^(W|E):' "$log" | head -3 | sed 's/^/  /' >&2 || true
fi
if DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >"$log" 2>&1; then
  exit 0
fi

# Which package, and why: one that apt does not know at all, or one it knows
# but could not fetch or install.
failed=0
for p in "${missing[@]}"; do
  candidate=$(apt-cache policy "$p" 2>/dev/null | sed -n 's/^ *Candidate: *//p')
  if [ -z "$candidate" ] || [ "$candidate" = "(none)" ]; then
    echo "setup: cannot install $p: apt has no package of that name in its sources$([ "$update_failed" -eq 0 ] || echo " (and the package lists could not be refreshed)")" >&2
    failed=1
  elif ! DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "$p" >"$log" 2>&1; then
    echo "setup: cannot install $p $candidate: apt-get failed (no network, or a dependency problem):" >&2
    grep -E '^(E|W):' "$log" | head -4 | sed 's/^/  /' >&2 || true
    failed=1
  fi
done
[ "$failed" -eq 0 ] && exit 0 # each one installed on its own
exit 1
