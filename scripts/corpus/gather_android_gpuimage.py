#!/usr/bin/env python3
"""cats-oss/android-gpuimage (GPUImage for Android, Java, OpenGL ES 2.0, GLSL ES 1.00): every
program the library's filters link, paired as their constructors pair them.

Shader text: the `static final String NAME = "..." + "..." ...;` constants of
library/src/main/java/**/*.java (Java literals decoded, `+` concatenation of literals and other
constants; a simple name is looked up in the class, then its superclasses, `Class.NAME`
directly). Pairing: a small interpreter of the constructors. Every `super(...)`, `this(...)` and
`new GPUImageX(...)` call whose String arguments are constants or `null` is an entry (calls
naming the enclosing constructor's parameters are reached through their callers instead); the
constructor it reaches (overloads told apart by arity, then by which positions hold strings) is
followed with its parameters bound, down to GPUImageFilter(String vertexShader, String
fragmentShader), whose onInit() hands both strings to OpenGlUtils.loadProgram unchanged
(GPUImageFilter() is NO_FILTER_VERTEX_SHADER + NO_FILTER_FRAGMENT_SHADER;
GPUImageTwoPassFilter adds `new GPUImageFilter(first...)` and `new GPUImageFilter(second...)`).
A call of a private static method returning constants (Dilation's
`getVertexShader(radius)`/`getFragmentShader(radius)` switches) gives one variant per `return`,
the n-th returns of the methods of one call taken together. Identical (vertex, fragment) pairs
are written once under the first name (files in name order, every class's super/this calls before
the `new X(...)` calls of filter groups, so a program is named after the class that owns it).

The strings have no #version: GLSL ES 1.00 on Android's GLES20 context. The stage files get
`#version 100` as their first line (the only change) so that desktop tools (glslangValidator -d,
Mesa's compatibility context) read them as ES 1.00 too.
Usage: gather_android_gpuimage.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

ROOT = "library/src/main/java/"
JAVA_TOKEN = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|//[^\n]*|/\*.*?\*/', re.S)
UNRESOLVED, OTHER = object(), object()


def strip_java_comments(src):
    return JAVA_TOKEN.sub(lambda m: " " if m.group(0)[0] == "/" else m.group(0), src)


def java_string(lit):
    def esc(m):
        e = m.group(1)
        if e[0] == "u":
            return chr(int(e.lstrip("u"), 16))
        if e[0] in "01234567":
            return chr(int(e, 8))
        return {"n": "\n", "t": "\t", "r": "\r", "b": "\b", "f": "\f", "s": " "}.get(e, e)
    return re.sub(r"\\(u+[0-9a-fA-F]{4}|[0-7]{1,3}|.)", esc, lit[1:-1])


def balanced(text, i, open_ch="(", close_ch=")"):
    """Index just past the bracket closing the one at text[i] (string literals skipped)."""
    depth = 0
    for tok in re.compile(r'"(?:\\.|[^"\\])*"|.', re.S).finditer(text, i):
        t = tok.group(0)
        if t == open_ch:
            depth += 1
        elif t == close_ch:
            depth -= 1
            if depth == 0:
                return tok.end()
    raise ValueError("unbalanced")


def split_args(text):
    args, depth, cur = [], 0, ""
    for tok in re.finditer(r'"(?:\\.|[^"\\])*"|.', text, re.S):
        t = tok.group(0)
        if t in "([{":
            depth += 1
        elif t in ")]}":
            depth -= 1
        if t == "," and depth == 0:
            args.append(cur.strip())
            cur = ""
        else:
            cur += t
    return [a for a in args + [cur.strip()] if a]


class Source:
    def __init__(self, mirror):
        self.supers, self.raw_consts, self.ctors, self.statics, self.order = {}, {}, {}, {}, []
        for path in sorted(p for p in mirror.files if p.startswith(ROOT) and p.endswith(".java")):
            src = strip_java_comments(mirror.text(path))
            c = re.search(r"\bclass\s+(\w+)(?:\s*<[^>]*>)?(?:\s+extends\s+(\w+))?", src)
            if not c:
                continue
            cls = c.group(1)
            self.order.append(cls)
            if c.group(2):
                self.supers[cls] = c.group(2)
            self.raw_consts[cls] = {m.group(1): m.group(2) for m in re.finditer(
                r"static\s+final\s+String\s+(\w+)\s*=\s*((?:\"(?:\\.|[^\"\\])*\"|[^;\"])*);", src)}
            self.ctors[cls] = []
            for m in re.finditer(rf"(?:public|protected|private)?\s*\b{cls}\s*\(([^)]*)\)\s*\{{", src):
                if re.search(r"\bnew\s*$", src[:m.start()]):
                    continue
                end = balanced(src, m.end() - 1, "{", "}")
                params = [p.split()[-2:] for p in split_args(m.group(1))]
                self.ctors[cls].append(([t for t, _ in params], [n for _, n in params], src[m.end():end - 1]))
            for m in re.finditer(r"static\s+String\s+(\w+)\s*\([^)]*\)\s*\{", src):
                end = balanced(src, m.end() - 1, "{", "}")
                self.statics[(cls, m.group(1))] = re.findall(r"return\s+([^;]+);", src[m.end():end - 1])

    def const(self, cls, name, depth=0):
        c = cls
        while c:
            if name in self.raw_consts.get(c, {}):
                return self.concat(c, self.raw_consts[c][name], depth)
            c = self.supers.get(c)
        return UNRESOLVED

    def concat(self, cls, expr, depth=0):
        if depth > 10:
            return UNRESOLVED
        out = []
        for part in re.finditer(r'"(?:\\.|[^"\\])*"|[\w.]+|\S', expr):
            t = part.group(0)
            if t[0] == '"':
                out.append(java_string(t))
            elif t == "+":
                continue
            elif re.match(r"[A-Za-z_][\w.]*$", t):
                owner, _, name = t.rpartition(".")
                v = self.const(owner or cls, name, depth + 1)
                if v is UNRESOLVED:
                    return UNRESOLVED
                out.append(v)
            else:
                return UNRESOLVED
        return "".join(out)


class Interp:
    def __init__(self, src):
        self.src, self.programs, self.unresolved = src, [], []

    def calls(self, cls, body, with_kind=False):
        out = []
        for m in re.finditer(r"\b(super|this|new\s+(GPUImage\w*))\s*\(", body):
            end = balanced(body, m.end() - 1)
            target = self.src.supers.get(cls) if m.group(1) == "super" else cls if m.group(1) == "this" else m.group(2)
            args = split_args(body[m.end():end - 1])
            out.append((bool(m.group(2)), target, args) if with_kind else (target, args))
        return out

    def value(self, cls, expr, env):
        if expr == "null":
            return None
        if expr in env:
            return env[expr]
        if re.match(r'"|[A-Z_][A-Z0-9_]*$|\w+\.[A-Z_][A-Z0-9_]*$', expr):
            return self.src.concat(cls, expr)
        return OTHER

    def variants(self, cls, args):
        """Per-variant argument texts: static String method calls replaced by their n-th return."""
        rets = {}
        for a in args:
            m = re.match(r"(\w+)\s*\(", a)
            if m and (cls, m.group(1)) in self.src.statics:
                rets[a] = self.src.statics[(cls, m.group(1))]
        k = max((len(r) for r in rets.values()), default=1)
        return [[rets[a][min(i, len(rets[a]) - 1)].strip() if a in rets else a for a in args] for i in range(k)]

    def call(self, cls, target, args, env, name, depth):
        if depth > 12 or target not in self.src.ctors:
            return
        variants = self.variants(cls, args)
        for i, vargs in enumerate(variants):
            vals = [self.value(cls, a, env) for a in vargs]
            vname = name + (f".r{i + 1}" if len(variants) > 1 else "")
            fits = [c for c in self.src.ctors[target] if len(c[0]) == len(vals)]
            if len(fits) > 1:
                fits = [c for c in fits if all((t == "String") == isinstance(v, str) or v is None
                                               for t, v in zip(c[0], vals))] or fits
            if not fits:
                continue
            types, params, body = fits[0]
            if any(v is UNRESOLVED or (v is OTHER and t == "String") for t, v in zip(types, vals)):
                self.unresolved.append((vname, target, vargs))
                continue
            if target == "GPUImageFilter" and types == ["String", "String"]:
                self.programs.append((vname, vals[0], vals[1]))
                continue
            new_env = dict(zip(params, vals))
            for t2, a2 in self.calls(target, body):
                self.call(target, t2, a2, new_env, vname, depth + 1)

    def entries(self):
        """super/this calls of every class first, then `new X(...)` ones (a filter group's
        members), so that a program is named after the filter class that owns it."""
        for pass_new in (False, True):
            for cls in self.src.order:
                for types, params, body in self.src.ctors[cls]:
                    for is_new, target, args in self.calls(cls, body, with_kind=True):
                        if is_new != pass_new or any(re.search(rf"\b{p}\b", a) for p in params for a in args):
                            continue
                        self.call(cls, target, args, {}, cls, 0)


def es100(text):
    return text if re.match(r"\s*#\s*version", text) else "#version 100\n" + text


def main():
    it = Interp(Source(Mirror(sys.argv[1])))
    out = sys.argv[2]
    it.entries()
    seen, names, n = set(), {}, 0
    for name, vs, fs in it.programs:
        if vs is None or fs is None or (vs, fs) in seen:
            continue
        seen.add((vs, fs))
        names[name] = names.get(name, 0) + 1
        prog = re.sub(r"^GPUImage(?=\w)", "", name if names[name] == 1 else f"{name}.{names[name]}")
        write_program(out, "android-gpuimage", prog,
                      [("vertex", "shader", es100(vs)), ("fragment", "shader", es100(fs))])
        n += 1
    skipped = sorted({f"{nm}->{t}({', '.join(a)})" for nm, t, a in it.unresolved})
    print(n, "programs;", len(skipped), "calls left out:", "; ".join(skipped))


main()
