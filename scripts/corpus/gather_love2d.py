#!/usr/bin/env python3
"""love2d/love (LÖVE 12): GLSL programs as src/modules/graphics/Shader.cpp builds them for a desktop
GL context: createShaderStageCode = the language's version line (glsl3 "#version 330 core",
glsl4 "#version 430 core"; `#pragma language glsl4` selects it), `#define LOVE_MULTI_RENDER_TARGETS 1`
when a custom effect() uses love_RenderTargets/love_Canvases, `#define VERTEX VERTEX` /
`#define PIXEL PIXEL`, global_syntax, the stage header, uniforms, global and stage functions,
the stage main (high-level position()/effect(), custom `void effect()`, raw
vertexmain/pixelmain), "#line 1\\n", then the user code. Programs: the standard shaders
(default, video, array, points: getDefaultCode) and every love.graphics.newShader(...) of
testing/tests/*.lua not wrapped in pcall (Graphics::newShader: each source gives the stages
whose entry point it holds, missing stages get the default code).
Usage: gather_love2d.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string_vars, strip_cpp_comments, write_program  # noqa: E402

VERSIONS = {"glsl3": "#version 330 core", "glsl4": "#version 430 core"}


def blank_comments(src):
    return re.sub(r"//[^\n]*|/\*.*?\*/", lambda m: re.sub(r"[^\n]", " ", m.group(0)), src, flags=re.S)


def entry(src, stage):
    s = blank_comments(src)
    if stage == "vertex":
        if re.search(r"void\s+vertexmain\s*\(", s):
            return "raw"
        return "main" if re.search(r"vec4\s+position\s*\(", s) else None
    if re.search(r"void\s+pixelmain\s*\(", s):
        return "raw"
    if re.search(r"vec4\s+effect\s*\(", s):
        return "main"
    return "custom" if re.search(r"void\s+effect\s*\(", s) else None


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    raw = strip_cpp_comments(m.text("src/modules/graphics/Shader.cpp"))
    lits = {k: v[0] for k, v in c_string_vars(raw).items() if v}
    for name, val in re.findall(r'static const (?:char|std::string) (\w+)(?:\[\])?\s*=\s*R"\((.*?)\)"', raw, re.S):
        lits[name] = val
    info = {"vertex": ("VERTEX", "vertex_header", "render_uniforms", "vertex_functions", "vertex_main", "vertex_main", "vertex_main_raw"),
            "fragment": ("PIXEL", "pixel_header", "render_uniforms", "pixel_functions", "pixel_main", "pixel_main_custom", "pixel_main_raw")}

    def stage_code(stage, code):
        lang = re.search(r"^\s*#pragma language (\w+)", code, re.M)
        lang = lang.group(1) if lang else "glsl3"
        kind = entry(code, "vertex" if stage == "vertex" else "pixel")
        name, header, uniforms, functions, main_hl, main_custom, main_raw = info[stage]
        s = VERSIONS.get(lang, VERSIONS["glsl3"]) + "\n"
        if kind == "custom" and re.search(r"love_RenderTargets|love_Canvases", blank_comments(code)):
            s += "#define LOVE_MULTI_RENDER_TARGETS 1\n"
        s += f"#define {name} {name}\n" + lits["global_syntax"] + lits[header] + lits[uniforms]
        s += lits["global_functions"] + lits[functions]
        s += lits[{"main": main_hl, "custom": main_custom, "raw": main_raw}[kind]] + "#line 1\n" + code
        return s

    def program(sources):
        stages = {}
        for code in sources:
            for st, key in (("vertex", "vertex"), ("fragment", "pixel")):
                if entry(code, key):
                    stages[st] = code
        if not stages:
            return None
        stages.setdefault("vertex", lits["defaultVertex"])
        stages.setdefault("fragment", lits["defaultStandardPixel"])
        return [(st, "shader", stage_code(st, c)) for st, c in (("vertex", stages["vertex"]), ("fragment", stages["fragment"]))]

    written = 0
    for std, v, p in (("default", "defaultVertex", "defaultStandardPixel"), ("video", "defaultVertex", "defaultVideoPixel"),
                      ("array", "defaultVertex", "defaultArrayPixel"), ("points", "defaultPointsVertex", "defaultStandardPixel")):
        write_program(out, "love2d", f"standard.{std}", program([lits[v], lits[p]]))
        written += 1
    longstr = r"\[(?P<eq>=*)\[(?P<body>.*?)\](?P=eq)\]"
    for f in m.files:
        if not (f.startswith("testing/tests/") and f.endswith(".lua")):
            continue
        lua = m.text(f)
        binds = {b.group(1): b.group("body") for b in re.finditer(rf"local\s+(\w+)\s*=\s*{longstr}", lua, re.S)}
        k = 0
        for c in re.finditer(rf"(pcall\(\s*)?love\.graphics\.newShader\s*(?:{longstr}|\((?P<args>[^)]*)\))", lua, re.S):
            if c.group(1):
                continue
            if c.group("body") is not None:
                sources = [c.group("body")]
            else:
                args = [a.strip() for a in c.group("args").split(",")]
                sources = [binds[a] for a in args if a in binds]
            prog = program(sources)
            if prog:
                k += 1
                write_program(out, "love2d", f"{os.path.basename(f)[:-4]}.{k}", prog)
                written += 1
    print(written, "programs")


main()
