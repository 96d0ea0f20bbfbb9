# Chapter 6's chart: memory (bytes per triangle: nodes, leaf blocks and shared vertices) against
# speed (Mrays/s, one thread, best ISA of the run) for every layout with Moeller-Trumbore, primary
# rays (left) and diffuse rays (right). gnuplot -e "table='IN.tsv'; png='OUT.png'" bytes_speed.gp
set terminal pngcairo size 1100,480 font "sans,10"
set output png
set datafile separator "\t"
set datafile commentschars "#"
set grid
unset key
set offsets graph 0.02, graph 0.22, graph 0.06, graph 0.08
set xlabel "bytes per triangle (less is better)"
set ylabel "Mrays/s, one thread (more is better)"
colour(l) = strstrt(l, "4") || strstrt(l, "8") ? 0x1f77b4 : 0xd62728
set multiplot layout 1, 2 title "Triangle layouts: memory against speed (BVH4 over the 130,560-triangle sphere, Möller-Trumbore; blue: blocks of 4 or 8, red: single triangles)"
do for [kind in "primary diffuse"] {
  set title kind . " rays"
  plot table using (strcol(1) eq kind ? $3 : 1/0):4:(colour(strcol(2))) with points pt 7 ps 1.2 lc rgb variable, \
       table using (strcol(1) eq kind ? $5 : 1/0):6:2 with labels left font "sans,8"
}
unset multiplot
