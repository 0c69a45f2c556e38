#!/usr/bin/env python3
"""WebGL2 Fundamentals (gfxfundamentals/webgl2-fundamentals): the programs its example pages link.

Every top-level example page webgl/*.html (the lessons' live samples; webgl/lessons/ holds the
articles, their translations and diagrams, not gathered) holds its shaders either in
`<script id="X" type="x-shader/x-vertex|fragment">` elements (any non-JS type: "notjs", ..) (their `.text`: the raw text between
the tags, CRLF read as LF by the HTML parser) or in JS string expressions of its inline scripts
(`const vs = \\`#version 300 es ...\\`;`, quoted pieces joined by `+`, `${NAME}` of a page
constant such as `const loc_aPosition = 3;` substituted), and pairs them with:
- `webglUtils.createProgramFromSources(gl, [v, f])` (webgl/resources/webgl-utils.js: index 0 is
  the vertex, 1 the fragment shader, text as is) and `webglUtils.createProgramFromScripts(gl,
  ["id", "id"])` (the elements' text, the stage by index); webgl-utils.js has no createProgramInfo,
  so the one page calling `webglUtils.createProgramInfo` throws there and links nothing;
- twgl (webgl/resources/twgl-full.min.js 4.17 or the 4.x CDN build): `twgl.createProgramInfo(gl,
  [a, b][, opts])` (a source without a newline is an element id, its text taken),
  `twgl.createProgramFromSources`, `twgl.createProgramFromScripts` (ids; stage by index) and
  `twgl.createProgram(gl, [a, b])` (an element id gives its text, and its type the stage); twgl's
  loadShader drops one leading blank line (`/^[ \\t]*\\n/`) before glShaderSource;
- the first lessons' own `createShader(gl, gl.VERTEX_SHADER, src)` + `createProgram(gl, vs, fs)`
  (gl.shaderSource with the text as is).
An identifier argument is the string the page assigns to it last before the call (else anywhere:
top-level `var`s set later in the page). Calls whose sources are built at run time (template
literals with `${..}` other than a page constant's name, arrays joined, sources read from the DOM in a loop) are counted as
unresolved and left out. Programs whose two texts equal an earlier page's (translations of a
sample, step-by-step variants) are one program, written under the first page in path order.
A stage without `#version` is GLSL ES 1.00 (WebGL 2 takes both); as in gather_pixi.py it gets
`#version 100` as its first line so desktop tools read ES 1.00 too.
Usage: gather_webgl2_fundamentals.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402
from gather_webgl_guide import JS_STRING, es100, js_string, strip_js_comments  # noqa: E402

JS_TYPES = {"", "text/javascript", "application/javascript", "module", "text/ecmascript"}
TWGL_BLANK = re.compile(r"^[ \t]*\n")
ARG = rf"(?:{JS_STRING}|[\w$.]+)"


def page_parts(html):
    """(elements id -> (type, text), inline JS of the page in order)."""
    html = html.replace("\r\n", "\n").replace("\r", "\n")
    elems, js = {}, []
    for m in re.finditer(r"<script\b([^>]*)>(.*?)</script\s*>", html, re.S | re.I):
        attrs, body = m.group(1), m.group(2)
        typ = re.search(r"""type\s*=\s*["']([^"']*)["']""", attrs)
        ident = re.search(r"""id\s*=\s*["']([^"']*)["']""", attrs)
        t = typ.group(1).strip().lower() if typ else ""
        if t not in JS_TYPES:  # a data block (x-shader/x-vertex, "notjs", "whatever"): its text
            if ident:
                elems[ident.group(1)] = (t, body)
        elif not re.search(r"\bsrc\s*=", attrs):
            js.append(body)
    return elems, "\n".join(js)


def constants(src):
    """name -> text of `const|let|var NAME = <number or string literal>;` (for `${NAME}`)."""
    out = {}
    for m in re.finditer(rf"\b(?:const|let|var)\s+([\w$]+)\s*=\s*(-?\d+(?:\.\d*)?|{JS_STRING})\s*[;,\n]", src):
        v = m.group(2)
        if v[0] in "'\"`":
            if "${" in v:
                continue
            v = js_string(v)
        out.setdefault(m.group(1), set()).add(v)
    return {k: next(iter(v)) for k, v in out.items() if len(v) == 1}


def substitute(lit, consts):
    """A template literal with each `${NAME}` of a page constant replaced (as JS would)."""
    return re.sub(r"\$\{\s*([\w$]+)\s*\}", lambda m: consts.get(m.group(1), m.group(0)), lit)


def string_defs(src):
    """[(offset, name, value or None when built at run time)]."""
    out = []
    consts = constants(src)
    for m in re.finditer(rf"(?<![\w$.])([\w$]+)\s*=(?!=)\s*((?:{JS_STRING})(?:\s*\+\s*(?:{JS_STRING}|[\w$.]+))*)", src):
        pieces = [substitute(p, consts) if p[0] == "`" else p for p in re.findall(rf"{JS_STRING}|[\w$.]+", m.group(2))]
        if any(not p[0] in "'\"`" or (p[0] == "`" and "${" in p) for p in pieces):
            out.append((m.start(), m.group(1), None))
        else:
            out.append((m.start(), m.group(1), "".join(js_string(p) for p in pieces)))
    return out


def resolve(defs, arg, pos):
    arg = arg.strip()
    if arg[:1] in "'\"`":
        return None if "${" in arg else js_string(arg)
    before = [v for off, n, v in defs if n == arg and off < pos]
    if before:
        return before[-1]
    anywhere = [v for off, n, v in defs if n == arg]
    return anywhere[-1] if anywhere else None


def split_args(s):
    return [a.group(0) for a in re.finditer(ARG, s)]


def programs_of(html):
    """[(stages [(stage, text)], how)] in call order; None text = unresolved."""
    elems, src = page_parts(html)
    src = strip_js_comments(src)
    defs = string_defs(src)
    found = []
    lib = (r"(?P<lib>twgl|webglUtils)?\.?(?P<fn>createProgramInfo|createProgramFromSources|createProgramFromScripts|createProgram)"
           r"\s*\(\s*[\w$.]+\s*,\s*\[(?P<args>[^\]]*)\]")
    for c in re.finditer(lib, src):
        if not c.group("lib") and src[c.start() - 1:c.start()] == ".":
            continue  # some other object's method
        lib_name = c.group("lib") or "twgl"
        if lib_name == "webglUtils" and c.group("fn") not in ("createProgramFromSources", "createProgramFromScripts"):
            # webgl-utils.js exports no createProgramInfo (webgl-picking-w-gpu-1pixel-w-texture
            # calls it and throws: nothing is linked), and its createProgram takes shader objects
            print("not a webgl-utils.js program call:", c.group(0).split("(")[0], file=sys.stderr)
            continue
        args = [resolve(defs, a, c.start()) for a in split_args(c.group("args"))]
        stages = []
        for k, a in enumerate(args):
            stage = "vertex" if k == 0 else "fragment"
            text = a
            by_id = c.group("fn") == "createProgramFromScripts" or (
                lib_name == "twgl" and a is not None and (
                    (c.group("fn") == "createProgramInfo" and "\n" not in a) or
                    (c.group("fn") == "createProgram" and a in elems)))
            if by_id:
                el = elems.get(a)
                text = el[1] if el else None
                if el and c.group("fn") == "createProgram":
                    stage = "fragment" if "frag" in el[0] else "vertex" if "vert" in el[0] else stage
            if text is not None and lib_name == "twgl":
                text = TWGL_BLANK.sub("", text, count=1)
            stages.append((stage, text))
        found.append((c.start(), stages))
    # the page's own createShader(gl, gl.X_SHADER, src) + createProgram(gl, a, b)
    shaders = {}
    for c in re.finditer(r"([\w$]+)\s*=\s*createShader\s*\(\s*[\w$]+\s*,\s*[\w$]+\.(VERTEX|FRAGMENT)_SHADER\s*,\s*(" + ARG + r")\s*\)"
                         r"|(?<![\w$.])createProgram\s*\(\s*[\w$]+\s*,\s*([\w$]+)\s*,\s*([\w$]+)\s*\)", src):
        if c.group(1):
            shaders[c.group(1)] = (c.group(2).lower(), resolve(defs, c.group(3), c.start()))
        elif c.group(4) in shaders and c.group(5) in shaders:
            found.append((c.start(), [shaders[c.group(4)], shaders[c.group(5)]]))
    return [s for _, s in sorted(found, key=lambda f: f[0])]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, unresolved, seen = 0, 0, {}
    for path in sorted(f for f in m.files if re.match(r"webgl/[^/]+\.html$", f)):
        progs = programs_of(m.text(path))
        for k, stages in enumerate(progs):
            name = os.path.basename(path)[:-5] + ("" if len(progs) == 1 else f".{k}")
            if len(stages) != 2 or any(t is None for _, t in stages) or {s for s, _ in stages} != {"vertex", "fragment"}:
                print("unresolved:", path, k, file=sys.stderr)
                unresolved += 1
                continue
            key = tuple(t for _, t in stages)
            if key in seen:
                continue
            seen[key] = name
            write_program(out, "webgl2fund", name, [(s, "shader", es100(t)) for s, t in stages])
            written += 1
    print(written, "programs,", unresolved, "unresolved calls")


if __name__ == "__main__":
    main()
