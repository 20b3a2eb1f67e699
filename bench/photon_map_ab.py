#!/usr/bin/env python3
"""Two builds of photon_map_bench side by side: runs `--focus 1` of each alternately, then prints a markdown
table of the medians over the rounds (tree build ms at 1 and 2 threads; gather k queries/s in raster and
random order at 1 and 2 threads) and whether the tree and gather hashes agree, naming those that differ (a
change that moves the gather's last bits on purpose is checked with bench/compare_irradiance.py instead).

Usage: bench/photon_map_ab.py OLD_BENCH NEW_BENCH [--rounds R] [--reps N] [extra photon_map_bench flags]
"""
import argparse
import os
import re
import statistics
import subprocess

TREE = re.compile(r"tree, .*: 1 thread (\S+) ms \(CPU (\S+) ms\), 2 threads (\S+) ms \(CPU (\S+) ms\); tree hash (\S+)")
GATHER = re.compile(r"gather, .* in (\w+) order, .*: 1 thread (\S+) k/s \((\S+) k per CPU s\), "
                    r"2 threads (\S+) k/s \((\S+) k per CPU s\); answers hash \(1 thread\) (\S+)")


def run(binary, reps, extra):
    out = subprocess.run([binary, "--focus", "1", "--reps", str(reps)] + extra, check=True,
                         capture_output=True, text=True).stdout
    figures, hashes = {}, {}
    for line in out.splitlines():
        if m := TREE.match(line):
            figures["tree, 1 thread: wall ms"] = float(m[1])
            figures["tree, 1 thread: CPU ms"] = float(m[2])
            figures["tree, 2 threads: wall ms"] = float(m[3])
            figures["tree, 2 threads: CPU ms"] = float(m[4])
            hashes["tree"] = m[5]
        elif m := GATHER.match(line):
            figures[f"gather {m[1]}, 1 thread: k queries/s"] = float(m[2])
            figures[f"gather {m[1]}, 1 thread: k queries per CPU s"] = float(m[3])
            figures[f"gather {m[1]}, 2 threads: k queries/s"] = float(m[4])
            figures[f"gather {m[1]}, 2 threads: k queries per CPU s"] = float(m[5])
            hashes[m[1]] = m[6]
    return figures, hashes


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--reps", type=int, default=1)
    args, extra = ap.parse_known_args()
    load = [os.getloadavg()[0]]
    results = {"old": [], "new": []}
    hashes = {}
    for r in range(args.rounds):
        for name, binary in (("old", args.old), ("new", args.new)) if r % 2 == 0 else (("new", args.new), ("old", args.old)):
            figures, h = run(binary, args.reps, extra)
            results[name].append(figures)
            hashes.setdefault(name, h)
            load.append(os.getloadavg()[0])
    print(f"{args.rounds} rounds, old and new alternately, {args.reps} rep(s) a run; "
          f"load average (1 min) {min(load):.1f}-{max(load):.1f}\n")
    print("| figure | old | new | new / old |")
    print("|---|---:|---:|---:|")
    for key in results["old"][0]:
        old = statistics.median(f[key] for f in results["old"])
        new = statistics.median(f[key] for f in results["new"])
        print(f"| {key} | {old:.1f} | {new:.1f} | {new / old:.2f}x |")
    same = hashes["old"] == hashes["new"]
    print(f"\nhashes of the tree and of every 1-thread gather's answers: {'identical' if same else 'DIFFERENT'} "
          f"({hashes['new']})")
    for key in hashes["new"]:
        if hashes["old"].get(key) != hashes["new"][key]:
            print(f"  {key}: old {hashes['old'].get(key)}, new {hashes['new'][key]}")


if __name__ == "__main__":
    main()
