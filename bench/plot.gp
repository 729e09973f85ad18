# Time against error for one lesson's sweep. bench_sweep calls it with -e setting:
#   data     the .plot.dat: one block per (scene, series), scene-major, two blank lines apart;
#            columns 1 frame_ms  2 cpu_ms  3 frame_min_ms  4 vis_mae  5 false_shadow_pct
#            6 false_lit_pct  7 shade_mae  8 a point's label  9 the value of `along`
#            10 air_rel_rmse (%)  11 air_mae (lesson 08; nan elsewhere)
#   out      the PNG to write;  title  the page title
#   xcol, xlabel  the time column and its axis label
#   scenes   scene names: one column of panels each
#   nseries, titles (quoted words), colors, dashes: one word per series
#   present  per scene a quoted word listing the series (1-based) that have points
#   along    the knob that changes along each line
#   ycols, ylabels (quoted words): one row of panels per error metric
nscenes = words(scenes)
nrows = words(ycols)
set datafile missing "nan"

# Ranges rounded out to 1-2-5 steps, shared by all panels (x) and along a row (y), so panels
# compare at a glance.
step(v) = 10 ** floor(log10(v) + 1e-9)
eps = 1e-9
nice_below(v) = (m = v / step(v), (m >= 5 - eps ? 5 : m >= 2 - eps ? 2 : 1) * step(v))
nice_above(v) = (m = v / step(v), \
                 (m <= 1 + eps ? 1 : m <= 2 + eps ? 2 : m <= 5 + eps ? 5 : 10) * step(v))
stats data using xcol nooutput
xmin = nice_below(STATS_min)
xmax = nice_above(STATS_max)
if (xmax <= xmin) { xmax = 10 * xmin }
array ymin[nrows]
array ymax[nrows]
do for [row = 1:nrows] {
  stats data using int(word(ycols, row)) nooutput
  ymin[row] = nice_below(STATS_min)
  ymax[row] = nice_above(STATS_max)
  if (ymax[row] <= ymin[row]) { ymax[row] = 10 * ymin[row] }
}

set terminal pngcairo size 1600, 540 * nrows + 90 font "DejaVu Sans,11" noenhanced
set output out
# The right 22% holds the legend, so every panel gets the same width.
set multiplot layout nrows, nscenes title title font ",14" \
    margins 0.06, 0.78, 0.07, 0.91 spacing 0.07, 0.1
set logscale xy
set xrange [xmin:xmax]
set grid xtics ytics mxtics mytics lc rgb "#dddddd", lc rgb "#eeeeee"
set format x "%g"
set format y "%g"
# Labelled tics at 1, 2 and 5 of every decade, not only at the decades; a knob that spans
# many decades (xcol 9, e.g. a bias) gets one label per decade, or they would overlap.
do for [e = -6:6] {
  if (xcol != 9) { set xtics add (2 * 10.0 ** e, 5 * 10.0 ** e) }
  set ytics add (2 * 10.0 ** e, 5 * 10.0 ** e)
}
set xlabel xlabel . ", log scale"
do for [row = 1:nrows] {
  ycol = int(word(ycols, row))
  set yrange [ymin[row]:ymax[row]]
  do for [s = 1:nscenes] {
    here = word(present, s)
    if (words(here) == 0) {
      set multiplot next
    } else {
      first = int(word(here, 1))
      set title word(scenes, s) font ",13"
      set ylabel word(ylabels, row) . ", log scale"
      if (row == 1 && s == nscenes) {
        key_title = "one line per knob combination;\nalong a line: " . along . \
            "\n(labels on the first line,\nalternately up-left and down-right)" . \
            "\nerror 0 is drawn at half a pixel\n"
        set key at screen 0.795, 0.89 left top Left reverse samplen 4 spacing 1.4 box \
            lc rgb "#bbbbbb" title key_title
      } else {
        unset key
      }
      plot for [k in here] data index ((s - 1) * nseries + int(k) - 1) using xcol:ycol \
             with linespoints lw 2 pt 7 ps 0.9 lc int(word(colors, int(k))) \
             dt int(word(dashes, int(k))) title word(titles, int(k)), \
           data index ((s - 1) * nseries + first - 1) every 2::0 using xcol:ycol:8 \
             with labels offset -1.6, 0.7 font ",9" tc rgb "#333333" notitle, \
           data index ((s - 1) * nseries + first - 1) every 2::1 using xcol:ycol:8 \
             with labels offset 1.6, -0.7 font ",9" tc rgb "#333333" notitle
    }
  }
}
unset multiplot
