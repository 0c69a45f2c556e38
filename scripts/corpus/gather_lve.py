#!/usr/bin/env python3
"""Pairs blurrypiano/littleVulkanEngine GLSL programs the way the engine builds its pipelines.

Every branch is a stage of the tutorial series (main, tut23..tut27, pointLights, ...; master and
tut0-22 hold one folder per episode, littleVulkanEngine/tutorialNN/). Render systems create
LvePipeline(device, "shaders/x.vert.spv", "shaders/x.frag.spv", config): in source order a vertex
literal and the next fragment literal form one program, read from the shaders/ folder of the
nearest enclosing project folder (CMake compiles each with glslangValidator, no defines).
Programs are deduplicated by content. Usage: gather_lve.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import write_program
from gather_vkguide import BranchMirror

LIT = re.compile(r'"(?:[\w.]+/)*shaders/([\w\-]+)\.(vert|frag)\.spv"')

git, out = sys.argv[1], sys.argv[2]
branches = subprocess.run(["git", f"--git-dir={git}", "for-each-ref", "--format=%(refname:short)", "refs/heads"],
                          capture_output=True, text=True, check=True).stdout.split()
seen = set()
for branch in branches:
    mirror = BranchMirror(git, branch)
    for f in mirror.files:
        if not f.endswith((".cpp", ".hpp")):
            continue
        vert = None
        for stem, ext in LIT.findall(mirror.text(f)):
            if ext == "vert":
                vert = stem
                continue
            if not vert:
                continue
            d = posixpath.dirname(f)
            while d and not mirror.exists(f"{d}/shaders/{vert}.vert"):
                d = posixpath.dirname(d)
            base = f"{d}/shaders/" if d else "shaders/"
            texts = (mirror.text(f"{base}{vert}.vert"), mirror.text(f"{base}{stem}.frag"))
            if None in texts or texts in seen:
                continue
            seen.add(texts)
            project = posixpath.basename(d) if d else "root"
            name = f"{branch}_{project}_{vert}" if vert == stem else f"{branch}_{project}_{vert}_{stem}"
            write_program(out, "lve", name, [("vertex", vert, texts[0]), ("fragment", stem, texts[1])])
            vert = None
print(len(seen), "programs")
