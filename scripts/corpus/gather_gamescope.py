#!/usr/bin/env python3
"""ValveSoftware/gamescope (SteamOS micro-compositor): the compute shaders its meson build compiles.

Build (src/meson.build): `glsl_generator` runs `glslangValidator -V <x.comp> --vn <x> -o x.h
[--depfile ..] [--quiet]` on every file of `shader_src` (shaders/cs_*.comp): Vulkan 1.0, no -I,
no defines. `#include "x"` (GL_GOOGLE_include_directive) resolves from the includer's directory
and is inlined (vkpost_common.expand). Each .comp is a compute pipeline of its own (rendervulkan.cpp
creates one per shader and specialization), so each is a program `gamescope__<name>` of one
stage, FLAGS `-V -l`. Specialization constants keep their defaults (as glslang's verdict sees them).
Usage: gather_gamescope.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402
from vkpost_common import expand, write_flags  # noqa: E402

ROOT = "src"


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    meson = mirror.text(f"{ROOT}/meson.build") or ""
    block = re.search(r"shader_src\s*=\s*\[(.*?)\]", meson, re.S)
    files = re.findall(r"'([^']+\.comp)'", block.group(1)) if block else []
    n = 0
    for f in files:
        if not mirror.exists(f"{ROOT}/{f}"):
            continue
        name = posixpath.basename(f)[:-5]
        d = write_program(out, "gamescope", name, [("compute", name, expand(mirror, ROOT, f))])
        write_flags(d, "-V -l")
        n += 1
    print(n, "programs")


main()
