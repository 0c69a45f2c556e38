#!/usr/bin/env python3
"""Score effectc's renders of piglit GLSL execution tests by the tests' own probes.

Usage: conformance_probes.py [CORPUS_DIR] [STEP]

  CORPUS_DIR  default /work/corpus/conformance: one directory per program with
              stage files (shader*.vert/.frag/...), SOURCE (path of the piglit
              .shader_test inside the piglit repository), GLSLANG and MESA
              verdicts ("ok..." when that reference links the program).
  STEP        every STEP-th eligible program (default 1).

Environment:
  EFFECTC      effectc binary (default /tmp/effectc-frozen7)
  PIGLIT_GIT   bare piglit git dir (default /work/.mirror/Igalia+piglit/repo)
  JOBS         renders at once (default 2)
  VERBOSE=1    also list every PASS and every non-probeable program
  GUESSES=1    render without --gl-defaults (unset uniforms get effectc's guesses,
               as a plain `effectc render` does)

Eligible: GLSLANG and MESA verdicts both start with "ok".

Probeable: the [test] section uses only commands whose effect effectc can
reproduce with `effectc render --gl-defaults` of the bare stage files (GL's
initial state, one full-window quad):
  uniform <type> <name> <values>   -> --set name=v1,v2,...   (sampler uniforms
                                      are skipped; ints for a bool uniform are
                                      turned into true/false)
  draw rect -1 -1 2 2               -> one render
  clear color / clear / clear depth -> only matter where the fragment shader can
                                      discard (see below)
  probe all rgb[a], probe rgb[a] x y, probe rgb[a] (x, y),
  relative probe rgb[a] (x, y), probe rect rgba (x, y, w, h),
  relative probe rect rgb[a] (x, y, w, h)
  tolerance r g b a                 -> per-channel tolerance of later probes
  link success, hint, probe warn ...-> ignored (cannot change a PASS/FAIL, or
                                      the picture)
Anything else in [test] (other draws, textures, ortho, enable/disable, ssbo,
ubo array index, compute, ...), a [vertex data] section, a probe before the
first draw, no draw or no probe, makes the test NOT PROBEABLE; the report
counts which command did it.

Several draws: every `draw rect -1 -1 2 2` is rendered separately with the
uniforms set up to that point; the probes that follow a draw (up to the next
draw) are checked against that render. That is exact because each draw covers
the whole window and nothing blends, except where the fragment shader can
`discard` (then the earlier contents show through): a program whose fragment
stage contains `discard` is NOT PROBEABLE when it has several draws, or when it
clears to a colour different from effectc's background (0,0,0,1) in a channel
a probe reads.

Probe rule: a channel passes when |expected - actual/255| <= tol + 0.5/255,
tol = 0.01 (piglit's default piglit_tolerance) unless a `tolerance` line says
otherwise. piglit's GL coordinates have their origin bottom-left: pixel (x, y)
is row H-1-y of the top-down PNG. relative coordinates are truncated
(x = int(rx * W), clamped to W-1) as shader_runner does. Window size 250x250,
or `SIZE w h` from [require].

Outcome per probeable program: PASS (every probe passes), FAIL (first failing
probe recorded), NOT DRAWN (effectc exited non-zero, timed out (60 s) or wrote
no PNG; its first `error[` line recorded).
"""

import collections
import concurrent.futures
import glob
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

# `--gl-defaults` (GL's rule: an unset uniform is zero) unless GUESSES=1.
GL_DEFAULTS = [] if os.environ.get("GUESSES") == "1" else ["--gl-defaults"]

EFFECTC = os.environ.get("EFFECTC", "/tmp/effectc-frozen7")
PIGLIT_GIT = os.environ.get("PIGLIT_GIT", "/work/.mirror/Igalia+piglit/repo")
JOBS = int(os.environ.get("JOBS", "2"))
VERBOSE = os.environ.get("VERBOSE") == "1"
TIMEOUT = 60
DEFAULT_TOL = 0.01
HALF_LSB = 0.5 / 255.0
EFFECTC_BACKGROUND = (0.0, 0.0, 0.0, 1.0)

STAGE_ORDER = {"vert": 0, "tesc": 1, "tese": 2, "geom": 3, "frag": 4, "comp": 5}


class NotProbeable(Exception):
    def __init__(self, key, detail=""):
        super().__init__(key)
        self.key = key
        self.detail = detail


# ---------------------------------------------------------------- numbers --

def c_integer(tok):
    """A C integer literal as strtol(tok, NULL, 0) reads it: (negative, magnitude)."""
    t = tok.strip()
    body = t.lstrip("+-")
    if body.lower().startswith("0x"):
        v = int(body, 16)
    elif len(body) > 1 and body.startswith("0"):
        v = int(body, 8)
    else:
        v = int(body, 10)
    return t.startswith("-"), v


def c_strtol(tok):
    """strtol(tok, NULL, 0) as piglit's strtol_hex: 0x.. is a 32-bit pattern."""
    t = tok.strip()
    if t.startswith("0x") or t.startswith("0X"):
        v = int(t, 16) & 0xFFFFFFFF
        return v - (1 << 32) if v >= 1 << 31 else v
    neg, v = c_integer(t)
    return -v if neg else v


def c_strtoul(tok):
    neg, v = c_integer(tok)
    return (-v) & 0xFFFFFFFF if neg else v


def c_strto64(tok, signed):
    neg, v = c_integer(tok)
    if neg:
        v = -v
    if signed and v >= 1 << 63:
        v -= 1 << 64
    if not signed:
        v &= (1 << 64) - 1
    return v


def parse_float32(tok):
    """piglit's strtof_hex: 0x.. is the float's bit pattern."""
    t = tok.strip()
    if t.startswith("0x"):
        return struct.unpack("<f", struct.pack("<I", int(t, 16) & 0xFFFFFFFF))[0]
    return float(t)


def parse_float64(tok):
    t = tok.strip()
    if t.startswith("0x"):
        return struct.unpack("<d", struct.pack("<Q", int(t, 16) & ((1 << 64) - 1)))[0]
    return float(t)


def fmt_float(v):
    if not math.isfinite(v):
        raise ValueError("non-finite")
    s = repr(float(v))
    return s


# ---------------------------------------------------------------- uniforms --

def uniform_shape(utype):
    """(kind, component count) of a shader_runner uniform type, or None."""
    m = re.fullmatch(r"(float|double|int|uint|bool|int64_t|uint64_t|int64|uint64)", utype)
    if m:
        base = m.group(1)
        kind = {"float": "f", "double": "d", "int": "i", "uint": "u", "bool": "b",
                "int64_t": "i64", "int64": "i64", "uint64_t": "u64", "uint64": "u64"}[base]
        return kind, 1
    m = re.fullmatch(r"(|d|i|u|b|i64|u64)vec([234])", utype)
    if m:
        kind = {"": "f", "d": "d", "i": "i", "u": "u", "b": "b", "i64": "i64", "u64": "u64"}[m.group(1)]
        return kind, int(m.group(2))
    m = re.fullmatch(r"(d?)mat([234])(?:x([234]))?", utype)
    if m:
        c = int(m.group(2))
        r = int(m.group(3)) if m.group(3) else c
        return ("d" if m.group(1) else "f"), c * r
    return None


def split_top(s):
    """Split at commas outside parentheses/brackets."""
    out, depth, cur = [], 0, ""
    for ch in s:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    out.append(cur)
    return out


def declared_type(sources, base):
    """Type of uniform `base` as the shader text declares it (best effort)."""
    decl = re.compile(
        r"\buniform\s+(?:(?:lowp|mediump|highp|layout\s*\([^)]*\))\s+)*(\w+)\s+([^;{]*);")
    for m in decl.finditer(sources):
        for part in split_top(m.group(2)):
            n = re.match(r"\s*(\w+)", part)
            if n and n.group(1) == base:
                return m.group(1)
    # a member of a uniform block or a declaration list: `type name;`
    m = re.search(r"\b(\w+)\s+" + re.escape(base) + r"\s*(?:\[[^\]]*\]\s*)*[;,]", sources)
    return m.group(1) if m else None


def translate_uniform(rest, sources):
    """`<type> <name> <values...>` -> (name, value-string) or None (skip)."""
    toks = rest.split()
    if len(toks) < 2:
        raise NotProbeable("uniform (malformed)", rest)
    utype, name, vals = toks[0], toks[1], toks[2:]
    base = re.split(r"[\[.]", name, 1)[0]
    decl = declared_type(sources, base)
    if utype.startswith(("sampler", "isampler", "usampler", "image", "handle")):
        return None
    if decl and re.match(r"[iu]?(sampler|image)", decl) and "." not in name:
        return None  # a sampler set through `uniform int`: a texture unit
    shape = uniform_shape(utype)
    if shape is None:
        raise NotProbeable("uniform " + utype, rest)
    kind, n = shape
    if len(vals) < n:
        raise NotProbeable("uniform (too few values)", rest)
    vals = vals[:n]
    to_bool = kind == "b" or (decl is not None and re.fullmatch(r"bool|bvec[234]", decl))
    try:
        if to_bool:
            out = []
            for v in vals:
                if v in ("true", "false"):
                    out.append(v)
                else:
                    out.append("true" if (parse_float32(v) if kind in ("f", "d") else c_strtol(v)) != 0 else "false")
        elif kind == "f":
            out = [fmt_float(parse_float32(v)) for v in vals]
        elif kind == "d":
            out = [fmt_float(parse_float64(v)) for v in vals]
        elif kind == "i":
            out = [str(c_strtol(v)) for v in vals]
        elif kind == "u":
            out = [str(c_strtoul(v)) for v in vals]
        elif kind == "i64":
            out = [str(c_strto64(v, True)) for v in vals]
        elif kind == "u64":
            out = [str(c_strto64(v, False)) for v in vals]
        else:
            raise ValueError(kind)
    except ValueError:
        raise NotProbeable("uniform (value not expressible)", rest)
    return name, ",".join(out)


# ---------------------------------------------------------------- parsing --

FLOAT = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)"
SEP = r"\s*,\s*"


def floats_after(s, n):
    toks = re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", s)
    if len(toks) < n:
        return None
    return [float(t) for t in toks[:n]]


def parse_probe(line):
    """A probe line -> dict(kind, coords..., expected, ncomp) or None."""
    m = re.match(r"(relative\s+)?probe\s+(rect\s+)?(rgba|rgb)\b(.*)$", line)
    if not m:
        m2 = re.match(r"probe\s+all\s+(rgba|rgb)\b(.*)$", line)
        if not m2:
            return None
        n = 4 if m2.group(1) == "rgba" else 3
        e = floats_after(m2.group(2), n)
        if e is None:
            raise NotProbeable("probe (malformed)", line)
        return {"kind": "all", "n": n, "expected": e}
    rel, rect, comp, rest = bool(m.group(1)), bool(m.group(2)), m.group(3), m.group(4)
    n = 4 if comp == "rgba" else 3
    if rest.strip().startswith("int"):
        raise NotProbeable("relative probe rect rgba int", line)
    ncoord = 4 if rect else 2
    vals = floats_after(rest, ncoord + n)
    if vals is None:
        raise NotProbeable("probe (malformed)", line)
    return {"kind": "rect" if rect else "point", "rel": rel, "n": n,
            "coords": vals[:ncoord], "expected": vals[ncoord:ncoord + n]}


def sections(text):
    out = collections.OrderedDict()
    cur = None
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("[") and s.endswith("]"):
            cur = s[1:-1].strip()
            out.setdefault(cur, [])
            continue
        if cur is not None:
            out[cur].append(line)
    return out


def is_full_rect(vals):
    return vals is not None and all(abs(a - b) < 1e-9 for a, b in zip(vals, (-1, -1, 2, 2)))


def command_key(s):
    """A short name for a [test] command, for counting the non-probeable ones."""
    w = s.split()
    if not w:
        return s
    if w[:2] == ["draw", "rect"]:
        if len(w) > 2 and w[2] in ("ortho", "tex", "patch"):
            return "draw rect " + w[2]
        return "draw rect (not -1 -1 2 2)"
    if w[0] == "relative" and len(w) > 1:
        return " ".join(w[:5]) if w[2:3] == ["rect"] else " ".join(w[:3])
    if w[0] in ("enable", "disable") and len(w) > 1:
        return w[0] + " " + re.sub(r"\d+$", "N", w[1])
    if w[0] in ("draw", "probe", "link", "compile", "polygon", "clip", "atomic",
                "point", "patch", "shade", "ubo", "program", "memory",
                "texparameter", "fb", "viewport", "blend", "xfb", "ssbo", "image"):
        return " ".join(w[:2]) if len(w) > 1 and not re.match(r"[-\d(]", w[1]) else w[0]
    return w[0]


def plan_test(text, sources, has_discard):
    """Parse a .shader_test -> plan dict, or raise NotProbeable.

    Every blocking command is collected (NotProbeable.all lists their keys,
    once each); the exception's key is the first one."""
    secs = sections(text)
    blockers = []

    def block(key, detail=""):
        if key not in [b.key for b in blockers]:
            blockers.append(NotProbeable(key, detail))

    for name in secs:
        if name.startswith("vertex data"):
            block("[vertex data] section")
    if "test" not in secs:
        block("no [test] section")
        secs["test"] = []
    size = (250, 250)
    require_notes = []
    for line in secs.get("require", []):
        s = line.split("#", 1)[0].strip()
        if not s or s.startswith(("/*", "*")):
            continue
        m = re.match(r"SIZE\s+(\d+)\s+(\d+)", s)
        if m:
            size = (int(m.group(1)), int(m.group(2)))
        if not re.match(r"(GLSL( ES)?|GL( ES| CORE| COMPAT)?)\s*(>=|>|<|<=|=)", s):
            require_notes.append(s)

    uniforms = collections.OrderedDict()
    tol = [DEFAULT_TOL] * 4
    draws = []       # list of uniform dicts (None: a draw effectc cannot do)
    probes = []      # (draw index, probe dict, tolerance, text)
    clear_color = (0.0, 0.0, 0.0, 0.0)
    color_bit = False
    cleared_to = None
    cleared_after_draw = False
    ignored = []
    for raw in secs["test"]:
        s = raw.split("#", 1)[0].strip().rstrip(";").strip()
        if not s:
            continue
        try:
            if s.startswith("uniform "):
                r = translate_uniform(s[len("uniform "):], sources)
                if r is not None:
                    uniforms[r[0]] = r[1]
                continue
            w = s.split()
            if w[:2] == ["draw", "rect"] and not (len(w) > 2 and w[2] in ("ortho", "tex", "patch")):
                vals = floats_after(s[len("draw rect"):], 4)
                draws.append(dict(uniforms) if is_full_rect(vals) else None)
                cleared_after_draw = False
                if not is_full_rect(vals):
                    raise NotProbeable("draw rect (not -1 -1 2 2)", s)
                continue
            if w[0] == "draw":
                draws.append(None)
                raise NotProbeable(command_key(s), s)
            if s.startswith("clear color"):
                c = floats_after(s[len("clear color"):], 4)
                if c is None:
                    raise NotProbeable("clear color (malformed)", s)
                clear_color = tuple(c)
                color_bit = True
                continue
            if s.startswith("clear depth"):
                continue
            if s == "clear":
                if color_bit:
                    if draws:
                        cleared_after_draw = True
                    else:
                        cleared_to = clear_color
                continue
            if s.startswith("tolerance"):
                t = floats_after(s[len("tolerance"):], 4)
                if t is None:
                    raise NotProbeable("tolerance (malformed)", s)
                tol = t
                continue
            if s.startswith("link success") or s.startswith("hint ") or s.startswith("probe warn"):
                ignored.append(s)
                continue
            if "probe" in w[:2]:
                p = parse_probe(s)
                if p is None:
                    raise NotProbeable(command_key(s), s)
                if not draws:
                    raise NotProbeable("probe before any draw", s)
                if cleared_after_draw:
                    raise NotProbeable("probe after a clear that follows the draw", s)
                probes.append((len(draws) - 1, p, list(tol), raw.strip()))
                continue
            raise NotProbeable(command_key(s), s)
        except NotProbeable as e:
            block(e.key, e.detail)
    if not blockers:
        if not draws:
            block("no draw")
        elif not probes:
            block("no probe")
        elif has_discard:
            if len(draws) > 1:
                block("discard with several draws")
            elif cleared_to is not None:
                reads_alpha = any(p["n"] == 4 for _, p, _, _ in probes)
                n = 4 if reads_alpha else 3
                if any(abs(cleared_to[i] - EFFECTC_BACKGROUND[i]) > 1e-6 for i in range(n)):
                    block("discard over a clear colour effectc cannot set")
    if blockers:
        e = blockers[0]
        e.all = [b.key for b in blockers]
        raise e
    return {"size": size, "draws": draws, "probes": probes,
            "require": require_notes, "ignored": ignored}


# ---------------------------------------------------------------- rendering --

def stage_files(d):
    files = []
    for f in os.listdir(d):
        stem, _, ext = f.rpartition(".")
        if ext in STAGE_ORDER and stem.startswith("shader"):
            files.append(f)
    files.sort(key=lambda f: (STAGE_ORDER[f.rpartition(".")[2]], f))
    return [os.path.join(d, f) for f in files]


def first_error(text):
    for line in text.splitlines():
        if line.startswith("error[") or line.startswith("error:"):
            return line.strip()
    lines = [l for l in text.splitlines() if l.strip()]
    return lines[-1].strip() if lines else "(no output)"


def render(files, uniforms, size, outdir):
    """-> (pixels bytes, None) or (None, reason)."""
    shutil.rmtree(outdir, ignore_errors=True)
    cmd = [EFFECTC, "render", "--color", "never", "--target-env", "opengl",
           "--frames", "1", "--size", "%dx%d" % size] + GL_DEFAULTS + ["--out", outdir]
    for k, v in uniforms.items():
        cmd += ["--set", "%s=%s" % (k, v)]
    cmd += files
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return None, "timeout after %d s" % TIMEOUT
    out = p.stdout.decode("utf-8", "replace")
    pngs = glob.glob(os.path.join(outdir, "*_0000.png"))
    if p.returncode != 0 or len(pngs) != 1:
        why = first_error(out)
        if p.returncode == 0:
            why = "exit 0 but %d PNGs; %s" % (len(pngs), why)
        return None, why
    q = subprocess.run(["ffmpeg", "-loglevel", "error", "-i", pngs[0], "-f", "rawvideo",
                        "-pix_fmt", "rgba", "-"], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE)
    w, h = size
    if q.returncode != 0 or len(q.stdout) != w * h * 4:
        return None, "PNG unreadable or not %dx%d (%d bytes)" % (w, h, len(q.stdout))
    return q.stdout, None


def check_probe(pix, size, p, tol):
    """None if the probe passes, else a description of the first bad pixel."""
    W, H = size
    n = p["n"]
    if p["kind"] == "all":
        x0, y0, w, h = 0, 0, W, H
    elif p["kind"] == "point":
        x, y = p["coords"]
        if p["rel"]:
            x, y = int(x * W), int(y * H)
            x, y = min(x, W - 1), min(y, H - 1)
        x0, y0, w, h = int(x), int(y), 1, 1
    else:
        x, y, w, h = p["coords"]
        if p["rel"]:
            x0, y0, w, h = int(x * W), int(y * H), int(w * W), int(h * H)
        else:
            x0, y0, w, h = int(x), int(y), int(w), int(h)
    e = p["expected"]
    for gy in range(y0, y0 + h):
        if not 0 <= gy < H:
            return "pixel row %d outside the window" % gy
        row = (H - 1 - gy) * W
        for gx in range(x0, x0 + w):
            if not 0 <= gx < W:
                return "pixel column %d outside the window" % gx
            o = (row + gx) * 4
            a = pix[o:o + n]
            for c in range(n):
                if abs(e[c] - a[c] / 255.0) > tol[c] + HALF_LSB:
                    hint = ""
                    if tuple(pix[o:o + 4]) == tuple(int(v * 255) for v in EFFECTC_BACKGROUND):
                        hint = " [effectc's background colour: pixel not drawn?]"
                    return "at (%d, %d) expected %s got %s%s" % (
                        gx, gy, "(" + ", ".join("%g" % v for v in e) + ")",
                        "(" + ", ".join("%.3f" % (v / 255.0) for v in a) + ")", hint)
    return None


def run_program(d, plan, tmp):
    files = stage_files(d)
    cache = {}
    for i, uni in enumerate(plan["draws"]):
        key = tuple(uni.items())
        if key in cache:
            continue
        pix, why = render(files, uni, plan["size"], os.path.join(tmp, "d%d" % i))
        if pix is None:
            return "NOT DRAWN", why, None
        cache[key] = pix
    for di, p, tol, text in plan["probes"]:
        pix = cache[tuple(plan["draws"][di].items())]
        bad = check_probe(pix, plan["size"], p, tol)
        if bad:
            return "FAIL", "%s: %s" % (text, bad), None
    return "PASS", "", None


# ---------------------------------------------------------------- main --

def read_piglit(path):
    p = subprocess.run(["git", "--git-dir=" + PIGLIT_GIT, "show", "HEAD:" + path],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if p.returncode != 0:
        return None
    return p.stdout.decode("utf-8", "replace")


def strip_comments(src):
    src = re.sub(r"/\*.*?\*/", " ", src, flags=re.S)
    return re.sub(r"//[^\n]*", " ", src)


def verdict_ok(path):
    try:
        with open(path, "rb") as f:
            return f.read(2) == b"ok"
    except OSError:
        return False


def group_reason(reason):
    """A coarse key for grouping NOT DRAWN reasons."""
    m = re.match(r"(error\[\w+\]):?\s*(.*)", reason)
    if not m:
        return reason
    code, msg = m.groups()
    msg = re.sub(r"\bthe (vertex|fragment|geometry|tess\w*|compute) stage\b", "a stage", msg)
    msg = re.sub(r"\(.*\)", "(…)", msg)
    msg = re.sub(r"`[^`]*`|'[^']*'|\"[^\"]*\"", "‹…›", msg)
    msg = re.sub(r"\d+", "N", msg)
    return "%s %s" % (code, msg)


def main(argv):
    corpus = argv[1] if len(argv) > 1 else "/work/corpus/conformance"
    step = int(argv[2]) if len(argv) > 2 else 1
    progs = sorted(d for d in os.listdir(corpus)
                   if os.path.isdir(os.path.join(corpus, d)))
    eligible = [d for d in progs
                if verdict_ok(os.path.join(corpus, d, "GLSLANG"))
                and verdict_ok(os.path.join(corpus, d, "MESA"))]
    chosen = eligible[::step]

    nonprobe = collections.Counter()
    nonprobe_any = collections.Counter()   # every blocking command of a test
    nonprobe_examples = collections.defaultdict(list)
    plans = {}
    require_notes = collections.Counter()
    for d in chosen:
        full = os.path.join(corpus, d)
        try:
            src_path = open(os.path.join(full, "SOURCE")).read().strip()
        except OSError:
            nonprobe["no SOURCE"] += 1
            continue
        text = read_piglit(src_path)
        if text is None:
            nonprobe["shader_test not in the piglit mirror"] += 1
            nonprobe_examples["shader_test not in the piglit mirror"].append(d)
            continue
        files = stage_files(full)
        sources = ""
        for f in files:
            with open(f, encoding="utf-8", errors="replace") as fh:
                sources += strip_comments(fh.read()) + "\n"
        frag = "".join(strip_comments(open(f, encoding="utf-8", errors="replace").read())
                       for f in files if f.endswith(".frag"))
        has_discard = re.search(r"\bdiscard\b", frag) is not None
        try:
            plan = plan_test(text, sources, has_discard)
            if any(f.rpartition(".")[2] in ("tesc", "tese", "comp") for f in files):
                raise NotProbeable("tessellation/compute stage")
        except NotProbeable as e:
            nonprobe[e.key] += 1
            nonprobe_examples[e.key].append(d)
            for k in getattr(e, "all", [e.key]):
                nonprobe_any[k] += 1
            continue
        for r in plan["require"]:
            require_notes[r] += 1
        plans[d] = plan

    results = {}
    tmp = tempfile.mkdtemp(prefix="conformance_probes.")
    try:
        def work(d):
            return d, run_program(os.path.join(corpus, d), plans[d], os.path.join(tmp, d))
        with concurrent.futures.ThreadPoolExecutor(max_workers=JOBS) as ex:
            done = 0
            for d, r in ex.map(work, sorted(plans)):
                results[d] = r
                done += 1
                if done % 50 == 0:
                    print("… %d/%d rendered" % (done, len(plans)), file=sys.stderr, flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)

    outcome = collections.Counter(r[0] for r in results.values())
    nprobe = len(plans)
    print("effectc: %s" % EFFECTC)
    print("corpus:  %s (step %d)" % (corpus, step))
    print()
    print("%-28s %5s" % ("", "count"))
    print("%-28s %5d" % ("programs in corpus", len(progs)))
    print("%-28s %5d" % ("eligible (GLSLANG+MESA ok)", len(eligible)))
    print("%-28s %5d" % ("examined (every %d-th)" % step, len(chosen)))
    print("%-28s %5d" % ("not probeable", len(chosen) - nprobe))
    print("%-28s %5d" % ("probeable", nprobe))
    for k in ("PASS", "FAIL", "NOT DRAWN"):
        print("%-28s %5d" % ("  " + k.lower(), outcome[k]))
    pct = 100.0 * outcome["PASS"] / nprobe if nprobe else 0.0
    print("%-28s %5.1f%%" % ("pass % of probeable", pct))
    print()

    print("== FAIL (%d): first failing probe" % outcome["FAIL"])
    by_dir = collections.defaultdict(list)
    for d, (o, why, _) in sorted(results.items()):
        if o == "FAIL":
            by_dir[re.sub(r"_[^_]*$", "", d)].append((d, why))
    for g in sorted(by_dir):
        print("  [%s] %d" % (g, len(by_dir[g])))
        for d, why in by_dir[g]:
            print("    %s\n      %s" % (d, why))
    print()

    print("== NOT DRAWN (%d), grouped by effectc's first error" % outcome["NOT DRAWN"])
    groups = collections.defaultdict(list)
    for d, (o, why, _) in sorted(results.items()):
        if o == "NOT DRAWN":
            groups[group_reason(why)].append((d, why))
    for g, items in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        print("  %3d  %s" % (len(items), g))
        for d, why in items:
            print("         %s: %s" % (d, why))
    print()

    print("== NOT PROBEABLE (%d), by the first command effectc cannot reproduce" % (len(chosen) - nprobe))
    for k, n in nonprobe.most_common():
        ex = nonprobe_examples[k][:2]
        print("  %4d  %-40s e.g. %s" % (n, k, ", ".join(ex)))
        if VERBOSE:
            for d in nonprobe_examples[k][2:]:
                print("        %s" % d)
    print()
    print("== NOT PROBEABLE: every blocking command, counted once per test it occurs in")
    for k, n in nonprobe_any.most_common():
        print("  %4d  %s" % (n, k))
    print()
    if require_notes:
        print("== [require] lines of probeable tests effectc does not check (recorded only)")
        for r, n in require_notes.most_common():
            print("  %4d  %s" % (n, r))
        print()
    if VERBOSE:
        print("== PASS")
        for d, (o, _, _) in sorted(results.items()):
            if o == "PASS":
                print("  " + d)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
