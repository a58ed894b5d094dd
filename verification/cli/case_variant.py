#!/usr/bin/python3
"""Writes a variant of a case file for the end-to-end tests.

Usage: case_variant.py CASE OUT KEY=JSON [KEY=JSON ...]
KEY is a dotted key of the case (time.duration), JSON its new value
(0.005, -1.0, [{"method": "cb", "modes": [10]}]).
"""
import json
import sys

case, out = sys.argv[1], sys.argv[2]
document = json.load(open(case))
for assignment in sys.argv[3:]:
    key, value = assignment.split("=", 1)
    *parents, leaf = key.split(".")
    node = document
    for parent in parents:
        node = node[parent]
    node[leaf] = json.loads(value)
json.dump(document, open(out, "w"), indent=2)
