"""Rust source helpers for the glium/vulkano gatherers: string literals ("..." with escapes and
`\\`-newline continuation, r#"..."# raw strings), balanced-bracket spans, top-level splits,
and `let name = "...";` / `const NAME: &str = "...";` bindings."""
import re

LIT = r'r(?P<h>#*)"(?:.|\n)*?"(?P=h)|"(?:\\.|\\\n|[^"\\])*"'
_ESC = {"n": "\n", "t": "\t", "r": "\r", "0": "\0", "\\": "\\", '"': '"', "'": "'"}


def strip_comments(src):
    """Rust source with // and /* */ comments blanked, string literals kept."""
    tok = re.compile(r'r(?P<h>#*)"(?:.|\n)*?"(?P=h)|"(?:\\.|\\\n|[^"\\])*"|//[^\n]*|/\*.*?\*/', re.S)
    return tok.sub(lambda m: " " if m.group(0).startswith("/") else m.group(0), src)


def value(lit):
    """The value of one Rust string literal."""
    if lit.startswith("r"):
        h = len(lit) - len(lit[1:].lstrip("#")) - 1
        return lit[h + 2:len(lit) - h - 1]

    def esc(m):
        e = m.group(1)
        if e[0] == "\n":
            return ""  # `\` newline: the newline and the next line's leading whitespace go
        if e[0] == "u":
            return chr(int(e[2:-1], 16))
        if e[0] == "x":
            return chr(int(e[1:], 16))
        return _ESC.get(e, e)
    return re.sub(r"\\(\n\s*|u\{[0-9a-fA-F]+\}|x[0-9a-fA-F]{2}|.)", esc, lit[1:-1])


def span(src, i):
    """End index (exclusive) of the bracket group opening at src[i] ((, [ or {), literals skipped."""
    depth, k = 0, i
    while k < len(src):
        m = re.compile(LIT).match(src, k)
        if m:
            k = m.end()
            continue
        c = src[k]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                return k + 1
        k += 1
    return len(src)


def split_top(s):
    """Splits s at top-level commas (literals and brackets respected)."""
    parts, depth, cur, k = [], 0, "", 0
    while k < len(s):
        m = re.compile(LIT).match(s, k)
        if m:
            cur += m.group(0)
            k = m.end()
            continue
        c = s[k]
        depth += c in "([{"
        depth -= c in ")]}"
        if c == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += c
        k += 1
    if cur.strip():
        parts.append(cur)
    return [p.strip() for p in parts]


def bindings(src):
    """name -> string for `let name = LIT;`, `const NAME: &str = LIT;`, `static NAME: &str = LIT;`."""
    out = {}
    for m in re.finditer(rf"(?:let|const|static)\s+(?:mut\s+)?(\w+)\s*(?::\s*&(?:'static\s+)?str\s*)?=\s*({LIT})\s*;", src):
        out[m.group(1)] = value(m.group(2))
    return out
