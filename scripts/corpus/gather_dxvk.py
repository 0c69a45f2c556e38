#!/usr/bin/env python3
"""doitsujin/dxvk (D3D-on-Vulkan; its swapchain presenter/blitter, HUD overlay, video blit and
format-conversion shaders): the built-in GLSL its meson build compiles, paired as the C++ sources
build pipelines.

Build (meson.build `glsl_generator`): `glslangValidator --quiet --target-env vulkan1.3 --vn <x>
--depfile .. x -o x.h` [-gVS] for each file of the `*_shaders = files([...])` lists of
src/*/meson.build (dxvk incl. hud/, d3d9, d3d11): Vulkan 1.3, no -I, no defines; `#include "x"`
resolves from the includer's directory and is inlined (vkpost_common.expand).

Pairing: in each src/**/*.cpp, in source order, the shader arrays named by their basename
(`DxvkBuiltInShaderStage(dxvk_present_vert, ..)`, `new DxvkSpirvShader(info, d3d9_..._frag)`,
`CreatePipeline(.., d3d9_convert_nv12, ..)`): a vertex shader opens a graphics pipeline and each
following fragment shader of that file gives one program with it (the ternaries' alternatives:
present_frag/_blit/_ms/_ms_blit, fixed_function_frag/_sample); a compute shader is a program of its
own (once). A fragment shader with no vertex shader before it in its file (dxvk_dummy_frag, the
pipeline-library placeholder) is left out. Specialization constants keep their defaults. Programs
`dxvk__<vert>_<frag>` / `dxvk__<comp>`, FLAGS `-V --target-env vulkan1.3 -l`.
Usage: gather_dxvk.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402
from vkpost_common import expand, write_flags  # noqa: E402

EXT = {"vert": "vertex", "frag": "fragment", "comp": "compute"}
FLAGS = "-V --target-env vulkan1.3 -l"


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    shaders = {}  # basename -> path (relative to repo root)
    for mb in mirror.files:
        if not re.fullmatch(r"src/[^/]+/meson\.build", mb):
            continue
        for block in re.findall(r"\w+_shaders\s*=\s*files\(\[(.*?)\]\)", mirror.text(mb), re.S):
            for f in re.findall(r"'([^']+\.(?:vert|frag|comp))'", block):
                p = posixpath.normpath(posixpath.join(posixpath.dirname(mb), f))
                if mirror.exists(p):
                    shaders[posixpath.basename(p).rsplit(".", 1)[0]] = p
    if not shaders:
        print(0, "programs")
        return
    ident = re.compile(r"\b(" + "|".join(sorted(map(re.escape, shaders), key=len, reverse=True)) + r")\b")
    programs = []
    for f in sorted(x for x in mirror.files if x.startswith("src/") and x.endswith(".cpp")):
        src = "\n".join(l for l in strip_cpp_comments(mirror.text(f)).split("\n") if not l.lstrip().startswith("#"))
        vert = None
        for m in ident.finditer(src):
            name = m.group(1)
            ext = shaders[name].rsplit(".", 1)[1]
            if ext == "vert":
                vert = name
            elif ext == "frag" and vert:
                key = (vert, name)
                if key not in programs:
                    programs.append(key)
            elif ext == "comp" and (name,) not in programs:
                programs.append((name,))
    n = 0
    for names in programs:
        stages = []
        for name in names:
            p = shaders[name]
            stages.append((EXT[p.rsplit(".", 1)[1]], name, expand(mirror, "src", p[len("src/"):])))
        d = write_program(out, "dxvk", "+".join(names), stages)
        write_flags(d, FLAGS)
        n += 1
    print(n, "programs")


main()
