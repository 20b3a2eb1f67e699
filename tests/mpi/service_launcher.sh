#!/usr/bin/env bash
# The service with a launcher: facetlight-server --launcher 'mpirun -np 2' runs a job through mpirun on this
# machine to the same statistics as the in-process path, shows its progress while it runs, and cancels another
# job, leaving no rank behind.
# Usage: service_launcher.sh path/to/facetlight-server path/to/mpirun
set -euo pipefail
server="$1" mpirun="$2"
work="$(mktemp -d)"
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null && wait "$p" 2>/dev/null; done
    rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; tail -20 "$work"/*.log >&2; exit 1; }
json_get() { python3 -c 'import json,sys; d=json.load(sys.stdin); print(eval("d"+sys.argv[1]))' "$1"; }

start() {  # name extra-args... ; sets base_<name>
    local name="$1"; shift
    "$server" --host 127.0.0.1 --port 0 --data "$work/$name" --web "" --cores 2 --no-access-log "$@" \
        >"$work/$name.log" 2>&1 &
    pids+=($!)
    for _ in $(seq 1 200); do
        local port; port="$(sed -n 's|.*listening on http://127.0.0.1:\([0-9]*\)/.*|\1|p' "$work/$name.log")"
        if [ -n "$port" ] && curl -sf "http://127.0.0.1:$port/healthz" >/dev/null; then
            eval "base_$name=http://127.0.0.1:$port"
            return 0
        fi
        sleep 0.05
    done
    fail "the $name server did not start"
}
submit() { curl -sf -H 'Content-Type: application/json' --data-binary "$2" "$1/api/jobs" | json_get '["id"]'; }
status() { curl -sf "$1/api/jobs/$2"; }
wait_done() {  # base id -> final state; prints the most progress seen on fd 3
    local seen=0
    for _ in $(seq 1 1200); do
        local doc; doc="$(status "$1" "$2")"
        local s; s="$(echo "$doc" | json_get '["state"]')"
        local done; done="$(echo "$doc" | json_get '["progress"]["done"]')"
        [ "$done" -gt "$seen" ] 2>/dev/null && seen="$done"
        case "$s" in succeeded | failed | canceled) echo "$s $seen"; return 0 ;; esac
        sleep 0.1
    done
    fail "job $2 did not finish"
}

start local
start mpi --launcher "$mpirun -np 2 --oversubscribe"
rank_pattern="facetlight study --progress-json --job"  # the launcher's child command line
job='{"mesh":"round_brilliant","photons":3000000,"threads":1,"seed":11}'

read -r state seen < <(wait_done "$base_mpi" "$(submit "$base_mpi" "$job")")
[ "$state" = succeeded ] || fail "the launched job ended $state"
[ "$seen" -gt 0 ] || fail "no progress was reported while the launched job ran"
id_mpi="$(curl -sf "$base_mpi/api/jobs?limit=1" | json_get '["jobs"][0]["id"]')"
id_local="$(submit "$base_local" "$job")"
read -r state _ < <(wait_done "$base_local" "$id_local")
[ "$state" = succeeded ] || fail "the in-process job ended $state"
cmp <(curl -sf "$base_mpi/api/jobs/$id_mpi/stats.csv") <(curl -sf "$base_local/api/jobs/$id_local/stats.csv") ||
    fail "the launched job's statistics differ from the in-process ones"

long="$(submit "$base_mpi" '{"mesh":"round_brilliant","photons":100000000,"threads":1}')"
for _ in $(seq 1 200); do [ "$(status "$base_mpi" "$long" | json_get '["state"]')" = running ] && break; sleep 0.05; done
sleep 1
[ "$(pgrep -fc "$rank_pattern")" -ge 2 ] || fail "the long job is not running as mpirun ranks"
curl -sf -X POST "$base_mpi/api/jobs/$long/cancel" >/dev/null
read -r state _ < <(wait_done "$base_mpi" "$long")
[ "$state" = canceled ] || fail "the cancelled launched job ended $state"
sleep 0.5
! pgrep -f "$rank_pattern" >/dev/null || fail "a rank of the cancelled job is still running"
echo "service launcher: ok"
