#!/usr/bin/env python3
"""three.js (mrdoob/three.js, npm package `three` 0.187.0): the GLSL ES 3.00 programs its
WebGLRenderer links for a set of scenes, taken from the renderer itself.

Input: the unpacked npm package (`npm pack three@0.187.0 && tar xzf three-0.187.0.tgz` gives
PACKAGE_DIR=package; the git repository is far over the fetch size limit). three.js builds each
program in WebGLProgram from parameters WebGLPrograms.getParameters derives from the material,
the object (skinning, morph targets, instancing, batching, vertex colors, tangents, uv1..3), the
scene's lights/shadows/fog/environment and the renderer's settings (tone mapping, output color
space, clipping, logarithmic depth, shadow map type, precision): `#version 300 es`, the GLSL 1
compatibility defines (`#define attribute in`, `#define gl_FragColor pc_fragColor`, ...), the
precision block, `#define SHADER_TYPE/SHADER_NAME`, the material's `defines`, one `#define` or
blank line per parameter, uniform/attribute prologue, then ShaderLib's text with
`#include <chunk>` resolved recursively from ShaderChunk, NUM_DIR_LIGHTS/NUM_POINT_LIGHTS/...
and clipping plane counts substituted, and `#pragma unroll_loop_start` loops unrolled.
Re-implementing that would be guesswork, so gather_three_harness.mjs runs the package's own
src/Three.js under node against a recording stub WebGL 2 context (desktop-GPU answers: highp
supported, 16 texture units, the usual WebGL 2 extensions, every compile/link succeeds) and
records each glShaderSource text attached to a linked program. Scenes: every built-in mesh
material with defaults and with its maps; lights (ambient, hemisphere, 2 directional, point, spot,
rect area, light probe), shadows (PCF, VSM, basic, spot light map) with the depth/distance/VSM
programs they add; fog, vertex colors, skinning, morph targets, instancing, BatchedMesh, clipping,
logarithmic depth, each tone mapping, linear output; MeshPhysicalMaterial with all features and
with transmission; lines, points, sprites, shadow material; backgrounds and PMREM filtering;
one ShaderMaterial (GLSL 1 user code) and one RawShaderMaterial (GLSL3). Program name:
scene + `.` + SHADER_NAME (internal ShaderMaterials) or SHADER_TYPE; identical programs once.
Usage: gather_three.py PACKAGE_DIR OUT_DIR   (needs node)
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import write_program  # noqa: E402


def main():
    pkg, out = sys.argv[1], sys.argv[2]
    harness = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gather_three_harness.mjs")
    res = subprocess.run(["node", harness, pkg], capture_output=True, text=True, check=True)
    for line in res.stderr.splitlines():
        if "Error" in line:
            print("harness:", line, file=sys.stderr)
    n, seen, names = 0, set(), {}
    for line in res.stdout.splitlines():
        r = json.loads(line)
        key = (r["vert"], r["frag"])
        if key in seen:
            continue
        seen.add(key)
        sn = re.search(r"^#define SHADER_NAME (\S+)", r["frag"], re.M)
        st = re.search(r"^#define SHADER_TYPE (\S+)", r["frag"], re.M)
        shader = sn.group(1) if sn else (st.group(1) if st else "program")
        name = f"{r['scene']}.{shader}" if not r["scene"].startswith(shader + ".") else r["scene"]
        names[name] = names.get(name, 0) + 1
        if names[name] > 1:
            name += f".{names[name]}"
        stem = shader[0].lower() + shader[1:]
        write_program(out, "three", name, [("vertex", stem, r["vert"]), ("fragment", stem, r["frag"])])
        n += 1
    print(n, "programs")


main()
