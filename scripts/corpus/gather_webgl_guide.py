#!/usr/bin/env python3
"""WebGL Programming Guide (Matsuda & Lea, 2013): the GLSL ES 1.00 programs its examples link.

Input: a mirror of the book's example archive (skypanda100/webglbook_examples-master, one
"init" commit holding the original ch02..ch10, Appendix, gifts and lib/ of the download; the
author's site is not a git repository). Each example's .js holds its shaders as JS string
expressions (`var VSHADER_SOURCE = 'attribute vec4 a_Position;\\n' + ...;`, comments between
the pieces) and links them with lib/cuon-utils.js: `initShaders(gl, V, F)` (= createProgram +
useProgram) or `createProgram(gl, V, F)` (ProgramObject, Shadow*, gifts/ThreeDUI), which compile
V as the vertex and F as the fragment shader of one program, the text passed as is.
Appendix/LoadShaderFromFiles.js reads its two sources with `readShaderFile(gl, 'X', 'v'|'f')`
(XMLHttpRequest responseText of the file next to it; onReadShader stores 'v' in VSHADER_SOURCE,
'f' in FSHADER_SOURCE) before calling initShaders. Programs are in call order per file.
No shader has a #version line: GLSL ES 1.00 to WebGL. As gather_pixi.py does, `#version 100` is
written first so that desktop tools (glslangValidator -d, Mesa's compatibility context) read ES
1.00 too (the only change to the book's text; line numbers move by one). Examples whose two
texts equal an earlier example's (ch03's HelloTriangle_LINES ..., ch07's view variants) are one
program, written under the first name in path order.
Usage: gather_webgl_guide.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

JS_STRING = r"'(?:\\.|\\\n|[^'\\\n])*'|\"(?:\\.|\\\n|[^\"\\\n])*\"|`(?:\\.|[^`\\])*`"
_JS_TOKEN = re.compile(JS_STRING + r"|//[^\n]*|/\*.*?\*/", re.S)
_ESC = {"n": "\n", "t": "\t", "r": "\r", "b": "\b", "f": "\f", "v": "\v", "0": "\0", "\n": ""}


def strip_js_comments(src):
    return _JS_TOKEN.sub(lambda m: " " if m.group(0)[0] == "/" else m.group(0), src)


def js_string(lit):
    """The value of one JS string literal (no `${}` substitutions)."""
    body = lit[1:-1]
    if lit[0] == "`":
        body = body.replace("\r\n", "\n")

    def esc(m):
        e = m.group(1)
        if e[0] == "x":
            return chr(int(e[1:], 16))
        if e[0] == "u":
            return chr(int(e.strip("u{}"), 16))
        return _ESC.get(e, e)
    return re.sub(r"\\(x[0-9a-fA-F]{2}|u\{[0-9a-fA-F]+\}|u[0-9a-fA-F]{4}|.|\n)", esc, body, flags=re.S)


def js_string_vars(src):
    """name -> value of `NAME = 'a' + "b" + ...;` in comment-free JS (last assignment wins)."""
    out = {}
    for m in re.finditer(rf"\b(\w+)\s*=\s*((?:{JS_STRING})(?:\s*\+\s*(?:{JS_STRING}))*)\s*[;,\n]", src):
        out[m.group(1)] = "".join(js_string(s.group(0)) for s in re.finditer(JS_STRING, m.group(2)))
    return out


def file_sources(m, path, src):
    """Appendix/LoadShaderFromFiles: readShaderFile(gl, 'file', 'v') -> the variable onReadShader sets."""
    out = {}
    targets = dict(re.findall(r"shader\s*==\s*'(\w)'\s*\)\s*\{?\s*(\w+)\s*=\s*fileString", src))
    for c in re.finditer(r"readShaderFile\s*\(\s*\w+\s*,\s*(" + JS_STRING + r")\s*,\s*'(\w)'\s*\)", src):
        var = targets.get(c.group(2))
        text = m.text(os.path.normpath(os.path.join(os.path.dirname(path), js_string(c.group(1)))))
        if var and text is not None:
            out[var] = text
    return out


def es100(text):
    return text if re.match(r"\s*#\s*version", text) else "#version 100\n" + text


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, {}
    for path in sorted(f for f in m.files if f.endswith(".js") and not f.startswith("lib/")):
        src = strip_js_comments(m.text(path))
        strings = js_string_vars(src)
        strings.update(file_sources(m, path, src))
        calls = list(re.finditer(r"\b(?:initShaders|createProgram)\s*\(\s*\w+\s*,\s*(\w+)\s*,\s*(\w+)\s*[,)]", src))
        calls = [c for c in calls if not re.match(r"function\b", src[max(0, c.start() - 9):c.start()].strip())]
        for k, c in enumerate(calls):
            v, f = strings.get(c.group(1)), strings.get(c.group(2))
            if v is None or f is None:
                print("unresolved:", path, c.group(0), file=sys.stderr)
                continue
            name = path[:-3].replace("/", ".") + ("" if len(calls) == 1 else f".{k}")
            if (v, f) in seen:  # another example links the same two texts: the same program
                print("same as", seen[(v, f)] + ":", name, file=sys.stderr)
                continue
            seen[(v, f)] = name
            write_program(out, "webglguide", name, [("vertex", "shader", es100(v)), ("fragment", "shader", es100(f))])
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
