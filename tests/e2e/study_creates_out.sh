#!/usr/bin/env bash
# `facetlight study --out DIR` makes DIR (and its parents) when missing, and says so when it cannot.
# study_creates_out.sh FACETLIGHT
set -euo pipefail
exe="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo '{"mesh": "round_brilliant", "trace": {"photons": 20000, "threads": 1}}' > "$work/job.json"
"$exe" study --job "$work/job.json" --out "$work/new/nested"
test -s "$work/new/nested/stats.json" || { echo "no stats.json in the new folder"; exit 1; }
touch "$work/file"
if "$exe" study --job "$work/job.json" --out "$work/file/below" 2> "$work/err.txt"; then
    echo "a folder under a file was accepted"; exit 1
fi
grep -q "cannot create the output folder" "$work/err.txt" || { cat "$work/err.txt"; exit 1; }
# A job given inline instead of as a file: one message naming the missing file, not the job twice over.
inline='{"mesh": "round_brilliant"}'
if "$exe" study --job "$inline" --out "$work/inline" 2> "$work/err.txt"; then
    echo "an inline job was taken for a file"; exit 1
fi
[ "$(grep -o 'round_brilliant' "$work/err.txt" | wc -l)" -eq 1 ] || { cat "$work/err.txt"; exit 1; }
grep -q "cannot open" "$work/err.txt" || { cat "$work/err.txt"; exit 1; }
echo "study --out: folder created"
