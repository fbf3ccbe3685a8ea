# Ours / Box2D v3 per scene of its benchmark suite: one bar per setting (matched, our defaults)
# and worker count, from bench/results/step_v3_ratios.csv. Below the line at 1 ours is faster.
#
# Set with -e: csv (input), png (output), terminal ("pngcairo" or "png").

set datafile separator ','
# A scene one side did not run has an empty cell: no bar.
set datafile missing ''

if (terminal eq 'pngcairo') {
  set terminal pngcairo size 1400,700 noenhanced font 'Sans,11'
} else {
  set terminal png size 1400,700 noenhanced font 'DejaVuSans,10'
}
set output png

set title "Step time against Box2D v3 on its benchmark suite: ours / Box2D v3 (median wall time)" \
  font ',14'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set ylabel 'ours / Box2D v3'
set yrange [0:*]
set grid ytics lc rgb '#dddddd'
set xtics scale 0
set key top left box opaque
# The first line names the columns, the bars' titles.
set key autotitle columnheader
# Matched settings blue, our defaults orange; lighter with more workers.
colours = '#1f62b4 #f28e2b #7fb0e0 #ffc58a #0b3a70 #b35806'
columns = system(sprintf("head -1 '%s' | awk -F, '{ print NF }'", csv)) + 0
rows = system(sprintf("awk 'END { print NR - 1 }' '%s'", csv)) + 0
# Every scene keeps its place, with bars or without.
set xrange [-0.5:rows - 0.5]

bars = columns - 1
# Where gnuplot puts bar i of a cluster (clustered, gap 1): its value is written above it.
bar_x(i) = $0 + (i - 2 - (bars - 1) / 2.0) / (bars + 1.0)

plot for [i = 2:columns] csv using i:xtic(1) \
       linecolor rgb word(colours, (i - 2) % words(colours) + 1), \
     for [i = 2:columns] csv using (bar_x(i)):i:(sprintf('%.2f', column(i))) \
       with labels offset 0, 0.7 font ',8' notitle, \
     1 with lines dashtype 2 linecolor rgb '#000000' linewidth 2 title 'Box2D v3'
