#!/usr/bin/env python3
"""OGRECave/ogre sample media: one program per material technique whose pass references GLSL
programs, as OGRE's script compiler and GL render system load them.

Scripts: every .program / .material / .compositor under Media/ and Samples/Media/ (all resource
locations of the samples' resources.cfg). `vertex_program NAME LANGS {source ..., attach ...,
preprocessor_defines ...}` (also fragment_program, geometry_program, tessellation_*_program)
defines a program; a LANGS list holding `glsl` is GLSL (the universal `glsl glsles glslang hlsl`
programs too), `unified` programs resolve to their first GLSL `delegate`. Material techniques'
passes with `vertex_program_ref` + `fragment_program_ref` (+ geometry/tessellation refs) that all
resolve to GLSL make a program; `material A : B` starts from B's techniques and overrides its
refs per technique/pass index; `abstract` materials are skipped; identical programs once.

Stage text as GLSLShaderCommon::prepareImpl builds it for the GL render system (native GLSL
version 330): `OGRE_NATIVE_GLSL_VERSION_DIRECTIVE` replaced by `#version 330`, `#include`
resolved from the media by file name (HighLevelGpuProgram::_resolveIncludes, `#line 1 0` /
`#line N 0` around the text), the builtin defines (OGRE_GLSL=330, OGRE_<TYPE>_SHADER) and the
program's preprocessor_defines as `#define` lines after #version (OGRE runs its own
preprocessor with them; the GLSL preprocessor gives the same text, except `__VERSION__`, which
OGRE's is 100 without #version: substituted as 100 then), backslash-continued lines
joined as that preprocessor does. `attach` child programs go
in as further units of the same stage.
Usage: gather_ogre.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

NATIVE = 330
KINDS = {"vertex_program": "vertex", "fragment_program": "fragment", "geometry_program": "geometry",
         "tessellation_hull_program": "tess-control", "tessellation_domain_program": "tess-eval"}
TYPE_NAME = {"vertex": "VERTEX", "fragment": "FRAGMENT", "geometry": "GEOMETRY", "tess-control": "HULL",
             "tess-eval": "DOMAIN"}
REFS = {"vertex_program_ref": "vertex", "fragment_program_ref": "fragment", "geometry_program_ref": "geometry",
        "tessellation_hull_program_ref": "tess-control", "tessellation_domain_program_ref": "tess-eval"}
ORDER = ["vertex", "tess-control", "tess-eval", "geometry", "fragment"]


def parse(text):
    """OGRE script text -> list of nodes (header tokens, children | None, properties)."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.S)
    toks = re.findall(r"\{|\}|[^\s{}]+|\n", text)
    root = []
    stack = [root]
    line = []
    for t in toks:
        if t == "\n":
            if line:
                stack[-1].append((line, None))
                line = []
        elif t == "{":
            if not line and stack[-1] and stack[-1][-1][1] is None:
                line = stack[-1].pop()[0]  # header on the line before the brace
            node = (line, [])
            stack[-1].append(node)
            stack.append(node[1])
            line = []
        elif t == "}":
            if line:
                stack[-1].append((line, None))
                line = []
            if len(stack) > 1:
                stack.pop()
        else:
            line.append(t)
    return root


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    media = [f for f in m.files if f.startswith(("Media/", "Samples/Media/")) and "/GLSLES/" not in f
             and "Emscripten" not in f]
    by_name = {}
    for f in media:
        by_name.setdefault(os.path.basename(f), f)
    programs, materials = {}, {}
    for f in media:
        if not f.endswith((".program", ".material", ".compositor")):
            continue
        for head, body in parse(m.text(f)):
            if body is None or not head:
                continue
            if head[0] in KINDS and len(head) >= 3:
                props = {}
                for h, b in body:
                    if b is None and h:
                        props.setdefault(h[0], []).append(h[1:])
                programs[head[1]] = (KINDS[head[0]], head[2:], props)
            elif head[0] == "material" and len(head) >= 2:
                parent = head[3] if len(head) >= 4 and head[2] == ":" else None
                materials[head[1]] = (parent, body)
            elif head[0] == "abstract":
                continue

    def glsl(name, seen=()):
        p = programs.get(name)
        if not p or name in seen:
            return None
        kind, langs, props = p
        if "unified" in langs:
            for d in props.get("delegate", []):
                r = glsl(d[0], seen + (name,))
                if r:
                    return r
            return None
        return name if "glsl" in langs and "source" in props else None

    def include(text, depth=0):
        def rep(mm):
            inc = by_name.get(os.path.basename(mm.group(2)))
            if inc is None or depth > 8:
                return mm.group(0)
            line = text.count("\n", 0, mm.start()) + 2
            return "#line 1 0\n" + include(m.text(inc), depth + 1) + f"\n#line {line} 0"
        return re.sub(r'^([ \t]*)#include\s*["<]([^">]+)[">]', lambda mm: rep(mm), text, flags=re.M)

    def stage_text(name):
        kind, langs, props = programs[name]
        src = by_name.get(props["source"][0][0])
        if src is None:
            return None
        text = m.text(src).replace("OGRE_NATIVE_GLSL_VERSION_DIRECTIVE", f"#version {NATIVE}", 1)
        text = re.sub(r"\\[ \t]*\r?\n", "", include(text))  # CPreprocessor joins continued lines
        # `#ifdef OGRE_GLSL` / `#version N` / `#endif` (Isosurf): OGRE_GLSL is defined for CPreprocessor,
        # which keeps the #version line and blanks the directives
        text = re.sub(r"\A([ \t]*\n)*[ \t]*#[ \t]*ifdef[ \t]+OGRE_GLSL[ \t]*\n([ \t]*#[ \t]*version[^\n]*\n)[ \t]*#[ \t]*endif[^\n]*\n",
                      lambda mm: "\n" * mm.group(0)[:mm.start(2) - mm.start(0)].count("\n") + mm.group(2) + "\n", text)
        defs = [f"OGRE_GLSL {NATIVE}", f"OGRE_{TYPE_NAME[kind]}_SHADER"]
        for d in props.get("preprocessor_defines", []):
            for item in " ".join(d).replace(";", ",").split(","):
                item = item.strip()
                if item:
                    k, _, v = item.partition("=")
                    defs.append(f"{k.strip()} {v.strip()}".strip())
        block = "".join(f"#define {d}\n" for d in defs)
        v = re.search(r"^[ \t]*#version[^\n]*\n", text, re.M)
        if v:
            text = text[:v.end()] + block + f"#line {text.count(chr(10), 0, v.end()) + 1}\n" + text[v.end():]
        else:
            # OGRE's CPreprocessor runs with __VERSION__ = mShaderVersion, 100 when the source has
            # no #version (GLSLShaderCommon::prepareImpl); the GL compiler would see 110, so bake it in
            text = block + "#line 1\n" + re.sub(r"\b__VERSION__\b", "100", text)
        return text

    def techniques(name, depth=0):
        """[[{stage: program name}, ...per pass], ...per technique] of a material."""
        parent, body = materials[name]
        techs = [list(map(dict, t)) for t in techniques(parent, depth + 1)] if parent in materials and depth < 8 else []
        ti = 0
        for h, b in body:
            if b is None or not h or h[0] != "technique":
                continue
            if ti >= len(techs):
                techs.append([])
            pi = 0
            for ph, pb in b:
                if pb is None or not ph or ph[0] != "pass":
                    continue
                if pi >= len(techs[ti]):
                    techs[ti].append({})
                for rh, rb in pb:
                    if rh and rh[0] in REFS and len(rh) >= 2:
                        techs[ti][pi][REFS[rh[0]]] = rh[1]
                pi += 1
            ti += 1
        return techs

    n, seen = 0, set()
    for mat in sorted(materials):
        for ti, tech in enumerate(techniques(mat)):
            for pi, refs in enumerate(tech):
                if "vertex" not in refs or "fragment" not in refs:
                    continue
                names = {st: glsl(r) for st, r in refs.items()}
                if not all(names.values()):
                    continue
                stages = []
                for st in ORDER:
                    if st not in names:
                        continue
                    text = stage_text(names[st])
                    if text is None:
                        break
                    src = programs[names[st]][2]["source"][0][0]
                    stages.append((st, os.path.splitext(src)[0], text))
                    for att in programs[names[st]][2].get("attach", []):
                        for a in att:
                            if a in programs and glsl(a):
                                t = stage_text(a)
                                if t:
                                    stages.append((st, os.path.splitext(programs[a][2]["source"][0][0])[0], t))
                else:
                    key = tuple(t for _, _, t in stages)
                    if key in seen:
                        continue
                    seen.add(key)
                    label = mat + (f".t{ti}" if ti else "") + (f".p{pi}" if pi else "")
                    write_program(out, "ogre", label, stages)
                    n += 1
    print(n, "programs")


main()
