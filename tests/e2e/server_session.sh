# Sourced by tests/e2e/server_e2e.sh and bench/status_polls.sh: a scratch folder $work removed on exit with
# the server started in it, and start_server, which starts facetlight-server on a free loopback port and
# waits for /healthz. Needs python3 and curl.
work="$(mktemp -d)"
pid=""
cleanup() {
    [ -n "$pid" ] && kill "$pid" 2>/dev/null && wait "$pid" 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT

# start_server SERVER [ARGS...]: sets port, base and pid, logs to $work/server.log; false if it never answers.
start_server() {
    local server="$1"
    shift
    port="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')"
    base="http://127.0.0.1:$port"
    "$server" --host 127.0.0.1 --port "$port" "$@" >>"$work/server.log" 2>&1 &
    pid=$!
    for _ in $(seq 1 200); do curl -sf "$base/healthz" >/dev/null 2>&1 && return 0; sleep 0.05; done
    return 1
}
