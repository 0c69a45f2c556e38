#!/usr/bin/env python3
"""isl-org/Open3D legacy visualizer (desktop GL 3.3): each ShaderWrapper subclass's Compile()
in cpp/open3d/visualization/shader/*.cpp calls `CompileShaders(VertexName, GeometryName|NULL,
FragmentName)`; the names are the C strings the build generates from
cpp/open3d/visualization/shader/glsl/<Name>.glsl (verbatim file text), so a call is a program.
Usage: gather_open3d.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

m, out = Mirror(sys.argv[1]), sys.argv[2]
glsl = "cpp/open3d/visualization/shader/glsl/"
n, seen = 0, set()
for f in m.files:
    if not re.match(r"cpp/open3d/visualization/shader/\w+\.cpp$", f):
        continue
    for v, g, fr in re.findall(r"CompileShaders\(\s*(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*\)", strip_cpp_comments(m.text(f))):
        if (v, g, fr) in seen:
            continue
        stages = [("vertex", v, m.text(glsl + v + ".glsl"))]
        if g not in ("NULL", "nullptr"):
            stages.append(("geometry", g, m.text(glsl + g + ".glsl")))
        stages.append(("fragment", fr, m.text(glsl + fr + ".glsl")))
        if any(t is None for _, _, t in stages):
            continue
        seen.add((v, g, fr))
        write_program(out, "open3d", f"{os.path.basename(f)[:-4]}.{fr}", stages)
        n += 1
print(n, "programs")
