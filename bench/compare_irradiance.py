#!/usr/bin/env python3
"""Compares two builds' irradiance estimates, as `photon_map_bench --focus 1 --irradiance FILE` writes them
(doubles, one a query): how many have the same bits, the largest relative differences, and the queries
whose estimates differ by more than rounding; with FILE.sets beside both, the queries whose sets of k
nearest differ and those whose k-th distances do.

Usage: bench/compare_irradiance.py OLD_FILE NEW_FILE
"""
import array
import os
import sys


def load(path):
    a = array.array("d")
    with open(path, "rb") as f:
        a.frombytes(f.read())
    return a


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    old, new = load(sys.argv[1]), load(sys.argv[2])
    if len(old) != len(new):
        sys.exit(f"{len(old)} estimates against {len(new)}")
    same = sum(a == b for a, b in zip(old, new))
    rel = [(abs(a - b) / max(abs(a), abs(b)) if a != b else 0.0, i) for i, (a, b) in enumerate(zip(old, new))]
    rel.sort(reverse=True)
    print(f"{len(old)} estimates: {same} with the same bits, {len(old) - same} differing; "
          f"largest relative differences:")
    for r, i in rel[:3]:
        print(f"  {r:.3g} (query {i}: {old[i]!r} against {new[i]!r})")
    past = [i for r, i in rel if r > 1e-12]
    print(f"{len(past)} past 1e-12 (a different photon, as at a tie at the k-th distance): {past[:20]}")
    if os.path.exists(sys.argv[1] + ".sets") and os.path.exists(sys.argv[2] + ".sets"):
        a, b = open(sys.argv[1] + ".sets", "rb").read(), open(sys.argv[2] + ".sets", "rb").read()
        size = len(a) // len(old)
        if len(a) != len(b) or size * len(old) != len(a):
            sys.exit("the .sets files do not match the estimates")
        differ = [i for i in range(len(old)) if a[i * size:(i + 1) * size] != b[i * size:(i + 1) * size]]
        radius = [i for i in differ if a[i * size:i * size + 4] != b[i * size:i * size + 4]]
        print(f"sets of k nearest: {len(old) - len(differ)} the same, {len(differ)} differing {differ[:20]}; "
              f"k-th distance differing at {len(radius)} queries {radius[:20]}")


if __name__ == "__main__":
    main()
