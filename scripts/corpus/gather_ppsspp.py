#!/usr/bin/env python3
"""hrydgard/ppsspp post-processing shaders: one program per assets/shaders/defaultshaders.ini
section with `Fragment=` and `Vertex=` (the `Type=Texture` compute upscalers and the
`Type=StereoToMono` shaders, whose files say they are only compiled for Vulkan, are left out), text as the desktop OpenGL path without translation compiles them.

PresentationCommon::CompileShaderModule passes the GLSL 1.xx file text straight through when
the draw context's language is GLSL_1xx (desktop GL below 3.3, which has no core profile in
SDL's/Windows' non-core fallback); OpenGLShaderModule::Compile then applies
ApplyGLSLPrelude (Common/GPU/OpenGL/GLFeatures.cpp) to a source without `#version`: no
version line on a non-core desktop context, and the fragment stage gets
`#ifdef GL_ES / precision mediump float; / #endif` in front. (GL >= 3.3 contexts go through
glslang + SPIRV-Cross instead, whose generated text is not gathered.)
Usage: gather_ppsspp.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

FRAGMENT_PRELUDE = "#ifdef GL_ES\nprecision mediump float;\n#endif\n"


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    base = "assets/shaders/"
    sections, cur = [], None
    for line in m.text(base + "defaultshaders.ini").splitlines():
        line = line.strip()
        if line.startswith("[") and line.endswith("]"):
            cur = {"name": line[1:-1]}
            sections.append(cur)
        elif cur is not None and "=" in line and not line.startswith("#"):
            k, _, v = line.partition("=")
            cur[k.strip()] = v.strip()
    n = 0
    for s in sections:
        if "Fragment" not in s or "Vertex" not in s or s.get("Type", "Render") != "Render":
            continue
        vs, fs = m.text(base + s["Vertex"]), m.text(base + s["Fragment"])
        if vs is None or fs is None:
            continue
        stages = []
        for stage, f, text in (("vertex", s["Vertex"], vs), ("fragment", s["Fragment"], fs)):
            if "#version" not in text and stage == "fragment":
                text = FRAGMENT_PRELUDE + text
            stages.append((stage, os.path.splitext(f)[0], text))
        write_program(out, "ppsspp", re.sub(r"[()]", "", s["name"]), stages)
        n += 1
    print(n, "programs")


main()
