#!/bin/sh
# The speed-against-accuracy chart of chapter 7: runs the chart benchmarks (Mrays/s through
# BVH4 and the leak rate, on the same rays of the accuracy scene, for every layout, intersector
# and ISA) and plots one against the other with gnuplot.
#
#   chapters/07_intersectors/chart/speed_vs_accuracy.sh [BUILD_DIR] [OUTPUT.png]
#
# BUILD_DIR defaults to build; OUTPUT to chapters/07_intersectors/ch07_speed_vs_accuracy.png. The
# plotted table is kept beside it (same name, .tsv).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build}
png=${2:-$here/../ch07_speed_vs_accuracy.png}
bench="$build/chapters/07_intersectors/ch07_bench"
[ -x "$bench" ] || { echo "no $bench: build the ch07_bench target first" >&2; exit 1; }
json=$(mktemp)
trap 'rm -f "$json"' EXIT
table="${png%.png}.tsv"
# Three runs of each point, the median plotted: the machines are shared.
"$bench" --benchmark_filter='^chart/' --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_format=json --benchmark_out_format=json --benchmark_out="$json" > /dev/null
python3 "$here/chart_table.py" "$json" > "$table"
gnuplot -e "table='$table'; png='$png'" "$here/speed_vs_accuracy.gp"
echo "wrote $png (data: $table)"
