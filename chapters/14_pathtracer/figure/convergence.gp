# Chapter 14's convergence chart: RMSE against samples per pixel, both samplers, log-log, with
# the 1/sqrt(spp) slope of plain Monte Carlo for reference.
# gnuplot -e "table='IN.tsv'; png='OUT.png'" convergence.gp
set terminal pngcairo size 800,460 font "sans,11"
set output png
set datafile separator "\t"
set logscale xy
set grid
set key top right
set xrange [0.8:320]
set xtics (1, 2, 4, 8, 16, 32, 64, 128, 256)
set xlabel "samples per pixel"
set ylabel "RMSE against a 4,096-sample reference"
set title "The Cornell box, 128 x 128: error against samples per pixel"
stats table skip 1 using 2 nooutput
first = STATS_max
plot table using 1:2 with linespoints lw 2 pt 7 title "independent", \
     table using 1:3 with linespoints lw 2 pt 5 title "Sobol (Owen-scrambled)", \
     first / sqrt(x) with lines dt 2 lc rgb "#666666" title "1/sqrt(spp) from 1 spp"
