#!/usr/bin/env bash
# docs/tls/nginx.conf in front of facetlight-server with a token (issue 31, item 1): over HTTPS the page loads
# without the token, /api needs it, and a job from the page's own https Origin is accepted.
# Usage: tests/e2e/tls_proxy.sh path/to/facetlight-server path/to/nginx
set -euo pipefail
server="$1"
nginx="$2"
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/server_session.sh"
stop_nginx() { [ -f "$work/nginx.pid" ] && kill "$(cat "$work/nginx.pid")" 2>/dev/null || true; }
trap 'stop_nginx; cleanup' EXIT

fail() { echo "FAIL: $*"; cat "$work/server.log" "$work/error.log" 2>/dev/null | tail -20; exit 1; }
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

token="tls-proxy-test-token-0123456789"
echo "$token" >"$work/token"
mkdir -p "$work/web" "$work/meshes"
echo '<!doctype html><title>facetlight</title>' >"$work/web/index.html"
start_server "$server" --data "$work/data" --meshes "$work/meshes" --web "$work/web" --token-file "$work/token" \
    --allowed-host gems.example.com || fail "the server did not start"

openssl req -x509 -newkey rsa:2048 -nodes -days 1 -subj /CN=gems.example.com \
    -addext subjectAltName=DNS:gems.example.com -keyout "$work/key.pem" -out "$work/cert.pem" 2>/dev/null
https_port="$(free_port)"
http_port="$(free_port)"
sed -e "s|listen 443 ssl|listen 127.0.0.1:$https_port ssl|" -e "s|listen 80;|listen 127.0.0.1:$http_port;|" \
    -e "s|/etc/letsencrypt/live/gems.example.com/fullchain.pem|$work/cert.pem|" \
    -e "s|/etc/letsencrypt/live/gems.example.com/privkey.pem|$work/key.pem|" \
    -e "s|127.0.0.1:8080|127.0.0.1:$port|" "$here/../../docs/tls/nginx.conf" >"$work/site.conf"
grep -q "127.0.0.1:$port" "$work/site.conf" || fail "docs/tls/nginx.conf no longer has the lines this test replaces"
cat >"$work/nginx.conf" <<CONF
pid $work/nginx.pid;
error_log $work/error.log;
events {}
http {
    access_log off;
    client_body_temp_path $work/body;
    proxy_temp_path $work/proxy;
    include $work/site.conf;
}
CONF
"$nginx" -p "$work" -c "$work/nginx.conf" || fail "nginx did not start"

url="https://gems.example.com:$https_port"
c=(curl -s -o /dev/null -w '%{http_code}' --cacert "$work/cert.pem" --resolve "gems.example.com:$https_port:127.0.0.1")
for _ in $(seq 1 100); do [ "$("${c[@]}" "$url/healthz")" = 200 ] && break; sleep 0.05; done
expect() { [ "$1" = "$2" ] || fail "$3: HTTP $1, expected $2"; }
expect "$("${c[@]}" "$url/healthz")" 200 "/healthz without the token"
expect "$("${c[@]}" "$url/")" 200 "the page without the token"
expect "$("${c[@]}" "$url/api/jobs")" 401 "/api/jobs without the token"
expect "$("${c[@]}" -H "Authorization: Bearer $token" "$url/api/jobs")" 200 "/api/jobs with the token"
expect "$("${c[@]}" -H "Authorization: Bearer $token" -H 'Content-Type: application/json' \
    -H "Origin: https://gems.example.com:$https_port" \
    --data-binary '{"mesh":"round_brilliant","photons":200,"threads":1}' "$url/api/jobs")" 202 "a job from the page's Origin"
expect "$("${c[@]}" "http://127.0.0.1:$http_port/api/jobs" -H 'Host: gems.example.com')" 301 "plain HTTP"
echo "tls_proxy: 6 requests through nginx as docs/tls/nginx.conf says"
