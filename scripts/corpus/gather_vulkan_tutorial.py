#!/usr/bin/env python3
"""Pairs the Vulkan Tutorial's GLSL programs (Overv/VulkanTutorial code/, KhronosGroup/Vulkan-Tutorial
attachments/) as its CMakeLists.txt builds them.

`add_chapter(NN_name SHADER X)` compiles X.vert and X.frag (glslangValidator --target-env
vulkan1.0, no defines) into the chapter's vert.spv/frag.spv: one program per distinct X.
The source name is taken from the layout: code/ -> overv_tutorial, attachments/ -> khronos_tutorial.
Usage: gather_vulkan_tutorial.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

mirror, out = Mirror(sys.argv[1]), sys.argv[2]
folder = "code" if mirror.exists("code/CMakeLists.txt") else "attachments"
source = {"code": "overv_tutorial", "attachments": "khronos_tutorial"}[folder]
cmake = mirror.text(f"{folder}/CMakeLists.txt")
n = 0
for shader in dict.fromkeys(re.findall(r'add_chapter\s*\(\s*\w+\s+SHADER\s+(\w+)', cmake)):
    stages = [(stage, shader, mirror.text(f"{folder}/{shader}.{ext}"))
              for stage, ext in (("vertex", "vert"), ("fragment", "frag"))]
    if all(text is not None for _, _, text in stages):
        write_program(out, source, shader, stages)
        n += 1
print(n, "programs")
