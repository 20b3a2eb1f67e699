#!/usr/bin/env bash
# `facetlight doubling`: zircon with its axis tilted doubles the pavilion's edges seen through the table,
# diamond does not; the measurement comes out as JSON, the face-up picture as PNG; bad input is refused naming
# its flag.
# cli_doubling.sh FACETLIGHT
set -euo pipefail
exe="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$exe" doubling --mesh round_brilliant --material zircon --optic-axis-tilt 45 --doubling-picture 160 \
    --json "$work/d.json" --out "$work/out" > "$work/zircon.txt"
grep -q "through the table: median 0.0[0-9]* mm" "$work/zircon.txt" || { echo "no doubling line"; cat "$work/zircon.txt"; exit 1; }
cmp "$work/d.json" "$work/out/doubling.json" || { echo "--json and --out disagree"; exit 1; }
head -c 8 "$work/out/doubling.png" | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a" || { echo "no PNG"; exit 1; }
python3 - "$work/d.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["doubly_refracting"] is True and j["settings"]["material"] == "zircon", j
assert 0.05 < j["table"]["median_mm"] < 0.15 and j["table"]["pixels"] > 3000, j["table"]
assert j["doubling"]["picture_size"] == 160 and abs(j["view_to_axis_deg"] - 45) < 1e-9, j
PY
"$exe" doubling --mesh round_brilliant --material diamond --doubling-picture 64 > "$work/diamond.txt"
grep -q "no doubling: singly refracting" "$work/diamond.txt" || { echo "diamond doubled"; cat "$work/diamond.txt"; exit 1; }
refused() {  # refused EXPECTED-MESSAGE FLAGS...
    local expected="$1"
    shift
    if "$exe" doubling --mesh round_brilliant "$@" 2> "$work/err.txt" > /dev/null; then
        echo "accepted: $*"; exit 1
    fi
    grep -q -- "$expected" "$work/err.txt" || { echo "expected '$expected' for $*:"; cat "$work/err.txt"; exit 1; }
}
refused "--doubling-picture must be an integer between 32 and 2048" --doubling-picture 8
refused "--doubling-tilt must be" --doubling-tilt 80
refused "--loupe must be" --loupe 0
refused "--material must be one of" --material glassy
echo "doubling: zircon doubles, diamond does not"
