#!/usr/bin/env python3
"""Pairs g-truc/ogl-samples programs the way the samples load them.

Each samples/<name>.cpp names its stage files in constants such as
VERT_SHADER_SOURCE_TEXTURE("gl-320/x.vert"); files whose constants share the suffix after
*_SHADER_SOURCE form one program. Usage: gather_oglsamples.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, subprocess, sys

git, out = sys.argv[1], sys.argv[2]
def show(path):
    return subprocess.run(["git", f"--git-dir={git}", "show", f"HEAD:{path}"], capture_output=True).stdout
files = subprocess.run(["git", f"--git-dir={git}", "ls-tree", "-r", "--name-only", "HEAD"], capture_output=True, text=True).stdout.split()
stage_of = {"VERT": "vert", "VERTEX": "vert", "FRAG": "frag", "FRAGMENT": "frag", "GEOM": "geom", "GEOMETRY": "geom"}
pat = re.compile(r'\b(VERT|VERTEX|FRAG|FRAGMENT|GEOM|GEOMETRY|CONT|CONTROL|EVAL|EVALUATION|COMP|COMPUTE)_SHADER_SOURCE(\w*)\s*\(\s*"([^"]+)"')
n = 0
for f in files:
    if not (f.startswith("samples/gl-") and f.endswith(".cpp")):
        continue
    src = show(f).decode("utf-8", "replace")
    progs = {}
    for kind, suffix, path in pat.findall(src):
        progs.setdefault(suffix, []).append((kind, path))
    sample = os.path.basename(f)[:-4]
    for suffix, stages in progs.items():
        kinds = [stage_of.get(k) for k, _ in stages]
        if None in kinds or "vert" not in kinds or "frag" not in kinds:
            continue  # tessellation/compute programs, or half programs
        d = os.path.join(out, f"oglsamples__{sample}{suffix.lower()}")
        os.makedirs(d, exist_ok=True)
        for (k, path), ext in zip(stages, kinds):
            data = show("data/" + path)
            if not data:
                break
            with open(os.path.join(d, os.path.basename(path).rsplit(".", 1)[0] + "." + ext), "wb") as fh:
                fh.write(data)
        n += 1
print(n, "programs")
