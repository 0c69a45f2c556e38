#!/usr/bin/env python3
"""libgdx/libgdx built-in shaders as a desktop (LWJGL, GL 2.0) application compiles them.

ShaderProgram(vertex, fragment) hands each stage's text to glShaderSource as one string; this
snapshot's ShaderProgram prepends nothing (later versions' prependVertexCode /
prependFragmentCode are empty by default), and the GLSL files carry no #version, so the desktop
driver compiles them as GLSL 1.10.

- g3d DefaultShader: `new ShaderProgram(prefix + vertexShader, prefix + fragmentShader)` with
  g3d/shaders/default.{vertex,fragment}.glsl and DefaultShader.createPrefix(renderable, config)
  for the CONFIGS below (vertex attributes, material attributes, environment), Config defaults
  numDirectionalLights 2, numPointLights 5, numBones 12. createPrefix is re-done here in the
  order of the Java (checked against its text at run time: every `#define` string and alias it
  uses must be found in DefaultShader.java / the attribute classes).
- g3d DepthShader: DefaultShader.createPrefix + `#define PackedDepthFlag` (Config.depthBufferOnly
  false) with depth.{vertex,fragment}.glsl; a shadow/depth ModelBatch renders without an
  Environment, so no lighting defines.
- g3d particles ParticleShader: createPrefix (`#version 120` on ApplicationType.Desktop, then
  `#define billboard` + screenFacing / viewPointFacing, or nothing for point sprites) with
  particles.{vertex,fragment}.glsl.
- SpriteBatch.createDefaultShader() (also PolygonSpriteBatch's) and
  ImmediateModeRenderer20.createDefaultShader(hasNormals, hasColors, numTexCoords) (ShapeRenderer
  uses (false, true, 0)): Java string building; the methods are compiled and run with `java`
  (single-file source launch) with ShaderProgram's attribute-name constants, so the text is
  exactly what the Java builds.

- tests' g3d ShaderCollectionTest: each entry of its `shaders[]` but "<default>" is loaded with
  tests/g3d/ShaderLoader (`name.glsl:VS` / `:FS` snippets of tests/gdx-tests-android/assets/
  data/g3d/shaders, `[section]` headers, lines trimmed and ended with "\r\n", `#include
  "file:section"` / `":section"` spliced once per load) as Config.vertexShader/fragmentShader of
  a MultiPassShader (a DefaultShader: createPrefix + text), with the test's Environment (ambient
  + one directional light) for the teapot (position, normal, uv; diffuse texture) and for a
  normal-mapped material with the environment cubemap selected (`collection.<shader>.<config>`).

Usage: gather_libgdx.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

GFX = "gdx/src/com/badlogic/gdx/graphics/"
G3D = GFX + "g3d/shaders/"
ATTRS = GFX + "g3d/attributes/"

# (name, vertex attributes in mesh order, material attributes, environment or None, bones)
# environment: set of "fog", "shadowMap", "environmentMap".
CONFIGS = [
    ("textured_lit", ["Position", "Normal", "TexCoord0"], {"DiffuseTexture"}, set(), False),
    ("colored_unlit", ["Position", "ColorPacked"], set(), None, False),
    ("diffusecolor_fog", ["Position", "Normal"], {"DiffuseColor"}, {"fog"}, False),
    ("skinned", ["Position", "Normal", "TexCoord0", "BoneWeight0", "BoneWeight1", "BoneWeight2", "BoneWeight3"],
     {"DiffuseTexture"}, set(), True),
    ("bump_specular_blended", ["Position", "Normal", "Tangent", "BiNormal", "TexCoord0"],
     {"Blended", "DiffuseTexture", "NormalTexture", "SpecularTexture", "SpecularColor", "Shininess", "AlphaTest"},
     set(), False),
    ("shadow_envmap_emissive", ["Position", "Normal", "TexCoord0"],
     {"DiffuseTexture", "EmissiveColor", "ReflectionColor"}, {"shadowMap", "environmentMap"}, False),
    ("blended_texture_unlit", ["Position", "TexCoord0"], {"Blended", "DiffuseTexture", "AlphaTest"}, None, False),
    ("all_textures_fog", ["Position", "Color", "Normal", "TexCoord0"],
     {"DiffuseTexture", "SpecularTexture", "NormalTexture", "EmissiveTexture", "ReflectionTexture",
      "AmbientTexture", "DiffuseColor", "EmissiveColor"}, {"fog"}, False),
]
DEPTH_CONFIGS = [
    ("static", ["Position", "Normal", "TexCoord0"], {"DiffuseTexture"}, None, False),
    ("skinned", ["Position", "Normal", "TexCoord0", "BoneWeight0", "BoneWeight1"], {"DiffuseTexture"}, None, True),
    ("blended_alphatest", ["Position", "TexCoord0"], {"Blended", "DiffuseTexture", "AlphaTest"}, None, False),
]
NUM_DIR, NUM_POINT, NUM_BONES = 2, 5, 12
COLLECTION_CONFIGS = [
    ("teapot", ["Position", "Normal", "TexCoord0"], {"DiffuseTexture"}, set(), False),
    ("normalmap_envmap", ["Position", "Normal", "Tangent", "BiNormal", "TexCoord0"],
     {"DiffuseTexture", "NormalTexture", "SpecularTexture", "Shininess"}, {"environmentMap"}, False),
]
TESTS = "tests/gdx-tests/src/com/badlogic/gdx/tests/g3d/"
TEST_SHADERS = "tests/gdx-tests-android/assets/data/g3d/shaders/"
IMMEDIATE = [(False, True, 0), (False, True, 1), (True, False, 2)]  # ShapeRenderer's first


def aliases(m):
    out = {}
    for cls in ("BlendingAttribute", "TextureAttribute", "ColorAttribute", "FloatAttribute"):
        for a in re.finditer(r'(?:final\s+)?static\s+(?:final\s+)?String\s+(\w*Alias)\s*=\s*"([^"]*)"', m.text(ATTRS + cls + ".java")):
            out[cls + "." + a.group(1)] = a.group(2)
    return out


def create_prefix(java, al, attrs, mat, env, bones):
    """DefaultShader.createPrefix, statement by statement."""
    p = ""
    has = set(attrs)
    if "Position" in has:
        p += "#define positionFlag\n"
    if has & {"Color", "ColorPacked"}:
        p += "#define colorFlag\n"
    if "BiNormal" in has:
        p += "#define binormalFlag\n"
    if "Tangent" in has:
        p += "#define tangentFlag\n"
    if "Normal" in has:
        p += "#define normalFlag\n"
    if "Normal" in has or {"Tangent", "BiNormal"} <= has:
        if env is not None:
            p += "#define lightingFlag\n#define ambientCubemapFlag\n"
            p += f"#define numDirectionalLights {NUM_DIR}\n#define numPointLights {NUM_POINT}\n"
            if "fog" in env:
                p += "#define fogFlag\n"
            if "shadowMap" in env:
                p += "#define shadowMapFlag\n"
            if "environmentMap" in env:
                p += "#define environmentCubemapFlag\n"
    for a in attrs:
        if a.startswith("BoneWeight"):
            p += f"#define boneWeight{a[10:]}Flag\n"
        elif a.startswith("TexCoord"):
            p += f"#define texCoord{a[8:]}Flag\n"
    if "Blended" in mat:
        p += f"#define {al['BlendingAttribute.Alias']}Flag\n"
    for t in ("Diffuse", "Specular", "Normal", "Emissive", "Reflection", "Ambient"):
        if t + "Texture" in mat:
            a = al[f"TextureAttribute.{t}Alias"]
            p += f"#define {a}Flag\n#define {a}Coord texCoord0\n"
    for c in ("Diffuse", "Specular", "Emissive", "Reflection"):
        if c + "Color" in mat:
            p += f"#define {al[f'ColorAttribute.{c}Alias']}Flag\n"
    if "Shininess" in mat:
        p += f"#define {al['FloatAttribute.ShininessAlias']}Flag\n"
    if "AlphaTest" in mat:
        p += f"#define {al['FloatAttribute.AlphaTestAlias']}Flag\n"
    if bones and NUM_BONES > 0:
        p += f"#define numBones {NUM_BONES}\n"
    return p


def check_create_prefix(java):
    """The Java this port follows: fail loudly when the snapshot's createPrefix differs."""
    body = java_method(java, r"public static String createPrefix \(")
    want = ['"#define positionFlag\\n"', '"#define colorFlag\\n"', '"#define binormalFlag\\n"',
            '"#define tangentFlag\\n"', '"#define normalFlag\\n"', '"#define lightingFlag\\n"',
            '"#define ambientCubemapFlag\\n"', '"#define numDirectionalLights "', '"#define numPointLights "',
            '"#define fogFlag\\n"', '"#define shadowMapFlag\\n"', '"#define environmentCubemapFlag\\n"',
            '"#define boneWeight"', '"#define texCoord"', 'Coord texCoord0\\n"', '"#define numBones "']
    pos = 0
    for w in want:
        k = body.find(w, pos)
        if k < 0:
            raise SystemExit(f"DefaultShader.createPrefix changed: {w} not found in order")
        pos = k
    n_define = len(re.findall(r'"#define ', body))
    if n_define != 34:
        raise SystemExit(f"DefaultShader.createPrefix changed: {n_define} '#define' literals, expected 34")


def java_method(src, header_re):
    m = re.search(header_re, src)
    start = src.index("{", m.end() - 1) if src[m.end() - 1] != "{" else m.end() - 1
    depth = 0
    for k in range(start, len(src)):
        depth += {"{": 1, "}": -1}.get(src[k], 0)
        if depth == 0:
            return src[m.start():k + 1]
    raise SystemExit("unbalanced method " + header_re)


def java_strings(m):
    """Runs SpriteBatch.createDefaultShader's and ImmediateModeRenderer20.create*Shader's string
    building; returns {"sprite": (vs, fs), (n, c, t): (vs, fs)}."""
    consts = "".join(f'static final String {a} = "{b}";\n' for a, b in re.findall(
        r'public static final String (\w+_ATTRIBUTE) = "([^"]*)";', m.text(GFX + "glutils/ShaderProgram.java")))
    sb = java_method(m.text(GFX + "g2d/SpriteBatch.java"), r"static public ShaderProgram createDefaultShader \(\) \{")
    sb_body = sb[sb.index("{") + 1:sb.index("ShaderProgram shader = new ShaderProgram(")]
    imr = m.text(GFX + "glutils/ImmediateModeRenderer20.java")
    vs = java_method(imr, r"static private String createVertexShader \(")
    fs = java_method(imr, r"static private String createFragmentShader \(")
    calls = "".join(f'out(createVertexShader({str(a).lower()}, {str(b).lower()}, {c}));'
                    f'out(createFragmentShader({str(a).lower()}, {str(b).lower()}, {c}));' for a, b, c in IMMEDIATE)
    prog = f"""public class H {{
  static class ShaderProgram {{ {consts} }}
  static void out(String s) {{ System.out.print(s.length() + ":" + s); }}
  static String[] sprite() {{ {sb_body} return new String[] {{ vertexShader, fragmentShader }}; }}
  {vs}
  {fs}
  public static void main(String[] a) throws Exception {{
    System.setOut(new java.io.PrintStream(System.out, true, "UTF-8"));
    String[] s = sprite(); out(s[0]); out(s[1]); {calls}
  }}
}}
"""
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "H.java"), "w") as fh:
            fh.write(prog)
        raw = subprocess.run(["java", os.path.join(d, "H.java")], capture_output=True, check=True).stdout.decode("utf-8")
    texts = []
    while raw:
        n, rest = raw.split(":", 1)
        texts.append(rest[:int(n)])
        raw = rest[int(n):]
    out = {"sprite": (texts[0], texts[1])}
    for k, key in enumerate(IMMEDIATE):
        out[key] = (texts[2 + 2 * k], texts[3 + 2 * k])
    return out


def jtrim(line):
    """java.lang.String.trim: strips chars <= ' ' at both ends."""
    a, b = 0, len(line)
    while a < b and line[a] <= " ":
        a += 1
    while b > a and line[b - 1] <= " ":
        b -= 1
    return line[a:b]


class ShaderLoader:
    """tests/g3d/ShaderLoader.load(name) (a fresh loader per shader, as ShaderCollectionTest does)."""

    def __init__(self, m, root):
        self.m, self.root, self.snippets, self.includes = m, root, {}, []

    def parse_file(self, name):
        text = self.m.text(self.root + name)
        if text is None:
            raise SystemExit("missing " + self.root + name)
        lines = re.split(r"\r\n|\r|\n", text)
        if lines and lines[-1] == "":
            lines.pop()  # BufferedReader.readLine gives no empty last line
        result, snip, buf = {}, "", ""
        for line in lines:
            idx = line.find("]")
            if len(line) > 3 and line[0] == "[" and idx > 1:
                if snip or buf:
                    result[snip] = buf
                buf, snip = "", line[1:idx]
            else:
                buf += jtrim(line) + "\r\n"
        if snip or buf:
            result[snip] = buf
        return result

    def load_into(self, out, name):
        idx = name.rfind(":")
        file_name = name if idx < 0 else name[:idx]
        snip_name = "" if idx < 0 or idx >= len(name) - 1 else name[idx + 1:]
        if file_name not in self.snippets:
            self.snippets[file_name] = self.parse_file(file_name)
        if snip_name not in self.snippets[file_name]:
            raise SystemExit(f"No snippet [{snip_name}] in file {file_name}")
        self.parse(out, file_name, self.snippets[file_name][snip_name])

    def parse(self, out, current, code):
        lines = code.split("\n")
        while lines and lines[-1] == "":
            lines.pop()  # String.split drops trailing empty strings
        for line in lines:
            i = line.find('"') if line.find("#include") == 0 else -1
            j = line.find('"', i + 1) if i > 0 else -1
            if i > 0 and j > i + 1:
                name = line[i + 1:j]
                if name[0] == ":":
                    name = current + name
                if name not in self.includes:
                    self.includes.append(name)
                    self.load_into(out, name)
            else:
                out.append(jtrim(line) + "\r\n")

    def load(self, name):
        out = []
        self.load_into(out, name)
        self.includes = []
        return "".join(out)


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    java = m.text(G3D + "DefaultShader.java")
    check_create_prefix(java)
    depth_java = m.text(G3D + "DepthShader.java")
    if '"#define PackedDepthFlag\\n"' not in depth_java or "depthBufferOnly = false" not in depth_java:
        raise SystemExit("DepthShader.createPrefix changed")
    al = aliases(m)
    n = 0
    dv, df = m.text(G3D + "default.vertex.glsl"), m.text(G3D + "default.fragment.glsl")
    for name, attrs, mat, env, bones in CONFIGS:
        pre = create_prefix(java, al, attrs, mat, env, bones)
        write_program(out, "libgdx", "default." + name, [("vertex", "default", pre + dv), ("fragment", "default", pre + df)])
        n += 1
    zv, zf = m.text(G3D + "depth.vertex.glsl"), m.text(G3D + "depth.fragment.glsl")
    for name, attrs, mat, env, bones in DEPTH_CONFIGS:
        pre = create_prefix(java, al, attrs, mat, env, bones) + "#define PackedDepthFlag\n"
        write_program(out, "libgdx", "depth." + name, [("vertex", "depth", pre + zv), ("fragment", "depth", pre + zf)])
        n += 1
    pj = m.text(GFX + "g3d/particles/ParticleShader.java")
    if pj is not None:
        if '"#version 120\\n"' not in pj or '"#define screenFacing\\n"' not in pj:
            raise SystemExit("ParticleShader.createPrefix changed")
        pv, pf = m.text(GFX + "g3d/particles/particles.vertex.glsl"), m.text(GFX + "g3d/particles/particles.fragment.glsl")
        for name, pre in (("billboard_screen", "#define billboard\n#define screenFacing\n"),
                          ("billboard_viewpoint", "#define billboard\n#define viewPointFacing\n"),
                          ("point", "")):
            pre = "#version 120\n" + pre
            write_program(out, "libgdx", "particles." + name,
                          [("vertex", "particles", pre + pv), ("fragment", "particles", pre + pf)])
            n += 1
    sct = m.text(TESTS + "ShaderCollectionTest.java")
    loader_src = m.text(TESTS + "ShaderLoader.java")
    if sct is not None and loader_src is not None:
        for w in ('out.append(line.trim()).append("\\r\\n")', 'line.indexOf("#include")) == 0',
                  "stringBuilder.append(line.trim()).append(\"\\r\\n\")"):
            if w not in loader_src:
                raise SystemExit("ShaderLoader changed: " + w)
        names = re.findall(r'"([^"]+)"', re.search(r"String shaders\[\]\s*=\s*new String\[\]\s*\{([^}]*)\}", sct).group(1))
        for name in names:
            if name.startswith("<"):
                continue
            ld = ShaderLoader(m, TEST_SHADERS)
            vs, fs = ld.load(name + ".glsl:VS"), ld.load(name + ".glsl:FS")
            for cname, attrs, mat, env, bones in COLLECTION_CONFIGS:
                pre = create_prefix(java, al, attrs, mat, env, bones)
                write_program(out, "libgdx", f"collection.{name}.{cname}",
                              [("vertex", name, pre + vs), ("fragment", name, pre + fs)])
                n += 1
    js = java_strings(m)
    write_program(out, "libgdx", "spritebatch", [("vertex", "sprite", js["sprite"][0]), ("fragment", "sprite", js["sprite"][1])])
    n += 1
    for key in IMMEDIATE:
        a, b, c = key
        name = f"immediate.n{int(a)}c{int(b)}t{c}" + (".shaperenderer" if key == (False, True, 0) else "")
        write_program(out, "libgdx", name, [("vertex", "immediate", js[key][0]), ("fragment", "immediate", js[key][1])])
        n += 1
    print(n, "programs")


main()
