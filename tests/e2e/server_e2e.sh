#!/usr/bin/env bash
# End to end with real curl against the real facetlight-server on a free loopback port: submit, poll, fetch
# stats and PNGs, cancel a long job, restart and find everything, kill -9 during a job and find it re-run to
# the same statistics, and bad input answered with the right 4xx while the server keeps serving.
# Usage: server_e2e.sh path/to/facetlight-server
set -euo pipefail
server="$1"
source "$(dirname "${BASH_SOURCE[0]}")/server_session.sh"
fail() { echo "FAIL: $*" >&2; echo "--- server log" >&2; tail -20 "$work/server.log" >&2; exit 1; }

start() {
    start_server "$server" --data "$work/data" --meshes "$work/meshes" --web "" --cores 2 ||
        fail "the server did not start"
}
json_get() { python3 -c 'import json,sys; d=json.load(sys.stdin); print(eval("d"+sys.argv[1]))' "$1"; }
submit() {  # body -> id
    curl -sf -H 'Content-Type: application/json' --data-binary "$1" "$base/api/jobs" | json_get '["id"]'
}
state() { curl -sf "$base/api/jobs/$1" | json_get '["state"]'; }
wait_state() {  # id state...
    local id="$1"; shift
    for _ in $(seq 1 3000); do
        local s; s="$(state "$id")"
        for want in "$@"; do [ "$s" = "$want" ] && return 0; done
        case "$s" in succeeded | failed | canceled) fail "job $id is $s, expected $*" ;; esac
        sleep 0.1
    done
    fail "job $id never reached $*"
}
expect_status() {  # code curl-args...
    local want="$1"; shift
    local got; got="$(curl -s -o "$work/body" -w '%{http_code}' "$@")"
    [ "$got" = "$want" ] || fail "expected $want, got $got for curl $*: $(head -c 300 "$work/body")"
    if [ "$want" -ge 400 ]; then
        python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["status"]==int(sys.argv[2]) and d["detail"]' \
            "$work/body" "$want" || fail "no problem+json body for $*"
    fi
}
png_size() { python3 -c 'import struct,sys; b=open(sys.argv[1],"rb").read(24); assert b[:8]==b"\x89PNG\r\n\x1a\n"; print("%dx%d"%struct.unpack(">II",b[16:24]))' "$1"; }

mkdir -p "$work/meshes"
start

echo "== submit, poll, fetch"
job='{"mesh":"round_brilliant","photons":200000,"threads":2,"seed":7,
      "render":{"width":64,"height":48,"samples":1,"map_photons":20000}}'
id="$(submit "$job")"
[[ "$id" =~ ^[0-9a-f]{32}$ ]] || fail "bad job id $id"
wait_state "$id" succeeded
curl -sf "$base/api/jobs/$id/stats" -o "$work/stats.json"
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$work/stats.json" || fail "stats is not JSON"
curl -sf "$base/api/jobs/$id/stats.csv" -o "$work/stats.csv"
head -1 "$work/stats.csv" | grep -q '^id,' || fail "stats.csv has no header"
for png in render heatmap angular; do
    curl -sf "$base/api/jobs/$id/$png.png" -o "$work/$png.png"
    png_size "$work/$png.png" >/dev/null || fail "$png.png is not a PNG"
done
[ "$(png_size "$work/render.png")" = "64x48" ] || fail "render.png is $(png_size "$work/render.png")"
# the stone in 3-D for the page: a facet for each of the statistics' facets, by the same ids
curl -sf "$base/api/jobs/$id/stone.json" -o "$work/stone.json" || fail "no stone.json"
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); t=json.load(open(sys.argv[2]))
assert s["units"] == "mm" and [f["id"] for f in s["facets"]] == [f["id"] for f in t["facets"]]' \
    "$work/stone.json" "$work/stats.json" || fail "stone.json does not match the statistics' facets"
# a plain curl -d sends a form's content type, which any site's page may send too: 415 (issue 31)
expect_status 415 -d '{"mesh":"round_brilliant","photons":1000}' "$base/api/jobs"
id_small="$(submit '{"mesh":"round_brilliant","photons":1000}')"

echo "== cancel a long job"
long="$(submit '{"mesh":"round_brilliant","photons":100000000,"threads":1}')"
wait_state "$long" running
expect_status 409 "$base/api/jobs/$long/stats"
expect_status 202 -X POST "$base/api/jobs/$long/cancel"
wait_state "$long" canceled
expect_status 200 -X POST "$base/api/jobs/$long/cancel"

echo "== bad input"
expect_status 400 -H 'Content-Type: application/json' --data-binary '{"mesh":' "$base/api/jobs"
expect_status 422 -H 'Content-Type: application/json' --data-binary '{"mesh":"round_brilliant","photons":"lots"}' "$base/api/jobs"
expect_status 422 -H 'Content-Type: application/json' --data-binary '{"mesh":"round_brilliant","photons":-1}' "$base/api/jobs"
expect_status 422 -H 'Content-Type: application/json' --data-binary '{"mesh":"round_brilliant","photons":1e15}' "$base/api/jobs"
expect_status 422 -H 'Content-Type: application/json' --data-binary '{"mesh":"round_brilliant","photons":10,"threads":100000}' "$base/api/jobs"
expect_status 422 -H 'Content-Type: application/json' --data-binary '{"mesh":"no_such_stone","photons":10}' "$base/api/jobs"
expect_status 422 -H 'Content-Type: application/json' --data-binary '{"mesh":"../../../etc/passwd","photons":10}' "$base/api/jobs"
expect_status 415 -H 'Content-Type: text/xml' --data-binary '{"mesh":"round_brilliant","photons":10}' "$base/api/jobs"
head -c 3000000 /dev/zero | tr '\0' ' ' > "$work/big.json"
expect_status 413 -H 'Content-Type: application/json' --data-binary @"$work/big.json" "$base/api/jobs"
expect_status 411 -H 'Content-Type: application/json' -H 'Transfer-Encoding: chunked' \
    --data-binary '{"mesh":"round_brilliant","photons":10}' "$base/api/jobs"
expect_status 414 "$base/api/jobs/$(head -c 10000 /dev/zero | tr '\0' 'a')"
expect_status 404 "$base/api/jobs/..%2F..%2Fetc%2Fpasswd"
expect_status 404 "$base/api/jobs/00000000000000000000000000000000"
head -c 4096 /dev/urandom > "$work/junk.bin"
expect_status 422 -H 'Content-Type: application/octet-stream' --data-binary @"$work/junk.bin" "$base/api/meshes?name=junk.stl"
printf 'solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n' > "$work/truncated.stl"
expect_status 422 -H 'Content-Type: application/octet-stream' --data-binary @"$work/truncated.stl" "$base/api/meshes?name=truncated.stl"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n' > "$work/open.obj"
expect_status 422 -H 'Content-Type: application/octet-stream' --data-binary @"$work/open.obj" "$base/api/meshes?name=open.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n' > "$work/tetra.obj"
expect_status 201 -F "file=@$work/tetra.obj;filename=../../tetra.obj" "$base/api/meshes"
expect_status 415 --data-binary @"$work/tetra.obj" "$base/api/meshes?name=tetra.obj"
expect_status 421 -H 'Host: evil.example' "$base/api/jobs"
expect_status 403 -H 'Origin: http://evil.example' -X POST "$base/api/jobs/$long/cancel"
ls "$work/data/meshes" | grep -q '^[0-9a-f]\{32\}\.obj$' || fail "upload not stored under its id"
expect_status 200 "$base/healthz"

echo "== restart: jobs and results are still there"
wait_state "$id_small" succeeded
kill -TERM "$pid"; wait "$pid" || true; pid=""
start
[ "$(state "$id")" = succeeded ] || fail "job lost across a restart"
[ "$(state "$long")" = canceled ] || fail "canceled job lost across a restart"
curl -sf "$base/api/jobs/$id/stats" | cmp -s - "$work/stats.json" || fail "stats changed across a restart"

echo "== kill -9 during a job: it runs again to the same statistics"
# Long enough (seconds) to be caught running, short enough to run twice more.
crash="$(submit '{"mesh":"round_brilliant","photons":20000000,"threads":2,"seed":7}')"
wait_state "$crash" running
kill -9 "$pid"; wait "$pid" 2>/dev/null || true; pid=""
start
wait_state "$crash" succeeded
ref="$(submit '{"mesh":"round_brilliant","photons":20000000,"threads":1,"seed":7}')"
wait_state "$ref" succeeded
cmp -s <(curl -sf "$base/api/jobs/$crash/stats.csv") <(curl -sf "$base/api/jobs/$ref/stats.csv") \
    || fail "the re-run job's statistics differ from an uninterrupted run"
expect_status 204 -X DELETE "$base/api/jobs/$ref"
expect_status 404 "$base/api/jobs/$ref"
[ ! -e "$work/data/jobs/$ref" ] || fail "deleted job's files remain"
echo "PASS"
