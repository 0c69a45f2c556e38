#!/usr/bin/env python3
"""GameTechDev/IntroductionToVulkan (Vulkan): Project/Tutorials/NN/TutorialNN.cpp creates
`CreateShaderModule("Data/Tutorials/NN/shader.vert.spv")` and the fragment module right after
for its one graphics pipeline; the .spv files are compiled from Project/Tutorials/NN/Data/
shader.vert / shader.frag (the build copies Data/ per tutorial), read as they are.
Usage: gather_intro_vulkan.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

EXT = {"vert": "vertex", "frag": "fragment", "geom": "geometry"}
m, out = Mirror(sys.argv[1]), sys.argv[2]
n = 0
for f in m.files:
    mm = re.match(r"Project/Tutorials/(\d+)/Tutorial\d+\.cpp$", f)
    if not mm:
        continue
    stages = []
    for p in re.findall(r'CreateShaderModule\(\s*"Data/Tutorials/\d+/([^"]+)\.spv"\s*\)', strip_cpp_comments(m.text(f))):
        text = m.text(f"Project/Tutorials/{mm.group(1)}/Data/{p}")
        if text is not None and p.rsplit(".", 1)[-1] in EXT:
            stages.append((EXT[p.rsplit(".", 1)[-1]], p.rsplit(".", 1)[0], text))
    if [s for s, _, _ in stages] == ["vertex", "fragment"]:
        write_program(out, "intro_vulkan", f"tutorial{mm.group(1)}", stages)
        n += 1
print(n, "programs")
