#!/usr/bin/env bash
# performance_tables.sh TABLE [DIR]: a Markdown table of docs/performance.md
# from the benchmark output scripts/plots.sh writes into DIR (default docs):
#   cost       from DIR/bench.txt: the cost per call of every entry, the added
#              costs and the right-hand side's split, all from one of its
#              runs (the fastest: least total time over the entries; a slow
#              spell of the machine only ever adds time)
#   stability  from DIR/bench.txt, work_precision.txt, implicit.txt,
#              long_runs.txt: each model's fastest mode at t = 0 and the
#              explicit methods' largest stable steps
#   long-runs  from DIR/long_runs.txt: energy errors over 10^6 fixed steps
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${2:-$root/docs}
case "${1:-}" in
cost)
  awk '
    # the text of line between the first "from" and the next "to"
    function field(line, from, to,    at) {
      at = index(line, from); if (at == 0) return "?"
      line = substr(line, at + length(from)); return substr(line, 1, index(line, to) - 1) }
    /^######## run / { run = $3; next }
    /^######## / { run = ""; next }
    run == "" { next }
    /^### / { model = $2; next }
    /^(Force|Constraint)_[A-Za-z_]+ +[0-9]+ / {
      total[run] += $4; n[run]++
      row[run, n[run]] = sprintf("| `%s` | %s %s | `%s` | %s | %s | %s | %s | %s |",
                                 model, $1, $2, $3, $4, $7, $9, $10, $11)
      next }
    /^right-hand side: / {
      nr[run]++
      rhs[run, nr[run]] = sprintf("| `%s` | %s | %s | %s | %s %% |", model,
                                  field($0, "right-hand side: ", " ns"),
                                  field($0, "calls in it ", " ns"),
                                  field($0, "own share ", " ns"), field($0, "(", " %"))
      next }
    /^added cost of / {
      na[run]++
      line = $0; sub(/^added cost of /, "", line); sub(/ ns per call.*/, "", line)
      split(line, parts, " over "); split(parts[2], tail, ": ")
      added[run, na[run]] = sprintf("| `%s` | %s | %s | %s |", model, parts[1], tail[1], tail[2])
    }
    END {
      best = ""
      for (r in total) if (best == "" || total[r] < total[best]) best = r
      if (best == "") { print "(no benchmark runs found)"; exit 1 }
      runs = 0; for (r in total) runs++
      printf "Run %s of the %d in `docs/bench.txt` (the fastest).\n\n", best, runs
      print "| model | element | entry | ns per call | host calls | host ns | floor ns | ratio to floor |"
      print "|---|---|---|---|---|---|---|---|"
      for (i = 1; i <= n[best]; i++) print row[best, i]
      if (na[best] > 0) {
        print ""
        print "| model | added cost of | over | ns per call |"
        print "|---|---|---|---|"
        for (i = 1; i <= na[best]; i++) print added[best, i]
      }
      print ""
      print "| model | right-hand side ns | user entries in it ns | harness ns | harness / user entries |"
      print "|---|---|---|---|---|"
      for (i = 1; i <= nr[best]; i++) print rhs[best, i]
    }' "$dir/bench.txt"
  ;;
stability)
  cat "$dir/bench.txt" "$dir/work_precision.txt" "$dir/implicit.txt" "$dir/long_runs.txt" | awk '
    /^### / { model = $2; next }
    /^stability at t = 0/ && !(model in seen) {
      seen[model] = 1
      lambda = $0; sub(/.*fastest mode lambda = /, "", lambda); sub(/ \(.*/, "", lambda)
      steps = $0; sub(/.*largest stable step: /, "", steps)
      split("euler symplectic-euler rk4 dopri5", names, " ")
      cells = ""
      for (k = 1; k <= 4; k++) {
        v = steps; sub(".*(^|, )" names[k] " ", "", v); sub(/,.*/, "", v)
        if (v ~ /^[0-9.e+-]+$/) v = v " s"
        cells = cells " " v " |"
      }
      rows[++count] = sprintf("| `%s` | %s |%s", model, lambda, cells)
    }
    END {
      print "| model | fastest mode lambda (1/s) | Euler | symplectic Euler | RK4 | DOPRI5 |"
      print "|---|---|---|---|---|---|"
      for (i = 1; i <= count; i++) print rows[i]
    }'
  ;;
long-runs)
  awk '
    /^### / { model = $2; next }
    /^long runs/ { inside = 1; next }
    inside && /^  method/ { next }
    inside && /^  [a-z]/ {
      rows[++count] = sprintf("| `%s` | %s | %s | %s | %s | %s | %s | %s | %s s |",
                              model, $1, $2, $3, $4, $5, $6, $7, $9)
      next }
    { inside = 0 }
    END {
      print "| model | method | steps | step (s) | energy error, first tenth | last tenth | drift per s | largest \\|phi\\| | run time |"
      print "|---|---|---|---|---|---|---|---|---|"
      for (i = 1; i <= count; i++) print rows[i]
    }' "$dir/long_runs.txt"
  ;;
*)
  echo "usage: performance_tables.sh cost|stability|long-runs [DIR]" >&2
  exit 2
  ;;
esac
