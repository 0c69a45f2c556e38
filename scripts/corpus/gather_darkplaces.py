#!/usr/bin/env python3
"""DarkPlacesEngine/darkplaces: the combined GLSL shader (shader_glsl.h, string literals
concatenated as builtinshaderstrings) compiled per mode and permutation the way gl_rmain.c
R_GLSL_CompilePermutation does: "#version 140\\n#define GLSL140\\n" (130 and 120 likewise
for older GL), "#define VERTEX_SHADER\\n" / "#define FRAGMENT_SHADER\\n", the mode's pretext
(shadermodeinfo: "#define MODE_LIGHTMAP\\n", ...), then for every permutation bit (in
shaderpermutationinfo order) its pretext ("#define USEDIFFUSE\\n", ...) when set or "\\n"
when not, no static parms (default cvars), then the source. No geometry stage (the engine
empties that list). Programs: for GLSL 140 every mode with no bit and with each single bit;
for 130 and 120 every mode with no bit.
Usage: gather_darkplaces.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, cap_sample, strip_cpp_comments, write_program  # noqa: E402


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    source = c_string(strip_cpp_comments(m.text("shader_glsl.h")))
    rmain = strip_cpp_comments(m.text("gl_rmain.c"))
    perm_block = re.search(r"shaderpermutationinfo\[SHADERPERMUTATION_COUNT\]\s*=\s*\{(.*?)\};", rmain, re.S).group(1)
    perms = [(c_string(a), c_string(b).strip()) for a, b in
             re.findall(r'\{\s*("(?:\\.|[^"\\])*")\s*,\s*("(?:\\.|[^"\\])*")\s*\}', perm_block)]
    mode_block = re.search(r"shadermodeinfo\[SHADERLANGUAGE_COUNT\]\[SHADERMODE_COUNT\]\s*=\s*\{\s*\{(.*?)\}\s*,?\s*\}\s*;",
                           rmain, re.S).group(1)
    modes = [(c_string(a), c_string(b).strip()) for a, b in
             re.findall(r'\{\s*"combined"\s*,\s*"glsl"\s*,\s*\w+\s*,\s*("(?:\\.|[^"\\])*")\s*,\s*("(?:\\.|[^"\\])*")\s*\}',
                        mode_block)]
    combos = [(140, mode, None) for mode in modes]
    combos += [(140, mode, k) for mode in modes for k in range(len(perms))]
    combos += [(v, mode, None) for v in (130, 120) for mode in modes]
    picked = cap_sample(combos, key=lambda c: f"{c[0]}{c[1][1]}{c[2]}")
    for version, (mode_pre, mode_name), bit in picked:
        head = f"#version {version}\n#define GLSL{version}\n"
        tail = mode_pre + "".join(p if k == bit else "\n" for k, (p, _) in enumerate(perms)) + source
        name = f"glsl{version}.{mode_name.replace('/', '_')}" + (f".{perms[bit][1]}" if bit is not None else "")
        write_program(out, "darkplaces", name, [("vertex", "combined", head + "#define VERTEX_SHADER\n" + tail),
                                                ("fragment", "combined", head + "#define FRAGMENT_SHADER\n" + tail)])
    print(len(picked), f"programs ({len(modes)} modes, {len(perms)} permutation bits)")


main()
