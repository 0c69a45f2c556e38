"""Helpers for gatherers whose project keeps shader text in C/C++/Python sources or
expands #include itself.

`c_string(text, start, defines)`: the concatenated C string literals that follow `start`
(e.g. `const char *vs =`) up to the closing `;`, honouring `#if defined(X)`/`#ifdef`/`#ifndef`/
`#elif`/`#else`/`#endif` lines (X is set when it is in `defines`).
`expand_includes(text, resolve, parent, pattern)`: replaces include lines by the resolved text,
recursively, each file once unless `once=False`.
"""
import re

_ESC = {"n": "\n", "t": "\t", "\\": "\\", '"': '"', "'": "'", "r": "\r", "0": "\0"}


def _unescape(s):
    return re.sub(r'\\(.)', lambda m: _ESC.get(m.group(1), m.group(1)), s)


def _cond(expr, defines):
    """C #if semantics: `defines` is a set of names or a dict name -> value; other names are 0."""
    values = defines if isinstance(defines, dict) else {}
    expr = expr.strip()
    expr = re.sub(r'defined\s*\(\s*(\w+)\s*\)', lambda m: str(int(m.group(1) in defines)), expr)
    expr = re.sub(r'defined\s+(\w+)', lambda m: str(int(m.group(1) in defines)), expr)
    expr = expr.replace("&&", " and ").replace("||", " or ").replace("!=", "<>").replace("!", " not ").replace("<>", "!=")
    expr = re.sub(r'\b(?!and\b|or\b|not\b)[A-Za-z_]\w*', lambda m: str(values.get(m.group(0), 0)), expr)
    try:
        return bool(eval(expr, {}))
    except Exception:
        return False


def c_string(text, start, defines=()):
    """Concatenated string literals after the first occurrence of `start`; None if absent."""
    i = text.find(start)
    if i < 0:
        return None
    rest = text[i + len(start):]
    stack = []  # (active, taken)
    out = []
    for line in rest.splitlines():
        s = line.strip()
        m = re.match(r'#\s*(if|ifdef|ifndef|elif|else|endif)\b(.*)', s)
        active = all(a for a, _ in stack)
        if m:
            kw, arg = m.group(1), m.group(2)
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
            continue
        if not active:
            continue
        pos = 0
        code = re.sub(r'//.*$', '', line) if '"' not in line else line
        for m2 in re.finditer(r'"((?:[^"\\]|\\.)*)"|//.*$|;', code):
            if m2.group(0) == ";":
                return "".join(out)
            if m2.group(0).startswith("//"):
                break
            out.append(_unescape(m2.group(1)))
    return "".join(out)


def expand_includes(text, resolve, parent=None, pattern=r'^[ \t]*#\s*include\s+["<]([^">]+)[">].*$',
                    once=True, _seen=None):
    """resolve(name, parent_key) -> (key, text) or None (line kept as is)."""
    seen = set() if _seen is None else _seen

    def repl(m):
        r = resolve(m.group(1), parent)
        if r is None:
            return m.group(0)
        key, body = r
        if once and key in seen:
            return ""
        seen.add(key)
        return expand_includes(body, resolve, key, pattern, once, seen)
    return re.sub(pattern, repl, text, flags=re.M)
