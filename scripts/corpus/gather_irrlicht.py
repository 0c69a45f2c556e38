#!/usr/bin/env python3
"""Irrlicht (zaki/irrlicht mirror; irrlicht/irrlicht has no snapshot here): example 10.Shaders
with high-level shaders on the OpenGL driver loads media/opengl.vert + media/opengl.frag;
COpenGLSLMaterialRenderer::createShader passes the file text unchanged (one string).
The other media shaders (opengl.vsh/.psh ARB assembly, d3d*) are not GLSL.
Usage: gather_irrlicht.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    main_cpp = m.text("examples/10.Shaders/main.cpp") or ""
    n = 0
    if '"opengl.vert"' in main_cpp and '"opengl.frag"' in main_cpp:
        vs, fs = m.text("media/opengl.vert"), m.text("media/opengl.frag")
        if vs is not None and fs is not None:
            write_program(out, "irrlicht", "10.Shaders", [("vertex", "opengl", vs), ("fragment", "opengl", fs)])
            n += 1
    print(n, "programs")


main()
