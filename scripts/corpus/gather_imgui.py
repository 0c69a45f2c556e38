#!/usr/bin/env python3
"""ocornut/imgui: backends/imgui_impl_opengl3.cpp ImGui_ImplOpenGL3_CreateDeviceObjects, for each
GLSL version string ImGui_ImplOpenGL3_Init accepts (the table in the file's header comment, and
the `glsl_version = "#version N"` defaults and examples' literals): the string + "\\n" is
prepended to the vertex_shader_glsl_* / fragment_shader_glsl_* literal picked by its number
(< 130: _120, >= 410: _410_core, == 300: _300_es, else _130). One program per version string.
Usage: gather_imgui.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string_vars, strip_cpp_comments, write_program  # noqa: E402


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    raw = m.text("backends/imgui_impl_opengl3.cpp")
    versions = re.findall(r'^//\s+\S+(?: \S+)?\s+\d+\s+"(#version [^"]+)"', raw, re.M)
    versions += re.findall(r'glsl_version\s*=\s*"(#version [^"]+)"', raw)
    for f in m.files:
        if f.startswith("examples/") and f.endswith(".cpp"):
            versions += re.findall(r'glsl_version\s*=\s*"(#version [^"]+)"', m.text(f))
    strings = c_string_vars(strip_cpp_comments(raw))
    written = 0
    for v in dict.fromkeys(versions):
        n = int(re.match(r"#version (\d+)", v).group(1))
        suffix = "120" if n < 130 else "410_core" if n >= 410 else "300_es" if n == 300 else "130"
        vs, fs = strings.get(f"vertex_shader_glsl_{suffix}"), strings.get(f"fragment_shader_glsl_{suffix}")
        if not vs or not fs:
            continue
        write_program(out, "imgui", "opengl3_" + v[len("#version "):].replace(" ", "_"),
                      [("vertex", "vs", v + "\n" + vs[0]), ("fragment", "fs", v + "\n" + fs[0])])
        written += 1
    print(written, "programs")


main()
