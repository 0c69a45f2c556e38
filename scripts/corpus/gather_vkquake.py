#!/usr/bin/env python3
"""Pairs Novum/vkQuake's Vulkan GLSL programs the way Quake/gl_rmisc.c builds its pipelines.

Compilation (meson.build): every file of the `shaders` list is compiled on its own as
`glslangValidator -V [--target-env vulkan1.1] -o <basename>.spv Shaders/<file>` (vulkan1.1 when the
name contains "sops"), and every `shader_variants` entry [source, spv name, args] compiles its
source again with those args (`-DNAME=V` defines, `--target-env vulkan1.1`). The SPIR-V is
embedded as `<name underscorified>_spv` (basic_oit.frag -> basic_oit_frag_spv) and loaded by
R_CreateShaderModules into `<name>_module` (CREATE_SHADER_MODULE[_COND]). A `-DNAME=V` becomes
`#define NAME V` (`-DNAME`: `#define NAME`, as glslangValidator's preamble has it), written after
the #version line; `#include "x.inc"` (GL_GOOGLE_include_directive) is inlined relative to the
including file, every time (no include guards, as glslang does it).

Pairing: gl_rmisc.c with `#ifdef`s resolved for a release build (no _DEBUG). In each
R_Create*Pipeline* function, in source order: R_InitDefaultStates(&x) sets x's stages to
basic_vert_module + basic_frag_module, R_CopyPipelineCreateInfos(&dst, &src) copies them,
`x.shader_stages[i].module = expr;` sets stage i (0 vertex, 1 fragment) to every `*_module`
named in expr (both arms of a ternary chosen by device settings such as the sample count;
VK_NULL_HANDLE = no stage: the sky stencil pipeline is vertex-only, stageCount 1), a
`VkShaderModule` parameter takes each value its callers pass, and each
R_CreateGraphicsPipeline(.., &x, ..) is one pipeline of x's stages; each
R_CreateComputePipeline(.., module_expr, ..) a compute program per module named. Programs are
deduplicated by stage texts. A program's FLAGS holds `-V --target-env vulkan1.1 -l` when one of
its stages is compiled for Vulkan 1.1 (the subgroup-op screen effects), else nothing is written
(corpus_verdicts.sh's default `-V -l`, Vulkan 1.0, like meson).
Usage: gather_vkquake.py MIRROR_GIT_DIR OUT_DIR
"""
import itertools
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program, strip_cpp_comments, cpp_ifdefs, c_string, call_args  # noqa: E402

EXT_STAGE = {"vert": "vertex", "frag": "fragment", "comp": "compute", "geom": "geometry"}
INC = re.compile(r'^[ \t]*#\s*include\s+"([^"]+)"[^\n]*', re.M)


def meson_list(src, name):
    """The bracketed list assigned to `name = [...]` in meson.build (comments dropped)."""
    src = re.sub(r"#[^\n]*", "", src)
    m = re.search(rf"^{name}\s*=\s*\[", src, re.M)
    depth, i = 1, m.end()
    while depth:
        depth += {"[": 1, "]": -1}.get(src[i], 0)
        i += 1
    return src[m.end():i - 1]


def shader_jobs(meson):
    """spv symbol (basic_oit_frag) -> (source path, [defines], target env or None)."""
    jobs = {}
    for path in re.findall(r"'([^']+)'", meson_list(meson, "shaders")):
        name = posixpath.basename(path)
        jobs[re.sub(r"\W", "_", name)] = (path, [], "vulkan1.1" if "sops" in name else None)
    for entry in re.findall(r"\[\s*('[^\[\]]*?)\s*\[([^\[\]]*)\]\s*\]", meson_list(meson, "shader_variants")):
        head, args = entry
        path, name = re.findall(r"'([^']+)'", head)[:2]
        args = re.findall(r"'([^']+)'", args)
        env = None
        if "--target-env" in args:
            env = args[args.index("--target-env") + 1]
        defs = [a[2:] for a in args if a.startswith("-D")]
        jobs[re.sub(r"\W", "_", name)] = (path, defs, env)
    return jobs


def inline(mirror, path):
    def sub(m):
        return inline(mirror, posixpath.normpath(posixpath.join(posixpath.dirname(path), m.group(1))))
    return INC.sub(sub, mirror.text(path))


def stage_text(mirror, job):
    path, defs, _ = job
    text = inline(mirror, path)
    lines = "".join("#define " + (d.replace("=", " ", 1) if "=" in d else d) + "\n" for d in defs)
    v = re.search(r"^[ \t]*#version[^\n]*\n", text, re.M)
    return text[:v.end()] + lines + text[v.end():] if v else lines + text


def functions(src):
    """name -> (parameter text, body) for every top-level function definition."""
    out = {}
    for m in re.finditer(r"^(?:static\s+)?void\s+(\w+)\s*\(([^)]*)\)\s*\{", src, re.M):
        depth, i = 1, m.end()
        while depth and i < len(src):
            depth += {"{": 1, "}": -1}.get(src[i], 0)
            i += 1
        out[m.group(1)] = (m.group(2), src[m.end():i - 1])
    return out


def modules(expr, params):
    """Alternatives of a module expression: spv symbols, None for VK_NULL_HANDLE."""
    alts = []
    for tok in re.findall(r"\w+", expr):
        if tok in params:
            alts.extend(params[tok])
        elif tok.endswith("_module"):
            alts.append(tok[:-len("_module")])
        elif tok == "VK_NULL_HANDLE":
            alts.append(None)
    return list(dict.fromkeys(alts))


EVENT = re.compile(r"R_InitDefaultStates\s*\(\s*&(?P<init>\w+)\s*\)"
                   r"|R_CopyPipelineCreateInfos\s*\(\s*&(?P<dst>\w+)\s*,\s*&(?P<src>\w+)\s*\)"
                   r"|(?P<var>\w+)\.shader_stages\[(?P<idx>\d)\]\.module\s*=\s*(?P<expr>[^;]*);"
                   r"|(?P<gfx>R_CreateGraphicsPipeline)\s*(?=\()"
                   r"|(?P<cmp>R_CreateComputePipeline)\s*(?=\()")


def trace(body, params):
    """[(kind, name, [[vertex alts], [fragment alts]] or [compute alts])] in source order."""
    state, out = {}, []
    for m in EVENT.finditer(body):
        if m.group("init"):
            state[m.group("init")] = [["basic_vert"], ["basic_frag"]]
        elif m.group("dst"):
            state[m.group("dst")] = [list(s) for s in state.get(m.group("src"), [["basic_vert"], ["basic_frag"]])]
        elif m.group("var"):
            state.setdefault(m.group("var"), [["basic_vert"], ["basic_frag"]])[int(m.group("idx"))] = modules(m.group("expr"), params)
        elif m.group("gfx"):
            args = call_args(body, m.end())
            var = args[1].lstrip("&").strip()
            out.append(("graphics", c_string(args[-1]) or args[-1], state[var]))
        elif m.group("cmp"):
            args = call_args(body, m.end())
            out.append(("compute", c_string(args[-1]) or args[-1], [modules(args[1], params)]))
    return out


def main():
    mirror, out = Mirror(sys.argv[1]), sys.argv[2]
    jobs = shader_jobs(mirror.text("meson.build"))
    src = cpp_ifdefs(strip_cpp_comments(mirror.text("Quake/gl_rmisc.c")), defined=())
    funcs = functions(src)
    created = set(re.findall(r"CREATE_SHADER_MODULE(?:_COND)?\s*\(\s*(\w+)", funcs["R_CreateShaderModules"][1]))
    pipelines = []
    for name in re.findall(r"^\s*(R_Create\w+)\s*\(\s*\)\s*;", funcs["R_CreatePipelines"][1], re.M):
        if name not in funcs:
            continue
        params, body = funcs[name]
        pipelines += trace(body, {})
        # helpers taking a VkShaderModule parameter, traced once per caller's value
        for callee in re.findall(r"\b(R_Create\w+)\s*\(", body):
            if callee == name or callee not in funcs or callee in ("R_CreateGraphicsPipeline", "R_CreateComputePipeline"):
                continue
            cparams, cbody = funcs[callee]
            plist = [p.strip() for p in cparams.split(",")]
            mod_idx = [(k, p.split()[-1]) for k, p in enumerate(plist) if p.startswith("VkShaderModule")]
            if not mod_idx:
                continue
            for cm in re.finditer(rf"\b{callee}\s*(?=\()", body):
                args = call_args(body, cm.end())
                pipelines += trace(cbody, {pname: modules(args[k], {}) for k, pname in mod_idx})
    n, seen = 0, set()
    for kind, pname, stages in pipelines:
        for combo in itertools.product(*stages):
            combo = [c for c in combo if c is not None]
            if not combo or any(c not in jobs or c not in created for c in combo):
                continue
            texts = []
            for sym in combo:
                path = jobs[sym][0]
                ext = path.rsplit(".", 1)[1]
                texts.append((EXT_STAGE[ext], sym.rsplit("_", 1)[0], stage_text(mirror, jobs[sym])))
            key = tuple(t for _, _, t in texts)
            if key in seen:
                continue
            seen.add(key)
            d = write_program(out, "vkquake", ".".join(stem for _, stem, _ in texts), texts)
            envs = {jobs[sym][2] for sym in combo} - {None}
            if envs:
                with open(os.path.join(d, "FLAGS"), "w") as fh:
                    fh.write(f"-V --target-env {max(envs)} -l\n")
            n += 1
    print(n, "programs")


main()
