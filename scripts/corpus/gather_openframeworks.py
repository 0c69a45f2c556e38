#!/usr/bin/env python3
"""openFrameworks (openframeworks/openFrameworks, 0.8.0-era master): the desktop programs of the
examples/gl/* samples and the programmable renderer's built-in default shaders, paired and
preprocessed as ofShader does.

Upstream is over the snapshot limit, and so is every fork with recent history; the snapshot used is
bbdumdum/openFrameworks at 750f0ba (2014-02-04, a merge of upstream master by a core developer,
OF_VERSION 0.8.0), which predates examples/shader/*.

Loading (libs/openFrameworks/gl/ofShader.cpp): `load(name)` is `load(name + ".vert", name + ".frag")`;
`load(vert, frag[, geom])` calls setupShaderFromFile for each non-empty path (files under the
example's bin/data/) and links; `setupShaderFromSource(GL_X_SHADER, text)` adds a stage to the object
and `linkProgram()` links what the object holds. setupShaderFromSource passes the text through
parseForIncludes: line by line (std::getline), every line written back with a newline (so the text
ends with one), a `#pragma include "f"` line replaced by the file's text (once per file). Nothing is
prepended: `#version` is what the file or literal has.

Pairing: each desktop sample's src/ofApp.cpp (not android/ios) is read twice, the way a desktop
build runs it with the programmable renderer (ofGLProgrammableRenderer, GL 3.2, `shadersGL3`
folders: `if(ofGetGLProgrammableRenderer()) {..}` then-branch, `#ifdef USE_PROGRAMMABLE_GL` taken)
and with the default GL2 renderer (else-branch, macro undefined); `#ifdef TARGET_OPENGLES` is false.
String arguments are literals, `STRINGIFY(...)` (the C preprocessor's stringification: comments
gone, white space runs one space), string variables and `+` concatenations of those. A program
whose two readings give the same stage texts is written once; otherwise `<example>.gl3` and
`<example>.gl2`. A load whose file is missing from the tree (gpuParticleSystemExample's
`shaders_programmable/`) is left out, as ofShader would fail it. Fragment-only programs (GL2
readings of alphaMaskingShaderExample, multiTextureShaderExample, gpuParticleSystemExample's
position and velocity updates) are kept: the compatibility profile links them.

Built-ins (ofGLProgrammableRenderer.cpp): the non-GLES `static string X = "#version 150\\n"
STRINGIFY(...)` texts, and setup()'s `uniqueShader == false` branch (desktop, not Raspberry Pi):
defaultTexColor, defaultTex2DColor, defaultNoTexColor, defaultTexNoColor, defaultTex2DNoColor,
defaultNoTexNoColor and bitmapStringShader, each setupShaderFromSource pair then linkProgram.

Usage: gather_openframeworks.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import (C_LITERAL, Mirror, c_string, call_args, cpp_ifdefs,  # noqa: E402
                    strip_cpp_comments, write_program)

RENDERER = "libs/openFrameworks/gl/ofGLProgrammableRenderer.cpp"
STAGE_OF = {"GL_VERTEX_SHADER": "vertex", "GL_FRAGMENT_SHADER": "fragment",
            "GL_GEOMETRY_SHADER": "geometry", "GL_GEOMETRY_SHADER_EXT": "geometry"}


def matching(src, i):
    """Index just past the bracket that closes the one at src[i] (literals skipped)."""
    depth, n = 0, len(src)
    while i < n:
        m = re.compile(C_LITERAL).match(src, i)
        if m:
            i = m.end()
            continue
        ch = src[i]
        if ch in "({[":
            depth += 1
        elif ch in ")}]":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return n


def stringify_macros(src, names):
    """Replaces every NAME(...) of a `#define NAME(x) #x` macro by the string literal the
    preprocessor makes of its argument (white space runs one space, ends trimmed)."""
    for name in names:
        while True:
            m = re.search(r"\b%s\s*\(" % name, src)
            if not m:
                break
            end = matching(src, m.end() - 1)
            text = re.sub(r"\s+", " ", src[m.end():end - 1]).strip()
            lit = '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
            src = src[:m.start()] + lit + src[end:]
    return src


def pick_branch(src, cond, then):
    """`if(cond){A}else{B}` (and a lone `if(cond){A}`) replaced by A (then) or B / nothing."""
    pat = re.compile(r"if\s*\(\s*" + cond + r"\s*\)\s*\{")
    while True:
        m = pat.search(src)
        if not m:
            return src
        a_end = matching(src, m.end() - 1)
        body_a, rest = src[m.end():a_end - 1], a_end
        body_b = ""
        e = re.compile(r"\s*else\s*\{").match(src, a_end)
        if e:
            b_end = matching(src, e.end() - 1)
            body_b, rest = src[e.end():b_end - 1], b_end
        src = src[:m.start()] + (body_a if then else body_b) + src[rest:]


def parse_for_includes(text, read, included=None, level=0):
    """ofShader::parseForIncludes: each line written back with "\\n"; `#pragma include` spliced."""
    included = [] if included is None else included
    if level > 32:
        return ""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    out = []
    for line in lines:
        m = re.match(r'^[ ]*#[ ]*pragma[ ]*include[ ]+["<](.*)[">].*', line)
        if not m:
            out.append(line + "\n")
            continue
        inc = m.group(1)
        if inc in included:
            continue
        included.append(inc)
        body = read(inc)
        if body:
            out.append(parse_for_includes(body, read, included, level + 1) + "\n")
    return "".join(out)


class Tracer:
    """Follows string variables and ofShader calls of comment-free, branch-resolved C++."""

    CALL = re.compile(r"(?P<obj>\w+(?:\(\))?)\s*(?:\.|->)\s*"
                      r"(?P<fn>load|setupShaderFromSource|setupShaderFromFile|linkProgram)\s*\(")
    ASSIGN = re.compile(r"(?:\bstring\s+)?(?P<var>\w+)\s*=\s*(?P<expr>(?:%s|[^;\"])*);" % C_LITERAL)

    def __init__(self, read):
        self.read = read  # data-relative path -> text or None
        self.vars, self.pending, self.programs = {}, {}, []

    def value(self, expr):
        """A string expression: literals, variables, `+` of those; None when unknown."""
        out = ""
        for part in (t.group(0) for t in re.finditer(C_LITERAL + r"|\w+", expr)):
            if part.startswith(('"', 'R"')):
                out += c_string(part)
            elif part in self.vars:
                out += self.vars[part]
            else:
                return None
        return out

    def run(self, src, obj_filter=None):
        pos = 0
        events = sorted([(m.start(), "call", m) for m in self.CALL.finditer(src)] +
                        [(m.start(), "assign", m) for m in self.ASSIGN.finditer(src)
                         if re.search(C_LITERAL, m.group("expr"))], key=lambda e: e[0])
        for start, kind, m in events:
            if start < pos:
                continue
            if kind == "assign":
                v = self.value(m.group("expr"))
                if v is not None:
                    self.vars[m.group("var")] = v
                continue
            obj, fn = m.group("obj"), m.group("fn")
            args = call_args(src, m.end() - 1)
            pos = m.end()
            if obj_filter and not obj_filter(obj):
                continue
            stages = self.pending.setdefault(obj, [])
            if fn == "load":
                vals = [self.value(a) for a in args]
                if None in vals:
                    continue
                paths = [vals[0] + ".vert", vals[0] + ".frag"] if len(vals) == 1 else vals
                ok = True
                for stage, path in zip(("vertex", "fragment", "geometry"), paths):
                    if not path:
                        continue
                    text = self.read(path)
                    if text is None:
                        ok = False
                        continue
                    stages.append((stage, path, text))
                if ok:
                    self.programs.append((obj, list(stages)))
                self.pending[obj] = []
            elif fn in ("setupShaderFromSource", "setupShaderFromFile"):
                stage = STAGE_OF.get(args[0].strip())
                val = self.value(args[1]) if len(args) > 1 else None
                if stage is None or val is None:
                    continue
                text = val if fn == "setupShaderFromSource" else self.read(val)
                if text is not None:
                    stages.append((stage, val if fn == "setupShaderFromFile" else obj, text))
            elif fn == "linkProgram":
                if stages:
                    self.programs.append((obj, list(stages)))
                self.pending[obj] = []
        return self.programs


def processed(stages, read):
    return [(stage, stem, parse_for_includes(text, read)) for stage, stem, text in stages]


def stem_of(stage, name):
    base = posixpath.basename(name)
    base = re.sub(r"\.(vert|frag|geom|glsl|vs|fs|gs)$", "", base)
    base = re.sub(r"\W+", "_", base).strip("_") or "shader"
    return base


def example_programs(m, app):
    """[(label, [(stage, stem, text)])] of one example for the gl3 and gl2 readings."""
    data = posixpath.join(posixpath.dirname(posixpath.dirname(app)), "bin/data")

    def read(p):
        return m.text(posixpath.normpath(posixpath.join(data, p)))

    raw = strip_cpp_comments(m.text(app))
    macros = re.findall(r"#\s*define\s+(\w+)\s*\(\s*(\w+)\s*\)\s*#\s*\2\b", raw)
    readings = {}
    for label, programmable in (("gl3", True), ("gl2", False)):
        src = cpp_ifdefs(raw, {"USE_PROGRAMMABLE_GL"} if programmable else set())
        src = stringify_macros(src, [n for n, _ in macros])
        src = re.sub(r"\bofIsGLProgrammableRenderer\b", "ofGetGLProgrammableRenderer", src)
        src = pick_branch(src, r"ofGetGLProgrammableRenderer\(\)", programmable)
        progs = Tracer(read).run(src)
        readings[label] = [(obj, processed(st, read)) for obj, st in progs]
    return readings


def renderer_programs(m):
    raw = strip_cpp_comments(m.text(RENDERER))
    src = cpp_ifdefs(raw, set())  # not TARGET_OPENGLES, not TARGET_RASPBERRY_PI
    macros = re.findall(r"#\s*define\s+(\w+)\s*\(\s*(\w+)\s*\)\s*#\s*\2\b", raw)
    src = stringify_macros(src, [n for n, _ in macros])
    # The `static string NAME = "..." "...";` texts.
    tracer = Tracer(lambda p: None)
    for mm in re.finditer(r"static\s+string\s+(\w+)\s*=\s*((?:%s|\s)+);" % C_LITERAL, src):
        tracer.vars[mm.group(1)] = c_string(mm.group(2))
    body = src[src.index("ofGLProgrammableRenderer::setup()"):]
    body = body[:matching(body, body.index("{"))]
    body = re.sub(r"\buniqueShader\s*=\s*\w+\s*;", "", body)
    body = pick_branch(body, r"uniqueShader", False)
    progs = tracer.run(body)
    return [(obj.replace("()", ""), processed(st, lambda p: None)) for obj, st in progs]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    n = 0
    apps = sorted(f for f in m.files if re.match(r"examples/(?!android/|ios/)[^/]+/[^/]+/src/ofApp\.cpp$", f))
    for app in apps:
        example = app.split("/")[2]
        readings = example_programs(m, app)
        gl3, gl2 = readings["gl3"], readings["gl2"]
        same = [(o, s) for o, s in gl3 if (o, s) in gl2]
        labelled = [(o, s, None) for o, s in same]
        labelled += [(o, s, "gl3") for o, s in gl3 if (o, s) not in same]
        labelled += [(o, s, "gl2") for o, s in gl2 if (o, s) not in same]
        objs = {o for o, _, _ in labelled}
        seen = {}
        for obj, stages, tag in labelled:
            name = example + ("." + obj if len(objs) > 1 else "") + ("." + tag if tag else "")
            seen[name] = seen.get(name, 0) + 1
            if seen[name] > 1:
                name += ".%d" % seen[name]
            write_program(out, "openframeworks", name,
                          [(st, stem_of(st, stem), text) for st, stem, text in stages])
            n += 1
    for obj, stages in renderer_programs(m):
        write_program(out, "openframeworks", "ofGLProgrammableRenderer." + obj,
                      [(st, obj, text) for st, _, text in stages])
        n += 1
    print(n, "programs")


main()
