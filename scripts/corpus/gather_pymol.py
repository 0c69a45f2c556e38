#!/usr/bin/env python3
"""schrodinger/pymol-open-source: the GLSL programs CShaderMgr builds (compatibility GL,
GLSL 1.10/1.20 with fixed-function state: gl_LightSource, gl_FrontColor, gl_TexCoord...).

Pairing, as layer0/ShaderMgr.cpp does it (desktop build, not PURE_OPENGL_ES_2):
- `make_program(name, "x.vs", "x.fs"[, geometry "x.gs"])` calls of CShaderMgr::Config; the
  connector program with its geometry shader (GLEW_EXT_geometry_shader4) and the cylinder/sphere
  programs (GL_FragDepth support) as on a current driver; tessellation (bezier) left out;
- each stage text is ShaderPreprocessor::getSource(file) of data/shaders/: line-wise, a line
  whose first non-blank text is `#ifdef V` / `#ifndef V` / `#else` / `#endif` / `#include F` is
  consumed (not written) and steers the inactive/active state with PyMOL's own boolean table;
  `#include` inserts the preprocessed file (`CallComputeColorForLight` is the
  call_compute_color_for_light.fs template expanded as Reload_CallComputeColorForLight does for
  light_count 2, spec_count -1); every other line is written verbatim;
- the boolean table is Reload_Shader_Variables with default settings: bg_image_mode_solid,
  depth_cue (depth_cue 1 and fog 1), use_geometry_shaders, line_smooth, GLEW_VERSION_3_0 and
  gl_VertexID_enabled true; ortho, ANAGLYPH, ray_trace_mode_3, transparency_mode_3,
  precomputed_lighting, ray_transparency_oblique, chromadepth(_postlighting), openvr_enabled,
  ONE_DRAW_BUFFER and anything else false. The shader text is passed to glShaderSource as is.
Identical programs are written once.
Usage: gather_pymol.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer, strip_cpp_comments  # noqa: E402

TRUE_VARS = {"bg_image_mode_solid", "depth_cue", "use_geometry_shaders", "line_smooth",
             "GLEW_VERSION_3_0", "gl_VertexID_enabled"}
DIR = "data/shaders/"


def call_compute_color_for_light(m, light_count=2, spec_count=-1):
    raw = preprocess(m, "call_compute_color_for_light.fs")
    out = raw.replace("`light`", "0").replace("`postfix`", "_0")
    postfix = ""
    for i in range(1, min(light_count, 8)):
        if i == spec_count + 1:
            postfix = " * 0.0"
        out += raw.replace("`light`", str(i)).replace("`postfix`", postfix)
    return out


def preprocess(m, name, depth=0):
    if name == "CallComputeColorForLight":
        return call_compute_color_for_light(m)
    text = m.text(DIR + name)
    if text is None or depth > 10:
        raise KeyError(name)
    out, if_depth, true_depth = [], 0, 0
    for line in text.splitlines(keepends=True):
        s = line.lstrip(" \t\r\n")
        word = s.split()[0] if s.split() else ""
        arg = s.split()[1] if len(s.split()) > 1 else ""
        if not s.startswith("#") or word not in ("#ifdef", "#ifndef", "#else", "#endif", "#include"):
            if if_depth == true_depth:
                out.append(line)
            continue
        if word in ("#ifdef", "#ifndef"):
            if if_depth == true_depth:
                val = arg in TRUE_VARS
                if word == "#ifndef":
                    val = not val
                if val:
                    true_depth += 1
            if_depth += 1
        elif word == "#include":
            if if_depth == true_depth:
                out.append(preprocess(m, arg, depth + 1))
        elif word == "#endif":
            if if_depth == true_depth:
                true_depth -= 1
            if_depth -= 1
        elif word == "#else":
            if if_depth == true_depth:
                true_depth -= 1
            elif if_depth == true_depth + 1:
                true_depth += 1
    return "".join(out)


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "pymol")
    src = strip_cpp_comments(m.text("layer0/ShaderMgr.cpp"))
    cfg = src[src.find("#define make_program"):]
    cfg = cfg[:cfg.find("Reload_Shader_Variables();")]
    seen = set()
    for call in re.finditer(r'make_program\(\s*"(\w+)"\s*,\s*"([\w.]+)"\s*,\s*"([\w.]+)"([^;]*)\)\s*;', cfg):
        name, vs, fs, rest = call.groups()
        if "tessParams" in rest or name in seen:  # the else branch (no geometry shader) not taken
            continue
        seen.add(name)
        stages = [("vertex", vs.replace(".", "_"), vs)]
        gs = re.search(r'"([\w.]+\.gs)"', cfg[max(0, call.start() - 400):call.start()]) if "geoParams" in rest else None
        if gs:
            stages.append(("geometry", gs.group(1).replace(".", "_"), gs.group(1)))
        stages.append(("fragment", fs.replace(".", "_"), fs))
        try:
            prog = [(st, stem, preprocess(m, f)) for st, stem, f in stages]
        except KeyError as e:
            print(f"pymol: {name}: no shader {e}")
            continue
        w.add(name, prog)
    w.report()


if __name__ == "__main__":
    main()
