# Mrays/s against leak rate, one point per layout, intersector and ISA (see speed_vs_accuracy.sh),
# for the accuracy scene's two ray sets side by side. Colour: the intersector. Shape: the ISA.
# Labels: the layout, on the AVX-512 points. The leak axis is logarithmic; no leak at all is
# drawn on the "none" line at the bottom.
set terminal pngcairo size 1400,650 font "sans,10"
set output png
set datafile separator "\t"
floor = 0.003
leak(x) = x > 0 ? x : floor
set logscale y
set yrange [floor / 1.8 : 40]
set ytics ("none" floor, "0.01" 0.01, "0.1" 0.1, "1" 1, "10" 10)
set grid
set xrange [0:*]
set xlabel "Mrays/s, one thread (higher is faster)"
set ylabel "leak rate: rays that slip through (%)"
isas = "scalar sse4 avx2 avx512"
kinds = "moeller pluecker watertight"
colour(k) = k eq "moeller" ? "#d62728" : k eq "pluecker" ? "#1f77b4" : "#2ca02c"
shape(i) = i eq "scalar" ? 4 : i eq "sse4" ? 6 : i eq "avx2" ? 8 : 7
# Stagger the labels vertically by layout, so that neighbours do not overwrite each other.
step(l) = l eq "triangle1" ? 0 : l eq "triangle4" ? 1 : l eq "triangle8" ? 2 : \
          l eq "triangle1i" ? 0 : l eq "triangle4i" ? 1 : l eq "triangle1v" ? 2 : 3
label_y(k, l, y) = leak(y) * (k eq "moeller" ? 1.35 ** (1 + step(l)) : 1.0 / 1.35 ** (1 + step(l)))
set multiplot layout 1, 2 title "Speed against accuracy on the accuracy scene (BVH4; one point per layout, intersector and ISA)"
do for [set in "view inside"] {
  if (set eq "view") { set title "the camera's 256 x 256 view (65,536 rays)"; set key off } \
  else { set title "from inside, at every vertex and edge (74,896 rays)"; set key outside right top box }
  plot for [k in kinds] for [i in isas] table \
         using ((strcol(1) eq set && strcol(3) eq k && strcol(4) eq i) ? $5 : 1/0):(leak($6)) \
         with points pt shape(i) ps 1.5 lc rgb colour(k) title sprintf("%s, %s", k, i), \
       table using ((strcol(1) eq set && strcol(4) eq "avx512") ? $5 : 1/0):(label_y(strcol(3), strcol(2), $6)):2 \
         with labels font "sans,7" notitle
}
unset multiplot
