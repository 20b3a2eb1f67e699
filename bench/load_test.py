#!/usr/bin/env python3
"""Bounded load test of facetlight-server on loopback: many concurrent clients submit small jobs and poll them
to completion. Checks that every job succeeds, that equal jobs give equal statistics and that no request
fails; prints request latencies and throughput as a Markdown row for docs/performance.md.

Usage: bench/load_test.py build/bin/facetlight-server [--clients 16] [--jobs-per-client 8] [--photons 2000]
"""
import argparse
import http.client
import json
import os
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def pct(values, p):
    values = sorted(values)
    return values[min(len(values) - 1, int(p / 100 * len(values)))] * 1000


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("server")
    ap.add_argument("--clients", type=int, default=16)
    ap.add_argument("--jobs-per-client", type=int, default=8)
    ap.add_argument("--photons", type=int, default=2000)
    args = ap.parse_args()

    work = tempfile.mkdtemp()
    port = free_port()
    total_jobs = args.clients * args.jobs_per_client
    proc = subprocess.Popen([args.server, "--port", str(port), "--data", os.path.join(work, "data"),
                             "--web", "", "--no-access-log", "--max-queue", str(total_jobs + 1),
                             "--http-threads", str(args.clients + 2)], stderr=subprocess.DEVNULL)
    lock = threading.Lock()
    submit_lat, poll_lat, errors, results = [], [], [], {}
    try:
        for _ in range(200):
            try:
                http.client.HTTPConnection("127.0.0.1", port, timeout=1).request("GET", "/healthz")
                break
            except OSError:
                time.sleep(0.05)

        def client(k):
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)

            def call(method, path, body=None):
                nonlocal conn
                for _ in range(2):  # the server closes keep-alive connections after 5 requests
                    try:
                        t = time.perf_counter()
                        conn.request(method, path, body=body, headers={"Content-Type": "application/json"})
                        r = conn.getresponse()
                        data = r.read()
                        return r.status, data, time.perf_counter() - t
                    except (http.client.RemoteDisconnected, ConnectionResetError, BrokenPipeError):
                        conn.close()
                        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
                raise RuntimeError("connection failed twice")

            for j in range(args.jobs_per_client):
                seed = j % 4  # equal seeds across clients: equal statistics expected
                job = {"mesh": "round_brilliant", "photons": args.photons, "threads": 1, "seed": seed}
                status, data, dt = call("POST", "/api/jobs", json.dumps(job))
                with lock:
                    submit_lat.append(dt)
                if status != 202:
                    with lock:
                        errors.append(f"submit {status} {data[:200]!r}")
                    continue
                jid = json.loads(data)["id"]
                while True:
                    status, data, dt = call("GET", f"/api/jobs/{jid}")
                    with lock:
                        poll_lat.append(dt)
                    state = json.loads(data)["state"] if status == 200 else "error"
                    if state not in ("queued", "running"):
                        break
                    time.sleep(0.02)
                if state != "succeeded":
                    with lock:
                        errors.append(f"job {jid} {state}")
                    continue
                status, csv, _ = call("GET", f"/api/jobs/{jid}/stats.csv")
                with lock:
                    results.setdefault(seed, set()).add(csv)

        t0 = time.perf_counter()
        threads = [threading.Thread(target=client, args=(k,)) for k in range(args.clients)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        wall = time.perf_counter() - t0
    finally:
        proc.terminate()
        proc.wait(timeout=30)
        shutil.rmtree(work, ignore_errors=True)

    inconsistent = [s for s, v in results.items() if len(v) != 1]
    print(f"clients {args.clients}, jobs {total_jobs} of {args.photons} photons, wall {wall:.2f} s, "
          f"{total_jobs / wall:.1f} jobs/s")
    print(f"POST /api/jobs: {len(submit_lat)} requests, median {pct(submit_lat, 50):.2f} ms, "
          f"p99 {pct(submit_lat, 99):.2f} ms")
    print(f"GET /api/jobs/{{id}}: {len(poll_lat)} requests, median {pct(poll_lat, 50):.2f} ms, "
          f"p99 {pct(poll_lat, 99):.2f} ms")
    print(f"errors {len(errors)}, seeds with differing statistics {len(inconsistent)}")
    for e in errors[:10]:
        print("  ", e)
    print(f"| {args.clients} | {total_jobs} | {args.photons} | {total_jobs / wall:.1f} | "
          f"{pct(submit_lat, 50):.2f} / {pct(submit_lat, 99):.2f} | {pct(poll_lat, 50):.2f} / {pct(poll_lat, 99):.2f} | "
          f"{len(poll_lat)} | {len(errors)} |")
    return 1 if errors or inconsistent else 0


if __name__ == "__main__":
    sys.exit(main())
