#!/usr/bin/env python3
"""libretro/glsl-shaders: every .glsl file holding both stages behind `#if defined(VERTEX)` /
`#elif defined(FRAGMENT)` is one program (a preset pass), compiled twice the way RetroArch's
gfx/drivers_shader/shader_glsl.c gl_glsl_compile_shader does on a desktop compatibility
context: when the file holds `#version` (strstr, anywhere), the stage text is
"#version N\\n" + define + the file from just after the version number (text before the
directive is dropped); without one, define + the file (GLSL 1.10). define is
"#define VERTEX\\n#define PARAMETER_UNIFORM\\n" or "#define FRAGMENT\\n#define PARAMETER_UNIFORM\\n";
no pass alias (alias_define empty). Written as x.vert / x.frag; capped at 800 programs.
Usage: gather_libretro_glsl.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, cap_sample, write_program  # noqa: E402


def stage_text(src, define):
    m = re.search(r"#version", src)
    if not m:
        return define + src
    n = re.match(r"\s*(\d*)", src[m.end():])
    return f"#version {int(n.group(1) or 0)}\n" + define + src[m.end() + n.end():]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    paths = []
    for p in m.files:
        if not p.endswith(".glsl"):
            continue
        t = m.text(p)
        if re.search(r"defined\s*\(\s*VERTEX\s*\)|#ifdef\s+VERTEX\b", t) and re.search(r"\bFRAGMENT\b", t):
            paths.append(p)
    picked = cap_sample(paths)
    for p in picked:
        src = m.text(p)
        stem = os.path.basename(p)[:-5]
        write_program(out, "libretro_glsl", p[:-5].replace("/shaders/", "/").replace("/", "_"), [
            ("vertex", stem, stage_text(src, "#define VERTEX\n#define PARAMETER_UNIFORM\n")),
            ("fragment", stem, stage_text(src, "#define FRAGMENT\n#define PARAMETER_UNIFORM\n"))])
    print(len(picked), "programs of", len(paths), "two-stage .glsl files")


main()
