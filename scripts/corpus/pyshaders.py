"""Finding shader program calls in Python sources (arcade, vispy, pyqtgraph gatherers).

`calls(text, names)` yields (call_node, env) for calls whose function name (or attribute
name) is in `names`; `value(node, env)` evaluates a node to a str / number / dict / list
when it is built from literals, names bound to literals (module, class or function level,
last binding wins), `+`, `%`/.format-free concatenation and textwrap.dedent(); else None.
"""
import ast
import textwrap


def _bindings(tree):
    env = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign):
            for t in node.targets:
                key = t.id if isinstance(t, ast.Name) else t.attr if isinstance(t, ast.Attribute) else None
                if key:
                    env.setdefault(key, []).append(node.value)
        elif isinstance(node, ast.AnnAssign) and node.value is not None and isinstance(node.target, ast.Name):
            env.setdefault(node.target.id, []).append(node.value)
    return env


def value(node, env, depth=0):
    if depth > 20 or node is None:
        return None
    if isinstance(node, ast.Constant):
        return node.value
    if isinstance(node, (ast.Name, ast.Attribute)):
        key = node.id if isinstance(node, ast.Name) else node.attr
        vals = env.get(key, [])
        return value(vals[-1], env, depth + 1) if len(vals) == 1 else None
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        a, b = value(node.left, env, depth + 1), value(node.right, env, depth + 1)
        return a + b if isinstance(a, str) and isinstance(b, str) else None
    if isinstance(node, ast.Dict):
        keys = [value(k, env, depth + 1) for k in node.keys]
        vals = [value(v, env, depth + 1) for v in node.values]
        return None if None in keys or None in vals else dict(zip(keys, vals))
    if isinstance(node, (ast.List, ast.Tuple)):
        vals = [value(v, env, depth + 1) for v in node.elts]
        return None if None in vals else vals
    if isinstance(node, ast.Call):
        fn = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        if fn == "dedent" and node.args:
            v = value(node.args[0], env, depth + 1)
            return textwrap.dedent(v) if isinstance(v, str) else None
    return None


def calls(text, names):
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return
    env = _bindings(tree)
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            fn = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if fn in names:
                yield node, env


def kwargs(node):
    return {k.arg: k.value for k in node.keywords if k.arg}
