#!/usr/bin/env python3
"""PacktPublishing/3D-Graphics-Rendering-Cookbook-Second-Edition (Vulkan, LightweightVK): every
graphics `ctx->createRenderPipeline({ .smVert = v, [.smTesc/.smTese/.smGeom = ..,] .smFrag = f })`
of the book's C++ sources (and the `loadShaderModule(ctx, "a.vert"), loadShaderModule(ctx, "b.frag")`
argument runs handed to the VKMesh classes that build the pipeline), with each module variable bound to the last
`v = loadShaderModule(ctx, "path")` before it in the same file (module members assigned in a
constructor count too); identical stage lists once; compute pipelines left out.

Stage text as shared/Utils.cpp readShaderFile builds it (`#include <path>` replaced by the file,
repeatedly, paths from the repository root; a UTF-8 BOM blanked) and then as
lvk::VulkanContext::createShaderModuleFromGLSL patches a source without `#version` (LightweightVK
at the revision deps/bootstrap.json pins, second argument: a mirror of
corporateshark/lightweightvk): the stage's `#version 460` + extension prologue, for fragment
shaders the bindless kTextures*/kSamplers* declarations and each textureBindless*() helper the
source names; geometry shaders get no prologue (LightweightVK adds none).
Usage: gather_3dgrc2.py MIRROR_GIT_DIR LVK_MIRROR_GIT_DIR OUT_DIR
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, strip_cpp_comments, write_program  # noqa: E402

EXT_STAGE = {".vert": "vertex", ".frag": "fragment", ".geom": "geometry", ".tesc": "tess-control",
             ".tese": "tess-eval", ".comp": "compute"}
FIELD = {"smVert": "vertex", "smTesc": "tess-control", "smTese": "tess-eval", "smGeom": "geometry",
         "smFrag": "fragment"}
LIT = r'"(?:\\.|[^"\\\n])*"'


def lvk_prologue(lvk_git, rev):
    """(prologue per stage group, [(substring, code)] for fragment helpers, kTLAS code) from
    createShaderModuleFromGLSL at LightweightVK revision `rev`."""
    src = subprocess.run(["git", f"--git-dir={lvk_git}", "show", f"{rev}:lvk/vulkan/VulkanClasses.cpp"],
                         capture_output=True, text=True, check=True).stdout
    body = src[src.index("VulkanContext::createShaderModuleFromGLSL("):]
    body = body[:body.index("sourcePatched += source;")]
    blocks = [c_string(b) for b in re.findall(rf"sourcePatched \+=((?:\s*{LIT})+)\s*;", body)]
    adds = [(c_string(a), c_string(b)) for a, b in re.findall(rf"addCode\(\s*({LIT})\s*,((?:\s*{LIT})+)\s*\)", body)]
    # blocks: mesh/task, vertex/compute/tess, fragment header, fragment declarations
    return blocks, adds


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[3]
    rev = next(d["source"]["revision"] for d in json.loads(m.text("deps/bootstrap.json")) if d["name"] == "lightweightvk")
    blocks, adds = lvk_prologue(sys.argv[2], rev)

    def read(path, depth=0):
        data = m.show(path)
        if data is None:
            return None
        if data[:3] == b"\xef\xbb\xbf":
            data = b"   " + data[3:]
        code = data.decode("utf-8", "replace")
        while "#include " in code and depth < 16:
            pos = code.index("#include ")
            p1, p2 = code.find("<", pos), code.find(">", pos)
            if p1 < 0 or p2 < 0 or p2 <= p1:
                return None
            inc = read(code[p1 + 1:p2], depth + 1)
            if inc is None:
                return None
            code = code[:pos] + inc + code[p2 + 1:]
        return code

    def patched(path):
        stage = EXT_STAGE[os.path.splitext(path)[1]]
        code = read(path)
        if code is None or "#version " in code:
            return code
        pre = ""
        if stage in ("vertex", "compute", "tess-control", "tess-eval"):
            pre = blocks[1]
        elif stage == "fragment":
            pre = blocks[2]
            for sub, text in adds:
                if sub == "kTLAS[" and sub in code:
                    pre += text
            pre += blocks[3]
            for sub, text in adds:
                if sub != "kTLAS[" and sub in code:
                    pre += text
        return pre + code

    n, seen = 0, set()

    def emit(f, stages):
        nonlocal n
        key = tuple(stages)
        if key in seen:
            return
        texts = [(st, os.path.basename(p).rsplit(".", 1)[0], patched(p)) for st, p in stages]
        if any(t is None for _, _, t in texts):
            return
        seen.add(key)
        chapter = f.split("/src/")[0].replace("/", "_")
        name = chapter + "_" + os.path.basename(stages[-1][1]).rsplit(".", 1)[0]
        while os.path.exists(os.path.join(out, f"3dgrc2__{name}")):
            name += "_"
        write_program(out, "3dgrc2", name, texts)
        n += 1

    for f in m.files:
        if f.startswith("deps/") or not f.endswith((".cpp", ".h")):
            continue
        src = strip_cpp_comments(m.text(f) or "")
        if "createRenderPipeline" not in src:
            continue
        mods = {}
        # modules handed straight to a mesh class that builds the pipeline from them:
        # VKMesh11(ctx, .., loadShaderModule(ctx, "a.vert"), loadShaderModule(ctx, "b.frag"))
        one = rf"loadShaderModule\(\s*\w+\s*,\s*({LIT})\s*\)"
        for mm in re.finditer(rf"{one}(?:\s*,\s*{one})+", src):
            paths = [c_string(p) for p in re.findall(one, mm.group(0))]
            stages = sorted(((EXT_STAGE[os.path.splitext(p)[1]], p) for p in paths),
                            key=lambda sp: ["vertex", "tess-control", "tess-eval", "geometry", "fragment", "compute"].index(sp[0]))
            if [st for st, _ in stages][:1] == ["vertex"] and stages[-1][0] == "fragment":
                emit(f, stages)
        pat = (rf"(?P<var>[\w.\->\[\]]+)\s*=\s*loadShaderModule\(\s*\w+\s*,\s*(?P<path>{LIT})\s*\)"
               r"|createRenderPipeline\(")
        for mm in re.finditer(pat, src):
            if mm.group("var"):
                mods[mm.group("var").split(".")[-1].split(">")[-1]] = c_string(mm.group("path"))
                continue
            depth, end = 1, mm.end()
            while depth and end < len(src):  # the call's balanced argument text
                depth += {"(": 1, ")": -1}.get(src[end], 0)
                end += 1
            fields = dict(re.findall(r"\.(sm\w+)\s*=\s*([\w.\->\[\]]+)", src[mm.end():end]))
            if "smVert" not in fields or "smFrag" not in fields:
                continue
            stages = []
            for fld in ("smVert", "smTesc", "smTese", "smGeom", "smFrag"):
                if fld in fields:
                    var = fields[fld].split(".")[-1].split(">")[-1]
                    if var not in mods:
                        break
                    stages.append((FIELD[fld], mods[var]))
            else:
                emit(f, stages)
    print(n, "programs")


main()
