#!/usr/bin/env bash
# plots.sh: regenerates the plots and benchmark numbers of docs/examples.md
# and docs/performance.md into docs/ (PNG plots, and docs/bench.txt and the
# other *.txt with the commands' own output), and the tables of
# docs/performance.md drawn from them (scripts/performance_tables.sh), each
# stamped with the commit, the date and the machine (scripts/stamp.sh).
# Timings are medians of repeated runs pinned to one processor; they vary
# with the machine, and from minute to minute on a shared one.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
stamp=$("$root/scripts/stamp.sh")
"$root/scripts/setup.sh" main
"$root/scripts/build.sh" build -DUSRSUB_TESTS=OFF
export MS_USERDLL_DIR="$root/build"
h="$root/build/usrsub-harness"
ex="$root/harness/examples"
out="$root/docs"
mkdir -p "$out"
omega=6.283185307179586

echo "== the seed's coupling examples (bushing rig)"
"$h" rig "$ex/bushing_coupling.xml" --element 1 --circle 5,$omega --end 1 --step 0.005 \
    --plot "$out/coupling_example1_coupled" >/dev/null
"$h" rig "$ex/bushing_coupling.xml" --element 2 --circle 5,$omega --end 1 --step 0.005 \
    --plot "$out/coupling_example1_uncoupled" >/dev/null
"$h" rig "$ex/bushing_coupling.xml" --element 1 --force-circle 125,$omega --end 1 --step 0.005 \
    --plot "$out/coupling_example2" >/dev/null
"$h" rig "$ex/bushing_coupling.xml" --element 3 --force-circle 125,$omega --end 1 --step 0.005 \
    --plot "$out/coupling_example3" >/dev/null

echo "== mount limits: force against deflection through both limits"
for e in 1 2; do
  "$h" rig "$ex/mount_limits_rig.xml" --element $e --line x,-6,6 --end 1 --step 0.002 \
      --out "$out/limits_x_$e.csv" >/dev/null
  "$h" rig "$ex/mount_limits_rig.xml" --element $e --line az,-0.5,0.5 --end 1 --step 0.002 \
      --out "$out/limits_az_$e.csv" >/dev/null
done
gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 1100,450 font ',11'
set output '$out/mount_limits_rig.png'
set multiplot layout 1,2 title 'mount limits (mount_limits.gbi) on a rig: the limits alone, and added to a linear bushing'
set grid
set key top right
set title 'x: gap 3 mm, K = 5000 N/mm^2, E = 2'
set xlabel 'x (mm)'; set ylabel 'Fx (N)'
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2
set arrow 2 from -3, graph 0 to -3, graph 1 nohead dt 2
plot '$out/limits_x_1.csv' using 2:14 with lines lw 2 title 'limits alone', \
     '$out/limits_x_2.csv' using 2:14 with lines lw 2 title 'bushing + limits'
set title 'az: gap 0.3 rad, K = 1e6 N mm/rad, E = 1'
set xlabel 'az (rad)'; set ylabel 'Tz (N mm)'
set arrow 1 from 0.3, graph 0 to 0.3, graph 1 nohead dt 2
set arrow 2 from -0.3, graph 0 to -0.3, graph 1 nohead dt 2
plot '$out/limits_az_1.csv' using 7:19 with lines lw 2 title 'limits alone', \
     '$out/limits_az_2.csv' using 7:19 with lines lw 2 title 'bushing + limits'
unset multiplot
GP

echo "== powertrain: deflection against time, gap marked"
"$h" run "$ex/powertrain.xml" --end 1 --integrator dopri5 --rtol 1e-8 --atol 1e-10 \
    --output-interval 0.001 --out "$out/powertrain.csv" --quiet > "$out/powertrain_run.txt"
gnuplot <<GP
set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 900,500 font ',11'
set output '$out/powertrain.png'
set title 'powertrain (150 kg on three mounts with limits): 1500 N m of engine torque from t = 0.4 s'
set grid
set xlabel 't (s)'; set ylabel 'vertical mount deflection (mm)'
set key bottom left
set arrow 1 from graph 0, first 2.5 to graph 1, first 2.5 nohead dt 2 lc rgb 'red'
set arrow 2 from graph 0, first -2.5 to graph 1, first -2.5 nohead dt 2 lc rgb 'red'
set label 1 'gap +2.5 mm' at 0.02, 2.8 tc rgb 'red'
set label 2 'gap -2.5 mm' at 0.02, -2.8 tc rgb 'red'
plot '$out/powertrain.csv' using 1:(column('force1.dz')) with lines lw 2 title 'left mount', \
     '$out/powertrain.csv' using 1:(column('force2.dz')) with lines lw 2 title 'right mount', \
     '$out/powertrain.csv' using 1:(column('force3.dz')) with lines lw 2 title 'rear torque rod'
GP

echo "== rotation measures: a tumbling body's energy on a linear bushing"
for m in vector angles; do
  "$h" run "$ex/tumble_$m.xml" --end 4 --integrator rk4 --step 1e-3 --output-interval 0.01 \
      --out "$out/tumble_$m.csv" --quiet
done
gnuplot <<GP
set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 900,500 font ',11'
set output '$out/tumble_energy.png'
set title 'a body tumbling on a linear bushing (tumble_*.xml), RK4 at 1 ms: energy error' noenhanced
set grid
set xlabel 't (s)'; set ylabel '(E - E(0)) / E(0)'
set key top left
stats '$out/tumble_vector.csv' using (column('energy')) every ::0::0 nooutput
e0 = STATS_min
plot '$out/tumble_angles.csv' using 1:((column('energy') - e0) / e0) with lines lw 2 \
         title 'projection angles (the solver measure)', \
     '$out/tumble_vector.csv' using 1:((column('energy') - e0) / e0) with lines lw 2 \
         title 'rotation vector (ROTATION\\_MEASURE)'
GP
rm -f "$out/tumble_vector.csv" "$out/tumble_angles.csv"

echo "== work-precision of the reference models"
{
  for m in damped_oscillator normal_modes geared_oscillator; do
    echo "### $m.xml"
    "$h" bench "$ex/$m.xml" --work-precision --out "$out/$m" | grep -v "^wrote"
  done
} > "$out/work_precision.txt"

echo "== implicit integration: work-precision of the stiff models, and the non-stiff ones"
# stiff_powertrain: errors of the powertrain (body 2), the slow outputs, over 1.5 s;
# atol = rtol (mm, mm/s, rad): a tighter atol only chases rounding on the stiff rods
{
  echo "### stiff_powertrain.xml"
  "$h" bench "$ex/stiff_powertrain.xml" --repeats 3 --work-precision --end 1.5 --outputs 2 \
      --atol-ratio 1 --target 1e-4 --out "$out/stiff_powertrain" | grep -v "^wrote"
  echo "### stiff_mount.xml (BDF up to order 2: its fast mode is lightly damped)"
  "$h" bench "$ex/stiff_mount.xml" --repeats 3 --work-precision --end 0.1 --atol-ratio 1 \
      --target 1e-4 --max-order 2 --out "$out/stiff_mount" | grep -v "^wrote"
  echo "### stiff_mount.xml (BDF up to order 5)"
  "$h" bench "$ex/stiff_mount.xml" --repeats 3 --work-precision --end 0.1 --atol-ratio 1 \
      --target 1e-4 | grep -v "^wrote"
  echo "### powertrain.xml"
  "$h" bench "$ex/powertrain.xml" --repeats 3 --work-precision --end 1 --atol-ratio 1 \
      --target 1e-4 --out "$out/powertrain" | grep -v "^wrote"
} > "$out/implicit.txt"

echo "== what BDF and DOPRI5 do to stiff_mount.xml's fast (5 kHz) mode"
"$h" run "$ex/stiff_mount.xml" --end 0.02 --integrator bdf --max-order 2 --rtol 1e-3 --atol 1e-3 \
    --output-interval 1e-5 --out "$out/stiff_mount_bdf2.csv" --quiet > "$out/stiff_mount_runs.txt"
"$h" run "$ex/stiff_mount.xml" --end 0.02 --integrator dopri5 --rtol 1e-3 --atol 1e-3 \
    --output-interval 1e-5 --out "$out/stiff_mount_dopri5.csv" --quiet >> "$out/stiff_mount_runs.txt"
gnuplot <<GP
set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 900,500 font ',11'
set output '$out/stiff_mount_fast_mode.png'
set title 'stiff_mount.xml: the gravity-excited 5 kHz mode (damping ratio 0.008) at rtol = atol = 1e-3' noenhanced
set grid
set xlabel 't (s)'; set ylabel 'vz (mm/s)'
set samples 4000
a = -250.0; w = sqrt(1e9 - a*a); e0 = 9.81e-6; B = -a*e0/w
vz(t) = exp(a*t)*((a*e0 + w*B)*cos(w*t) + (a*B - w*e0)*sin(w*t))
plot [0:0.02] '$out/stiff_mount_dopri5.csv' using 1:(column('body2.vz')) with lines lw 2 \
         title 'dopri5 (steps at its stability limit: no damping left)', \
     '$out/stiff_mount_bdf2.csv' using 1:(column('body2.vz')) with lines lw 2 \
         title 'bdf, order <= 2 (A-stable: damps the mode away)', \
     vz(x) with lines lw 1 lc rgb 'black' title 'closed form'
GP
rm -f "$out/stiff_mount_bdf2.csv" "$out/stiff_mount_dopri5.csv"

echo "== cost per call and the harness's share (three runs: the machine's speed wanders)"
{
  for run in 1 2 3; do
    echo "######## run $run"
    echo "### bench_coupler.xml";  "$h" bench "$ex/bench_coupler.xml" --repeats 41
    echo "### bench_bushing.xml";  "$h" bench "$ex/bench_bushing.xml" --repeats 41
    echo "### bench_limits.xml";   "$h" bench "$ex/bench_limits.xml" --repeats 41 \
        --compare vector:1,vector:2 --compare field:3,field:4 --compare field:3,field:7 \
        --compare field:8,field:9
    echo "### flex_joint_rig.xml"; "$h" bench "$ex/flex_joint_rig.xml" --repeats 41
    echo "### powertrain.xml";     "$h" bench "$ex/powertrain.xml" --repeats 41
  done
  echo "######## stability"
  echo "### stiff_mount.xml";    "$h" bench "$ex/stiff_mount.xml" --repeats 5
  echo "### flex_revolute.xml";  "$h" bench "$ex/flex_revolute.xml" --repeats 5
  echo "### revolute_pendulum.xml"; "$h" bench "$ex/revolute_pendulum.xml" --repeats 5
} > "$out/bench.txt"

echo "== long runs"
{
  echo "### normal_modes.xml";    "$h" bench "$ex/normal_modes.xml" --repeats 3 --long-run 1000000
  echo "### geared_pendulums.xml"; "$h" bench "$ex/geared_pendulums.xml" --repeats 3 \
      --long-run 1000000 --step 1e-4
} > "$out/long_runs.txt"
echo "== the suspension bushing with internal states (Force_StateEqn): its loops on the rig"
"$h" rig "$ex/suspension_bushing_rig.xml" --element 1 --line y,-1,-1 --sine az,0.05,1 \
    --end 2 --step 0.002 --out "$out/suspension_friction.csv" > "$out/suspension_bushing_rig.txt"
"$h" rig "$ex/suspension_bushing_rig.xml" --element 1 --sine y,0.5,10 --end 0.5 \
    --step 0.0005 --out "$out/suspension_rubber.csv" >> "$out/suspension_bushing_rig.txt"
gnuplot <<GP
set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 1100,450 font ',11'
set output '$out/suspension_bushing_loops.png'
set multiplot layout 1,2 title 'suspension_bushing.gbs on a rig: hysteresis from its internal states' noenhanced
set grid
unset key
set title 'friction: az = 0.05 sin(2 pi t) under a 1 mm radial deflection' noenhanced
set xlabel 'az (rad)'; set ylabel 'Tz (N mm)'
plot '$out/suspension_friction.csv' using (column('az')):(column('tz')) with lines lw 2
set title 'rubber filter (R = 60 1/s): y = 0.5 sin(2 pi 10 t)' noenhanced
set xlabel 'y (mm)'; set ylabel 'Fy (N)'
plot '$out/suspension_rubber.csv' every ::200 using (column('y')):(column('fy')) with lines lw 2
unset multiplot
GP
rm -f "$out/suspension_friction.csv" "$out/suspension_rubber.csv"

echo "== the suspension bushing in a run: every integrator, and what BDF saves"
{
  for run in "bdf" "dopri5" "dopri5-arkode" "rk4 --step 2e-6" "euler --step 1e-6" \
             "symplectic-euler --step 1e-6"; do
    echo "### run --integrator $run"
    # shellcheck disable=SC2086
    "$h" run "$ex/suspension_bushing.xml" --end 1 --integrator $run --quiet
  done
} > "$out/suspension_bushing_runs.txt"
"$h" run "$ex/suspension_bushing.xml" --end 1 --integrator bdf --rtol 1e-8 --atol 1e-11 \
    --output-interval 0.001 --out "$out/suspension_bushing.csv" --quiet > /dev/null
gnuplot <<GP
set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 900,700 font ',11'
set output '$out/suspension_bushing_run.png'
set multiplot layout 2,1 title 'suspension_bushing.xml: the arm end breaks loose, slides and sticks again' noenhanced
set grid
set key top left
set ylabel 'Tz on the arm (N mm)'
plot '$out/suspension_bushing.csv' using 1:(column('stateeqn1.tz')) with lines lw 2 title 'bushing', \
     '' using 1:(-12000*((column('t') < 0.1) ? 0 : (column('t') > 0.3) ? 1 : \
        ((column('t')-0.1)/0.2)**2*(3-2*(column('t')-0.1)/0.2))) with lines lw 1 dt 2 title 'minus the applied torque'
set xlabel 't (s)'; set ylabel 'az (rad)'
plot '$out/suspension_bushing.csv' using 1:(column('stateeqn1.u6')) with lines lw 2 title 'twist about the pivot'
unset multiplot
GP
rm -f "$out/suspension_bushing.csv"

echo "== the tables of docs/performance.md"
for table in cost stability long-runs; do
  "$root/scripts/performance_tables.sh" "$table" "$out" |
    "$root/scripts/doc_block.sh" "$out/performance.md" "$table" "scripts/plots.sh" "$stamp"
done
echo "== wrote $out"
