#!/usr/bin/env python3
"""PacktPublishing/Mastering-Graphics-Programming-with-Vulkan (Vulkan): the graphics pipelines of
each chapter's technique files source/chapterN/shaders/*.json, as the Raptor engine's
RenderResourcesLoader::load_gpu_technique / parse_gpu_pipeline and GpuDevice::compile_shader
build them. A pipeline's "shaders" list gives per stage the "includes" then the "shader" file
(from the chapter's shaders/ folder, RAPTOR_SHADER_FOLDER), concatenated as they are; the
stage is compiled by `glslangValidator -V --target-env vulkan1.2 -S <stage> --D <STAGE>_<PIPELINE>
--D <STAGE>` (pipeline name upper-cased), so the two macros are written as `#define` lines after
the #version line (where glslang's preamble puts them) and FLAGS holds the target env.
Pipelines with a vertex and a fragment stage only (compute, mesh, task and ray-tracing ones
left out); `inherit_from` pipelines (same stages, compiled under the child's name) left out;
programs identical to an earlier chapter's once.
Usage: gather_mastering_vulkan.py MIRROR_GIT_DIR OUT_DIR
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

STAGES = {"vertex": "VERTEX", "fragment": "FRAGMENT", "geometry": "GEOMETRY"}


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    techs = sorted((f for f in m.files if re.match(r"source/chapter\d+/shaders/[^/]+\.json$", f)),
                   key=lambda f: (int(re.search(r"chapter(\d+)", f).group(1)), f))
    n, seen = 0, set()
    for f in techs:
        folder = os.path.dirname(f)
        try:
            data = json.loads(m.text(f))
        except ValueError:
            continue
        for pipe in data.get("pipelines", []):
            shaders = pipe.get("shaders") or []
            kinds = [s.get("stage") for s in shaders]
            if "inherit_from" in pipe or "vertex" not in kinds or "fragment" not in kinds or not set(kinds) <= set(STAGES):
                continue
            stages = []
            for s in shaders:
                parts = [m.text(f"{folder}/{inc}") for inc in s.get("includes", [])] + [m.text(f"{folder}/{s['shader']}")]
                if any(p is None for p in parts):
                    break
                code = "".join(parts)
                st = STAGES[s["stage"]]
                defs = f"#define {st}_{pipe['name'].upper()}\n#define {st}\n"
                v = re.search(r"^[ \t]*#version[^\n]*\n", code, re.M)
                code = code[:v.end()] + defs + code[v.end():] if v else defs + code
                stages.append((s["stage"], os.path.splitext(s["shader"])[0], code))
            else:
                key = tuple(t for _, _, t in stages)
                if key in seen:
                    continue
                seen.add(key)
                chapter = re.search(r"(chapter\d+)", f).group(1)
                d = write_program(out, "mastering_vk", f"{chapter}.{data.get('name', os.path.basename(f)[:-5])}.{pipe['name']}", stages)
                with open(os.path.join(d, "FLAGS"), "w") as fh:
                    fh.write("-V --target-env vulkan1.2 -l\n")
                n += 1
    print(n, "programs")


main()
