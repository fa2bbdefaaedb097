#!/usr/bin/env bash
# stamp.sh: one line naming what a measurement ran on, for the documents that
# quote it: the commit (and whether the tree had changes outside docs/), the
# date, and the machine (cores, processor, memory). Measuring scripts take it
# before they start, since they write their results into docs/.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
if commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null); then
  if [ -n "$(git -C "$root" status --porcelain --untracked-files=no -- . ':!docs' 2>/dev/null)" ]; then
    commit="$commit with uncommitted changes"
  fi
else
  commit="unknown"
fi
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1)
mem=$(awk '/^MemTotal:/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo 2>/dev/null)
echo "commit $commit, $(date -u +%Y-%m-%d), $(nproc) cores of ${cpu:-an unknown processor}, ${mem:-unknown memory}"
