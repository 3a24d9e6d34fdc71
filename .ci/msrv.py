#!/usr/bin/env python3
"""Fails when a crate's `rust-version` is below what its dependency tree declares.

The MSRV is the largest `rust_version` over the packages of the normal (and build) dependency
tree in `cargo metadata --format-version 1 --filter-platform <host>`, the root excluded.
Usage (from the repository root): python3 .ci/msrv.py [Cargo.toml ...]  (default: both crates)
"""
import json
import re
import subprocess
import sys


def version(s):
    v = [int(x) for x in s.split(".")]
    return tuple(v + [0] * (3 - len(v)))


def needed(manifest):
    host = subprocess.run(["rustc", "-vV"], capture_output=True, text=True, check=True).stdout
    host = re.search(r"^host: (\S+)", host, re.M).group(1)
    meta = json.loads(subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--manifest-path", manifest,
         "--filter-platform", host], capture_output=True, text=True, check=True).stdout)
    pkgs = {p["id"]: p for p in meta["packages"]}
    nodes = {n["id"]: n for n in meta["resolve"]["nodes"]}
    root = meta["resolve"]["root"]
    seen, stack = set(), [root]
    while stack:
        i = stack.pop()
        if i in seen:
            continue
        seen.add(i)
        for d in nodes[i]["deps"]:
            if any(k["kind"] in (None, "build") for k in d["dep_kinds"]):
                stack.append(d["pkg"])
    found = [(version(pkgs[i]["rust_version"]), pkgs[i]["name"]) for i in seen
             if i != root and pkgs[i].get("rust_version")]
    return max(found), pkgs[root]


failed = False
for manifest in sys.argv[1:] or ["Cargo.toml", "python/Cargo.toml"]:
    (need, by), root = needed(manifest)
    declared = root.get("rust_version")
    need_s = "%d.%d" % need[:2] if need[2] == 0 else "%d.%d.%d" % need
    print(f"{manifest}: rust-version {declared}, dependency tree needs {need_s} ({by})")
    if declared is None or version(declared) < need:
        failed = True
        print(f"{manifest}: rust-version must be at least {need_s}", file=sys.stderr)
sys.exit(1 if failed else 0)
