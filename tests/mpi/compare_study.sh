#!/usr/bin/env bash
# A study run under mpirun with R ranks must equal the single-process run bit for bit, apart from `timing`:
# compare_study.sh FACETLIGHT MPIEXEC RANKS JOB_JSON
set -euo pipefail
exe="$1" mpiexec="$2" ranks="$3" job="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir "$work/one" "$work/many"
"$exe" study --job "$job" --out "$work/one"
"$mpiexec" --oversubscribe -np "$ranks" "$exe" study --job "$job" --out "$work/many" --progress-json \
    2> "$work/progress.txt"
grep -q '"phase":"done"' "$work/progress.txt" || { echo "no final progress line"; cat "$work/progress.txt"; exit 1; }
python3 "$(dirname "$0")/same_stats.py" "$work/one/stats.json" "$work/many/stats.json" "$ranks"
python3 -c 'import json, sys; assert json.load(open(sys.argv[1]))["totals"]["photons"] > 0' "$work/one/stats.json"
for f in stats.csv render.png heatmap.png angular.png; do
    if [ -f "$work/one/$f" ] || [ -f "$work/many/$f" ]; then
        cmp "$work/one/$f" "$work/many/$f"
    fi
done
echo "$ranks ranks: identical"
