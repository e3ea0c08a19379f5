#!/usr/bin/env python3
"""Checks what must hold of every recovered model over the artifacts of runs:

    scripts/check-invariants.py <artifact folder> [<artifact folder> ...]

Counts, per folder and in all: node names that are a variable's usual name (node_name, name,
options), port names that are no ROS name although not marked as expressions (an enum constant,
C++ text), the same port (kind, name, type, place) listed twice in a class, and message types
that are neither canonical (pkg/msg/T, pkg/srv/T, pkg/action/T) nor empty nor marked
`"type_resolved": false` (an expression left as written). The same checks but
the last run over every fixture in tst_fixtures (modelInvariantViolations). Exit 1 when any
holds a violation.
"""
import collections
import json
import os
import re
import sys

ROS_NAME = re.compile(r'^(~/?|/)?[A-Za-z_{][A-Za-z0-9_{}/~]*$')
TYPE = re.compile(r'^[A-Za-z][A-Za-z0-9_]*/(msg|srv|action)/[A-Za-z][A-Za-z0-9_]*$')
VARIABLE_NAMES = {"node_name", "name", "options"}


def check(folder):
    found = collections.defaultdict(list)
    ports = 0
    with open(os.path.join(folder, "atomic_nodes.json")) as f:
        atomic = json.load(f)
    for package in atomic["list_packages"]:
        for node in package["list_atomic_ros_node_classifiers"]:
            if node.get("node_name") in VARIABLE_NAMES:
                found["node name"].append(f"{node['class_name']}: {node['node_name']}")
            seen = set()
            for p in node.get("ports", []):
                ports += 1
                e = p["evidence"]
                key = (p["kind"], p["name"], p.get("type"), e["file"], e["line"], e.get("column"))
                if key in seen:
                    found["duplicate port"].append(f"{node['class_name']}: {p['name']}")
                seen.add(key)
                if p.get("name_origin") != "expression" and p["name"] and \
                        not ROS_NAME.match(p["name"]):
                    found["port name"].append(f"{node['class_name']}: {p['name']}")
                if p.get("type") and not TYPE.match(p["type"]) and \
                        p.get("type_resolved", True):
                    found["type"].append(f"{node['class_name']}: {p['type']}")
    return ports, found


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    failed = False
    for folder in sys.argv[1:]:
        ports, found = check(folder)
        failed = failed or bool(found)
        print(f"{folder}: {ports} ports; " + (", ".join(
            f"{kind} {len(v)}" for kind, v in sorted(found.items())) or "no violation"))
        for kind, v in sorted(found.items()):
            for text, n in collections.Counter(v).most_common(3):
                print(f"    {kind}: {text}" + (f" (x{n})" if n > 1 else ""))
    sys.exit(1 if failed else 0)
