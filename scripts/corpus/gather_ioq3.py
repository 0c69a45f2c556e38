#!/usr/bin/env python3
"""ioquake/ioq3 renderergl2: every GPU program GLSL_InitGPUShaders (code/renderergl2/tr_glsl.c)
builds on a desktop GL context with GLSL >= 1.50 and the default cvars (r_externalGLSL 0, so the
built-in copies of code/renderergl2/glsl/<name>_vp.glsl / _fp.glsl; r_normalMapping 1,
r_specularMapping 1, r_deluxeMapping 1, r_parallaxMapping 0, r_cubeMapping 0, r_deluxeSpecular
0.3, r_glossType 1, r_pbr 0, r_dlightMode 0, r_sunlightMode 1, r_shadowFilter 1,
r_shadowMapSize 1024, r_shadowCascadeZFar 1024; GPU vertex animation on, glslMaxAnimatedBones
IQM_MAX_JOINTS = 128, no normal-map swizzle, 640x480 video mode).

Stage text as GLSL_InitGPUShader builds it: GLSL_GetShaderHeader (`#version 150`, the `extra`
defines, the 1.20 -> 1.50 attribute/varying/gl_FragColor/texture2D macros, M_PI, the
deformGen/tcGen/colorGen/alphaGen enum values read from tr_local.h, r_FBufScale, `#line 0`)
followed by the file text. Permutation loops (generic, fogpass, dlight, lightall, shadowfill,
calclevels4x, depthBlur) with the same skip rules; greyscale inherits shadowmask's defines as in
the C code. Usage: gather_ioq3.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

BONES = 128
VID_W, VID_H = 640, 480
CV = dict(normalMapping=1, specularMapping=1, deluxeMapping=1, parallaxMapping=0, cubeMapping=0,
          deluxeSpecular=0.3, glossType=1, pbr=0, dlightMode=0, sunlightMode=1, shadowFilter=1,
          shadowMapSize=1024.0, shadowCascadeZFar=1024.0)


def c_enums(src):
    """name -> value for every enumerator of the `enum { ... }` blocks of a C header."""
    vals = {}
    for body in re.findall(r"\benum\s*\w*\s*\{(.*?)\}", src, re.S):
        body = re.sub(r"//[^\n]*|/\*.*?\*/", "", body, flags=re.S)
        nxt = 0
        for item in body.split(","):
            item = item.strip()
            if not item:
                continue
            m = re.match(r"(\w+)\s*(?:=\s*(.+))?$", item, re.S)
            if not m:
                continue
            if m.group(2):
                expr = re.sub(r"\b[A-Za-z_]\w*\b", lambda t: str(vals.get(t.group(0), 0)), m.group(2))
                try:
                    nxt = int(eval(expr, {"__builtins__": {}}))
                except Exception:  # not a plain integer expression
                    continue
            vals[m.group(1)] = nxt
            nxt += 1
    return vals


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    E = c_enums(m.text("code/renderergl2/tr_local.h"))

    def header(vertex, extra):
        s = "#version 150\n" + extra
        if vertex:
            s += "#define attribute in\n#define varying out\n"
        else:
            s += ("#define varying in\nout vec4 out_Color;\n#define gl_FragColor out_Color\n"
                  "#define texture2D texture\n#define textureCubeLod textureLod\n#define shadow2D texture\n")
        s += "#ifndef M_PI\n#define M_PI 3.14159265358979323846\n#endif\n"
        s += ("#ifndef deformGen_t\n#define deformGen_t\n" + "".join(
            f"#define {k} {E[k]}\n" for k in ("DGEN_WAVE_SIN", "DGEN_WAVE_SQUARE", "DGEN_WAVE_TRIANGLE", "DGEN_WAVE_SAWTOOTH",
                                              "DGEN_WAVE_INVERSE_SAWTOOTH", "DGEN_BULGE", "DGEN_MOVE")) + "#endif\n")
        s += ("#ifndef tcGen_t\n#define tcGen_t\n" + "".join(
            f"#define {k} {E[k]}\n" for k in ("TCGEN_LIGHTMAP", "TCGEN_TEXTURE", "TCGEN_ENVIRONMENT_MAPPED", "TCGEN_FOG",
                                              "TCGEN_VECTOR")) + "#endif\n")
        s += f"#ifndef colorGen_t\n#define colorGen_t\n#define CGEN_LIGHTING_DIFFUSE {E['CGEN_LIGHTING_DIFFUSE']}\n#endif\n"
        s += (f"#ifndef alphaGen_t\n#define alphaGen_t\n#define AGEN_LIGHTING_SPECULAR {E['AGEN_LIGHTING_SPECULAR']}\n"
              f"#define AGEN_PORTAL {E['AGEN_PORTAL']}\n#endif\n")
        s += f"#ifndef r_FBufScale\n#define r_FBufScale vec2({1.0 / VID_W:f}, {1.0 / VID_H:f})\n#endif\n"
        if CV["pbr"]:
            s += "#define USE_PBR\n"
        return s + "#line 0\n"

    n = 0

    def program(name, file, extra, tag=""):
        nonlocal n
        stages = []
        for st, suf in (("vertex", "vp"), ("fragment", "fp")):
            text = m.text(f"code/renderergl2/glsl/{file}_{suf}.glsl")
            stages.append((st, f"{file}_{suf}", header(st == "vertex", extra) + text))
        write_program(out, "ioq3", name + (f".{tag}" if tag else ""), stages)
        n += 1

    bones = f"#define USE_BONE_ANIMATION\n#define MAX_GLSL_BONES {BONES}\n"
    for i in range(E["GENERICDEF_COUNT"]):
        if i & E["GENERICDEF_USE_VERTEX_ANIMATION"] and i & E["GENERICDEF_USE_BONE_ANIMATION"]:
            continue
        x = ""
        if i & E["GENERICDEF_USE_DEFORM_VERTEXES"]:
            x += "#define USE_DEFORM_VERTEXES\n"
        if i & E["GENERICDEF_USE_TCGEN_AND_TCMOD"]:
            x += "#define USE_TCGEN\n#define USE_TCMOD\n"
        if i & E["GENERICDEF_USE_VERTEX_ANIMATION"]:
            x += "#define USE_VERTEX_ANIMATION\n"
        elif i & E["GENERICDEF_USE_BONE_ANIMATION"]:
            x += bones
        if i & E["GENERICDEF_USE_FOG"]:
            x += "#define USE_FOG\n"
        if i & E["GENERICDEF_USE_RGBAGEN"]:
            x += "#define USE_RGBAGEN\n"
        program("generic", "generic", x, f"{i:02d}")
        last = x
    program("texturecolor", "texturecolor", last)  # extradefines left over from the loop
    for i in range(E["FOGDEF_COUNT"]):
        if i & E["FOGDEF_USE_VERTEX_ANIMATION"] and i & E["FOGDEF_USE_BONE_ANIMATION"]:
            continue
        x = "#define USE_DEFORM_VERTEXES\n" if i & E["FOGDEF_USE_DEFORM_VERTEXES"] else ""
        if i & E["FOGDEF_USE_VERTEX_ANIMATION"]:
            x += "#define USE_VERTEX_ANIMATION\n"
        elif i & E["FOGDEF_USE_BONE_ANIMATION"]:
            x += bones
        program("fogpass", "fogpass", x, str(i))
    for i in range(E["DLIGHTDEF_COUNT"]):
        program("dlight", "dlight", "#define USE_DEFORM_VERTEXES\n" if i & E["DLIGHTDEF_USE_DEFORM_VERTEXES"] else "", str(i))
    fast = not (CV["normalMapping"] or CV["specularMapping"])
    for i in range(E["LIGHTDEF_COUNT"]):
        lt = i & E["LIGHTDEF_LIGHTTYPE_MASK"]
        if i & E["LIGHTDEF_USE_PARALLAXMAP"] and not CV["parallaxMapping"]:
            continue
        if i & E["LIGHTDEF_USE_SHADOWMAP"] and (not lt or not CV["sunlightMode"]):
            continue
        if i & E["LIGHTDEF_ENTITY_VERTEX_ANIMATION"] and i & E["LIGHTDEF_ENTITY_BONE_ANIMATION"]:
            continue
        x = "#define USE_SHADOWMAP\n" if CV["dlightMode"] >= 2 else ""
        if lt:
            x += "#define USE_LIGHT\n" + ("#define USE_FAST_LIGHT\n" if fast else "")
            if lt == E["LIGHTDEF_USE_LIGHTMAP"]:
                x += "#define USE_LIGHTMAP\n" + ("#define USE_DELUXEMAP\n" if CV["deluxeMapping"] and not fast else "")
            elif lt == E["LIGHTDEF_USE_LIGHT_VECTOR"]:
                x += "#define USE_LIGHT_VECTOR\n"
            elif lt == E["LIGHTDEF_USE_LIGHT_VERTEX"]:
                x += "#define USE_LIGHT_VERTEX\n"
            if CV["normalMapping"]:
                x += "#define USE_NORMALMAP\n"
            if CV["specularMapping"]:
                x += "#define USE_SPECULARMAP\n"
            if CV["cubeMapping"]:
                x += "#define USE_CUBEMAP\n"
            elif CV["deluxeSpecular"] > 0.000001:
                x += f"#define r_deluxeSpecular {CV['deluxeSpecular']:f}\n"
            x += {0: "#define GLOSS_IS_GLOSS\n", 1: "#define GLOSS_IS_SMOOTHNESS\n", 2: "#define GLOSS_IS_ROUGHNESS\n",
                  3: "#define GLOSS_IS_SHININESS\n"}.get(CV["glossType"], "#define GLOSS_IS_GLOSS\n")
        if i & E["LIGHTDEF_USE_SHADOWMAP"]:
            x += "#define USE_SHADOWMAP\n"
            x += {1: "#define SHADOWMAP_MODULATE\n", 2: "#define USE_PRIMARY_LIGHT\n"}.get(CV["sunlightMode"], "")
        if i & E["LIGHTDEF_USE_TCGEN_AND_TCMOD"]:
            x += "#define USE_TCGEN\n#define USE_TCMOD\n"
        if i & E["LIGHTDEF_ENTITY_VERTEX_ANIMATION"]:
            x += "#define USE_MODELMATRIX\n#define USE_VERTEX_ANIMATION\n"
        elif i & E["LIGHTDEF_ENTITY_BONE_ANIMATION"]:
            x += "#define USE_MODELMATRIX\n" + bones
        program("lightall", "lightall", x, f"{i:03d}")
    for i in range(E["SHADOWMAPDEF_COUNT"]):
        if i & E["SHADOWMAPDEF_USE_VERTEX_ANIMATION"] and i & E["SHADOWMAPDEF_USE_BONE_ANIMATION"]:
            continue
        x = "#define USE_VERTEX_ANIMATION\n" if i & E["SHADOWMAPDEF_USE_VERTEX_ANIMATION"] else ""
        if i & E["SHADOWMAPDEF_USE_BONE_ANIMATION"]:
            x += bones
        program("shadowfill", "shadowfill", x, str(i))
    program("pshadow", "pshadow", "#define USE_PCF\n#define USE_DISCARD\n")
    for name in ("down4x", "bokeh", "tonemap"):
        program(name, name, "")
    for i in range(2):
        program("calclevels4x", "calclevels4x", "" if i else "#define FIRST_PASS\n", str(i))
    x = "#define USE_SHADOW_FILTER\n" if CV["shadowFilter"] >= 1 else ""
    x += "#define USE_SHADOW_FILTER2\n" if CV["shadowFilter"] >= 2 else ""
    x += "#define USE_SHADOW_CASCADE\n" if CV["shadowCascadeZFar"] != 0 else ""
    x += f"#define r_shadowMapSize {CV['shadowMapSize']:f}\n#define r_shadowCascadeZFar {CV['shadowCascadeZFar']:f}\n"
    program("shadowmask", "shadowmask", x)
    program("greyscale", "greyscale", x)  # the C code reuses shadowmask's extradefines
    program("ssao", "ssao", "")
    for i in range(4):
        x = "#define USE_VERTICAL_BLUR\n" if i & 1 else "#define USE_HORIZONTAL_BLUR\n"
        x += "" if i & 2 else "#define USE_DEPTH\n"
        program("depthBlur", "depthblur", x, str(i))
    print(n, "programs")


main()
