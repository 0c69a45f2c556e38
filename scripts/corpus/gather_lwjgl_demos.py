#!/usr/bin/env python3
"""LWJGL/lwjgl3-demos: programs of src/**/*.java as the demos build them, followed in source order.

`int x = [Cls.]createShader("org/lwjgl/demo/.../a.vs", GL_<STAGE>_SHADER[_ARB][, "430 core"])`
reads the class-path resource res/<path> verbatim (ioResourceToByteBuffer); with a version
argument the demos' createShader(resource, type, version) sends "#version <v>\\n" first.
`glAttachShader(p, x)` / `glAttachObjectARB(p, x)` collect, `glLinkProgram(p)` /
`glLinkProgramARB(p)` make one program. Identical programs are written once.
Usage: gather_lwjgl_demos.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, STAGE_NAMES, strip_cpp_comments, write_program  # noqa: E402

STEM = {"vertex": "vs", "fragment": "fs", "geometry": "gs", "tess-control": "tcs",
        "tess-eval": "tes", "compute": "cs"}
CALLS = re.compile(
    r'(?P<var>[\w.]+)\s*=\s*(?:\w+\.)?createShader\(\s*"(?P<path>[^"]+)"\s*,\s*GL_(?P<st>\w+?)_SHADER(?:_ARB)?'
    r'\s*(?:,\s*"(?P<ver>[^"]*)"\s*)?\)'
    r'|glAttach(?:Shader|ObjectARB)\(\s*(?P<aprog>[\w.]+)\s*,\s*(?P<ash>[\w.]+)\s*\)'
    r'|glLinkProgram(?:ARB)?\(\s*(?P<lprog>[\w.]+)\s*\)')


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, set()
    for f in m.files:
        if not (f.startswith("src/") and f.endswith(".java")):
            continue
        src = strip_cpp_comments(m.text(f))
        if "createShader(" not in src:
            continue
        shaders, attached, k = {}, {}, 0
        for c in CALLS.finditer(src):
            if c.group("var"):
                text = m.text("res/" + c.group("path"))
                if text is not None and c.group("ver"):
                    text = f"#version {c.group('ver')}\n" + text
                shaders[c.group("var")] = (STAGE_NAMES.get(c.group("st")), os.path.basename(c.group("path")), text)
            elif c.group("aprog"):
                attached.setdefault(c.group("aprog"), []).append(shaders.get(c.group("ash")))
            else:
                stages = attached.pop(c.group("lprog"), [])
                if not stages or any(s is None or s[0] is None or s[2] is None for s in stages):
                    continue
                key = tuple((s, t) for s, _, t in stages)
                if key in seen:
                    continue
                seen.add(key)
                k += 1
                count, files = {}, []
                for s, _, t in stages:
                    count[s] = count.get(s, 0) + 1
                    files.append((s, STEM[s] + ("" if count[s] == 1 else str(count[s])), t))
                demo = f[len("src/org/lwjgl/demo/"):-5].replace("/", ".") if f.startswith("src/org/lwjgl/demo/") else f[4:-5]
                write_program(out, "lwjgl_demos", f"{demo}.{k}", files)
                written += 1
    print(written, "programs")


main()
