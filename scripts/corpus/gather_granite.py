#!/usr/bin/env python3
"""Themaister/Granite (engine, not tests/): the programs its C++ asks the ShaderManager for with
literal shader paths, compiled at run time by GLSLCompiler (granite_common.py: Granite's
`#include` splicing with `#line N "file"`, defines then `STAGE_* 1` in shaderc's preamble,
`builtin://` = assets/; the engine adds no include directory).

Call sites: `cmd.set_program("builtin://a.comp"[, "builtin://b.frag"], {defines})`,
`CommandBufferUtil::draw_fullscreen_quad(cmd, vert, frag[, {defines}])`,
`get_shader_manager().register_graphics(vert, frag)` / `register_compute(comp)` (their
`register_variant({})`: no defines) and `request_program(...)` with string paths; a path argument
is a "builtin://..." literal or a `const char *x = "builtin://..."` of the same file. Stages by
extension (.vert .frag .comp); programs with task/mesh stages, non-literal paths or a
non-literal define list (`defines` vectors built at run time, the renderer suites'
RenderQueue-driven variants) are left out. A literal define list `{{"NAME", expr}, ..}` gives one
program per value combination: a literal number as is, a `cond ? a : b` both arms, a comparison
0 and 1, a name its literal assignments in the file (`constexpr unsigned MaxLODIndirect = 8`,
`phase_int = 0/1`), `info.member` the literals engine .cpp files assign to `.member`; a call
with any other value (enum casts such as `Util::ecast(quality)`) is left out and reported.
Ternaries comparing one expression (`phase == 0 ? 1 : 0`, `phase == 1 ? 1 : 0`) are expanded
jointly over the values it is compared with (0 and 1), not as independent bits.
`register_compute/register_graphics(..)` take the define list of the `register_variant({..})`
that follows. A program whose preprocessing fails in GLSLCompiler itself is left out and
reported (none at 7c59ad8; the SMAA passes, left out for their SMAA_QUALITY, would be: a
`#include "SMAA.h"` inside a comment of the CRLF file post/SMAA.hlsl is still spliced, its
path keeping the `\r`). De-duplicated by stage texts; at most 80 programs (mirror.cap_sample).
FLAGS: `-V --target-env vulkan1.3 -l` (ShaderManager targets Vulkan 1.3 on a 1.3 device,
else 1.1).
Usage: gather_granite.py MIRROR_GIT_DIR OUT_DIR
"""
import itertools
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import write_program, strip_cpp_comments, c_string, cap_sample, call_args  # noqa: E402
from granite_common import GitTree, GraniteCompiler, EXT_STAGE  # noqa: E402

CALL = re.compile(r"\b(set_program|draw_fullscreen_quad|register_graphics|register_compute|request_program)\s*(?=\()")
DEF = re.compile(r'\{\s*"(\w+)"\s*,\s*([^{}]+?)\s*\}')


def values(expr, src, members):
    """Values a define expression takes, or None when it cannot be told from the source."""
    expr = expr.strip()
    if re.fullmatch(r"-?\d+", expr):
        return [int(expr)]
    m = re.fullmatch(r"(.+?)\?\s*(-?\d+)\s*:\s*(-?\d+)", expr)
    if m:
        return list(dict.fromkeys([int(m.group(2)), int(m.group(3))]))
    inner = re.fullmatch(r"int\((.*)\)", expr)
    inner = inner.group(1).strip() if inner else expr
    if re.search(r"!=|==|<|>|!", inner):
        return [0, 1]
    if re.fullmatch(r"\w+", inner):  # a constant or a local int with literal assignments
        vals = re.findall(rf"\b{inner}\s*=\s*(-?\d+)\s*;", src)
        return list(dict.fromkeys(int(v) for v in vals)) or None
    m = re.fullmatch(r"\w+(?:\.|->)(\w+)", inner)
    if m and members.get(m.group(1)):  # a struct member: the literals the engine assigns it
        return sorted(members[m.group(1)])
    return None


def combos(defs, exprs):
    """Define value combinations; `S == N ? a : b` arms on the same S are taken jointly (one
    S value at a time, over the values it is compared with), the rest independently."""
    subj = {}
    for e in exprs:
        m = re.fullmatch(r"(.+?)\s*==\s*(-?\d+)\s*\?\s*(-?\d+)\s*:\s*(-?\d+)", e.strip())
        if m:
            subj.setdefault(m.group(1).strip(), set()).add(int(m.group(2)))
    subj = {k: sorted(v) for k, v in subj.items() if sum(
        1 for e in exprs if e.strip().startswith(k)) > 1}
    keys = list(subj)
    free = [i for i, e in enumerate(exprs) if not any(e.strip().startswith(k) for k in keys)]
    out = []
    for sv in itertools.product(*(subj[k] for k in keys)):
        for fv in itertools.product(*(defs[i][1] for i in free)):
            vals = dict(zip(free, fv))
            for i, e in enumerate(exprs):
                if i in vals:
                    continue
                m = re.fullmatch(r"(.+?)\s*==\s*(-?\d+)\s*\?\s*(-?\d+)\s*:\s*(-?\d+)", e.strip())
                vals[i] = int(m.group(3)) if sv[keys.index(m.group(1).strip())] == int(m.group(2)) else int(m.group(4))
            dv = [(defs[i][0], vals[i]) for i in range(len(defs))]
            if dv not in out:
                out.append(dv)
    return out


def main():
    tree, out = GitTree(sys.argv[1]), sys.argv[2]

    unresolved = set()

    def resolve(path):
        proto, _, p = path.partition("://")
        return (tree, "assets/" + p) if proto == "builtin" else (None, None)

    comp = GraniteCompiler(resolve, [])
    found, members, exprs = [], {}, {}
    for f in tree.files:
        if f.endswith(".cpp") and not f.startswith(("tests/", "third_party/", "slangmosh/")):
            for mem, v in re.findall(r"\.(\w+)\s*=\s*(-?\d+)\s*;", tree.text(f)):
                members.setdefault(mem, set()).add(int(v))
    for f in sorted(p for p in tree.files if p.endswith(".cpp") and not p.startswith(("tests/", "slangmosh/", "third_party/"))):
        src = tree.text(f)
        if "builtin://shaders/" not in src:
            continue
        src = strip_cpp_comments(src)
        for m in CALL.finditer(src):
            args = call_args(src, m.end())
            if m.group(1).startswith("register_"):  # the define list of the variant then registered
                rv = re.compile(r"register_variant\s*(?=\()").search(src, m.end(), m.end() + 400)
                if rv:
                    args += [a for a in call_args(src, rv.end()) if a.startswith("{")]
            paths, defs, ok = [], [], True
            for a in args:
                if a.startswith('"builtin://'):
                    paths.append(c_string(a))
                elif re.fullmatch(r"\w+", a) and re.search(rf'\bconst\s+char\s*\*\s*{a}\s*=\s*"builtin://', src[:m.start()]):
                    lit = re.findall(rf'\bconst\s+char\s*\*\s*{a}\s*=\s*("builtin://[^"]*")', src[:m.start()])[-1]
                    paths.append(c_string(lit))
                elif a.startswith("{"):
                    defs = DEF.findall(a)
                elif re.fullmatch(r"\w+", a) and a not in ("cmd", "device") and paths:
                    ok = False  # a define list built at run time
            if not paths or not ok or any(p.rsplit(".", 1)[-1] not in EXT_STAGE for p in paths):
                continue
            vals = [values(e, src, members) for _, e in defs]
            if any(v is None for v in vals):
                unresolved.add(f"{'+'.join(paths)}: " + ", ".join(n for (n, _), v in zip(defs, vals) if v is None))
                continue
            dl = [(n, v) for (n, _), v in zip(defs, vals)]
            exprs[id(dl)] = [e for _, e in defs]
            found.append((f, paths, dl))
    programs, seen, failed = [], set(), set()
    for f, paths, defs in found:
        for dv in combos(defs, exprs[id(defs)]):
            stages = []
            try:
                for p in paths:
                    stage = EXT_STAGE[p.rsplit(".", 1)[1]]
                    stem = os.path.splitext(p[len("builtin://shaders/"):])[0].replace("/", ".")
                    stages.append((stage, stem.rsplit(".", 1)[-1], comp.stage_text(p, stage, dv), stem))
            except KeyError as e:  # GLSLCompiler::preprocess fails: "Failed to include GLSL file"
                failed.add(f"{'+'.join(paths)}: {e.args[0]}")
                continue
            key = tuple(t for _, _, t, _ in stages)
            if key in seen:
                continue
            seen.add(key)
            name = "+".join(dict.fromkeys(s for _, _, _, s in stages)) + "".join(f".{k}{v}" for k, v in dv)
            programs.append((name, [(st, stem, t) for st, stem, t, _ in stages]))
    programs = cap_sample(programs, 80, key=lambda p: p[0])
    for name, stages in programs:
        d = write_program(out, "granite", name, stages)
        with open(os.path.join(d, "FLAGS"), "w") as fh:
            fh.write("-V --target-env vulkan1.3 -l\n")
    for f in sorted(unresolved):
        print("left out (define value not known from the source):", f, file=sys.stderr)
    for f in sorted(failed):
        print("left out (Granite's preprocessor fails):", f, file=sys.stderr)
    print(len(programs), "programs of", len(seen))


main()
