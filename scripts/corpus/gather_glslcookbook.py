#!/usr/bin/env python3
"""Pairs OpenGL 4 Shading Language Cookbook programs (daw42/glslcookbook, 2nd edition, or
PacktPublishing/OpenGL-4-Shading-Language-Cookbook-Third-Edition) the way the scenes load them.

In each chapterNN/*.cpp (with `#ifdef __APPLE__` branches resolved for Linux), the calls
`P.compileShader("shader/x.vert" [, GLSLShader::STAGE])` up to `P.link()` make one program
(ingredients/glslprogram.cpp: the file is sent verbatim; without a stage argument the stage
follows the extension table, .vert/.vs, _vert.glsl/.vert.glsl, ...). Paths are relative to the
chapter directory. Programs with compute stages are left out.
Usage: gather_glslcookbook.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, cpp_ifdefs, graphics_program, strip_cpp_comments, write_program

EXT = {".vs": "vertex", ".vert": "vertex", "_vert.glsl": "vertex", ".vert.glsl": "vertex",
       ".gs": "geometry", ".geom": "geometry", ".geom.glsl": "geometry",
       ".tcs": "tess-control", ".tcs.glsl": "tess-control", ".tes": "tess-eval", ".tes.glsl": "tess-eval",
       ".fs": "fragment", ".frag": "fragment", "_frag.glsl": "fragment", ".frag.glsl": "fragment",
       ".cs": "compute", ".cs.glsl": "compute"}
ENUM = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry",
        "TESS_CONTROL": "tess-control", "TESS_EVALUATION": "tess-eval", "COMPUTE": "compute"}


def stage_of(path):
    """GLSLProgram::getExtension on the path as written, looked up in the extension table."""
    dot = path.rfind(".")
    ext = path[dot:] if dot >= 0 else ""
    if ext == ".glsl":
        loc = path.rfind(".", 0, dot)
        loc = loc if loc >= 0 else path.rfind("_", 0, dot)
        ext = path[loc:] if loc >= 0 else ""
    return EXT.get(ext)


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    source = "glslcookbook3" if ".vert.glsl" in m.text("ingredients/glslprogram.cpp") else "glslcookbook"
    written = 0
    for f in m.files:
        if not re.match(r"chapter\d+/[^/]+\.cpp$", f):
            continue
        src = cpp_ifdefs(strip_cpp_comments(m.text(f)))
        pending, seen = {}, []
        for g in re.finditer(r'(\w+)\s*\.\s*compileShader\(\s*"([^"]+)"\s*(?:,\s*GLSLShader::(\w+))?\s*\)'
                             r"|(\w+)\s*\.\s*link\(\s*\)", src):
            if g.group(1):
                path = os.path.normpath(os.path.join(os.path.dirname(f), g.group(2)))
                stage = ENUM.get(g.group(3)) if g.group(3) else stage_of(g.group(2))
                pending.setdefault(g.group(1), []).append((stage, path))
                continue
            shaders = pending.pop(g.group(4), [])
            texts = [(st, m.text(p)) for st, p in shaders]
            if not graphics_program(texts) or shaders in seen:
                continue
            seen.append(shaders)
            scene = os.path.basename(f)[:-4]
            stems = "+".join(dict.fromkeys(os.path.basename(p).split(".")[0] for _, p in shaders))
            write_program(out, source, f"{os.path.dirname(f)}.{scene}.{stems}",
                          [(st, os.path.basename(p).split(".")[0], t) for (st, p), (_, t) in zip(shaders, texts)])
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
