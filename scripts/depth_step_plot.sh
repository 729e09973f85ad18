#!/usr/bin/env bash
# The depth-step curve of lessons 06/07 (issue 19): the world size of one step of an 8-bit
# map against the distance from the light, for several near planes, from the formula the
# lessons report (common/math/shadow_math.hpp depthStepWorld): z^2 (f - n) / (f n 255) for
# projective depth, (f - n) / 255 for linear. Writes docs/depth_step.png.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/depth_step.png}
gnuplot <<GP
set terminal pngcairo size 900,560 font ",11" noenhanced
set output "$out"
set title "One 8-bit depth step in world units, against distance from the light\n(torus_pyramid's casters lie 4 to 10 units from the light: shaded band)"
set xlabel "distance from the light (world units)"
set ylabel "one step (world units, log; lower is more precise)"
set logscale y
set format y "%g"
set xrange [0:14]
set yrange [0.001:20]
set key bottom right box opaque
set grid
set object 1 rect from 4,0.001 to 10,20 fc rgb "#eeeeee" fs solid noborder behind
step(z, n, f) = z*z*(f - n)/(f*n*255.0)
plot step(x, 0.1, 100) w l lw 2 title "projective, near 0.1, far 100", \
     step(x, 0.2, 100) w l lw 2 title "projective, near 0.2, far 100", \
     step(x, 0.5, 100) w l lw 2 title "projective, near 0.5, far 100", \
     step(x, 2, 100) w l lw 2 title "projective, near 2, far 100", \
     step(x, 2, 1000) w l lw 2 dt 2 title "projective, near 2, far 1000 (far x10: barely moves)", \
     (100 - 0.2)/255.0 w l lw 2 dt 3 lc rgb "black" title "linear, far 100 (any near)", \
     (12 - 0.2)/255.0 w l lw 2 dt 4 lc rgb "gray40" title "linear, far 12"
GP
echo "$out"
