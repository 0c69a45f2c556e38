#!/usr/bin/env python3
"""Pairs KhronosGroup/Vulkan-Samples GLSL programs the way the samples load them.

Each samples/**/*.cpp (and framework/) names its stage files in load calls:
load_shader("hdr", "bloom.vert.spv", ..) -> shaders/hdr/glsl/bloom.vert, load_shader("x/y.frag.spv"),
vkb::ShaderSource{"base.vert.spv"} -> shaders/base.vert, `cond ? "a.frag.spv" : "b.frag.spv"`.
A vertex shader reference opens a pipeline group; each later fragment reference (or ternary of
them) closes one program with it and any geometry shader seen in between; compute/mesh/task/ray
references end the group. A variable holding a loaded stage counts where it is used, not where
it is loaded. shader_object pairs stages through shaders/shader_object/shaders.json.
The build compiles with `glslc -I shaders/includes/glsl` (no defines): #include "x" is inlined
from the including file's folder, then shaders/includes/glsl; #pragma once is honoured.
Usage: gather_khronos_samples.py MIRROR_GIT_DIR OUT_DIR
"""
import json, os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

STAGE = {"vert": "vertex", "geom": "geometry", "frag": "fragment"}
EXTS = "vert|frag|geom|tesc|tese|comp|mesh|task|rgen|rchit|rmiss|rahit|rint|rcall"
LIT = re.compile(r'(?:"([\w\-]+)"\s*,\s*)?"([^"\n]*?)\.(' + EXTS + r')(?:\.spv)?"')
DEF = re.compile(r'^\s*(?:[\w:<>]+\s+)*?(?:const\s+)?[\w:<>]+\s+(\w+)\s*[({=]|^\s*(\w+)\s*=(?!=)')


def strip_comments(src):
    src = re.sub(r'/\*.*?\*/', ' ', src, flags=re.S)
    return re.sub(r'(?<![:"])//[^\n]*', ' ', src)


def resolve(m, sample, mirror):
    """Path of the GLSL file a literal names, trying the framework's folder conventions."""
    arg, path, ext = m.group(1), m.group(2).lstrip("/"), m.group(3)
    name = path.rsplit("/", 1)[-1]
    cands = [f"{arg}/glsl/{path}", f"{arg}/{path}"] if arg else []
    cands += [path, f"{posixpath.dirname(path)}/glsl/{name}", f"{sample}/glsl/{name}", f"{sample}/{name}"]
    for c in cands:
        if mirror.exists(f"shaders/{c}.{ext}"):
            return (ext, f"shaders/{c}.{ext}")
    return (ext, None)


def references(src, sample, mirror):
    """The stage references of a source file in order: lists of alternatives [(ext, path)]."""
    items, var, used = [], {}, set()
    for stmt in strip_comments(src).split(";"):
        head = re.split(r'[{}]\s*\n|\belse\b|\)\s*\n', stmt)[-1]  # the statement proper, after block starts
        d = DEF.match(head)
        name, lhs_end = (d.group(1) or d.group(2), len(stmt) - len(head) + d.end()) if d else (None, 0)
        refs, lits, i = [], list(LIT.finditer(stmt)), 0  # refs: (position, alternatives)
        while i < len(lits):
            alts = [lits[i]]
            while i + 1 < len(lits) and lits[i + 1].group(3) == alts[0].group(3) and \
                    ":" in stmt[lits[i].end():lits[i + 1].start()] and "," not in stmt[lits[i].end():lits[i + 1].start()]:
                i += 1
                alts.append(lits[i])
            refs.append((alts[0].start(), [resolve(a, sample, mirror) for a in alts]))
            i += 1
        for vname, alts in var.items():
            refs += [(m.start(), alts) for m in re.finditer(r'\b%s\b' % re.escape(vname), stmt)
                     if not (vname == name and m.start() < lhs_end)]
        refs.sort(key=lambda r: r[0])
        kinds = {e for _, alts in refs for e, _ in alts}
        if name and len(kinds) == 1:  # a variable holding a stage (or a choice of stages)
            old = [] if name in used or name not in var else var[name]
            var[name] = old + [a for _, alts in refs for a in alts if a not in old]
            used.discard(name)
            used.update(v for v in var if v != name and re.search(r'\b%s\b' % re.escape(v), stmt))
            continue
        items += [alts for _, alts in refs]
        used.update(v for v in var if re.search(r'\b%s\b' % re.escape(v), stmt))
    return items


def programs(items):
    """Groups references into programs: [(ext, path), ...] lists; groups with tessellation are left out."""
    group = None  # [vertex alternatives, geometry, fragment alternatives..., has tessellation]
    for alts in items + [[("vert", None)]]:
        ext = alts[0][0]
        if ext in ("vert", "comp", "mesh", "task") or ext.startswith("r"):
            if group and group[0] and not group[3]:
                for frags in group[2]:
                    verts = group[0]
                    pairs = zip(verts, frags) if len(verts) == len(frags) > 1 else [(v, f) for v in verts for f in frags]
                    for v, f in pairs:
                        yield [v] + group[1] + [f]
            group = [alts if ext == "vert" else None, [], [], False]
        elif group and ext == "geom":
            group[1] = alts[:1]
        elif group and ext == "frag":
            group[2].append(alts)
        elif group:
            group[3] = True


def shader_object(mirror):
    """shader_object binds stages from shaders.json: material vert x frag, each geom with the first vert."""
    data = json.loads(mirror.text("shaders/shader_object/shaders.json"))
    p = lambda f: ("vert" if ".vert" in f else "geom" if ".geom" in f else "frag",
                   "shaders/shader_object/" + f[:-4])
    as_list = lambda x: x if isinstance(x, list) else [x]
    groups = [data["skybox"], data["terrain"], *data["basic"].values(), data["post_process"]]
    for g in groups:
        for f in as_list(g["frag"]):
            yield [p(g["vert"]), p(f)]
    mat = data["material"]
    for f in mat["frag"]:
        for v in mat["vert"]:
            yield [p(v), p(f)]
        for g in mat["geo"]:
            yield [p(mat["vert"][0]), p(g), p(f)]


def inline(mirror, path, once=None, depth=0):
    """The file with its #include "x" lines replaced by the files, as glslc -I shaders/includes/glsl does."""
    once = set() if once is None else once
    out = []
    for line in mirror.text(path).splitlines(keepends=True):
        m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
        if re.match(r'\s*#\s*pragma\s+once', line):
            once.add(path)
            continue
        if not m:
            out.append(line)
            continue
        for c in (posixpath.normpath(posixpath.join(posixpath.dirname(path), m.group(1))),
                  "shaders/includes/glsl/" + m.group(1)):
            if mirror.exists(c):
                if c not in once and depth < 20:
                    body = inline(mirror, c, once, depth + 1)
                    out.append(body if body.endswith("\n") else body + "\n")
                break
        else:
            out.append(line)  # unresolved: left for the checker to report
    return "".join(out)


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    found = []
    for f in mirror.files:
        if f.startswith(("samples/", "framework/")) and f.endswith((".cpp", ".h")):
            sample = f.split("/")[-2]
            if sample != "shader_object":
                found += [(sample, p) for p in programs(references(mirror.text(f), sample, mirror))]
    found += [("shader_object", p) for p in shader_object(mirror)]
    seen, names = set(), set()
    for sample, prog in found:
        key = tuple(prog)
        if key in seen or any(p is None or not mirror.exists(p) for _, p in prog):
            continue
        seen.add(key)
        stems = []
        for _, p in prog:
            s = posixpath.basename(p).rsplit(".", 1)[0]
            if s not in stems:
                stems.append(s)
        name = posixpath.dirname(prog[0][1]).replace("shaders", "").replace("/glsl", "").strip("/") or "shaders"
        name = name + "_" + "_".join(stems)
        while name in names:
            name += "_"
        names.add(name)
        write_program(out, "khronos_samples", name,
                      [(STAGE[e], posixpath.basename(p).rsplit(".", 1)[0], inline(mirror, p)) for e, p in prog])
    print(len(seen), "programs")


main()
