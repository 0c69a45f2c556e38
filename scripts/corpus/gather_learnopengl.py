#!/usr/bin/env python3
"""Pairs JoeyDeVries/LearnOpenGL programs the way the chapters load them.

`Shader name("a.vs", "a.fs"[, "a.gs"[, tcs, tes]])` (includes/learnopengl/shader*.h) and
`ResourceManager::LoadShader("a.vs", "a.fs", nullptr|"a.gs", name)` read the files verbatim;
paths are relative to the chapter's directory (FileSystem::getPath("x") to the repository).
The first chapters build programs from inline strings with glShaderSource/glAttachShader,
followed with mirror.GLTrace. Programs with tessellation stages are left out.
Usage: gather_learnopengl.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, GLTrace, graphics_program, strip_cpp_comments, write_program

ONE = r'(?:"[^"]*"|FileSystem::getPath\(\s*"[^"]*"\s*\)(?:\.c_str\(\))?|nullptr|NULL|0)'
ARG = rf"\s*{ONE}\s*"
CALL = re.compile(rf"\bShader\s+(\w+)\s*\(({ARG}(?:,{ARG}){{1,4}})\)"
                  rf"|ResourceManager::LoadShader\(({ARG}(?:,{ARG}){{2}}),\s*\"([^\"]*)\"\s*\)")
STAGES = ["vertex", "fragment", "geometry", "tess-control", "tess-eval"]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written = 0
    for f in m.files:
        if not (f.startswith("src/") and f.endswith(".cpp")):
            continue
        src = strip_cpp_comments(m.text(f))
        progs = []
        for c in CALL.finditer(src):
            args = re.findall(ONE, c.group(2) or c.group(3))
            shaders = []
            for stage, a in zip(STAGES, args):
                lit = re.search(r'"([^"]*)"', a)
                if lit:
                    base = "" if a.startswith("FileSystem") else os.path.dirname(f)
                    path = os.path.normpath(os.path.join(base, lit.group(1)))
                    shaders.append((stage, m.text(path), os.path.basename(path)))
            progs.append((c.group(1) or c.group(4), shaders))
        for prog, shaders in GLTrace(src).run():
            progs.append((prog, [(s, t, s[:4]) for s, t in shaders] if all(shaders) else [None]))
        seen = []
        for prog, shaders in progs:
            if None in shaders or not graphics_program([(s, t) for s, t, _ in shaders]) or shaders in seen:
                continue
            seen.append(shaders)
            name = os.path.dirname(f)[4:].replace("/", "_") + "." + prog
            stems = [n if n in ("vert", "frag", "geom") else n.rsplit(".", 1)[0] for _, _, n in shaders]
            write_program(out, "learnopengl", name, [(s, stem, t) for (s, t, _), stem in zip(shaders, stems)])
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
