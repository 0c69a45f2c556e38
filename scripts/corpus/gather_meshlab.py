#!/usr/bin/env python3
"""cnr-isti-vclab/meshlab: the GLSL programs MeshLab's own code builds (compatibility GL, GLSL 1.10/1.20).

Pairing, as each loader does it (texts verbatim unless said otherwise):
- render_gdp (meshrender.cpp loadGDPDoc): each resources/shaders/*.gdp names one VertexProgram
  and one FragmentProgram file (Filename0), relative to the .gdp's directory.
- decorate_shadow (decorate_shader.h compileAndLink(prog, v, f, path)): path + ".vert" and
  path + ".frag" for each literal `defaultShadersPath() + "/decorate_shadow/..."` (the
  defaultShadersPath is resources/shaders). A path that names no file (vsm/objectVSM is
  passed as "/shaders/decorate_shadow/vsm/objectVSM") is skipped as MeshLab fails to open it.
- filter_ao set_shaders(":/AmbientOcclusion/shaders/ambient_occlusionN"): ambient_occlusion.vert
  (last char cut) + ambient_occlusionN.frag, from the plugin's shaders/ directory (its .qrc).
- decorate_base: QGLShaderProgram addShaderFromSourceFile(Vertex/Fragment, ":/decorate/contour.*");
  QGLShader puts "#define lowp/mediump/highp" before the text (after leading #version/#extension).
- GPUProgram(vs, fs[, gs]) in filter_sdfgpu and render_radiance_scaling: files verbatim, "" = no
  stage (fixed-function vertex stage for the fragment-only SDF / obscurance passes).
- createShaders("vs literal", "fs literal") in alignset.cpp / render_helper.cpp (inline C strings).
- glw::createProgram(ctx, "", vertSrc, fragSrc) with `std::string x = GLW_STRINGIFY( ... );`
  sources: the macro argument stringized (#S: comments dropped, whitespace runs -> one space).
- render_splatpyramid (unsupported/plugins_experimental): SetSources(loadShaderSource("a.vert"),
  loadShaderSource("a.frag")); loadShaderSource reads resources/shaders/splatpyramid/<file>.
Identical programs are written once.
Usage: gather_meshlab.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer, strip_cpp_comments, c_string, C_LITERAL  # noqa: E402

PLAIN = r'"(?:\\.|[^"\\\n])*"'
QGL_HEADER = "#define lowp\n#define mediump\n#define highp\n"


def qgl(text):
    pos = 0
    while text.startswith("#version", pos) or text.startswith("#extension", pos):
        nl = text.find("\n", pos)
        pos = len(text) if nl < 0 else nl + 1
    return text[:pos] + QGL_HEADER + text[pos:]


def balanced(src, i):
    """src[i] == '(' -> index of its matching ')'."""
    depth = 0
    for j in range(i, len(src)):
        if src[j] == "(":
            depth += 1
        elif src[j] == ")":
            depth -= 1
            if depth == 0:
                return j
    return -1


def stringize(arg):
    arg = re.sub(r"/\*.*?\*/|//[^\n]*", " ", arg, flags=re.S)
    return re.sub(r"\s+", " ", arg).strip()


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "meshlab")
    # render_gdp
    for f in sorted(x for x in m.files if x.startswith("resources/shaders/") and x.endswith(".gdp")):
        x = m.text(f)
        vp = re.search(r'VertexProgram="([^"]*)"', x)
        fp = re.search(r'FragmentProgram="([^"]*)"', x)
        d = os.path.dirname(f)
        stages = []
        for stage, g in (("vertex", vp), ("fragment", fp)):
            if g and g.group(1):
                t = m.text(f"{d}/{g.group(1)}")
                if t is None:
                    stages = None
                    break
                stages.append((stage, os.path.splitext(g.group(1))[0], t))
        if stages:
            w.add("gdp." + os.path.splitext(os.path.basename(f))[0], stages)
    for f in m.files:
        if not f.startswith(("src/meshlabplugins/", "unsupported/plugins_experimental/render_splatpyramid/")) \
                or not f.endswith((".cpp", ".cc")):
            continue
        src = strip_cpp_comments(m.text(f))
        plugin = f.split("/")[-2]
        pdir = os.path.dirname(f)
        for c in re.finditer(r'compileAndLink\([^;]*?defaultShadersPath\(\)\s*\+\s*"([^"]+)"', src):
            base = "resources/shaders" + c.group(1)
            v, fr = m.text(base + ".vert"), m.text(base + ".frag")
            if v is None or fr is None:
                print("skip (no file):", base, file=sys.stderr)
                continue
            w.add(f"{plugin}.{c.group(1).strip('/').replace('/', '.')}",
                  [("vertex", os.path.basename(base), v), ("fragment", os.path.basename(base), fr)])
        for c in re.finditer(r'QString\s+\w+\s*\(\s*":/AmbientOcclusion/shaders/(\w+)"\s*\)', src):
            name = c.group(1)
            v = m.text(f"{pdir}/shaders/{name[:-1]}.vert")
            fr = m.text(f"{pdir}/shaders/{name}.frag")
            if v and fr:
                w.add(f"{plugin}.{name}", [("vertex", name[:-1], v), ("fragment", name, fr)])
        adds = re.findall(r'addShaderFromSourceFile\(\s*QGLShader::(Vertex|Fragment)\s*,\s*":/decorate/([\w.]+)"', src)
        if adds:
            stages = [(k.lower(), os.path.splitext(n)[0], qgl(m.text(f"{pdir}/{n}"))) for k, n in adds]
            w.add(f"{plugin}.{os.path.splitext(adds[0][1])[0]}", stages)
        for c in re.finditer(r'new\s+GPUProgram\(([^;]*)\)\s*;', src):
            args = c.group(1)
            pathvar = re.search(r'string\s+path\s*=\s*"([^"]*)"', src)
            lits = []
            for a in re.split(r",(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)", args):
                a = a.strip()
                s = re.search(r'"([^"]*)"', a)
                lit = s.group(1) if s else ""
                if a.startswith("path") and pathvar:
                    lit = pathvar.group(1) + lit
                lits.append(lit)
            stages = []
            for stage, lit in zip(("vertex", "fragment", "geometry"), lits):
                if not lit:
                    continue
                rel = re.sub(r"^:/\w+/", pdir + "/", lit)
                t = m.text(rel)
                if t is None:
                    stages = None
                    break
                stages.append((stage, os.path.splitext(os.path.basename(rel))[0], t))
            if stages:
                w.add(f"{plugin}.{stages[-1][1]}", stages)
        for c in re.finditer(r"(\w+(?:\[\w+\])?)\s*=\s*createShaders\(\s*((?:" + PLAIN + r"|\s)+),((?:" + PLAIN + r"|\s)+)\)", src):
            key = re.sub(r"^.*\[|\]$", "", c.group(1))
            w.add(f"{plugin}.{key}",
                  [("vertex", "vs", c_string(c.group(2))), ("fragment", "fs", c_string(c.group(3)))])
        if "GLW_STRINGIFY" in src:
            strs = {}
            events = []
            for c in re.finditer(r"(\w+)\s*=\s*GLW_STRINGIFY\s*\(", src):
                end = balanced(src, c.end() - 1)
                events.append((c.start(), "def", c.group(1), stringize(src[c.end():end])))
            for c in re.finditer(r"(?:glw::)?createProgram\(\s*\w+\s*,\s*\"\"\s*,\s*(\w+)\s*,\s*(\w+)\s*\)", src):
                events.append((c.start(), "use", c.group(1), c.group(2)))
            for _, kind, a, b in sorted(events):
                if kind == "def":
                    strs[a] = b
                elif a in strs and b in strs:
                    w.add(f"{plugin}.{b}", [("vertex", a, strs[a]), ("fragment", b, strs[b])])
        for c in re.finditer(r'SetSources\(\s*loadShaderSource\("([\w.]+)"\)[^,]*,\s*loadShaderSource\("([\w.]+)"\)', src):
            v = m.text("resources/shaders/splatpyramid/" + c.group(1))
            fr = m.text("resources/shaders/splatpyramid/" + c.group(2))
            if v and fr:
                w.add(f"splatpyramid.{os.path.splitext(c.group(1))[0]}",
                      [("vertex", os.path.splitext(c.group(1))[0], v), ("fragment", os.path.splitext(c.group(2))[0], fr)])
    w.report()


main()
