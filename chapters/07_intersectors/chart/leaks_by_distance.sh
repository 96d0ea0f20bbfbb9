#!/bin/sh
# Chapter 7's chart of leak rate against distance from the origin: runs leaks_by_distance
# (bench/leaks) and plots its table with gnuplot.
#
#   chapters/07_intersectors/chart/leaks_by_distance.sh [BUILD_DIR] [OUTPUT.png]
#
# BUILD_DIR defaults to build; OUTPUT to chapters/07_intersectors/ch07_leaks_by_distance.png. The
# plotted table is kept beside it (same name, .tsv). Leak counts do not depend on the machine.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build}
png=${2:-$here/../ch07_leaks_by_distance.png}
program="$build/bench/leaks_by_distance"
[ -x "$program" ] || { echo "no $program: build the leaks_by_distance target first" >&2; exit 1; }
table="${png%.png}.tsv"
"$program" > "$table"
# One row per distance, one column per series (in the program's order), for gnuplot's lines.
wide=$(mktemp)
trap 'rm -f "$wide"' EXIT
awk -F'\t' 'NR > 1 { if (!($2 in col)) { col[$2] = ++n; name[n] = $2 }
                      if (!($1 in row)) { row[$1] = ++m; key[m] = $1 }
                      rate[row[$1], col[$2]] = $5 }
             END { printf "offset"; for (j = 1; j <= n; j++) printf "\t%s", name[j]; print ""
                   for (i = 1; i <= m; i++) { printf "%s", key[i]
                     for (j = 1; j <= n; j++) printf "\t%s", rate[i, j]; print "" } }' "$table" > "$wide"
gnuplot -e "table='$wide'; png='$png'" "$here/leaks_by_distance.gp"
echo "wrote $png (data: $table)"
