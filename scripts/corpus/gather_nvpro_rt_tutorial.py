#!/usr/bin/env python3
"""Pairs the raster programs of nvpro-samples/vk_raytracing_tutorial_KHR as each tutorial builds them.

Each ray_tracing_*/ folder's *.cpp add stages to a graphics pipeline generator with
addShader(nvh::loadFile("spv/x.vert.spv", ..), VK_SHADER_STAGE_VERTEX_BIT): in source order a
vertex literal and the next fragment literal form one program (the scene raster pass
vert_shader+frag_shader, the tonemapper passthrough+post). Ray tracing stages are not used.
CMake compiles <folder>/shaders/* with glslangValidator --target-env vulkan1.2, no defines;
#include "x" (GL_GOOGLE_include_directive) is inlined from the same folder. Programs are
deduplicated by content. With a third argument the first few programs are also written there
unexpanded, the included files next to them.
Usage: gather_nvpro_rt_tutorial.py MIRROR_GIT_DIR OUT_DIR [INCLUDE_OUT_DIR]
"""
import os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

INCLUDE_SUBSET = 4
LIT = re.compile(r'"spv/([\w\-]+)\.(vert|frag)\.spv"')
INC = re.compile(r'^[ \t]*#\s*include\s+"([^"]+)"[^\n]*', re.M)


def inline(mirror, path, used):
    def sub(m):
        inc = posixpath.join(posixpath.dirname(path), m.group(1))
        used.add(inc)
        return inline(mirror, inc, used) if mirror.exists(inc) else m.group(0)
    return INC.sub(sub, mirror.text(path))


mirror, out = Mirror(sys.argv[1]), sys.argv[2]
inc_out = sys.argv[3] if len(sys.argv) > 3 else None
seen, n_inc = set(), 0
for folder in sorted({f.split("/")[0] for f in mirror.files if f.startswith("ray_tracing")}):
    vert = None
    for f in sorted(f for f in mirror.files if f.startswith(folder + "/") and f.endswith(".cpp")):
        for stem, ext in LIT.findall(mirror.text(f)):
            if ext == "vert":
                vert = stem
                continue
            if not vert:
                continue
            files = [("vertex", vert, f"{folder}/shaders/{vert}.vert"), ("fragment", stem, f"{folder}/shaders/{stem}.frag")]
            used = set()
            texts = tuple(inline(mirror, p, used) for _, _, p in files)
            vert = None
            if texts in seen:
                continue
            seen.add(texts)
            name = f"{folder}_{files[0][1]}_{stem}"
            write_program(out, "nvpro_rt", name, [(s, st, t) for (s, st, _), t in zip(files, texts)])
            if inc_out and n_inc < INCLUDE_SUBSET and used:
                d = write_program(inc_out, "nvpro_rt", name, [(s, st, mirror.show(p)) for s, st, p in files])
                for inc in used:
                    with open(os.path.join(d, posixpath.basename(inc)), "wb") as fh:
                        fh.write(mirror.show(inc))
                n_inc += 1
print(len(seen), "programs")
