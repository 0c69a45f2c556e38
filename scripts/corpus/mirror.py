"""Reading a bare git mirror (what the search tool's `fetch` brings) and writing corpus programs.

Every gather_*.py script imports this module: `Mirror(git_dir)` lists and reads files at HEAD,
`write_program(out, source, name, stages)` writes one program directory
`<out>/<source>__<name>/` with one file per stage (`.vert`, `.frag`, `.geom`, ...).
For shaders held in C/C++ sources: strip_cpp_comments, c_string, c_string_vars, cpp_ifdefs and
GLTrace (follows glCreateShader/glShaderSource/glAttachShader/glLinkProgram in source order).
"""
import os
import re
import subprocess

STAGE_EXT = {"vertex": "vert", "fragment": "frag", "geometry": "geom",
             "tess-control": "tesc", "tess-eval": "tese", "compute": "comp"}


class Mirror:
    def __init__(self, git_dir):
        self.git_dir = git_dir
        out = subprocess.run(["git", f"--git-dir={git_dir}", "ls-tree", "-r", "--name-only", "HEAD"],
                             capture_output=True, text=True, check=True).stdout
        self.files = out.splitlines()
        self._set = set(self.files)

    def exists(self, path):
        return path in self._set

    def show(self, path):
        """The file's bytes at HEAD, or None when there is no such file."""
        if path not in self._set:
            return None
        return subprocess.run(["git", f"--git-dir={self.git_dir}", "show", f"HEAD:{path}"],
                              capture_output=True, check=True).stdout

    def text(self, path):
        data = self.show(path)
        return None if data is None else data.decode("utf-8", "replace")


def safe_name(name):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_")


def write_program(out, source, name, stages):
    """stages: list of (stage, file_stem, text_or_bytes). Returns the program directory."""
    d = os.path.join(out, f"{safe_name(source)}__{safe_name(name)}")
    os.makedirs(d, exist_ok=True)
    for stage, stem, body in stages:
        ext = STAGE_EXT[stage]
        if isinstance(body, str):
            body = body.encode("utf-8")
        with open(os.path.join(d, f"{safe_name(stem)}.{ext}"), "wb") as fh:
            fh.write(body)
    return d


# Reading shaders out of C/C++ sources.
C_LITERAL = r'R"(?P<rawdelim>[^(\s]*)\((?:.|\n)*?\)(?P=rawdelim)"|"(?:\\.|\\\n|[^"\\\n])*"'
_CPP_TOKEN = re.compile(C_LITERAL + r"|'(?:\\.|[^'\\\n])*'|//[^\n]*|/\*.*?\*/", re.S)
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "a": "\a", "b": "\b", "f": "\f", "v": "\v", "\n": ""}


def split_commas(text):
    """The items of a comma-separated list, split at the commas outside parentheses."""
    parts, depth, cur = [], 0, ""
    for ch in text:
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    return parts + [cur]


def strip_cpp_comments(src):
    """C/C++ source with each comment replaced by a space; string and char literals kept."""
    return _CPP_TOKEN.sub(lambda m: " " if m.group(0)[0] == "/" else m.group(0), src)


def c_string(expr):
    """The value of the string literals in a C/C++ expression, adjacent ones concatenated and
    escapes decoded (raw strings R"d(...)d" kept as they are); text between them is ignored."""
    def esc(m):
        e = m.group(1)
        if e[0] == "x":
            return chr(int(e[1:], 16))
        if e[0] in "01234567":
            return chr(int(e, 8))
        return _ESCAPES.get(e, e)
    out = []
    for m in re.finditer(C_LITERAL, expr):
        lit = m.group(0)
        if lit[0] == "R":
            d = len(m.group("rawdelim"))
            out.append(lit[d + 3:-d - 2])
        else:
            out.append(re.sub(r"\\(x[0-9a-fA-F]+|[0-7]{1,3}|.|\n)", esc, lit[1:-1]))
    return "".join(out)


def c_string_vars(src):
    """name -> list of string values for `name = "..." "...";` (one value) and
    `name[] = { "...", "..." };` (one value per element) in comment-free C/C++ source."""
    lits = rf"(?:{C_LITERAL}|\s|\\\n)+"
    out = {}
    for m in re.finditer(rf"(\w+)\s*=\s*(?:\(\s*)?({lits})(?=[;),])", src):
        out[m.group(1)] = [c_string(m.group(2))]
    for m in re.finditer(rf"(\w+)\s*\[[^\]]*\]\s*=\s*\{{((?:{C_LITERAL}|[^\"}}])*)\}}", src):
        elems = [""]
        for t in re.finditer(C_LITERAL + r"|,", m.group(2)):
            if t.group(0) == ",":
                elems.append("")
            else:
                elems[-1] += t.group(0)
        out[m.group(1)] = [c_string(e) for e in elems if e]
    return out


LVALUE = r"[A-Za-z_][\w.]*(?:->\w+)*(?:\[[^\]\n]*\])?"


class GLTrace:
    """Follows, in source order, the GL calls of comment-free C/C++ source that make programs:
    glCreateShader/glShaderSource (sources from string literals, `p = s.c_str()` aliases),
    glCreateProgram/glAttachShader/glLinkProgram. `loaders` adds project calls that make a
    shader: (regex, fn(match) -> (stage, text or None)); the shader
    goes to the LVALUE the call is assigned to, or to NAME[k] inside `NAME[] = { call, ... }`.
    `linkers` adds calls that link: (regex with `dst`, `shaders`, `n` groups), like sb7's
    link_from_shaders(shaders, 2). `sources` adds calls that fill a string variable, such as
    reading a file into a buffer: (regex with a `var` group, fn(match) -> text). After run(), `programs` is a list of (program variable,
    [(stage, text or None), ...]) in link order."""

    def __init__(self, src, loaders=(), linkers=(), sources=()):
        self.src, self.loaders, self.linkers, self.sources = src, list(loaders), list(linkers), list(sources)
        self.strings = c_string_vars(src)
        self.shaders, self.attached, self.programs = {}, {}, []

    def _initializers(self, src, calls):
        """Rewrites `NAME[] = { call, call }` as `NAME[0] = call; NAME[1] = call;`."""
        def split(m):
            body = m.group(2)
            if not re.search(calls, body):
                return m.group(0)
            parts = split_commas(body)
            return " ".join(f"{m.group(1)}[{k}] = {p.strip()};" for k, p in enumerate(parts) if p.strip())
        return re.sub(r"(\w+)\s*\[[^\]]*\]\s*=\s*\{((?:[^{}\"]|" + C_LITERAL + r")*)\}\s*;", split, src)

    def text(self, expr, count):
        """The text glShaderSource(sh, count, expr, ...) passes."""
        expr = re.sub(r"\([^()]*\*\s*\)|\s", "", expr)  # casts such as (const GLchar**)
        name = expr.lstrip("&")
        vals = self.strings.get(name)
        if not vals:
            return None
        vals = vals[:int(count)] if count.strip().isdigit() else vals
        return "".join(v.split("\0")[0] for v in vals)  # each string ends at its first NUL

    def run(self):
        unnamed = lambda pat: re.sub(r"\(\?P<\w+>", "(?:", pat)
        norm = lambda e: re.sub(r"\s+|this->", "", e)
        calls = "|".join(unnamed(p) for p, _ in self.loaders) or "(?!)"
        src = self._initializers(self.src, r"glCreateShader|" + calls)
        alts = [rf"(?P<cdst>{LVALUE})\s*=\s*glCreateShader\(\s*GL_(?P<cst>\w+?)_SHADER\s*\)",
                rf"glShaderSource\(\s*(?P<ssh>[^,]+?)\s*,\s*(?P<sn>[^,]+?)\s*,\s*(?P<ssrc>[^,]+?)\s*,",
                rf"(?P<alias>\w+)\s*=\s*(?:\([\w\s*]+\)\s*)?(?P<aval>\w+)(?:\.c_str\(\)|\.data\(\))?\s*;",
                rf"(?P<pdst>{LVALUE})\s*=\s*glCreateProgram\(\s*\)",
                rf"glAttachShader\(\s*(?P<aprog>[^,]+?)\s*,\s*(?P<ash>[^)]+?)\s*\)",
                rf"glLinkProgram\(\s*(?P<lprog>[^)]+?)\s*\)"]
        for k, (pat, _) in enumerate(self.loaders):
            alts.append(rf"(?:(?P<ldst{k}>{LVALUE})\s*=\s*)?(?P<lcall{k}>{unnamed(pat)})")
        for k, pat in enumerate(self.linkers):
            alts.append(rf"(?P<link{k}>{unnamed(pat)})")
        for k, (pat, _) in enumerate(self.sources):
            alts.append(rf"(?P<source{k}>{unnamed(pat)})")
        for m in re.finditer("|".join(alts), src):
            g = {k: v for k, v in m.groupdict().items() if v is not None}
            if "cdst" in g:
                self.shaders[norm(g["cdst"])] = (STAGE_NAMES.get(g["cst"]), None)
            elif "ssh" in g:
                sh = norm(g["ssh"])
                stage = self.shaders.get(sh, (None, None))[0]
                self.shaders[sh] = (stage, self.text(g["ssrc"], g["sn"]))
            elif "alias" in g:  # p = s.c_str(); p = (const GLchar*)buf; or anything else
                self.strings[g["alias"]] = self.strings.get(g["aval"])
            elif "pdst" in g:
                self.attached[norm(g["pdst"])] = []
            elif "aprog" in g:
                self.attached.setdefault(norm(g["aprog"]), []).append(self.shaders.get(norm(g["ash"])))
            elif "lprog" in g:
                self.programs.append((norm(g["lprog"]), list(self.attached.get(norm(g["lprog"]), []))))
            else:
                for k, (pat, fn) in enumerate(self.loaders):
                    if f"lcall{k}" in g:
                        sub = re.match(pat, g[f"lcall{k}"])
                        if g.get(f"ldst{k}"):
                            self.shaders[norm(g[f"ldst{k}"])] = fn(sub)
                for k, (pat, fn) in enumerate(self.sources):
                    if f"source{k}" in g:
                        sub = re.match(pat, g[f"source{k}"])
                        self.strings[sub.group("var")] = [fn(sub)]
                for k, pat in enumerate(self.linkers):
                    if f"link{k}" in g:
                        sub = re.match(pat, g[f"link{k}"])
                        self.link(norm(sub.group("dst")), norm(sub.group("shaders")), sub.group("n"))
        return self.programs

    def link(self, dst, expr, n):
        """A program of the n shader slots starting at expr (`shaders`, `&shaders.vs`, `&cs`)."""
        expr = expr.lstrip("&")
        base = expr.split(".")[0].split("[")[0]
        slots = [k for k in self.shaders if k == base or k.startswith((base + "[", base + "."))]
        if expr in slots:
            slots = slots[slots.index(expr):]
        self.programs.append((dst, [self.shaders[k] for k in slots[:int(n)]]))


STAGE_NAMES = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry",
               "TESS_CONTROL": "tess-control", "TESS_EVALUATION": "tess-eval", "COMPUTE": "compute"}


GRAPHICS_STAGES = {"vertex", "fragment", "geometry", "tess-control", "tess-eval"}


def graphics_stages(kinds):
    """True when the stage kinds make a complete program: vertex and fragment, a geometry
    stage, and an evaluation stage with or without a control stage."""
    kinds = set(kinds)
    return ({"vertex", "fragment"} <= kinds <= GRAPHICS_STAGES
            and ("tess-control" not in kinds or "tess-eval" in kinds))


def graphics_program(shaders):
    """True when the (stage, text) list is a complete graphics program (graphics_stages)."""
    stages = [s for s, _ in shaders] if all(shaders) else [None]
    return None not in stages and all(t is not None for _, t in shaders) and graphics_stages(stages)


def cpp_ifdefs(src, defined=()):
    """C/C++ source with #ifdef/#ifndef/#if [!]defined(X)/#elif/#else/#endif branches resolved
    for the macros in `defined` (others undefined; `#if N` is N != 0, any other #if true)."""
    out, stack = [], []  # stack of [this branch live, some branch already taken]
    for line in src.split("\n"):
        d = re.match(r"\s*#\s*(ifdef|ifndef|if|elif|else|endif)\b(.*)", line)
        if not d:
            if all(live for live, _ in stack):
                out.append(line)
            continue
        kind, cond = d.group(1), d.group(2).split("//")[0].strip()
        if kind in ("ifdef", "ifndef", "if", "elif"):
            name = re.match(r"(!?)\s*(?:defined\s*\(?\s*(\w+)\s*\)?|(\w+))$", cond) if kind in ("if", "elif") else None
            if kind == "ifdef":
                val = cond in defined
            elif kind == "ifndef":
                val = cond not in defined
            elif name and not (name.group(3) or "").isdigit():
                val = ((name.group(2) or name.group(3)) in defined) != bool(name.group(1))
            else:
                val = cond != "0"
            if kind == "elif":
                live = not stack[-1][1] and val
                stack[-1] = [live, stack[-1][1] or live]
            else:
                stack.append([val, val])
        elif kind == "else":
            stack[-1] = [not stack[-1][1], True]
        elif stack:
            stack.pop()
    return "\n".join(out)


def cap_sample(items, cap=800, key=str):
    """At most `cap` of `items`, a deterministic sample (the smallest SHA-1 of key(item)),
    kept in their original order; all of them when there are no more than `cap`."""
    import hashlib
    items = list(items)
    if len(items) <= cap:
        return items
    keep = set(sorted(range(len(items)), key=lambda i: hashlib.sha1(key(items[i]).encode()).hexdigest())[:cap])
    return [it for i, it in enumerate(items) if i in keep]


def version_position(src):
    """QOpenGLShader's findVersionDirectivePosition: (split position, line)."""
    state, i = "sol", 0
    while i < len(src):
        c = src[i]
        if state == "pp":
            if c in " \t":
                pass
            elif src.startswith("version", i):
                j = src.find("\n", i)
                j = len(src) if j < 0 else j
                return j + 1, src.count("\n", 0, j) + 1
            elif c == "/":
                state = "cs"
            else:
                state = "sol" if c == "\n" else "normal"
        elif state == "sol" and c in " \t":
            pass
        elif state == "sol" and c == "#":
            state = "pp"
        elif state in ("sol", "normal"):
            state = "cs" if c == "/" else "sol" if c == "\n" else "normal"
        elif state == "cs":
            state = "ml" if c == "*" else "sl" if c == "/" else "normal"
        elif state == "ml":
            state = "ce" if c == "*" else "ml"
        elif state == "sl":
            state = "normal" if c == "\n" else "sl"
        elif state == "ce":
            state = "normal" if c == "/" else "ce" if c == "*" else "ml"
        i += 1
    return 0, 1


def call_args(text, start):
    """The top-level comma-separated arguments of the bracketed list opening at text[start]
    (`(` or `{`; nested `()`, `[]`, `{}` and string literals kept whole)."""
    depth, i, cur, args = 0, start, "", []
    while i < len(text):
        ch = text[i]
        if ch == '"' and depth >= 1:
            j = text.find('"', i + 1)
            while j > 0 and text[j - 1] == "\\":
                j = text.find('"', j + 1)
            j = len(text) - 1 if j < 0 else j
            cur += text[i:j + 1]
            i = j + 1
            continue
        if ch in "([{":
            depth += 1
            if depth == 1:
                i += 1
                continue
        elif ch in ")]}":
            depth -= 1
            if depth == 0:
                args.append(cur.strip())
                return args
        if ch == "," and depth == 1:
            args.append(cur.strip())
            cur = ""
        else:
            cur += ch
        i += 1
    return args
