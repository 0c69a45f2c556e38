#!/usr/bin/env python3
"""Pairs SaschaWillems/Vulkan-glTF-PBR GLSL programs the way src/main.cpp and base/ui.hpp build them.

Stage files are named by literals: addPipelineSet("pbr", "pbr.vert.spv", "material_pbr.frag.spv"),
shaderStages = { loadShader(device, "genbrdflut.vert.spv", ..), loadShader(.., "genbrdflut.frag.spv", ..) },
shaderStages[1] = loadShader(device, "irradiancecube.frag.spv", ..) in a switch after the
filtercube.vert. In source order a vertex literal opens a pipeline and each following fragment
literal makes one program with it. Shaders (data/shaders/) are compiled one by one with
glslangValidator -V, no defines; #include "includes/x.glsl" (GL_GOOGLE_include_directive) is inlined.
With a third argument, the programs using #include are also written there unexpanded, with
the included files next to them. Usage: gather_gltf_pbr.py MIRROR_GIT_DIR OUT_DIR [INCLUDE_OUT_DIR]
"""
import os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

STAGE = {"vert": "vertex", "frag": "fragment"}
LIT = re.compile(r'"([\w\-]+)\.(vert|frag)\.spv"')


def includes(mirror, path):
    return [posixpath.normpath(posixpath.join(posixpath.dirname(path), m))
            for m in re.findall(r'^[ \t]*#\s*include\s+"([^"]+)"', mirror.text(path), re.M)]


def inline(mirror, path):
    text = mirror.text(path)
    for inc in re.findall(r'^[ \t]*#\s*include\s+"([^"]+)"', text, re.M):
        full = posixpath.normpath(posixpath.join(posixpath.dirname(path), inc))
        text = re.sub(r'^[ \t]*#\s*include\s+"%s"' % re.escape(inc), lambda _: inline(mirror, full), text, flags=re.M)
    return text


mirror, out = Mirror(sys.argv[1]), sys.argv[2]
inc_out = sys.argv[3] if len(sys.argv) > 3 else None
progs, vert = [], None
for f in ("src/main.cpp", "base/ui.hpp"):
    for stem, ext in LIT.findall(mirror.text(f)):
        if ext == "vert":
            vert = stem
        elif vert and (vert, stem) not in progs:
            progs.append((vert, stem))
for vert, frag in progs:
    files = [("vertex", vert, f"data/shaders/{vert}.vert"), ("fragment", frag, f"data/shaders/{frag}.frag")]
    name = vert if vert == frag else f"{vert}_{frag}"
    write_program(out, "gltf_pbr", name, [(s, stem, inline(mirror, p)) for s, stem, p in files])
    incs = [i for _, _, p in files for i in includes(mirror, p)]
    if inc_out and incs:
        d = write_program(inc_out, "gltf_pbr", name, [(s, stem, mirror.show(p)) for s, stem, p in files])
        for inc in incs:
            os.makedirs(os.path.join(d, posixpath.dirname(posixpath.relpath(inc, "data/shaders"))), exist_ok=True)
            with open(os.path.join(d, posixpath.relpath(inc, "data/shaders")), "wb") as fh:
                fh.write(mirror.show(inc))
print(len(progs), "programs")
