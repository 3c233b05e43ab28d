#!/usr/bin/env python3
"""The core's folders as layers: a file of src/impact may include its own folder and the folders
below it, never one above, so that a reader knows from the tree what a room may touch.
Prints each include that runs upward and exits 1 if there is any. Usage: layers.py [SRC_DIR]

Bottom-up (ARCHITECTURE.md, "Layout"): the leaves at the root (format, heap_value, version), then
the model and its laws, the forces, the methods' plain data, the output's plain data, the time
loop, the time-steppers, the references, the ensemble, the chain, and the run: the variant of
steppers, the observers, the scene and the value API. The umbrella impact.hpp includes them all."""
import os, re, sys

LAYERS = ["", "model", "forces", "methods", "output", "loop", "steppers", "references",
          "ensemble", "chain", "run"]
UMBRELLA = "impact.hpp"

src = sys.argv[1] if len(sys.argv) > 1 else "src"
core = os.path.join(src, "impact")
include = re.compile(r'^\s*#\s*include\s*"impact/([^"]+)"', re.M)
upward, files = [], 0
for root, _, names in os.walk(core):
    for name in sorted(names):
        if not name.endswith((".cpp", ".hpp")):
            continue
        path = os.path.join(root, name)
        folder = os.path.relpath(root, core).replace(".", "")
        if folder not in LAYERS:
            upward.append(f"{path}: the folder {folder} is not a layer of layers.py")
            continue
        files += 1
        if folder == "" and name == UMBRELLA:
            continue
        for target in include.findall(open(path, errors="replace").read()):
            to = os.path.dirname(target)
            if to not in LAYERS:
                upward.append(f"{path}: includes impact/{target}, in no layer")
            elif LAYERS.index(to) > LAYERS.index(folder):
                upward.append(f"{path}: includes impact/{target}, a layer above "
                              f"({folder or 'the root'} < {to})")
for line in upward:
    print(line)
print("layers: %d files in %d folders, upward includes: %d" % (files, len(LAYERS), len(upward)))
sys.exit(1 if upward else 0)
