#!/usr/bin/env python3
"""horde3d/Horde3D: the GLSL programs of the .shader resources as the OpenGL 2 backend builds them
(GLSL 1.10: the GL2 device sets no version preamble).

Pairing, as ShaderResource::load / compileCombination do it:
- a .shader file is split at `[[NAME]]` section headers; `[[FX]]` holds the effect, every other
  section is a private code resource;
- each top-level `context X { VertexShader = compile GLSL A; PixelShader = compile GLSL B; }` of
  the FX section (the ones outside the `OpenGL4 { }` / `OpenGLES3 { }` blocks, which are the
  other backends' contexts) is one program: section A as the vertex stage, B as the fragment
  stage (GeometryShader when present);
- CodeResource::load: outside comments, `#include "res"` up to the end of its line is replaced by
  the named code resource (a file relative to the Content directory, itself assembled the same
  way), and a flag token `_Fnn_Name` is cut to `_Fnn_`;
- combination mask 0 (no flags) and the masks of the *.material.xml files that name the shader
  (`<ShaderFlag name="_Fnn_..."/>`), with compileCombination's flag block
  (`\r\n// ---- Flags ----\r\n#define _Fnn_\r\n...// ---------------\r\n`) before the code.
Identical programs are written once. Only the compatibility-profile filter of legacy_common.
Usage: gather_horde3d.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer  # noqa: E402


def code_resource(m, text, content_root, depth=0):
    """CodeResource::load + assembleCode on `text`."""
    out, i, n = [], 0, len(text)
    line_c = block_c = False
    while i < n:
        if not line_c and not block_c and text.startswith("//", i):
            line_c = True
        elif not line_c and not block_c and text.startswith("/*", i):
            block_c = True
        if line_c and text[i] in "\r\n":
            line_c = False
        elif block_c and text.startswith("*/", i):
            block_c = False
        if not line_c and not block_c and text.startswith("#include", i):
            j = i + 8
            end = j
            while end < n and text[end] not in "\r\n":
                end += 1
            q = re.search(r'"([^"\r\n]*)"', text[j:end])
            if not q or depth > 8:
                return None
            inc = m.text(f"{content_root}/{q.group(1)}")
            if inc is None:
                return None
            sub = code_resource(m, inc, content_root, depth + 1)
            if sub is None:
                return None
            out.append(sub)
            i = end
            continue
        if not line_c and not block_c and re.match(r"_F\d\d_", text[i:i + 5]):
            out.append(text[i:i + 5])
            i += 5
            while i < n and text[i] not in " \t\r\n":
                i += 1
            continue
        out.append(text[i])
        i += 1
    return "".join(out)


def top_level_blocks(fx):
    """The FX text with the `Name { ... }` backend blocks (OpenGL4, OpenGLES3) removed."""
    out, i = [], 0
    for mm in re.finditer(r"\b(OpenGL4|OpenGLES3)\s*\{", fx):
        if mm.start() < i:
            continue
        out.append(fx[i:mm.start()])
        depth, j = 0, mm.end() - 1
        while j < len(fx):
            depth += {"{": 1, "}": -1}.get(fx[j], 0)
            if depth == 0:
                break
            j += 1
        i = j + 1
    out.append(fx[i:])
    return "".join(out)


def material_masks(m):
    """shader path (relative to Content) -> set of flag-number tuples used by materials."""
    masks = {}
    for f in (x for x in m.files if x.endswith(".material.xml")):
        x = m.text(f)
        s = re.search(r'<Shader\s+source="([^"]+)"', x)
        if not s:
            continue
        flags = tuple(sorted({int(n) for n in re.findall(r'<ShaderFlag\s+name="_F(\d\d)_', x)}))
        if flags:
            masks.setdefault(s.group(1), set()).add(flags)
    return masks


def flag_block(flags):
    if not flags:
        return ""
    return ("\r\n// ---- Flags ----\r\n" + "".join(f"#define _F{n:02d}_\r\n" for n in flags)
            + "// ---------------\r\n")


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "horde3d")
    masks = material_masks(m)
    for f in sorted(x for x in m.files if x.endswith(".shader")):
        text = m.text(f)
        content_root = f[:f.rfind("/shaders/")] if "/shaders/" in f else os.path.dirname(f)
        parts = re.split(r"^\[\[(\w+)\]\][^\n]*\n?", text, flags=re.M)
        sections = {parts[k]: parts[k + 1] for k in range(1, len(parts) - 1, 2)}
        fx = sections.get("FX")
        if fx is None:
            continue
        fx = re.sub(r"/\*.*?\*/|//[^\n]*", " ", fx, flags=re.S)
        shader = os.path.splitext(os.path.basename(f))[0]
        prefix = f.split("/")[0] + "." if not f.startswith("Horde3D/") else ""
        for ctx in re.finditer(r"\bcontext\s+(\w+)\s*\{([^{}]*)\}", top_level_blocks(fx)):
            body = ctx.group(2)
            stages = []
            for key, stage in (("VertexShader", "vertex"), ("GeometryShader", "geometry"),
                               ("PixelShader", "fragment")):
                s = re.search(rf"\b{key}\s*=\s*compile\s+GLSL\s+(\w+)\s*;", body)
                if s:
                    code = sections.get(s.group(1))
                    code = None if code is None else code_resource(m, code, content_root)
                    if code is None:
                        stages = None
                        break
                    stages.append((stage, s.group(1), code))
            if not stages or {s for s, _, _ in stages} < {"vertex", "fragment"}:
                continue
            rel = f[len(content_root) + 1:]
            for flags in [()] + sorted(masks.get(rel, ())):
                name = f"{prefix}{shader}.{ctx.group(1)}" + "".join(f".F{n:02d}" for n in flags)
                w.add(name, [(st, stem, flag_block(flags) + code) for st, stem, code in stages])
    w.report()


if __name__ == "__main__":
    main()
