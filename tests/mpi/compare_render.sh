#!/usr/bin/env bash
# `mpirun -np R facetlight render` must write the single-process pictures and statistics (apart from `timing`):
# compare_render.sh FACETLIGHT MPIEXEC RANKS MESH
set -euo pipefail
exe="$1" mpiexec="$2" ranks="$3" mesh="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
args=(render --mesh "$mesh" --photons 100000 --threads 2 --seed 4 --width 64 --height 48 --samples 2
      --map-photons 20000)
"$exe" "${args[@]}" --out "$work/one" > /dev/null
"$mpiexec" --oversubscribe -np "$ranks" "$exe" "${args[@]}" --out "$work/many" > /dev/null
for f in render.png heatmap.png angular.png stats.csv; do cmp "$work/one/$f" "$work/many/$f"; done
python3 "$(dirname "$0")/same_stats.py" "$work/one/stats.json" "$work/many/stats.json" "$ranks"
echo "$ranks ranks: identical"
