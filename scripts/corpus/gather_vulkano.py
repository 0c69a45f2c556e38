#!/usr/bin/env python3
"""vulkano-rs/vulkano examples: GLSL of `vulkano_shaders::shader! { ty: "vertex", src: "..." | path: "x.glsl",
[define: [("N", "v")], vulkan_version: "1.x", include: [..]] }` (also the `shaders: { name: { .. } }`
form), as vulkano-shaders compiles them with shaderc: a `path` is relative to the example crate
(the folder holding its Cargo.toml), `#include "f"` / `<f>` is expanded relative to the including
file (then vulkano-shaders/include, which holds vulkano.glsl, the crate, the include dirs), `define` entries become `#define N v` lines
right after #version. Pairing, per .rs file in source order: a vertex shader opens a
pipeline, tessellation/geometry shaders join it, a fragment shader closes it (one program);
a compute shader alone is one program; task/mesh/ray-tracing shaders are left out.
A vulkan_version other than 1.0 is written to FLAGS (`-V --target-env vulkan1.x -l`).
Usage: gather_vulkano.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402
from rustlit import LIT, span, split_top, strip_comments, value  # noqa: E402

TY = {"vertex": "vertex", "fragment": "fragment", "geometry": "geometry", "compute": "compute",
      "tess_ctrl": "tess-control", "tess_eval": "tess-eval"}


def crate_dir(m, path):
    d = posixpath.dirname(path)
    while d and not m.exists(d + "/Cargo.toml"):
        d = posixpath.dirname(d)
    return d


def expand(m, path, text, dirs, depth=0):
    def inc(mt):
        for base in [posixpath.dirname(path)] + dirs:
            p = posixpath.normpath(posixpath.join(base, mt.group(1)))
            t = m.text(p)
            if t is not None and depth < 20:
                return expand(m, p, t, dirs, depth + 1)
        raise FileNotFoundError(mt.group(1))
    return re.sub(r'^[ \t]*#[ \t]*include[ \t]*[<"]([^>"]+)[>"][^\n]*', inc, text, flags=re.M)


def shader(m, f, body):
    """(stage, text, vulkan_version) of one shader! body, or None."""
    opts = {}
    for field in split_top(body):
        kv = re.match(r"(\w+)\s*:\s*(.*)$", field, re.S)
        if kv:
            opts[kv.group(1)] = kv.group(2).strip()
    ty = re.fullmatch(r'"(\w+)"', opts.get("ty", ""))
    if not ty or ty.group(1) not in TY:
        return None
    crate = crate_dir(m, f)
    dirs = ["vulkano-shaders/include", crate] + [posixpath.normpath(posixpath.join(crate, value(x)))
                      for x in re.findall(LIT, opts.get("include", ""))]
    if "src" in opts:
        text, origin = value(opts["src"]), f
    elif "path" in opts:
        origin = posixpath.normpath(posixpath.join(crate, value(opts["path"])))
        text = m.text(origin)
        if text is None:
            return None
    else:
        return None
    try:
        text = expand(m, origin, text, dirs)
    except FileNotFoundError:
        return None
    defines = [[value(x.group(0)) for x in re.finditer(LIT, d)]
               for d in re.findall(r"\(([^()]*)\)", opts.get("define", ""))]
    if defines:
        lines = "".join(f"#define {d[0]} {d[1] if len(d) > 1 else ''}\n" for d in defines if d)
        text = re.sub(r"^([ \t]*#[ \t]*version[^\n]*\n)", lambda mt: mt.group(1) + lines, text, count=1, flags=re.M)
    vv = re.fullmatch(r'"1\.(\d)"', opts.get("vulkan_version", ""))
    return TY[ty.group(1)], text, (vv.group(1) if vv and vv.group(1) != "0" else None)


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written = 0
    for f in m.files:
        if not (f.startswith("examples/") and f.endswith(".rs")):
            continue
        src = strip_comments(m.text(f))
        found = []
        for c in re.finditer(r"shader!\s*\{", src):
            body = src[c.end():span(src, c.end() - 1) - 1]
            multi = re.match(r"\s*shaders\s*:\s*\{", body)
            if multi:
                inner = body[multi.end():span(body, multi.end() - 1) - 1]
                for e in re.finditer(r"(\w+)\s*:\s*\{", inner):
                    found.append(shader(m, f, inner[e.end():span(inner, e.end() - 1) - 1]))
            else:
                found.append(shader(m, f, body))
        example = f[len("examples/"):-3].replace("/main", "")
        pending, k = [], 0
        for s in found:
            if s is None:
                continue
            stage, text, vv = s
            if stage == "compute":
                progs = [[s]]
            elif stage == "vertex":
                pending, progs = [s], []
            elif stage in ("tess-control", "tess-eval", "geometry"):
                pending, progs = (pending + [s] if pending else []), []
            else:
                progs, pending = ([pending + [s]] if pending else []), []
            for p in progs:
                k += 1
                d = write_program(out, "vulkano", f"{example}.{k}", [(st, "shader", t) for st, t, _ in p])
                vers = [v for _, _, v in p if v]
                if vers:
                    with open(os.path.join(d, "FLAGS"), "w") as fh:
                        fh.write(f"-V --target-env vulkan1.{max(vers)} -l\n")
                written += 1
    print(written, "programs")


main()
