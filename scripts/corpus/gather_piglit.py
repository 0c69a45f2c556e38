#!/usr/bin/env python3
"""piglit (Igalia/piglit, a mirror of mesa/piglit): `.shader_test` scripts whose program is meant
to link, as tests/shaders/shader_runner.c builds it.

Sections `[vertex shader]`, `[tessellation control shader]`, `[tessellation evaluation shader]`,
`[geometry shader]`, `[fragment shader]`, `[compute shader]` hold the text verbatim up to the
next section (several sections of one stage are several shaders, all attached);
`[vertex shader passthrough]` is shader_runner's passthrough source. compile_glsl: a text
without "#version " gets "#version N\\n" first (N from `GLSL >= X.YZ` in [require], " es"
for GLSL ES other than 1.00). Kept: scripts whose [test] says `link success` or draws/probes
(`draw ...`, `compute ...`, `probe ...`), not `link error`; left out: SPIR-V sections,
ARB assembly ([vertex program], [fragment program]), [shader include] (ARB include paths).
Each program directory also gets EXPECTED (`link`), REQUIRE (the [require] lines),
SOURCE (the script's path) and, when [require] says `SSO ENABLED` (shader_runner then links
each stage as its own separable program), SSO (`yes`): linked together those may fail.
Programs with a geometry stage go to GEOM_OUT, the rest to OUT (each capped at 800,
deterministic sample); source name `piglit`.
Usage: gather_piglit.py MIRROR_GIT_DIR OUT_DIR GEOM_OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, cap_sample, write_program  # noqa: E402

PASSTHROUGH = ("#if __VERSION__ >= 130\nin vec4 piglit_vertex;\n#else\n"
               "attribute vec4 piglit_vertex;\n#endif\n"
               "void main() { gl_Position = piglit_vertex; }\n")
STAGES = {"vertex shader": "vertex", "vertex shader passthrough": "vertex",
          "tessellation control shader": "tess-control",
          "tessellation evaluation shader": "tess-eval", "geometry shader": "geometry",
          "fragment shader": "fragment", "compute shader": "compute"}
UNSUPPORTED = re.compile(r"spirv|program\]|shader include|specializations")


def parse(text):
    """[(header, body)] in order."""
    sections, cur = [], None
    for line in text.splitlines(keepends=True):
        m = re.match(r"\[([^\]]+)\]\s*$", line)
        if m:
            cur = [m.group(1).strip(), ""]
            sections.append(cur)
        elif cur is not None:
            cur[1] += line
    return sections


def program(text):
    """(stages, require lines) or None when the script is not a GLSL program meant to link."""
    sections = parse(text)
    heads = [h for h, _ in sections]
    if any(UNSUPPORTED.search(h) for h in heads):
        return None
    require = "".join(b for h, b in sections if h == "require")
    test = "".join(b for h, b in sections if h == "test")
    if re.search(r"^\s*SPIRV\s+(YES|ONLY)", require, re.M):
        return None
    if re.search(r"^\s*link error", test, re.M):
        return None
    if not re.search(r"^\s*(link success|draw|compute|probe)", test, re.M):
        return None
    m = re.search(r"^\s*GLSL\s+(ES\s+)?>=\s*(\d+)\.(\d+)", require, re.M)
    if not m:
        return None
    num = int(m.group(2)) * 100 + int(m.group(3))
    version = f"#version {num}{' es' if m.group(1) and num != 100 else ''}\n"
    stages = []
    for h, b in sections:
        if h in STAGES:
            body = PASSTHROUGH if h == "vertex shader passthrough" else b
            if "#version " not in body:
                body = version + body
            stages.append([STAGES[h], body])
    if not stages:
        return None
    return stages, require


def main():
    m, out, gout = Mirror(sys.argv[1]), sys.argv[2], sys.argv[3]
    found = {"geometry": [], "other": []}
    for p in m.files:
        if not p.endswith(".shader_test"):
            continue
        r = program(m.text(p))
        if r:
            found["geometry" if any(s == "geometry" for s, _ in r[0]) else "other"].append((p, r))
    for kind, dest in (("geometry", gout), ("other", out)):
        picked = cap_sample(found[kind], key=lambda t: t[0])
        for p, (stages, require) in picked:
            name = re.sub(r"^tests/(spec/)?", "", p)[:-len(".shader_test")].replace("/", "_")
            count, files = {}, []
            for stage, body in stages:
                count[stage] = count.get(stage, 0) + 1
                stem = "shader" if count[stage] == 1 else f"shader{count[stage]}"
                files.append((stage, stem, body))
            d = write_program(dest, "piglit", name, files)
            extra = (("SSO", "yes\n"),) if re.search(r"^\s*SSO\s+ENABLED", require, re.M) else ()
            for fname, content in (("EXPECTED", "link\n"), ("REQUIRE", require.strip() + "\n"), ("SOURCE", p + "\n")) + extra:
                with open(os.path.join(d, fname), "w") as fh:
                    fh.write(content)
        print(f"{kind}: {len(picked)} programs of {len(found[kind])} -> {dest}")


main()
