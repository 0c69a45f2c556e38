#!/usr/bin/env python3
"""OpenRCT2/OpenRCT2 OpenGL drawing engine (src/openrct2-ui/drawing/engines/opengl): one program per
`OpenGLShaderProgram("<name>")` base-class initializer of the *Shader.cpp classes
(ApplyPaletteShader, ApplyTransparencyShader, CopyRectShader, DrawLineShader, DrawRectShader).

OpenGLShaderProgram(name) (OpenGLShaderProgram.cpp) builds an OpenGLShader for GL_VERTEX_SHADER and
one for GL_FRAGMENT_SHADER; OpenGLShader::GetPath is the shaders directory (data/shaders in the
source tree) + name + ".vert" / ".frag", and ReadSourceCode reads the whole file into a
NUL-terminated std::string passed as one string to glShaderSource (length nullptr): the file
verbatim, nothing prepended (the files carry their own #version).
Usage: gather_openrct2.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, strip_cpp_comments, write_program  # noqa: E402

ENGINE = "src/openrct2-ui/drawing/engines/opengl/"
SHADERS = "data/shaders/"


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    n = 0
    for p in m.files:
        if not (p.startswith(ENGINE) and p.endswith(".cpp")):
            continue
        src = strip_cpp_comments(m.text(p))
        for c in re.finditer(r":\s*OpenGLShaderProgram\(\s*(\"[^\"]*\")\s*\)", src):
            name = c_string(c.group(1))
            stages = []
            for stage, ext in (("vertex", "vert"), ("fragment", "frag")):
                data = m.show(SHADERS + name + "." + ext)
                if data is None:
                    raise SystemExit(f"missing {SHADERS}{name}.{ext}")
                stages.append((stage, name, data.split(b"\0")[0]))
            write_program(out, "openrct2", name, stages)
            n += 1
    print(n, "programs")


main()
