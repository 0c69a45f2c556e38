#!/usr/bin/env python3
"""mgba-emu/mgba: the GLSL programs of the OpenGL video backend and of the GBA OpenGL renderer on a
desktop GL 3.2+ context (the `else` branch of the GL_VERSION checks: not "OpenGL ES ", not 2.x).

- src/platform/opengl/gles2.c, mGLES2ShaderInit(shader, vs, fs, ...): the vertex shader is
  glShaderSource'd as { _gl32VHeader, vs or _nullVertexShader } and the fragment shader as
  { _gl32FHeader, fs or _nullFragmentShader } (`#version 150 core` plus the attribute/varying/
  texture2D/gl_FragColor compatibility defines). Programs: each mGLES2ShaderInit call of
  mGLES2ContextInit (a 0 argument is the null shader), named `backend.<field>`, and each pass of
  every res/shaders/<x>.shader/manifest.ini as mGLES2ShaderLoad reads it (`[shader] passes`,
  `[pass.N] vertexShader / fragmentShader` file names in the pack directory, file bytes verbatim;
  a pack is skipped whole where mGLES2ShaderLoad would fail), named `<x>.pass<N>`.
- src/gba/renderers/gl.c, GBAVideoGLRendererInit: one vertex shader { _gl3Header, _vertexShader }
  shared by every program, and one fragment shader per _compileShader call with the
  shaderBuffer[0..count) strings as they are set just before it (shaderBuffer[0] = _gl3Header,
  `#version 330 core`), named `gba.<shader field>`. The string macros the literals use
  (PALETTE_ENTRY, MOSAIC) are expanded first.
Usage: gather_mgba.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import C_LITERAL, Mirror, c_string_vars, strip_cpp_comments, write_program  # noqa: E402

GLES2 = "src/platform/opengl/gles2.c"
GBA_GL = "src/gba/renderers/gl.c"
MAX_PASSES = 8  # gles2.c MAX_PASSES


def expand_string_macros(src):
    """Comment-free C source with `#define NAME "lit" ...` (string-literal-only bodies, backslash
    continuations allowed) removed and NAME replaced by those literals outside string literals."""
    macros = {}

    def grab(m):
        body = m.group(2).replace("\\\n", " ")
        if re.fullmatch(rf"\s*(?:{C_LITERAL}\s*)+", body):
            macros[m.group(1)] = body.strip()
            return ""
        return m.group(0)
    src = re.sub(r"^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+((?:[^\n\\]|\\\n|\\.)*)$", grab, src, flags=re.M)
    if not macros:
        return src
    pat = re.compile(r"\b(" + "|".join(map(re.escape, macros)) + r")\b")
    out, last = [], 0
    for lit in re.finditer(C_LITERAL, src):
        out.append(pat.sub(lambda m: macros[m.group(1)], src[last:lit.start()]) + lit.group(0))
        last = lit.end()
    return "".join(out) + pat.sub(lambda m: macros[m.group(1)], src[last:])


def ini(text):
    """inih-style sections: {section: {key: value}} (`;`/`#` comment lines, inline ` ;` comments)."""
    out, sec = {}, ""
    for line in text.splitlines():
        line = line.strip()
        if not line or line[0] in ";#":
            continue
        if line.startswith("["):
            sec = line[1:line.find("]")].strip()
            out.setdefault(sec, {})
        elif "=" in line or ":" in line:
            k, v = re.split(r"[=:]", line, 1)
            v = re.split(r"\s;", v, 1)[0]
            out.setdefault(sec, {})[k.strip()] = v.strip()
    return out


def c_int(v):
    m = re.match(r"\s*([+-]?(?:0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*))", v or "")
    return int(m.group(1), 0) if m else None


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    n = 0

    # OpenGL video backend (gles2.c)
    src = strip_cpp_comments(m.text(GLES2))
    s = {k: v[0] for k, v in c_string_vars(src).items() if v}
    vhead, fhead = s["_gl32VHeader"], s["_gl32FHeader"]

    def backend(name, vs, fs, vstem, fstem):
        nonlocal n
        vs = vs if vs is not None else s["_nullVertexShader"]
        fs = fs if fs is not None else s["_nullFragmentShader"]
        enc = lambda t: t.encode() if isinstance(t, str) else t
        write_program(out, "mgba", name, [("vertex", vstem, enc(vhead) + enc(vs)),
                                          ("fragment", fstem, enc(fhead) + enc(fs))])
        n += 1

    init = src[src.index("mGLES2ContextInit"):]
    for field, vs, fs in re.findall(r"mGLES2ShaderInit\(\s*&\s*context->(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*,", init):
        get = lambda a, null: (None, null) if a in ("0", "NULL") else (s[a], a)
        (vt, vn), (ft, fn) = get(vs, "_nullVertexShader"), get(fs, "_nullFragmentShader")
        backend(f"backend.{field}", vt, ft, vn, fn)

    packs = sorted({f.split("/")[2] for f in m.files if f.startswith("res/shaders/") and f.endswith("/manifest.ini")})
    skipped = []
    for pack in packs:
        d = f"res/shaders/{pack}/"
        conf = ini(m.text(d + "manifest.ini"))
        passes = c_int(conf.get("shader", {}).get("passes"))
        if passes is None or not 1 <= passes <= MAX_PASSES:
            skipped.append(pack)
            continue
        progs = []
        for p in range(passes):
            sec = conf.get(f"pass.{p}", {})
            fs, vs = sec.get("fragmentShader"), sec.get("vertexShader")
            if any(x is not None and (x.startswith(".") or "/" in x or not m.exists(d + x)) for x in (fs, vs)):
                progs = None
                break
            progs.append((p, vs, fs))
        if progs is None:
            skipped.append(pack)
            continue
        base = pack[:-len(".shader")] if pack.endswith(".shader") else pack
        for p, vs, fs in progs:
            backend(f"{base}.pass{p}", m.show(d + vs) if vs else None, m.show(d + fs) if fs else None,
                    vs or "_nullVertexShader", fs or "_nullFragmentShader")

    # GBA OpenGL renderer (gba/renderers/gl.c)
    src = expand_string_macros(strip_cpp_comments(m.text(GBA_GL)))
    s = {k: v[0] for k, v in c_string_vars(src).items() if v}
    body = src[src.index("void GBAVideoGLRendererInit"):]
    buf, vtext = {}, None
    for a in re.finditer(r"shaderBuffer\[(\d+)\]\s*=\s*(\w+)\s*;|glShaderSource\(\s*vs\s*,\s*(\d+)|"
                         r"_compileShader\(\s*\w+\s*,\s*&\s*\w+->(\w+(?:\[\d+\])?)\s*,\s*shaderBuffer\s*,\s*(\d+)", body):
        if a.group(1):
            buf[int(a.group(1))] = a.group(2)
        elif a.group(3):
            if "_gl3Header" in body[:a.start()] and buf.get(0) != "_gl3Header":
                buf[0] = "_gl3Header"  # the desktop branch of the GL_VERSION check
            vtext = "".join(s[buf[i]] for i in range(int(a.group(3))))
        else:
            buf[0] = "_gl3Header"
            names = [buf[i] for i in range(int(a.group(5)))]
            write_program(out, "mgba", "gba." + a.group(4).replace("[", "").replace("]", ""),
                          [("vertex", "_vertexShader", vtext),
                           ("fragment", "_".join(x.lstrip("_") for x in names[1:]), "".join(s[x] for x in names))])
            n += 1
    print(n, "programs", f"(packs skipped: {', '.join(skipped)})" if skipped else "")


main()
