#!/usr/bin/env python3
"""adriengivry/Overload: each Resources/**/*.ovfx is one program (ShaderLoader::ParseShader).

LoadShader: line by line, a line holding `#include "p"` becomes the included file (":x" is
Resources/Engine/x, the editor's path parser), every line ends with "\\n"; then the text is
split at `#shader vertex` / `#shader fragment` lines. Usage: gather_overload.py MIRROR_GIT_DIR OUT_DIR
"""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]


def resolve(p):
    if p.startswith(":"):
        for root in ("Resources/Engine/", "Resources/Editor/"):
            if m.exists(root + p[1:]):
                return root + p[1:]
    return p


def getlines(text):
    lines = text.split("\n")
    return lines[:-1] if lines[-1] == "" else lines


def load(path):
    buf = []
    for line in getlines(m.text(path)):
        if "#include" in line:
            q = line.split('"')
            if len(q) >= 3:
                buf.append(load(resolve(q[1])) + "\n")
        else:
            buf.append(line + "\n")
    return "".join(buf)


n = 0
for f in m.files:
    if not f.endswith(".ovfx"):
        continue
    parts, kind = {"vertex": [], "fragment": []}, None
    for line in getlines(load(f)):
        if "#shader" in line:
            kind = "vertex" if "vertex" in line else "fragment" if "fragment" in line else kind
        elif kind:
            parts[kind].append(line + "\n")
    stem = os.path.basename(f)[:-5]
    name = f.split("/")[1] + "_" + f.split("Shaders/", 1)[1][:-5].replace("/", "_")
    write_program(out, "overload", name, [(st, stem, "".join(parts[st])) for st in ("vertex", "fragment")])
    n += 1
print(n, "programs")
