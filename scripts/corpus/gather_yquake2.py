#!/usr/bin/env python3
"""yquake2/yquake2 GL3 renderer: every program createShaders() (src/client/refresh/gl3/gl3_shaders.c)
builds on a desktop GL context (YQ2_GL3_GLES3 undefined).

The shader sources are `static const char* name = MULTILINE_STRING( ... );` with
`#define MULTILINE_STRING(...) #__VA_ARGS__`, so each is the C preprocessor's stringification of
its tokens: comments removed, every run of white space (newlines included) one space, none at
either end. CompileShader(type, src, src2) hands glShaderSource the strings
{ "#version 150\\n", src[, src2] } (no separator between them). initShader2D(&gl3state.X, vs, fs)
compiles vs and fs alone; initShader3D(&gl3state.X, vs, fs) compiles vertexCommon3D + vs and
fragmentCommon3D + fs. One program per initShader2D/initShader3D call, named after the gl3state
field; the call arguments that are local variables chosen by a cvar (`lightmappedFrag` by
gl3_colorlight, `particleFrag` by gl3_particle_square) give the program for the cvar's default
(read from gl3_main.c's Cvar_Get) and a second `<field>.<cvar><value>` program for the other choice.
The gl1/soft renderers have no GLSL; there is no gl4 renderer in this repository.
Usage: gather_yquake2.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

SRC = "src/client/refresh/gl3/gl3_shaders.c"
MAIN = "src/client/refresh/gl3/gl3_main.c"
VERSION = "#version 150\n"


def stringify(tokens):
    """#__VA_ARGS__ of comment-free text: white space runs become one space, ends trimmed."""
    return re.sub(r"\s+", " ", tokens).strip()


def multiline_strings(src):
    """name -> stringified text of every `name = MULTILINE_STRING( ... )`."""
    out = {}
    for m in re.finditer(r"(\w+)\s*=\s*MULTILINE_STRING\s*\(", src):
        depth, i = 1, m.end()
        while depth:
            depth += {"(": 1, ")": -1}.get(src[i], 0)
            i += 1
        out[m.group(1)] = stringify(src[m.end():i - 1])
    return out


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    src = strip_cpp_comments(m.text(SRC))
    strings = multiline_strings(src)
    cvars = {k: float(v) for k, v in re.findall(r'Cvar_Get\(\s*"(\w+)"\s*,\s*"([^"]*)"', m.text(MAIN))
             if re.fullmatch(r"-?[0-9.]+", v)}
    body = src[src.index("createShaders(void)"):]
    body = body[:body.index("\nqboolean GL3_InitShaders")] if "\nqboolean GL3_InitShaders" in body else body
    # cvar-selected locals: name -> [(choice, label or None for the default)]
    choices = {}
    for v, cv, zero, nonzero in re.findall(
            r"const\s+char\s*\*\s*(\w+)\s*=\s*\(\s*(\w+)->value\s*==\s*0\.0f\s*\)\s*\?\s*(\w+)\s*:\s*(\w+)\s*;", body):
        dflt = cvars.get(cv, 0.0) == 0.0
        choices[v] = [(zero if dflt else nonzero, None), (nonzero if dflt else zero, f"{cv}{0 if not dflt else 1}")]
    for v, first, cv, other in re.findall(
            r"const\s+char\s*\*\s*(\w+)\s*=\s*(\w+)\s*;\s*if\s*\(\s*(\w+)->value\s*!=\s*0\.0f\s*\)\s*\{\s*\1\s*=\s*(\w+)\s*;", body):
        dflt = cvars.get(cv, 0.0) != 0.0
        choices[v] = [(other if dflt else first, None), (first if dflt else other, f"{cv}{0 if dflt else 1}")]
    n = 0
    for kind, field, vs, fs in re.findall(
            r"initShader(2D|3D)\(\s*&\s*gl3state\.(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*\)", body):
        for vsrc, vtag in choices.get(vs, [(vs, None)]):
            for fsrc, ftag in choices.get(fs, [(fs, None)]):
                if vtag and ftag:
                    continue
                if kind == "2D":
                    vtext, ftext = VERSION + strings[vsrc], VERSION + strings[fsrc]
                else:
                    vtext = VERSION + strings["vertexCommon3D"] + strings[vsrc]
                    ftext = VERSION + strings["fragmentCommon3D"] + strings[fsrc]
                tag = vtag or ftag
                write_program(out, "yquake2", field + (f".{tag}" if tag else ""),
                              [("vertex", vsrc, vtext), ("fragment", fsrc, ftext)])
                n += 1
    print(n, "programs")


main()
