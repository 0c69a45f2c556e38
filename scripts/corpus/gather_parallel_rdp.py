#!/usr/bin/env python3
"""Themaister/parallel-rdp (N64 RDP on Vulkan compute): programs as its own CMake build makes them.

parallel-rdp/CMakeLists.txt defines PARALLEL_RDP_SHADER_DIR, so rdp_renderer.cpp and
video_interface.cpp take the `#ifdef PARALLEL_RDP_SHADER_DIR` branch: `cmd.set_program("rdp://x.comp",
{{"NAME", expr}, ..})` (a compute program) or `cmd.set_program("rdp://v.vert", "rdp://f.frag",
{..})` (vertex + fragment), compiled at run time by Granite's ShaderManager / GLSLCompiler
(granite_common.py: Granite's own `#include` splicing with `#line N "file"`, the defines then
`STAGE_* 1` in shaderc's preamble). `rdp://` is parallel-rdp/shaders/; the renderer adds the
include directory `builtin://shaders/inc` (Granite's assets/shaders/inc, read from the Granite
submodule's pinned commit in a Themaister/Granite mirror). Define values: a literal as is; an
expression on `debug_channel` (RDP_DEBUG, off by default) takes its false arm; any other
expression (`caps.x ? 1 : 0`, `int(caps.ubershader)`) both 0 and 1, one program each.
FLAGS: `-V --target-env vulkan1.3 -l` (ShaderManager targets Vulkan 1.3 on a 1.3 device).
Usage: gather_parallel_rdp.py RDP_MIRROR_GIT_DIR GRANITE_MIRROR_GIT_DIR OUT_DIR
"""
import itertools
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import write_program, strip_cpp_comments  # noqa: E402
from granite_common import GitTree, GraniteCompiler, EXT_STAGE  # noqa: E402

CALL = re.compile(r'set_program\(\s*"(rdp://[^"]+)"(?:\s*,\s*"(rdp://[^"]+)")?\s*(?:,\s*\{(?P<defs>(?:[^{}]|\{[^{}]*\})*)\}\s*)?\)\s*;')
DEF = re.compile(r'\{\s*"(\w+)"\s*,\s*([^{}]+?)\s*\}')


def values(expr):
    expr = expr.strip()
    if re.fullmatch(r"-?\d+", expr):
        return [int(expr)]
    m = re.fullmatch(r"(.+?)\?\s*(-?\d+)\s*:\s*(-?\d+)", expr)
    if m and "debug_channel" in m.group(1):
        return [int(m.group(3))]
    if m:
        return [int(m.group(2)), int(m.group(3))]
    return [0, 1]


def main():
    rdp_git, granite_git, out = sys.argv[1:4]
    rdp = GitTree(rdp_git)
    pin = subprocess.run(["git", f"--git-dir={rdp_git}", "ls-tree", "HEAD", "Granite"],
                         capture_output=True, text=True, check=True).stdout.split()[2]
    granite = GitTree(granite_git, pin)

    def resolve(path):
        proto, _, p = path.partition("://")
        return {"rdp": (rdp, "parallel-rdp/shaders/" + p), "builtin": (granite, "assets/" + p)}.get(proto, (None, None))

    comp = GraniteCompiler(resolve, ["builtin://shaders/inc"])
    n, seen = 0, set()
    for f in ("parallel-rdp/rdp_renderer.cpp", "parallel-rdp/video_interface.cpp"):
        for m in CALL.finditer(strip_cpp_comments(rdp.text(f))):
            paths = [p for p in m.groups()[:2] if p]
            defs = DEF.findall(m.group("defs") or "")
            names = [d for d, _ in defs]
            for vals in itertools.product(*(values(e) for _, e in defs)):
                dv = list(zip(names, vals))
                stages = []
                for p in paths:
                    stage = EXT_STAGE[p.rsplit(".", 1)[1]]
                    stages.append((stage, os.path.splitext(p[6:])[0], comp.stage_text(p, stage, dv)))
                key = tuple(t for _, _, t in stages)
                if key in seen:
                    continue
                seen.add(key)
                suffix = "".join(f".{k}{v}" for k, v in dv if k != "DEBUG_ENABLE")
                d = write_program(out, "parallel_rdp", "+".join(s for _, s, _ in stages) + suffix, stages)
                with open(os.path.join(d, "FLAGS"), "w") as fh:
                    fh.write("-V --target-env vulkan1.3 -l\n")
                n += 1
    print(n, "programs")


main()
