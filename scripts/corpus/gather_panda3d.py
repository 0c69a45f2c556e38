#!/usr/bin/env python3
"""panda3d/panda3d: the GLSL programs of samples/ and tests/display/ as Panda3D loads them, plus
the GL GraphicsStateGuardian's built-in default shader.

Pairing:
- `Shader.load(Shader.SL_GLSL, "a.vert", "b.frag"[, "c.geom"])` (positional or vertex=,
  fragment=, geometry=) and `Shader.make(Shader.SL_GLSL, vert, frag[, geom])` with literal
  (or literal-bound) arguments in samples/**.py, found with Python's ast; file names are
  looked up next to the script (the sample directory is on the model path).
- tests/display/test_glsl_shader.py: the `glsl_gsg` fixture's two inline programs (GLSL 1.20
  and 1.50), each `run_glsl_compile_check(gsg, 'glsl_x' + suffix + '.vert', ...)` test that is
  expected to compile, once per suffix ('' for GLSL 1.50 drivers, '_legacy' for older), and
  every `run_glsl_test(gsg, code, preamble, ..., version=, exts=)` call as the compute shader
  GLSL_COMPUTE_TEMPLATE.format(...) builds (extension lines sorted: Panda iterates a set;
  `code`/`preamble` are the string bindings in force at the call). The expect_fail test
  (glsl_bad*.vert) and the angle-include-without-model-path test (load returns None) are left out.
- panda/src/glstuff/glGraphicsStateGuardian_src.cxx: `default_vshader` + `default_fshader`
  (desktop, non-Apple branch: `#version 130`), used when there is no fixed-function pipeline,
  and the two vertices-float64 variants (`default_vshader_fp64`, `default_vshader_fp64_gl41`).

Stage text: Panda adds no header (no #version, no defines). With glsl-preprocess on (the
default) Shader::do_read_source / do_load_source run r_preprocess_source line by line: `//`
and one `/* */` per line stripped, backslash continuations joined, `#pragma include "f"` /
`<f>` (and `#include "f"` under GL_GOOGLE_include_directive) replaced by the file's own
preprocessed text framed by `#line N 2048+k // name` directives, `#pragma once` honoured,
trailing whitespace stripped and one "\\n" appended. This script reimplements that.
Usage: gather_panda3d.py MIRROR_GIT_DIR OUT_DIR
"""
import ast, os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program, strip_cpp_comments, cpp_ifdefs, c_string_vars

m, out = Mirror(sys.argv[1]), sys.argv[2]


class Preproc:
    """Shader::r_preprocess_source / r_preprocess_include for one Shader object."""

    def __init__(self, model_path):
        self.model_path = model_path      # directories searched for includes
        self.included = []                # Shader::_included_files
        self.once = set()

    def find(self, fn, source_dir):
        for d in ([source_dir] if source_dir is not None else []) + self.model_path:
            p = posixpath.normpath(posixpath.join(d, fn))
            if m.exists(p):
                return p
        return None

    def include(self, out, fn, source_dir, depth):
        if depth > 10:
            raise ValueError("include depth")
        full = self.find(fn, source_dir)
        if full is None:
            raise ValueError("include not found: " + fn)
        if full in self.once:
            return
        fileno = 2048 + len(self.included)
        self.included.append(fn)
        self.source(out, m.text(full), fn, full, fileno, depth)

    def source(self, out, text, fn, full, fileno=0, depth=0):
        lines = text.split("\n")
        if lines and lines[-1] == "":
            lines.pop()                   # std::getline: no empty line after a final newline
        it = iter(lines)
        lineno, had_include, ext_inc, ext_line = 0, False, 0, 0
        wld = fileno != 0                 # write_line_directive

        def emit(line):
            nonlocal wld
            if wld:
                out.append(f"#line {lineno} {fileno} // {fn}\n")
                wld = False
            out.append(line + "\n")

        for line in it:
            lineno += 1
            if line == "":
                if not wld:
                    out.append("\n")
                continue
            while line.endswith("\\"):
                line = line[:-1]
                nxt = next(it, None)
                if nxt is None:
                    break
                line += nxt
                if not wld:
                    out.append("\n")
                lineno += 1
            lc, bc = line.find("//"), line.find("/*")
            lc = len(line) + 1 if lc < 0 else lc
            bc = len(line) + 1 if bc < 0 else bc
            if lc < bc:
                line = line[:lc]
            elif bc < lc:
                rest = line[bc + 2:]
                line = line[:bc] + " "
                end = rest.find("*/")
                while end < 0:
                    rest = next(it, None)
                    if rest is None:
                        raise ValueError("unterminated comment")
                    if not wld:
                        out.append("\n")
                    lineno += 1
                    end = rest.find("*/")
                line += rest[end + 2:]
            line = line.rstrip(" \t\r\n\v\f")
            if line == "":
                if not wld:
                    out.append("\n")
                continue
            d = re.match(r"\s*#\s*(\S{1,63})", line)
            if len(line) < 8 or not d:
                emit(line)
                continue
            directive = d.group(1)
            p = re.match(r"\s*#\s*pragma\s+(\S{1,63})", line)
            if directive == "pragma" and p:
                if p.group(1) == "include":
                    q = re.fullmatch(r'\s*#\s*pragma[ \t]+include\s*"([^"]+)"\s*', line)
                    a = re.fullmatch(r"\s*#\s*pragma[ \t]+include\s*<([^>]+)>\s*", line)
                    if q:
                        self.include(out, q.group(1), posixpath.dirname(full), depth + 1)
                    elif a:
                        self.include(out, a.group(1), None, depth + 1)
                    else:
                        raise ValueError("malformed #pragma include")
                    wld, had_include = True, True
                    continue
                if p.group(1) == "once":
                    if full:
                        self.once.add(full)
                    continue
            elif directive == "endif":
                if had_include:
                    wld = True
            elif directive == "extension":
                e = re.match(r"\s*#\s*extension[ \t]+([^: \t]+)\s*:\s*(\S{1,8})", line)
                if e:
                    mode = {"require": 2, "enable": 2, "warn": 1, "disable": 0}[e.group(2)]
                    if e.group(1) == "all":
                        ext_inc = ext_line = mode
                    elif e.group(1) == "GL_GOOGLE_include_directive":
                        ext_inc = ext_line = mode
                        continue
                    elif e.group(1) == "GL_GOOGLE_cpp_style_line_directive":
                        ext_line = mode
                        continue
            elif ext_inc > 0 and directive == "include":
                q = re.fullmatch(r'\s*#\s*include[ \t]+"([^"]+)"\s*', line)
                self.include(out, q.group(1), posixpath.dirname(full), depth + 1)
                wld, had_include = True, True
                continue
            elif ext_line > 0 and directive == "line":
                q = re.fullmatch(r'\s*#\s*line[ \t]+(\d+)[ \t]+"([^"]+)"\s*', line)
                if q:
                    lineno = int(q.group(1))
                    fileno = 2048 + len(self.included)
                    self.included.append(q.group(2))
                    out.append(f"#line {lineno} {fileno} // {q.group(2)}\n")
                    continue
            emit(line)


def finish(text):
    return text.rstrip(" \t\r\n\v\f") + "\n"


def read_stage(pp, path):
    """do_read_source: a file from the model path."""
    buf = []
    pp.source(buf, m.text(path), path, path)
    return finish("".join(buf))


def load_stage(pp, text):
    """do_load_source: a string (fn "created-shader", no directory)."""
    buf = []
    pp.source(buf, text, "created-shader", "")
    return finish("".join(buf))


STAGES = ("vertex", "fragment", "geometry")
programs = []  # (name, [(stage, stem, text)])


def add(name, stages):
    programs.append((name, [(s, stem, t) for s, stem, t in stages if t is not None]))


def literal(node, env):
    """str value of a constant / name bound to a constant in `env` / `a + b`."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.Name):
        return env.get(node.id)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        a, b = literal(node.left, env), literal(node.right, env)
        return a + b if a is not None and b is not None else None
    return None


def ordered_events(fn_node):
    """Assignments of str constants to names and calls inside fn_node, in source order."""
    ev = []
    for n in ast.walk(fn_node):
        if isinstance(n, ast.Assign) and len(n.targets) == 1 and isinstance(n.targets[0], ast.Name):
            ev.append((n.lineno, n.col_offset, 0, n))
        elif isinstance(n, ast.Call):
            ev.append((n.lineno, n.col_offset, 1, n))
    return [n for *_, n in sorted(ev, key=lambda e: (e[0], e[1], e[2]))]


def callee(call):
    f = call.func
    return f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", "")


def shader_args(call, env):
    """(vertex, fragment, geometry) expressions of Shader.load/make(SL_GLSL, ...)."""
    args = call.args[1:]
    kw = {k.arg: k.value for k in call.keywords if k.arg}
    return [args[i] if i < len(args) else kw.get(s) for i, s in enumerate(STAGES)]


# 1. samples/**.py: Shader.load / Shader.make with SL_GLSL.
for f in m.files:
    if not (f.startswith("samples/") and f.endswith(".py")):
        continue
    tree = ast.parse(m.text(f))
    module_env = {}
    for n in tree.body:
        if isinstance(n, ast.Assign) and len(n.targets) == 1 and isinstance(n.targets[0], ast.Name):
            v = literal(n.value, module_env)
            if v is not None:
                module_env[n.targets[0].id] = v
    sdir = posixpath.dirname(f)
    for call in ast.walk(tree):
        if not (isinstance(call, ast.Call) and callee(call) in ("load", "make") and call.args
                and isinstance(call.args[0], ast.Attribute) and call.args[0].attr == "SL_GLSL"):
            continue
        exprs = shader_args(call, module_env)
        vals = [literal(e, module_env) if e is not None else None for e in exprs]
        if vals[0] is None or vals[1] is None:
            continue
        pp = Preproc([sdir])
        if callee(call) == "load":
            paths = [posixpath.join(sdir, v) if v else None for v in vals]
            stages = [(s, posixpath.basename(p).split(".")[0], read_stage(pp, p))
                      for s, p in zip(STAGES, paths) if p]
            name = posixpath.basename(sdir) + "_" + posixpath.basename(paths[0]).split(".")[0]
        else:
            stages = [(s, s[:4], load_stage(pp, v) if v else None) for s, v in zip(STAGES, vals)]
            name = posixpath.basename(sdir) + "_" + posixpath.basename(f)[:-3] + "_inline"
        add(name, stages)

# 2. tests/display/test_glsl_shader.py
TD = "tests/display"
tpath = TD + "/test_glsl_shader.py"
tree = ast.parse(m.text(tpath))
template = None
for n in tree.body:
    if isinstance(n, ast.Assign) and getattr(n.targets[0], "id", "") == "GLSL_COMPUTE_TEMPLATE":
        template = n.value.value
funcs = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
# run_glsl_test's defaults
rdef = funcs["run_glsl_test"].args
rnames = [a.arg for a in rdef.args]
rdefaults = dict(zip(rnames[len(rnames) - len(rdef.defaults):], rdef.defaults))

# the glsl_gsg fixture: two inline programs
fx = funcs["glsl_gsg"]
for stmt in ast.walk(fx):
    if isinstance(stmt, ast.If) and any(isinstance(s, ast.Assign) for s in stmt.body):
        for branch, label in ((stmt.body, "glsl_gsg_120"), (stmt.orelse, "glsl_gsg_150")):
            benv = {}
            for s in branch:
                if isinstance(s, ast.Assign):
                    benv[s.targets[0].id] = literal(s.value, benv)
            pp = Preproc([])
            add(label, [("vertex", "vert", load_stage(pp, benv["vert"])),
                        ("fragment", "frag", load_stage(pp, benv["frag"]))])

# run_glsl_compile_check tests not expected to fail, once per suffix
for name, fn in funcs.items():
    if not name.startswith("test_"):
        continue
    checks = [c for c in ast.walk(fn) if isinstance(c, ast.Call) and callee(c) == "run_glsl_compile_check"]
    if not checks or any(k.arg == "expect_fail" and getattr(k.value, "value", False) for c in checks for k in c.keywords):
        continue
    for suffix in ("", "_legacy"):
        env = {"suffix": suffix}
        files = {}
        for node in ordered_events(fn):
            if isinstance(node, ast.Assign) and isinstance(node.value, ast.Call) and callee(node.value) == "Filename":
                v = literal(node.value.args[1], env) if len(node.value.args) > 1 else None
                if v is not None:
                    files[node.targets[0].id] = v
        vp, fp = files.get("vert_path"), files.get("frag_path")
        if not vp or not fp:
            continue
        # the model path holds tests/display when the test uses with_current_dir_on_model_path
        mp = [TD] if "with_current_dir_on_model_path" in [a.arg for a in fn.args.args] else []
        pp = Preproc(mp)
        add(name[5:] + (suffix or "_150"),
            [("vertex", vp.split(".")[0], read_stage(pp, f"{TD}/{vp}")),
             ("fragment", fp.split(".")[0], read_stage(pp, f"{TD}/{fp}"))])

# run_glsl_test compute programs
for name, fn in funcs.items():
    if not name.startswith("test_"):
        continue
    env, k = {}, 0
    for node in ordered_events(fn):
        if isinstance(node, ast.Assign):
            v = literal(node.value, env)
            if v is not None:
                env[node.targets[0].id] = v
            continue
        if callee(node) != "run_glsl_test":
            continue
        bound = dict(zip(rnames, node.args))
        bound.update({kw.arg: kw.value for kw in node.keywords if kw.arg})
        get = lambda a: bound.get(a, rdefaults.get(a))
        body, preamble = literal(get("body"), env), literal(get("preamble"), env)
        version = get("version").value
        exts = get("exts")
        extset = set(e.value for e in exts.elts) if isinstance(exts, ast.Set) else set()
        if body is None or preamble is None:
            continue
        extset |= {"GL_ARB_compute_shader", "GL_ARB_shader_image_load_store"}
        extensions = "".join(f"#extension {e} : require\n" for e in sorted(extset))
        code = template.format(version=version, extensions=extensions,
                               preamble=preamble.strip(), body=body.rstrip().lstrip("\n"))
        k += 1
        pp = Preproc([])
        programs.append((f"{name[5:]}_{k}", [("compute", "comp", load_stage(pp, code))]))

# 3. the GSG's default shader (desktop GL, not Apple)
gsg = m.text("panda/src/glstuff/glGraphicsStateGuardian_src.cxx")
a = gsg.index("static const string default_vshader")
b = gsg.index("uchar_bgr_to_rgb", a)
region = cpp_ifdefs(strip_cpp_comments(gsg[a:b]))
strs = {k: v[0] for k, v in c_string_vars(region).items()}
for vs, label in (("default_vshader", "gsg_default"), ("default_vshader_fp64", "gsg_default_fp64"),
                  ("default_vshader_fp64_gl41", "gsg_default_fp64_gl41")):
    pp = Preproc([])
    add(label, [("vertex", vs, load_stage(pp, strs[vs])),
                ("fragment", "default_fshader", load_stage(pp, strs["default_fshader"]))])

seen, n = set(), 0
for name, stages in programs:
    key = tuple((s, t) for s, _, t in stages)
    if key in seen:
        continue
    seen.add(key)
    write_program(out, "panda3d", name, stages)
    n += 1
print(n, "programs")
