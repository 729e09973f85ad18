#!/usr/bin/env bash
# The two teaching diagrams of lessons 06 and 07 (issue 19), drawn with gnuplot from what the
# shaders compute (common/shaders/depth_digits.glsl):
#   docs/diagram_06_steps.png   06: the map's step m against the fragment's ramp step r on a
#                               number line; lit only where m > r, so a tie is shadowed, and
#                               what bias.steps=3 does to both.
#   docs/diagram_07_digits.png  07: the three passes as a decision tree on the two digits.
# Usage: scripts/diagrams.sh [outdir]   (default docs)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs}

# --- 06: one row per case; cell k is ramp step r = k, coloured by what the alpha test does
# with the map value m of that row: green lit (m > r), orange a tie (shadowed), red shadowed.
cells() {  # row y, map value m
  local y=$1 m=$2 k colour
  for k in $(seq 96 108); do
    if ((k < m)); then colour="#7fd17f"; elif ((k == m)); then colour="#f0a040"; else colour="#e07070"; fi
    echo "set object rect from $k-0.46,$y-0.32 to $k+0.46,$y+0.32 fc rgb \"$colour\" fs solid 1.0 border lc rgb \"#555555\" front"
    echo "set label \"$k\" at $k,$y center front font \",10\""
  done
}
{
  cat <<'GP'
set terminal pngcairo size 980,560 font ",11" noenhanced
GP
  echo "set output \"$out/diagram_06_steps.png\""
  cat <<'GP'
set title "Lesson 06: the map's step m against the fragment's ramp step r.\nalpha = 0.5 + (m - r)/255 and the alpha test is GREATER 0.5: lit only where m > r, so a tie is shadowed"
unset border; unset tics; unset key
set xrange [92.5:111.8]
set yrange [-0.9:6.1]
set label "no bias:\nm = 102" at 92.6,4.0 left
set label "bias.steps = 3:\nm = 105" at 92.6,1.0 left
set label "each cell: the fragment's ramp step r.   green: lit (m > r)   orange: a tie (m = r), shadowed   red: shadowed (m < r)" at 102.5,5.6 center
# row A: no bias, the caster's own depth truncated to step 102
set arrow from 102,4.9 to 102,4.34 head filled lc rgb "black" lw 2 front
set label "the map holds the caster: step 102" at 102,5.05 center font ",10"
set arrow from 102,3.0 to 102,3.66 head filled lc rgb "black" front
set label "the caster's own fragment, r = 102:\na tie, shadowed (acne)" at 102.3,2.65 right font ",10"
set arrow from 106,3.0 to 106,3.66 head filled lc rgb "black" front
set label "the floor behind it, r = 106:\nshadowed (correct)" at 105.7,2.65 left font ",10"
# row B: the offset adds 3 steps to what the map holds
set arrow from 105,1.9 to 105,1.34 head filled lc rgb "black" lw 2 front
set label "the map holds step 102 + 3 steps of offset = 105" at 105,2.05 center font ",10"
set arrow from 102,0.0 to 102,0.66 head filled lc rgb "black" front
set label "the caster's own fragment, r = 102:\n102 < 105, lit (correct)" at 102.3,-0.35 right font ",10"
set arrow from 104,0.0 to 104,0.66 head filled lc rgb "black" front
set label "a receiver less than 3 steps behind, r = 103 or 104:\nlit (wrong): the shadow comes loose" at 103.7,-0.35 left font ",10"
GP
  cells 4 102
  cells 1 105
  echo "plot NaN"
} | gnuplot

# --- 07: the decision tree of passes 2 and 3 on the digits (big, little) of the map M and of
# the fragment F; the example values are 16-bit steps written as big*256 + little.
box() {  # x1 y1 x2 y2 colour text
  echo "set object rect from $1,$2 to $3,$4 fc rgb \"$5\" fs solid 1.0 border lc rgb \"#444444\" lw 1.5"
  # gnuplot sets a label's first line at its position: lift it by half the extra lines
  local lines
  lines=$(awk -F'\\\\n' '{print NF - 1}' <<<"$6")
  echo "set label \"$6\" at ($1+$3)/2.0,($2+$4)/2.0+1.6*$lines center front"
}
arrow() {  # x1 y1 x2 y2 label
  echo "set arrow from $1,$2 to $3,$4 head filled lc rgb \"#333333\" lw 1.5"
  echo "set label \"$5\" at ($1+$3)/2.0+1,($2+$4)/2.0 left front font \",10\""
}
{
  cat <<'GP'
set terminal pngcairo size 980,640 font ",11" noenhanced
GP
  echo "set output \"$out/diagram_07_digits.png\""
  cat <<'GP'
set title "Lesson 07: 16 bits compared as two 8-bit digits in three passes (M: the map, F: the fragment)"
unset border; unset tics; unset key
set xrange [0:100]
set yrange [0:100]
GP
  box 25 88 75 98 "#dddddd" "pass 1: draw everything dimmed, stencil cleared to 0"
  box 25 68 75 80 "#eeeeee" "compare the big digits:\nbig(M) against big(F)"
  arrow 50 88 50 80 ""
  box 2 36 30 52 "#7fd17f" "big(M) > big(F)\npass 2 lights it (green)\nand writes stencil 1"
  box 36 36 64 52 "#e07070" "big(M) < big(F)\nshadowed: pass 2 discards,\npass 3's alpha is 0"
  box 70 36 98 52 "#f0f0b0" "big(M) = big(F)\npass 3 (stencil != 1):\nalpha = little(M) - little(F)"
  arrow 35 68 16 52 ">"
  arrow 50 68 50 52 "<"
  arrow 65 68 84 52 "="
  box 56 6 80 22 "#8fb0f0" "alpha > 0\npass 3 lights it (blue)"
  box 82 6 99 22 "#e07070" "alpha <= 0\nshadowed\n(a tie too)"
  arrow 80 36 68 22 ""
  arrow 88 36 90.5 22 ""
  echo "set label \"example: M = 97*256 + 168\" at 2,28 left font \",10\""
  echo "set label \"F = 96*256 + 250: green\" at 2,23 left font \",10\""
  echo "set label \"F = 98*256 + 3: shadowed\" at 2,18 left font \",10\""
  echo "set label \"F = 97*256 + 118: blue (168 - 118 > 0)\" at 2,13 left font \",10\""
  echo "set label \"F = 97*256 + 168: a tie, shadowed\" at 2,8 left font \",10\""
  echo "plot NaN"
} | gnuplot
for f in "$out/diagram_06_steps.png" "$out/diagram_07_digits.png"; do
  [[ -s $f ]] || { echo "diagrams.sh: $f was not written" >&2; exit 1; }
  echo "$f"
done
