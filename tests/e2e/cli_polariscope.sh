#!/usr/bin/env bash
# `facetlight polariscope`: a doubly refracting stone blinks between crossed polarisers, a singly refracting
# brilliant stays light (its reflections turn the polarisation); the readings come out as JSON, the chart as PNG and the turning view as WebP; bad input is refused
# naming its flag.
# cli_polariscope.sh FACETLIGHT
set -euo pipefail
exe="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$exe" polariscope --mesh round_brilliant --material sapphire --optic-axis-tilt 90 --angles 12 --polariscope-photons 3000 \
    --json "$work/p.json" --out "$work/out" > "$work/sapphire.txt"
grep -q "dark at 0, 90, 180 and 270 deg of a turn: doubly refracting" "$work/sapphire.txt" ||
    { echo "sapphire across its axis did not blink"; cat "$work/sapphire.txt"; exit 1; }
cmp "$work/p.json" "$work/out/polariscope.json" || { echo "--json and --out disagree"; exit 1; }
head -c 8 "$work/out/polariscope.png" | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a" || { echo "no PNG"; exit 1; }
head -c 16 "$work/out/polariscope.webp" | grep -q "WEBPVP8X" || { echo "no animated WebP"; exit 1; }
python3 - "$work/p.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert len(j["readings"]) == 12 and j["blinks"] is True, j
assert j["settings"]["material"] == "sapphire" and j["settings"]["optic_axis"]["tilt_deg"] == 90
r = {x["angle_deg"]: x["share"] for x in j["readings"]}
assert r[45.0] > 5 * r[0.0] and r[45.0] > 5 * r[90.0], r
PY
# --polariscope-picture 0: no turning view, the readings and the chart still written (it failed 'an animation
# needs a frame').
"$exe" polariscope --mesh round_brilliant --material sapphire --angles 4 --polariscope-photons 100 \
    --polariscope-picture 0 --out "$work/nopicture" > /dev/null
[[ -f "$work/nopicture/polariscope.png" && ! -e "$work/nopicture/polariscope.webp" ]] ||
    { echo "--polariscope-picture 0: expected polariscope.png and no polariscope.webp"; ls "$work/nopicture"; exit 1; }
"$exe" polariscope --mesh round_brilliant --material cubic_zirconia --angles 12 --polariscope-photons 3000 > "$work/cz.txt"
grep -q "stays light as it turns" "$work/cz.txt" || { echo "cubic zirconia's brilliant did not stay light"; cat "$work/cz.txt"; exit 1; }
refused() {  # refused EXPECTED-MESSAGE FLAGS...
    local expected="$1"
    shift
    if "$exe" polariscope --mesh round_brilliant "$@" 2> "$work/err.txt" > /dev/null; then
        echo "accepted: $*"; exit 1
    fi
    grep -q -- "$expected" "$work/err.txt" || { echo "expected '$expected' for $*:"; cat "$work/err.txt"; exit 1; }
}
refused "--angles must be an integer between 4 and 360" --angles 2
refused "--polariscope-photons must be" --polariscope-photons 5
refused "--optic-axis-tilt must be" --optic-axis-tilt 200
refused "--material must be one of" --material glassy
echo "polariscope: blinks for sapphire, stays light for cubic zirconia"
