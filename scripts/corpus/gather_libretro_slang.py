#!/usr/bin/env python3
"""libretro/slang-shaders: every .slang file whose text, after include expansion, holds
`#pragma stage vertex` and `#pragma stage fragment` is one Vulkan GLSL program, split the way
RetroArch's gfx/drivers_shader/glslang_util.c does it:

- glslang_read_shader_file: the root's first line must start with "#version "; it is kept,
  followed by "#extension GL_GOOGLE_cpp_style_line_directive : require" and `#line 2 "name"`;
  every line starting with "#include " is replaced by the included file (path relative to the
  including file, recursively, `#line 1 "inc"` first) and then `#line i+1 "name"`; every line
  starting with "#endif" or "#pragma" is followed by `#line i+2 "name"`.
- build_stage_source(lines, stage): line 0, then each later line unless it is
  `#pragma name ...` / `#pragma format ...` (dropped) or inside another stage's
  `#pragma stage X` section (the part before any stage pragma is shared).

Written as x.vert / x.frag (source libretro_slang); capped at 800 programs (deterministic
sample). Usage: gather_libretro_slang.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, cap_sample, write_program  # noqa: E402


def read_shader(m, path, out, root, depth=0):
    text = m.text(path)
    if text is None or depth > 30:
        raise FileNotFoundError(path)
    lines = text.split("\n")
    base = posixpath.basename(path)
    if root:
        if not lines[0].startswith("#version "):
            raise ValueError("no #version first")
        out += [lines[0], "#extension GL_GOOGLE_cpp_style_line_directive : require"]
    out.append(f'#line {2 if root else 1} "{base}"')
    for i in range(1 if root else 0, len(lines)):
        line = lines[i]
        if line.startswith("#include "):
            q = line.split('"')
            if len(q) < 3 or not q[1]:
                raise ValueError("bad include")
            inc = posixpath.normpath(posixpath.join(posixpath.dirname(path), q[1]))
            read_shader(m, inc, out, False, depth + 1)
            out.append(f'#line {i + 1} "{base}"')
        elif line.startswith("#endif") or line.startswith("#pragma"):
            out += [line, f'#line {i + 2} "{base}"']
        else:
            out.append(line)
    return out


def stage_source(lines, stage):
    s, active = [lines[0]], True
    for line in lines[1:]:
        if line.startswith("#pragma stage "):
            active = line.rstrip("\r") == f"#pragma stage {stage}"
        elif line.startswith("#pragma name ") or line.startswith("#pragma format "):
            pass
        elif active:
            s.append(line)
            continue
        s.append("")
    return "\n".join(s) + "\n"


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    programs, bad = [], 0
    for p in m.files:
        if not p.endswith(".slang"):
            continue
        try:
            lines = read_shader(m, p, [], True)
        except (FileNotFoundError, ValueError):
            bad += 1
            continue
        stages = {l.rstrip("\r") for l in lines if l.startswith("#pragma stage ")}
        if {"#pragma stage vertex", "#pragma stage fragment"} <= stages:
            programs.append((p, lines))
    picked = cap_sample(programs, key=lambda t: t[0])
    for p, lines in picked:
        stem = posixpath.basename(p)[:-6]
        write_program(out, "libretro_slang", p[:-6].replace("/shaders/", "/").replace("/", "_"), [
            ("vertex", stem, stage_source(lines, "vertex")),
            ("fragment", stem, stage_source(lines, "fragment"))])
    print(len(picked), "programs of", len(programs), f"two-stage .slang files ({bad} unreadable)")


main()
