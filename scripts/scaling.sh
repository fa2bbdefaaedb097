#!/usr/bin/env bash
# scaling.sh [OUT_DIR [N...]]: how the integrators' stepping time grows with
# the model. Chains of N bodies (scripts/chain_model.sh, N = 2 .. 128, or the
# sizes given), each run
# 0.5 s at rtol 1e-5, atol 1e-8 with BDF (the assembled Newton matrix on KLU
# and on dense LU, and differences by column groups on KLU) and DOPRI5;
# stepping time (output excluded) per simulated second, the median of three
# runs, and the process's peak memory. Writes OUT_DIR/scaling.csv, the
# fitted exponents (8 to 128 bodies) in OUT_DIR/scaling.txt and the log-log
# plot OUT_DIR/scaling.png (default OUT_DIR: docs), and, when OUT_DIR holds
# performance.md, its table in that file's block "scaling", stamped with the
# commit, the date and the machine (scripts/stamp.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/docs}
sizes=(2 4 8 16 32 64 128)
if (($# > 1)); then shift; sizes=("$@"); fi
mkdir -p "$out"
stamp=$("$root/scripts/stamp.sh")
"$root/scripts/setup.sh" main >/dev/null
"$root/scripts/build.sh" build -DUSRSUB_TESTS=OFF >/dev/null
export MS_USERDLL_DIR="$root/build"
h="$root/build/usrsub-harness"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
end=0.5
series=("bdf-klu:--integrator bdf --linear-solver klu"
        "bdf-dense:--integrator bdf --linear-solver dense"
        "bdf-fd-klu:--integrator bdf --jacobian fd --linear-solver klu"
        "dopri5:--integrator dopri5")
csv="$out/scaling.csv"
echo "series,bodies,states,stepping_seconds_per_simulated_second,steps,rhs,peak_mb" > "$csv"
for n in "${sizes[@]}"; do
  sh "$root/scripts/chain_model.sh" "$n" "$work/chain.xml"
  for s in "${series[@]}"; do
    name=${s%%:*} args=${s#*:}
    # dense LU is O(n^3): past 64 bodies it is only slower
    [ "$name" = bdf-dense ] && [ "$n" -gt 64 ] && continue
    times=()
    for repeat in 1 2 3; do
      # shellcheck disable=SC2086
      text=$("$h" run "$work/chain.xml" --end $end --rtol 1e-5 --atol 1e-8 --quiet \
             --output-interval $end $args)
      times+=("$(echo "$text" | sed -n 's/.*s: \([0-9.e+-]*\) s stepping.*/\1/p')")
    done
    median=$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p)
    steps=$(echo "$text" | sed -n 's/^  steps \([0-9]*\),.*/\1/p')
    rhs=$(echo "$text" | sed -n 's/.*right-hand sides \([0-9]*\),.*/\1/p')
    peak=$(echo "$text" | sed -n 's/.*peak memory \([0-9.]*\) MB.*/\1/p')
    per=$(awk -v t="$median" -v e=$end 'BEGIN { printf "%.6g", t / e }')
    echo "$name,$n,$((13 * n + 2)),$per,$steps,$rhs,$peak" | tee -a "$csv"
  done
done
# least-squares slope of log(time) against log(bodies), 8 to 128 bodies
{
  echo "Fitted exponent of stepping time against bodies (8 to 128 bodies; 1 = linear):"
  for s in "${series[@]}"; do
    name=${s%%:*}
    awk -F, -v s="$name" '$1 == s && $2 >= 8 {
        x = log($2); y = log($4); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
      END { if (n > 1) printf "  %-11s %.2f (%d sizes)\n", s, (n * sxy - sx * sy) / (n * sxx - sx * sx), n }' "$csv"
  done
  echo "At 64 bodies, DOPRI5's stepping time over each BDF's:"
  awk -F, '$2 == 64 { t[$1] = $4 } END {
      for (s in t) if (s != "dopri5") printf "  %-11s %.2gx\n", s, t["dopri5"] / t[s] }' "$csv" | sort
} | tee "$out/scaling.txt"
gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,550 font ',11'
set output '$out/scaling.png'
set title 'stepping time per simulated second against model size (chains of N bodies, rtol 1e-5)'
set logscale xy
set grid
set xlabel 'bodies N (13 N + 2 states)'; set ylabel 'stepping time per simulated second (s)'
set key top left
plot for [s in 'bdf-klu bdf-dense bdf-fd-klu dopri5'] '$csv' using (strcol(1) eq s ? \$2 : 1/0):4 \
     with linespoints lw 2 title s
GP
if [ -f "$out/performance.md" ]; then
  {
    echo "Stepping time per simulated second (median of three runs) and the process's peak memory:"
    echo
    echo "| bodies (states) | BDF, partials, KLU | BDF, partials, dense | BDF, fd, KLU | DOPRI5 | peak memory (BDF, KLU) |"
    echo "|---|---|---|---|---|---|"
    awk -F, 'NR > 1 {
        if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2; states[$2] = $3 }
        t[$1, $2] = sprintf("%.3g s", $4)
        if ($1 == "bdf-klu") peak[$2] = $7 " MB" }
      END {
        for (i = 1; i <= n; i++) {
          b = order[i]
          printf "| %s (%s) | %s | %s | %s | %s | %s |\n", b, states[b], t["bdf-klu", b],
                 t["bdf-dense", b], t["bdf-fd-klu", b], t["dopri5", b], peak[b] }
      }' "$csv"
    awk -F, '$2 == 64 && ($1 == "dopri5" || $1 == "bdf-klu") { steps[$1] = $5 }
      END { if (length(steps) == 2)
              printf "\nAt 64 bodies DOPRI5 takes %s steps, BDF with the partials on KLU %s.\n",
                     steps["dopri5"], steps["bdf-klu"] }' "$csv"
    echo
    echo '```'
    cat "$out/scaling.txt"
    echo '```'
  } | "$root/scripts/doc_block.sh" "$out/performance.md" scaling "scripts/scaling.sh" "$stamp"
  echo "wrote $csv, $out/scaling.txt, $out/scaling.png and the scaling table of $out/performance.md"
else
  echo "wrote $csv, $out/scaling.txt, $out/scaling.png"
fi
