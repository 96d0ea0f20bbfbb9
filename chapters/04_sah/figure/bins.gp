# Chapter 4's chart: bins per axis against build speed (left axis) and the SAH cost of the tree
# (right axis), both relative to 32 bins. gnuplot -e "table='IN.tsv'; png='OUT.png'" bins.gp
set terminal pngcairo size 800,420 font "sans,11"
set output png
set datafile separator "\t"
set logscale x 2
set xtics (4, 8, 16, 32, 64)
set xrange [3.4:76]
set grid
set key top right
set offsets 0, 0, graph 0.1, graph 0.1
set xlabel "bins per axis"
set ylabel "build speed relative to 32 bins"
set y2label "SAH cost relative to 32 bins"
set ytics nomirror
set y2tics
set lmargin 10
set rmargin 11
set title "Binned SAH: bins against build speed and tree quality (BVH4, 1M-triangle terrain, one thread)"
plot table using 1:2 axes x1y1 with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "build speed (Mtris/s)", \
     table using 1:3 axes x1y2 with linespoints lw 2 pt 5 lc rgb "#d62728" title "SAH cost (lower is better)"
