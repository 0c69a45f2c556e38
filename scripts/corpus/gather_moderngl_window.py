#!/usr/bin/env python3
"""moderngl/moderngl-window: programs as moderngl_window/opengl/program.py builds them.

A single-file program (`load_program("x.glsl")`, every .glsl under a programs/ folder that
holds FRAGMENT_SHADER) gives a vertex stage, a geometry stage when GEOMETRY_SHADER occurs in
the text and a fragment stage; separate files come from `load_program(vertex_shader=...,
geometry_shader=..., fragment_shader=...)` calls in the examples. Per stage (ShaderSource):
text stripped, `#define <STAGE>_SHADER 1` and `#line 2` inserted after the #version line,
`#include path` lines replaced by the file found in a resource dir (recursively). Programs
with tessellation stages are skipped. Usage: gather_moderngl_window.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
RES = ["examples/resources", "moderngl_window/scene/programs", "moderngl_window/text/bitmapped",
       "tests/fixtures/resources", "examples/resources/programs", "tests/fixtures/resources/programs"]


def find(path):
    for d in RES:
        if m.exists(f"{d}/{path}"):
            return f"{d}/{path}"
    return None


def includes(lines, depth=0):
    if depth > 100:
        raise RecursionError
    for nr, line in enumerate(lines):
        if line.strip().startswith("#include"):
            inc = find(re.search(r'#include\s+"?([^"]+)', line.strip())[1])
            sub = includes(m.text(inc).split("\n"), depth + 1)
            return includes(lines[:nr] + sub + lines[nr + 1:], depth)
    return lines


def stage(kind, text):
    lines = text.strip().split("\n")
    if not lines[0].startswith("#version"):
        raise ValueError("no #version")
    lines[1:1] = [f"#define {kind}_SHADER 1", "#line 2"]
    return "\n".join(includes(lines))


def emit(name, parts):
    try:
        stages = [(st, stem, stage(kind, text)) for st, kind, stem, text in parts]
    except (ValueError, RecursionError, TypeError):
        return 0
    write_program(out, "moderngl_window", name, stages)
    return 1


n = 0
for f in m.files:
    if not (f.endswith(".glsl") and "/programs/" in f):
        continue
    src = m.text(f)
    if "FRAGMENT_SHADER" not in src or "TESS_" in src:
        continue
    stem = os.path.basename(f)[:-5]
    parts = [("vertex", "VERTEX", stem, src)]
    if "GEOMETRY_SHADER" in src:
        parts.append(("geometry", "GEOMETRY", stem, src))
    parts.append(("fragment", "FRAGMENT", stem, src))
    n += emit(f.split("programs/", 1)[1][:-5], parts)

call = re.compile(r'load_program\(\s*((?:\w+_shader\s*=\s*"[^"]+"\s*,?\s*)+)\)')
for f in m.files:
    if f.endswith(".py") and f.startswith(("examples/", "tests/")):
        for args in call.findall(m.text(f)):
            kw = dict(re.findall(r'(\w+)_shader\s*=\s*"([^"]+)"', args))
            if set(kw) - {"vertex", "geometry", "fragment"} or "fragment" not in kw:
                continue
            paths = [(st, find(kw[st])) for st in ("vertex", "geometry", "fragment") if st in kw]
            if any(p is None for _, p in paths):
                continue
            parts = [(st, st.upper(), os.path.basename(p)[:-5], m.text(p)) for st, p in paths]
            n += emit("sep_" + "_".join(os.path.basename(p)[:-5] for _, p in paths), parts)
print(n, "programs")
