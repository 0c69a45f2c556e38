#!/usr/bin/env python3
"""etlegacy/etlegacy renderer2 (the XreaL-derived OpenGL 3.3 renderer of ET: Legacy): the programs
GLSL_CompileGPUShaders (src/renderer2/tr_glsl.c) asks for, each in a sample of its macro permutations.

Text, as the engine builds it:
- The .glsl files are embedded at build time by src/renderer2/glsl/shdr/shaders2h.cpp
  (cmake/ETLBuildRenderer.cmake: `shdr2h LEGACY glsl gldef/default.gldef shaders.h`, binary
  mode): make_c_string strips comments (and the character after each `*/`), drops blank lines,
  squeezes blank runs (a blank before a `/` or `*` two characters on is dropped), and ends the
  text with a newline; GetFallbackShader(name) returns it (no glsl/ files are shipped) and
  GLSL_GetShaderText appends "\\n". `#include "lib/x"` is spliced by GLSL_PreprocessShaderText
  with lib/x_vp or lib/x_fp by stage (the character after the include's name, the newline, is
  skipped).
- A stage is GLSL_GetShaderHeader (`#version 330 core`, vertex `#define attribute in` /
  `#define varying out`, fragment `#define varying in`, `out vec4 out_Color[4];`,
  gl_FragColor / gl_FragData defines, then the texture2D/textureCube/texture2DProj defines),
  then `#ifndef M\\n#define M 1\\n#endif\\n` for each token of the macro string, then
  shaderExtraDef (GLSL_BuildShaderExtraDef, ending in `#line 0`) and the preprocessed file.
- Definitions (filename, fragfilename, macros, extramacros) from src/renderer2/gldef/default.gldef.
  The macro string of permutation p lists the definition's macros whose bit is set, in the
  order of tr_glsldef.h's MACRO_DEF list, then extramacros; permutations with vertex skinning
  and animation together, or with parallax/deluxe/reflections/specular but no normal mapping,
  are refused as GLSL_GenerateMacroString does.
- shaderExtraDef for the cvar defaults of tr_init.c (cg_shadows 1, so no shadow-map block;
  r_hdrRendering 0, r_normalMapping 0, r_precomputedLighting 1, r_diffuseLighting 0.35, ...),
  enum values from tr_local.h / tr_extra.h, a 1280x720 window (r_mode -2 falls back to
  r_customwidth/height), NPOT textures, GPU vertex skinning with MAX_BONES (Mesa's 4096 vertex
  uniform components give (4096 - 160) / 16 bones, bounded by MAX_BONES).

Programs: `<definition>` (permutation 0) and `<definition>.<macros>`; at most 6 permutations a
definition (permutation 0 and a deterministic sample of the others, mirror.cap_sample).
Usage: gather_etlegacy.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, cap_sample, strip_cpp_comments, write_program  # noqa: E402

R2 = "src/renderer2/"
GLSL_DIR = R2 + "glsl/"
PER_DEF = 6
WIDTH, HEIGHT = 1280, 720
MAX_VERTEX_UNIFORM_COMPONENTS = 4096


def make_c_string(s):
    """shaders2h.cpp make_c_string in binary (not plain-text) mode."""
    out, n, i = [], len(s), 0
    while i < n:
        c = s[i]
        c2 = s[i + 1] if i + 1 < n else ""
        if c == "/" and c2 == "/":
            i += 2
            while i < n and s[i] != "\n":
                i += 1
            if i < n:
                continue  # goto LOOP_HEAD at the newline
        elif c == "/" and c2 == "*":
            while i + 1 < n and not (s[i] == "*" and s[i + 1] == "/"):
                i += 1
            i += 2
        elif c == "\n":
            while i + 1 < n and s[i + 1] == "\n":
                i += 1
            jumped = False
            x = i + 1
            while x < n:
                if s[x] == "\n" or (s[x] == "/" and x + 1 < n and s[x + 1] in "/*"):
                    i, jumped = x, True
                    break
                if ord(s[x]) > 32:
                    break
                if x + 1 == n:
                    i = x + 1
                x += 1
            if jumped:
                continue
            if out:
                out.append("\n")
        elif c == " ":
            while i + 1 < n and s[i + 1] in " \t":
                i += 1
            if i + 1 < n and s[i + 1] != "\n":
                if i + 2 < n and s[i + 1] != "/" and s[i + 2] not in "/*":
                    out.append(" ")
        elif c == "\t":
            if out and i + 1 < n and s[i + 1] != "\n":
                out.append("\t")
        else:
            out.append(c)
        i += 1
    text = "".join(out)
    if len(text) > 2 and not text.endswith("\n"):
        text += "\n"
    return text


def parse_token(s, i):
    """COM_ParseExt2 without line breaks: (token, index after it); quoted strings unquoted."""
    while i < len(s) and s[i] in " \t\r":
        i += 1
    if i >= len(s) or s[i] == "\n":
        return "", i
    if s[i] == '"':
        j = s.find('"', i + 1)
        j = len(s) if j < 0 else j
        return s[i + 1:j], min(j + 1, len(s))
    j = i
    while j < len(s) and s[j] > " ":
        j += 1
    return s[i:j], j


class Shaders:
    def __init__(self, m):
        self.m = m
        self.cache = {}

    def text(self, name):
        """GetFallbackShader(name) + "\\n" (GLSL_GetShaderText)."""
        if name not in self.cache:
            path = GLSL_DIR + name + ".glsl"
            match = [f for f in self.m.files if f.lower() == path.lower()]
            if not match:
                raise KeyError(name)
            self.cache[name] = make_c_string(self.m.text(match[0])) + "\n"
        return self.cache[name]

    def preprocess(self, text, suffix):
        """GLSL_PreprocessShaderText."""
        out, i, n = [], 0, len(text)
        while i < n:
            c = text[i]
            if c == "/" and i + 1 < n and text[i + 1] == "/":
                i += 2
                while i < n and text[i] != "\n":
                    i += 1
            elif c == "/" and i + 1 < n and text[i + 1] == "*":
                i += 2
                while i < n and not (text[i] == "*" and i + 1 < n and text[i + 1] == "/"):
                    i += 1
                if i < n:
                    i += 2
            elif c == "#":
                tok, j = parse_token(text, i + 1)
                if tok.lower() == "include":
                    name, j = parse_token(text, j)
                    out.append(self.preprocess(self.text(name + suffix), suffix))
                    i = j
                else:
                    out.append(c)
            else:
                out.append(c)
            i += 1
        return "".join(out)


def c_enums(src):
    """NAME -> value of every enumerator in comment-free C source."""
    vals = {}
    for body in re.findall(r"\benum\b[^{;]*\{([^}]*)\}", src):
        k = -1
        for item in body.split(","):
            item = item.strip()
            if not item:
                continue
            m = re.match(r"(\w+)\s*(?:=\s*(.+))?$", item, re.S)
            if not m:
                continue
            k = int(m.group(2).strip(), 0) if m.group(2) and re.fullmatch(r"\s*-?\w+\s*", m.group(2)) \
                and m.group(2).strip().lstrip("-").isdigit() else k + 1
            vals[m.group(1)] = k
    return vals


def cvar_defaults(src):
    return {name: val for name, val in re.findall(r'Cvar_Get\(\s*"(\w+)"\s*,\s*"([^"]*)"', src)}


def extra_def(m):
    """GLSL_BuildShaderExtraDef for the default cvars (see the module docstring)."""
    local = strip_cpp_comments(m.text(R2 + "tr_local.h"))
    extra_h = strip_cpp_comments(m.text(R2 + "tr_extra.h"))
    enums = c_enums(local + "\n" + extra_h)
    cv = cvar_defaults(m.text(R2 + "tr_init.c"))
    defines = dict(re.findall(r"#define\s+(\w+)\s+(\S[^\n]*)", local))
    defines.update(re.findall(r"#define\s+(\w+)\s+(\S[^\n]*)", strip_cpp_comments(m.text("src/renderercommon/tr_types.h"))))

    def num(name):
        v = defines[name].strip()
        return int(eval(re.sub(r"[A-Z_][A-Z0-9_]*", lambda t: str(num(t.group(0))), v)))

    f = lambda k: float(cv[k])  # noqa: E731
    i = lambda k: int(float(cv[k]))  # noqa: E731
    s = ""
    s += "#ifndef r_SpecularExponent\n#define r_SpecularExponent %f\n#endif\n" % f("r_specularExponent")
    s += "#ifndef r_SpecularExponent2\n#define r_SpecularExponent2 %f\n#endif\n" % f("r_specularExponent2")
    s += "#ifndef r_SpecularScale\n#define r_SpecularScale %f\n#endif\n" % f("r_specularScale")
    s += "#ifndef r_NormalScale\n#define r_NormalScale %f\n#endif\n" % f("r_normalScale")
    s += "#ifndef M_PI\n#define M_PI 3.14159265358979323846f\n#endif\n"
    s += "#ifndef M_TAU\n#define M_TAU 6.28318530717958647693f\n#endif\n"
    s += "#ifndef MAX_SHADOWMAPS\n#define MAX_SHADOWMAPS %i\n#endif\n" % num("MAX_SHADOWMAPS")
    s += "#ifndef MAX_SHADER_DEFORM_PARMS\n#define MAX_SHADER_DEFORM_PARMS %i\n#endif\n" % num("MAX_SHADER_DEFORM_PARMS")
    groups = [("deform_t", ["DEFORM_WAVE", "DEFORM_BULGE", "DEFORM_MOVE"]),
              ("genFunc_t", ["GF_NONE", "GF_SIN", "GF_SQUARE", "GF_TRIANGLE", "GF_SAWTOOTH",
                             "GF_INVERSE_SAWTOOTH", "GF_NOISE"]),
              ("deformGen_t", ["DGEN_WAVE_SIN", "DGEN_WAVE_SQUARE", "DGEN_WAVE_TRIANGLE", "DGEN_WAVE_SAWTOOTH",
                               "DGEN_WAVE_INVERSE_SAWTOOTH", "DGEN_WAVE_NOISE", "DGEN_BULGE", "DGEN_MOVE"]),
              ("colorGen_t", ["CGEN_VERTEX", "CGEN_ONE_MINUS_VERTEX"]),
              ("alphaGen_t", ["AGEN_VERTEX", "AGEN_ONE_MINUS_VERTEX"]),
              ("alphaTest_t", ["ATEST_GT_0", "ATEST_LT_128", "ATEST_GE_128"])]
    for guard, names in groups:
        s += "#ifndef %s\n#define %s\n" % (guard, guard)
        s += "".join("#define %s %i\n" % (nm, enums[nm]) for nm in names)
        s += "#endif\n"
    s += "#ifndef r_FBufScale\n#define r_FBufScale vec2(%f, %f)\n#endif\n" % (1.0 / WIDTH, 1.0 / HEIGHT)
    s += "#define ScreenWidth %i\n#define ScreenHeight %i\n" % (WIDTH, HEIGHT)
    s += "#ifndef r_NPOTScale\n#define r_NPOTScale vec2(%f, %f)\n#endif\n" % (1, 1)
    shadows = int(float(cvar_defaults(m.text(R2 + "tr_init.c")).get("cg_shadows", "0")))
    if shadows >= enums["SHADOWING_ESM16"]:
        raise SystemExit("cg_shadows default enables shadow mapping: the shadow block is not written here")
    if i("r_hdrRendering"):
        s += "#ifndef r_HDRRendering\n#define r_HDRRendering 1\n#endif\n"
        s += "#ifndef r_HDRContrastThreshold\n#define r_HDRContrastThreshold %f\n#endif\n" % f("r_hdrContrastThreshold")
        s += "#ifndef r_HDRContrastOffset\n#define r_HDRContrastOffset %f\n#endif\n" % f("r_hdrContrastOffset")
        s += "#ifndef r_HDRToneMappingOperator\n#define r_HDRToneMappingOperator_%i\n#endif\n" % i("r_hdrToneMappingOperator")
        s += "#ifndef r_HDRGamma\n#define r_HDRGamma %f\n#endif\n" % f("r_hdrGamma")
    if i("r_precomputedLighting"):
        s += "#ifndef r_precomputedLighting\n#define r_precomputedLighting 1\n#endif\n"
    if i("r_heatHazeFix"):
        s += "#ifndef r_heatHazeFix\n#define r_heatHazeFix 1\n#endif\n"
    bones = max(0, min((MAX_VERTEX_UNIFORM_COMPONENTS - 16 * 10) // 16, num("MAX_BONES")))
    skinning = bool(i("r_vboVertexSkinning")) and bones >= 12
    if skinning:
        s += "#ifndef r_VertexSkinning\n#define r_VertexSkinning 1\n#endif\n"
        s += "#ifndef MAX_GLSL_BONES\n#define MAX_GLSL_BONES %i\n#endif\n" % bones
    else:
        s += "#ifndef MAX_GLSL_BONES\n#define MAX_GLSL_BONES %i\n#endif\n" % 4
    if i("r_normalMapping"):
        s += "#ifndef r_NormalMapping\n#define r_NormalMapping 1\n#endif\n"
    if i("r_normalMapping") and i("r_parallaxMapping"):
        s += "#ifndef r_ParallaxMapping\n#define r_ParallaxMapping 1\n#endif\n"
    if i("r_wrapAroundLighting"):
        s += "#ifndef r_WrapAroundLighting\n#define r_WrapAroundLighting %i\n#endif\n" % i("r_wrapAroundLighting")
    if f("r_diffuseLighting") >= 0.0:
        s += "#ifndef r_diffuseLighting\n#define r_diffuseLighting %f\n#endif\n" % f("r_diffuseLighting")
    if i("r_rimLighting"):
        s += "#ifndef r_rimLighting\n#define r_rimLighting 1\n#endif\n"
        s += "#ifndef r_rimColor\n#define r_rimColor vec4(0.26, 0.19, 0.16, 0.0)\n#endif\n"
        s += "#ifndef r_rimExponent\n#define r_rimExponent %f\n#endif\n" % f("r_rimExponent")
    s += "#line 0\n"
    return s, skinning


def header(stage):
    h = "#version 330 core\n"
    if stage == "vertex":
        h += "#define attribute in\n#define varying out\n"
    else:
        h += ("#define varying in\nout vec4 out_Color[4];\n#define gl_FragColor out_Color[0]\n"
              "#define gl_FragData out_Color\n")
    return h + "#define textureCube texture\n#define texture2D texture\n#define texture2DProj textureProj\n"


def definitions(text):
    """name -> {filename, fragfilename, macros[], extramacros} of the gldef text."""
    defs, lines, k = {}, text.split("\n"), 0
    while k < len(lines):
        name = lines[k].strip()
        if re.fullmatch(r"\w+", name) and k + 1 < len(lines) and lines[k + 1].strip() == "{":
            d, k = {"macros": [], "extramacros": ""}, k + 2
            while lines[k].strip() != "}":
                key, _, rest = lines[k].strip().partition(" ")
                key = key.lower()
                if key == "macros":
                    d["macros"] = rest.split()
                elif key in ("filename", "fragfilename", "extramacros"):
                    d[key] = parse_token(rest, 0)[0]
                k += 1
            defs[name] = d
        k += 1
    return defs


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    glsl_c = strip_cpp_comments(m.text(R2 + "tr_glsl.c"))
    macro_names = re.findall(r"^MACRO_DEF\((\w+)\)", strip_cpp_comments(m.text(R2 + "tr_glsldef.h")), re.M)
    defs = definitions(make_c_string(m.text(R2 + "gldef/default.gldef")))
    body = glsl_c[glsl_c.index("void GLSL_CompileGPUShaders(void)"):]
    wanted = re.findall(r'GLSL_GetShaderProgram\("(\w+)"\)', body[:body.index("\n}\n")])
    extra, skinning = extra_def(m)
    sh = Shaders(m)
    n = 0
    for name in wanted:
        d = defs[name]
        vname, fname = d["filename"], d.get("fragfilename", d["filename"])
        vtext = extra + sh.preprocess(sh.text(vname + "_vp"), "_vp")
        ftext = extra + sh.preprocess(sh.text(fname + "_fp"), "_fp")
        global_idx = [macro_names.index(x) for x in d["macros"]]
        perms = []
        for p in range(1 << len(d["macros"])):
            on = sorted(global_idx[x] for x in range(len(global_idx)) if p & (1 << x))
            names = [macro_names[i] for i in on]
            if "USE_VERTEX_SKINNING" in names and "USE_VERTEX_ANIMATION" in names:
                continue
            if any(x in names for x in ("USE_PARALLAX_MAPPING", "USE_DELUXE_MAPPING", "USE_REFLECTIONS",
                                        "USE_SPECULAR")) and "USE_NORMAL_MAPPING" not in names:
                continue
            if "USE_VERTEX_SKINNING" in names and not skinning:
                continue
            perms.append(names)
        chosen = [perms[0]] + cap_sample(perms[1:], PER_DEF - 1, key=lambda ns: name + " " + " ".join(ns))
        for names in chosen:
            tokens = names + d["extramacros"].split()
            defs_txt = "".join("#ifndef %s\n#define %s 1\n#endif\n" % (t, t) for t in tokens)
            label = name + ("." + "+".join(x.replace("USE_", "").lower() for x in names) if names else "")
            write_program(out, "etlegacy", label,
                          [("vertex", vname.replace("/", "_"), header("vertex") + defs_txt + vtext),
                           ("fragment", fname.replace("/", "_"), header("fragment") + defs_txt + ftext)])
            n += 1
    print(n, "programs")


main()
