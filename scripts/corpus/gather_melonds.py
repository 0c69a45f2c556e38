#!/usr/bin/env python3
"""melonDS-emu/melonDS: every program the OpenGL renderers and the Qt frontend build.

Graphics programs go through OpenGL::CompileVertexFragmentProgram(result, vs, fs, name, attrs,
fragouts) (src/OpenGLSupport.cpp), which hands each std::string to glShaderSource as one string,
nothing prepended. The `k<Name>` sources of src/OpenGL_shaders/*.glsl are embedded by
cmake/MakeEmbed.cmake as `const char* k<Name> = R"(<file>)";`, i.e. the file verbatim; the
frontend's kScreenVS/FS and kScreenVS_OSD/FS_OSD are raw literals in
src/frontend/qt_sdl/main_shaders.h / OSD_shaders.h.
- One program per `CompileVertexFragmentProgram(X, kVS, kFS, "Name", ...)` call in
  GPU2D_OpenGL.cpp, GPU3D_OpenGL.cpp, GPU_OpenGL.cpp and frontend/qt_sdl/Screen.cpp, named after
  its name argument.
- GLRenderer3D::BuildRenderShader(wbuffer) for wbuffer false/true: "RenderShaderZ" is
  k3DRenderVS + k3DRenderFS as they are, "RenderShaderW" has `wbufdef` ("#define WBuffer\\n")
  inserted after the first line (`find('\\n') + 1`) of both.

Compute programs (the compute 3D renderer, GL 4.3): ComputeRenderer3D::CompileShader(shader,
source, defines) builds "#version 430 core\\n", `#define D\\n` per define, the ScreenWidth /
ScreenHeight / MaxWorkTiles / TileSize / CoarseTileCountY / CoarseTileArea /
ClearCoarseBinMaskLocalSize lines (read from the function and evaluated), then
ComputeRendererShaders::Common + source (GPU3D_Compute_shaders.h; std::string constants are
`+` concatenations of other constants and raw literals, evaluated here), passed to
CompileComputeProgram as one string. One program per ShaderCompileStep case (named after its defines), for the default
3D.GL.ScaleFactor 1 (src/frontend/qt_sdl/Config.cpp) and its maximum 16 (`.x16`), with
SetRenderSettings' TileSize formula (GetMSBit as in src/Utils.h).
Usage: gather_melonds.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, c_string_vars, strip_cpp_comments, write_program, C_LITERAL  # noqa: E402

CALL_FILES = ["src/GPU2D_OpenGL.cpp", "src/GPU3D_OpenGL.cpp", "src/GPU_OpenGL.cpp",
              "src/frontend/qt_sdl/Screen.cpp"]
FRONT_HEADERS = ["src/frontend/qt_sdl/main_shaders.h", "src/frontend/qt_sdl/OSD_shaders.h"]
COMPUTE = "src/GPU3D_Compute.cpp"
COMPUTE_SH = "src/GPU3D_Compute_shaders.h"
CONFIG = "src/frontend/qt_sdl/Config.cpp"


def string_constants(src):
    """name -> value of `const std::string N{...};`, `const std::string N = a + "b" + ...;` and
    `const char* N = R"(...)";` in comment-free C++ (terms are literals or earlier constants)."""
    out = {}
    pat = re.compile(r"const\s+(?:std::string|char\s*\*)\s+(\w+)\s*(?:=|\{)((?:" + C_LITERAL + r"|[^;\"])*?)\}?\s*;")
    for m in pat.finditer(src):
        val = ""
        for t in re.finditer(C_LITERAL + r"|[A-Za-z_]\w*", m.group(2)):
            tok = t.group(0)
            val += c_string(tok) if tok.startswith(('"', 'R"')) else out[tok]
        out[m.group(1)] = val
    return out


def get_msbit(v, bits=8):
    for s in (1, 2, 4, 8, 16, 32):
        if s < bits:
            v |= v >> s
    return v - (v >> 1)


def compute_settings(scale, coarse_x):
    """SetRenderSettings(scale, ...): the members CompileShader reads."""
    tile_scale = (2 * scale // 9) & 0xFF  # u8
    tile_scale = (get_msbit(tile_scale) << 1) & 0xFF
    tile_scale += tile_scale == 0
    tile = min(8 * tile_scale, 32)
    w, h = 256 * scale, 192 * scale
    ty = 4 if tile < 32 else 6
    return {"ScreenWidth": w, "ScreenHeight": h, "TileSize": tile, "CoarseTileCountY": ty,
            "ClearCoarseBinMaskLocalSize": 64 if tile < 32 else 48, "CoarseTileArea": coarse_x * ty,
            "MaxWorkTiles": (w // tile) * (h // tile) * 16}


def function_body(src, head):
    i = src.index(head)
    i = src.index("{", i)
    depth, j = 0, i
    while True:
        depth += {"{": 1, "}": -1}.get(src[j], 0)
        j += 1
        if depth == 0:
            return src[i + 1:j - 1]


def compile_shader_header(body, defines, values):
    """Runs CompileShader's `shaderSource += ...;` statements (the define loop once per define)."""
    def terms(expr, define=None):
        val = ""
        for t in re.finditer(C_LITERAL + r"|'(?:\\.|[^'])'|std::to_string\(\s*(?P<num>\w+)\s*\)|[\w:]+", expr):
            tok = t.group(0)
            if tok.startswith(("\"", "R\"")):
                val += c_string(tok)
            elif tok[0] == "'":
                val += c_string('"' + tok[1:-1] + '"')
            elif t.group("num"):
                val += str(values[t.group("num")])
            elif tok == "define":
                val += define
            elif tok in ("source",) or "::" in tok:
                return None  # the common + source part, added by the caller
            else:
                raise ValueError(f"unknown term {tok!r} in CompileShader")
        return val
    out = ""
    loop = re.search(r"for\s*\(\s*const\s+char\s*\*\s*define\s*:\s*defines\s*\)\s*\{(.*?)\}", body, re.S)
    parts = [(body[:loop.start()], None), (loop.group(1), "loop"), (body[loop.end():], None)]
    for text, kind in parts:
        for d in (defines if kind else [None]):
            for m in re.finditer(r"shaderSource\s*\+=\s*((?:" + C_LITERAL + r"|[^;\"])*);", text):
                v = terms(m.group(1), d)
                if v is not None:
                    out += v
    return out


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    srcs = {}
    for p in m.files:
        mm = re.fullmatch(r"src/OpenGL_shaders/(\w+)\.glsl", p)
        if mm:
            srcs["k" + mm.group(1)] = m.text(p)  # MakeEmbed.cmake: R"(<file>)"
    for h in FRONT_HEADERS:
        for k, v in c_string_vars(strip_cpp_comments(m.text(h))).items():
            srcs[k] = v[0]
    n = 0
    seen = set()
    for f in CALL_FILES:
        src = strip_cpp_comments(m.text(f))
        for c in re.finditer(r"CompileVertexFragmentProgram\(\s*(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*,\s*(\"[^\"]*\"|\w+)", src):
            vs, fs, name = c.group(2), c.group(3), c.group(4)
            if name.startswith('"'):
                prog = c_string(name)
                write_program(out, "melonds", prog, [("vertex", vs, srcs[vs]), ("fragment", fs, srcs[fs])])
                n += 1
                seen.add(prog)
                continue
            # BuildRenderShader(bool wbuffer)
            body = function_body(src, "BuildRenderShader(bool wbuffer)")
            wdef = c_string(re.search(r"std::string\s+wbufdef\s*=\s*(" + C_LITERAL + ")", body).group(1))
            vname = re.search(r"std::string\s+vsbuf\s*=\s*(\w+)\s*;", body).group(1)
            fname = re.search(r"std::string\s+fsbuf\s*=\s*(\w+)\s*;", body).group(1)
            assert body.count("find('\\n') + 1") == 2, "BuildRenderShader insertion changed"
            pfx, t_true, t_false = re.search(r'"(\w*)%c"\s*,\s*wbuffer\s*\?\s*\'(\w)\'\s*:\s*\'(\w)\'', body).groups()
            for wb, tag in ((False, t_false), (True, t_true)):
                stages = []
                for stage, k in (("vertex", vname), ("fragment", fname)):
                    t = srcs[k]
                    if wb:
                        pos = t.index("\n") + 1
                        t = t[:pos] + wdef + t[pos:]
                    stages.append((stage, k, t))
                write_program(out, "melonds", pfx + tag, stages)
                n += 1
    # compute renderer
    csrc = strip_cpp_comments(m.text(COMPUTE))
    consts = string_constants(strip_cpp_comments(m.text(COMPUTE_SH)))
    body = function_body(csrc, "ComputeRenderer3D::CompileShader(")
    assert re.search(r"shaderSource\s*\+=\s*ComputeRendererShaders::Common\s*;\s*shaderSource\s*\+=\s*source\s*;", body)
    coarse_x = int(re.search(r"CoarseTileCountX\s*=\s*(\d+)", m.text("src/GPU3D_Compute.h")).group(1))
    mx = int(re.search(r'\{"3D\.GL\.ScaleFactor",\s*\{\d+,\s*(\d+)\}\}', m.text(CONFIG)).group(1))
    dflt0 = int(re.search(r'\{"3D\.GL\.ScaleFactor",\s*(\d+)\}', m.text(CONFIG)).group(1))
    steps = re.findall(r"case\s+(\d+)\s*:\s*CompileShader\(\s*(\w+(?:\[\d+\])?)\s*,\s*ComputeRendererShaders::(\w+)\s*,\s*\{([^}]*)\}\s*\)",
                       function_body(csrc, "ComputeRenderer3D::ShaderCompileStep("))
    for scale, sfx in ((dflt0, ""), (mx, ".x%d" % mx)):
        vals = compute_settings(scale, coarse_x)
        for case, var, source, defs in steps:
            defines = [c_string(d.group(0)) for d in re.finditer(C_LITERAL, defs)]
            text = compile_shader_header(body, defines, vals) + consts["Common"] + consts[source]
            name = "compute." + "_".join(defines) + sfx
            write_program(out, "melonds", name, [("compute", source, text)])
            n += 1
    print(n, "programs")


main()
