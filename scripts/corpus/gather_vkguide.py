#!/usr/bin/env python3
"""Pairs vblanco20-1/vulkan-guide GLSL programs the way the engine code builds its pipelines.

The default branch holds only the web site; the code lives on branches all-chapters (legacy
tutorial), all-chapters-2 (new tutorial) and engine (extra chapter). In their chapter-*/*.cpp and
extra-engine/*.cpp, load_shader_module("../../shaders/x.vert.spv", &var) loads a module; the
modules (or "x.vert.spv" literals) pushed into the builder since the last _shaderStages.clear() /
set_shaders(vert, frag) form one program at each build_pipeline(...); build_effect(eng, "v.vert.spv",
"f.frag.spv") is one program on its own (an empty fragment name: vertex only). Shaders are compiled
one by one with glslangValidator -V (CMakeLists.txt), no defines; #include "x" (with
GL_GOOGLE_include_directive) is inlined from shaders/.
Usage: gather_vkguide.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

BRANCHES = ("all-chapters", "all-chapters-2", "engine")
STAGE = {"vert": "vertex", "frag": "fragment", "geom": "geometry"}
LIT = re.compile(r'"(?:[\w.]*/)*([\w\-]+)\.(vert|frag|geom|comp)\.spv"')
LOAD = re.compile(r'load_shader_module\([^;]*?' + LIT.pattern + r'[^;]*?&(\w+)')


class BranchMirror(Mirror):
    """A Mirror reading one branch instead of HEAD."""
    def __init__(self, git_dir, ref):
        self.git_dir, self.ref = git_dir, ref
        self.files = subprocess.run(["git", f"--git-dir={git_dir}", "ls-tree", "-r", "--name-only", ref],
                                    capture_output=True, text=True, check=True).stdout.splitlines()
        self._set = set(self.files)

    def show(self, path):
        if path not in self._set:
            return None
        return subprocess.run(["git", f"--git-dir={self.git_dir}", "show", f"{self.ref}:{path}"],
                              capture_output=True, check=True).stdout


def programs(src):
    var, cur = {}, {}
    for stmt in re.sub(r'//[^\n]*', '', src).split(";"):
        m = LOAD.search(stmt)
        if m:
            var[m.group(3)] = (m.group(2), m.group(1))
            continue
        effect = "build_effect(" in stmt and LIT.search(stmt)
        if "_shaderStages.clear()" in stmt or effect:
            cur = {}
        refs = [(m.start(), (m.group(2), m.group(1))) for m in LIT.finditer(stmt)]
        refs += [(m.start(), var[m.group(0)]) for m in re.finditer(r'\w+', stmt) if m.group(0) in var]
        for _, (ext, stem) in sorted(refs):
            cur = {} if ext == "comp" else {**cur, ext: stem}  # a compute module ends the graphics stages
        if effect or "build_pipeline(" in stmt:
            if "vert" in cur:
                yield dict(cur)
            if effect:
                cur = {}


def inline(mirror, path, depth=0):
    out = []
    for line in mirror.text(path).splitlines(keepends=True):
        m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
        inc = m and posixpath.normpath(posixpath.join(posixpath.dirname(path), m.group(1)))
        out.append(inline(mirror, inc, depth + 1) + "\n" if inc and mirror.exists(inc) and depth < 20 else line)
    return "".join(out)


def main():
    out, seen = sys.argv[2], set()
    for branch in BRANCHES:
        mirror = BranchMirror(sys.argv[1], branch)
        for f in mirror.files:
            if not (re.match(r'(chapter-\d[^/]*|extra-engine)/[^/]+\.cpp$', f)):
                continue
            for prog in programs(mirror.text(f)):
                stages = [(STAGE[e], s, inline(mirror, f"shaders/{s}.{e}")) for e, s in sorted(
                    prog.items(), key=lambda x: list(STAGE).index(x[0])) if mirror.exists(f"shaders/{s}.{e}")]
                key = tuple(t for _, _, t in stages)
                if len(stages) != len(prog) or key in seen:
                    continue
                seen.add(key)
                name = f"{branch}_" + "_".join(dict.fromkeys(s for _, s, _ in stages))
                while os.path.exists(os.path.join(out, "vkguide__" + name)):
                    name += "_"
                write_program(out, "vkguide", name, stages)
    print(len(seen), "programs")


if __name__ == "__main__":
    main()
