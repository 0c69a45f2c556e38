#!/usr/bin/env python3
"""wlroots (Wayland compositor library; GitHub mirror live-clones/wlroots, or swaywm/wlroots up to
its archiving): the Vulkan renderer's shader pairs.

Build (render/vulkan/shaders/meson.build): each file of `vulkan_shaders_src` is compiled on its
own by `glslang -V x -o x.h --vn <x>_data [--quiet]` (Vulkan 1.0, no -I, no defines).

Pairing (render/vulkan/renderer.c): `vkCreateShaderModule(.., &renderer->M)` after `.pCode =
<file>_data` binds module M to a shader file; every `VkPipelineShaderStageCreateInfo` in source
order with `.stage = VK_SHADER_STAGE_VERTEX_BIT, .module = renderer->V` opens a pipeline and each
following fragment stage `.module = renderer->F` gives one program V+F (the switch of the texture
pipeline: quad and texture; the blend->output pipeline: output). Specialization constants keep
their defaults. Programs `wlroots__<frag>`, FLAGS `-V -l`.
Usage: gather_wlroots.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402
from vkpost_common import expand, write_flags  # noqa: E402

ROOT = "render/vulkan/shaders"
EXT = {"vert": "vertex", "frag": "fragment", "comp": "compute", "geom": "geometry"}


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    meson = mirror.text(f"{ROOT}/meson.build") or ""
    block = re.search(r"vulkan_shaders_src\s*=\s*\[(.*?)\]", meson, re.S)
    built = re.findall(r"'([^']+)'", block.group(1)) if block else []
    by_data = {f.replace(".", "_").replace("-", "_") + "_data": f for f in built}
    src = strip_cpp_comments(mirror.text("render/vulkan/renderer.c"))
    modules = {}
    for m in re.finditer(r"\.pCode\s*=\s*(\w+)\s*,.*?vkCreateShaderModule\([^;]*?&renderer->(\w+)\s*\)", src, re.S):
        if m.group(1) in by_data:
            modules[m.group(2)] = by_data[m.group(1)]
    pairs, vert = [], None
    for m in re.finditer(r"\.stage\s*=\s*VK_SHADER_STAGE_(VERTEX|FRAGMENT)_BIT\s*,\s*\.module\s*=\s*renderer->(\w+)", src):
        f = modules.get(m.group(2))
        if f is None:
            continue
        if m.group(1) == "VERTEX":
            vert = f
        elif vert and (vert, f) not in pairs:
            pairs.append((vert, f))
    n = 0
    for vert, frag in pairs:
        stages = [(EXT[x.rsplit(".", 1)[1]], x.rsplit(".", 1)[0], expand(mirror, ROOT, x)) for x in (vert, frag)]
        d = write_program(out, "wlroots", frag.rsplit(".", 1)[0], stages)
        write_flags(d, "-V -l")
        n += 1
    print(n, "programs")


main()
