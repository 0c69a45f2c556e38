#!/usr/bin/env python3
"""Pairs g-truc/ogl-samples programs the way the samples load them.

Only samples that samples/CMakeLists.txt builds (glCreateSampleGTC) and only desktop GL ones.
In each samples/<name>.cpp the statements are followed in order (for-loops over `i` unrolled):
`X = Compiler.create(GL_<STAGE>_SHADER, getDataDirectory() + CONST, "args")` makes a shader,
glAttachShader/glLinkProgram make a program, `glCreateShaderProgramv` of `loadFile(...)` makes a
one-stage program from the raw file, and glUseProgramStages puts one-stage programs together
into a pipeline. Shader text is what framework/compiler.cpp's parser sends: with `--version N
--profile P` it starts with `#version N P` and drops the file's #version lines (else the file's
#version line is moved first), `--define X` adds `#define X`, and each `#include "f"` line is
replaced by f (from the shader's directory) verbatim. Programs with compute stages are left
out. Usage: gather_oglsamples.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, graphics_stages, strip_cpp_comments, write_program

STAGES = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry",
          "TESS_CONTROL": "tess-control", "TESS_EVALUATION": "tess-eval", "COMPUTE": "compute"}


def preprocess(m, path, args):
    """framework/compiler.cpp: compiler::commandline + compiler::parser."""
    toks = args.split()
    version, profile, defines, includes = -1, "core", [], [os.path.dirname(path) + "/"]
    it = iter(toks)
    for t in it:
        if "-D" in t:
            defines.append(t[2:])
        elif "-I" in t:
            includes.append("data/" + t[2:])
        elif t == "--define":
            defines.append(next(it, ""))
        elif t in ("--version", "-v"):
            version = int(next(it))
        elif t in ("--profile", "-p"):
            profile = next(it, profile)
        elif t == "--include":
            includes.append("data/" + next(it, ""))
    text = f"#version {version} {profile}\n" if version != -1 else ""
    text += "".join(f"#define {d}\n" for d in defines)
    lines = m.show(path).decode("latin-1").split("\n")
    if lines and lines[-1] == "":
        lines.pop()  # std::getline yields no empty line after the final newline
    for line in lines:
        for directive in ("#version", "#include"):
            off = line.find(directive)
            if off != -1:
                break
        if off == -1:
            text += line + "\n"
            continue
        com = line.find("//")
        if com != -1 and com < off:
            continue  # the parser drops such lines
        if directive == "#version":
            if version == -1:
                text = line + "\n" + text
            continue
        q1 = line.find('"', off)
        name = line[q1 + 1:line.find('"', q1 + 1)]
        for inc in includes:
            body = m.show(os.path.normpath(inc + name))
            if body:
                text += body.decode("latin-1")
                break
    return text.encode("latin-1")


def enums(src):
    vals = {}
    for ns, body in re.findall(r"namespace\s+(\w+)\s*\{\s*enum\s*\w*\s*\{([^}]*)\}", src):
        for k, name in enumerate(n.split("=")[0].strip() for n in body.split(",") if n.strip()):
            vals[f"{ns}::{name}"] = k
    for body in re.findall(r"\benum\s*\w*\s*\{([^}]*)\}", src):
        for k, name in enumerate(n.split("=")[0].strip() for n in body.split(",") if n.strip()):
            vals.setdefault(name, k)
    return vals


def index_value(expr, vals):
    expr = expr.strip()
    if re.fullmatch(r"\d+", expr):
        return int(expr)
    if expr in vals:
        return vals[expr]
    m = re.fullmatch(r"([\w:]+)\s*\+\s*(\d+)", expr)
    return vals[m.group(1)] + int(m.group(2)) if m and m.group(1) in vals else None


def unroll(src, vals):
    """Replaces `for(... i = 0; i < N; ++i) BODY` by N copies of BODY with i literal."""
    pat = re.compile(r"for\s*\(\s*[\w:]*\s*i\s*=\s*0\s*;\s*\(?\s*i\s*<\s*([\w:]+)\s*\)?(?:\s*&&\s*\w+)?\s*;"
                     r"\s*(?:\+\+i|i\+\+)\s*\)\s*")
    while True:
        m = pat.search(src)
        if not m:
            return src
        start = end = m.end()
        if src[start] == "{":
            depth = 0
            for end in range(start, len(src)):
                depth += {"{": 1, "}": -1}.get(src[end], 0)
                if depth == 0:
                    break
            body, end = src[start + 1:end], end + 1
        else:
            end = src.index(";", start) + 1
            body = src[start:end]
        n = index_value(m.group(1), vals)
        copies = "".join(re.sub(r"\bi\b", str(k), body) for k in range(n or 0))
        src = src[:m.start()] + copies + src[end:]


def norm(vals, expr):
    """A variable's name with `this->` dropped and constant [indices] evaluated."""
    def idx(m):
        k = index_value(m.group(1), vals)
        return f"[{m.group(1) if k is None else k}]"
    return re.sub(r"\[([^\]]*)\]", idx, re.sub(r"this->", "", expr)).replace(" ", "")


def sample_programs(src):
    src = strip_cpp_comments(src)
    vals = enums(src)
    consts = dict(re.findall(r'(\w+)\s*(?:\(|=)\s*"([^"]+)"\s*\)?\s*;', src))
    arrays = {n: re.findall(r'"([^"]+)"', body)
              for n, body in re.findall(r"(\w+)\s*\[[^\]]*\]\s*=\s*\{([^}]*)\}", src)}
    src = unroll(src, vals)

    def const(expr):
        a = re.fullmatch(r"(\w+)\s*\[(.+)\]", expr.strip())
        if a:
            k = index_value(a.group(2), vals)
            return arrays.get(a.group(1), [None] * 99)[k] if k is not None else None
        return consts.get(expr.strip())

    shaders, attached, linked, pipelines = {}, {}, {}, {}
    stmt = re.compile(
        r"(?P<dst>[\w:>-]+(?:\[[^\]]*\])?)\s*=\s*Compiler\.create\(\s*GL_(?P<st>\w+?)_SHADER\s*,\s*getDataDirectory\(\)\s*\+\s*"
        r"(?P<file>[\w\[\]:+ ]+?)\s*(?:,\s*\"(?P<args>[^\"]*)\"\s*)?\)"
        r"|(?P<pdst>[\w:>-]+(?:\[[^\]]*\])?)\s*=\s*glCreateProgram\(\)"
        r"|glAttachShader\(\s*(?P<aprog>[^,]+?)\s*,\s*(?P<ash>[^)]+?)\s*\)"
        r"|glLinkProgram\(\s*(?P<lprog>[^)]+?)\s*\)"
        r"|loadFile\(\s*getDataDirectory\(\)\s*\+\s*(?P<rawfile>[\w\[\]:+ ]+?)\s*\)"
        r"|(?P<sdst>[\w:>-]+(?:\[[^\]]*\])?)\s*=\s*glCreateShaderProgramv\(\s*GL_(?P<sst>\w+?)_SHADER"
        r"|glUseProgramStages\(\s*(?P<pipe>[^,]+?)\s*,[^,]+,\s*(?P<uprog>[^)]+?)\s*\)")
    raw = None
    for s in stmt.finditer(src):
        g = s.groupdict()
        if g["dst"]:
            path = const(g["file"])
            shaders[norm(vals, g["dst"])] = (STAGES.get(g["st"]), path, g["args"] or "")
        elif g["pdst"]:
            attached[norm(vals, g["pdst"])] = []
        elif g["aprog"]:
            attached.setdefault(norm(vals, g["aprog"]), []).append(shaders.get(norm(vals, g["ash"])))
        elif g["lprog"]:
            linked[norm(vals, g["lprog"])] = list(attached.get(norm(vals, g["lprog"]), []))
        elif g["rawfile"]:
            raw = const(g["rawfile"])
        elif g["sdst"]:
            linked[norm(vals, g["sdst"])] = [(STAGES.get(g["sst"]), raw, None)]
        elif g["pipe"]:
            pipelines.setdefault(norm(vals, g["pipe"]), []).append(norm(vals, g["uprog"]))
    progs = dict(linked)
    for pipe, members in pipelines.items():
        if len(members) > 1 and all(p in linked for p in members):
            for p in members:
                progs.pop(p, None)
            progs["pipeline:" + pipe] = [sh for p in members for sh in linked[p]]
    return progs


def built_samples(m):
    """(profile-version-name) of each glCreateSampleGTC in samples/CMakeLists.txt."""
    names, profile, version = [], None, None
    for line in m.text("samples/CMakeLists.txt").splitlines():
        line = line.split("#")[0]
        a = re.match(r"\s*set\(GL_PROFILE_GTC\s+(\w+)\)", line)
        b = re.match(r"\s*set\(GL_VERSION_GTC\s+(\w+)\)", line)
        c = re.match(r"\s*glCreateSampleGTC\(([\w-]+)\)", line)
        profile = a.group(1) if a else profile
        version = b.group(1) if b else version
        if c:
            names.append(f"{profile}-{version}-{c.group(1)}")
    return names


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written, skipped = 0, []
    for sample in built_samples(m):
        if not sample.startswith("gl-") or not m.exists(f"samples/{sample}.cpp"):
            continue
        progs = []
        for key, shaders in sample_programs(m.text(f"samples/{sample}.cpp")).items():
            if not shaders or any(sh is None or sh[0] is None or sh[1] is None for sh in shaders):
                skipped.append(f"{sample}:{key}")
                continue
            kinds = {sh[0] for sh in shaders}
            if not graphics_stages(kinds):
                continue
            stages = [(stage, os.path.basename(path).rsplit(".", 1)[0],
                       m.show("data/" + path) if args is None else preprocess(m, "data/" + path, args))
                      for stage, path, args in shaders]
            if stages not in progs:  # the same text through another loader path is the same program
                progs.append(stages)
        for stages in progs:
            name = sample if len(progs) == 1 else sample + "." + "+".join(sorted({s[1] for s in stages}))
            write_program(out, "oglsamples", name, stages)
            written += 1
    print(written, "programs; not resolved (tessellation/mesh arrays):", ", ".join(skipped))


if __name__ == "__main__":
    main()
