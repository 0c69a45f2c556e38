#!/usr/bin/env python3
"""pythonarcade/arcade: every `ctx.program(...)` / `ctx.load_program(...)` call in arcade/,
doc/ and tests/ with literal (or literal-bound) sources is one program.

load_program reads the files (":system:x" is arcade/resources/system/x, other paths are
relative to the calling file, `CURRENT_DIR / "x"` too) and expands `#include :system:...`
lines (Context.shader_inc). Then, per stage, arcade/gl/glsl.py ShaderSource: text stripped,
`common` sources inserted before the line holding main(), `defines` substituted into matching
#define lines. Transform-feedback (no fragment stage) and tessellation programs are skipped.
Usage: gather_arcade.py MIRROR_GIT_DIR OUT_DIR
"""
import ast, os, posixpath, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program
from pyshaders import calls, kwargs, value

m, out = Mirror(sys.argv[1]), sys.argv[2]


def resolve(node, env, pyfile):
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div):
        rel = value(node.right, env)
        return posixpath.normpath(posixpath.join(posixpath.dirname(pyfile), rel)) if isinstance(rel, str) else None
    p = value(node, env)
    if not isinstance(p, str):
        return None
    if p.startswith(":system:"):
        return posixpath.normpath("arcade/resources/system/" + p[len(":system:"):].lstrip("/"))
    if p.startswith(":resources:"):
        return posixpath.normpath("arcade/resources/assets/" + p[len(":resources:"):].lstrip("/"))
    return posixpath.normpath(posixpath.join(posixpath.dirname(pyfile), p))


def shader_inc(src):
    lines = src.splitlines()
    for i, line in enumerate(lines):
        if line.strip().startswith("#include"):
            lines[i] = m.text(resolve(ast.Constant(line.split()[1].replace('"', "")), {}, ""))
    return "\n".join(lines)


def shader_source(src, common, defines):
    lines = src.strip().split("\n")
    if not lines[0].strip().startswith("#version"):
        return None
    if common:
        nr = next(i for i, l in enumerate(lines) if "main()" in l)
        for c in common:
            lines = lines[:nr] + c.split("\n") + lines[nr:]
    for nr, line in enumerate(lines):
        s = line.strip()
        if defines and s.startswith("#define") and len(s.split()) > 1 and s.split()[1] in defines:
            lines[nr] = "#define {} {}".format(s.split()[1], defines[s.split()[1]])
    return "\n".join(lines)


n, names = 0, set()
for f in m.files:
    if not (f.endswith(".py") and f.startswith(("arcade/", "doc/", "tests/"))):
        continue
    for call, env in calls(m.text(f), {"program", "load_program"}):
        kw = kwargs(call)
        if "fragment_shader" not in kw or "vertex_shader" not in kw or any(k.startswith("tess") for k in kw):
            continue
        defines = value(kw["defines"], env) if "defines" in kw else {}
        if defines is None:
            continue
        stages = [(st, kw.get(st + "_shader")) for st in ("vertex", "geometry", "fragment") if kw.get(st + "_shader")]
        try:
            if call.func.attr == "load_program":
                paths = [resolve(node, env, f) for _, node in stages]
                common = [m.text(resolve(c, env, f)) for c in (kw["common"].elts if "common" in kw else [])]
                srcs = [shader_inc(m.text(p)) for p in paths]
                stems = [posixpath.basename(p).rsplit(".", 1)[0] for p in paths]
            else:
                srcs = [value(node, env) for _, node in stages]
                common = value(kw["common"], env) if "common" in kw else []
                stems = [st for st, _ in stages]
            texts = [shader_source(s, common, defines) for s in srcs]
        except (TypeError, AttributeError, StopIteration):
            continue
        if None in texts:
            continue
        name = f[:-3].split("/")[-1] + "_" + (stems[-1] if call.func.attr == "load_program" else str(call.lineno))
        if name in names:
            name += f"_{call.lineno}"
        names.add(name)
        write_program(out, "arcade", name, [(st, stem, t) for (st, _), stem, t in zip(stages, stems, texts)])
        n += 1
print(n, "programs")
