#!/usr/bin/env python3
"""TheCherno/Hazel (Vulkan GLSL): the Renderer2D shaders `Shader::Create("assets/shaders/X.glsl")`
(Hazel/src/Hazel/Renderer/Renderer2D.cpp, files from Hazelnut/assets/shaders/), split as
OpenGLShader::PreProcess does at each `#type vertex|fragment|pixel` line (the text after that line
up to the next `#type`), each stage compiled by shaderc for Vulkan 1.2 (FLAGS).
Usage: gather_hazel.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

TYPES = {"vertex": "vertex", "fragment": "fragment", "pixel": "fragment"}
m, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
for path in re.findall(r'Shader::Create\(\s*"([^"]+\.glsl)"\s*\)', strip_cpp_comments(m.text("Hazel/src/Hazel/Renderer/Renderer2D.cpp"))):
    src = m.text("Hazelnut/" + path)
    if src is None:
        continue
    stages, pos = {}, src.find("#type")
    while pos != -1:
        eol = min(i for i in (src.find("\r", pos), src.find("\n", pos)) if i != -1)
        kind = src[pos + 6:eol]
        nxt = eol
        while nxt < len(src) and src[nxt] in "\r\n":
            nxt += 1
        pos = src.find("#type", nxt)
        stages[TYPES[kind]] = src[nxt:] if pos == -1 else src[nxt:pos]
    name = os.path.basename(path)[:-5]
    d = write_program(out, "hazel", name, [(st, name, stages[st]) for st in ("vertex", "fragment") if st in stages])
    with open(os.path.join(d, "FLAGS"), "w") as fh:
        fh.write("-V --target-env vulkan1.2 -l\n")
    n += 1
print(n, "programs")
