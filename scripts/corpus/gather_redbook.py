#!/usr/bin/env python3
"""openglredbook/examples (OpenGL Programming Guide, 9th edition): programs as src/*/*.cpp build them.

- `ShaderInfo arr[] = { { GL_X_SHADER, "media/shaders/a/b.vert" }, ..., { GL_NONE, NULL } };`
  then `LoadShaders(arr)` (lib/LoadShaders.cpp: each file read verbatim, relative to bin/,
  all attached, then glLinkProgram): one program per array.
- `vglAttachShaderSource(prog, GL_X_SHADER, var)` with `static const char var[] = "..."`
  literals: the attached sources up to `glLinkProgram(prog)` form one program.
All stages kept (tessellation and compute too); identical programs written once.
Usage: gather_redbook.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import C_LITERAL, Mirror, STAGE_NAMES, c_string, c_string_vars, strip_cpp_comments, write_program  # noqa: E402

STEM = {"vertex": "vs", "fragment": "fs", "geometry": "gs", "tess-control": "tcs",
        "tess-eval": "tes", "compute": "cs"}


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, set()
    for f in m.files:
        if not (f.startswith("src/") and f.endswith(".cpp")):
            continue
        src = strip_cpp_comments(m.text(f))
        strings = c_string_vars(src)
        for v in re.finditer(rf"(\w+)\s*\[\s*\]\s*=\s*((?:{C_LITERAL}|\s)+);", src):  # char x[] = "..." "...";
            strings[v.group(1)] = [c_string(v.group(2))]
        sample = f.split("/")[1]
        programs = []
        for a in re.finditer(r"ShaderInfo\s+(\w+)\s*\[\s*\]\s*=\s*\{(.*?)\}\s*;", src, re.S):
            stages = []
            for e in re.finditer(r'\{\s*GL_(\w+?)_SHADER\s*,\s*"([^"]+)"\s*\}', a.group(2)):
                text = m.text("bin/" + e.group(2))
                stages.append((STAGE_NAMES.get(e.group(1)), os.path.basename(e.group(2)), text))
            programs.append((a.group(1), stages))
        attached = {}
        for c in re.finditer(r"vglAttachShaderSource\(\s*(\w+)\s*,\s*GL_(\w+?)_SHADER\s*,\s*(\w+)\s*\)"
                             r"|glLinkProgram\(\s*(\w+)\s*\)", src):
            if c.group(1):
                text = (strings.get(c.group(3)) or [None])[0]
                attached.setdefault(c.group(1), []).append((STAGE_NAMES.get(c.group(2)), None, text))
            elif c.group(4) in attached:
                programs.append((c.group(4), attached.pop(c.group(4))))
        for name, stages in programs:
            if not stages or any(s is None or t is None for s, _, t in stages):
                continue
            key = tuple((s, t) for s, _, t in stages)
            if key in seen:
                continue
            seen.add(key)
            files, count = [], {}
            for s, stem, t in stages:
                count[s] = count.get(s, 0) + 1
                stem = STEM[s] + ("" if count[s] == 1 else str(count[s]))
                files.append((s, stem, t))
            write_program(out, "redbook", f"{sample}.{name}", files)
            written += 1
    print(written, "programs")


main()
