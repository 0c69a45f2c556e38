#!/usr/bin/env python3
"""Pairs capnramses/antons_opengl_tutorials_book programs the way the chapters load them.

Each chapter's main.c/main.cpp is followed with mirror.GLTrace: glShaderSource from inline
strings or from buffers filled by parse_file_into_str("x.glsl", buf, n) (gl_utils.cpp: fgets
lines concatenated, i.e. the file verbatim), glAttachShader + glLinkProgram. Besides,
create_programme_from_files(VS, FS) and 41's create_shader_program_from_files(VS, FS) (file
names as literals or #define'd) read both files verbatim. Paths are relative to the chapter.
Programs with tessellation/compute stages are left out.
Usage: gather_antons.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, GLTrace, cpp_ifdefs, graphics_program, strip_cpp_comments, write_program

FROM_FILES = re.compile(r"(\w+)\s*=\s*create_(?:programme|shader_program)_from_files\(\s*(\"[^\"]*\"|\w+)\s*,\s*(\"[^\"]*\"|\w+)\s*\)")


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written = 0
    for f in m.files:
        if not re.match(r"\d\d_[^/]+/main\.(c|cpp)$", f):
            continue
        chapter = f.split("/")[0]
        src = cpp_ifdefs(strip_cpp_comments(m.text(f)))
        defines = dict(re.findall(r'#define\s+(\w+)\s+"([^"]*)"', src))
        read = lambda name: m.text(os.path.normpath(os.path.join(chapter, name)))
        progs = []
        for c in FROM_FILES.finditer(src):
            vs, fs = (defines.get(a, a.strip('"')) for a in c.group(2, 3))
            progs.append((c.group(1), [("vertex", vs.split(".")[0], read(vs)), ("fragment", fs.split(".")[0], read(fs))]))
        trace = GLTrace(src, sources=[(r'parse_file_into_str\(\s*"(?P<path>[^"]+)"\s*,\s*(?P<var>\w+)',
                                       lambda s: read(s.group("path")))])
        for prog, shaders in trace.run():
            progs.append((prog, [(st, st[:4], t) for st, t in shaders] if all(shaders) else [None]))
        seen = []
        for prog, shaders in progs:
            if None in shaders or not graphics_program([(st, t) for st, _, t in shaders]) or shaders in seen:
                continue
            seen.append(shaders)
            write_program(out, "antons", f"{chapter}.{prog}", shaders)
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
