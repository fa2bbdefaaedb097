#!/usr/bin/env bash
# Installs the Debian packages the project needs, when they are missing.
#   cmake, gcc, make      build
#   libcmocka-dev         unit tests
#   libexpat1-dev         the harness's XML model reader
#   gnuplot-nox           plots of rig and bench results
#   clang, libclang-rt-14-dev   libFuzzer targets and ThreadSanitizer runs
#   valgrind              the unload/reload leak check
set -euo pipefail
packages=(cmake gcc make libc6-dev libcmocka-dev libexpat1-dev gnuplot-nox clang
          libclang-rt-14-dev valgrind)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
