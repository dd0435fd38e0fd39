# Koba & Sato, Figure 1 (arrangement of particles): the particles a_i of a jittered grid in
# Omega_H, the domain Omega, and one particle a_k with its interaction disc B_h(a_k).
# Omega_H is the square (-H, 1+H)^2 of this package, not the rounded H-neighbourhood of Omega.
load 'figures/style.gp'
set output out
set datafile columnheaders
fp = datadir.'/koba_sato_fig_particles.tsv'
fc = datadir.'/koba_sato_fig_circles.tsv'
H = real(system("awk -F' = ' '/^# H = /{print $2; exit}' ".fp))
unset logscale
set format x '%g'
set format y '%g'
set size ratio -1
set xrange [-H-0.05:1+H+0.05]
set yrange [-H-0.05:1+H+0.05]
set xlabel 'x_1'
set ylabel 'x_2'
set key outside right top box opaque
set object 1 rect from -H,-H to 1+H,1+H fs empty border lc rgb '#555555' dt 2 lw 1
set object 2 rect from 0,0 to 1,1 fs empty border lc rgb '#000000' lw 2
set label 1 'Ω' at 0.03,0.95 font ',14'
set label 2 'Ω_H' at -H+0.01,1+H-0.035 font ',12'
plot rows_named(fp, '$c["role"]=="o" || $c["role"]=="R"') using (column("x")):(column("y")) with points pt 7 ps 0.35 lc rgb '#1f4e9c' title 'a_i', \
     rows_named(fp, '$c["role"]=="k"') using (column("x")):(column("y")) with points pt 7 ps 1.0 lc rgb '#b22222' title 'a_k', \
     rows_named(fc, '$c["name"]=="h"') using (column("x")):(column("y")):(column("r")) with circles fs empty lc rgb '#b22222' dt 1 lw 1.5 title 'B_h(a_k)'
