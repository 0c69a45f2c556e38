"""Shared by the Cinder gatherers (cinder/Cinder, paulhoux/Cinder-Samples,
simongeilfus/Cinder-Experiments).

Programs: in each app's .cpp (desktop branch of #if CINDER_GL_ES..., // comments dropped),
every statement `GlslProg::create( A, B [, C] )` (vertex, fragment, geometry) and every
statement holding `.vertex( A )` and `.fragment( B )` (a GlslProg::Format chain, with its
`.geometry`, `.define( "X" [, v] )`, `.version( N )`; a define value that is a runtime
count `toString( x.size() )` becomes 4, other runtime values skip the program). A stage is `loadAsset( "p" )`,
`loadResource( "p" | RES_X )` or a variable assigned one of those. Programs with
tessellation stages, or stages given as runtime strings, are skipped.

Text per stage: cinder::gl::ShaderPreprocessor::parse (src/cinder/gl/ShaderPreprocessor.cpp):
a source without #version gets `#version 150` (or Format::version), then the defines, then
`#line`; defines go right after an existing #version line; `#include "x"` is expanded
(current dir, then assets root; each file once) between #line directives.
"""
import posixpath, re
from cstr import _cond
from mirror import write_program, safe_name

FALLBACK_DEFINE_VALUE = "4"  # value for .define( "N", s ) with s = toString( runtime count )


# include/cinder/gl/platform.h values; CINDER_GL_ES_VERSION stays undefined (0) on desktop
CINDER_MACROS = {"CINDER_GL_ES_VERSION_2": 200, "CINDER_GL_ES_VERSION_3": 300, "CINDER_GL_ES_VERSION_3_1": 310,
                 "CINDER_GL_ES_VERSION_3_2": 320}


def desktop_lines(text, defines=CINDER_MACROS):
    """C++ source with inactive #if branches and // comments blanked."""
    stack, out = [], []
    for line in text.splitlines():
        s = line.strip()
        m = re.match(r'#\s*(if|ifdef|ifndef|elif|else|endif)\b(.*)', s)
        if m:
            kw, arg = m.group(1), re.sub(r'//.*', '', m.group(2))
            if kw in ("if", "ifdef", "ifndef"):
                c = _cond(arg, defines) if kw == "if" else ((arg.strip() in defines) == (kw == "ifdef"))
                stack.append((c, c))
            elif kw == "elif" and stack:
                _, taken = stack.pop()
                c = not taken and _cond(arg, defines)
                stack.append((c, taken or c))
            elif kw == "else" and stack:
                _, taken = stack.pop()
                stack.append((not taken, True))
            elif kw == "endif" and stack:
                stack.pop()
            out.append("")
            continue
        out.append(re.sub(r'//.*', '', line) if all(a for a, _ in stack) else "")
    return "\n".join(out)


class Preprocessor:
    def __init__(self, m, assets):
        self.m, self.assets = m, assets

    def _find(self, inc, cur):
        for d in (cur, self.assets):
            p = posixpath.normpath(posixpath.join(d, inc))
            if self.m.exists(p):
                return p
        return None

    @staticmethod
    def _line(n, sid, version):
        return f"#line {n + 1 if version >= 330 else n} {sid}\n"

    def _read(self, text, path, start, version, tree):
        out, n = [], start
        lines = text.split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        for line in lines:
            inc = re.match(r'^[ \t]*#[ \t]*include[ \t]*["<]([^">]+)[">]', line)
            if inc:
                before = len(tree)
                out.append(self._recurse(inc.group(1), posixpath.dirname(path), version, tree))
                out.append(self._line(n, before, version))
            else:
                out.append(line + "\n")
            n += 1
        return "".join(out)

    def _recurse(self, inc, cur, version, tree):
        full = self._find(inc, cur)
        if full is None:
            raise KeyError(inc)
        if full in tree:
            return ""
        head = self._line(0, len(tree) + 1, version)
        tree.add(full)
        return head + self._read(self.m.text(full), full, 1, version, tree)

    def parse(self, path, version=150, defines=()):
        src = self.m.text(path)
        lines = src.split("\n")
        vline = None
        for i, line in enumerate(lines[:-1]):  # the loader only looks at newline-terminated lines
            if re.match(r'^[ \t]*#[ \t]*version[ \t]+\d', line):
                vline = i
                break
        tree = set()
        if vline is not None:
            version = int(re.search(r'\d+', lines[vline]).group(0))
            if not defines:
                return self._read(src, path, 1, version, tree)
            directives = "\n".join(lines[:vline + 1]) + "\n"
            body, start = "\n".join(lines[vline + 1:]), vline + 1
        else:
            directives, body, start = f"#version {version}\n", src, 0
        for k, v in defines:
            directives += f"#define {k}" + (f" {v}" if v else "") + "\n"
        directives += self._line(start, 0, version)
        return directives + self._read(body, path, start + 1, version, tree)


_STAGE_CALL = re.compile(r'\.(vertex|fragment|geometry|tessellation\w*|define|version)\s*\(')


def _args(s, i):
    """Split the call arguments starting after '(' at index i; returns (args, end)."""
    depth, cur, args = 1, "", []
    while i < len(s):
        c = s[i]
        if c == '"':
            j = s.find('"', i + 1)
            if j < 0:
                return args, len(s)
            cur += s[i:j + 1]
            i = j + 1
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                args.append(cur.strip())
                return args, i
        if c == "," and depth == 1:
            args.append(cur.strip())
            cur = ""
        else:
            cur += c
        i += 1
    return args, i


def programs_in_cpp(m, cpp_path):
    """Yields dicts {vertex, fragment, geometry?, defines, version} of source expressions."""
    src = desktop_lines(m.text(cpp_path))
    src = re.sub(r'/\*.*?\*/', '', src, flags=re.S)
    variables = dict(re.findall(r'\b(\w+)\s*=\s*((?:load(?:Asset|Resource|File))\s*\([^;]*?\))\s*;', src))
    values = dict(re.findall(r'\b(\w+)\s*=\s*(\d+|"[^"]*")\s*;', src))
    values.update((k, FALLBACK_DEFINE_VALUE) for k in re.findall(r'\b(\w+)\s*=\s*toString\(', src))
    for stmt in src.split(";"):
        create = re.search(r'GlslProg::create\s*\(', stmt)
        if create:
            args, _ = _args(stmt, create.end())
            if 2 <= len(args) <= 3 and "Format" not in args[0]:
                p = {"vertex": args[0], "fragment": args[1], "defines": [], "version": 150}
                if len(args) == 3:
                    p["geometry"] = args[2]
                yield p, variables
                continue
        calls = list(_STAGE_CALL.finditer(stmt))
        kinds = {c.group(1) for c in calls}
        if not {"vertex", "fragment"} <= kinds or any(k.startswith("tess") for k in kinds):
            continue
        p = {"defines": [], "version": 150}
        for c in calls:
            args, _ = _args(stmt, c.end())
            k = c.group(1)
            if k == "define":
                name = args[0].strip('"')
                val = args[1] if len(args) > 1 else ""
                val = values.get(val, val)
                if val and not val.startswith('"') and not re.fullmatch(r'\d+', val):
                    p["unresolved"] = True
                p["defines"].append((name, val.strip('"')))
            elif k == "version":
                v = values.get(args[0], args[0])
                p["version"] = int(v) if v.isdigit() else 150
            else:
                p[k] = args[0]
        if not p.pop("unresolved", False):
            yield p, variables


def resolve_source(m, expr, variables, cpp_path):
    """Repository path of a stage source expression, or None."""
    expr = variables.get(expr.strip(), expr.strip())
    call = re.match(r'(loadAsset|loadResource|loadFile)\s*\(\s*(.*)\)\s*$', expr, re.S)
    if not call:
        return None
    kind, arg = call.group(1), call.group(2).strip()
    d = posixpath.dirname(cpp_path)
    lit = re.fullmatch(r'"([^"]+)"', arg)
    if kind == "loadResource" and not lit:
        # RES_X: #define RES_X CINDER_RESOURCE( prefix, name, id, type ) in the app's headers
        name = None
        root = cpp_path.split("/src/")[0]
        for f in m.files:
            if f.startswith(root + "/include/") and f.endswith(".h"):
                r = re.search(r'#define\s+' + re.escape(arg) + r'\s+CINDER_RESOURCE\s*\(\s*[^,]*,\s*([^,\s]+)\s*,', m.text(f))
                if r:
                    name = r.group(1)
        if not name:
            return None
        want = "resources/" + name
    elif lit:
        want = (("resources/" if kind == "loadResource" else "assets/") + lit.group(1)) if kind != "loadFile" else None
        if want is None:
            return None
    else:
        return None
    while True:  # Cinder looks for assets/ (and resources/) in the app's folder and its parents
        p = posixpath.normpath(posixpath.join(d, want))
        if m.exists(p):
            return p
        if not d or d == ".":
            return None
        d = posixpath.dirname(d)


def gather(m, out, source, cpp_filter):
    n, seen, names = 0, set(), set()
    for cpp in m.files:
        if not cpp.endswith(".cpp") or not cpp_filter(cpp):
            continue
        for p, variables in programs_in_cpp(m, cpp):
            stages, key = [], []
            for st in ("vertex", "fragment", "geometry"):
                if st not in p:
                    continue
                path = resolve_source(m, p[st], variables, cpp)
                if path is None:
                    break
                stages.append((st, path))
            else:
                key = (tuple(stages), tuple(p["defines"]), p["version"])
                if key in seen:
                    continue
                seen.add(key)
                assets = stages[0][1].split("/assets/")[0] + "/assets" if "/assets/" in stages[0][1] else posixpath.dirname(stages[0][1])
                pre = Preprocessor(m, assets)
                try:
                    texts = [(st, posixpath.basename(path).rsplit(".", 1)[0], pre.parse(path, p["version"], p["defines"]))
                             for st, path in stages]
                except KeyError:
                    continue
                labels = [posixpath.relpath(path, assets).rsplit(".", 1)[0] for _, path in stages[:2]]
                app = cpp.split("/src/")[0].split("/")[-1] if "/src/" in cpp else posixpath.basename(cpp)[:-4]
                name = app + "_" + (labels[0] if labels[0] == labels[1] else "_".join(labels))
                if p["defines"]:
                    name += "_" + "_".join(k + (v or "") for k, v in p["defines"])
                if safe_name(name) in names:
                    name += f"_{n}"
                names.add(safe_name(name))
                write_program(out, source, name, texts)
                n += 1
    return n
