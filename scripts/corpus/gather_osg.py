#!/usr/bin/env python3
"""openscenegraph/OpenSceneGraph: osg::Program objects built in examples/ and src/ C++ code.

Pairing, in source order per file:
- `P = new osg::Program` (re)starts program P; `P->addShader(S)` adds shader S to it; a program
  is complete when P is assigned a new osg::Program or at the end of the file.
- S is `new osg::Shader(osg::Shader::TYPE, TEXT)`, a variable assigned such an expression,
  a shader made with `new osg::Shader(osg::Shader::TYPE)` and given `S->setShaderSource(TEXT)`,
  or `osgDB::readRefShaderFileWithFallback(TYPE, "file", FALLBACK)` (the fallback text: the
  OpenSceneGraph-Data files are not in the repository, so osg uses the built-in text).
- TEXT is a string literal or a variable holding literals (`char x[] = "..."`, `const char* x =`,
  `std::string x(...)`); the latest definition before the use wins; `#include "shaders/x.cpp"`
  (osg's built-in shader sources) is expanded first; #if/#ifdef resolved with nothing defined
  but the file's own `#define`s
  (`#if 1` taken, `#if 0` not).
- Shaders read only from data files (osgDB::readShaderFile, readRefShaderFile,
  osg::Shader::readShaderFile) are not in the repository and are left out; a program that gets
  such a file for a stage it has no inline shader for is skipped (it would be a different program).
- Every addShader of P between two `new osg::Program` is kept, whichever if/else branch it is in
  (osg attaches them all when the branches are not exclusive; exclusive branches may merge).
osg compiles each shader's text as given (no define/#version injection without
`#pragma import_defines` defines or vertex-attribute aliasing, both off by default on GL2),
except that State::convertVertexShaderSourceToOsgBuiltIns (run on every stage) replaces `$VAR`
outside quotes by DisplaySettings' value, here the desktop GL2 build's SHADER_NONE hint
(OSG_GLSL_VERSION and OSG_PRECISION_FLOAT empty, OSG_VARYING_IN/OUT `varying`), an unknown
`$VAR` by nothing (State_Utils::substitudeEnvVars).
Identical programs are written once. Usage: gather_osg.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from legacy_common import Mirror, Writer, strip_cpp_comments, c_string, C_LITERAL  # noqa: E402
from mirror import cpp_ifdefs  # noqa: E402

TYPES = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry",
         "TESSCONTROL": "tess-control", "TESSEVALUATION": "tess-eval", "COMPUTE": "compute"}
STEM = {"vertex": "vs", "fragment": "fs", "geometry": "gs", "tess-control": "tcs", "tess-eval": "tes", "compute": "cs"}
_N = [0]


def L():
    """C_LITERAL with its raw-string group renamed, so it can appear several times in one regex."""
    _N[0] += 1
    return C_LITERAL.replace("rawdelim", f"rd{_N[0]}")


LITS = rf"(?:{L()}|\s)+"


def expand(m, path, src, depth=0):
    def rep(mm):
        inc = os.path.normpath(os.path.join(os.path.dirname(path), mm.group(1)))
        t = m.text(inc)
        return expand(m, inc, t, depth + 1) if t is not None and depth < 3 else mm.group(0)
    return re.sub(r'^[ \t]*#\s*include\s+"([^"]+\.cpp)"', rep, src, flags=re.M)


OSG_VALUES = {"OSG_GLSL_VERSION": "", "OSG_PRECISION_FLOAT": "",
              "OSG_VARYING_IN": "varying", "OSG_VARYING_OUT": "varying"}


def osg_env_vars(s):
    """State_Utils::substitudeEnvVars with the SHADER_NONE values (no environment variables)."""
    pos = 0
    while pos < len(s):
        found = [i for i in (s.find(c, pos) for c in "$'\"") if i >= 0]
        if not found:
            break
        pos = min(found)
        if s[pos] in "'\"":
            end = s.find(s[pos], pos + 1)
            if end < 0:
                break
            pos = end + 1
        else:
            end = re.match(r"\$[A-Za-z0-9_]*", s[pos:]).end() + pos
            s = s[:pos] + OSG_VALUES.get(s[pos + 1:end], "") + s[end:]
    return s


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    w = Writer(out, "osg")
    for f in sorted(m.files):
        if not f.startswith(("examples/", "src/")) or not f.endswith((".cpp", ".h")) or "/shaders/" in f.lower():
            continue
        if "osgAndroid" in f or "GLES" in f or "IPhone" in f or "emscripten" in f:
            continue
        raw = m.text(f)
        if "addShader" not in raw:
            continue
        src = strip_cpp_comments(expand(m, f, raw))
        src = cpp_ifdefs(src, set(re.findall(r"^[ \t]*#[ \t]*define[ \t]+(\w+)", src, re.M)))
        strings, shaders, progs, files_for = {}, {}, {}, {}
        done = []

        def text(expr):
            expr = expr.strip()
            if expr.startswith(("\"", "R\"")):
                return c_string(expr)
            expr = re.sub(r"\.(c_str|get)\(\)$", "", expr)
            return strings.get(expr)

        def finish(p):
            if p in progs and progs[p]:
                done.append((p, progs[p], files_for.get(p, set())))
            progs[p], files_for[p] = [], set()

        shader_new = r"new\s+(?:osg::)?Shader\s*\(\s*(?:osg::)?Shader::(\w+)\s*(?:,\s*((?:" + C_LITERAL + r"|[^()]|\([^()]*\))*?))?\s*\)"
        alts = [
            rf"(?P<sdef>\w+)\s*(?:\[\s*\w*\s*\])?\s*(?:=\s*\{{?|\(\s*)(?P<slit>{LITS})\s*[)}}]?\s*;",
            r"(?P<pnew>[\w.>-]+)\s*=\s*new\s+(?:osg::)?Program\b",
            rf"(?P<shv>[\w.>-]+)\s*=\s*{shader_new}",
            r"(?P<ssrc>[\w.>-]+)\s*(?:->|\.)\s*setShaderSource\s*\(\s*(?P<ssrcx>(?:" + L() + r"|[^()])*?)\s*\)\s*;",
            r"(?P<padd>[\w.>-]+)\s*(?:->|\.)\s*addShader\s*\(\s*(?P<parg>(?:" + L() + r"|[^()]|\((?:" + L() + r"|[^()]|\([^()]*\))*\))*?)\s*\)\s*;",
        ]
        for mm in re.finditer("|".join(alts), src):
            g = mm.groupdict()
            if g["sdef"]:
                strings[g["sdef"]] = c_string(g["slit"])
            elif g["pnew"]:
                finish(g["pnew"])
            elif g["shv"]:
                sm = re.search(shader_new, mm.group(0))
                shaders[g["shv"]] = [TYPES.get(sm.group(1)), text(sm.group(2)) if sm.group(2) else None]
            elif g["ssrc"]:
                if g["ssrc"] in shaders:
                    shaders[g["ssrc"]][1] = text(g["ssrcx"])
            elif g["padd"]:
                p, arg = g["padd"], g["parg"]
                progs.setdefault(p, [])
                sm = re.match(shader_new, arg)
                fb = re.search(r"readRefShaderFileWithFallback\s*\(\s*(?:osg::)?Shader::(\w+)\s*,\s*[^,]+,\s*(\w+)\s*\)", arg)
                if sm:
                    progs[p].append((TYPES.get(sm.group(1)), text(sm.group(2)) if sm.group(2) else None))
                elif fb:
                    progs[p].append((TYPES.get(fb.group(1)), strings.get(fb.group(2))))
                elif re.search(r"read\w*ShaderFile", arg):
                    t = re.search(r"Shader::(\w+)", arg)
                    files_for.setdefault(p, set()).add(TYPES.get(t.group(1)) if t else None)
                elif re.sub(r"\.get\(\)$", "", arg.strip()) in shaders:
                    progs[p].append(tuple(shaders[re.sub(r"\.get\(\)$", "", arg.strip())]))
                else:
                    progs[p].append((None, None))
        for p in list(progs):
            finish(p)
        base = os.path.splitext(f)[0].replace("examples/", "").replace("/", ".")
        for p, stages, from_files in done:
            if any(s is None or t is None for s, t in stages):
                continue
            if any(s is None or s not in {x for x, _ in stages} for s in from_files):
                continue
            order = ["vertex", "tess-control", "tess-eval", "geometry", "fragment", "compute"]
            files, count = [], {}
            for s, t in sorted(stages, key=lambda st: order.index(st[0])):
                count[s] = count.get(s, 0) + 1
                files.append((s, STEM[s] + ("" if count[s] == 1 else str(count[s])), osg_env_vars(t)))
            w.add(f"{base}.{re.sub(r'[^A-Za-z0-9_]+', '_', p)}", files)
    w.report()


main()
