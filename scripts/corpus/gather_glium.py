#!/usr/bin/env python3
"""glium/glium: programs of examples/*.rs and tests/*.rs as glium builds them (sources verbatim).

- `program!(facade, N [es] => { vertex: S, fragment: S[, geometry: S,
  tessellation_control: S, tessellation_evaluation: S, ...] }, ...)`: one program per
  version block (glium picks the block the context supports; every block is kept).
- `Program::from_source(facade, vs, fs, None | Some(gs))`, kept only when the call is
  unwrapped (`.unwrap()`, `?`), not when a test expects an error.
S is a string literal, a `let`/`const` binding of one in the file, or include_str!("p")
(relative to the .rs file). Usage: gather_glium.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402
from rustlit import LIT, bindings, span, split_top, strip_comments, value  # noqa: E402

FIELDS = {"vertex": "vertex", "fragment": "fragment", "geometry": "geometry",
          "tessellation_control": "tess-control", "tessellation_evaluation": "tess-eval"}


def resolve(m, path, expr, binds):
    expr = expr.strip().lstrip("&")
    if re.fullmatch(LIT, expr, re.S):
        return value(expr)
    inc = re.fullmatch(r'include_str!\(\s*"([^"]+)"\s*\)', expr)
    if inc:
        return m.text(posixpath.normpath(posixpath.join(posixpath.dirname(path), inc.group(1))))
    return binds.get(expr)


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, set()
    for f in m.files:
        if not (f.startswith(("examples/", "tests/")) and f.endswith(".rs")):
            continue
        src = strip_comments(m.text(f))
        binds = bindings(src)
        stem = posixpath.basename(f)[:-3]
        progs = []
        for c in re.finditer(r"\bprogram!\s*\(", src):
            body = src[c.end():span(src, c.end() - 1) - 1]
            for b in re.finditer(r"(\d+)\s*(es)?\s*=>\s*\{", body):
                block = body[b.end():span(body, b.end() - 1) - 1]
                stages = []
                for field in split_top(block):
                    kv = re.match(r"(\w+)\s*:\s*(.*)$", field, re.S)
                    if kv and kv.group(1) in FIELDS:
                        stages.append((FIELDS[kv.group(1)], resolve(m, f, kv.group(2), binds)))
                progs.append((f"{stem}.{b.group(1)}{'es' if b.group(2) else ''}", stages))
        for c in re.finditer(r"Program::from_source\s*\(", src):
            end = span(src, c.end() - 1)
            if not re.match(r"\s*(\.unwrap\(\)|\?|\.expect\()", src[end:end + 30]):
                continue
            args = split_top(src[c.end():end - 1])
            if len(args) < 3:
                continue
            stages = [("vertex", resolve(m, f, args[1], binds)), ("fragment", resolve(m, f, args[2], binds))]
            g = re.fullmatch(r"Some\((.*)\)", args[3], re.S) if len(args) > 3 else None
            if g:
                stages.append(("geometry", resolve(m, f, g.group(1), binds)))
            progs.append((f"{stem}.from_source", stages))
        for name, stages in progs:
            if not stages or any(t is None for _, t in stages) or "vertex" not in [s for s, _ in stages]:
                continue
            key = tuple(stages)
            if key in seen:
                continue
            seen.add(key)
            n = 1
            while os.path.exists(os.path.join(out, f"glium__{name}{'' if n == 1 else '.' + str(n)}")):
                n += 1
            write_program(out, "glium", name + ("" if n == 1 else f".{n}"), [(s, "shader", t) for s, t in stages])
            written += 1
    print(written, "programs")


main()
