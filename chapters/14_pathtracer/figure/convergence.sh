#!/usr/bin/env bash
# Chapter 14's convergence chart: the Cornell box at 128 x 128 rendered with 1 to 256 samples
# per pixel by each sampler of chapter 11, and the root-mean-square error of each image against
# a 4,096-sample reference rendered with another seed, on a log-log plot.
#
#   bash convergence.sh RTK WORK_FOLDER OUTPUT.png
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rtk=$1 work=$2 png=$3
scene=$here/../../../scenes/cornell_box/cornell_box.ecs
mkdir -p "$work"
common=(-c "$scene" -size 128 128 -depth 8)
"$rtk" render "${common[@]}" -spp 4096 -seed 99 -o "$work/reference.pfm"
table=${png%.png}.tsv
for sampler in independent sobol; do
  for spp in 1 2 4 8 16 32 64 128 256; do
    "$rtk" render "${common[@]}" -spp $spp -seed 1 -sampler $sampler -o "$work/$sampler-$spp.pfm" > /dev/null
  done
done
python3 "$here/rmse.py" "$work" > "$table"
gnuplot -e "table='$table'; png='$png'" "$here/convergence.gp"
echo "wrote $png (data: $table)"
