#!/usr/bin/env python3
"""processing/processing4 core OpenGL shaders, as PGraphicsOpenGL pairs them (default
color/texture/light/texlight/line/point shaders, the mask shader TexVert+MaskFrag) and the
PGL blit shaders kept inline in PGL.java (texVertShaderSource + tex2D/texRect frag).

Text: PGL.preprocessVertexSource / preprocessFragmentSource on the file's lines, for two
driver GLSL versions (JOGL reports the context's: 120, and 410 as on a macOS core context):
a line is prepended (vertex) or two (fragment, `out vec4 _fragColor;` for >= 130), the first
is `#version N`; for >= 130 varying/attribute/texture/texture2D.../gl_FragColor are renamed
with the same regular expressions; lines joined with "\\n". Usage: gather_processing.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
SH = "core/src/processing/opengl/shaders/"
ID = r"(?<![0-9A-Z_a-z])(%s)(?![0-9A-Z_a-z]|\s*\()"
FN = r"(?<![0-9A-Z_a-z])(%s)(?=\s*\()"


def has_version(lines):
    for l in lines:
        v, c = l.find("#version"), l.find("//")
        if v >= 0 and (c < 0 or v < c):
            return True
    return False


def preprocess(lines, version, frag):
    if has_version(lines):
        return "\n".join(lines)
    rules = []
    if version >= 130:
        if frag:
            rules = [(ID % "varying|attribute", "in"), (ID % "texture", "texMap"),
                     (FN % "texture2DRect|texture2D|texture3D|textureCube", "texture"), (ID % "gl_FragColor", "_fragColor")]
        else:
            rules = [(ID % "varying", "out"), (ID % "attribute", "in"), (ID % "texture", "texMap"),
                     (FN % "texture2DRect|texture2D|texture3D|textureCube", "texture")]
    offset = 2 if frag and version >= 130 else 1
    src = [None] * offset
    for line in lines:
        if "#version" in line:
            line = line[:line.index("#version")]
        for pat, rep in rules:
            line = re.sub(pat, rep, line)
        src.append(line)
    src[0] = f"#version {version}"
    if offset == 2:
        src[1] = "out vec4 _fragColor;"
    return "\n".join(src)


def load_strings(path):
    return m.text(path).splitlines()  # PApplet.loadStrings: BufferedReader.readLine()


def java_array(src, name, consts):
    body = re.search(r'String\[\]\s+' + name + r'\s*=\s*\{(.*?)\};', src, re.S).group(1)
    items = []
    for item in re.findall(r'"((?:[^"\\]|\\.)*)"|([A-Z_]+)', body):
        items.append(item[0].replace("\\n", "\n") if item[0] or not item[1] else consts[item[1]])
    return items


pgl = m.text("core/src/processing/opengl/PGL.java")
directive = "".join(s.replace("\\n", "\n") for s in re.findall(
    r'"((?:[^"\\]|\\.)*)"', re.search(r'SHADER_PREPROCESSOR_DIRECTIVE\s*=((?:\s*"(?:[^"\\]|\\.)*"\s*\+?)+);', pgl).group(1)))
consts = {"SHADER_PREPROCESSOR_DIRECTIVE": directive}
PAIRS = [("Color", "ColorVert", "ColorFrag"), ("Texture", "TexVert", "TexFrag"), ("Light", "LightVert", "LightFrag"),
         ("TexLight", "TexLightVert", "TexLightFrag"), ("Line", "LineVert", "LineFrag"),
         ("Point", "PointVert", "PointFrag"), ("Mask", "TexVert", "MaskFrag")]
progs = [(n, v, load_strings(SH + v + ".glsl"), f, load_strings(SH + f + ".glsl")) for n, v, f in PAIRS]
tex_vert = java_array(pgl, "texVertShaderSource", consts)
progs += [("PGL_tex2D", "texVert", tex_vert, "tex2DFrag", java_array(pgl, "tex2DFragShaderSource", consts)),
          ("PGL_texRect", "texVert", tex_vert, "texRectFrag", java_array(pgl, "texRectFragShaderSource", consts))]
n = 0
for version in (120, 410):
    for name, vstem, vlines, fstem, flines in progs:
        write_program(out, "processing", f"{name}_glsl{version}",
                      [("vertex", vstem, preprocess(vlines, version, False)),
                       ("fragment", fstem, preprocess(flines, version, True))])
        n += 1
print(n, "programs")
