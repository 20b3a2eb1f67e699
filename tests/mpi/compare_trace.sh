#!/usr/bin/env bash
# `mpirun -np R facetlight trace` must write the single-process statistics bit for bit, apart from `timing`:
# compare_trace.sh FACETLIGHT MPIEXEC RANKS MESH
set -euo pipefail
exe="$1" mpiexec="$2" ranks="$3" mesh="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
args=(trace --mesh "$mesh" --photons 250000 --threads 2 --seed 9 --light hemisphere)
"$exe" "${args[@]}" --json "$work/one.json" --csv "$work/one.csv"
"$mpiexec" --oversubscribe -np "$ranks" "$exe" "${args[@]}" --json "$work/many.json" --csv "$work/many.csv" \
    --progress-json 2> "$work/progress.txt"
grep -q '"done":250000,"phase":"tracing","total":250000' "$work/progress.txt" ||
    { echo "no final progress line"; cat "$work/progress.txt"; exit 1; }
python3 - "$work/one.json" "$work/many.json" "$ranks" <<'PY'
import json, sys
one, many = (json.load(open(p)) for p in sys.argv[1:3])
assert many["timing"]["ranks"] == int(sys.argv[3]), many["timing"]
for doc in (one, many):
    doc.pop("timing")
if one != many:
    sys.exit("statistics differ between 1 and %s ranks" % sys.argv[3])
assert one["totals"]["photons"] == 250000
PY
cmp "$work/one.csv" "$work/many.csv"
echo "$ranks ranks: identical"
