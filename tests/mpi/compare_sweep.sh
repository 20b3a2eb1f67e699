#!/usr/bin/env bash
# A sweep with fire (and a search for the most) run under mpirun with R ranks, its points spread over them,
# must equal the single-process run bit for bit, apart from `timing` and the rounds' seconds:
# compare_sweep.sh FACETLIGHT MPIEXEC RANKS JOB_JSON
set -euo pipefail
exe="$1" mpiexec="$2" ranks="$3" job="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir "$work/one" "$work/many"
"$exe" study --job "$job" --out "$work/one"
"$mpiexec" --oversubscribe -np "$ranks" "$exe" study --job "$job" --out "$work/many"
python3 - "$work/one" "$work/many" <<'PY'
import json, sys
one, many = sys.argv[1], sys.argv[2]
def load(folder, name, drop):
    doc = json.load(open(f"{folder}/{name}"))
    drop(doc)
    return json.dumps(doc, sort_keys=True)
def no_timing(d): d.pop("timing")
def no_seconds(d):
    for r in d["rounds"]: r.pop("seconds")
sweep = json.load(open(f"{one}/sweep.json"))
assert len(sweep["points"]) == 8 and all("totals" in p for p in sweep["points"]), "every point traced"
assert all(p["fire"]["coloured_return_weighted"] > 0 for p in sweep["points"]), "every point's fire figures"
assert load(one, "sweep.json", no_timing) == load(many, "sweep.json", no_timing), "sweep.json differs"
assert load(one, "best.json", no_seconds) == load(many, "best.json", no_seconds), "best.json differs"
PY
for f in sweep.csv sweep.png best.obj; do cmp "$work/one/$f" "$work/many/$f"; done
echo "$ranks ranks: identical"
