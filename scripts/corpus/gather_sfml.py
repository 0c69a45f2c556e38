#!/usr/bin/env python3
"""SFML/SFML examples (desktop GL compatibility profile, GLSL 1.10-1.20): each
`shader.loadFromFile("resources/a.vert", ["resources/b.geom",] "resources/c.frag")` and
fragment-only `loadFromFile("resources/x.frag", sf::Shader::Type::Fragment)` (linked with the
fixed-function vertex stage, so only the fragment file) of examples/*/*.cpp, paths relative to
the example folder; sf::Shader::compile passes the text unchanged.
Usage: gather_sfml.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

EXT = {"vert": "vertex", "frag": "fragment", "geom": "geometry"}
m, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
for f in m.files:
    if not re.match(r"examples/[^/]+/[^/]+\.cpp$", f):
        continue
    base = os.path.dirname(f)
    for args in re.findall(r"\.loadFromFile\(([^()]*(?:\([^()]*\))?[^()]*)\)", strip_cpp_comments(m.text(f))):
        paths = re.findall(r'"([^"]+\.(?:vert|frag|geom))"', args)
        if not paths:
            continue
        if len(paths) == 1 and "Type::Fragment" not in args:
            continue
        stages = [(EXT[p.rsplit(".", 1)[1]], os.path.basename(p).rsplit(".", 1)[0], m.text(f"{base}/{p}")) for p in paths]
        if any(t is None for _, _, t in stages):
            continue
        write_program(out, "sfml", f"{os.path.basename(base)}.{stages[-1][1]}", stages)
        n += 1
print(n, "programs")
