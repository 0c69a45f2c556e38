#!/usr/bin/env python3
"""Pairs OpenGL SuperBible programs (openglsuperbible/sb6code or sb7code) as the samples do.

Each src/<sample>/*.cpp is followed in order with mirror.GLTrace: shaders come from inline
string arrays (glCreateShader + glShaderSource(sh, 1, vs_source, NULL)), sb6::shader::load /
sb7::shader::load("media/shaders/...", GL_X_SHADER) (the file verbatim, from bin/media; sb7code
does not ship its media pack, so those programs are left out) and sb7::shader::from_string;
programs are glAttachShader + glLinkProgram or sbN::program::link_from_shaders(shaders, n).
The source name (sb6/sb7) follows the repository. Usage: gather_superbible.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, GLTrace, STAGE_NAMES, graphics_program, strip_cpp_comments, write_program


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    book = "sb7" if m.exists("src/sb7/sb7shader.cpp") else "sb6"
    written = missing = 0
    for f in m.files:
        if not (f.startswith("src/") and f.endswith(".cpp")) or f.startswith(f"src/{book}/"):
            continue
        src = strip_cpp_comments(m.show(f).decode("latin-1"))  # byte-faithful
        trace = GLTrace(src)

        def load(mt):
            data = m.show("bin/" + mt.group("path"))
            return STAGE_NAMES.get(mt.group("st")), None if data is None else data.decode("latin-1")

        def from_string(mt):
            return STAGE_NAMES.get(mt.group("st")), trace.text(mt.group("var"), "1")

        trace.loaders = [
            (rf'{book}::shader::load\(\s*"(?P<path>[^"]+)"\s*,\s*GL_(?P<st>\w+?)_SHADER[^)]*\)', load),
            (rf"{book}::shader::from_string\(\s*(?P<var>\w+)\s*,\s*GL_(?P<st>\w+?)_SHADER[^)]*\)", from_string)]
        trace.linkers = [rf"(?P<dst>[\w.]+)\s*=\s*{book}::program::link_from_shaders\(\s*(?P<shaders>[&\w.]+)"
                         rf"\s*,\s*(?P<n>\d+)"]
        sample = f.split("/")[1]
        seen = []
        for prog, shaders in trace.run():
            if not graphics_program(shaders):
                missing += any(s and s[1] is None for s in shaders)
                continue
            if shaders in seen:
                continue
            seen.append(shaders)
            name = sample if f == f"src/{sample}/{sample}.cpp" else f[4:-4]
            stem = {"vertex": "vs", "fragment": "fs", "geometry": "gs"}
            write_program(out, book, f"{name}.{prog}", [(s, stem[s], t.encode("latin-1")) for s, t in shaders])
            written += 1
    print(written, "programs;", missing, "left out for lack of a shader file")


if __name__ == "__main__":
    main()
