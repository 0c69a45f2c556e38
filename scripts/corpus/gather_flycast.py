#!/usr/bin/env python3
"""flyinghead/flycast: the OpenGL ("gles", GL 3 path) renderer's programs on a desktop GL 3+
context on Linux (not __APPLE__, not GLES, not LIBRETRO).

Shader text is built with ShaderSource (core/rend/shader_util.h): generate() is
`header + "\\n"`, then `#define <name> <value>\\n` per addConstant (in order, setConstant
replaces a value in place, bools/ints through std::to_string), then each addSource segment
+ "\\n". gl_CompileAndLink(vs, fs) (core/rend/gles/gles.cpp) passes each text as one string to
glShaderSource. OpenGlSource (gles.h) starts with header gl.glsl_version_header, addConstant
("TARGET_GL", gl.gl_version) and addSource(ShaderCompatSource); findGLVersion sets them for a
desktop GL >= 3 context to "#version 130" / "GL3" (the non-__APPLE__ branch). The segment
literals (`const char* X = R"(...)";`) are read from the C++ files, and the addConstant /
setConstant / addSource sequences of the builder classes (VertexSource, FragmentShaderSource,
N2VertexSource) and of the call sites are read from their bodies and evaluated with the
arguments below.

Programs:
- pipeline.<name>: CompilePipelineShader(s): vertex VertexSource(pp_Gouraud, divPosZ) or, for
  naomi2, N2VertexSource(pp_Gouraud, false, pp_Texture); fragment FragmentShaderSource(s). A fixed
  sample of GetProgram argument combinations (PIPELINES below; fields not named are 0, pp_FogCtrl
  2 = no fog unless named), divPosZ = !isNaomi2 && rend.NativeDepthInterpolation (default false,
  core/cfg/option.cpp), except `.native_depth` with it on.
- modvol, n2modvol: create_modvol_shader (gl_major >= 3, so both).
- postprocess.d<dither>i<interlaced>v<vga>: PostProcessShader::compile(dither, interlaced, vga)
  for the 6 reachable keys (both select() calls pass vga only when not interlaced; interlaced+vga
  would declare `taps` twice in main). postprocess.cpp is built for LIBRETRO only, but it is the
  GL3 text all the same.
- quad, quad.rot90: GlQuadDrawer's two programs (ROTATE 0, then setConstant ROTATE 1).
The GL 4.3 OIT renderer (core/rend/gl4) and imgui's backend (core/deps) are not gathered.
Usage: gather_flycast.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, c_string_vars, cpp_ifdefs, strip_cpp_comments, write_program, C_LITERAL  # noqa: E402

GLES = "core/rend/gles/gles.cpp"
GLES_H = "core/rend/gles/gles.h"
N2 = "core/rend/gles/naomi2.cpp"
PP = "core/rend/gles/postprocess.cpp"
QUAD = "core/rend/gles/quad.cpp"
OPTION = "core/cfg/option.cpp"

FIELDS = ["cp_AlphaTest", "pp_InsideClipping", "pp_Texture", "pp_UseAlpha", "pp_IgnoreTexA", "pp_ShadInstr",
          "pp_Offset", "pp_FogCtrl", "pp_Gouraud", "pp_BumpMap", "fog_clamping", "trilinear", "palette",
          "naomi2", "dithering"]
T = dict(pp_Texture=1, pp_UseAlpha=1, pp_Gouraud=1)
PIPELINES = [
    ("flat_untextured", {}),
    ("gouraud_untextured", dict(pp_Gouraud=1)),
    ("gouraud_alpha", dict(pp_Gouraud=1, pp_UseAlpha=1)),
    ("tex_decal", dict(T, pp_ShadInstr=0)),
    ("tex_modulate", dict(T, pp_ShadInstr=1)),
    ("tex_decal_alpha", dict(T, pp_ShadInstr=2)),
    ("tex_modulate_alpha", dict(T, pp_ShadInstr=3)),
    ("tex_ignore_texa", dict(T, pp_ShadInstr=1, pp_IgnoreTexA=1)),
    ("tex_offset", dict(T, pp_ShadInstr=1, pp_Offset=1)),
    ("tex_offset_fog_vertex", dict(T, pp_ShadInstr=1, pp_Offset=1, pp_FogCtrl=1)),
    ("fog_lut", dict(T, pp_ShadInstr=1, pp_FogCtrl=0)),
    ("fog_lut_mode2", dict(T, pp_ShadInstr=1, pp_FogCtrl=3)),
    ("fog_clamping", dict(T, pp_ShadInstr=1, pp_FogCtrl=0, fog_clamping=1)),
    ("alpha_test", dict(T, pp_ShadInstr=1, cp_AlphaTest=1)),
    ("clip_inside", dict(T, pp_ShadInstr=1, pp_InsideClipping=1)),
    ("bumpmap", dict(T, pp_ShadInstr=1, pp_Offset=1, pp_BumpMap=1)),
    ("trilinear", dict(T, pp_ShadInstr=1, trilinear=1)),
    ("palette_nearest", dict(T, pp_ShadInstr=1, palette=1)),
    ("palette_bilinear", dict(T, pp_ShadInstr=1, palette=2)),
    ("palette_fog_lut_mode2", dict(T, pp_ShadInstr=1, palette=1, pp_FogCtrl=3)),
    ("dithering", dict(T, pp_ShadInstr=1, dithering=1)),
    ("naomi2_untextured", dict(pp_Gouraud=1, naomi2=1)),
    ("naomi2_textured", dict(T, pp_ShadInstr=1, naomi2=1)),
    ("naomi2_flat_fog", dict(T, pp_Gouraud=0, pp_ShadInstr=3, pp_FogCtrl=0, naomi2=1)),
]


class Source:
    """ShaderSource."""
    def __init__(self, header=""):
        self.header, self.constants, self.segments = header, [], []

    def add_constant(self, name, value="0"):
        self.constants.append([name, value])

    def set_constant(self, name, value):
        for c in self.constants:
            if c[0] == name:
                c[1] = value
                return
        self.add_constant(name, value)

    def generate(self):
        return (self.header + "\n" + "".join(f"#define {n} {v}\n" for n, v in self.constants)
                + "".join(s + "\n" for s in self.segments))


CALL = re.compile(r"(?P<cond>if\s*\(\s*(?P<neg>!?)\s*(?P<cv>[\w.>:-]+)\s*\)\s*)?\.?\b(?P<m>addConstant|setConstant|addSource)"
                  r"\(\s*(?P<a>(?:" + C_LITERAL + r"|\([^()]*\)|[^()\"])*)\)")


def value(expr, env):
    e = re.sub(r"^\(\s*int\s*\)\s*", "", expr.strip())
    if re.fullmatch(r"-?\d+", e):
        return int(e)
    if e in ("true", "false"):
        return int(e == "true")
    if e.startswith('"'):
        return c_string(e)
    key = re.split(r"->|\.|::", e)[-1]
    v = env[key]
    return int(v) if isinstance(v, bool) else v


def apply_calls(obj, body, env, lits):
    """Runs the addConstant/setConstant/addSource calls of `body` in order on obj."""
    for m in CALL.finditer(body):
        if m.group("cond"):
            c = bool(value(m.group("cv"), env))
            if c == bool(m.group("neg")):
                continue
        args = [t.group(0).strip() for t in re.finditer(C_LITERAL + r"|(?:\([^()]*\)|[^,\"])+", m.group("a"))]
        args = [a for a in args if a]
        if m.group("m") == "addSource":
            a = args[0]
            obj.segments.append(c_string(a) if a.startswith('"') else lits[a])
        else:
            name = c_string(args[0])
            v = str(value(args[1], env)) if len(args) > 1 else "0"
            (obj.add_constant if m.group("m") == "addConstant" else obj.set_constant)(name, v)
    return obj


def ctor(src, cls):
    """(parameter names, body) of the `Cls::Cls(...)` or in-class `Cls(...) : Base()` constructor."""
    m = re.search(rf"\b(?:{cls}::)?{cls}\s*\(([^)]*)\)\s*:\s*\w+\([^)]*\)\s*\{{", src)
    params = [p.split()[-1].lstrip("*&") for p in m.group(1).split(",") if p.strip()]
    i, depth = m.end(), 1
    j = i
    while depth:
        depth += {"{": 1, "}": -1}.get(src[j], 0)
        j += 1
    return params, src[i:j - 1]


def statement(src, start):
    """The text of the statement that begins at `start` (to the `;` outside literals)."""
    m = re.compile(r"(?:" + C_LITERAL + r"|[^;\"])*;").match(src, src.index(start))
    return m.group(0)


def main():
    mir, out = Mirror(sys.argv[1]), sys.argv[2]
    text = {p: strip_cpp_comments(mir.text(p)) for p in (GLES, GLES_H, N2, PP, QUAD)}
    lits = {}
    for p in (GLES, N2):
        lits.update({k: v[0] for k, v in c_string_vars(text[p]).items() if v})
    # findGLVersion, desktop GL >= 3, not __APPLE__
    fv = cpp_ifdefs(text[GLES][text[GLES].index("void findGLVersion()"):], defined=())
    fv = fv[fv.index('gl.gl_version = "GL3"'):]
    env = {"gl_version": c_string(re.search(r"gl\.gl_version\s*=\s*(\"[^\"]*\")", fv).group(1)),
           "glsl_version_header": c_string(re.search(r"gl\.glsl_version_header\s*=\s*(\"[^\"]*\")", fv).group(1))}
    opt = cpp_ifdefs(mir.text(OPTION), defined=())
    env["NativeDepthInterpolation"] = re.search(r'NativeDepthInterpolation\("[^"]*",\s*(\w+)\)', opt).group(1) == "true"
    _, gl_src_body = ctor(text[GLES_H], "OpenGlSource")

    def gl_source(env_):
        return apply_calls(Source(env_["glsl_version_header"]), gl_src_body, env_, lits)

    def build(cls, file, args, env_):
        params, body = ctor(text[file], cls)
        e = dict(env_, **dict(zip(params, args)))
        return apply_calls(gl_source(e), body, e, lits)

    n = 0

    def emit(name, vs, fs):
        nonlocal n
        write_program(out, "flycast", name, [("vertex", "vertex", vs.generate() if isinstance(vs, Source) else vs),
                                             ("fragment", "fragment", fs.generate() if isinstance(fs, Source) else fs)])
        n += 1

    # CompilePipelineShader
    for native in (env["NativeDepthInterpolation"], not env["NativeDepthInterpolation"]):
        for name, fields in PIPELINES:
            s = {f: 0 for f in FIELDS}
            s["pp_FogCtrl"] = 2
            s.update(fields)
            if native != env["NativeDepthInterpolation"] and (s["naomi2"] or name not in ("tex_modulate", "fog_lut")):
                continue
            s["divPosZ"] = int(not s["naomi2"] and native)
            # PipelineShader field names as FragmentShaderSource reads them (s->x)
            e = dict(env, **s)
            if s["naomi2"]:
                vs = build("N2VertexSource", N2, [s["pp_Gouraud"], 0, s["pp_Texture"]], e)
            else:
                vs = build("VertexSource", GLES, [s["pp_Gouraud"], s["divPosZ"]], e)
            fs = build("FragmentShaderSource", GLES, [None], e)
            emit("pipeline." + name + (".native_depth" if native else ""), vs, fs)
    # create_modvol_shader
    body = text[GLES][text[GLES].index("static void create_modvol_shader()"):]
    vargs = re.search(r"VertexSource\s+vertexShader\(([^)]*)\)", body).group(1).split(",")
    vs = build("VertexSource", GLES, [value(a, env) for a in vargs], env)
    fs = apply_calls(gl_source(env), statement(body, "fragmentShader.addConstant"), env, lits)
    emit("modvol", vs, fs)
    n2args = re.search(r"N2VertexSource\s+n2vertexShader\(([^)]*)\)", body).group(1).split(",")
    vs = build("N2VertexSource", N2, [value(a, env) for a in n2args], env)
    apply_calls(fs, statement(body, "fragmentShader.setConstant"), env, lits)
    emit("n2modvol", vs, fs)
    # PostProcessShader::compile
    pl = {k: v[0] for k, v in c_string_vars(text[PP]).items() if v}
    body = text[PP][text[PP].index("void compile(bool dither, bool interlaced, bool vga)"):]
    for d in (0, 1):
        for i in (0, 1):
            for v in (0, 1):
                if i and v:  # both select() calls pass vga = vclk_div == 1 && interlace == 0
                    continue
                e = dict(env, dither=d, interlaced=i, vga=v)
                vs = apply_calls(gl_source(e), statement(body, "vertexShader.addSource"), e, dict(lits, **pl))
                fs = apply_calls(gl_source(e), statement(body, "fragmentShader.addConstant"), e, dict(lits, **pl))
                emit(f"postprocess.d{d}i{i}v{v}", vs, fs)
    # GlQuadDrawer
    ql = dict(lits, **{k: v[0] for k, v in c_string_vars(text[QUAD]).items() if v})
    body = text[QUAD][text[QUAD].index("GlQuadDrawer::GlQuadDrawer()"):]
    fs = apply_calls(gl_source(env), statement(body, "fragmentShader.addSource"), env, ql).generate()
    vs = apply_calls(gl_source(env), statement(body, "vertexShader.addConstant"), env, ql)
    emit("quad", vs, fs)
    apply_calls(vs, statement(body, "vertexShader.setConstant"), env, ql)
    emit("quad.rot90", vs, fs)
    print(n, "programs")


main()
