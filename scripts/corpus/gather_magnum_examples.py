#!/usr/bin/env python3
"""mosra/magnum-examples: each src/**.cpp that creates `GL::Shader vert{GL::Version::GLxyz, Vertex}`
and a fragment shader is one program; the stage text is what GL::Shader assembles: the
#version line for GLxyz, then each addSource() (rs.getString("f") = file f next to the .cpp,
Utility::format("#define X {}\\n", v) with v = the Shaders::GenericGL3D location or the
example's default count) preceded by "#line 1 N\\n" (GLSL >= 330).
Usage: gather_magnum_examples.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
VALUES = {"Position::Location": "0", "Normal::Location": "5", "numShadowLevels": "3"}  # generic.glsl / ShadowsExample defaults
VERSIONS = {"GL330": "330", "GL400": "400", "GL410": "410", "GL430": "430", "GL450": "450"}


def source(arg, d):
    f = re.match(r'rs\.getString\(\s*"([^"]+)"', arg)
    if f:
        return m.text(posixpath.join(d, f.group(1))) or m.text(next(p for p in m.files if p.endswith("/" + f.group(1))))
    fmt = re.match(r'Utility::format\(\s*((?:"[^"]*"\s*)+),(.*)\)\s*$', arg, re.S)
    if fmt:
        text = "".join(re.findall(r'"([^"]*)"', fmt.group(1))).replace("\\n", "\n")
        vals = [next(v for k, v in VALUES.items() if k in a) for a in fmt.group(2).split(",")]
        return text.replace("{}", "{}").format(*vals)
    raise ValueError(arg)


n = 0
for f in m.files:
    if not (f.startswith("src/") and f.endswith(".cpp")):
        continue
    src, d = m.text(f), posixpath.dirname(f)
    decl = dict((t, (var, v)) for var, v, t in re.findall(
        r'GL::Shader\s+(\w+)\s*[({]\s*GL::Version::(GL\d+)\s*,\s*GL::Shader::Type::(Vertex|Fragment|Geometry)', src))
    if "Vertex" not in decl or "Fragment" not in decl:
        continue
    stages = []
    for t, st in (("Vertex", "vertex"), ("Geometry", "geometry"), ("Fragment", "fragment")):
        if t not in decl:
            continue
        var, ver = decl[t]
        chain = re.search(r'\b' + var + r'\s*\.\s*(addSource\(.*?);', src, re.S).group(1)
        args, depth, cur = [], 0, ""
        for piece in re.split(r'(\.addSource\(|addSource\()', chain):
            if piece in (".addSource(", "addSource("):
                continue
            if piece.strip():
                args.append(piece.strip()[:-1].strip())  # drop the call's closing parenthesis
        parts = ["#version %s\n" % VERSIONS[ver]]
        for a in args:
            parts += ["#line 1 %d\n" % ((len(parts) + 1) // 2), source(a, d)]
        stages.append((st, var, "".join(parts)))
    write_program(out, "magnumex", f[4:-4].replace("/", "_"), stages)
    n += 1
print(n, "programs")
