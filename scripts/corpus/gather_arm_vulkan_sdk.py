#!/usr/bin/env python3
"""ARM-software/vulkan-sdk (Vulkan): each sample's samples/<name>/<name>.cpp fills a stage array
with `shaderStages[k].module = loadShaderModule(device, "shaders/x.vert.spv")` before each
vkCreateGraphicsPipelines; a vertex module opens a program and the next fragment module closes
it (the compute sample's particle.comp pipeline left out). The .spv is glslc's output of
samples/<name>/shaders/x.vert (CMake add_shader), read as it is.
Usage: gather_arm_vulkan_sdk.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

EXT = {"vert": "vertex", "frag": "fragment", "geom": "geometry", "tesc": "tess-control", "tese": "tess-eval"}
m, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
for f in m.files:
    mm = re.match(r"samples/([^/]+)/[^/]+\.cpp$", f)
    if not mm:
        continue
    base = f"samples/{mm.group(1)}"
    cur = []
    for p in re.findall(r'loadShaderModule\(\s*\w+\s*,\s*"([^"]+)\.spv"\s*\)', strip_cpp_comments(m.text(f))):
        stage = EXT.get(p.rsplit(".", 1)[-1])
        if stage == "vertex":
            cur = []
        if stage is None or m.text(f"{base}/{p}") is None:
            cur = []
            continue
        cur.append((stage, os.path.basename(p).rsplit(".", 1)[0], m.text(f"{base}/{p}")))
        if stage == "fragment" and cur[0][0] == "vertex":
            write_program(out, "arm_vulkan_sdk", f"{mm.group(1)}.{cur[0][1]}", cur)
            n += 1
            cur = []
print(n, "programs")
