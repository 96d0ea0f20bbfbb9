# Mrays/s against leak rate, one point per layout, intersector and ISA (see speed_vs_accuracy.sh),
# for the accuracy scene's two ray sets side by side. Colour: the intersector. Shape: the ISA.
# The leak axis is logarithmic; no leak at all is drawn on the "none" line at the bottom.
set terminal pngcairo size 1100,620 font "sans,10"
set output png
set datafile separator "\t"
floor = 0.003
leak(x) = x > 0 ? x : floor
set logscale y
set yrange [floor / 1.8 : 40]
set ytics ("none" floor, "0.01" 0.01, "0.1" 0.1, "1" 1, "10" 10)
set grid
set xrange [0:*]
set offsets 0, graph 0.1, 0, 0
set xlabel "Mrays/s, one thread (higher is faster)"
set ylabel "leak rate: rays that slip through (%)"
isas = "scalar sse4 avx2 avx512"
kinds = "moeller pluecker watertight"
colour(k) = k eq "moeller" ? "#d62728" : k eq "pluecker" ? "#1f77b4" : "#2ca02c"
shape(i) = i eq "scalar" ? 4 : i eq "sse4" ? 6 : i eq "avx2" ? 8 : 7
# The layouts are not labelled: their points lie too close together to name legibly; the table
# beside the chart (.tsv) names every point.
set multiplot layout 1, 2 margins 0.07, 0.98, 0.27, 0.9 spacing 0.07 title "Speed against accuracy on the accuracy scene (BVH4; one point per layout, intersector and ISA)"
do for [set in "view inside"] {
  if (set eq "view") { set title "the camera's 256 x 256 view (65,536 rays)"; set key off } \
  else { set title "from inside, at every vertex and edge (74,896 rays)"; \
         set key at screen 0.5, screen 0.02 center bottom horizontal maxrows 3 box }
  plot for [k in kinds] for [i in isas] table \
         using ((strcol(1) eq set && strcol(3) eq k && strcol(4) eq i) ? $5 : 1/0):(leak($6)) \
         with points pt shape(i) ps 1.5 lc rgb colour(k) title sprintf("%s, %s", k, i),
}
unset multiplot
