#!/usr/bin/env python3
"""DadSchoorse/vkBasalt (Vulkan post-processing layer): its built-in effects, paired as the effect
classes create their pipelines.

Build (src/shader/meson.build): every `src/shader/*.{vert,frag}.glsl` listed in `shader_src` is
compiled on its own by `glslangValidator -V -x x.frag.glsl -o x.frag.h` (stage from the second
extension, Vulkan 1.0, no -I and no defines); `#include "x.h"` (GL_GOOGLE_include_directive)
resolves in src/shader/ and is inlined (vkpost_common.expand).

Pairing: effect_cas/deband/dls/fxaa/lut.cpp hand `full_screen_triangle_vert` + `<effect>_frag`
to SimpleEffect (one graphics pipeline each); effect_smaa.cpp builds three pipelines: smaa_edge_vert
with smaa_edge_color_frag or smaa_edge_luma_frag (config `smaaEdgeDetection`, both kept),
smaa_blend_vert + smaa_blend_frag, smaa_neighbor_vert + smaa_neighbor_frag. Programs are
`vkbasalt__<effect>` with FLAGS `-V -l` (Vulkan 1.0). ReShade .fx effects are not GLSL: left out.
Usage: gather_vkbasalt.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402
from vkpost_common import expand, write_flags  # noqa: E402

ROOT = "src/shader"


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    meson = mirror.text(f"{ROOT}/meson.build") or ""
    built = set(re.findall(r"'([^']+\.glsl)'", meson))
    pairs = []
    for f in sorted(mirror.files):
        m = re.fullmatch(r"src/effect_(\w+)\.cpp", f)
        if not m:
            continue
        src = mirror.text(f)
        # SimpleEffect subclasses: vertexCode = a_vert; fragmentCode = b_frag;
        v = re.search(r"vertexCode\s*=\s*(\w+)_vert\s*;", src)
        fr = re.search(r"fragmentCode\s*=\s*(\w+)_frag\s*;", src)
        if v and fr:
            pairs.append((m.group(1), v.group(1), fr.group(1)))
            continue
        # Effects that create their modules themselves: createShaderModule(.., x_vert, ..) then
        # the fragment module(s) of that pipeline (a ternary names alternatives).
        mods = re.findall(r"createShaderModule\(\s*\w+\s*,\s*(\w+)\s*,", src)
        alts = {a: [x for x in re.findall(r"(\w+_frag)\b", b)] for a, b in
                re.findall(r"auto\s+(\w+)\s*=\s*([^;]*);", src)}
        vert = None
        for mod in mods:
            if mod.endswith("_vert"):
                vert = mod[:-5]
            elif vert:
                frags = alts.get(mod, [mod])
                for frag in frags:
                    if frag.endswith("_frag"):
                        pairs.append((frag[:-5], vert, frag[:-5]))
                vert = None
    n = 0
    for name, vert, frag in pairs:
        vf, ff = f"{vert}.vert.glsl", f"{frag}.frag.glsl"
        if vf not in built or ff not in built:
            continue
        stages = [("vertex", vert, expand(mirror, ROOT, vf)), ("fragment", frag, expand(mirror, ROOT, ff))]
        d = write_program(out, "vkbasalt", name, stages)
        write_flags(d, "-V -l")
        n += 1
    print(n, "programs")


main()
