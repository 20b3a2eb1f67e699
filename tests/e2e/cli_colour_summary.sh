#!/usr/bin/env bash
# What trace and render print for a coloured stone (issue 29, item 6): the absorbed share with its error when
# the material absorbs (and no such line for a clear stone), and render --colour's face-up colour figures.
set -euo pipefail
tool=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
spectrum='{"wavelength_nm": [400, 550, 700], "ordinary_per_mm": [0.3, 0.05, 0.15]}'
small=(--mesh round_brilliant --photons 4000 --threads 2 --no-view)

"$tool" trace "${small[@]}" --absorption "$spectrum" --json "$dir/absorbing.json" >"$dir/absorbing.txt"
grep -q '^  absorbed inside the stone  *[0-9.]* +- [0-9.]* %$' "$dir/absorbing.txt"
# The line says what the statistics say.
python3 - "$dir/absorbing.json" "$dir/absorbing.txt" <<'PY'
import json, re, sys
t = json.load(open(sys.argv[1]))["totals"]
line = next(l for l in open(sys.argv[2]) if "absorbed inside the stone" in l)
share, err = map(float, re.findall(r"([0-9.]+) \+- ([0-9.]+) %", line)[0])
assert t["absorbed"] > 0, t
assert abs(share - 100 * t["absorbed_share"]) < 0.006 and abs(err - 100 * t["absorbed_share_stderr"]) < 0.006, (line, t)
PY
"$tool" trace "${small[@]}" >"$dir/clear.txt"
if grep -q 'absorbed' "$dir/clear.txt"; then
  echo "a clear stone printed an absorbed share" >&2
  exit 1
fi

"$tool" render "${small[@]}" --absorption "$spectrum" --width 32 --height 32 --samples 1 --map-photons 2000 \
  --colour-picture 24 --colour-samples 1 --colour-wavelengths 8 --out "$dir/render" >"$dir/render.txt"
grep -q '^  absorbed inside the stone  *[0-9.]* +- [0-9.]* %$' "$dir/render.txt"
grep -q '^Face-up colour under D65 at 6.5 mm ([0-9]* pixels, [0-9]* view rays):$' "$dir/render.txt"
for f in L a b chroma; do
  grep -q "^  $f  *-\?[0-9.]* +- [0-9.]*   spread  *[0-9.]* +- [0-9.]*$" "$dir/render.txt"
done
grep -q '^  mean colour L\* [0-9.]* a\* -\?[0-9.]* b\* -\?[0-9.]* (#[0-9a-f]\{6\})$' "$dir/render.txt"
for f in windowed extinct saturated; do
  grep -q "^  $f  *[0-9.]*% +- [0-9.]*$" "$dir/render.txt"
done
test -s "$dir/render/colour.png"
echo "cli colour summary: ok"
