#!/usr/bin/env python3
"""raysan5/raylib examples: each LoadShader(vs, fs) call in examples/*/*.c is one program.

Paths are TextFormat("resources/shaders/glsl%i/x.fs", GLSL_VERSION) with GLSL_VERSION 330
(desktop), relative to the example's folder; a 0/NULL stage is rlgl's default shader
(src/rlgl.h, GRAPHICS_API_OPENGL_33 branch). Usage: gather_raylib.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program
from cstr import c_string

m, out = Mirror(sys.argv[1]), sys.argv[2]
rlgl = m.text("src/rlgl.h")
default = {"vertex": c_string(rlgl, "const char *defaultVShaderCode =", {"GRAPHICS_API_OPENGL_33"}),
           "fragment": c_string(rlgl, "const char *defaultFShaderCode =", {"GRAPHICS_API_OPENGL_33"})}
arg = r'\s*(0|NULL|TextFormat\(\s*"[^"]+"\s*,\s*GLSL_VERSION\s*\)|"[^"]+")\s*'
call = re.compile(r'\bLoadShader\(' + arg + ',' + arg + r'\)')
n, seen = 0, set()
for f in m.files:
    if not (f.startswith("examples/") and f.endswith(".c")):
        continue
    src, base = m.text(f), os.path.dirname(f)
    for vs, fs in call.findall(src):
        stages, key = [], []
        for stage, a in (("vertex", vs), ("fragment", fs)):
            p = re.search(r'"([^"]+)"', a)
            if not p:
                stages.append((stage, "default", default[stage]))
                key.append("default")
                continue
            path = os.path.normpath(os.path.join(base, p.group(1).replace("%i", "330")))
            text = m.text(path)
            if text is None:
                break
            stages.append((stage, os.path.basename(path).rsplit(".", 1)[0], text))
            key.append(path)
        if len(stages) < 2 or tuple(key) in seen:
            continue
        seen.add(tuple(key))
        name = os.path.basename(f)[:-2] + "_" + stages[1][1]
        write_program(out, "raylib", name, stages)
        n += 1
print(n, "programs")
