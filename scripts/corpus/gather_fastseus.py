#!/usr/bin/env python3
"""ExDragine/FastSEUS-Renewed: an OptiFine shader pack (Minecraft, SEUS lineage), GLSL 1.20 on
the compatibility profile (ftransform, gl_MultiTexCoord0, gl_Color, gl_TextureMatrix,
gl_ModelViewMatrix, gl_FragData...).

Pairing, as OptiFine's Shaders loads a pack: every program name OptiFine knows (gbuffers_*,
composite..composite15, deferred..deferred15, final, shadow*) is `shaders/<name>.vsh` +
`shaders/<name>.fsh` (+ `<name>.gsh`); files with other names (composite2.vsh1, ...) are not
loaded. Stage text as OptiFine builds it: `#include "x"` lines replaced by the file (relative to
the including file, `/x` from shaders/), recursively, and the fixed macro block
(ShaderMacros: MC_VERSION, MC_GL_VERSION, MC_GLSL_VERSION, OS, vendor and renderer of a Mesa
driver on Linux, MC_RENDER_QUALITY, MC_SHADOW_QUALITY, MC_HAND_DEPTH, MC_RENDER_STAGE_*)
inserted after the #version line. Pack options (shaders.properties) keep their defaults (the
`#define` lines of the sources).
Usage: gather_fastseus.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer  # noqa: E402

ROOT = "shaders"
PROGRAMS = (["gbuffers_" + n for n in (
    "basic", "textured", "textured_lit", "skybasic", "skytextured", "clouds", "terrain",
    "terrain_solid", "terrain_cutout_mip", "terrain_cutout", "damagedblock", "block", "beaconbeam",
    "item", "entities", "entities_glowing", "armor_glint", "spidereyes", "hand", "weather", "water",
    "hand_water", "line")]
    + ["shadow", "shadow_solid", "shadow_cutout"]
    + ["deferred"] + [f"deferred{i}" for i in range(1, 16)]
    + ["composite"] + [f"composite{i}" for i in range(1, 16)] + ["final"])
STAGES = (("vertex", "vsh"), ("geometry", "gsh"), ("fragment", "fsh"))
MACROS = """#define MC_VERSION 11202
#define MC_GL_VERSION 210
#define MC_GLSL_VERSION 120
#define MC_OS_LINUX
#define MC_GL_VENDOR_OTHER
#define MC_GL_RENDERER_MESA
#define MC_RENDER_QUALITY 1.0
#define MC_SHADOW_QUALITY 1.0
#define MC_HAND_DEPTH 0.125
#define MC_RENDER_STAGE_NONE 0
#define MC_RENDER_STAGE_SKY 1
#define MC_RENDER_STAGE_SUNSET 2
#define MC_RENDER_STAGE_SUN 4
#define MC_RENDER_STAGE_CUSTOM_SKY 3
#define MC_RENDER_STAGE_MOON 5
#define MC_RENDER_STAGE_STARS 6
#define MC_RENDER_STAGE_VOID 7
#define MC_RENDER_STAGE_TERRAIN_SOLID 8
#define MC_RENDER_STAGE_TERRAIN_CUTOUT_MIPPED 9
#define MC_RENDER_STAGE_TERRAIN_CUTOUT 10
#define MC_RENDER_STAGE_ENTITIES 11
#define MC_RENDER_STAGE_BLOCK_ENTITIES 12
#define MC_RENDER_STAGE_DESTROY 13
#define MC_RENDER_STAGE_OUTLINE 14
#define MC_RENDER_STAGE_DEBUG 15
#define MC_RENDER_STAGE_HAND_SOLID 16
#define MC_RENDER_STAGE_TERRAIN_TRANSLUCENT 17
#define MC_RENDER_STAGE_TRIPWIRE 18
#define MC_RENDER_STAGE_PARTICLES 19
#define MC_RENDER_STAGE_CLOUDS 20
#define MC_RENDER_STAGE_RAIN_SNOW 21
#define MC_RENDER_STAGE_WORLD_BORDER 22
#define MC_RENDER_STAGE_HAND_TRANSLUCENT 23
"""


def expand(m, path, depth=0):
    text = m.text(path)
    if text is None or depth > 10:
        return None
    out = []
    for line in text.splitlines(keepends=True):
        inc = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
        if not inc:
            out.append(line)
            continue
        name = inc.group(1)
        target = posixpath.normpath(ROOT + "/" + name.lstrip("/") if name.startswith("/")
                                    else posixpath.join(posixpath.dirname(path), name))
        sub = expand(m, target, depth + 1)
        if sub is None:
            return None
        out.append(sub if sub.endswith("\n") else sub + "\n")
    return "".join(out)


def with_macros(text):
    v = re.search(r"^[ \t]*#[ \t]*version[^\n]*\n", text, re.M)
    pos = v.end() if v else 0
    return text[:pos] + MACROS + text[pos:]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "fastseus")
    for prog in PROGRAMS:
        stages = []
        for stage, ext in STAGES:
            path = f"{ROOT}/{prog}.{ext}"
            if m.exists(path):
                text = expand(m, path)
                if text is None:
                    stages = []
                    break
                stages.append((stage, prog, with_macros(text)))
        if {"vertex", "fragment"} <= {s for s, _, _ in stages}:
            w.add(prog, stages)
    w.report()


if __name__ == "__main__":
    main()
