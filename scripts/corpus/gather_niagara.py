#!/usr/bin/env python3
"""Pairs zeux/niagara GLSL programs the way src/niagara.cpp builds them.

createProgram(device, VK_PIPELINE_BIND_POINT_GRAPHICS, { &shaders["mesh.vert"], &shaders["mesh.frag"] }, ..)
names the stages of one program (src/shaders/<name>.glsl); programs with task/mesh stages are left
out. CMake compiles each file with glslangValidator -V --target-env vulkan1.3, no defines;
#include "x.h" (GL_GOOGLE_include_directive) is inlined relative to the including file
(src/shaders/mesh.h includes ../config.h), each header once per stage.
Usage: gather_niagara.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

STAGE = {"vert": "vertex", "geom": "geometry", "frag": "fragment"}
INC = re.compile(r'^[ \t]*#\s*include\s+"([^"]+)"[^\n]*', re.M)


def inline(mirror, path, once):
    def sub(m):
        inc = posixpath.normpath(posixpath.join(posixpath.dirname(path), m.group(1)))
        if inc in once:
            return ""
        once.add(inc)
        return inline(mirror, inc, once)
    return INC.sub(sub, mirror.text(path))


mirror, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
src = mirror.text("src/niagara.cpp")
for group in re.findall(r'createProgram\([^;]*?VK_PIPELINE_BIND_POINT_GRAPHICS\s*,\s*\{([^}]*)\}', src):
    names = re.findall(r'shaders\["([\w\-]+)\.(\w+)"\]', group)
    if not names or any(ext not in STAGE for _, ext in names):
        continue  # task/mesh programs
    files = [(STAGE[ext], stem, f"src/shaders/{stem}.{ext}.glsl") for stem, ext in names]
    name = "_".join(dict.fromkeys(stem for stem, _ in names))
    write_program(out, "niagara", name, [(s, stem, inline(mirror, p, set())) for s, stem, p in files])
    n += 1
print(n, "programs")
