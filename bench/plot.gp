# Error against time for one sweep, with its Pareto front. bench_sweep (plot.cpp) decides the
# panels, the ranges and where every label goes; this only draws. Called with -e setting:
#   term     png, or svg (hovering a point shows its settings, time and error)
#   out, width, height (pixels), title (may hold line breaks)
#   data     six blocks per panel p, at index 6(p-1) + 0 the other points (time, error, hover
#            text with \n for line breaks, colour 0xRRGGBB) and + 1 the front in cost order
#            (time, error, hover text), + 2 the lesson's default, + 3 label lines (time, error,
#            text, colour; left end and middle of the line), + 4 leader lines (two-point
#            segments), + 5 each series' own front as steps (time, error, colour; a blank line
#            between)
#   npanels; per panel, words: p_left p_right p_bottom p_top (screen fractions of the plot
#            area), p_ymin p_ymax, p_ysteps p_titles p_ylabels (quoted)
#   xmin, xmax, xsteps, xlabel: the time axis, shared by every panel
#   key_x, key_y (screen), key_front, key_other, key_default, note
#   series, series_colours: the series' names and colours (#rrggbb), words; "" for none
set datafile missing "nan"
# The two characters \n to line breaks (a data file's strings take no escapes).
lines(s) = (i = strstrt(s, "\\n"), i == 0 ? s : s[1:i - 1] . "\n" . lines(s[i + 2:]))
# Fonts in points; the SVG's are pixels, cairo's PNG has 4/3 as many pixels as points.
px = (term eq "svg") ? 4.0 / 3.0 : 1.0
font(pt) = sprintf("DejaVu Sans,%g", pt * px)
front_color = "#1f5fa8"
other_color = "#b9b9b9"
default_color = "#d0362c"
f9 = font(9)
f10 = font(10)
f11 = font(11)
f13 = font(13)

if (term eq "svg") {
  set terminal svg size width, height mouse standalone font f10 noenhanced background "white"
} else {
  set terminal pngcairo size width, height font f10 noenhanced
}
set output out
set multiplot title title font f13
set logscale xy
set xrange [xmin:xmax]
set grid xtics ytics mxtics mytics lc rgb "#dddddd", lc rgb "#f0f0f0"
set format x "%g"
set format y "%g"
# Labelled tics at the multiples of each decade that xsteps and p_ysteps list (more where a
# decade is long on the page), not only at the decades.
set xtics
do for [e = -6:6] {
  do for [k in xsteps] { set xtics add (real(k) * 10.0 ** e) }
}
set xlabel xlabel font f10
if (strlen(note) > 0) {
  set label 1 note at screen key_x, key_y - (74.0 + 20.0 * words(series)) / height left font f10 \
      tc rgb "#555555"
}
do for [p = 1:npanels] {
  set lmargin at screen real(word(p_left, p))
  set rmargin at screen real(word(p_right, p))
  set bmargin at screen real(word(p_bottom, p))
  set tmargin at screen real(word(p_top, p))
  ylo = real(word(p_ymin, p))
  yhi = real(word(p_ymax, p))
  set yrange [ylo:yhi]
  set ytics
  ysteps = word(p_ysteps, p)
  do for [e = -6:6] {
    do for [k in ysteps] { set ytics add (real(k) * 10.0 ** e) }
  }
  set title lines(word(p_titles, p)) font f11
  set ylabel lines(word(p_ylabels, p)) font f10
  if (p == 1) {
    set key at screen key_x, key_y left top vertical Left reverse samplen 3 spacing 1.25 \
        font f10 nobox
  } else {
    unset key
  }
  b = 6 * (p - 1)
  if (term eq "svg") {
    plot data index b using 1:2:(lines(stringcolumn(3))):4 \
           with labels hypertext point pt 7 ps 0.7 lc rgb variable notitle, \
         data index b + 5 using 1:2:3 with lines lw 1.5 lc rgb variable notitle, \
         data index b + 1 using 1:2 with steps lw 2.5 lc rgb front_color notitle, \
         data index b + 1 using 1:2:(lines(stringcolumn(3))) \
           with labels hypertext point pt 7 ps 1.2 lc rgb front_color notitle, \
         data index b + 2 using 1:2 with points pt 6 ps 2.6 lw 2 lc rgb default_color notitle, \
         data index b + 4 using 1:2 with lines lw 1 lc rgb "#888888" notitle, \
         data index b + 3 using 1:2:3:4 with labels left font f9 tc rgb variable notitle, \
         keyentry with linespoints lw 2.5 pt 7 ps 1.2 lc rgb front_color title key_front, \
         keyentry with points pt 7 ps 0.7 lc rgb other_color title key_other, \
         keyentry with points pt 6 ps 2.6 lw 2 lc rgb default_color title key_default, \
         for [k = 1:words(series)] keyentry with linespoints lw 1.5 pt 7 ps 0.7 \
           lc rgb word(series_colours . " #000000", k) title word(series, k)
  } else {
    plot data index b using 1:2:4 with points pt 7 ps 0.7 lc rgb variable notitle, \
         data index b + 5 using 1:2:3 with lines lw 1.5 lc rgb variable notitle, \
         data index b + 1 using 1:2 with steps lw 2.5 lc rgb front_color notitle, \
         data index b + 1 using 1:2 with points pt 7 ps 1.2 lc rgb front_color notitle, \
         data index b + 2 using 1:2 with points pt 6 ps 2.6 lw 2 lc rgb default_color notitle, \
         data index b + 4 using 1:2 with lines lw 1 lc rgb "#888888" notitle, \
         data index b + 3 using 1:2:3:4 with labels left font f9 tc rgb variable notitle, \
         keyentry with linespoints lw 2.5 pt 7 ps 1.2 lc rgb front_color title key_front, \
         keyentry with points pt 7 ps 0.7 lc rgb other_color title key_other, \
         keyentry with points pt 6 ps 2.6 lw 2 lc rgb default_color title key_default, \
         for [k = 1:words(series)] keyentry with linespoints lw 1.5 pt 7 ps 0.7 \
           lc rgb word(series_colours . " #000000", k) title word(series, k)
  }
}
unset multiplot
