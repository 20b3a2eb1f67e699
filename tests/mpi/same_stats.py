"""Exits non-zero unless two statistics documents are equal apart from `timing`, and the second says it ran
on RANKS ranks. Usage: same_stats.py ONE.json MANY.json RANKS"""
import json
import sys

one, many = (json.load(open(p)) for p in sys.argv[1:3])
assert many["timing"]["ranks"] == int(sys.argv[3]), many["timing"]
for doc in (one, many):
    doc.pop("timing")
if one != many:
    sys.exit("statistics differ between 1 and %s ranks" % sys.argv[3])
