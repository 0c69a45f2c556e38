#!/usr/bin/env python3
"""gameplay3d/GamePlay: programs from .material files (every `pass` with vertexShader,
fragmentShader, defines; `material a : b` inherits b's namespaces) and from literal
Effect::createFromFile / Material::create / setMaterial("x.vert", "y.frag"[, "defines"]) calls,
plus the built-in sprite and font effects.

Stage text as Effect::createFromSource passes it (3 strings): the defines (";"-separated,
each as "#define X\\n"; desktop: no OPENGL_ES), "\\n", then the file with every
`#include "p"` replaced by the file p next to the includer, plus "\\n". The shaders have no
#version (desktop GLSL 1.10). "res/x" is looked up in the sample's res/ and in gameplay/res/.
Usage: gather_gameplay.py MIRROR_GIT_DIR OUT_DIR
"""
import copy, os, posixpath, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]


def res(path, base):
    for root in (base, "gameplay/"):
        if m.exists(root + path):
            return root + path
    return None


def includes(path):
    src = m.text(path)
    d = path[:path.rfind("/") + 1]
    return re.sub(r'#include[^"]*"([^"]*)"', lambda mm: includes(d + mm.group(1)), src)


def stage(path, defines):
    ds = ";".join(x for x in [defines] if x)
    pre = ("#define " + ds.replace(";", "\n#define ") + "\n") if ds else ""
    body = includes(path)
    return pre + "\n" + body + ("\n" if body else "")


def parse_properties(text):
    """Tree of (type, id, parent, keys, children) from the Properties format."""
    text = re.sub(r'//[^\n]*', '', text)
    tokens = re.findall(r'\{|\}|[^\n{}]+', text)
    root = {"type": "", "id": "", "parent": None, "keys": {}, "children": []}
    stack = [root]
    pending = None
    for t in tokens:
        t = t.strip()
        if not t:
            continue
        if t == "{":
            node = {"type": "", "id": "", "parent": None, "keys": {}, "children": []}
            if pending:
                head, _, parent = pending.partition(":")
                parts = head.split()
                node["type"] = parts[0]
                node["id"] = parts[1] if len(parts) > 1 else ""
                node["parent"] = parent.strip() or None
            stack[-1]["children"].append(node)
            stack.append(node)
            pending = None
        elif t == "}":
            stack.pop()
        elif "=" in t:
            k, _, v = t.partition("=")
            stack[-1]["keys"][k.strip()] = v.strip()
        else:
            pending = t
    return root


def merge(base, over):
    base = copy.deepcopy(base)
    base["keys"].update(over["keys"])
    for c in over["children"]:
        same = [b for b in base["children"] if b["type"] == c["type"] and b["id"] == c["id"]]
        if same:
            base["children"][base["children"].index(same[0])] = merge(same[0], c)
        else:
            base["children"].append(c)
    return base


def passes(node):
    if node["type"] == "pass":
        yield node
    for c in node["children"]:
        yield from passes(c)


programs = []  # (vert, frag, defines, base, label)
for f in m.files:
    base = f.split("res/")[0] if "res/" in f else ""
    if f.endswith(".material"):
        mats = [c for c in parse_properties(m.text(f))["children"] if c["type"] == "material"]
        by_id = {c["id"]: c for c in mats}
        for mat in mats:
            full = merge(by_id[mat["parent"]], mat) if mat["parent"] in by_id else mat
            for p in passes(full):
                k = p["keys"]
                if "vertexShader" in k and "fragmentShader" in k:
                    programs.append((k["vertexShader"], k["fragmentShader"], k.get("defines", ""), base,
                                     posixpath.basename(f)[:-9] + "_" + mat["id"]))
    elif f.endswith(".cpp"):
        for v, fr, d in re.findall(r'(?:createFromFile|Material::create|setMaterial)\(\s*"([^"]+\.vert)"\s*,\s*"([^"]+\.frag)"(?:\s*,\s*"([^"]*)")?', m.text(f)):
            programs.append((v, fr, d, base, posixpath.basename(f)[:-4]))
programs += [("res/shaders/sprite.vert", "res/shaders/sprite.frag", "", "gameplay/", "SpriteBatch"),
             ("res/shaders/font.vert", "res/shaders/font.frag", "", "gameplay/", "Font"),
             ("res/shaders/font.vert", "res/shaders/font.frag", "DISTANCE_FIELD", "gameplay/", "Font")]

n, seen = 0, set()
for v, fr, d, base, label in programs:
    vp, fp = res(v, base), res(fr, base)
    if not vp or not fp or (vp, fp, d) in seen:
        continue
    seen.add((vp, fp, d))
    name = f"{label}_{posixpath.basename(vp)[:-5]}_{posixpath.basename(fp)[:-5]}_{d}"
    write_program(out, "gameplay", name, [("vertex", posixpath.basename(vp)[:-5], stage(vp, d)),
                                          ("fragment", posixpath.basename(fp)[:-5], stage(fp, d))])
    n += 1
print(n, "programs")
