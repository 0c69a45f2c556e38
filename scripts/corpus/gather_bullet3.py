#!/usr/bin/env python3
"""bulletphysics/bullet3 (physics engine; its example browser's OpenGL 3 renderer, in place of
xbmc/xbmc, which is over the snapshot limit with every fork that has system/shaders/GL): every
program its C++ links.

- `X = gltLoadShaderPair(vs, fs)` (examples/OpenGLWindow/LoadShader.cpp): glShaderSource(shader, 1,
  &text, NULL) of each argument, vertex then fragment, attach, link. The arguments are
  `static const char* name = "..." "...";` literals of the calling file or of the headers it
  `#include`s: GLInstancingRenderer.cpp's `Shaders/*.h` are the build3/stringify output of
  `Shaders/*.glsl` and are what is compiled (the .h text is used, not the .glsl). Callers:
  GLInstancingRenderer::InitShaders (instancing, point sprite, shadow-map create/use, projective
  texture, segmentation mask, points, lines, triangle), GLPrimitiveRenderer and
  test/OpenGLTrueTypeFont.
- `CompileGLShader("Name", vs, fs)` (examples/StandaloneMain/hellovr_opengl_main.cpp, OpenVR):
  glShaderSource of each literal argument, vertex then fragment, link; one program per call.

No preprocessing: each string goes to glShaderSource as written (each ends at its NUL).
Usage: gather_bullet3.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import (Mirror, c_string, c_string_vars, call_args, strip_cpp_comments,  # noqa: E402
                    write_program)


def strings_of(m, path, seen=None):
    """name -> text of the string variables of `path` and of the local headers it includes."""
    seen = set() if seen is None else seen
    if path in seen or not m.exists(path):
        return {}
    seen.add(path)
    src = strip_cpp_comments(m.text(path))
    out = {}
    for inc in re.findall(r'#\s*include\s+"([^"]+)"', src):
        out.update(strings_of(m, posixpath.normpath(posixpath.join(posixpath.dirname(path), inc)), seen))
    out.update({k: v[0] for k, v in c_string_vars(src).items() if len(v) == 1})
    return out


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    n = 0
    callers = [f for f in m.files if f.endswith((".cpp", ".c"))
               and not f.startswith("examples/ThirdPartyLibs/")]
    for path in sorted(callers):
        text = m.text(path)
        if "gltLoadShaderPair(" not in text and "CompileGLShader(" not in text:
            continue
        src = strip_cpp_comments(text)
        strings = strings_of(m, path)
        base = posixpath.basename(posixpath.dirname(path)) if path.startswith("test/") else \
            posixpath.splitext(posixpath.basename(path))[0]
        for c in re.finditer(r"(?:(?P<dst>[\w.>-]+)\s*=\s*)?gltLoadShaderPair\s*\(", src):
            if src[:c.start()].rstrip().endswith(("GLuint", "*")):
                continue  # the definition / declaration
            args = call_args(src, c.end() - 1)
            if len(args) != 2 or not all(re.fullmatch(r"\w+", a) for a in args):
                continue
            vs, fs = strings.get(args[0]), strings.get(args[1])
            if vs is None or fs is None:
                print("skipped (no text):", path, args, file=sys.stderr)
                continue
            dst = re.sub(r".*(?:\.|->)", "", c.group("dst") or "program")
            write_program(out, "bullet3", f"{base}.{dst}",
                          [("vertex", args[0], vs.split("\0")[0]), ("fragment", args[1], fs.split("\0")[0])])
            n += 1
        for c in re.finditer(r"\bCompileGLShader\s*\(", src):
            args = call_args(src, c.end() - 1)
            if len(args) != 3 or not all(a.lstrip().startswith('"') for a in args):
                continue  # the definition
            name = re.sub(r"\W+", "_", c_string(args[0])).strip("_")
            write_program(out, "bullet3", f"{base}.{name}",
                          [("vertex", "vertex", c_string(args[1])), ("fragment", "fragment", c_string(args[2]))])
            n += 1
    print(n, "programs")


main()
