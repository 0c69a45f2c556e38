#!/usr/bin/env python3
"""dosbox-staging/dosbox-staging: every resources/shaders/**/*.glsl (one file holding both
stages under `#if defined(VERTEX)` / `#elif defined(FRAGMENT)`), compiled twice as
Shader::BuildShader (src/gui/render/shader.cpp) does: FindShaderAndReadSource appends '\\n' to
the file, then the text up to and including the first `#version ` line, `#define VERTEX 1` or
`#define FRAGMENT 1`, and the rest. Written as <name>.vert / <name>.frag.
Usage: gather_dosbox.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402


def build(src, define):
    top = ""
    ver = src.find("#version ")
    if ver >= 0:
        end = src.find("\n", ver + 9)
        if end >= 0:
            top, src = src[:end + 1], src[end + 1:]
    return top + f"#define {define} 1\n" + src


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    n = 0
    for f in m.files:
        if not (f.startswith("resources/shaders/") and f.endswith(".glsl")):
            continue
        src = m.text(f) + "\n"
        name = f[len("resources/shaders/"):-len(".glsl")]
        stem = os.path.basename(name)
        write_program(out, "dosbox", name.replace("/", "_"),
                      [("vertex", stem, build(src, "VERTEX")), ("fragment", stem, build(src, "FRAGMENT"))])
        n += 1
    print(n, "programs")


main()
