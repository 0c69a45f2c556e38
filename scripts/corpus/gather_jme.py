#!/usr/bin/env python3
"""jMonkeyEngine 3 material library: one program per material-definition (.j3md) technique and
define variant, with the stage text jME hands to glShaderSource.

Mirror: jMonkeyEngine/jmonkeyengine itself is over the snapshot size limit; the tree used is
delftsre/jmonkeyengine, a jME fork whose HEAD is upstream master of 2016-03-10 (jME 3.1 alpha),
so every file comes from one consistent engine version. Material definitions: every .j3md under
jme3-core, jme3-effects and jme3-terrain src/main/resources/Common/MatDefs. Asset paths
(`Common/...`) resolve against all modules' src/main/resources, as the classpath locator does.

What the engine does, and what is emulated:
- J3MLoader / BlockLanguageParser: statements end at newline, `;`, `{`, `}`; `//` comments;
  `MaterialParameters` lines `<TYPE> <NAME> [(binding)] [-LINEAR] [: default]` (Color = Vector4,
  texture defaults ignored); Technique `VertexShader GLSLnnn : path` (also Geometry,
  TessellationControl, TessellationEvaluation), `LightMode`, `Defines { NAME [: Param] }` (a define
  without a param is a preset define, Boolean true). ShaderNodes techniques (no shader paths,
  UnshadedNodes.j3md) are left out: they go through ShaderGenerator, not emulated.
- Technique choice (Material.selectTechnique) on a desktop GL 3.3 renderer (all GLSL100..GLSL330,
  geometry and tessellation caps): of the unnamed ("Default") techniques, the first one whose
  languages are supported, continuing past a SinglePass one because RenderManager's preferred light
  mode is MultiPass; the SinglePass default technique is also written (label `.SinglePass`,
  RenderManager.setPreferredLightMode(SinglePass)). Named techniques are all written except `X`
  when `X15` exists (the shadow renderers / particles pick `X15` with Caps.GLSL150).
- Defines (Technique.getAllDefines + DefineList.getCompiled): preset defines plus the defines
  bound to parameters that are set; Boolean true -> `1` (false -> absent), Int/Float -> Java
  toString of the value, any other type -> `1`; SinglePass techniques add SINGLE_PASS_LIGHTING 1
  and NB_LIGHTS 3 (default batch size 1 * 3). One `#define NAME VALUE` line each, sorted by name
  (TreeMap). Parameters start at their MaterialDef defaults (Material's constructor).
  APPROXIMATION: which parameters a game sets is not in the library; besides the defaults-only
  variant, up to 3 variants per technique set the technique's bound parameters found in three
  fixed profiles of commonly used parameters (textured + normal map + PSSM hardware shadows;
  specular/skinning/alpha-discard + point-light PCF shadows + multisampling; instancing/vertex
  lighting/parallax/env map + faded PSSM Poisson shadows), with the values jME's own code uses
  (e.g. ShadowMapSize 1024.0, FilterMode the EdgeFilteringMode ordinal, NumberOfBones 30).
  Techniques bound to ShadowMapSize (post-shadow passes) always get what AbstractShadowRenderer
  sets with its defaults (ShadowMapSize 1024.0, FilterMode 1, PCFEdge 1.0, HardwareShadows).
- GLSLLoader: lines read with BufferedReader.readLine and re-joined with `\\n`; a line whose trim
  starts with `#import ` is removed and, when it is a quoted path, that file's text (loaded the same
  way, wrapped in `// -- begin import X --` / `// -- end import X --`) is inserted at that point;
  a file already injected in this load becomes `// X was already injected at the top.`.
- GLRenderer.updateShaderSourceData: `#version NNN` (`#version NNN core` from 150 up, `#version 110`
  for GLSL100 on desktop), no SRGB define (gamma correction off by default), `#define
  <TYPE>_SHADER 1` (VERTEX, FRAGMENT, GEOMETRY, TESSELLATIONCONTROL, TESSELLATIONEVALUATION), the
  define list, then the loaded source.
Programs are named `<MatDefs folder>.<j3md name>[.<technique>][.vN]`; identical programs are
written once; defaults-only variants first, then variant 1, 2, 3 of every
technique, capped at 150 programs.
Usage: gather_jme.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

MODULES = ("jme3-core/", "jme3-effects/", "jme3-terrain/")
CAP = 150
SUPPORTED = {"GLSL100", "GLSL110", "GLSL120", "GLSL130", "GLSL140", "GLSL150", "GLSL330"}
SHADER_KINDS = {"VertexShader": "vertex", "FragmentShader": "fragment", "GeometryShader": "geometry",
                "TessellationControlShader": "tess-control",
                "TessellationEvaluationShader": "tess-eval"}
TYPE_DEFINE = {"vertex": "VERTEX", "fragment": "FRAGMENT", "geometry": "GEOMETRY",
               "tess-control": "TESSELLATIONCONTROL", "tess-eval": "TESSELLATIONEVALUATION"}
ORDER = ["vertex", "tess-control", "tess-eval", "geometry", "fragment"]
TEX = object()  # a texture / matrix / vector value: define value 1
PROFILES = [
    {"DiffuseMap": TEX, "NormalMap": TEX, "ColorMap": TEX, "Texture": TEX, "UseMaterialColors": True,
     "HardwareShadows": True, "FilterMode": 1, "PCFEdge": 1.0, "ShadowMapSize": 1024.0, "Splits": TEX,
     "GlowMap": TEX, "AlphaMap": TEX, "DiffuseMap_1": TEX, "DiffuseMap_2": TEX, "DiffuseMap_0_scale": 1.0, "DiffuseMap_1_scale": 1.0,
     "DiffuseMap_2_scale": 1.0, "region1ColorMap": TEX},
    {"DiffuseMap": TEX, "SpecularMap": TEX, "NumberOfBones": 30, "AlphaDiscardThreshold": 0.5,
     "LightViewProjectionMatrix5": TEX, "FilterMode": 3, "PCFEdge": 1.0, "ShadowMapSize": 512.0,
     "VertexColor": True, "GlowColor": TEX, "LightMap": TEX, "SeparateTexCoord": True,
     "NumSamples": 4, "NumSamplesDepth": 4, "ColorMap": TEX, "Texture": TEX},
    {"UseInstancing": True, "VertexLighting": True, "UseVertexColor": True, "DiffuseMap": TEX,
     "ParallaxMap": TEX, "SteepParallax": True, "EnvMap": TEX, "ColorMap": TEX, "FadeInfo": TEX,
     "Splits": TEX, "FilterMode": 4, "PCFEdge": 1.0, "ShadowMapSize": 2048.0, "HardwareShadows": True,
     "PointSprite": True, "useTriPlanarMapping": True, "WardIso": True},
]


# AbstractShadowRenderer always sets these on the post-shadow material and the receivers' materials
# (defaults: shadow map size 1024, EdgeFilteringMode.Bilinear = 1, edge 1, CompareMode.Hardware).
SHADOW_RENDERER = {"ShadowMapSize": 1024.0, "FilterMode": 1, "PCFEdge": 1.0, "HardwareShadows": True}


class Stmt:
    def __init__(self, line):
        self.line, self.contents = line, []


def parse_blocks(text):
    """com.jme3.util.blockparser.BlockLanguageParser."""
    root = Stmt("<root>")
    stack, last, buf = [root], None, []
    in_comment, last_char = False, "\0"

    def push():
        nonlocal last
        content = "".join(buf).strip()
        if content:
            last = Stmt(content)
            stack[-1].contents.append(last)
            buf.clear()
    for c in list(text) + [None]:
        if c == "\r":
            continue
        if in_comment and c == "\n":
            in_comment = False
        elif c == "/" and last_char == "/":
            buf.pop()
            in_comment = True
            push()
            last_char = "\0"
        elif not in_comment:
            if c is None or c in "{}\n;":
                push()
                last_char = "\0"
                if c == "{":
                    stack.append(last)
                elif c == "}":
                    if len(stack) > 1:
                        stack.pop()
                elif c is None:
                    break
            else:
                buf.append(c)
                last_char = c
    return root.contents


def java_float(x):
    """Float.toString of a float32 value."""
    f = struct.unpack("f", struct.pack("f", x))[0]
    for p in range(1, 10):
        s = f"{f:.{p}g}"
        if struct.unpack("f", struct.pack("f", float(s)))[0] == f:
            break
    v = float(s)
    if v == 0:
        return "0.0"
    if 1e-3 <= abs(v) < 1e7:
        r = repr(v)
        if "e" in r:
            r = f"{v:.10f}".rstrip("0")
        return r if "." in r else r + ".0"
    m, e = f"{v:e}".split("e")
    m = m.rstrip("0")
    m = m + "0" if m.endswith(".") else m
    return f"{m}E{int(e)}"


def jtrim(s):
    return s.strip("".join(chr(i) for i in range(33)))


def read_lines(text):
    lines = re.split(r"\r\n|\r|\n", text)
    if lines and lines[-1] == "":
        lines.pop()
    return lines


class GLSLLoader:
    """com.jme3.shader.plugins.GLSLLoader for one main shader file."""

    def __init__(self, assets):
        self.assets = assets

    def load(self, path):
        self.cache = {}
        root = self.node(self.assets[path], "[main]")
        return self.resolve(root, set())

    def node(self, text, name):
        sb, deps = [], []
        size = 0
        if name != "[main]":
            sb.append(f"// -- begin import {name} --\n")
            size += len(sb[-1])
        for ln in read_lines(text):
            t = jtrim(ln)
            if t.startswith("#import "):
                ln = jtrim(t[8:])
                if ln.startswith('"') and ln.endswith('"') and len(ln) > 3:
                    ln = ln[1:-1]
                    dep = self.cache.get(ln)
                    if dep is None:
                        if ln not in self.assets:
                            raise KeyError(ln)
                        dep = self.node(self.assets[ln], ln)
                    deps.append((size, dep))
            else:
                sb.append(ln + "\n")
                size += len(sb[-1])
        if name != "[main]":
            sb.append(f"// -- end import {name} --\n")
        n = {"name": name, "src": "".join(sb), "deps": deps}
        self.cache[name] = n
        return n

    def resolve(self, n, injected):
        if id(n) in injected:
            return f"// {n['name']} was already injected at the top.\n"
        injected.add(id(n))
        if not n["deps"]:
            return n["src"]
        parts = [(idx, self.resolve(d, injected)) for idx, d in n["deps"]]
        s = n["src"]
        for idx, txt in reversed(parts):
            s = s[:idx] + txt + s[idx:]
        return s


def header(lang, kind):
    v = int(lang[4:])
    if v > 100:
        h = f"#version {v}" + (" core" if v >= 150 else "") + "\n"
    else:
        h = "#version 110\n"
    return h + f"#define {TYPE_DEFINE[kind]}_SHADER 1\n"


def read_matdef(text):
    top = parse_blocks(text)
    mdef = next((s for s in top if s.line.startswith("MaterialDef")), None)
    if mdef is None:
        return None, []
    params, techs = {}, []
    for s in mdef.contents:
        head = s.line.split()
        if head[0] == "MaterialParameters":
            for p in s.contents:
                st, default = p.line, None
                if ":" in st:
                    st, default = [x.strip() for x in st.split(":", 1)]
                if st.endswith("-LINEAR"):
                    st = st[:-7]
                if "(" in st:
                    st = st[:st.index("(")]
                sp = st.split()
                if len(sp) != 2:
                    continue
                typ = "Vector4" if sp[0] == "Color" else sp[0]
                val = None
                if default is not None and not typ.startswith("Texture"):
                    if typ == "Boolean":
                        val = default.lower() == "true"
                    elif typ == "Int":
                        val = int(default)
                    elif typ == "Float":
                        val = float(default)
                    else:
                        val = TEX
                params[sp[1]] = (typ, val)
        elif head[0] == "Technique":
            t = {"name": head[1] if len(head) > 1 else "Default", "light": "Disable", "shaders": {},
                 "presets": [], "binds": {}}
            for ts in s.contents:
                th = ts.line.split()
                if th[0] in SHADER_KINDS:
                    left, _, path = ts.line.partition(":")
                    lang = left.split()[1]
                    t["shaders"][SHADER_KINDS[th[0]]] = (lang, path.strip())
                elif th[0] == "LightMode":
                    t["light"] = th[1]
                elif th[0] == "Defines":
                    for d in ts.contents:
                        sp = d.line.split(":")
                        if len(sp) == 1:
                            t["presets"].append(sp[0].strip())
                        elif len(sp) == 2:
                            t["binds"][sp[1].strip()] = sp[0].strip()
            techs.append(t)
    return params, techs


def define_value(typ, val):
    if val is None:
        return None
    if val is TEX:
        return "1"
    if typ == "Boolean":
        return "1" if val else None
    if typ == "Int":
        return str(int(val))
    if typ == "Float":
        return java_float(val)
    return "1"


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    assets = {}
    for f in m.files:
        mm = re.match(r"[^/]+/src/main/resources/(.*)$", f)
        if mm and f.endswith((".vert", ".frag", ".geom", ".glsl", ".glsllib", ".tsctrl", ".tseval")):
            assets.setdefault(mm.group(1), None)
            if assets[mm.group(1)] is None:
                assets[mm.group(1)] = m.text(f)
    matdefs = [f for f in m.files if f.endswith(".j3md") and f.startswith(MODULES)
               and "/src/main/resources/Common/MatDefs/" in f]
    loader = GLSLLoader(assets)
    rounds = [[] for _ in range(len(PROFILES) + 1)]
    for f in matdefs:
        params, techs = read_matdef(m.text(f))
        if params is None:
            continue
        stem = os.path.basename(os.path.dirname(f)) + "." + os.path.splitext(os.path.basename(f))[0]
        chosen = []
        defaults = [t for t in techs if t["name"] == "Default"]
        pick = None
        for t in defaults:
            langs = {lang for lang, _ in t["shaders"].values()}
            if langs <= SUPPORTED:  # a technique without shaders needs no caps either
                pick = t
                if t["light"] in ("MultiPass", "Disable"):
                    break
        if pick is not None and pick["shaders"]:
            chosen.append(("", pick))
        for t in defaults:
            if t["light"] == "SinglePass" and t is not pick and t["shaders"]:
                chosen.append((".SinglePass", t))
        names = {t["name"] for t in techs}
        for t in techs:
            if t["name"] != "Default" and t["shaders"] and t["name"] + "15" not in names:
                chosen.append(("." + t["name"], t))
        for suffix, t in chosen:
            if "vertex" not in t["shaders"] or "fragment" not in t["shaders"]:
                continue
            base = {p: v for p, (typ, v) in params.items() if v is not None}
            if "ShadowMapSize" in t["binds"]:
                base.update({p: v for p, v in SHADOW_RENDERER.items() if p in params})
            sets = [base]
            for prof in PROFILES:
                extra = {p: v for p, v in prof.items() if p in t["binds"] and p in params}
                if extra:
                    sets.append({**base, **extra})
            seen_defs = []
            for vi, values in enumerate(sets):
                defs = {d: "1" for d in t["presets"]}
                for p, d in t["binds"].items():
                    if p in params and p in values:
                        v = define_value(params[p][0], values[p])
                        if v is not None:
                            defs[d] = v
                if t["light"] == "SinglePass":
                    defs["SINGLE_PASS_LIGHTING"] = "1"
                    defs["NB_LIGHTS"] = "3"
                if defs in seen_defs:
                    continue
                seen_defs.append(defs)
                block = "".join(f"#define {k} {defs[k]}\n" for k in sorted(defs))
                stages = []
                try:
                    for kind in ORDER:
                        if kind in t["shaders"]:
                            lang, path = t["shaders"][kind]
                            text = header(lang, kind) + block + loader.load(path)
                            stages.append((kind, os.path.splitext(os.path.basename(path))[0], text))
                except KeyError as e:
                    print(f"skip {f} {t['name']}: missing {e}", file=sys.stderr)
                    break
                label = stem + suffix + (f".v{vi}" if vi else "")
                rounds[min(vi, len(rounds) - 1)].append((label, stages))
    n, seen = 0, set()
    for r in rounds:
        for label, stages in r:
            key = tuple((k, t) for k, _, t in stages)
            if key in seen or n >= CAP:
                continue
            seen.add(key)
            write_program(out, "jme", label, stages)
            n += 1
    print(n, "programs")


main()
