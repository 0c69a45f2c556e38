#!/usr/bin/env python3
"""PacktPublishing/3D-Graphics-Rendering-Cookbook, OpenGL side: in Chapter*/**.cpp and shared/**.cpp,
`GLShader v("data/shaders/x.vert")` shaders and `GLProgram p(v1, v2, ...)` programs
(shared/glFramework/GLShader.cpp: the stage from the extension, the text from
shared/Utils.cpp readShaderFile: a UTF-8 BOM blanked, then repeatedly the first
"#include " up to the next '>' replaced by readShaderFile(<name>), names relative to the
repository root, the working directory). Identical programs are written once.
Usage: gather_3dgrc.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

EXT = {".vert": "vertex", ".frag": "fragment", ".geom": "geometry", ".tesc": "tess-control",
       ".tese": "tess-eval", ".comp": "compute"}


def read_shader(m, name, depth=0):
    data = m.show(name)
    if data is None or depth > 20:
        raise FileNotFoundError(name)
    if data[:3] == b"\xef\xbb\xbf":
        data = b"   " + data[3:]
    code = data.decode("utf-8", "replace")
    while "#include " in code:
        pos = code.find("#include ")
        p1, p2 = code.find("<", pos), code.find(">", pos)
        if p1 < 0 or p2 < 0 or p2 <= p1:
            raise ValueError("bad include")
        code = code[:pos] + read_shader(m, code[p1 + 1:p2], depth + 1) + code[p2 + 1:]
    return code


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, set()
    for f in m.files:
        if not (f.startswith(("Chapter", "shared/")) and f.endswith(".cpp")):
            continue
        src = strip_cpp_comments(m.text(f))
        shaders = {v: p for v, p in re.findall(r'GLShader\s+(\w+)\s*[({]\s*"([^"]+)"\s*[)}]', src)}
        for name, args in re.findall(r"GLProgram\s+(\w+)\s*[({]([\w\s,]+)[)}]", src):
            vars_ = [a.strip() for a in args.split(",") if a.strip()]
            if not vars_ or any(v not in shaders for v in vars_):
                continue
            stages = []
            try:
                for v in vars_:
                    p = shaders[v]
                    stages.append((EXT[os.path.splitext(p)[1]], os.path.basename(p).rsplit(".", 1)[0], read_shader(m, p)))
            except (FileNotFoundError, ValueError, KeyError):
                continue
            key = tuple(stages)
            if key in seen:
                continue
            seen.add(key)
            sample = os.path.dirname(f).replace("/", "_")
            write_program(out, "3dgrc", f"{sample}.{name}", stages)
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
