#!/usr/bin/env python3
"""fogleman/Craft (desktop GL 2.1 / GLSL 1.20): each `load_program("shaders/x_vertex.glsl",
"shaders/x_fragment.glsl")` of src/main.c; util.c's load_shader passes the file text unchanged.
Usage: gather_craft.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

m, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
for vs, fs in re.findall(r'load_program\(\s*"([^"]+)"\s*,\s*"([^"]+)"\s*\)', strip_cpp_comments(m.text("src/main.c"))):
    stages = [("vertex", os.path.basename(vs)[:-5], m.text(vs)), ("fragment", os.path.basename(fs)[:-5], m.text(fs))]
    if all(t is not None for _, _, t in stages):
        write_program(out, "craft", os.path.basename(vs).split("_")[0], stages)
        n += 1
print(n, "programs")
