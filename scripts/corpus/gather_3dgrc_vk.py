#!/usr/bin/env python3
"""PacktPublishing/3D-Graphics-Rendering-Cookbook, Vulkan side: in Chapter*/**.{cpp,h} and
shared/**.{cpp,h}, the "data/shaders/.../VK*.{vert,frag,geom,tesc,tese,comp}" literals of each C++
statement are pipelines of those stages in order (`createGraphicsPipeline(..,
{ "a.vert", "a.frag", "a.geom" }, ..)`, `initPipeline({ .. })`, `multiRenderer(ctx, scene,
"a.vert", "a.frag", ..)`, `ComputedImage(vkDev, "a.comp", ..)`); a statement with a lone
fragment stage is a post-processing pass that VulkanShaderProcessor draws with
"data/shaders/chapter08/VK02_Quad.vert"; MultiRenderer's DefaultMeshVertexShader/
DefaultMeshFragmentShader pair too. `testShaderCompilation` calls compile one stage each:
consecutive ones of one file stem form one program. Within a statement a vertex or
compute stage, or a stage met again, starts the next pipeline (initializer lists build
several); a lone vertex stage (the processor's `{ VK02_Quad.vert, shaderFile }`) is none.
Text as shared/Utils.cpp readShaderFile
reads it (a UTF-8 BOM blanked, each "#include <name>" replaced by that file, names relative
to the repository root). Identical programs are written once. Vulkan GLSL (glslang -V).
Usage: gather_3dgrc_vk.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gather_3dgrc import read_shader  # noqa: E402  (readShaderFile, shared by both sides)
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

EXT = {".vert": "vertex", ".frag": "fragment", ".geom": "geometry", ".tesc": "tess-control",
       ".tese": "tess-eval", ".comp": "compute"}
ORDER = ["vertex", "tess-control", "tess-eval", "geometry", "fragment", "compute"]
QUAD = "data/shaders/chapter08/VK02_Quad.vert"
LITERAL = re.compile(r'"(data/shaders/[^"]*/VK[^"]*\.(?:vert|frag|geom|tesc|tese|comp))"')


def pipelines(src):
    """Lists of shader paths, one per statement (or per run of testShaderCompilation)."""
    out, tests = [], []
    for statement in re.split(r";", src):
        paths = LITERAL.findall(statement)
        if not paths or re.search(r"DefaultMesh(?:Vertex|Fragment)Shader\s*=", statement):
            continue
        if "testShaderCompilation" in statement:
            stem = paths[0].rsplit(".", 1)[0]
            if tests and tests[0].rsplit(".", 1)[0] != stem:
                out.append(tests)
                tests = []
            tests += paths
            continue
        # One statement can build several pipelines (a constructor's initializer list):
        # a vertex stage, a compute stage or a repeated stage starts the next one.
        groups = []
        for p in paths:
            kind = EXT[os.path.splitext(p)[1]]
            kinds = [EXT[os.path.splitext(q)[1]] for q in groups[-1]] if groups else []
            if not groups or kind in ("vertex", "compute") or kind in kinds or "compute" in kinds:
                groups.append([])
            groups[-1].append(p)
        for g in groups:
            kinds = [EXT[os.path.splitext(q)[1]] for q in g]
            if "vertex" not in kinds and "compute" not in kinds:
                g = [QUAD] + g
            elif kinds == ["vertex"]:
                continue
            out.append(g)
    if tests:
        out.append(tests)
    defaults = re.findall(r'DefaultMesh(?:Vertex|Fragment)Shader\s*=\s*"([^"]+)"', src)
    if len(defaults) == 2:
        out.append(defaults)
    return out


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, seen = 0, set()
    for f in m.files:
        if not (f.startswith(("Chapter", "shared/")) and f.endswith((".cpp", ".h"))):
            continue
        for paths in pipelines(strip_cpp_comments(m.text(f))):
            try:
                stages = [(EXT[os.path.splitext(p)[1]], os.path.basename(p).rsplit(".", 1)[0], read_shader(m, p)) for p in paths]
            except (FileNotFoundError, ValueError, KeyError):
                continue
            kinds = [s[0] for s in stages]
            if len(set(kinds)) != len(kinds) or ("compute" in kinds and len(kinds) > 1):
                continue
            stages.sort(key=lambda s: ORDER.index(s[0]))
            key = tuple(stages)
            if key in seen:
                continue
            seen.add(key)
            name = "+".join(s[1] for s in stages)
            write_program(out, "3dgrc_vk", f"{os.path.dirname(f).replace('/', '_')}.{name}", stages)
            written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
