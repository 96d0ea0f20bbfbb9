# Leak rate against distance from the origin (see leaks_by_distance.sh): rays from inside closed
# meshes aimed at their vertices and edges, through a BVH4. Solid: with chapter 2's widened box
# exits; dashed: without. Both axes logarithmic; no leak at all is drawn on the "none" line.
set terminal pngcairo size 1000,560 font "sans,11"
set output png
set datafile separator "\t"
floor = 1e-5
leak(x) = x > 0 ? 100 * x : 100 * floor
set logscale xy
set xrange [0.5 : 2e7]
set yrange [100 * floor / 2 : 100]
set ytics ("none" 100 * floor, "0.01" 0.01, "0.1" 0.1, "1" 1, "10" 10, "100" 100)
set format x "10^{%T}"
set grid
set key outside right top box
set xlabel "distance of the meshes from the origin (every axis)"
set ylabel "leak rate: rays that slip through (%)"
set title "Rays from inside closed meshes of size 16, at every vertex and edge midpoint (BVH4)"
# The table has one column per series, in this order (leaks_by_distance.sh pivots the TSV).
titles = "Möller-Trumbore|Möller-Trumbore, exits not widened|stable Plücker|stable Plücker, exits not widened|watertight|watertight, exits not widened|Embree 3|Embree 3, robust mode"
colours = "#d62728 #d62728 #1f77b4 #1f77b4 #2ca02c #2ca02c #7f7f7f #7f7f7f"
title(i) = system(sprintf("echo '%s' | cut -d'|' -f%d", titles, i))
dashes(i) = i % 2 == 0 ? 2 : 1   # the series without widened exits are dashed, open circles
marks(i) = i % 2 == 0 ? 6 : 7
plot for [i = 1:8] table using 1:(leak(column(i + 1))) with linespoints lw 2 \
     dashtype dashes(i) pointtype marks(i) pointsize 0.9 linecolor rgb word(colours, i) title title(i)
