#!/usr/bin/env python3
"""Hostile requests against the real facetlight-server (issue 18): malformed and smuggling-prone heads, bad
lengths, short and abandoned bodies, deep JSON, out-of-range settings, hostile meshes, slow clients, a
forged access-log line, a disk under --min-free and (where a tmpfs can be mounted) a disk that is really full
or read-only. Every answer must have the expected status, every error must be problem+json, /healthz must
answer within a second after each request, and every status seen on a route of the API must be documented
for it in the OpenAPI document the server serves.

Usage: tests/server/hostile_requests.py path/to/facetlight-server
"""
import errno
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time

ID = "0123456789abcdef0123456789abcdef"
HTTP_THREADS = 2
MAX_PER_PEER = 24
REQUEST_TIMEOUT_S = 3
MAX_BODY = 1 << 20


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    def __init__(self, binary, work, *extra, log_dir=None, host="127.0.0.1", per_peer=MAX_PER_PEER,
                 request_timeout=REQUEST_TIMEOUT_S):
        self.port = free_port()
        self.disk_full = False  # on a full disk /healthz may answer 503: nothing can be written
        os.makedirs(os.path.join(work, "meshes"), exist_ok=True)
        self.log_path = os.path.join(log_dir or work, "server.log")
        self.log = open(self.log_path, "ab")
        self.proc = subprocess.Popen(
            [binary, "--host", host, "--port", str(self.port), "--data", os.path.join(work, "data"),
             "--meshes", os.path.join(work, "meshes"), "--web", os.path.join(work, "web"), "--cores", "1",
             "--http-threads", str(HTTP_THREADS), "--max-connections-per-peer", str(per_peer),
             "--request-timeout", str(request_timeout), "--max-body", str(MAX_BODY), *extra],
            stdout=self.log, stderr=self.log)
        # The server measures this machine's rates before it listens: about 1 s, ten times that under ASan.
        deadline = time.time() + 60
        while time.time() < deadline and self.proc.poll() is None:
            try:
                # 503: up, on a disk that takes no more writes.
                if self.request(b"GET /healthz HTTP/1.1\r\nHost: localhost\r\n\r\n", timeout=1)[0] in (200, 503):
                    return
            except OSError:
                time.sleep(0.05)
        raise SystemExit("FAIL: the server did not start\n" + open(self.log_path).read())

    def connect(self, timeout=5):
        s = socket.create_connection(("127.0.0.1", self.port), timeout=timeout)
        s.settimeout(timeout)
        return s

    def request(self, raw, timeout=10, shut_write=False):
        """Sends raw bytes and reads one response: (status, headers, body)."""
        with self.connect(timeout) as s:
            s.sendall(raw)
            if shut_write:
                s.shutdown(socket.SHUT_WR)
            status, headers, body = read_response(s)
        observe(raw, status)
        return status, headers, body

    def get_json(self, path):
        return json.loads(self.request(http("GET", path))[2])

    def stop(self):
        self.proc.terminate()
        try:
            self.proc.wait(30)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        self.log.close()
        # Under scripts/sanitize a report ends the server (halt_on_error) or its exit (leaks): the log says which.
        with open(self.log_path, "rb") as f:
            log = f.read().decode("latin-1")
        for report in re.findall(r"ERROR: (?:Address|Leak)Sanitizer[^\n]*|runtime error:[^\n]*", log):
            fail("sanitizer", report)


def read_response(s):
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = s.recv(65536)
        if not chunk:
            raise OSError("the connection closed before a response: %r" % data[:200])
        data += chunk
    head, body = data.split(b"\r\n\r\n", 1)
    lines = head.decode("latin-1").split("\r\n")
    status = int(lines[0].split()[1])
    headers = {}
    for line in lines[1:]:
        k, _, v = line.partition(":")
        headers[k.strip().lower()] = v.strip()
    length = int(headers.get("content-length", "0"))
    while len(body) < length:
        chunk = s.recv(65536)
        if not chunk:
            break
        body += chunk
    if len(body) > length:
        raise OSError("more than one response to one request: %r" % body[length:length + 80])
    return status, headers, body


def http(method, path, body=b"", headers=None, length=True):
    head = "%s %s HTTP/1.1\r\n" % (method, path)
    for k, v in {"Host": "localhost", **(headers or {})}.items():
        head += "%s: %s\r\n" % (k, v)
    if length and (body or method in ("POST", "PUT", "PATCH")):
        head += "Content-Length: %d\r\n" % len(body)
    return head.encode("latin-1") + b"\r\n" + body


def job(**fields):
    j = {"mesh": "round_brilliant", "photons": 200, "threads": 1}
    j.update(fields)
    return json.dumps(j).encode()


def post_job(body, ctype="application/json", **headers):
    return http("POST", "/api/jobs", body, {"Content-Type": ctype, **headers})


def post_estimate(body, ctype="application/json", **headers):
    return http("POST", "/api/jobs/estimate", body, {"Content-Type": ctype, **headers})


def upload(data, name="m.obj", ctype="application/octet-stream"):
    return http("POST", "/api/meshes?name=" + name, data, {"Content-Type": ctype} if ctype else {})


def multipart(data, **headers):
    body = (b"--b0undary\r\nContent-Disposition: form-data; name=\"file\"; filename=\"m.obj\"\r\n\r\n" + data +
            b"\r\n--b0undary--\r\n")
    return http("POST", "/api/meshes", body, {"Content-Type": "multipart/form-data; boundary=b0undary", **headers})


EVIL = {"Origin": "http://evil.example"}


CUBE_OBJ = (b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
            b"f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n")
CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fuzz", "corpus")


def corpus(kind, name):
    with open(os.path.join(CORPUS, kind, name), "rb") as f:
        return f.read()


# (name, raw request, expected status or set of statuses, field the problem must name or None)
def cases():
    deep = b"[" * 150000 + b"]" * 150000
    big_material = job(material="x" * 100000)
    return [
        ("healthz", http("GET", "/healthz"), 200, None),
        ("openapi", http("GET", "/api/openapi.json"), 200, None),
        ("job list", http("GET", "/api/jobs"), 200, None),
        ("mesh list", http("GET", "/api/meshes"), 200, None),
        ("HTTP/1.0", b"GET /healthz HTTP/1.0\r\n\r\n", 200, None),
        ("limit 0", http("GET", "/api/jobs?limit=0"), 400, "limit"),
        ("limit abc", http("GET", "/api/jobs?limit=abc"), 400, "limit"),
        ("offset -1", http("GET", "/api/jobs?offset=-1"), 400, "offset"),
        ("limit 20 digits", http("GET", "/api/jobs?limit=99999999999999999999"), 400, "limit"),
        ("unknown job", http("GET", "/api/jobs/" + ID), 404, None),
        ("unknown job stats", http("GET", "/api/jobs/%s/stats" % ID), 404, None),
        ("unknown job png", http("GET", "/api/jobs/%s/render.png" % ID), 404, None),
        ("cancel unknown", http("POST", "/api/jobs/%s/cancel" % ID), 404, None),
        ("delete unknown", http("DELETE", "/api/jobs/" + ID), 404, None),
        ("delete unknown mesh", http("DELETE", "/api/meshes/" + ID), 404, None),
        ("delete shipped mesh", http("DELETE", "/api/meshes/round_brilliant"), 404, None),
        ("id not hex", http("GET", "/api/jobs/ZZZZ"), 404, None),
        ("traversal", http("GET", "/api/jobs/../../etc/passwd"), {400, 404}, None),
        ("encoded traversal", http("GET", "/api/jobs/%2e%2e%2f%2e%2e%2fetc%2fpasswd"), {400, 404}, None),
        ("static traversal", http("GET", "/../../../etc/passwd"), {400, 404}, None),
        ("NUL in path", http("GET", "/index.html%00.js"), 400, None),
        ("newline in path", http("GET", "/api/jobs%0d%0aX-Forged:%201"), 400, None),
        ("long URL", http("GET", "/api/jobs?x=" + "a" * 3000), 414, None),
        ("garbage request line", b"HELLO\r\n\r\n", 400, None),
        ("PUT job", http("PUT", "/api/jobs/" + ID, b"{}"), 405, None),
        ("PATCH jobs", http("PATCH", "/api/jobs", b"{}"), 405, None),
        ("DELETE healthz", http("DELETE", "/healthz"), 405, None),
        ("POST healthz", http("POST", "/healthz", b""), 405, None),
        ("GET cancel", http("GET", "/api/jobs/%s/cancel" % ID), 405, None),
        ("DELETE meshes", http("DELETE", "/api/meshes"), 405, None),
        ("OPTIONS jobs", http("OPTIONS", "/api/jobs"), 405, None),
        ("POST job without length", http("POST", "/api/jobs", length=False), 411, None),
        ("POST mesh without length", http("POST", "/api/meshes", length=False), 411, None),
        ("chunked job", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nTransfer-Encoding: chunked\r\n\r\n5\r\n{\"a\":\r\n0\r\n\r\n",
         411, None),
        ("length abc", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: abc\r\n\r\n", 400, None),
        ("length -1", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: -1\r\n\r\n", 400, None),
        ("length 1e3", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: 1e3\r\n\r\n", 400, None),
        ("length 20 digits", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: 99999999999999999999\r\n\r\n",
         400, None),
        ("two lengths", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: 2\r\nContent-Length: 40\r\n\r\n{}",
         400, None),
        ("length over max-body", b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: %d\r\n\r\n{" % (MAX_BODY + 1),
         413, None),
        ("upload over max-upload",
         b"POST /api/meshes HTTP/1.1\r\nHost: localhost\r\nContent-Length: 17000000\r\n\r\nv 0 0 0\n", 413, None),
        ("GET with length over max-body",
         b"GET /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: %d\r\n\r\n" % (MAX_BODY + 1), 413, None),
        ("huge header", http("GET", "/healthz", headers={"X-Big": "a" * 20000}), 400, None),
        # Issue 31, item 2: a request's head is capped at 64 KiB and 100 lines.
        ("99 header lines", http("GET", "/healthz", headers={"X-%d" % i: "1" for i in range(98)}), 200, None),
        ("101 header lines", http("GET", "/healthz", headers={"X-%d" % i: "1" for i in range(100)}), 431, None),
        ("head of 70 KB", http("GET", "/healthz", headers={"X-%d" % i: "a" * 1000 for i in range(70)}), 431, None),
        ("header line without colon", b"GET /healthz HTTP/1.1\r\nHost: localhost\r\nX-No-Colon\r\n\r\n", 400, None),
        ("NUL in a header value", b"GET /healthz HTTP/1.1\r\nHost: localhost\r\nX-A: a\x00b\r\n\r\n", 400, None),
        ("folded header line", b"GET /healthz HTTP/1.1\r\nHost: localhost\r\nX-A: 1\r\n\tmore: 2\r\n\r\n", 400, None),
        ("Transfer-Encoding with a space before its colon",
         b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\nContent-Length: %d\r\n"
         b"Transfer-Encoding : chunked\r\n\r\n" % len(job()) + job(), 400, None),
        ("Transfer-Encoding beside Content-Length",
         b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\nContent-Length: %d\r\n"
         b"transfer-encoding: chunked\r\n\r\n" % len(job()) + job(), {400, 411}, None),
        ("not JSON", post_job(b"{photons: 5}"), 400, None),
        ("JSON array", post_job(b"[]"), 400, None),
        ("JSON trailing junk", post_job(b"{} {}"), 400, None),
        ("NaN literal", post_job(b'{"mesh":"round_brilliant","photons":NaN}'), 400, None),
        ("nested 150000 deep", post_job(deep), 400, None),
        ("wrong content type", post_job(job(), "image/png"), 415, None),
        ("no mesh", post_job(b'{"photons": 100}'), 422, "mesh"),
        ("unknown mesh", post_job(job(mesh="no_such_cut")), 422, "mesh"),
        ("mesh path", post_job(job(mesh="/etc/passwd")), 422, "mesh"),
        ("mesh 100 KB", post_job(job(mesh="m" * 100000)), 422, "mesh"),
        ("photons 0", post_job(job(photons=0)), 422, "photons"),
        ("photons -5", post_job(job(photons=-5)), 422, "photons"),
        ("photons 1e300", post_job(job(photons=1e300)), 422, "photons"),
        ("photons string", post_job(job(photons="many")), 422, "photons"),
        ("photons 1.5", post_job(job(photons=1.5)), 422, "photons"),
        ("seed 2^64 as float", post_job(b'{"mesh":"round_brilliant","photons":200,"seed":1.8446744073709552e19}'),
         422, "seed"),
        ("seed -1", post_job(job(seed=-1)), 422, "seed"),
        ("threads 0", post_job(job(threads=0)), 422, "threads"),
        ("threads 1e9", post_job(job(threads=1e9)), 422, "threads"),
        ("unknown field", post_job(job(colour="red")), 422, "colour"),
        ("unknown material 100 KB", post_job(big_material), 422, "material"),
        ("direction zero", post_job(job(light={"direction": [0, 0, 0]})), 422, "light.direction"),
        ("direction strings", post_job(job(light={"direction": ["a", 1, 2]})), 422, "light.direction"),
        ("point light at 1e308", post_job(job(light={"model": "point", "position": [0, 0, 1e308]})), 422,
         "light.position"),
        ("render width 1e9", post_job(job(render={"width": 1e9})), 422, "render.width"),
        ("render width -1", post_job(job(render={"width": -1})), 422, "render.width"),
        ("render yes", post_job(job(render="yes")), 422, "render"),
        # Issue 31, item 8: a frame count that overflows an int was one frame.
        ("tilt step 1e-9", post_job(job(render=True, tilt_series={"max_deg": 45, "step_deg": 1e-9})), 422,
         "tilt_series.step_deg"),
        ("tilt step 3e-8", post_job(job(render=True, tilt_series={"max_deg": 45, "step_deg": 3e-8})), 422,
         "tilt_series.step_deg"),
        ("tilt step 5e-324", post_job(job(render=True, tilt_series={"max_deg": 45, "step_deg": 5e-324})), 422,
         "tilt_series.step_deg"),
        ("upload GemCad 1e300", upload(corpus("gemcad", "huge_distance.asc"), "huge.asc"), 422, "file"),
        ("upload cube 1e155", upload(corpus("obj", "cube_1e155.obj")), 422, "file"),
        ("upload flat square", upload(corpus("obj", "flat_square.obj")), 422, "file"),
        ("upload self-intersecting", upload(corpus("obj", "octahedron_self_intersecting.obj")), 422, "file"),
        ("upload empty", upload(b""), 422, "file"),
        ("upload binary junk", upload(b"\x01\x02\xff\xfe junk", "junk"), 422, "file"),
        ("upload format ply", upload(CUBE_OBJ, "m.obj&format=ply"), 422, "format"),
        ("upload open cube", upload(CUBE_OBJ[:CUBE_OBJ.rfind(b"f ")]), 422, "file"),
        # Issue 31, item 9: face indices beyond an int wrapped to vertex 4.
        ("upload index 2^32+4", upload(CUBE_OBJ.replace(b"f 2 4 8 6", b"f 2 4294967300 8 6")), 422, "file"),
        ("upload index 2^64+4", upload(CUBE_OBJ.replace(b"f 2 4 8 6", b"f 2 18446744073709551620 8 6")), 422, "file"),
        ("upload index -(2^32-4)", upload(CUBE_OBJ.replace(b"f 2 4 8 6", b"f 2 -4294967292 8 6")), 422, "file"),
        ("upload cube", upload(CUBE_OBJ, "cube.obj"), 201, None),
        ("direction 1e308", post_job(job(light={"direction": [1e308, 1e308, -1e308]})), 202, None),
        # Issue 31, item 1: DNS rebinding and cross-site requests.
        ("Host evil.example", http("GET", "/api/jobs", headers={"Host": "evil.example"}), 421, None),
        ("Host evil.example:port", http("GET", "/healthz", headers={"Host": "evil.example:8080"}), 421, None),
        ("Host evil.example page", http("GET", "/", headers={"Host": "evil.example"}), 421, None),
        ("Host empty", http("GET", "/api/jobs", headers={"Host": ""}), {400, 421}, None),
        ("HTTP/1.1 without Host", b"GET /api/jobs HTTP/1.1\r\n\r\n", 400, None),
        ("Host localhost.evil.example", http("GET", "/api/meshes", headers={"Host": "localhost.evil.example"}), 421,
         None),
        ("Host 127.0.0.1 with port", http("GET", "/api/jobs", headers={"Host": "127.0.0.1:8080"}), 200, None),
        ("Host [::1]", http("GET", "/api/jobs", headers={"Host": "[::1]:8080"}), 200, None),
        ("job from evil origin", post_job(job(), **EVIL), 403, None),
        ("text job from evil origin", post_job(job(), "text/plain", **EVIL), 403, None),
        ("job from null origin", post_job(job(), Origin="null"), 403, None),
        ("multipart upload from evil origin", multipart(CUBE_OBJ, **EVIL), 403, None),
        ("cancel from evil origin", http("POST", "/api/jobs/%s/cancel" % ID, headers=EVIL), 403, None),
        ("delete from evil origin", http("DELETE", "/api/jobs/" + ID, headers=EVIL), 403, None),
        ("delete mesh from evil origin", http("DELETE", "/api/meshes/" + ID, headers=EVIL), 403, None),
        ("list from evil origin", http("GET", "/api/jobs", headers=EVIL), 200, None),
        ("form-encoded job", post_job(job(), "application/x-www-form-urlencoded"), 415, None),
        ("text/plain job", post_job(job(), "text/plain"), 415, None),
        ("job without content type", http("POST", "/api/jobs", job()), 415, None),
        ("text/plain upload", upload(CUBE_OBJ, ctype="text/plain"), 415, None),
        ("upload without content type", upload(CUBE_OBJ, ctype=None), 415, None),
        # Issue 31, items 5 and 6: free text is capped, and problems quote at most an excerpt of the input.
        ("job name 100 KB", post_job(job(name="n" * 100000)), 422, "name"),
        ("job name 1025 bytes", post_job(job(name="n" * 1025)), 422, "name"),
        ("constraint 100 KB", post_job(job(sweep={"axes": [{"name": "pavilion", "from": 40, "to": 41, "step": 1}],
                                                  "constraints": ["x" * 100000]})), 422, None),
        ("constraint 1000 bytes", post_job(job(sweep={"axes": [{"name": "pavilion", "from": 40, "to": 41, "step": 1}],
                                                      "constraints": ["x" * 1000]})), 422, None),
        ("sweep axis name 100 KB", post_job(job(sweep={"axes": [{"name": "p" * 100000, "from": 40, "to": 41,
                                                                 "step": 1}]})), 422, None),
        ("unknown field 100 KB", post_job(job(**{"k" * 100000: 1})), 422, None),
        ("unknown render field 100 KB", post_job(job(render={"k" * 100000: 1})), 422, None),
        ("upload vertex 100 KB", upload(b"v 0 0 " + b"9" * 100000 + b"x\n" + CUBE_OBJ), 422, "file"),
        ("upload face index 100 KB", upload(CUBE_OBJ + b"f 1 2 " + b"9" * 100000 + b"\n"), 422, "file"),
        ("upload GemCad gear 100 KB", upload(b"GemCad 5.0\ng " + b"9" * 100000 + b" 0\n", "g.asc"), 422, "file"),
        ("job from our origin", post_job(job(), Origin="http://localhost:8080"), 202, None),
        ("multipart upload", multipart(CUBE_OBJ, Origin="http://127.0.0.1:8080"), 201, None),
        ("multipart upload without a boundary", http("POST", "/api/meshes", b"--b0undary\r\n" + CUBE_OBJ,
                                                     {"Content-Type": "multipart/form-data"}), 400, "Content-Type"),
        # Issue 31: an estimate checks a job as a submission does, and stores nothing.
        ("estimate", post_estimate(job()), 200, None),
        ("estimate not JSON", post_estimate(b"{photons: 5}"), 400, None),
        ("estimate JSON array", post_estimate(b"[]"), 400, None),
        ("estimate photons -5", post_estimate(job(photons=-5)), 422, "photons"),
        ("estimate unknown mesh", post_estimate(job(mesh="no_such_cut")), 422, "mesh"),
        ("estimate tilt step 1e-9", post_estimate(job(render=True, tilt_series={"max_deg": 45, "step_deg": 1e-9})),
         422, "tilt_series.step_deg"),
        ("estimate text/plain", post_estimate(job(), "text/plain"), 415, None),
        ("estimate from evil origin", post_estimate(job(), **EVIL), 403, None),
        ("estimate without length", http("POST", "/api/jobs/estimate", length=False), 411, None),
        ("estimate over max-body",
         b"POST /api/jobs/estimate HTTP/1.1\r\nHost: localhost\r\nContent-Length: %d\r\n\r\n{" % (MAX_BODY + 1),
         413, None),
        ("GET estimate", http("GET", "/api/jobs/estimate"), 405, None),
        ("multipart upload without a file part", http(
            "POST", "/api/meshes", b"--b\r\nContent-Disposition: form-data; name=\"other\"\r\n\r\nx\r\n--b--\r\n",
            {"Content-Type": "multipart/form-data; boundary=b"}), 422, "file"),
    ]


def check_problem(name, status, headers, body, field):
    if status < 400:
        return
    if not headers.get("content-type", "").startswith("application/problem+json"):
        fail(name, "content type %r, not problem+json" % headers.get("content-type"))
    try:
        doc = json.loads(body)
    except ValueError:
        return fail(name, "the problem is not JSON: %r" % body[:200])
    if doc.get("status") != status or not doc.get("detail"):
        fail(name, "problem %.300r" % doc)
    if field and doc.get("field") != field:
        fail(name, "problem names field %r, not %r: %.300r" % (doc.get("field"), field, doc))
    if len(body) > 1500:
        fail(name, "the problem is %d bytes long: it echoes the input" % len(body))


failures = []
observed = set()  # (method, path, status) of every answer


def observe(raw, status):
    words = raw.split(b"\r\n", 1)[0].decode("latin-1").split(" ")
    if len(words) == 3:
        observed.add((words[0], words[1].split("?", 1)[0], status))


def check_documented(openapi):
    """Every status an API route answered is documented for that route (405: for some method of its path)."""
    templates = [(re.compile("^" + re.sub(r"\\{[a-z]+\\}", "[^/]+", re.escape(path)) + "$"), ops)
                 for path, ops in openapi["paths"].items()]
    checked = 0
    for method, path, status in sorted(observed):
        ops = next((ops for pattern, ops in templates if pattern.match(path)), None)
        if ops is None:
            continue  # not an API route: static files, traversal attempts
        checked += 1
        if status == 405:
            documented = any("405" in op["responses"] for op in ops.values())
        else:
            documented = str(status) in ops.get(method.lower(), {}).get("responses", {})
        if not documented:
            fail("OpenAPI", "%s %s answered %d, which /api/openapi.json does not document" % (method, path, status))
    return checked


def fail(name, why):
    failures.append("%s: %s" % (name, why))
    print("FAIL %s: %s" % (name, why))


def healthz_fast(server, name):
    start = time.time()
    try:
        status = server.request(http("GET", "/healthz"), timeout=1)[0]
    except OSError as e:
        return fail(name, "/healthz did not answer within 1 s afterwards (%s)" % e)
    if status not in ((200, 503) if server.disk_full else (200,)):
        fail(name, "/healthz answered %d afterwards" % status)
    return time.time() - start


def healthz_probe(server, name):
    """One /healthz probe beside slow clients: (seconds, 1 if the first try missed 1 s). A miss gets one more
    try, failing `name` if that misses too: on a loaded CI machine a probe may miss the second once."""
    start = time.time()
    try:
        server.request(http("GET", "/healthz"), timeout=1)
        return time.time() - start, 0
    except OSError:
        return healthz_fast(server, name) or 0, 1


def job_total(server):
    return server.get_json("/api/jobs")["total"]


def mesh_total(server):
    return len(server.get_json("/api/meshes")["uploaded"])


def run_cases(server):
    n = 0
    for name, raw, want, field in cases():
        n += 1
        start = time.time()
        try:
            status, headers, body = server.request(raw)
        except OSError as e:
            fail(name, "no response (%s)" % e)
            continue
        wanted = want if isinstance(want, set) else {want}
        if status not in wanted:
            fail(name, "status %d, expected %s: %s" % (status, sorted(wanted), body[:300]))
        else:
            check_problem(name, status, headers, body, field)
        if status == 405 and "allow" not in headers:
            fail(name, "405 without Allow")
        if status == 411 and time.time() - start > 1:
            fail(name, "411 took %.1f s" % (time.time() - start))
        healthz_fast(server, name)
    return n


def run_short_bodies(server):
    """Bodies that stop short of their Content-Length store nothing."""
    jobs, meshes = job_total(server), mesh_total(server)
    body = job()
    # The client half-closes after part of the body: the server sees the end at once.
    status = server.request(b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                            b"Content-Length: %d\r\n\r\n" % (len(body) + 50) + body, shut_write=True)[0]
    if status != 400:
        fail("short job body", "status %d, expected 400" % status)
    status = server.request(b"POST /api/meshes?name=c.obj HTTP/1.1\r\nHost: localhost\r\n"
                            b"Content-Type: application/octet-stream\r\nContent-Length: %d\r\n\r\n"
                            % (len(CUBE_OBJ) + 10) + CUBE_OBJ, shut_write=True)[0]
    if status != 400:
        fail("short mesh body", "status %d, expected 400" % status)
    # The client goes away mid-body.
    for raw in (b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                b"Content-Length: %d\r\n\r\n" % (len(body) + 50) + body,
                b"POST /api/meshes HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/octet-stream\r\n"
                b"Content-Length: 1000\r\n\r\n" + CUBE_OBJ):
        s = server.connect()
        s.sendall(raw)
        s.close()
    time.sleep(0.5)
    healthz_fast(server, "abandoned bodies")
    if job_total(server) != jobs:
        fail("short bodies", "a job was stored from an incomplete body")
    if mesh_total(server) != meshes:
        fail("short bodies", "a mesh was stored from an incomplete body")
    return 6


def run_slow_clients(server):
    """4 x --http-threads clients sending a header line every 2 s leave /healthz answering within 1 s; a
    request that takes longer than --request-timeout is cut; one peer cannot hold more than its share."""
    slow = []
    for i in range(4 * HTTP_THREADS):
        s = server.connect(timeout=30)
        s.sendall(b"GET /healthz HTTP/1.1\r\nHost: localhost\r\n")
        slow.append(s)
    start = time.time()
    worst = 0
    while time.time() - start < REQUEST_TIMEOUT_S - 0.5:
        for s in slow:
            s.sendall(b"X-Slow: 1\r\n")
        worst = max(worst, healthz_fast(server, "slow clients") or 0)
        time.sleep(0.5)
    print("  /healthz with %d slow clients: slowest answer %.0f ms" % (len(slow), worst * 1000))
    # Past the deadline the slow clients are answered (408-like close) or cut off.
    time.sleep(REQUEST_TIMEOUT_S)
    for s in slow:
        try:
            s.sendall(b"X-Slow: 1\r\n")
            s.settimeout(2)
            data = s.recv(100)
            if data and not data.startswith(b"HTTP/1.1 4"):
                fail("slow client", "still being served past the deadline: %r" % data[:60])
        except OSError:
            pass
        s.close()
    # One peer's connections beyond its cap are answered 429 at once.
    held = [server.connect() for _ in range(MAX_PER_PEER)]
    time.sleep(0.3)
    try:
        status, headers, body = server.request(http("GET", "/healthz"), timeout=2)
        if status != 429:
            fail("per-peer cap", "connection %d answered %d, expected 429" % (MAX_PER_PEER + 1, status))
        else:
            check_problem("per-peer cap", status, headers, body, None)
    except OSError as e:
        fail("per-peer cap", "no answer (%s)" % e)
    for s in held:
        s.close()
    time.sleep(0.3)
    healthz_fast(server, "after the per-peer cap")
    return len(slow) + 2


def rss_kib(pid):
    with open("/proc/%d/status" % pid) as f:
        return next(int(line.split()[1]) for line in f if line.startswith("VmRSS:"))


def run_header_flood(server):
    """8 connections each sending 4 MB of header lines: each is cut at 64 KiB, and the server's memory grows by
    less than 16 MiB (110 MB a connection were kept before)."""
    before = rss_kib(server.proc.pid)
    line = b"X-Flood: " + b"a" * 1000 + b"\r\n"
    floods = []
    for _ in range(8):
        s = server.connect()
        s.sendall(b"GET /healthz HTTP/1.1\r\nHost: localhost\r\n")
        floods.append(s)
    for s in floods:
        try:
            for _ in range(4000):
                s.sendall(line)
        except OSError:
            pass  # cut off: what should happen
        s.close()
    time.sleep(0.5)
    grown = (rss_kib(server.proc.pid) - before) / 1024
    print("  header flood: 8 x 4 MB of header lines, the server grew by %.1f MiB" % grown)
    if grown > 16:
        fail("header flood", "the server grew by %.1f MiB" % grown)
    healthz_fast(server, "header flood")
    return 8


def run_log_forgery(server):
    forged = '2026-01-01T00:00:00Z 6.6.6.6 "GET /forged" 200 0'
    server.request(http("GET", "/api/jobs%0a" + forged.replace(" ", "%20").replace('"', "%22")))
    time.sleep(0.2)
    with open(server.log_path, "rb") as f:
        log = f.read().decode("latin-1")
    if any(line.startswith(forged) for line in log.splitlines()):
        fail("access log", "a %0a in the path forged a log line")
    return 1


def expect(server, name, raw, wanted):
    status, headers, body = server.request(raw)
    wanted = wanted if isinstance(wanted, set) else {wanted}
    if status not in wanted:
        fail(name, "status %d, expected %s: %s" % (status, sorted(wanted), body[:200]))
    else:
        check_problem(name, status, headers, body, None)
    healthz_fast(server, name)
    return status, body


def run_slow_clients_across_peers(binary, work):
    """Issue 31, item 3: slow clients from 5 addresses, each under the per-peer cap, together more than
    --max-http-threads: /healthz from another address must still answer within 1 s every time (it waited for a
    slow client's deadline)."""
    threads, per_peer, peers = 16, 8, 5
    server = Server(binary, os.path.join(work, "slow-peers"), "--max-http-threads", str(threads),
                    per_peer=per_peer, request_timeout=20)
    slow = []
    try:
        for peer in range(2, 2 + peers):
            for _ in range(per_peer):
                s = socket.socket()
                s.bind(("127.0.0.%d" % peer, 0))
                s.settimeout(5)
                s.connect(("127.0.0.1", server.port))
                s.sendall(b"GET /healthz HTTP/1.1\r\nHost: localhost\r\n")
                slow.append(s)
        time.sleep(0.3)
        start, worst, probes, missed = time.time(), 0, 0, 0
        while time.time() - start < 4:
            for s in slow:
                try:
                    s.sendall(b"X-Slow: 1\r\n")
                except OSError:
                    pass  # ended by the server to free its thread: what should happen
            # Without the eviction every probe waits for a slow client's 20-s deadline: two misses in a row tell.
            took, miss = healthz_probe(server, "/healthz beside slow clients of %d addresses" % peers)
            worst, missed = max(worst, took), missed + miss
            probes += 1
            time.sleep(0.25)
        print("  /healthz beside %d slow clients from %d addresses (%d threads at most): %d probes, slowest %.0f ms"
              ", %d answered only at the second try" % (len(slow), peers, threads, probes, worst * 1000, missed))
    finally:
        for s in slow:
            s.close()
        server.stop()
    return probes


def parse_response(raw):
    """(status, headers, body) of one whole response in `raw`, or None."""
    if b"\r\n\r\n" not in raw:
        return None
    head, body = raw.split(b"\r\n\r\n", 1)
    lines = head.decode("latin-1").split("\r\n")
    headers = {k.strip().lower(): v.strip() for k, _, v in (line.partition(":") for line in lines[1:])}
    return int(lines[0].split()[1]), headers, body


def run_slow_bodies(binary, work):
    """Issue 31: request bodies trickled at 8 bytes/s get 408 once they fall behind --min-body-rate (1024 B/s) after
    their 2-s grace, so they cannot hold the server's threads: 4 new ones a second for 8 s against
    --max-http-threads 16 (without the rate they pile up to 32, each held until the 20-s --request-timeout), and
    /healthz answers within 1 s throughout."""
    threads, waves, per_wave = 16, 8, 4
    server = Server(binary, os.path.join(work, "slow-bodies"), "--max-http-threads", str(threads),
                    request_timeout=20)
    head = (b"POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
            b"Content-Length: 4096\r\n\r\n")
    slow = {}  # socket -> [when its head was sent, what came back]
    answers = []  # (seconds from its head to the end of the answer, raw answer)
    start, sent, worst, probes, missed = time.time(), 0, 0, 0, 0
    try:
        while sent < waves * per_wave or slow:
            if time.time() - start > 30:
                fail("slow bodies", "%d slow bodies still held after 30 s" % len(slow))
                break
            if sent < waves * per_wave and time.time() >= start + sent // per_wave:
                for _ in range(per_wave):
                    s = server.connect()
                    s.sendall(head + b"{")
                    s.setblocking(False)
                    slow[s] = [time.time(), b""]
                    sent += 1
            for s, state in list(slow.items()):
                try:
                    s.send(b"  ")  # 2 bytes every 0.25 s
                except OSError:
                    pass  # closed by the server after its answer
                try:
                    data = s.recv(65536)
                except BlockingIOError:
                    continue
                except OSError:
                    data = b""
                state[1] += data
                if not data:  # the server answers, then closes the connection
                    answers.append((time.time() - state[0], state[1]))
                    del slow[s]
                    s.close()
            # Without the rate every probe waits once 16 slow bodies hold the threads: two misses in a row tell.
            took, miss = healthz_probe(server, "/healthz beside slow bodies")
            worst, missed = max(worst, took), missed + miss
            probes += 1
            time.sleep(0.25)
        slowest = 0
        for took, raw in answers:
            parsed = parse_response(raw)
            if parsed is None:
                fail("slow body", "closed after %.1f s without an answer: %r" % (took, raw[:100]))
                continue
            status, headers, body = parsed
            observe(head, status)
            slowest = max(slowest, took)
            if status != 408:
                fail("slow body", "status %d after %.1f s, expected 408: %r" % (status, took, body[:200]))
            else:
                check_problem("slow body", status, headers, body, None)
                if "--min-body-rate" not in json.loads(body)["detail"]:
                    fail("slow body", "the problem does not name --min-body-rate: %.300r" % body)
            if took > 6:
                fail("slow body", "answered after %.1f s: past its 2-s grace it is 1 KiB behind at once" % took)
        print("  %d slow bodies (%d a second for %d s, --max-http-threads %d): %d answered, the slowest after %.1f s;"
              " /healthz %d probes, slowest %.0f ms, %d answered only at the second try"
              % (sent, per_wave, waves, threads, len(answers), slowest, probes, worst * 1000, missed))
        if job_total(server) != 0:
            fail("slow bodies", "a job was stored from a slow body")
        expect(server, "job after slow bodies", post_job(job()), 202)
    finally:
        for s in slow:
            s.close()
        server.stop()
    return sent + 1


def run_allowed_host(binary, work):
    """--allowed-host adds a name the server is reached by (behind a proxy, or on the network)."""
    server = Server(binary, os.path.join(work, "allowed"), "--allowed-host", "Gems.Example")
    try:
        expect(server, "allowed host", http("GET", "/api/jobs", headers={"Host": "gems.example:8443"}), 200)
        expect(server, "job from the allowed host", post_job(job(), Origin="https://gems.example"), 202)
        expect(server, "loopback beside an allowed host", http("GET", "/api/jobs", headers={"Host": "localhost"}),
               200)
        expect(server, "other host beside an allowed host", http("GET", "/api/jobs", headers={"Host": "evil.example"}),
               421)
    finally:
        server.stop()
    return 4


TOKEN = "t0ken-for-the-hostile-suite-0123"


def refuses_to_start(binary, name, args, why):
    """The server exits at once with a non-zero status, saying `why` on stderr."""
    try:
        done = subprocess.run([binary, "--port", str(free_port()), *args], capture_output=True, timeout=10)
    except subprocess.TimeoutExpired:
        return fail(name, "the server started")
    if done.returncode == 0 or why not in done.stderr.decode("latin-1"):
        fail(name, "exit %d, stderr %r (expected %r)" % (done.returncode, done.stderr[-300:], why))


def run_bearer_token(binary, work):
    """Issue 31, item 1: with --token-file every /api request needs the token; /healthz and the page do not;
    a --host other than loopback needs a token file or an explicit --no-auth."""
    folder = os.path.join(work, "token")
    os.makedirs(os.path.join(folder, "web"))
    with open(os.path.join(folder, "web", "index.html"), "w") as f:
        f.write("<!doctype html><title>facetlight</title>")
    token_file = os.path.join(folder, "token")
    with open(token_file, "w") as f:
        f.write(TOKEN + "\n")
    empty = os.path.join(folder, "empty")
    open(empty, "w").close()
    refuses_to_start(binary, "--host 0.0.0.0 without a token", ["--host", "0.0.0.0"], "--token-file")
    refuses_to_start(binary, "--host 192.0.2.1 without a token", ["--host", "192.0.2.1"], "--no-auth")
    refuses_to_start(binary, "empty token file", ["--token-file", empty], "empty")
    refuses_to_start(binary, "missing token file", ["--token-file", os.path.join(folder, "missing")], "not a file")
    refuses_to_start(binary, "token file and --no-auth", ["--token-file", token_file, "--no-auth"], "excludes")
    n = 5
    bearer = {"Authorization": "Bearer " + TOKEN}
    server = Server(binary, folder, "--token-file", token_file, host="0.0.0.0")
    try:
        expect(server, "job list without the token", http("GET", "/api/jobs"), 401)
        headers = server.request(http("GET", "/api/jobs"))[1]
        if not headers.get("www-authenticate", "").startswith("Bearer"):
            fail("job list without the token", "WWW-Authenticate is %r" % headers.get("www-authenticate"))
        expect(server, "job list with another token",
               http("GET", "/api/jobs", headers={"Authorization": "Bearer " + TOKEN[:-1] + "4"}), 401)
        expect(server, "job list with the token as Basic",
               http("GET", "/api/jobs", headers={"Authorization": "Basic " + TOKEN}), 401)
        expect(server, "job without the token", post_job(job()), 401)
        expect(server, "upload without the token", upload(CUBE_OBJ), 401)
        expect(server, "result file without the token", http("GET", "/api/jobs/%s/render.png" % ID), 401)
        expect(server, "result file with the token", http("GET", "/api/jobs/%s/render.png" % ID, headers=bearer),
               404)
        expect(server, "openapi without the token", http("GET", "/api/openapi.json"), 401)
        expect(server, "job list with the token", http("GET", "/api/jobs", headers=bearer), 200)
        expect(server, "job with the token", post_job(job(), **bearer), 202)
        expect(server, "healthz without the token", http("GET", "/healthz"), 200)
        expect(server, "page without the token", http("GET", "/"), 200)
        n += 12
    finally:
        server.stop()
    server = Server(binary, os.path.join(work, "no-auth"), "--no-auth", host="0.0.0.0")
    try:
        expect(server, "job list with --no-auth", http("GET", "/api/jobs"), 200)
        n += 1
    finally:
        server.stop()
    return n


def run_mesh_store(binary, work):
    """Issue 31, item 10: uploads take at most --max-mesh-store together (507 beyond, naming it); a mesh can be
    deleted (204), but not while a queued or running job names it (409)."""
    server = Server(binary, os.path.join(work, "mesh-store"), "--max-mesh-store", str(2 * len(CUBE_OBJ) + 10))
    try:
        first = json.loads(expect(server, "first upload", upload(CUBE_OBJ), 201)[1])["mesh"]
        second = json.loads(expect(server, "second upload", upload(CUBE_OBJ), 201)[1])["mesh"]
        status, body = expect(server, "upload past --max-mesh-store", upload(CUBE_OBJ), 507)
        if status == 507 and "--max-mesh-store" not in json.loads(body)["detail"]:
            fail("upload past --max-mesh-store", "the problem does not name the limit: %.300r" % body)
        expect(server, "delete an upload", http("DELETE", "/api/meshes/" + first), 204)
        expect(server, "delete it again", http("DELETE", "/api/meshes/" + first), 404)
        expect(server, "upload after a delete", upload(CUBE_OBJ), 201)
        running = json.loads(server.request(post_job(job(mesh=second, photons=100000000)))[2])["id"]
        expect(server, "delete a mesh a job uses", http("DELETE", "/api/meshes/" + second), 409)
        server.request(http("POST", "/api/jobs/%s/cancel" % running))
        wait_finished(server, running)
        expect(server, "delete it once the job ended", http("DELETE", "/api/meshes/" + second), 204)
    finally:
        server.stop()
    return 8


def run_job_budget(binary, work):
    """Issue 31, item 4: a job estimated over --max-job-seconds gets 422 naming its costliest part and the field to
    lower, and nothing is stored; one within it is accepted with its estimate."""
    server = Server(binary, os.path.join(work, "budget"), "--max-job-seconds", "60")
    try:
        render = {"width": 2048, "height": 2048, "samples": 256, "max_depth": 64}
        status, body = expect(server, "job over --max-job-seconds", post_job(job(render=render)), 422)
        if status == 422:
            problem = json.loads(body)
            if problem.get("field") != "render.samples" or not problem["detail"].startswith("render: about ") \
                    or "of the 60 s a job may take" not in problem["detail"]:
                fail("job over --max-job-seconds", "the problem does not name the part and both numbers: %.300r" % body)
        if job_total(server) != 0:
            fail("job over --max-job-seconds", "a refused job was stored")
        status, body = expect(server, "job within --max-job-seconds", post_job(job()), 202)
        if status == 202 and not 0 < json.loads(body).get("estimate_s", 0) < 60:
            fail("job within --max-job-seconds", "no estimate_s within the limit: %.300r" % body)
    finally:
        server.stop()
    return 2


def run_durable_cancel(binary, work):
    """Issue 31, item 7: an acknowledged cancel survives kill -9, for a queued job (200) and a running one (202)."""
    folder = os.path.join(work, "cancel")
    server = Server(binary, folder)
    try:
        running = json.loads(server.request(post_job(job(photons=100000000)))[2])["id"]
        queued = json.loads(server.request(post_job(job()))[2])["id"]
        for _ in range(200):
            if server.get_json("/api/jobs/" + running)["state"] == "running":
                break
            time.sleep(0.05)
        expect(server, "cancel queued", http("POST", "/api/jobs/%s/cancel" % queued), 200)
        # Killed at once after the answer: the worker has had no time to record the end of the job.
        status = server.request(http("POST", "/api/jobs/%s/cancel" % running))[0]
        server.proc.kill()
        server.proc.wait()
        if status != 202:
            fail("cancel running", "status %d, expected 202" % status)
    finally:
        server.stop()
    server = Server(binary, folder)
    try:
        for name, job_id in (("queued", queued), ("running", running)):
            state = server.get_json("/api/jobs/" + job_id)["state"]
            if state != "canceled":
                fail("cancel %s after kill -9" % name, "the job is %s, not canceled" % state)
    finally:
        server.stop()
    return 4


def run_storage_guard(binary, work):
    """A disk with less than --min-free left refuses new jobs and uploads with 507 and keeps answering."""
    server = Server(binary, os.path.join(work, "full"), "--min-free", str(10 ** 18))
    try:
        expect(server, "job on a full disk", post_job(job()), 507)
        expect(server, "upload on a full disk", upload(CUBE_OBJ), 507)
        if server.get_json("/api/jobs")["total"] != 0:
            fail("full disk", "a job was stored")
        if server.get_json("/healthz").get("storage", {}).get("state") != "full":
            fail("full disk", "/healthz does not say the storage is full")
    finally:
        server.stop()
    return 3


def wait_finished(server, job_id):
    for _ in range(600):
        state = server.get_json("/api/jobs/" + job_id)
        if state["state"] not in ("queued", "running"):
            return state
        time.sleep(0.1)
    fail("job " + job_id, "never finished")
    return state


def fill(path):
    """Writes zeros into `path` until not one more byte fits."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_APPEND)
    try:
        for chunk in (1 << 16, 1 << 12, 1):
            try:
                while True:
                    os.write(fd, b"\0" * chunk)
            except OSError as e:
                if e.errno != errno.ENOSPC:
                    raise
    finally:
        os.close(fd)


def leftovers(folder):
    return [os.path.join(d, f) for d, _, files in os.walk(folder) for f in files if f.endswith(".tmp")]


def run_real_full_disk(binary, work):
    """A data folder on a small tmpfs, filled for real, then remounted read-only (needs root: else skipped;
    the in-process FullDiskTest covers the same cases by injected write failures)."""
    disk = os.path.join(work, "tmpfs")
    os.makedirs(disk)
    if subprocess.call(["mount", "-t", "tmpfs", "-o", "size=8m", "tmpfs", disk], stderr=subprocess.DEVNULL) != 0:
        print("  real full disk: skipped (cannot mount a tmpfs here)")
        return 0
    n = 0
    try:
        server = Server(binary, disk, "--min-free", "0", log_dir=work)
        try:
            rendered = job(render={"width": 64, "height": 48, "samples": 1, "map_photons": 2000})
            done = json.loads(server.request(post_job(rendered))[2])["id"]
            if wait_finished(server, done)["state"] != "succeeded":
                fail("real full disk", "the first job did not succeed")
            fill(os.path.join(disk, "filler"))
            # Issue 31, item 10: with --min-free 0 a disk without a free byte said "ok".
            time.sleep(1.1)  # the write probe's answer is kept a second
            status, _, body = server.request(http("GET", "/healthz"))
            health = json.loads(body)
            if status != 503 or health["storage"]["state"] != "full" or not health["storage"].get("detail"):
                fail("/healthz on a really full disk with --min-free 0", "%d %.300r" % (status, health))
            server.disk_full = True
            status, body = expect(server, "job on a really full disk", post_job(rendered), {202, 507})
            if status == 202:  # the database had room: then the results have none
                end = wait_finished(server, json.loads(body)["id"])
                if end["state"] != "failed" or "storage" not in end.get("error", ""):
                    fail("job on a really full disk", "ended %.300r" % end)
            expect(server, "upload on a really full disk", upload(CUBE_OBJ), 507)
            expect(server, "delete on a really full disk", http("DELETE", "/api/jobs/" + done), 204)
            expect(server, "deleted job", http("GET", "/api/jobs/" + done), 404)
            if leftovers(disk):
                fail("real full disk", "leftovers: %s" % leftovers(disk))
            n += 5
        finally:
            server.stop()
        fill(os.path.join(disk, "filler"))  # what the delete freed
        server = Server(binary, disk, log_dir=work)  # starts on a full disk, under the default --min-free
        server.disk_full = True
        try:
            status, _, body = server.request(http("GET", "/healthz"))
            health = json.loads(body)
            if status != 503 or health["status"] != "degraded" or health["storage"]["state"] != "full":
                fail("start on a full disk", "/healthz says %d %.300r" % (status, health))
            expect(server, "job after a start on a full disk", post_job(job()), 507)
            n += 2
        finally:
            server.stop()
        subprocess.check_call(["mount", "-o", "remount,ro", disk])
        server = Server(binary, disk, log_dir=work)
        try:
            health = server.get_json("/healthz")
            if health["storage"]["state"] != "read-only":
                fail("start on a read-only disk", "/healthz says %.300r" % health)
            expect(server, "job list on a read-only disk", http("GET", "/api/jobs"), 200)
            expect(server, "job on a read-only disk", post_job(job()), 503)
            n += 3
        finally:
            server.stop()
        with open(os.path.join(work, "server.log"), "rb") as f:
            log = f.read().decode("latin-1")
        for why in ("nearly full", "read-only"):
            if why not in log:
                fail("real full disk", "the log does not say %r" % why)
    finally:
        subprocess.call(["umount", "-l", disk])
    print("  real full disk and read-only store: %d requests" % n)
    return n


def run_no_inodes(binary, work):
    """A disk with bytes free but no inode left takes no new file: /healthz must say so (its write probe), not
    "ok" (needs root to mount a tmpfs; else skipped)."""
    disk = os.path.join(work, "tmpfs-inodes")
    os.makedirs(disk)
    if subprocess.call(["mount", "-t", "tmpfs", "-o", "size=8m,nr_inodes=200", "tmpfs", disk],
                       stderr=subprocess.DEVNULL) != 0:
        print("  disk without inodes: skipped (cannot mount a tmpfs here)")
        return 0
    try:
        server = Server(binary, disk, "--min-free", "0", log_dir=work)
        try:
            for i in range(1000):
                try:
                    open(os.path.join(disk, "inode-%d" % i), "w").close()
                except OSError as e:
                    if e.errno != errno.ENOSPC:
                        raise
                    break
            time.sleep(1.1)  # the write probe's answer is kept a second
            status, _, body = server.request(http("GET", "/healthz"))
            health = json.loads(body)
            if status != 503 or "takes no more writes" not in health["storage"].get("detail", ""):
                fail("/healthz on a disk without inodes", "%d %.300r" % (status, health))
            if health["storage"]["free_bytes"] == 0:
                fail("/healthz on a disk without inodes", "no byte free either: the probe was not what told")
        finally:
            server.stop()
    finally:
        subprocess.call(["umount", "-l", disk])
    return 1


def main():
    binary = sys.argv[1]
    work = tempfile.mkdtemp()
    os.makedirs(os.path.join(work, "meshes"))
    os.makedirs(os.path.join(work, "web"))
    with open(os.path.join(work, "web", "index.html"), "w") as f:
        f.write("<!doctype html><title>facetlight</title>")
    server = Server(binary, work)
    openapi = server.get_json("/api/openapi.json")
    try:
        total = run_cases(server)
        total += run_short_bodies(server)
        total += run_log_forgery(server)
        total += run_header_flood(server)
        total += run_slow_clients(server)
        if server.proc.poll() is not None:
            fail("server", "exited with %s" % server.proc.returncode)
    finally:
        server.stop()
    try:
        total += run_slow_clients_across_peers(binary, work)
        total += run_slow_bodies(binary, work)
        total += run_allowed_host(binary, work)
        total += run_bearer_token(binary, work)
        total += run_mesh_store(binary, work)
        total += run_job_budget(binary, work)
        total += run_durable_cancel(binary, work)
        total += run_storage_guard(binary, work)
        total += run_real_full_disk(binary, work)
        total += run_no_inodes(binary, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("  %d answers of API routes checked against the OpenAPI document" % check_documented(openapi))
    print("%d hostile requests, %d failures" % (total, len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
