#!/usr/bin/env python3
"""Pairs progschj/OpenGL-Examples programs the way the examples build them.

Each NNname.cpp holds its shaders as C++ string literals (`std::string vertex_source = "..."`)
passed with `source = vertex_source.c_str(); glShaderSource(sh, 1, &source, &length)`; programs
are glAttachShader + glLinkProgram. Followed in order with mirror.GLTrace. Programs with
tessellation/compute stages are left out. Usage: gather_progschj.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, GLTrace, graphics_program, strip_cpp_comments, write_program


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written = 0
    for f in m.files:
        if not re.match(r"\d\d[^/]*\.cpp$", f):
            continue
        seen = []
        for prog, shaders in GLTrace(strip_cpp_comments(m.text(f))).run():
            if not graphics_program(shaders) or shaders in seen:
                continue
            seen.append(shaders)
            write_program(out, "progschj", f"{f[:-4]}.{prog}", [(st, st[:4], t) for st, t in shaders])
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
