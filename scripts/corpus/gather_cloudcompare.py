#!/usr/bin/env python3
"""CloudCompare/CloudCompare: the GLSL programs its GL filters load (compatibility GL, GLSL 1.10
with ftransform/gl_TexCoord/gl_MultiTexCoord0/gl_FragData).

Pairing, as the code does it:
- `ccShader::fromFile(shadersPath, "Dir/name")` (ccBilateralFilter, qEDL, qSSAO, the GL window's
  rendering shader): Dir/name.vert + Dir/name.frag (ccShader.cpp fromFile -> loadProgram);
  the shader tree is installed from the `shaders/` folders of libs/, plugins/ and qCC/;
  a pair whose files are not in the tree is skipped;
- `colorRampShader->loadProgram(QString(), shaderPath)` with shaderPath ".../ColorRamp/
  color_ramp.frag": a fragment-only program (no vertex shader: fixed-function vertex stage);
- ccShader is a QOpenGLShaderProgram and addShaderFromSourceFile compiles through
  QOpenGLShader::compileSourceCode, which on desktop GL inserts after the #version line (if any)
  `#define lowp`, `#define mediump`, `#define highp` and `#line N` (N the line after #version).
Usage: gather_cloudcompare.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer, strip_cpp_comments  # noqa: E402
from mirror import version_position  # noqa: E402

QUALIFIERS = "#define lowp\n#define mediump\n#define highp\n"


def qt(src):
    pos, line = version_position(src)
    return src[:pos] + QUALIFIERS + f"#line {line}\n" + src[pos:]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "cloudcompare")
    tree = {}  # installed shader path "Dir/file" -> repository path
    for f in m.files:
        k = f.rfind("/shaders/")
        if k >= 0 and (f.startswith(("libs/", "plugins/", "qCC/"))):
            tree.setdefault(f[k + len("/shaders/"):], f)
    for f in sorted(x for x in m.files if x.endswith(".cpp")):
        src = strip_cpp_comments(m.text(f))
        for c in re.finditer(r'(?:->|\.)fromFile\(\s*[^,()]+(?:\([^()]*\))?(?:\s*\+\s*QString\("([^"]*)"\))?\s*,\s*'
                             r'(?:QString\()?"([^"]+)"\)?\s*,\s*\w+\s*\)', src):
            sub = (c.group(1) or "").strip("/")
            base = f"{sub}/{c.group(2)}" if sub else c.group(2)
            vs, fs = tree.get(base + ".vert"), tree.get(base + ".frag")
            if vs is None or fs is None:
                print(f"cloudcompare: {base}: no .vert/.frag in the tree, skipped")
                continue
            w.add(base.replace("/", "."), [("vertex", os.path.basename(base), qt(m.text(vs))),
                                           ("fragment", os.path.basename(base), qt(m.text(fs)))])
        if re.search(r"loadProgram\(\s*QString\(\)\s*,", src):
            for path in re.findall(r'"(?:%1)?(/?\w+/\w+\.frag)"', src):
                fs = tree.get(path.strip("/"))
                if fs:
                    w.add(path.strip("/").rsplit(".", 1)[0].replace("/", "."),
                          [("fragment", os.path.basename(path).rsplit(".", 1)[0], qt(m.text(fs)))])
    w.report()


if __name__ == "__main__":
    main()
