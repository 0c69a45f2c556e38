#!/usr/bin/env python3
"""RetroArch's own built-in GLSL programs (the stock and stock-blend programs the GL driver
draws the game frame and the menu with), from the neil4/RetroArch-Lite fork (master 2ec4443 of
2026-02-08, a trimmed RetroArch 1.x line); libretro/RetroArch itself is over the snapshot
limit, so its newer gfx/drivers/gl_shaders/ menu pipelines are not gathered.

gfx/drivers_shader/shader_glsl.c: compile_program(vertex, fragment) compiles each stage with
compile_shader(define, program), which gives glShaderSource four strings: the version line
(desktop: none unless the source has `#version`; a core context: `#version N` from the context
version, 3.0 -> 130, 3.1 -> 140, 3.2 -> 150, else major*100+minor*10), `#define VERTEX\\n#define
PARAMETER_UNIFORM\\n` or `#define FRAGMENT\\n...`, glsl_alias_define (empty: no preset passes),
the source. gl_glsl_init: stock program = stock_vertex/fragment_modern (no shader preset, the
default) or _legacy (a non-modern preset) or _core (core context); the blend program
(GL_SHADER_STOCK_BLEND) = _modern_blend or _core_blend when the shader is modern.
Programs: modern, modern_blend, legacy, core150 (GL 3.2 core), core150_blend, core330.
Usage: gather_retroarch_lite.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, c_string_vars, strip_cpp_comments, write_program  # noqa: E402

SRC = "gfx/drivers_shader/shader_glsl.c"


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    src = strip_cpp_comments(m.text(SRC))
    strings = c_string_vars(src)
    cp = re.search(r"static GLuint compile_program\(.*?\n\}", src, re.S).group(0)
    vdef, fdef = (c_string(x) for x in re.findall(r'(\"#define (?:VERTEX|FRAGMENT)[^;]*?\")\s*,', cp))
    assert "VERTEX" in vdef and "FRAGMENT" in fdef
    assert re.search(r"case 320:\s*version_no = 150;", src) and '"#version %u\\n"' in src
    programs = [("modern", "stock_vertex_modern", "stock_fragment_modern", ""),
                ("modern_blend", "stock_vertex_modern_blend", "stock_fragment_modern_blend", ""),
                ("legacy", "stock_vertex_legacy", "stock_fragment_legacy", ""),
                ("core150", "stock_vertex_core", "stock_fragment_core", "#version 150\n"),
                ("core150_blend", "stock_vertex_core_blend", "stock_fragment_core_blend", "#version 150\n"),
                ("core330", "stock_vertex_core", "stock_fragment_core", "#version 330\n")]
    for name, v, f, version in programs:
        write_program(out, "retroarch_lite", name, [
            ("vertex", v, version + vdef + strings[v][0]),
            ("fragment", f, version + fdef + strings[f][0])])
    print(len(programs), "programs")


main()
