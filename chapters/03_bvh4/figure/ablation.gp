# Chapter 3's chart: each traversal trick switched off, its cost as time off / time with all
# tricks on (above 1: the trick was worth that much), per structure and ray kind.
# gnuplot -e "table='IN.tsv'; png='OUT.png'" ablation.gp
set terminal pngcairo size 1000,460 font "sans,11"
set output png
set datafile separator "\t"
set style data histograms
set style histogram clustered gap 1.2
set style fill solid 0.85 border -1
set boxwidth 0.9
set key below horizontal maxrows 2 width 2
set grid ytics
set yrange [0.9:*]
set offsets 0, 0, graph 0.05, 0
set xtics rotate by -30 left
set lmargin 10
set bmargin 9
set ylabel "time with the trick off / all on"
set title "What each traversal trick buys (one thread; geometric mean over the scenes)"
stats table skip 1 using 2 nooutput
n = STATS_columns - 1
plot for [c = 2:n + 1] table using c:xtic(1) title columnheader(c) lc c, \
     1 with lines lc rgb "#444444" dt 2 notitle
