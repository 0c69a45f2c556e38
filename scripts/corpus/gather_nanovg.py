#!/usr/bin/env python3
"""memononen/nanovg (vector-graphics UI library): the one program src/nanovg_gl.h's
glnvg__renderCreate links, for the desktop backends the examples build (example_gl2.c
NANOVG_GL2_IMPLEMENTATION, example_gl3.c / example_fbo.c NANOVG_GL3_IMPLEMENTATION; the GLES
backends left out), with and without NVG_ANTIALIAS (the examples pass it unless DEMO_MSAA).

glnvg__createShader(shader, "shader", shaderHeader, opts, fillVertShader, fillFragShader) gives
glShaderSource three strings per stage: shaderHeader (the C `#if` chain resolved for the backend:
GL2 `#define NANOVG_GL2 1`, no #version; GL3 `#version 150 core` + `#define NANOVG_GL3 1`; then
`#define USE_UNIFORMBUFFER 1` when NANOVG_GL_USE_UNIFORMBUFFER, which GL3 always defines, else
`#define UNIFORMARRAY_SIZE 11`; then an empty line), opts (`#define EDGE_AA 1\\n` with
NVG_ANTIALIAS, else ""), and the stage text. Programs `gl2`, `gl2.aa`, `gl3`, `gl3.aa`.
Usage: gather_nanovg.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string_vars, cpp_ifdefs, strip_cpp_comments, write_program  # noqa: E402

SRC = "src/nanovg_gl.h"
BACKENDS = {"gl2": {"NANOVG_GL2"}, "gl3": {"NANOVG_GL3", "NANOVG_GL_USE_UNIFORMBUFFER"}}


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    raw = strip_cpp_comments(m.text(SRC))
    body = raw[raw.index("static int glnvg__renderCreate("):]
    n = 0
    for backend, defined in BACKENDS.items():
        # C `#if` lines only: the GLSL `#ifdef` lines are inside string literals.
        strings = c_string_vars(cpp_ifdefs(body, defined))
        header = strings["shaderHeader"][0]
        vs, fs = strings["fillVertShader"][0], strings["fillFragShader"][0]
        opts = {}
        for call in re.finditer(r'glnvg__createShader\([^;]*?"shader"\s*,\s*shaderHeader\s*,\s*("(?:\\.|[^"\\])*"|NULL)', body):
            opt = call.group(1)
            opts["aa" if opt != "NULL" else None] = "" if opt == "NULL" else \
                opt[1:-1].encode().decode("unicode_escape")
        for tag, opt in opts.items():
            write_program(out, "nanovg", backend + (f".{tag}" if tag else ""),
                          [("vertex", "fill", header + opt + vs), ("fragment", "fill", header + opt + fs)])
            n += 1
    print(n, "programs")


main()
