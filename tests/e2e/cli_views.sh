#!/usr/bin/env bash
# `facetlight render` with the viewer's views: the flags made from the settings tables turn a view on, the
# files and figures come out, and a bad value is refused naming its flag.
# cli_views.sh FACETLIGHT
set -euo pipefail
exe="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
small=(--mesh round_brilliant --photons 20000 --threads 2 --map-photons 2000 --samples 1 --width 32 --height 32)
"$exe" render "${small[@]}" --aset-samples 2 --tilt-series 2 --tilt-axis 90 --out "$work/out" > "$work/log.txt"
for f in aset.png tilt.webp tilt.png stats.json; do
    test -s "$work/out/$f" || { echo "no $f"; cat "$work/log.txt"; exit 1; }
done
grep -q "ASET shares" "$work/log.txt" || { echo "no ASET shares printed"; cat "$work/log.txt"; exit 1; }
grep -q "tilt series: 5 frames" "$work/log.txt" || { echo "not 5 frames"; cat "$work/log.txt"; exit 1; }
grep -q '"axis_deg": *90' "$work/out/stats.json" || { echo "axis_deg not in the statistics"; exit 1; }
grep -q '"samples": *2' "$work/out/stats.json" || { echo "aset.samples not in the statistics"; exit 1; }
refused() {  # refused EXPECTED-MESSAGE FLAGS...
    local expected="$1"
    shift
    if "$exe" render "${small[@]}" "$@" --out "$work/bad" 2> "$work/err.txt" > /dev/null; then
        echo "accepted: $*"; exit 1
    fi
    grep -q -- "$expected" "$work/err.txt" || { echo "expected '$expected' for $*:"; cat "$work/err.txt"; exit 1; }
}
refused "--tilt-series must be" --tilt-series 0
refused "--tilt-axis must be" --tilt-axis 400
refused "--tilt-step must be no more than" --tilt-series 2 --tilt-step 3
refused "--aset-samples must be" --aset-samples 0
echo "render: viewer's views from their flags"
