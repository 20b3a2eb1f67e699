#!/usr/bin/env bash
# facetlight sweep end to end: a small grid writes sweep.json and sweep.csv with a row a point, and bad input
# ends with a message naming the fault and a non-zero exit.
set -euo pipefail
tool=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

"$tool" sweep round_brilliant --vary pavilion=39:42:1 --vary crown=33,35 --photons 2000 --threads 2 \
  --out "$dir/map" >/dev/null
test "$(wc -l <"$dir/map/sweep.csv")" -eq 9
grep -q '"weighted_return_stderr"' "$dir/map/sweep.json"
head -1 "$dir/map/sweep.csv" | grep -q ',brightness,brightness_stderr,'
test -s "$dir/map/map_brightness.png"

# --maximize alone searches for the default figure, brightness.
"$tool" sweep round_brilliant --vary pavilion=40,41 --photons 1000 --threads 2 --office-points 1000 \
  --spot-photons 20000 --maximize --refine-rounds 0 --out "$dir/default" >"$dir/default.txt"
grep -q '"figure": "brightness"' "$dir/default/best.json"
grep -Eq '^best brightness [0-9.]+ \+- .*; [0-9]+ designs? cannot be told apart' "$dir/default.txt"
if grep -q '1 designs' "$dir/default.txt"; then
  echo "one design is not designs" >&2
  exit 1
fi

"$tool" sweep round_brilliant --vary pavilion=38:43:1 --photons 2000 --threads 2 --no-view --maximize weighted_return \
  --constraint total_depth\<=61 --refine-rounds 1 --out "$dir/best" >/dev/null
grep -q '"interval"' "$dir/best/best.json"
grep -q '^# facetlight cut round_brilliant' "$dir/best/best.obj"
test -s "$dir/best/curves.png"

# With --fire every point carries its fire figures, and the search takes one.
"$tool" sweep round_brilliant --vary pavilion=40,41 --fire --no-view --photons 2000 --threads 2 --figure coloured_share \
  --maximize coloured_return_weighted --refine-rounds 0 --out "$dir/fire" >/dev/null
head -1 "$dir/fire/sweep.csv" | grep -q ',coloured_return_weighted,coloured_return_weighted_stderr,'
grep -q '"mean_separation_deg_stderr"' "$dir/fire/sweep.json"
grep -q '"figure": "coloured_return_weighted"' "$dir/fire/best.json"
test -s "$dir/fire/curves.png"

# With --colour every point carries its colour figures; a size axis darkens an absorbing stone.
"$tool" sweep round_brilliant --material blue_sapphire --vary size_mm=3,12 --colour --colour-picture 24 \
  --colour-samples 1 --colour-wavelengths 4 --no-view --photons 200 --threads 2 --figure colour_lightness \
  --out "$dir/colour" >/dev/null
head -1 "$dir/colour/sweep.csv" | grep -q '^size_mm,.*,colour_lightness,colour_lightness_stderr,'
test -s "$dir/colour/curves.png"
python3 - "$dir/colour/sweep.json" <<'PY'
import json, sys
points = json.load(open(sys.argv[1]))["points"]
small, large = (p["colour"]["colour_lightness"] for p in points)
assert large < small, (small, large)
PY

# Along the optic axis: blue sapphire seen through the table with c lying in it is lighter than along c
# (its E || c spectrum absorbs less, docs/physics.md, "Colour against the optic axis").
"$tool" sweep round_brilliant --material blue_sapphire --size-mm 8 --vary optic_axis_tilt=0,90 --colour \
  --colour-picture 120 --colour-samples 1 --colour-wavelengths 8 --no-view --photons 200 --threads 2 \
  --figure colour_lightness --out "$dir/axis" >/dev/null
head -1 "$dir/axis/sweep.csv" | grep -q '^optic_axis_tilt,'
python3 - "$dir/axis/sweep.json" <<'PY'
import json, sys
along, across = (p["colour"] for p in json.load(open(sys.argv[1]))["points"])
lift = across["colour_lightness"] - along["colour_lightness"]
sigma = (along["colour_lightness_stderr"] ** 2 + across["colour_lightness_stderr"] ** 2) ** 0.5
assert lift > 3 * sigma, (lift, sigma)
PY

# A real GemCad design's tiers (issue 27): GemCad's own standard round brilliant for quartz. A search over two
# tiers writes best.asc, which opens again with the design's 73 facets and the searched tier's slope measured
# back.
design=$(dirname "$0")/../data/gemcad/SRB.asc
"$tool" sweep "$design" --vary tier:1=42.5:43.5:0.5 --vary tier:A=33,35 --photons 1500 --threads 2 --no-view \
  --maximize weighted_return --refine-rounds 0 --out "$dir/design" >"$dir/design.txt"
grep -q 'best.asc' "$dir/design.txt"
test -s "$dir/design/map_weighted_return.png"
head -1 "$dir/design/best.asc" | grep -q '^GemCad 5.0'
"$tool" info --mesh "$dir/design/best.asc" --json >"$dir/best_info.json"
python3 - "$dir/best_info.json" "$dir/design/best.json" <<'PY'
import json, sys
info = json.load(open(sys.argv[1]))
best = json.load(open(sys.argv[2]))["best"]["values"]
# Steeper main pavilion tiers keep every facet (a shallower one than 42.5 cuts tier 2 away).
assert info["facet_count"] == 73, info["facet_count"]
tiers = {t["name"]: t for t in info["cutting_sheet"]["tiers"]}
assert sum(t["facets_cut"] for t in tiers.values()) == 73
for name, key in (("1", "tier:1"), ("A", "tier:A")):
    assert abs(abs(tiers[name]["angle_deg"]) - best[key]) < 1e-6, (tiers[name], best)
    assert abs(tiers[name]["measured_angle_deg"] - tiers[name]["angle_deg"]) < 0.01, tiers[name]
assert info["frame"]["file_orientation"] is True
PY

fails() {  # fails EXPECTED-MESSAGE ARGS...: the tool must exit non-zero and say EXPECTED-MESSAGE
  local expected=$1
  shift
  if "$tool" sweep "$@" --photons 1000 --out "$dir/bad" 2>"$dir/err" >/dev/null; then
    echo "accepted: $*" >&2
    exit 1
  fi
  grep -q "$expected" "$dir/err" || { echo "for '$*' expected '$expected', got: $(cat "$dir/err")" >&2; exit 1; }
}
fails "unknown shape" round_brillant --vary pavilion=37:45:1
fails "neither a parameter" round_brilliant --vary pavillion=37:45:1
fails "inverted" round_brilliant --vary pavilion=45:37:1
fails "must be above 0" round_brilliant --vary pavilion=37:45:0
fails "at most 10000" round_brilliant --vary pavilion=30:59:0.01 --vary crown=10:59:0.01
fails "say what to vary" round_brilliant
fails "has no parameter" round_brilliant --vary pavilion=40,41 --set tabel=55
fails "no quantity 'depth'" round_brilliant --vary pavilion=40,41 --maximize weighted_return --constraint depth\<=62
fails "unknown figure" round_brilliant --vary pavilion=40,41 --maximize sparkle
fails "^facetlight: .*--maximise; did you mean '--maximize'?" round_brilliant --vary pavilion=40,41 --maximise brightness
fails "maximize: the figure coloured_share is measured by a fire trace" round_brilliant --vary pavilion=40,41 \
  --maximize coloured_share
fails "figure: .*turn it on (--fire" round_brilliant --vary pavilion=40,41 --figure mean_separation_deg
fails "figure: .*colour view, which is off: turn it on (--colour" round_brilliant --vary size_mm=3,6 \
  --material emerald --figure colour_lightness
fails "no point of the sweep absorbs (the material diamond is clear)" round_brilliant --vary size_mm=3,6 --colour \
  --material diamond
fails "no point of the sweep absorbs (the material auto, diamond or a design's own index, is clear)" \
  round_brilliant --vary size_mm=3,6 --colour
fails "sweep.axes\[0\]: the colour view sees the stone face-up" round_brilliant --vary tilt=0,10 --colour \
  --material emerald
fails "sweep axis optic_axis_tilt needs a doubly refracting (uniaxial or biaxial) material, whose axes it turns (got diamond)" \
  round_brilliant --vary optic_axis_tilt=0:90:15 --material diamond
fails "sweep axis optic_axis_rotation needs a biaxial material, whose X axis it turns about Z (got sapphire)" \
  round_brilliant --vary optic_axis_rotation=0,90 --material sapphire
fails "sweep axis optic_axis_tilt needs polarization on" round_brilliant --vary optic_axis_tilt=0,90 \
  --material sapphire --polarization off
fails "sweep.axes\[0\]: the optic axis lies along the table's normal (optic_axis tilt 0 deg), where its azimuth" \
  round_brilliant --vary optic_axis_azimuth=0,45 --material sapphire
fails "SRB has no parameter 'tier:P9'" "$design" --vary tier:1=40,41 --set tier:P9=30
fails "neither a parameter of SRB" "$design" --vary tier:X=40,41
echo "cli sweep: ok"
