#!/usr/bin/env bash
# Status polls while a job runs (issue 18 target: >= 10 000 requests/s with p99 < 20 ms on 2 cores): starts
# facetlight-server on a free loopback port, submits a long job, waits until it runs, then drives
# GET /api/jobs/{id} with wrk (Debian package wrk) and prints wrk's latency distribution and a Markdown row
# for docs/performance.md. The job keeps the cores busy the whole time, as in service.
#
# Usage: bench/status_polls.sh build/bin/facetlight-server [seconds=10] [connections=32] [wrk threads=2]
set -euo pipefail
server="$1"
seconds="${2:-10}"
connections="${3:-32}"
threads="${4:-2}"
command -v wrk >/dev/null || { echo "status_polls: needs wrk (apt-get install wrk)" >&2; exit 2; }
source "$(dirname "${BASH_SOURCE[0]}")/../tests/e2e/server_session.sh"
start_server "$server" --data "$work/data" --meshes "$work/meshes" --web "" --no-access-log \
    --http-threads "$threads" || { echo "the server did not start" >&2; exit 1; }
id="$(curl -sf -H 'Content-Type: application/json' \
    --data-binary '{"mesh":"round_brilliant","photons":100000000,"threads":2}' "$base/api/jobs" |
    python3 -c 'import json,sys; print(json.load(sys.stdin)["id"])')"
for _ in $(seq 1 200); do
    curl -sf "$base/api/jobs/$id" | grep -q '"state": "running"' && break
    sleep 0.05
done
curl -sf "$base/api/jobs/$id" | grep -q '"state": "running"' || { echo "the job never ran" >&2; exit 1; }
wrk -t "$threads" -c "$connections" -d "${seconds}s" --latency "$base/api/jobs/$id" | tee "$work/wrk.txt"
curl -sf "$base/api/jobs/$id" | grep -q '"state": "running"' || { echo "the job stopped during the run" >&2; exit 1; }
rps="$(sed -n 's/^Requests\/sec: *//p' "$work/wrk.txt")"
p50="$(awk '$1 == "50%" {print $2}' "$work/wrk.txt")"
p99="$(awk '$1 == "99%" {print $2}' "$work/wrk.txt")"
errors="$(sed -n 's/^ *Non-2xx or 3xx responses: *//p' "$work/wrk.txt")"
echo "| $connections | $threads | ${seconds} s | $rps | $p50 | $p99 | ${errors:-0} |"
