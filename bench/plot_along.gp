# Error along a knob, for sweeps whose knob costs no time (a bias, a frustum's far/near):
# bench_sweep writes <sweep>_along.png with it, next to the time-against-error plot (plot.gp).
# Called with -e setting:
#   data     one block per (scene, series), scene-major, two blank lines apart; columns
#            1 the knob's value (0 drawn at half the smallest)  2 its label  3.. one per metric
#   out, title (may hold line breaks)
#   scenes   scene names: one column of panels each
#   nseries, titles (quoted words), colors, dashes: one word per series
#   present  per scene a quoted word listing the series (1-based) that have points
#   along    the knob on the x axis;  nmetrics, ylabels (quoted words): one row per metric
#   key_title
# The first line's points are labelled with the knob's value, alternately up-left and
# down-right.
nscenes = words(scenes)
nrows = nmetrics
set datafile missing "nan"

step(v) = 10 ** floor(log10(v) + 1e-9)
eps = 1e-9
nice_below(v) = (m = v / step(v), (m >= 5 - eps ? 5 : m >= 2 - eps ? 2 : 1) * step(v))
nice_above(v) = (m = v / step(v), \
                 (m <= 1 + eps ? 1 : m <= 2 + eps ? 2 : m <= 5 + eps ? 5 : 10) * step(v))
stats data using 1 nooutput
xmin = STATS_min
xmax = STATS_max
array ymin[nrows]
array ymax[nrows]
do for [row = 1:nrows] {
  stats data using (column(2 + row)) nooutput
  ymin[row] = nice_below(STATS_min)
  ymax[row] = nice_above(STATS_max)
  if (ymax[row] <= ymin[row]) { ymax[row] = 10 * ymin[row] }
}

set terminal pngcairo size 1600, 540 * nrows + 110 font "DejaVu Sans,11" noenhanced
set output out
# The right 24% holds the legend, so every panel gets the same width.
set multiplot layout nrows, nscenes title title font ",13" \
    margins 0.06, 0.76, 0.07, 0.88 spacing 0.07, 0.1
set logscale xy
set xrange [xmin / 1.5 : xmax * 1.5]
set grid xtics ytics mxtics mytics lc rgb "#dddddd", lc rgb "#eeeeee"
set format x "%g"
set format y "%g"
do for [e = -6:6] {
  set ytics add (2 * 10.0 ** e, 5 * 10.0 ** e)
}
set xlabel along . " (0 drawn at the left edge), log scale"
do for [row = 1:nrows] {
  set yrange [ymin[row]:ymax[row]]
  do for [s = 1:nscenes] {
    here = word(present, s)
    if (words(here) == 0) {
      set multiplot next
    } else {
      first = int(word(here, 1))
      set title word(scenes, s) font ",13"
      set ylabel word(ylabels, row)
      if (row == 1 && s == nscenes) {
        set key at screen 0.775, 0.86 left top Left reverse samplen 3 spacing 1.3 box \
            lc rgb "#bbbbbb" title key_title font ",10"
      } else {
        unset key
      }
      plot for [k in here] data index ((s - 1) * nseries + int(k) - 1) using 1:(column(2 + row)) \
             with linespoints lw 2 pt 7 ps 0.9 lc int(word(colors, int(k))) \
             dt int(word(dashes, int(k))) title word(titles, int(k)), \
           data index ((s - 1) * nseries + first - 1) every 2::0 using 1:(column(2 + row)):2 \
             with labels offset -1.6, 0.7 font ",9" tc rgb "#333333" notitle, \
           data index ((s - 1) * nseries + first - 1) every 2::1 using 1:(column(2 + row)):2 \
             with labels offset 1.6, -0.7 font ",9" tc rgb "#333333" notitle
    }
  }
}
unset multiplot
