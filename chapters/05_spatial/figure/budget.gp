# Chapter 5's chart: the duplication budget of the binned spatial splits against the references
# per triangle it lets the builder make (left) and the diffuse rays' speed they buy, relative to
# a 10 % budget (right), one line per scene. gnuplot -e "table='IN.tsv'; png='OUT.png'" budget.gp
set terminal pngcairo size 1000,400 font "sans,11" noenhanced
set output png
set datafile separator "\t"
set grid
set key top left
set logscale x
set xtics ("10 %%" 10, "30 %%" 30, "60 %%" 60, "100 %%" 100, "200 %%" 200)
set xrange [8:250]
set offsets 0, 0, graph 0.08, graph 0.08
stats table skip 1 using 1 nooutput
scenes = (STATS_columns - 1) / 2
set multiplot layout 1, 2 title "Spatial splits: the duplication budget (binned splits, BVH4, one thread)"
set xlabel "duplication budget"
set ylabel "references per triangle"
plot for [s = 0:scenes - 1] table using 1:2 * s + 2 with linespoints lw 2 pt 7 title columnheader(2 * s + 2)
set ylabel "diffuse Mrays/s relative to a 10 % budget"
plot for [s = 0:scenes - 1] table using 1:2 * s + 3 with linespoints lw 2 pt 7 title columnheader(2 * s + 3), \
     1 with lines lc rgb "#444444" dt 2 notitle
unset multiplot
