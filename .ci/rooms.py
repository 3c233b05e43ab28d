#!/usr/bin/env python3
"""Include graph of a C++ tree: a room = a source with its header (same stem, same folder).
Prints each include cycle between rooms (a strongly connected component of more than one room)
and exits 1 if there is any. Usage: rooms.py DIR... (paths relative to the current directory).
The repository's own copy of the project's shared rooms tool (same output, same exit code), so that
CI and ctest's `rooms` check the source tree without anything outside the checkout."""
import os, re, sys

inc = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
files = []
for d in sys.argv[1:]:
    for root, _, names in os.walk(d):
        files += [os.path.join(root, n) for n in names if n.endswith((".cpp", ".hpp", ".h", ".cc"))]
room = lambda p: os.path.splitext(os.path.normpath(p))[0]
by_tail = {}
for p in files:
    by_tail.setdefault(os.path.normpath(p), p)
def resolve(src, name):
    cands = [os.path.join(os.path.dirname(src), name)] + [os.path.join(d, name) for d in
             sorted({os.path.dirname(os.path.dirname(f)) for f in files} | {os.path.dirname(f) for f in files})]
    for c in cands:
        c = os.path.normpath(c)
        if c in by_tail: return c
    return None
edges = {}
for p in files:
    a = room(p)
    edges.setdefault(a, set())
    for name in inc.findall(open(p, errors="replace").read()):
        q = resolve(p, name)
        if q and room(q) != a: edges[a].add(room(q))
# Tarjan
index, low, stack, on, sccs, n = {}, {}, [], set(), [], [0]
sys.setrecursionlimit(10000)
def visit(v):
    index[v] = low[v] = n[0]; n[0] += 1; stack.append(v); on.add(v)
    for w in edges.get(v, ()):
        if w not in index: visit(w); low[v] = min(low[v], low[w])
        elif w in on: low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop(); on.discard(w); comp.append(w)
            if w == v: break
        if len(comp) > 1: sccs.append(sorted(comp))
for v in list(edges):
    if v not in index: visit(v)
for c in sccs: print("cycle: " + " <-> ".join(c))
print("rooms: %d, include cycles: %d" % (len(edges), len(sccs)))
sys.exit(1 if sccs else 0)
