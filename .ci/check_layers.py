#!/usr/bin/env python3
"""Fails when the crate's module graph has an import cycle.

Reads every `crate::...` and `super::...` path in src/ (outside `#[cfg(test)]` modules and
comments; the binary's main.rs and src/cli/ are skipped), maps it to the module it names, and looks for strongly connected components at the
level of layers (depth 1: model, solvers, ...) and of modules (depth 2: model::material, ...).
Usage (from the repository root): python3 .ci/check_layers.py [-v]
"""
import os
import re
import sys

ROOT = "src"


def module_path(f):
    p = os.path.relpath(f, ROOT)[:-3].split("/")
    return tuple(p[:-1] if p[-1] in ("mod", "lib") else p)


# main.rs and src/cli/ are the binary crate: they only use the library, never the reverse
BINARY = os.path.join(ROOT, "cli")
FILES = [os.path.join(d, f) for d, _, fs in os.walk(ROOT) for f in fs
         if f.endswith(".rs") and f != "main.rs"
         and os.path.commonpath([d, BINARY]) != BINARY]
MODS = {module_path(f): f for f in FILES}
PATH = r"((?:[a-z_][a-z0-9_]*::)*[a-z_][a-z0-9_]*)"


def target(segs):
    for k in range(len(segs), 0, -1):
        if tuple(segs[:k]) in MODS:
            return segs[:k]
    return None


def graph(depth):
    edges = {}
    for mp, f in MODS.items():
        text = open(f, encoding="utf-8").read().split("\n#[cfg(test)]")[0]
        text = re.sub(r"//[^\n]*", "", text)
        src = "::".join(mp[:depth])
        refs = [m.group(1).split("::") for m in re.finditer(r"\bcrate::" + PATH, text)]
        base = list(mp[:-1])
        refs += [base + m.group(1).split("::") for m in re.finditer(r"\bsuper::" + PATH, text)]
        for segs in refs:
            t = target(segs)
            if t is None:
                continue
            dst = "::".join(t[:depth])
            if dst and dst != src and not src.startswith(dst + "::") and not dst.startswith(src + "::"):
                edges.setdefault(src, set()).add(dst)
    return edges


def cycles(edges):
    index, low, stack, on, out, n = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = n[0]
        n[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in list(edges):
        if v not in index:
            visit(v)
    return out


failed = False
for depth in (1, 2):
    edges = graph(depth)
    found = cycles(edges)
    if "-v" in sys.argv:
        for k in sorted(edges):
            print(f"{k} -> {', '.join(sorted(edges[k]))}")
    if found:
        failed = True
        print(f"import cycles at depth {depth}: {found}", file=sys.stderr)
print("layers: no import cycle" if not failed else "layers: import cycles found")
sys.exit(1 if failed else 0)
