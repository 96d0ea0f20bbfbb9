# Chapter 1's chart: the slab test's speed-up over the one-box-at-a-time scalar loop, for each
# ISA variant at widths 4, 8 and 16 (the variant's own width is where its bar peaks).
# gnuplot -e "table='IN.tsv'; png='OUT.png'" simd_speedups.gp
set terminal pngcairo size 900,420 font "sans,11"
set output png
set datafile separator "\t"
set style data histograms
set style histogram clustered gap 1.5
set style fill solid 0.85 border -1
set boxwidth 0.9
set key top left
set grid ytics
set yrange [0:*]
set xrange [-0.6:2.6]
set offsets 0, 0, graph 0.12, 0
set lmargin 9
set bmargin 4
set xlabel "SIMD width of the wrapper types (lanes)"
set ylabel "box tests/s relative to scalar, width 1"
set title "The slab test per ISA variant and width (one thread; scalar at widths > 1 is the portable backend)"
plot for [c = 2:5] table using c:xtic(1) title columnheader(c) lc c, \
     for [c = 2:5] table skip 1 using ($0 + (c - 3.5) / 5.5):c:(sprintf("%.1f", column(c))) \
       with labels offset 0, 0.7 font "sans,9" notitle
