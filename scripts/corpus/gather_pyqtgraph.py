#!/usr/bin/env python3
"""pyqtgraph/pyqtgraph OpenGL programs, both desktop branches of each loader:

- opengl/shaders.py ShaderProgram(name, [VertexShader(s), FragmentShader(s)]): PyOpenGL
  compileShader(code) as is (no #version: GLSL 1.10; es2_compat is macOS-only).
- opengl/items/GL*Item.py getShaderProgram(): compileShader([glsl_version, src]) with
  SHADER_CORE and the item's "#version 140\\n" (context >= 3.1) or SHADER_LEGACY and the item's
  legacy version string (context < 3.1).
- graphicsItems/PlotCurveItem.py and PColorMeshItem.py: QOpenGLShaderProgram
  addShaderFromSourceCode of the *_140 / "#version 140"-joined or compat sources; Qt 5.15
  QOpenGLShader::compileSourceCode inserts, after an optional #version line, the fragment
  blend-equation-advanced header, `#define lowp/mediump/highp` and `#line N`.
Usage: gather_pyqtgraph.py MIRROR_GIT_DIR OUT_DIR
"""
import ast, os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program, version_position
from pyshaders import calls, value

m, out = Mirror(sys.argv[1]), sys.argv[2]
P = "pyqtgraph/"
QUALIFIERS = "#define lowp\n#define mediump\n#define highp\n"
BLEND = ("#ifdef GL_KHR_blend_equation_advanced\n#extension GL_ARB_fragment_coord_conventions : enable\n"
         "#extension GL_KHR_blend_equation_advanced : enable\n#endif\n")


def qt(src, frag):
    pos, line = version_position(src)
    return src[:pos] + (BLEND if frag else "") + QUALIFIERS + f"#line {line}\n" + src[pos:]


n = 0
# opengl/shaders.py
for call, env in calls(m.text(P + "opengl/shaders.py"), {"ShaderProgram"}):
    if len(call.args) < 2 or not isinstance(call.args[1], ast.List):
        continue
    name = value(call.args[0], env) or "default"
    stages = []
    for sh in call.args[1].elts:
        kind = {"VertexShader": "vertex", "FragmentShader": "fragment"}.get(getattr(sh.func, "id", ""))
        if kind and isinstance(value(sh.args[0], env), str):
            stages.append((kind, kind[:4], value(sh.args[0], env)))
    write_program(out, "pyqtgraph", "shaders_" + name, stages)
    n += 1

# opengl/items: module-level SHADER_LEGACY / SHADER_CORE dicts keyed by GL.GL_*_SHADER
for f in m.files:
    if not re.match(P + r"opengl/items/GL\w+\.py$", f):
        continue
    src = m.text(f)
    tree = ast.parse(src)
    dicts = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Dict) and getattr(node.targets[0], "id", "").startswith("SHADER_"):
            dicts[node.targets[0].id] = {k.attr: v.value for k, v in zip(node.value.keys, node.value.values)
                                         if isinstance(k, ast.Attribute) and isinstance(v, ast.Constant)}
    versions = [v.encode().decode("unicode_escape") for v in re.findall(r'glsl_version = "([^"]*)"', src)]
    if len(versions) < 4 or "SHADER_CORE" not in dicts:
        continue
    for label, ver, d in (("core", versions[2], dicts["SHADER_CORE"]), ("legacy", versions[3], dicts["SHADER_LEGACY"])):
        stages = [(st, st[:4], ver + d[key]) for st, key in (("vertex", "GL_VERTEX_SHADER"), ("fragment", "GL_FRAGMENT_SHADER"))]
        write_program(out, "pyqtgraph", os.path.basename(f)[:-3] + "_" + label, stages)
        n += 1

# graphicsItems: QOpenGLShaderProgram
for f, variants in (("graphicsItems/PlotCurveItem.py", [("140", "VERT_SRC_140", "FRAG_SRC_140", ""), ("legacy", "VERT_SRC", "FRAG_SRC", "")]),
                    ("graphicsItems/PColorMeshItem.py", [("140", "VERT_SRC", "FRAG_SRC", "#version 140"),
                                                         ("compat", "VERT_SRC_COMPAT", "FRAG_SRC_COMPAT", "")])):
    env = {}
    for node in ast.walk(ast.parse(m.text(P + f))):
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant) and isinstance(node.targets[0], ast.Name):
            env[node.targets[0].id] = node.value.value
    for label, vs, fs, ver in variants:
        v, fr = (env[vs], env[fs]) if not ver else ("\n".join([ver, env[vs]]), "\n".join([ver, env[fs]]))
        write_program(out, "pyqtgraph", os.path.basename(f)[:-3] + "_" + label,
                      [("vertex", "vert", qt(v, False)), ("fragment", "frag", qt(fr, True))])
        n += 1
print(n, "programs")
