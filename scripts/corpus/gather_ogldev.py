#!/usr/bin/env python3
"""Pairs emeiri/ogldev programs the way the tutorials load them.

Technique classes (Common/technique.cpp) build one program per Init(): the
`AddShader(GL_<STAGE>_SHADER, "path")` calls up to Finalize(). A `switch` or `if (...) {} else {}`
around AddShader calls gives one program per branch. A path parameter (FullScreenTechnique::Init(
const char* pFragmentShaderFile)) takes each string passed to `...Init("x.fs")` in the project.
The early tutorials read `pVSFileName`/`pFSFileName` (or `ReadFile("shader.vs", vs)`) and attach
both. Paths are relative to the working directory: the .cpp's directory or the nearest parent
holding the file. ReadFile() re-joins getline() lines with "\n", so that is the text sent.
Programs with compute stages are left out (Vulkan/ is not GL).
Usage: gather_ogldev.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, graphics_stages, write_program

STAGES = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry",
          "TESS_CONTROL": "tess-control", "TESS_EVALUATION": "tess-eval", "COMPUTE": "compute"}
ADD = re.compile(r'AddShader\(\s*GL_(\w+)_SHADER\s*,\s*("[^"]*"|\w+)\s*\)')


def read_file(m, path):
    """ogldev_util.cpp ReadFile: getline() lines, each followed by "\n"."""
    lines = m.show(path).decode("latin-1").split("\n")
    if lines[-1] == "":
        lines.pop()
    return "".join(l + "\n" for l in lines).encode("latin-1")


def resolve(m, cpp, path):
    d = os.path.dirname(cpp)
    while True:
        p = os.path.normpath(os.path.join(d, path))
        if m.exists(p):
            return p
        if not d:
            return None
        d = os.path.dirname(d)


def block_end(text, start):
    """End of the brace block whose `{` is the first one at or after start."""
    depth = 0
    for i in range(text.index("{", start), len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return i + 1
    return len(text)


def variants(seg):
    """The AddShader lists one Init() segment can produce, one per switch case / if branch."""
    for b in re.finditer(r"\bswitch\s*\(|\bif\s*\((?!\s*!)[^)]*\)\s*\{", seg):
        end = block_end(seg, b.start())
        has_else = seg[end:].lstrip().startswith("else")
        if has_else:
            end = block_end(seg, end)
        body = seg[b.start():end]
        if not ADD.search(body):
            continue
        if body.startswith("switch"):  # cases without an AddShader (default: exit) are dropped
            alts = [a for a in re.split(r"\bcase\b[^:]*:|\bdefault\s*:", body)[1:] if ADD.search(a)]
        else:
            alts = re.split(r"\}\s*else\s*\{", body) if has_else else [body, ""]
        head = ADD.findall(seg[:b.start()])
        return [head + ADD.findall(alt) + t for alt in alts for t in variants(seg[end:])]
    return [ADD.findall(seg)]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    cpps = [f for f in m.files if f.endswith(".cpp") and not f.startswith(("Vulkan/", "Include/"))
            and "3rdparty" not in f]
    init_args = {}  # project dir -> strings passed to Init("...")
    for f in cpps:
        for a in re.findall(r'\bInit\(\s*"([^"]+\.\w+)"\s*\)', m.text(f)):
            init_args.setdefault(f.split("/")[0], []).append(a)
    progs = {}
    for f in cpps:
        src = re.sub(r"//[^\n]*|/\*.*?\*/", "", m.text(f), flags=re.S)
        lists = []
        if "AddShader(GL_" in src:
            for seg in re.split(r"\bFinalize\(\)", src):
                params = re.findall(r"Init\(\s*const\s+char\s*\*\s*(\w+)\s*\)", seg)
                for v in variants(seg):
                    for p in params:  # one program per string passed for the path parameter
                        if any(path == p for _, path in v):
                            v = [[(st, f'"{a}"' if path == p else path) for st, path in v]
                                 for a in init_args.get(f.split("/")[0], [])]
                            break
                    else:
                        v = [v]
                    lists += v
        else:
            names = dict(re.findall(r'(p[VFG]SFileName)\s*=\s*"([^"]+)"', src))
            reads = re.findall(r'ReadFile\(\s*("[^"]+"|\w+)\s*,', src)
            files = [names.get(r, r.strip('"')) for r in reads]
            stage = {"vs": "VERTEX", "fs": "FRAGMENT", "gs": "GEOMETRY", "cs": "TESS_CONTROL", "es": "TESS_EVALUATION"}
            if files and all(x.rsplit(".", 1)[-1] in stage for x in files):
                lists.append([(stage[x.rsplit(".", 1)[-1]], f'"{x}"') for x in files])
        for shaders in lists:
            kinds = [STAGES.get(st) for st, _ in shaders]
            paths = [resolve(m, f, p.strip('"')) if p.startswith('"') else None for _, p in shaders]
            if None in paths or not graphics_stages(kinds):
                continue
            key = tuple(zip(kinds, paths))
            name = os.path.dirname(f).replace("/", "_") + "." + \
                "+".join(dict.fromkeys(os.path.basename(p).rsplit(".", 1)[0] for p in paths))
            progs.setdefault(key, name)
    names = list(progs.values())
    for key, name in progs.items():
        if names.count(name) > 1:
            name += "." + "+".join(os.path.basename(p) for _, p in key)
        write_program(out, "ogldev", name, [(k, os.path.basename(p).rsplit(".", 1)[0], read_file(m, p))
                                            for k, p in key])
    print(len(progs), "programs")


if __name__ == "__main__":
    main()
