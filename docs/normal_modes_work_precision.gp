set datafile separator ','
set terminal pngcairo size 900,650 font ',11'
set logscale xy
set grid
set key outside right noenhanced
set format y '10^{%L}'
set format x '10^{%L}'
set ylabel 'relative error'
set output '/work/main/docs/normal_modes_error_time.png'
set title 'normal_modes.xml: error against run time (s)' noenhanced
set xlabel 'run time (s)'
plot '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'euler' && strcol(8) eq 'ok' ? $5 : 1/0):6 with linespoints lw 2 lc 1 title 'euler, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'euler' && strcol(8) eq 'ok' ? $5 : 1/0):7 with lines dt 2 lc 1 title 'euler, largest', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'symplectic-euler' && strcol(8) eq 'ok' ? $5 : 1/0):6 with linespoints lw 2 lc 2 title 'symplectic-euler, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'symplectic-euler' && strcol(8) eq 'ok' ? $5 : 1/0):7 with lines dt 2 lc 2 title 'symplectic-euler, largest', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'rk4' && strcol(8) eq 'ok' ? $5 : 1/0):6 with linespoints lw 2 lc 3 title 'rk4, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'rk4' && strcol(8) eq 'ok' ? $5 : 1/0):7 with lines dt 2 lc 3 title 'rk4, largest', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'dopri5' && strcol(8) eq 'ok' ? $5 : 1/0):6 with linespoints lw 2 lc 4 title 'dopri5, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'dopri5' && strcol(8) eq 'ok' ? $5 : 1/0):7 with lines dt 2 lc 4 title 'dopri5, largest'
set output '/work/main/docs/normal_modes_error_evaluations.png'
set title 'normal_modes.xml: error against right-hand-side evaluations' noenhanced
set xlabel 'right-hand-side evaluations'
plot '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'euler' && strcol(8) eq 'ok' ? $4 : 1/0):6 with linespoints lw 2 lc 1 title 'euler, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'euler' && strcol(8) eq 'ok' ? $4 : 1/0):7 with lines dt 2 lc 1 title 'euler, largest', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'symplectic-euler' && strcol(8) eq 'ok' ? $4 : 1/0):6 with linespoints lw 2 lc 2 title 'symplectic-euler, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'symplectic-euler' && strcol(8) eq 'ok' ? $4 : 1/0):7 with lines dt 2 lc 2 title 'symplectic-euler, largest', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'rk4' && strcol(8) eq 'ok' ? $4 : 1/0):6 with linespoints lw 2 lc 3 title 'rk4, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'rk4' && strcol(8) eq 'ok' ? $4 : 1/0):7 with lines dt 2 lc 3 title 'rk4, largest', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'dopri5' && strcol(8) eq 'ok' ? $4 : 1/0):6 with linespoints lw 2 lc 4 title 'dopri5, end', '/work/main/docs/normal_modes_work_precision.csv' using (strcol(1) eq 'dopri5' && strcol(8) eq 'ok' ? $4 : 1/0):7 with lines dt 2 lc 4 title 'dopri5, largest'
