# Chapter 4's growth chart: build time per triangle (left axis; one thread's also as its user
# time alone) and peak memory per triangle (right axis) of the default structure's tree against
# the scene's size, with the curve that user time would follow if it grew like log n.
# gnuplot -e "table='IN.tsv'; png='OUT.png'" growth.gp
set terminal pngcairo size 800,420 font "sans,11"
set output png
set datafile separator "\t"
set logscale x 2
set xtics ("1M" 1000000, "4M" 4000000, "16M" 16000000)
set xrange [700000:23000000]
set grid
set key bottom right
set xlabel "triangles"
set ylabel "build time per triangle (ns)"
set y2label "peak memory per triangle (bytes)"
set yrange [0:*]
set y2range [0:*]
set ytics nomirror
set y2tics
set lmargin 10
set rmargin 11
set title "Binned SAH, BVH8 with rotations, leaves in blocks of 8, spheres: growth with the number of triangles"
plot table using 1:2 axes x1y1 with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "time, one thread (CPU time)", \
     table using 1:7 axes x1y1 with linespoints lw 2 pt 6 lc rgb "#2ca02c" title "of which the builder's own (user time)", \
     table using 1:3 axes x1y1 with linespoints lw 2 pt 9 lc rgb "#17becf" title "time, two threads (wall clock)", \
     table using 1:6 axes x1y1 with lines lw 1 dt 2 lc rgb "#555555" title "log n from 1M (user time)", \
     table using 1:4 axes x1y2 with linespoints lw 2 pt 5 lc rgb "#d62728" title "peak memory"
