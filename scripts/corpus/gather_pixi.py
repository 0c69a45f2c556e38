#!/usr/bin/env python3
"""PixiJS v7 (pixijs/pixijs, npm package `pixi.js` 7.4.3, WebGL renderer): the GLSL ES 1.00
programs its renderer and built-in filters link.

Input: the unpacked npm package (`npm pack pixi.js@7.4.3 && tar xzf pixi.js-7.4.3.tgz` gives
PACKAGE_DIR=package; the git repository is over the fetch size limit). dist/pixi.mjs holds every
shader as a JS template literal (`var fragment$5 = \\`varying vec2 vTextureCoord;...\\``, line
ends as JS reads them: CRLF -> LF) and the code that pairs and prepares them:

- Program(vertexSrc, fragmentSrc, name = "pixi-shader"): both sources trimmed; unless the vertex
  source starts with `#version`, `#define SHADER_NAME <name>` (name, then name-2, name-3 ... per
  Program made with it: nameCache) goes first in each, then setPrecision puts
  `precision <p> float;` before a source that does not start with `precision` (vertex:
  Program.defaultVertexPrecision highp; fragment: defaultFragmentPrecision, mediump off Apple
  devices, highp being supported). Program.from caches by text (one Program per pair).
- the pairs: BatchRenderer (defaultVertexSrc + defaultFragmentTemplate with `%count%` and
  `%forloop%` filled by BatchShaderGenerator for maxTextures = min(MAX_TEXTURE_IMAGE_UNITS 16,
  32) = 16, a `new Program`), Filter's defaults, each `class X extends Filter` constructor's
  `super(vertex, fragment, ...)`, BlurFilterPass's generateBlurVertSource(kernelSize,
  horizontal) / generateBlurFragSource(kernelSize) (ported: kernel sizes 5..15, both
  directions), MeshMaterial's Program.from(vertex$1, fragment$1), BitmapText's MSDF
  Program.from(msdfVert, msdfFrag), ParticleRenderer's Shader.from(vertex, fragment), and the
  TilingSpriteRenderer's three (simple, WebGL 2 `#version 300 es`, WebGL 1 `#version 100`, the
  latter two skipping the SHADER_NAME/precision preparation).
Programs are made in that order (SHADER_NAME numbering follows it). A stage without a
`#version` line is GLSL ES 1.00 to the WebGL implementation; the stage files get `#version 100`
as their first line so that desktop tools (glslangValidator -d, Mesa's compatibility context)
read them as ES 1.00 too (the only change to pixi's text).
Usage: gather_pixi.py PACKAGE_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import write_program  # noqa: E402

BUNDLE = "dist/pixi.mjs"
MAX_TEXTURES = 16
VERTEX_PRECISION, FRAGMENT_PRECISION = "highp", "mediump"


def template_literals(js):
    """name -> value of `var|const|let|, NAME = \\`...\\`` literals without `${`."""
    out = {}
    for m in re.finditer(r"(?:^(?:var|const|let) |^`, |, )([\w$]+) = `((?:\\.|[^`\\])*)`", js, re.M | re.S):
        body = m.group(2)
        if "${" in body:
            continue
        body = body.replace("\r\n", "\n").replace("\r", "\n")
        body = re.sub(r"\\(.)", lambda e: {"n": "\n", "t": "\t", "r": "\n"}.get(e.group(1), e.group(1)), body)
        out.setdefault(m.group(1), body)
    return out


def getter(js, cls_pat, name):
    m = re.search(cls_pat, js)
    body = js[m.end():]
    g = re.search(r"static get " + name + r"\(\) \{\s*return ([\w$]+);", body)
    return g.group(1)


def js_array(js, name):
    m = re.search(name + r" = \{(.*?)\}", js, re.S)
    return {int(k): [float(x) for x in v.split(",")] for k, v in re.findall(r"(\d+): \[([^\]]*)\]", m.group(1))}


def js_num(x):
    """A JS number's toString()."""
    if x == int(x) and abs(x) < 1e21:
        return str(int(x))
    r = repr(x)
    if "e-" in r:
        mant, exp = r.split("e-")
        return f"{mant}e-{int(exp)}"
    return r


class Programs:
    def __init__(self):
        self.names = {}

    def prepare(self, vsrc, fsrc, name="pixi-shader"):
        vsrc, fsrc = vsrc.strip(), fsrc.strip()
        if vsrc[:8] != "#version":
            name = re.sub(r"\s+", "-", name)
            if name in self.names:
                self.names[name] += 1
                name += f"-{self.names[name]}"
            else:
                self.names[name] = 1
            vsrc = f"#define SHADER_NAME {name}\n{vsrc}"
            fsrc = f"#define SHADER_NAME {name}\n{fsrc}"
            vsrc = set_precision(vsrc, VERTEX_PRECISION)
            fsrc = set_precision(fsrc, FRAGMENT_PRECISION)
        return vsrc, fsrc


def set_precision(src, requested, max_supported="highp"):
    if src[:9] != "precision":
        p = requested
        if requested == "highp" and max_supported != "highp":
            p = "mediump"
        return f"precision {p} float;\n{src}"
    if max_supported != "highp" and src[:15] == "precision highp":
        return src.replace("precision highp", "precision mediump", 1)
    return src


def es100(text):
    return text if re.match(r"\s*#\s*version", text) else "#version 100\n" + text


def main():
    pkg, out = sys.argv[1], sys.argv[2]
    js = open(os.path.join(pkg, BUNDLE), encoding="utf-8").read()
    lit = template_literals(js)
    progs = Programs()
    pairs = []  # (program name, vertex text, fragment text, via Program.from cache?)

    # BatchRenderer
    bv = lit[getter(js, r"const _BatchRenderer = class _BatchRenderer2 extends ObjectRenderer \{", "defaultVertexSrc")]
    bf = lit[getter(js, r"const _BatchRenderer = class _BatchRenderer2 extends ObjectRenderer \{", "defaultFragmentTemplate")]
    loop = "\n\n"  # BatchShaderGenerator.generateSampleSrc
    for i in range(MAX_TEXTURES):
        if i > 0:
            loop += "\nelse "
        if i < MAX_TEXTURES - 1:
            loop += f"if(vTextureId < {i}.5)"
        loop += "\n{" + f"\n\tcolor = texture2D(uSamplers[{i}], vTextureCoord);" + "\n}"
    loop += "\n\n"
    pairs.append(("batch", bv, re.sub("%forloop%", loop, re.sub("%count%", str(MAX_TEXTURES), bf, flags=re.I), flags=re.I)))
    # Filter defaults
    fv = lit[getter(js, r"const _Filter = class _Filter2 extends Shader \{", "defaultVertexSrc")]
    ff = lit[getter(js, r"const _Filter = class _Filter2 extends Shader \{", "defaultFragmentSrc")]
    pairs.append(("filter_default", fv, ff))
    alias = dict(re.findall(r"([\w$]+) = (\$[\w$]+)[,;]", js[js.index("const defaultVertex = $defaultVertex"):][:200]))
    # class X extends Filter { constructor(..) { .. super(A, B ..) }
    for m in re.finditer(r"class (\w+) extends Filter \{", js):
        body = js[m.end():m.end() + 4000]
        s = re.search(r"super\(\s*(?:vertexSrc \|\| )?([\w$]+),\s*(?:fragmentSrc \|\| )?([\w$]+)", body)
        if not s:
            continue  # BlurFilter: super() holding two passes; BlurFilterPass below
        v, f = (alias.get(x, x) for x in s.groups())
        if v in lit and f in lit:
            pairs.append((m.group(1), lit[v], lit[f]))
    # BlurFilterPass: generateBlurVertSource / generateBlurFragSource
    gauss = js_array(js, "GAUSSIAN_VALUES")
    vt = lit["vertTemplate"]
    ft_m = re.search(r"fragTemplate = \[(.*?)\]\.join\(`\n`\)", js, re.S)
    ft = "\n".join(re.findall(r'"((?:\\.|[^"\\])*)"', ft_m.group(1)))
    for k in sorted(gauss):
        kernel, half = gauss[k], len(gauss[k])
        floop = ""
        for i in range(k):
            value = k - i - 1 if i >= half else i
            floop += f"gl_FragColor += texture2D(uSampler, vBlurTexCoords[{i}]) * {js_num(kernel[value])};\n"
        frag = ft.replace("%blur%", floop, 1).replace("%size%", str(k), 1)
        for horizontal in (True, False):
            hl = -(-k // 2)
            vloop = ""
            for i in range(k):
                off = f"{i - (hl - 1)}.0"
                vloop += (f"vBlurTexCoords[{i}] =  textureCoord + vec2({off} * strength, 0.0);\n" if horizontal
                          else f"vBlurTexCoords[{i}] =  textureCoord + vec2(0.0, {off} * strength);\n")
            vert = vt.replace("%blur%", vloop, 1).replace("%size%", str(k), 1)
            pairs.append((f"BlurFilterPass.{'x' if horizontal else 'y'}{k}", vert, frag))
    # MeshMaterial, MSDF bitmap text, ParticleRenderer, TilingSprite
    mm = re.search(r"class MeshMaterial extends Shader \{.*?Program\.from\(([\w$]+), ([\w$]+)\)", js, re.S)
    pairs.append(("MeshMaterial", lit[mm.group(1)], lit[mm.group(2)]))
    pairs.append(("BitmapText.msdf", lit["msdfVert"], lit["msdfFrag"]))
    pr = re.search(r"class ParticleRenderer extends ObjectRenderer \{.*?Shader\.from\(([\w$]+), ([\w$]+)", js, re.S)
    pairs.append(("ParticleRenderer", lit[pr.group(1)], lit[pr.group(2)]))
    ts = re.search(r"this\.simpleShader = Shader\.from\(([\w$]+), ([\w$]+), uniforms\), this\.shader = renderer\.context\.webGLVersion > 1 \? "
                   r"Shader\.from\(([\w$]+), ([\w$]+), uniforms\) : Shader\.from\(([\w$]+), ([\w$]+), uniforms\)", js)
    pairs += [("TilingSprite.simple", lit[ts.group(1)], lit[ts.group(2)]),
              ("TilingSprite.gl2", lit[ts.group(3)], lit[ts.group(4)]),
              ("TilingSprite.gl1", lit[ts.group(5)], lit[ts.group(6)])]

    cache, n = set(), 0
    for name, v, f in pairs:
        if (v, f) in cache:  # Program.from's cache
            continue
        cache.add((v, f))
        pv, pf = progs.prepare(v, f)
        write_program(out, "pixi", name, [("vertex", name.split(".")[0], es100(pv)),
                                          ("fragment", name.split(".")[0], es100(pf))])
        n += 1
    print(n, "programs")


main()
