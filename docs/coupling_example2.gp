set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 900,800 font ',11'
set grid
unset key
set output '/work/main/docs/coupling_example2_force_path.png'
set title 'element 1: force path, Fy against Fx'
set size ratio -1
set xlabel 'Fx'
set ylabel 'Fy'
plot '/work/main/docs/coupling_example2.csv' using 14:15 with lines lw 2
set output '/work/main/docs/coupling_example2_deformation_path.png'
set title 'element 1: deformation path, y against x'
set xlabel 'x'
set ylabel 'y'
plot '/work/main/docs/coupling_example2.csv' using 2:3 with lines lw 2
set size noratio
set terminal pngcairo size 960,460 font ',10'
set output '/work/main/docs/coupling_example2_force_deformation.png'
set multiplot layout 1,2 title 'element 1: force against deformation per direction'
set title 'Fx against x'
set xlabel 'x'
set ylabel 'Fx'
plot '/work/main/docs/coupling_example2.csv' using 2:14 with lines lw 2
set title 'Fy against y'
set xlabel 'y'
set ylabel 'Fy'
plot '/work/main/docs/coupling_example2.csv' using 3:15 with lines lw 2
unset multiplot
