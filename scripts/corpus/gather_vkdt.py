#!/usr/bin/env python3
"""hanatos/vkdt (Vulkan raw photo processor): every shader stage its Makefile compiles, paired as
the pipeline loads them.

Build (src/Makefile, bin/config.mk.defaults): every `pipe/modules/*/*.{comp,vert,tesc,tese,geom,frag}`
(one directory level) is compiled on its own, from src/, by
`glslangValidator -Ipipe/modules -I<module dir>/ --target-env vulkan1.3 x.comp -o x.comp.spv`
(`--target-env vulkan1.3` implies -V; no defines), and gui/shd/gui.{vert,frag} by
`glslangValidator -Igui --target-env vulkan1.3`. `#include "x"` (GL_GOOGLE_include_directive) is
resolved as glslangValidator's DirStackFileIncluder does: the includer's directory, then the
directories of the files that included it (innermost first), then the -I directories last to first
(the module directory, then pipe/modules); no once-only handling (the sources have no guards or
`#pragma once`). The include is inlined as glslang's preprocessor sees it: `#line 1 "<path>"`, the
file (expanded the same way), `#line <next> "<includer>"` (paths relative to src/, normalised); an
include that cannot be found is left for the checker to report.

Pairing (pipe/graph-run-nodes-allocate.h, pipe/graph.c dt_graph_create_shader_module): a node's
kernel K of module M is `modules/M/K.comp.spv` (a compute pipeline), or `K.vert.spv` + `K.frag.spv`
for a graphics node (main.vert present: draw, overlay); so each .comp is one compute program and
each .vert with its same-named .frag one graphics program; the GUI's nuklear pipeline is
gui.vert + gui.frag. Programs are `vkdt__<module>.<kernel>` (`vkdt__gui`), with FLAGS
`-V --target-env vulkan1.3 -l`.
Usage: gather_vkdt.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

EXT_STAGE = {"comp": "compute", "vert": "vertex", "tesc": "tess-control", "tese": "tess-eval",
             "geom": "geometry", "frag": "fragment"}
INC = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"')


def expand(mirror, path, ext_dirs, stack=(), depth=0):
    """The text of src/`path` with its includes inlined; `stack` holds the directories of the
    files that included it (outermost first)."""
    text = mirror.text("src/" + path)
    dirs = list(stack) + [posixpath.dirname(path)]
    out = []
    lines = text.split("\n")
    for no, line in enumerate(lines, start=1):
        m = INC.match(line)
        found = None
        if m and depth < 32:
            for d in list(reversed(dirs)) + list(reversed(ext_dirs)):
                cand = posixpath.normpath(posixpath.join(d, m.group(1)))
                if mirror.exists("src/" + cand):
                    found = cand
                    break
        if not found:
            out.append(line)
            continue
        body = expand(mirror, found, ext_dirs, dirs, depth + 1)
        out.append(f'#line 1 "{found}"\n{body}\n#line {no + 1} "{path}"')
    return "\n".join(out)


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    files = [f[4:] for f in mirror.files if re.fullmatch(r"src/pipe/modules/[^/]+/[^/]+\.(comp|vert|tesc|tese|geom|frag)", f)]
    n = 0
    for f in sorted(files):
        module, base = f.split("/")[2], posixpath.basename(f)
        kernel, ext = base.rsplit(".", 1)
        ext_dirs = ["pipe/modules", posixpath.dirname(f)]
        if ext == "comp":
            stages = [("compute", kernel, expand(mirror, f, ext_dirs))]
        elif ext == "vert":
            stages = [(EXT_STAGE[e], kernel, expand(mirror, f[:-4] + e, ext_dirs))
                      for e in ("vert", "tesc", "tese", "geom", "frag") if mirror.exists(f"src/{f[:-4]}{e}")]
        else:
            continue  # compiled, but only loaded with its kernel's vertex stage
        d = write_program(out, "vkdt", f"{module}.{kernel}", stages)
        with open(os.path.join(d, "FLAGS"), "w") as fh:
            fh.write("-V --target-env vulkan1.3 -l\n")
        n += 1
    if mirror.exists("src/gui/shd/gui.vert"):
        stages = [(EXT_STAGE[e], "gui", expand(mirror, f"gui/shd/gui.{e}", ["gui"])) for e in ("vert", "frag")]
        d = write_program(out, "vkdt", "gui", stages)
        with open(os.path.join(d, "FLAGS"), "w") as fh:
            fh.write("-V --target-env vulkan1.3 -l\n")
        n += 1
    print(n, "programs")


main()
