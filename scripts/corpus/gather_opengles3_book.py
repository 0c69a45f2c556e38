#!/usr/bin/env python3
"""OpenGL ES 3.0 Programming Guide (danginsburg/opengles3-book): the programs each sample links.

- C samples (Chapter_*/*/*.c): `esLoadProgram ( vShaderStr, fShaderStr )` (Common/Source/
  esShader.c: esLoadShader(GL_VERTEX_SHADER, a), esLoadShader(GL_FRAGMENT_SHADER, b), attach,
  link); each argument is the `char NAME[] = "..." "...";` literal declared last before the call
  (several functions of one file reuse the names vShaderStr/fShaderStr). Hello_Triangle's own
  `LoadShader ( GL_X_SHADER, NAME )` + glAttachShader + glLinkProgram is followed the same way.
  ParticleSystemTransformFeedback's emit program is linked again after
  glTransformFeedbackVaryings; the shaders are the same, so one program.
- Android_Java samples: `ESShader.loadProgram ( vShaderStr, fShaderStr )` with
  `String NAME = "..." + "...";` literals, `ESShader.loadProgramFromAsset ( ctx, "a", "b" )`
  (assets/<a>, the file's bytes as is), HelloTriangle's LoadShader pair. A Java program whose
  two texts equal a C program's is the same program and is not written again (so are C samples
  sharing one pair: Example_6_6, MapBuffers, VertexArrayObjects, TextureWrap).
The text is the literal's value (escapes decoded); every shader has `#version 300 es`.
Chapter_10/PVR_* .pfx effects are PVRShaman workspaces, not loaded by the book's code: left out.
Usage: gather_opengles3_book.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import C_LITERAL, Mirror, c_string, strip_cpp_comments, write_program  # noqa: E402

LITS = rf"(?:{C_LITERAL}|\s|\+)+"


def literal_defs(src):
    """[(offset, name, value)] for `NAME[] = "..." ...;` (C) and `String NAME = "..." + ...;` (Java)."""
    out = []
    for m in re.finditer(rf"(\w+)\s*(?:\[\s*\])?\s*=\s*({LITS});", src):
        if '"' in m.group(2):
            out.append((m.start(), m.group(1), c_string(m.group(2))))
    return out


def value_before(defs, name, pos):
    best = None
    for off, n, v in defs:
        if n == name and off < pos:
            best = v
    return best


def arg_text(defs, arg, pos, asset_dir, m):
    arg = arg.strip()
    if arg.startswith('"'):
        path = f"{asset_dir}/assets/{c_string(arg)}"
        return m.text(path)
    return value_before(defs, arg, pos)


def programs_of(m, path, java):
    src = strip_cpp_comments(m.text(path))
    defs = literal_defs(src)
    asset_dir = path.split("/src/")[0] if java else None
    progs = []
    load = (r"ESShader\.loadProgram(?:FromAsset)?\s*\(\s*(?:\w+\s*,\s*(?=\"))?([^,()]+),\s*([^,()]+)\)" if java
            else r"\besLoadProgram\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)")
    for c in re.finditer(load, src):
        v = arg_text(defs, c.group(1), c.start(), asset_dir, m)
        f = arg_text(defs, c.group(2), c.start(), asset_dir, m)
        progs.append((c.start(), v, f))
    # Hello_Triangle: its own LoadShader ( GL_X_SHADER, NAME ) then attach + link
    shaders = {}
    attached = {}
    for c in re.finditer(r"(\w+)\s*=\s*LoadShader\s*\(\s*(?:GLES30\.)?GL_(VERTEX|FRAGMENT)_SHADER\s*,\s*(\w+)\s*\)"
                         r"|glAttachShader\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)|glLinkProgram\s*\(\s*(\w+)\s*\)", src):
        if c.group(1):
            shaders[c.group(1)] = (c.group(2).lower(), value_before(defs, c.group(3), c.start()))
        elif c.group(4):
            if c.group(5) in shaders:
                attached.setdefault(c.group(4), []).append(shaders[c.group(5)])
        elif c.group(6) in attached:
            st = dict(attached.pop(c.group(6)))
            progs.append((c.start(), st.get("vertex"), st.get("fragment")))
    return [(v, f) for _, v, f in sorted(progs, key=lambda p: p[0])]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, {}
    c_files = sorted(f for f in m.files if re.match(r"Chapter_\d+/[^/]+/[^/]+\.c$", f))
    java_files = sorted(f for f in m.files if re.match(r"Android_Java/Chapter_\d+/.*Renderer\.java$", f))
    for path in c_files + java_files:
        java = path.endswith(".java")
        parts = path.split("/")
        sample = f"{parts[1]}.{parts[2]}" if java else f"{parts[0]}.{parts[1]}"
        progs = programs_of(m, path, java)
        for k, (v, f) in enumerate(progs):
            if v is None or f is None:
                print("unresolved:", path, k, file=sys.stderr)
                continue
            name = sample + ("" if len(progs) == 1 else f".{k}") + (".java" if java else "")
            if (v, f) in seen:
                print("same as", seen[(v, f)] + ":", name, file=sys.stderr)
                continue
            seen[(v, f)] = name
            write_program(out, "opengles3book", name, [("vertex", "shader", v), ("fragment", "shader", f)])
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
