#!/usr/bin/env bash
# facetlight trace for a person and for a program: by default the verdict and the figures as text; with
# --json the statistics as JSON on stdout (no file, or -) or in a file, the summary still printed.
set -euo pipefail
tool=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
small=(--mesh round_brilliant --photons 4000 --threads 2 --office-points 2000 --spot-photons 40000)

"$tool" trace "${small[@]}" >"$dir/summary.txt"
grep -q '^Verdict: light performance 100.0 +- [0-9.]* (the GIA reference: 100); no faults$' "$dir/summary.txt"
grep -q "^  brightness [0-9.]* +- [0-9.]* %, as the GIA reference's" "$dir/summary.txt"
grep -q '^  none  fish-eye: ' "$dir/summary.txt"
grep -q '^  cosine-weighted return  *[0-9.]* +- [0-9.]* %$' "$dir/summary.txt"
if grep -q '^  none  bow-tie' "$dir/summary.txt"; then
  echo "the bow-tie does not apply to a round stone" >&2
  exit 1
fi

# A mesh with no facet facing up is turned so its largest faces up, and the statistics say so; --keep-frame
# keeps it as it is (docs/gemcad.md). A tetrahedron standing on a vertex.
cat >"$dir/tetra.obj" <<'OBJ'
v 1 1 1
v -1 -1 1
v -1 1 -1
v 1 -1 -1
f 1 2 4
f 1 3 2
f 1 4 3
f 2 3 4
OBJ
"$tool" trace --mesh "$dir/tetra.obj" --photons 2000 --no-view --json "$dir/tetra.json" >/dev/null
"$tool" trace --mesh "$dir/tetra.obj" --photons 2000 --no-view --keep-frame --json "$dir/kept.json" >/dev/null
python3 - "$dir/tetra.json" "$dir/kept.json" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
# trace --json writes what a job's stats.json holds of the stone (docs/stats-schema.md).
assert stats["material"]["source"] == "default" and stats["material"]["name"] == "diamond", stats["material"]
assert stats["material"]["optic"] == "isotropic" and stats["material"]["birefringence"] == 0, stats["material"]
assert stats["cutting_sheet"]["source"] == "measured from the mesh", stats["cutting_sheet"]["source"]
assert stats["size"]["carats"] > 0, stats["size"]
turned, kept = (json.load(open(p))["mesh"]["frame"] for p in sys.argv[1:3])
assert turned["file_orientation"] is False and turned["turned_deg"] > 1, turned
assert kept["file_orientation"] is True and "table_facet" not in kept, kept
PY
# A doubly refracting material says so: calcite, traced at n_o (docs/optics.md).
"$tool" trace --mesh "$dir/tetra.obj" --photons 2000 --no-view --material calcite --json "$dir/calcite.json" >/dev/null
python3 - "$dir/calcite.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))["material"]
assert m["optic"] == "uniaxial" and abs(m["birefringence"] - 0.1722) < 1e-4 and abs(m["n_d"] - 1.6583) < 1e-4, m
PY

"$tool" trace "${small[@]}" --json >"$dir/stdout.json"
"$tool" trace "${small[@]}" --json - >"$dir/dash.json"
"$tool" trace "${small[@]}" --json "$dir/file.json" --csv "$dir/facets.csv" >"$dir/with-file.txt"
grep -q '^Verdict: ' "$dir/with-file.txt"
python3 - "$dir" <<'PY'
import json, sys
d = sys.argv[1]
docs = [json.load(open(f"{d}/{name}.json")) for name in ("stdout", "dash", "file")]
for doc in docs:
    doc.pop("timing")
assert docs[0] == docs[1] == docs[2], "the three ways of asking for JSON differ"
assert docs[0]["viewer"]["score"]["value"] == 100.0, docs[0]["viewer"]["score"]
# The facet table carries each share's binomial standard error over the photons that hit the stone.
import csv, math
rows = list(csv.DictReader(open(f"{d}/facets.csv")))
facets = {f["id"]: f for f in docs[2]["facets"]}
hit = docs[2]["totals"]["hit"]
assert len(rows) == len(facets)
for r in rows:
    p = facets[int(r["id"])]["leaving_share"]
    assert abs(float(r["leaving_share_stderr"]) - math.sqrt(p * (1 - p) / hit)) <= 1e-8, (r, p)
assert any(float(r["leaving_share_stderr"]) > 0 for r in rows)
PY

# Without the viewer: the trace's figures alone.
"$tool" trace "${small[@]}" --no-view >"$dir/plain.txt"
if grep -q '^Verdict' "$dir/plain.txt"; then
  echo "a trace without the viewer printed a verdict" >&2
  exit 1
fi
grep -q '^Trace: 4000 photons' "$dir/plain.txt"
# A mistyped flag or subcommand: the facetlight: prefix, the name meant, a non-zero exit.
if "$tool" trace --mesh round_brilliant --photon 1000 2>"$dir/err" >/dev/null; then
  echo "accepted --photon" >&2
  exit 1
fi
grep -q "^facetlight: .*--photon; did you mean '--photons'?" "$dir/err"
if "$tool" trcae 2>"$dir/err" >/dev/null; then
  echo "accepted trcae" >&2
  exit 1
fi
grep -q "^facetlight: .*did you mean 'trace'?" "$dir/err"
echo "cli summary: ok"
