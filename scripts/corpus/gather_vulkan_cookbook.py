#!/usr/bin/env python3
"""Pairs PacktPublishing/Vulkan-Cookbook GLSL programs the way each sample's main.cpp loads them.

Samples/Source Files/<chapter>/<sample>/main.cpp reads precompiled stages with
GetBinaryFileContents("Data/Shaders/<chapter>/<sample>/x.vert.spv", ..) before creating each
pipeline; in source order a vertex stage opens a pipeline, a geometry stage joins it and a
fragment stage closes it (a vertex stage with no fragment stage, as the shadow pass: vertex only).
Pipelines with tessellation stages are left out. No includes, no defines.
Usage: gather_vulkan_cookbook.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

STAGE = {"vert": "vertex", "geom": "geometry", "frag": "fragment"}
LIT = re.compile(r'"Data/Shaders/([^"]+)\.(vert|geom|frag|tesc|tese|comp)\.spv"')


def pipelines(src):
    group = {}
    for path, ext in LIT.findall(src) + [(None, "vert")]:
        if ext in ("vert", "comp") and "vert" in group:
            yield group  # a vertex stage with no fragment stage
        if ext in ("vert", "comp"):
            group = {ext: path} if ext == "vert" else {}
        elif group:
            group[ext] = path
            if ext == "frag":
                yield group
                group = {}


mirror, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
for f in mirror.files:
    if not (f.startswith("Samples/Source Files/") and f.endswith("/main.cpp")):
        continue
    sample = f.split("/")[-2]
    for group in pipelines(mirror.text(f)):
        if set(group) - set(STAGE):
            continue  # tessellation
        stages = [(STAGE[e], os.path.basename(group[e]), mirror.text(f"Samples/Data/Shaders/{group[e]}.{e}"))
                  for e in STAGE if e in group]
        if any(t is None for _, _, t in stages):
            continue
        stems = "_".join(dict.fromkeys(s for _, s, _ in stages))
        write_program(out, "vulkan_cookbook", f"{sample}_{stems}", stages)
        n += 1
print(n, "programs")
