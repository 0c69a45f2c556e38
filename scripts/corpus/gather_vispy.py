#!/usr/bin/env python3
"""vispy/vispy gloo programs: `gloo.Program(vert, frag)` and `.set_shaders(vert, frag[, geom])`
calls in examples/ and vispy/ whose sources are literal strings (or names bound to them;
Python ast). Templated visual shaders ($name substitution) are skipped.

Text: gloo/preprocessor.py merge_includes (`#include "f"` replaced by vispy/glsl/f or
vispy/glsl/*/f wrapped in start/end comments, each file once per shader, 10 rounds) then
glir.py _convert_desktop_shader (precision statements and highp/mediump/lowp removed,
#extension lines moved to the top, `#version 120` added when absent).
Usage: gather_vispy.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program
from pyshaders import calls, kwargs, value

m, out = Mirror(sys.argv[1]), sys.argv[2]
INC = re.compile(r'\#\s*include\s*"(?P<filename>[a-zA-Z0-9\_\-\.\/]+)"')


def find(name):
    if m.exists("vispy/glsl/" + name):
        return "vispy/glsl/" + name
    return next((f for f in m.files if re.fullmatch(r"vispy/glsl/[^/]+/" + re.escape(name), f)), None)


def merge_includes(code):
    seen = []

    def repl(mm):
        name = mm.group("filename")
        if name in seen:
            return ""
        seen.append(name)
        path = find(name)
        if not path:
            raise KeyError(name)
        return '\n// --- start of "%s" ---\n' % name + m.text(path) + '// --- end of "%s" ---\n' % name
    for _ in range(10):
        if not INC.search(code):
            break
        code = INC.sub(repl, code)
    return code


def desktop(shader):
    has_version, lines, ext = False, [], []
    for line in shader.lstrip().splitlines():
        s = line.lstrip()
        has_version = has_version or line.startswith("#version")
        if s.startswith("precision "):
            line = ""
        if s.startswith("#extension"):
            ext.append(s)
            line = ""
        for prec in (" highp ", " mediump ", " lowp "):
            line = line.replace(prec, " ")
        lines.append(line.rstrip())
    for e in ext:
        lines.insert(has_version, e)
    if not has_version:
        lines.insert(0, "#version 120\n")
    return "\n".join(lines)


n, names = 0, set()
for f in m.files:
    if not (f.endswith(".py") and f.startswith(("examples/", "vispy/"))) or "/tests/" in f:
        continue
    for call, env in calls(m.text(f), {"Program", "set_shaders"}):
        kw, args = kwargs(call), call.args
        nodes = [kw.get("vert", args[0] if args else None), kw.get("frag", args[1] if len(args) > 1 else None)]
        if call.func.__class__.__name__ == "Attribute" and call.func.attr == "set_shaders":
            nodes.append(kw.get("geom", args[2] if len(args) > 2 else None))
        srcs = [value(nd, env) for nd in nodes]
        if not all(isinstance(s, str) for s in srcs[:2]) or (len(srcs) > 2 and srcs[2] is not None and not isinstance(srcs[2], str)):
            continue
        if any("$" in s for s in srcs if s):
            continue
        try:
            texts = [desktop(merge_includes(s)) if s else None for s in srcs]
        except KeyError:
            continue
        stages = [("vertex", "vert", texts[0])]
        if len(texts) > 2 and texts[2]:
            stages.append(("geometry", "geom", texts[2]))
        stages.append(("fragment", "frag", texts[1]))
        name = f[:-3].replace("examples/", "").replace("/", "_") + f"_{call.lineno}"
        write_program(out, "vispy", name, stages)
        n += 1
print(n, "programs")
