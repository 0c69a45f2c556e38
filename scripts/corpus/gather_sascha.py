#!/usr/bin/env python3
"""Pairs SaschaWillems/Vulkan GLSL programs as the examples load them.

examples/<ex>/<ex>.cpp calls loadShader(getShadersPath() + "<ex>/<stem>.vert.spv", ...);
a .vert and a .frag (and .geom) of the same stem in the same example form one program.
Usage: gather_sascha.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, subprocess, sys
git, out = sys.argv[1], sys.argv[2]
def show(p): return subprocess.run(["git", f"--git-dir={git}", "show", f"HEAD:{p}"], capture_output=True).stdout
files = subprocess.run(["git", f"--git-dir={git}", "ls-tree", "-r", "--name-only", "HEAD"], capture_output=True, text=True).stdout.split()
pat = re.compile(r'"([\w\-/]+)\.(vert|frag|geom|tesc|tese)\.spv"')
n = 0
for f in files:
    if not (f.startswith("examples/") and f.endswith(".cpp")):
        continue
    src = show(f).decode("utf-8", "replace")
    progs = {}
    for stem, ext in pat.findall(src):
        progs.setdefault(stem, set()).add(ext)
    for stem, exts in progs.items():
        if not {"vert", "frag"} <= exts or exts & {"tesc", "tese"}:
            continue  # tessellation programs are left out (no tessellation in the comparison)
        d = os.path.join(out, "sascha__" + stem.replace("/", "_"))
        ok = True
        for ext in exts:
            data = show(f"shaders/glsl/{stem}.{ext}")
            if not data:
                ok = False
                break
            os.makedirs(d, exist_ok=True)
            with open(os.path.join(d, os.path.basename(stem) + "." + ext), "wb") as fh:
                fh.write(data)
        # Included files, copied relative to the program.
        if ok:
            for ext in exts:
                for inc in re.findall(rb'#include\s+"([^"]+)"', show(f"shaders/glsl/{stem}.{ext}")):
                    src_path = os.path.normpath(os.path.join(os.path.dirname(f"shaders/glsl/{stem}"), inc.decode()))
                    data = show(src_path)
                    if data:
                        dst = os.path.normpath(os.path.join(d, inc.decode()))
                        os.makedirs(os.path.dirname(dst), exist_ok=True)
                        open(dst, "wb").write(data)
            n += 1
print(n, "programs")
