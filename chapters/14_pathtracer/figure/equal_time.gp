# Chapter 14's equal-time chart: relative RMS error against rendering time, log-log, for RTK's
# two samplers and for Embree 3's path tracer, each against its own converged image; one panel
# per scene (the scenes found in the table).
# gnuplot -e "table='IN.tsv'; png='OUT.png'" equal_time.gp
set terminal pngcairo size 1000,440 font "sans,11"
set output png
set datafile separator "\t"
set logscale xy
set grid
set key bottom left
set xlabel "seconds, one thread (spp x median time per sample)"
set ylabel "relative RMS error"
pick(scene, program) = (strcol(1) eq scene && strcol(2) eq program) ? column(3) : NaN
stats table skip 1 using (strcol(1) eq "buddha" ? 1 : 0) nooutput
has_buddha = STATS_max > 0
if (has_buddha) { set multiplot layout 1,2 }
do for [scene in "cornell buddha"] {
  if (scene eq "cornell" || has_buddha) {
    set title (scene eq "cornell" ? "Cornell box (Embree's script), 160 x 120" : "Happy Buddha (100,000 triangles), 160 x 120")
    plot table skip 1 using (pick(scene, "RTK independent")):4 with linespoints lw 2 pt 7 title "RTK, independent", \
         table skip 1 using (pick(scene, "RTK sobol")):4 with linespoints lw 2 pt 5 title "RTK, Sobol (default)", \
         table skip 1 using (pick(scene, "Embree")):4 with linespoints lw 2 pt 9 title "Embree 3 pathtracer", \
         table skip 1 using (pick(scene, "RTK sobol -time")):4 with points pt 6 ps 1.5 lc rgb "#444444" title "RTK, -time runs as measured"
  }
}
if (has_buddha) { unset multiplot }
