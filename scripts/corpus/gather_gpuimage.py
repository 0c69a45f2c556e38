#!/usr/bin/env python3
"""BradLarson/GPUImage (Objective-C image/video filter framework, iOS side: OpenGL ES 2.0, GLSL
ES 1.00): every program the framework's filters and outputs link, paired as the code pairs them.

Shader text: `NSString *const kName = SHADER_STRING( ... );` in framework/Source/*.m and
framework/Source/iOS/*.m, with `#if TARGET_IPHONE_SIMULATOR || TARGET_OS_IPHONE` taken (the Mac
`#else` branches, without precision qualifiers, are left out). GPUImageFilter.h defines
SHADER_STRING(text) as `@ STRINGIZE2(text)`, so the string is the C preprocessor's
stringization of the tokens: comments gone, every run of white space between tokens one space,
none at the ends (the whole shader on one line); STRINGIZE2 expands the argument first, so the
file's own `#define`s apply (GPUImageLevelsFilter.m's LevelsControl(...) chain, and the
`#define` lines inside the argument, which clang runs as directives: GPUImageMedianFilter.m's
s2/mnmx3..6 swap macros; spacing
around an expansion approximated by one space each side).

Pairing: a small interpreter of the init methods. Every `[super|self|[X alloc] initWith...Shader...:]`
message and every `programForVertexShaderString:fragmentShaderString:` message whose arguments
are constants, `nil`, or local variables assigned constants (the n-th assignment of each such
variable taken together: the `switch (radius)` cases of Dilation/Erosion; `x = nil;` initial
values dropped; `[NSString stringWithFormat:@"..%@.." , kConst]` with only `%@` evaluated, as
for the Hough transform's GL_EXT_shader_framebuffer_fetch variant) is an entry; the
method it reaches (looked up from the superclass for `super`, from the object's class for
`self`, from X for `[X alloc]`; superclasses from the @interface lines) is followed with its
parameters bound (`a ? a : kDefault` picks the default when a is nil) down to the
programForVertexShaderString: calls of GPUImageFilter (first program) and GPUImageTwoPassFilter
(second program), which link. Programs whose strings are built at run time (stringWithFormat /
appendFormat: the optimized Gaussian blurs, box blurs, the Harris corner non-maximum suppression
variants...) are left out and counted. Identical (vertex, fragment) pairs are written once under
the first name (classes in file-name order, super/self messages before the `[X alloc]` ones of
filter groups, so a program is named after the class that owns it).

GLProgram hands the text to glShaderSource unchanged; with no #version it is GLSL ES 1.00 on iOS.
The stage files get `#version 100` as their first line (the only change) so that desktop tools
(glslangValidator -d, Mesa's compatibility context) read them as ES 1.00 too.
Usage: gather_gpuimage.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, cpp_ifdefs, split_commas, strip_cpp_comments, write_program  # noqa: E402

DIRS = ("framework/Source/", "framework/Source/iOS/")
EMIT = re.compile(r"programForVertexShaderString:\s*(.+?)\s+fragmentShaderString:\s*(.+?)\s*\]", re.S)
UNRESOLVED = object()


def balanced(text, i, open_ch, close_ch):
    """Index just past the bracket closing the one at text[i]."""
    depth = 0
    for j in range(i, len(text)):
        if text[j] == open_ch:
            depth += 1
        elif text[j] == close_ch:
            depth -= 1
            if depth == 0:
                return j + 1
    raise ValueError("unbalanced")


def c_macros(src):
    """name -> (params or None, body) of the `#define` lines of comment-free source."""
    out = {}
    for m in re.finditer(r"^[ \t]*#[ \t]*define[ \t]+(\w+)(\([^)]*\))?[ \t]*(.*)$", src, re.M):
        params = None if m.group(2) is None else [p.strip() for p in m.group(2)[1:-1].split(",") if p.strip()]
        out[m.group(1)] = (params, m.group(3).strip())
    return out




def expand(text, macros, active=frozenset()):
    """The C preprocessor's expansion of `text` for object- and function-like macros without
    `#`/`##` in their bodies (arguments expanded first, the result rescanned)."""
    out, i = [], 0
    for m in re.finditer(r"\b[A-Za-z_]\w*\b", text):
        name = m.group(0)
        if m.start() < i or name not in macros or name in active:
            continue
        params, body = macros[name]
        if "#" in body:
            continue
        if params is None:
            out.append(text[i:m.start()])
            out.append(" " + expand(body, macros, active | {name}) + " ")
            i = m.end()
            continue
        call = re.compile(r"\s*\(").match(text, m.end())
        if not call:
            continue
        end = balanced(text, call.end() - 1, "(", ")")
        args = [expand(a.strip(), macros, active) for a in split_commas(text[call.end():end - 1])]
        env = dict(zip(params, args))
        sub = re.sub(r"\b\w+\b", lambda w: env.get(w.group(0), w.group(0)), body)
        out.append(text[i:m.start()])
        out.append(" " + expand(sub, macros, active | {name}) + " ")
        i = end
    out.append(text[i:])
    return "".join(out)


def stringize(tokens):
    """`#x` of the C preprocessor for comment-free tokens: one space for each run of white
    space, none at the ends (a macro's expansion counted as set off by white space)."""
    return re.sub(r"\s+", " ", tokens).strip()


class Source:
    def __init__(self, mirror):
        self.consts, self.supers, self.methods = {}, {}, {}  # methods[(cls, selector)] = (params, body)
        self.order = []
        files = sorted(p for p in mirror.files if any(p.startswith(d) and "/" not in p[len(d):] for d in DIRS))
        for path in files:
            text = mirror.text(path)
            if path.endswith(".h"):
                for m in re.finditer(r"@interface\s+(\w+)\s*:\s*(\w+)", strip_cpp_comments(text)):
                    self.supers[m.group(1)] = m.group(2)
            elif path.endswith(".m"):
                self.read_m(cpp_ifdefs(strip_cpp_comments(text), {"TARGET_OS_IPHONE", "TARGET_IPHONE_SIMULATOR"}))

    def read_m(self, src):
        macros = c_macros(src)  # STRINGIZE2's argument is macro-expanded (GPUImageLevelsFilter.m)
        for m in re.finditer(r"NSString\s*\*\s*const\s+(\w+)\s*=\s*SHADER_STRING\s*\(", src):
            end = balanced(src, m.end() - 1, "(", ")")
            arg = src[m.end():end - 1]
            # clang runs directives met while collecting macro arguments (-Wembedded-directive):
            # GPUImageMedianFilter.m's `#define s2(a, b) ...` lines are C macros, gone from the
            # text and expanded in it.
            inner = dict(macros, **c_macros(arg))
            arg = re.sub(r"^[ \t]*#[ \t]*define\b.*$", "", arg, flags=re.M)
            self.consts[m.group(1)] = stringize(expand(arg, inner))
        for impl in re.finditer(r"@implementation\s+(\w+)(.*?)@end", src, re.S):
            cls, body = impl.group(1), impl.group(2)
            self.order.append(cls)
            for mm in re.finditer(r"^[-+]\s*\([^)]*\)\s*([^{;]*?)\s*;?\s*\{", body, re.M):
                sig = mm.group(1)
                parts = re.findall(r"(\w+)\s*:\s*\([^)]*\)\s*(\w+)", sig)
                selector = "".join(p + ":" for p, _ in parts) if parts else sig.strip()
                end = balanced(body, mm.end() - 1, "{", "}")
                self.methods[(cls, selector)] = ([v for _, v in parts], body[mm.end():end - 1])

    def lookup(self, cls, selector):
        while cls:
            if (cls, selector) in self.methods:
                return cls, self.methods[(cls, selector)]
            cls = self.supers.get(cls)
        return None, None


def messages(body):
    """(position, receiver, selector, [arg texts]) of the shader-ish messages of a method body."""
    out = []
    for m in re.finditer(r"\[\s*(super|self|\[\s*(\w+)\s+alloc\s*\])\s+(?=\w+:)", body):
        end = balanced(body, m.start(), "[", "]")
        inner = body[m.end():end - 1]
        kws = list(re.finditer(r"(?<![\w?:])(\w+):(?!:)", inner))
        selector = "".join(k.group(1) + ":" for k in kws)
        if "Shader" not in selector:
            continue
        args = [inner[k.end():(kws[i + 1].start() if i + 1 < len(kws) else len(inner))].strip()
                for i, k in enumerate(kws)]
        out.append((m.start(), m.group(2) or m.group(1), selector, args))
    for m in EMIT.finditer(body):
        out.append((m.start(), None, "EMIT", [m.group(1), m.group(2)]))
    return sorted(out, key=lambda t: t[0])


class Interp:
    def __init__(self, src):
        self.src, self.programs, self.unresolved = src, [], []

    def value(self, expr, env, local):
        expr = expr.strip()
        t = re.match(r"(.+?)\s*\?\s*(.+?)\s*:\s*(.+)$", expr, re.S)
        if t:
            c = self.value(t.group(1), env, local)
            return self.value(t.group(2) if c is not None else t.group(3), env, local)
        if expr == "nil":
            return None
        f = re.match(r'\[NSString\s+stringWithFormat:\s*@("(?:\\.|[^"\\])*")\s*((?:,\s*\w+\s*)*)\]$', expr)
        if f and not re.search(r"%(?!@)", c_string(f.group(1))):
            vals = [self.value(a, env, local) for a in re.findall(r"\w+", f.group(2))]
            parts = c_string(f.group(1)).split("%@")
            if UNRESOLVED in vals or None in vals or len(vals) != len(parts) - 1:
                return UNRESOLVED
            return "".join(p + v for p, v in zip(parts, vals + [""]))
        if expr in env:
            return env[expr]
        if expr in local:
            return local[expr]
        return self.src.consts.get(expr, UNRESOLVED)

    def alternatives(self, body, pos, args, env):
        """Bindings of the local variables the args name: the n-th constant assignment of each."""
        names = {w for a in args for w in re.findall(r"\b\w+\b", a)
                 if w not in env and w not in self.src.consts and w != "nil"}
        cands = {}
        for n in names:
            vals = [self.value(r, env, {}) for r in re.findall(rf"(?<![\w.]){n}\s*=\s*([^;=][^;]*);", body[:pos])]
            vals = [v for v in vals if v is not None] or vals  # `x = nil;` before the branches
            if vals:
                cands[n] = vals
        k = max((len(v) for v in cands.values()), default=1)
        return [{n: v[min(i, len(v) - 1)] for n, v in cands.items()} for i in range(k)]

    def run(self, dyn, impl, params, body, env, name, depth=0):
        if depth > 12:
            return
        for pos, recv, selector, args in messages(body):
            for local in self.alternatives(body, pos, args, env):
                vals = [self.value(a, env, local) for a in args]
                self.call(dyn, impl, recv, selector, args, vals, name, depth)

    def call(self, dyn, impl, recv, selector, args, vals, name, depth):
        if UNRESOLVED in vals:
            self.unresolved.append((name, selector, args))
            return
        if selector == "EMIT":
            self.programs.append((name, vals[0], vals[1]))
            return
        if recv == "super":
            start, new_dyn = self.src.supers.get(impl), dyn
        elif recv == "self":
            start, new_dyn = dyn, dyn
        else:
            start, new_dyn = recv, recv
        found, method = self.src.lookup(start, selector)
        if not method:
            return
        params, body = method
        self.run(new_dyn, found, params, body, dict(zip(params, vals)), name, depth + 1)

    def entries(self):
        """super/self messages of every class first, then `[[X alloc] init...]` ones (a filter
        group's members), so that a program is named after the class that owns it."""
        for pass_alloc in (False, True):
            self.entries_pass(pass_alloc)

    def entries_pass(self, pass_alloc):
        for cls in self.src.order:
            for (c, selector), (params, body) in self.src.methods.items():
                if c != cls:
                    continue
                for pos, recv, sel, args in messages(body):
                    if (recv not in ("super", "self", None)) != pass_alloc:
                        continue
                    if any(re.search(rf"\b{p}\b", a) for p in params for a in args):
                        continue  # reached through the method's callers
                    alts = self.alternatives(body, pos, args, {})
                    for i, local in enumerate(alts):
                        vals = [self.value(a, {}, local) for a in args]
                        self.call(cls, cls, recv, sel, args, vals, cls + (f".v{i + 1}" if len(alts) > 1 else ""), 0)


def es100(text):
    return text if re.match(r"\s*#\s*version", text) else "#version 100\n" + text


def main():
    src = Source(Mirror(sys.argv[1]))
    out = sys.argv[2]
    it = Interp(src)
    it.entries()
    seen, names, n = set(), {}, 0
    for name, vs, fs in it.programs:
        if vs is None or fs is None or (vs, fs) in seen:
            continue
        seen.add((vs, fs))
        names[name] = names.get(name, 0) + 1
        prog = name if names[name] == 1 else f"{name}.{names[name]}"
        prog = re.sub(r"^GPUImage(?=\w)", "", prog)
        write_program(out, "gpuimage", prog, [("vertex", "shader", es100(vs)), ("fragment", "shader", es100(fs))])
        n += 1
    skipped = sorted({f"{nm}:{sel}" for nm, sel, _ in it.unresolved})
    print(n, "programs;", len(skipped), "calls with run-time built strings left out:", " ".join(skipped))


main()
