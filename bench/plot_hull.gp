# Hull build time against n, log-log, one panel per point distribution and one line per
# implementation: the paper's figure 11 (Chan against divide and conquer) extended.
#
# Set with -e: csv (input), png (output), terminal ("pngcairo" or "png"), and the
# space-separated lists cases and implementations, in drawing order.

set datafile separator ','
# Filtered-out rows become NaN; treating NaN as missing keeps each line unbroken.
set datafile missing NaN

if (terminal eq 'pngcairo') {
  set terminal pngcairo size 1600,1200 enhanced font 'Sans,11' linewidth 1.2
} else {
  set terminal png size 1600,1200 enhanced font 'DejaVuSans,10'
}
set output png

# A fixed style per implementation, so a line keeps its colour when others are left out.
# Chan and divide and conquer, the paper's pair, are drawn thickest; their prefiltered
# variants share their colour, dashed.
style_names = 'chan divide-conquer graham jarvis monotone-chain chan+prefilter divide-conquer+prefilter cgal qhull'
style_colours = '#1f62b4 #d62728 #2ca02c #9467bd #8c564b #1f62b4 #d62728 #000000 #7f7f7f'
style_widths = '3 3 1.5 1.5 1.5 2 2 2 2'
style_dashes = '1 1 1 1 1 2 2 1 1'
style_points = '7 5 9 11 13 6 4 1 2'
style_index(name, i) = i > words(style_names) ? 0 : \
  (word(style_names, i) eq name ? i : style_index(name, i + 1))
do for [i = 1:words(style_names)] {
  eval sprintf("set linetype %d linecolor rgb '%s' linewidth %s dashtype %s pointtype %s", \
               i, word(style_colours, i), word(style_widths, i), word(style_dashes, i), \
               word(style_points, i))
}
# Unknown names get the next linetype, gnuplot's own colour.
linetype_of(name) = style_index(name, 1) > 0 ? style_index(name, 1) : words(style_names) + 1

selected(case_name, implementation) = \
  strcol(1) eq case_name && strcol(3) eq implementation

set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'n (points)'
set ylabel 'median build time (ms)'
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key bottom right reverse Left box opaque font ',9' spacing 1.1
set offsets graph 0.02, graph 0.02, 0, 0

set multiplot layout 2,2 title 'Convex hull build time against n (median of one whole build)' \
  font ',14'
do for [case_name in cases] {
  set title case_name font ',12'
  plot for [implementation in implementations] csv \
    using (selected(case_name, implementation) ? $2 : NaN): \
          (selected(case_name, implementation) ? $4 / 1e6 : NaN) \
    with linespoints linetype linetype_of(implementation) pointsize 0.9 title implementation
}
unset multiplot
