#!/usr/bin/env python3
"""Pairs SaschaWillems/Vulkan GLSL programs per graphics pipeline, as the examples build them.

examples/<ex>/*.cpp fill a stage array (shaderStages[0] = loadShader(getShadersPath() +
"<ex>/<stem>.vert.spv", ...), `= { loadShader(..), loadShader(..) }`, push_back(loadShader(..)))
and call vkCreateGraphicsPipelines; the stages in the array bound to pStages (cut to stageCount
when set to a number) at each create call form one program; stages loaded but handed to a
pipeline elsewhere (base/ UI overlay, text overlay class, pipeline library) form one program
per array. Also base/*.cpp. The shaders are compiled with plain
`glslangValidator -V` (shaders/glsl/compileshaders.py: no defines; only ray tracing uses #include).
Programs with tessellation are left out. Usage: gather_sascha.py MIRROR_GIT_DIR OUT_DIR
"""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

STAGE = {"vert": "vertex", "frag": "fragment", "geom": "geometry"}
LOAD = re.compile(r'(?:\w+(?:->|::|\.))*load\w*\([^;]*?"([\w\-/]+)\.(vert|frag|geom|tesc|tese|comp)\.(?:spv|bin)"')
SLOT = re.compile(r'(\w+)\[(\d+)\](?:\.module)?\s*=\s*$')
PUSH = re.compile(r'(\w+)\.push_back\(\s*$')
DECL = re.compile(r'(?:std::array<[^;>]*>|std::vector<VkPipelineShaderStageCreateInfo>)\s+(\w+)|\b(\w+)\s*=\s*\{')


def pipelines(src, example):
    """Yields the list of (ext, stem) stages of each graphics pipeline the source creates."""
    arrays, active, limit, used = {}, None, None, set()
    for stmt in src.split(";"):
        for m in DECL.finditer(stmt):
            name = m.group(1) or m.group(2)
            if name in arrays or LOAD.search(stmt, m.end()):
                arrays[name] = []
        for m in re.finditer(r'(\w+)\.clear\(\)', stmt):
            arrays[m.group(1)] = []
        for m in LOAD.finditer(stmt):
            stem, ext = m.group(1), m.group(2)
            if "/" not in stem:
                stem = f"{example}/{stem}"
            before = stmt[:m.start()]
            slot, push = SLOT.search(before), PUSH.search(before)
            if slot:
                arr = arrays.setdefault(slot.group(1), [])
                i = int(slot.group(2))
                arr.extend([None] * (i + 1 - len(arr)))
                arr[i] = (ext, stem)
                name = slot.group(1)
            else:  # push_back or an item of a braced list
                decl = [d.group(1) or d.group(2) for d in DECL.finditer(before)]
                name = push.group(1) if push else (decl[-1] if decl else "?")
                arrays.setdefault(name, []).append((ext, stem))
            active = active if active in arrays and active != "?" else name
        m = re.search(r'pStages\s*=\s*&?(\w+)', stmt)
        if m and m.group(1) in arrays:
            active = m.group(1)
        m = re.search(r'stageCount\s*=\s*(?:static_cast<uint32_t>\()?([\w.]+)', stmt)
        if m:
            limit = int(m.group(1)) if m.group(1).isdigit() else None
        if re.search(r'vkCreateGraphicsPipelines|vkCreateShadersEXT', stmt) and active in arrays and active != "?":
            stages = [s for s in arrays[active][:limit] if s]
            used.update(stages)
            yield stages
    # Stages handed to a pipeline elsewhere (overlay classes, pipeline libraries: "?") form one program.
    for stages in arrays.values():
        if stages and not used & set(stages):
            yield [s for s in stages if s]


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    seen, names = set(), set()
    for f in mirror.files:
        if not (f.startswith(("examples/", "base/")) and f.endswith(".cpp")):
            continue
        example = f.split("/")[-2]
        for stages in pipelines(mirror.text(f), example):
            key = tuple(sorted(set(stages), key=lambda s: (list(STAGE).index(s[0]) if s[0] in STAGE else 9, s[1])))
            exts = [e for e, _ in key]
            if key in seen or "vert" not in exts or not set(exts) <= set(STAGE) or len(set(exts)) != len(exts):
                continue
            texts = [(STAGE[e], os.path.basename(s), mirror.text(f"shaders/glsl/{s}.{e}")) for e, s in key]
            if any(t is None for _, _, t in texts):
                continue
            seen.add(key)
            name = "_".join(s.replace("/", "_") for s in dict.fromkeys(s for _, s in key))
            if name in names:
                name += "_" + "".join(exts)
            names.add(name)
            write_program(out, "sascha", name, texts)
    print(len(seen), "programs")


main()
