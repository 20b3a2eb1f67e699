#!/usr/bin/env bash
# `mpirun -np R facetlight trace` must write the single-process statistics bit for bit, apart from `timing`:
# compare_trace.sh FACETLIGHT MPIEXEC RANKS MESH
set -euo pipefail
exe="$1" mpiexec="$2" ranks="$3" mesh="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
args=(trace --mesh "$mesh" --photons 250000 --threads 2 --seed 9 --light hemisphere)
"$exe" "${args[@]}" --json "$work/one.json" --csv "$work/one.csv" >/dev/null
"$mpiexec" --oversubscribe -np "$ranks" "$exe" "${args[@]}" --json "$work/many.json" --csv "$work/many.csv" \
    --progress-json 2> "$work/progress.txt" >/dev/null
# Tracing (too quick here to be sampled), then rank 0's viewer figures, whose last line says they are done.
tail -1 "$work/progress.txt" | grep -q '^{"done":\([0-9]*\),"phase":"viewing","total":\1}$' ||
    { echo "no final progress line"; cat "$work/progress.txt"; exit 1; }
python3 "$(dirname "$0")/same_stats.py" "$work/one.json" "$work/many.json" "$ranks"
python3 -c 'import json, sys; assert json.load(open(sys.argv[1]))["totals"]["photons"] == 250000' "$work/one.json"
cmp "$work/one.csv" "$work/many.csv"
echo "$ranks ranks: identical"
