#!/usr/bin/env bash
# What trace and render print for a coloured stone (issue 29, item 6): the absorbed share with its error when
# the material absorbs (and no such line for a clear stone), and render --colour's and trace --colour's face-up
# colour figures.
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

# trace --colour measures the same figures without drawing them: the render's L* at the same settings, bit for
# bit (the colour view does not depend on the photons), in the summary and in stats.json.
"$tool" trace "${small[@]}" --absorption "$spectrum" --colour-picture 24 --colour-samples 1 --colour-wavelengths 8 \
  --json "$dir/trace-colour.json" >/dev/null
"$tool" trace "${small[@]}" --absorption "$spectrum" --colour-picture 24 --colour-samples 1 --colour-wavelengths 8 \
  >"$dir/trace-colour.txt"
grep -q '^Face-up colour under D65 at 6.5 mm ([0-9]* pixels, [0-9]* view rays):$' "$dir/trace-colour.txt"
python3 - "$dir/trace-colour.json" "$dir/render/stats.json" <<'PY'
import json, sys
traced, rendered = (json.load(open(f))["colour"] for f in sys.argv[1:])
assert traced["L"] == rendered["L"] and traced["extinct"] == rendered["extinct"], (traced["L"], rendered["L"])
PY
if "$tool" trace "${small[@]}" >/dev/null 2>&1 && "$tool" trace "${small[@]}" | grep -q 'Face-up colour'; then
  echo "trace without --colour measured the colour" >&2
  exit 1
fi
# A corundum coloured by its chromophores (docs/optics.md, "Corundum by its chromophores"): it absorbs, its
# settings keep the concentrations, and a material that is not corundum is refused naming the flag.
"$tool" trace "${small[@]}" --material ruby --absorption '{"corundum_ppma": {"cr": 300, "fe_ti": 5}}' \
  --json "$dir/corundum.json" >"$dir/corundum.txt"
grep -q '^  absorbed inside the stone  *[0-9.]* +- [0-9.]* %$' "$dir/corundum.txt"
python3 - "$dir/corundum.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["settings"]["absorption"] == {"corundum_ppma": {"cr": 300, "fe_ti": 5}}, r["settings"]["absorption"]
assert r["totals"]["absorbed"] > 0, r["totals"]
PY
if "$tool" trace "${small[@]}" --material diamond --absorption '{"corundum_ppma": {"cr": 300}}' \
  >/dev/null 2>"$dir/diamond.err"; then
  echo "corundum_ppma on diamond was not refused" >&2
  exit 1
fi
grep -q -- '--absorption: absorption.corundum_ppma colours corundum only' "$dir/diamond.err"
echo "cli colour summary: ok"
