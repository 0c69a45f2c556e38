#!/usr/bin/env python3
"""supertuxkart/stk-code: programs from `loadProgram(KIND, GL_VERTEX_SHADER, "a.vert",
[GL_GEOMETRY_SHADER, "b.geom",] GL_FRAGMENT_SHADER, "c.frag")` calls in src/ and from the
data/shaders/sps_*.xml SP shaders (first-pass and shadow-pass; also the skinned-mesh vertex
shader with the same fragment shader).

Stage text as ShaderFilesManager::loadShader builds it, assuming a desktop GL 3.3 core
context with the usual extensions (GLSL 330, explicit attrib location and UBOs usable,
skinning through a TBO, deferred lighting on): `#version 330`, `#extension
GL_ARB_explicit_attrib_location : enable`, `#define Explicit_Attrib_Location_Usable`,
a `//path` comment, `#define Advanced_Lighting_Enabled`, `precision highp float;` (fragment),
`#define MAX_BONES 1024`, then header.txt and the file, each line preceded by "\\n",
`#stk_include "x"` lines replaced by data/shaders/x the same way.
Usage: gather_stk.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
import xml.etree.ElementTree as ET
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
SH = "data/shaders/"


def getlines(text):
    lines = text.split("\n")
    return lines[:-1] if lines[-1] == "" else lines  # std::getline yields no empty last line


def read_file(name):
    text = m.text(SH + name)
    if text is None:
        raise KeyError(name)
    code = []
    for line in getlines(text):
        if "#stk_include" in line:
            code.append(read_file(line.split('"')[1]))
        else:
            code.append("\n" + line)
    return "".join(code)


def stage_text(name, stage):
    code = "#version 330\n#extension GL_ARB_explicit_attrib_location : enable\n#define Explicit_Attrib_Location_Usable\n"
    code += f"//{SH}{name}\n#define Advanced_Lighting_Enabled\n"
    if stage == "fragment":
        code += "precision highp float;\n"
    code += "#define MAX_BONES 1024\n"
    return code + "".join("\n" + l for l in getlines(m.text(SH + "header.txt"))) + read_file(name)


programs = []
call = re.compile(r'loadProgram\(\s*\w+\s*,((?:\s*GL_\w+_SHADER\s*,\s*"[^"]+"\s*,?)+)\)')
for f in m.files:
    if f.startswith("src/") and f.endswith(".cpp"):
        for args in call.findall(m.text(f)):
            st = re.findall(r'GL_(\w+)_SHADER\s*,\s*"([^"]+)"', args)
            kinds = [k for k, _ in st]
            if "VERTEX" in kinds and "FRAGMENT" in kinds and set(kinds) <= {"VERTEX", "GEOMETRY", "FRAGMENT"}:
                programs.append([(k.lower(), n) for k, n in st])
    elif re.match(r'data/shaders/sps_.*\.xml$', f):
        root = ET.fromstring(m.text(f))
        for p in list(root.iter("first-pass")) + list(root.iter("shadow-pass")):
            vs, fs = p.get("vertex-shader"), p.get("fragment-shader")
            if vs and fs:
                programs.append([("vertex", vs), ("fragment", fs)])
                if p.get("skinned-mesh-shader"):
                    programs.append([("vertex", p.get("skinned-mesh-shader")), ("fragment", fs)])

n, seen = 0, set()
for prog in programs:
    key = tuple(prog)
    if key in seen:
        continue
    seen.add(key)
    try:
        stages = [(st, name.rsplit(".", 1)[0], stage_text(name, st)) for st, name in prog]
    except KeyError:
        continue
    write_program(out, "stk", "_".join(s[1] for s in stages), stages)
    n += 1
print(n, "programs")
