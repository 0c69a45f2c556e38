#!/usr/bin/env python3
"""urho3d/Urho3D GLSL shaders (bin/CoreData/Shaders/GLSL), paired the way the engine pairs them.

Pairs come from Techniques/*.xml passes (technique vs/ps/vsdefines/psdefines, pass overrides,
vsexcludes/psexcludes: Technique::BeginLoad), from RenderPaths and PostProcess `quad` and
`lightvolumes` commands, and from the UI/debug Basic+Stencil shaders in the C++. Renderer
variation defines (Renderer.cpp) are appended per pass lighting mode: per-pixel passes
(litbase/light/litalpha) get a few lightVSVariations/lightPSVariations pairs (+PCF_SHADOW),
per-vertex passes (base/alpha/material/deferred) NUMVERTEXLIGHTS, all scene passes a few
geometryVSVariations and heightFogVariations; capped at 20 programs per shader file.
Stage text (Shader::BeginLoad + OGL ShaderVariation::Create): #include lines expanded, the
other stage's function commented out, VS()/PS() renamed main(); then `#version` (the file's,
else 150), `#define COMPILEVS|COMPILEPS`, `#define MAXBONES 128`, one `#define X ` per
normalized (upper-cased, sorted) define, `#define GL3`, the code.
Usage: gather_urho3d.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, sys
import xml.etree.ElementTree as ET
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
SH = "bin/CoreData/Shaders/GLSL/"
GEOMETRY = ["", "SKINNED", "INSTANCED", "BILLBOARD"]
LIGHT = [("PERPIXEL DIRLIGHT", "PERPIXEL DIRLIGHT"),
         ("PERPIXEL SPOTLIGHT SHADOW", "PERPIXEL SPOTLIGHT SHADOW PCF_SHADOW"),
         ("PERPIXEL POINTLIGHT", "PERPIXEL POINTLIGHT CUBEMASK SPECULAR"),
         ("PERPIXEL DIRLIGHT SHADOW NORMALOFFSET", "PERPIXEL DIRLIGHT SPECULAR SHADOW NORMALOFFSET PCF_SHADOW")]
VERTEXLIGHTS = ["", "NUMVERTEXLIGHTS=2"]
FOG = ["", "HEIGHTFOG"]
PERVERTEX, PERPIXEL = {"base", "alpha", "material", "deferred"}, {"light", "litbase", "litalpha"}


def process(path):
    out = []
    for line in m.text(path).replace("\r", "").split("\n"):
        if line.startswith("#include"):
            out.append(process(posixpath.dirname(path) + "/" + line[9:].replace('"', "").strip()))
        else:
            out.append(line + "\n")
    return "".join(out)


def comment_out(code, sig):
    start = code.find(sig)
    if start < 0:
        return code
    code = code[:start] + "/*" + code[start:]
    level = 0
    for i in range(start + 2 + len(sig), len(code)):
        if code[i] == "{":
            level += 1
        elif code[i] == "}":
            level -= 1
            if level == 0:
                return code[:i + 1] + "*/" + code[i + 1:]
    return code


def variation(name, stage, defines):
    code = process(SH + name + ".glsl")
    if code.endswith("\n"):
        code = code[:-1]  # the last ReadLine() of the file adds "\n" only after a line
    own, other = ("VS", "PS") if stage == "VS" else ("PS", "VS")
    code = comment_out(code, f"void {other}(").replace(f"void {own}(", "void main(")
    text, ver_end = "", 0
    i = code.find("#")
    if i >= 0 and code[i + 1:i + 8] == "version":
        ver_end = i + 9
        while ver_end < len(code) and code[ver_end].isdigit():
            ver_end += 1
        text += code[i:ver_end] + "\n"
    if not ver_end:
        text += "#version 150\n"
    text += "#define COMPILEVS\n" if stage == "VS" else "#define COMPILEPS\n"
    text += "#define MAXBONES 128\n"
    for d in sorted(d for d in defines.upper().split(" ") if d):
        text += "#define " + d.replace("=", " ") + " \n"
    text += "#define GL3\n"
    return text + code[ver_end:]


def exclude(defs, excl):
    ex = set(excl.split())
    return " ".join(d for d in defs.split() if d not in ex) if ex else defs


programs = []  # (vs, vsdefines, ps, psdefines, label)
for f in m.files:
    if re.search(r'/Techniques/.+\.xml$', f):
        try:
            root = ET.fromstring(m.text(f))
        except ET.ParseError:
            continue
        gvs, gps = root.get("vs", ""), root.get("ps", "")
        gvd, gpd = root.get("vsdefines", ""), root.get("psdefines", "")
        for p in root.iter("pass"):
            vs, vd = (p.get("vs"), p.get("vsdefines", "")) if p.get("vs") else (gvs, (gvd + " " if gvd else "") + p.get("vsdefines", ""))
            ps, pd = (p.get("ps"), p.get("psdefines", "")) if p.get("ps") else (gps, (gpd + " " if gpd else "") + p.get("psdefines", ""))
            vd, pd = exclude(vd, p.get("vsexcludes", "")), exclude(pd, p.get("psexcludes", ""))
            name = p.get("name", "").lower()
            mode = p.get("lighting", "").lower() or ("pervertex" if name in PERVERTEX else "perpixel" if name in PERPIXEL else "unlit")
            label = posixpath.basename(f)[:-4] + "_" + name
            for g in GEOMETRY:
                if mode == "perpixel":
                    for lv, lp in LIGHT:
                        programs.append((vs, f"{vd} {lv} {g}", ps, f"{pd} {lp}", label))
                elif mode == "pervertex":
                    for vl in VERTEXLIGHTS:
                        programs.append((vs, f"{vd} {vl} {g}", ps, pd, label))
                else:
                    programs.append((vs, f"{vd} {g}", ps, pd, label))
            programs.append((vs, f"{vd}", ps, f"{pd} HEIGHTFOG", label))
    elif re.search(r'/(RenderPaths|PostProcess)/[^/]+\.xml$', f):
        root = ET.fromstring(m.text(f))
        for c in root.iter("command"):
            if c.get("type") == "quad" and c.get("vs"):
                programs.append((c.get("vs"), c.get("vsdefines", ""), c.get("ps"), c.get("psdefines", ""), posixpath.basename(f)[:-4]))
            elif c.get("type") == "lightvolumes":
                for lv, lp in (("DIRLIGHT", "PERPIXEL DIRLIGHT"), ("", "PERPIXEL POINTLIGHT SPECULAR"),
                               ("", "PERPIXEL SPOTLIGHT SHADOW PCF_SHADOW"), ("DIRLIGHT ORTHO", "PERPIXEL DIRLIGHT ORTHO")):
                    programs.append((c.get("vs"), lv + " " + c.get("vsdefines", ""), c.get("ps"), lp + " " + c.get("psdefines", ""), posixpath.basename(f)[:-4]))
for vd, pd in (("VERTEXCOLOR", "VERTEXCOLOR"), ("DIFFMAP VERTEXCOLOR", "DIFFMAP VERTEXCOLOR"),
               ("DIFFMAP VERTEXCOLOR", "DIFFMAP ALPHAMASK VERTEXCOLOR"), ("DIFFMAP VERTEXCOLOR", "ALPHAMAP VERTEXCOLOR")):
    programs.append(("Basic", vd, "Basic", pd, "UI"))
programs.append(("Stencil", "", "Stencil", "", "Renderer"))

# round-robin over technique passes so the per-file cap keeps variety
by_label = {}
for p in programs:
    by_label.setdefault(p[4], []).append(p)
rounds = [ps[i] for i in range(max(map(len, by_label.values()))) for ps in by_label.values() if i < len(ps)]
n, seen, per_file = 0, set(), {}
for vs, vd, ps, pd, label in rounds:
    norm = lambda s: " ".join(sorted(d for d in s.upper().split(" ") if d))
    key = (vs, norm(vd), ps, norm(pd))
    if key in seen or not m.exists(SH + vs + ".glsl") or not m.exists(SH + ps + ".glsl"):
        continue
    seen.add(key)
    if per_file.get(vs, 0) >= 20:
        continue
    per_file[vs] = per_file.get(vs, 0) + 1
    name = f"{vs}_{ps}_" + "_".join(norm(vd).split() + ["PS"] + norm(pd).split())
    write_program(out, "urho3d", name[:150], [("vertex", vs, variation(vs, "VS", vd)),
                                              ("fragment", ps, variation(ps, "PS", pd))])
    n += 1
print(n, "programs")
