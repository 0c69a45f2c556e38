#!/usr/bin/env python3
"""freedesktop/mesa-demos (GitHub mirror of Mesa's demos): GLSL programs as the demos build them.

- C sources under src/ (not src/egl: GLES): util/shaderutil.c's CompileShaderText(GL_X_SHADER, text)
  and CompileShaderFile(GL_X_SHADER, file) (the file read verbatim, relative to the demo's own
  directory, which is where the demos run from) make shaders; LinkShaders(v, f),
  LinkShaders3(v, g, f) and LinkShaders3WithGeometryInfo(v, g, f, ...) attach the non-zero
  ones (in that order) and link; plain glCreateShader/glShaderSource/glAttachShader/glLinkProgram
  in source order are followed too (mirror.GLTrace). #if/#ifdef resolved as on Linux (nothing
  defined, `#if 1` taken, `#if 0` not). A program with a stage whose text cannot be
  resolved statically (read from argv, sprintf-built) is left out.
  The demos' LoadAndCompileShader(shader, text) / load_and_compile_shader helpers are read as
  glShaderSource(shader, 1, &text, NULL); with no argv the demos use their inline texts.
- src/glsl/*.shtest: shtest.c's `vs FILE` / `fs FILE` lines.
- src/fpglsl/*.glsl: fp-tri.c's fragment shader file (argv) linked with its inline vertShaderText;
  src/vpglsl/*.glsl: vp-tris.c's vertex shader file with its inline fragShaderText.
Identical programs are written once.
Usage: gather_mesademos.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer, strip_cpp_comments, c_string, C_LITERAL  # noqa: E402
from mirror import GLTrace, c_string_vars, cpp_ifdefs, STAGE_NAMES  # noqa: E402

STEM = {"vertex": "vs", "fragment": "fs", "geometry": "gs"}


def link_rewrite(src):
    """prog = LinkShaders(a, b) -> glCreateProgram/glAttachShader/glLinkProgram calls."""
    def rep(m):
        dst, fn, args = m.group(1), m.group(2), [a.strip() for a in m.group(3).split(",")]
        shaders = args[:2] if fn == "LinkShaders" else args[:3]
        calls = [f"{dst} = glCreateProgram();"]
        calls += [f"glAttachShader({dst}, {s});" for s in shaders if s not in ("0", "NULL")]
        return " ".join(calls + [f"glLinkProgram({dst});"])
    return re.sub(r"([\w.\[\]>-]+)\s*=\s*(LinkShaders3WithGeometryInfo|LinkShaders3|LinkShaders)\s*\(([^;]*?)\)\s*;", rep, src)


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "mesademos")
    for f in sorted(m.files):
        if not f.startswith("src/") or not f.endswith((".c", ".cpp")) or f.startswith(("src/egl/", "src/util/")):
            continue
        raw = m.text(f)
        if not re.search(r"glShaderSource|CompileShader(Text|File)", raw):
            continue
        src = link_rewrite(cpp_ifdefs(strip_cpp_comments(raw)))
        # the demos' own compile helpers around glShaderSource(shader, 1, &text, NULL)
        src = re.sub(r"\b(?:LoadAndCompileShader|load_and_compile_shader)\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)",
                     r"glShaderSource(\1, 1, &\2, NULL)", src)
        d = os.path.dirname(f)
        strings = c_string_vars(src)
        for v in re.finditer(rf"(\w+)\s*\[\s*\]\s*=\s*((?:{C_LITERAL}|\s)+);", src):
            strings[v.group(1)] = [c_string(v.group(2))]

        def value(expr):
            expr = expr.strip()
            if expr.startswith('"'):
                return c_string(expr)
            vals = strings.get(expr)
            return vals[0] if vals and len(vals) == 1 else None

        def text_loader(mm):
            return STAGE_NAMES.get(mm.group("st")), value(mm.group("e"))

        def file_loader(mm):
            name = value(mm.group("e"))
            return STAGE_NAMES.get(mm.group("st")), (m.text(f"{d}/{name}") if name else None)

        tr = GLTrace(src, loaders=[
            (r"CompileShaderText\s*\(\s*GL_(?P<st>\w+?)_SHADER(?:_ARB)?\s*,\s*(?P<e>[^()]*?)\s*\)", text_loader),
            (r"CompileShaderFile\s*\(\s*GL_(?P<st>\w+?)_SHADER(?:_ARB)?\s*,\s*(?P<e>[^()]*?)\s*\)", file_loader)])
        tr.strings.update(strings)
        tr.run()
        base = os.path.splitext(os.path.basename(f))[0]
        for prog, stages in tr.programs:
            if not stages or any(s is None or s[0] is None or s[1] is None for s in stages):
                continue
            files, count = [], {}
            for stage, text in stages:
                count[stage] = count.get(stage, 0) + 1
                files.append((stage, STEM.get(stage, stage) + ("" if count[stage] == 1 else str(count[stage])), text))
            w.add(f"{d.split('/')[-1]}.{base}.{re.sub(r'[^A-Za-z0-9_]+', '_', prog)}", files)
    for f in sorted(x for x in m.files if x.endswith(".shtest")):
        d, stages = os.path.dirname(f), []
        for line in m.text(f).splitlines():
            mm = re.match(r"(vs|fs)\s+(\S+)", line)
            if mm:
                stages.append(("vertex" if mm.group(1) == "vs" else "fragment",
                               os.path.splitext(mm.group(2))[0], m.text(f"{d}/{mm.group(2)}")))
        if stages and all(t is not None for _, _, t in stages):
            w.add("shtest." + os.path.splitext(os.path.basename(f))[0], stages)
    for d, prog, other, other_stage, own_stage in (("src/fpglsl", "fp-tri.c", "vertShaderText", "vertex", "fragment"),
                                                   ("src/vpglsl", "vp-tris.c", "fragShaderText", "fragment", "vertex")):
        inline = c_string_vars(strip_cpp_comments(m.text(f"{d}/{prog}")))[other][0]
        for f in sorted(x for x in m.files if x.startswith(d + "/") and x.endswith(".glsl")):
            stem = os.path.splitext(os.path.basename(f))[0]
            stages = [(own_stage, stem, m.text(f)), (other_stage, STEM[other_stage], inline)]
            stages.sort(key=lambda s: s[0] != "vertex")
            w.add(f"{d.split('/')[-1]}.{stem}", stages)
    w.report()


main()
