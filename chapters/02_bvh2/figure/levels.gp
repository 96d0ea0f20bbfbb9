# Chapter 2's picture: the boxes of a median-built BVH2, level by level, over its triangles.
# gnuplot -e "dir='FOLDER'; png='OUT.png'" levels.gp, FOLDER written by ch02_figure.
set terminal pngcairo size 1200,360 font "sans,11"
set output png
set datafile separator "\t"
set size ratio -1
unset key
unset xtics
unset ytics
set border 0
set xrange [5:100]
set yrange [5:100]
tris = dir . "/triangles.tsv"
boxes = dir . "/boxes.tsv"
colour(d) = d == 1 ? 0xd62728 : d == 2 ? 0x1f77b4 : d == 3 ? 0x2ca02c : 0x9467bd
set multiplot layout 1, 4 margins 0.01, 0.99, 0.02, 0.88 spacing 0.02 \
    title "A median-built BVH2 over 96 triangles, two per leaf" font "sans,13"
do for [d = 1:3] {
  set title sprintf("depth %d: %d boxes", d, 2 ** d)
  plot tris with filledcurves closed fc rgb "#bbbbbb" fs solid 1.0 border lc rgb "#777777", \
       boxes using (column(5) == d ? ($1 + $3) / 2 : 1/0):(($2 + $4) / 2):(($3 - $1) / 2):(($4 - $2) / 2) \
         with boxxyerror fs empty lw 2 lc rgb colour(d)
}
set title "the leaves"
plot tris with filledcurves closed fc rgb "#bbbbbb" fs solid 1.0 border lc rgb "#777777", \
     boxes using (column(6) == 1 ? ($1 + $3) / 2 : 1/0):(($2 + $4) / 2):(($3 - $1) / 2):(($4 - $2) / 2) \
       with boxxyerror fs empty lw 1.2 lc rgb colour(4)
unset multiplot
