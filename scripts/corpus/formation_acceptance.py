#!/usr/bin/env python3
"""How `effectc check` forms programs on three public codebases, against the programs their
host code links, and whether a varying mismatch injected into each host program is caught.

Usage: formation_acceptance.py EFFECTC [WORK_DIR]   (WORK_DIR defaults to /tmp/formation)

Everything is re-created from the local git mirrors (MIRROR_ROOT, default /work/.mirror):
each codebase's HEAD tree is extracted into WORK_DIR/<codebase> (`git archive HEAD | tar x`;
when the mirror lacks some blobs, e.g. large binary assets of a partial clone, the tree is
written blob by blob from `git cat-file --batch` and the missing paths are listed). Nothing is
written anywhere else. For each codebase:

 (a) host programs (derived from the host code, below) against `effectc check --format json`'s
     `formed` list over the whole tree; a program is keyed by its set of (stage, file) pairs:
     exact matches, extra programs formed, host programs missed (with what effectc formed
     from their files instead);
 (b) formed programs with one stage, and whether each carries note N0002;
 (c) injection: one input the fragment stage reads (after its `#define` aliases, e.g.
     `#define vTexCoord TEX0.xy`) is renamed `X` -> `X_injected` throughout the fragment
     stage's text (identifier boundaries; struct members and `.X` accesses left alone; a block
     input's block name), the check is run again, and the host program counts as caught when
     an error E0202 (E0201 for blocks) names `X_injected`; caught in a program effectc formed
     differently from the host's is counted apart. A W0202 naming it (the input is unread once
     preprocessed, which GL accepts) is counted apart, not as a miss. Fragment stages with no
     user input, only location-qualified inputs (they still match by location), no input that
     is read, or (libretro) only inputs declared outside the FRAGMENT section or used outside
     it are "not injectable". The file is restored after each run (and compared).

Codebases:
 1. libretro/glsl-shaders: host programs = every .glsl file with a VERTEX and a FRAGMENT
    conditional (RetroArch compiles it twice, defining VERTEX or FRAGMENT, and always defines
    PARAMETER_UNIFORM: the root effectc.toml is `define = { PARAMETER_UNIFORM = 1 }`).
    Injection into the FRAGMENT section only; checked per file (`check FILE`).
 2. paroj/gltut: host programs from each `Tut NN */*.cpp`: successive literal
    `Framework::LoadShader(GL_X_SHADER, "a.vert")` calls up to `CreateProgram`; string literals
    naming .vert/.geom/.frag files inside one call's parentheses or one initializer's braces
    (`LoadProgram("PCN.vert", "X.frag")`, `{"PN.vert", "PCN.vert", "X.frag"}`: each vertex
    with the next fragment); and `Framework::Scene("x.xml")` files' `<prog vert= frag= geom=>`
    (framework/Scene.cpp links those). Names resolve as Framework::FindFileOrThrow does:
    `<tutorial>/data/NAME`, else the shared `data/NAME`. Two rows: an effectc.toml with one
    [[program]] per host program, and no effectc.toml (automatic rules only). Injection per
    distinct fragment file, whole tree checked.
 3. McNopper/OpenGL: host programs from `ExampleNN/src/*.c`: glusFileLoadText("../ExampleNN/
    shader/x.vert.glsl", &var) then glusProgramBuildFromSource / glusProgramCreateFromSource
    (&p, vertex, control, evaluation, geometry, fragment), glusProgramBuildComputeFromSource,
    and glusProgramBuildSeparableFromSource + glusProgramPipelineBuild. No effectc.toml.
    Injection per distinct fragment file, whole tree checked.

Prints a markdown table per codebase and totals; exits 0.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time

MIRROR_ROOT = os.environ.get("MIRROR_ROOT", "/work/.mirror")
SUFFIX = "_injected"
CAUGHT_CODES = ("E0202", "E0201")
EXAMPLES = 8  # examples listed per failure class

# --------------------------------------------------------------------------------------------
# extraction and running effectc


def git(git_dir, *args, **kw):
    return subprocess.run(["git", f"--git-dir={git_dir}", *args], capture_output=True, **kw)


def extract(git_dir, dest):
    """HEAD's tree into dest. Returns (method, missing paths)."""
    shutil.rmtree(dest, ignore_errors=True)
    os.makedirs(dest)
    arch = subprocess.Popen(["git", f"--git-dir={git_dir}", "archive", "HEAD"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    tar = subprocess.run(["tar", "x", "-C", dest], stdin=arch.stdout, capture_output=True)
    arch.stdout.close()
    arch.stderr.read()
    arch.wait()
    if arch.returncode == 0 and tar.returncode == 0:
        return "git archive HEAD | tar x", []
    # The mirror lacks some blobs: write the tree blob by blob, skipping the missing ones.
    shutil.rmtree(dest)
    os.makedirs(dest)
    listing = git(git_dir, "ls-tree", "-r", "-z", "HEAD", check=True).stdout
    blobs = []
    for rec in listing.split(b"\0"):
        if not rec:
            continue
        meta, path = rec.split(b"\t", 1)
        mode, kind, oid = meta.split()
        if kind == b"blob":
            blobs.append((mode, oid, os.fsdecode(path)))
    out = git(git_dir, "cat-file", "--batch", input=b"".join(oid + b"\n" for _, oid, _ in blobs)).stdout
    pos, missing = 0, []
    for mode, oid, path in blobs:
        nl = out.index(b"\n", pos)
        header = out[pos:nl].split()
        pos = nl + 1
        if header[-1] == b"missing":
            missing.append(path)
            continue
        size = int(header[2])
        data = out[pos:pos + size]
        pos += size + 1
        target = os.path.join(dest, path)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if mode == b"120000":
            os.symlink(os.fsdecode(data), target)
            continue
        with open(target, "wb") as fh:
            fh.write(data)
        if mode == b"100755":
            os.chmod(target, 0o755)
    return "git cat-file --batch (git archive failed: blobs missing from the mirror)", missing


def head_commit(git_dir):
    return git(git_dir, "rev-parse", "HEAD", text=True).stdout.strip()


class Effectc:
    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.runs = 0
        self.seconds = 0.0

    def check(self, cwd, args, timeout=900):
        t0 = time.monotonic()
        p = subprocess.run([self.path, "check", "--format", "json", *args], cwd=cwd,
                           capture_output=True, timeout=timeout)
        dt = time.monotonic() - t0
        self.runs += 1
        self.seconds += dt
        try:
            doc = json.loads(p.stdout)
        except ValueError:
            raise SystemExit(f"effectc printed no JSON for {args} in {cwd} (exit {p.returncode}):\n"
                             f"{p.stderr.decode(errors='replace')[:2000]}")
        return Report(doc, p.returncode, dt)


def norm(path):
    return os.path.normpath(path) if path else path


class Report:
    def __init__(self, doc, rc, seconds):
        self.rc, self.seconds = rc, seconds
        self.diags = doc.get("diagnostics", [])
        self.formed = doc.get("formed", [])
        for d in self.diags:
            d["file"] = norm(d.get("file"))
        self.programs = []  # (key, formed entry)
        for f in self.formed:
            key = frozenset((s["stage"], norm(s["file"])) for s in f["stages"])
            self.programs.append((key, f))
        self.keys = {k for k, _ in self.programs}
        self.alone_noted = set()  # files named by an N0002 note
        for d in self.diags:
            if d["code"] == "N0002":
                m = re.match(r"`([^`]+)`", d["message"])
                if m:
                    self.alone_noted.add(norm(m.group(1)))

    def errors_on(self, files):
        return [d for d in self.diags if d["severity"] == "error" and d["file"] in files]

    def containing(self, path):
        return [(k, f) for k, f in self.programs if any(p == path for _, p in k)]


# --------------------------------------------------------------------------------------------
# GLSL text: comments, inputs, renaming

def blank_comments(src):
    """Comments replaced by spaces (newlines kept), so offsets stay the same."""
    def sub(m):
        return re.sub(r"[^\n]", " ", m.group(0))
    return re.sub(r"//[^\n]*|/\*.*?(?:\*/|$)", sub, src, flags=re.S)


QUAL = r"(?:flat|smooth|noperspective|centroid|sample|invariant|precise|highp|mediump|lowp|COMPAT_PRECISION|PRECISION)"
BASE_KEYWORDS = ("in", "varying", "COMPAT_VARYING")


def input_keywords(text):
    """`in`, `varying` and the macros a file defines as one of them (`#define IN varying`)."""
    extra = re.findall(r"(?m)^[ \t]*#[ \t]*define[ \t]+(\w+)[ \t]+(?:in|varying)[ \t]*$", text)
    return tuple(dict.fromkeys(BASE_KEYWORDS + tuple(k for k in extra if "ATTRIBUTE" not in k)))


NAME_ITEM = r"[A-Za-z_]\w*(?:\s*\[[^\]]*\])?"


def decl_patterns(keywords):
    kw = "|".join(re.escape(k) for k in keywords)
    var = re.compile(
        rf"(?m)(?:^|(?<=;))[ \t]*(?:layout\s*\((?P<layout>[^)]*)\)\s*)?(?:{QUAL}\s+)*"
        rf"(?:{kw})\s+(?:[A-Za-z_]\w*\s+)*?(?P<type>[A-Za-z_]\w*)\s+"
        rf"(?P<names>{NAME_ITEM}(?:\s*,\s*{NAME_ITEM})*)\s*;")
    block = re.compile(
        rf"(?m)(?:^|(?<=;))[ \t]*(?:layout\s*\((?P<layout>[^)]*)\)\s*)?(?:{QUAL}\s+)*(?:{kw})\s+(?P<name>[A-Za-z_]\w*)\s*\{{")
    return var, block


def word(name):
    return re.compile(rf"(?<![\w.]){re.escape(name)}(?!\w)")


def declared_inputs(text, keywords=BASE_KEYWORDS):
    """[(name, kind 'var'|'block', has_location)] declared in comment-free text, in order."""
    var, block = decl_patterns(keywords)
    found = []
    for m in var.finditer(text):
        if m.group("type") in keywords:
            continue
        loc = bool(m.group("layout") and re.search(r"\blocation\b", m.group("layout")))
        for part in m.group("names").split(","):
            n = re.match(r"\s*([A-Za-z_]\w*)", part)
            if n and not n.group(1).startswith("gl_"):
                found.append((m.start(), n.group(1), "var", loc))
    for m in block.finditer(text):
        loc = bool(m.group("layout") and re.search(r"\blocation\b", m.group("layout")))
        found.append((m.start(), m.group("name"), "block", loc))
    return [f[1:] for f in sorted(found)]


def struct_bodies(text):
    """Spans of `struct X { ... }` bodies (their members are not the input)."""
    return [m.span() for m in re.finditer(r"\bstruct\s+\w*\s*\{[^{}]*\}", text)]


def name_spans(name, text):
    """Occurrences of `name` as an identifier, outside struct bodies and member accesses."""
    bodies = struct_bodies(text)
    return [m.span() for m in word(name).finditer(text) if not any(a <= m.start() < b for a, b in bodies)]


def rename(name, new, text, clean):
    """text with `name` renamed where clean (its comment-free twin) names it as an identifier."""
    for a, b in reversed(name_spans(name, clean)):
        text = text[:a] + new + text[b:]
    return text


def is_read(name, text, keywords, depth=0):
    """Whether code lines of text use `name` (an occurrence not in declaration position, i.e.
    not right after a type or qualifier identifier), directly or through an object-like macro
    whose body names it (followed a few levels)."""
    aliases, code = [], []
    for line in text.split("\n"):
        st = line.lstrip()
        if st.startswith("#"):
            m = re.match(r"#\s*define\s+(\w+)(?:\([^)]*\))?\s+(.*)", st)
            if m and word(name).search(m.group(2)) and m.group(1) != name:
                aliases.append(m.group(1))
            code.append(" " * len(line))
        else:
            code.append(line)
    code = "\n".join(code)
    for a, _ in name_spans(name, code):
        before = re.search(r"([A-Za-z_]\w*)\s*$", code[:a])
        if not before or before.group(1) == "return":
            return True
    return depth < 4 and any(is_read(a, text, keywords, depth + 1) for a in aliases)


def used_outside(name, text):
    """Whether text names `name` other than as the macro a `#define name ...` defines (that
    macro no longer applies once the fragment section's occurrences are renamed)."""
    defined = [m.start(1) for m in re.finditer(rf"(?m)^[ \t]*#[ \t]*define[ \t]+({re.escape(name)})\b", text)]
    return any(a not in defined for a, _ in name_spans(name, text))


def pick_input(decl_text, stage_text, keywords=BASE_KEYWORDS, outside_text=""):
    """The input to rename: declared in decl_text, read in stage_text, not named in
    outside_text (comment-free all). Returns (name, kind) or (None, reason)."""
    inputs = declared_inputs(decl_text, keywords)
    if not inputs:
        return None, "no user varying input"
    free = [i for i in inputs if not i[2]]
    if not free:
        return None, "only location-qualified inputs (a renamed one still matches by location)"
    read = [i for i in free if i[1] == "block" or is_read(i[0], stage_text, keywords)]
    if not read:
        return None, "inputs declared but never read"
    inside = [i for i in read if not used_outside(i[0], outside_text)]
    if not inside:
        return None, "every read input is also used outside the FRAGMENT section (e.g. by a shared #define)"
    for name, kind, _ in inside:
        if kind == "var":
            return name, kind
    return inside[0][0], inside[0][1]


def read_text(path):
    with open(path, "rb") as fh:
        return fh.read().decode("utf-8", "surrogateescape")


def write_text(path, text):
    with open(path, "wb") as fh:
        fh.write(text.encode("utf-8", "surrogateescape"))


# --------------------------------------------------------------------------------------------
# results

class Row:
    """One checked configuration of one codebase."""

    def __init__(self, label):
        self.label = label
        self.host = {}          # key -> {"sources": set, "fragment": path or None}
        self.report = None
        self.inj = {}           # key -> (outcome, detail); outcome caught|caught-other|missed|unread|skip
        self.caught_with_new_error = []  # (key, diagnostic): caught, but the injection also made another error
        self.inj_runs = 0
        self.inj_seconds = 0.0
        self.notes = []


def stage_list(key):
    order = ["vertex", "tess_control", "tess_eval", "geometry", "fragment", "compute"]
    return sorted(key, key=lambda sp: (order.index(sp[0]) if sp[0] in order else 9, sp[1]))


def show_key(key):
    files = []
    for st, p in stage_list(key):
        if p not in files:
            files.append(p)
    stages = "+".join(st for st, _ in stage_list(key))
    return f"{' + '.join(files)} [{stages}]"


def formation(row):
    rep = row.report
    host = set(row.host)
    exact = host & rep.keys
    extra = [k for k, _ in rep.programs if k not in host]
    missed = sorted(host - rep.keys, key=show_key)
    lone = [(k, f) for k, f in rep.programs if len(f["stages"]) == 1]
    lone_noted = [(k, f) for k, f in lone if norm(f["stages"][0]["file"]) in rep.alone_noted]
    host_files = {p for k in host for _, p in k}
    return dict(exact=exact, extra=extra, missed=missed, lone=lone, lone_noted=lone_noted,
                host_files=host_files)


def why_missed(row, key):
    """What effectc formed from a missed host program's files."""
    rep = row.report
    parts = []
    seen = set()
    for _, p in stage_list(key):
        for k, f in rep.containing(p):
            if k in seen:
                continue
            seen.add(k)
            alone = " (N0002)" if len(k) == 1 and p in rep.alone_noted else ""
            parts.append(f"formed {show_key(k)}: {f['why']}{alone}")
        if not rep.containing(p):
            parts.append(f"{p}: in no formed program")
    return "; ".join(parts)


def inject_outcomes(row):
    c = {"caught": 0, "caught-other": 0, "missed": 0, "unread": 0, "skip": 0}
    for outcome, _ in row.inj.values():
        c[outcome] += 1
    return c


def print_row_details(row, f):
    rep = row.report
    print(f"\n**{row.label}** — details")
    for note in row.notes:
        print(f"- {note}")
    if f["missed"]:
        print(f"- host programs missed ({len(f['missed'])}):")
        for k in f["missed"][:EXAMPLES * 3]:
            print(f"  - {show_key(k)} — {why_missed(row, k)}")
        if len(f["missed"]) > EXAMPLES * 3:
            print(f"  - … {len(f['missed']) - EXAMPLES * 3} more")
    if f["extra"]:
        used = [k for k in f["extra"] if any(p in f["host_files"] for _, p in k)]
        print(f"- extra programs formed ({len(f['extra'])}; {len(used)} of them hold a file a host program uses):")
        for k in sorted(f["extra"], key=show_key)[:EXAMPLES * 3]:
            why = dict(rep.programs)[k]["why"]
            print(f"  - {show_key(k)} — {why}")
        if len(f["extra"]) > EXAMPLES * 3:
            print(f"  - … {len(f['extra']) - EXAMPLES * 3} more")
    lone_un = [(k, x) for k, x in f["lone"] if (k, x) not in f["lone_noted"]]
    if lone_un:
        print(f"- one-stage programs without an N0002 note ({len(lone_un)}):")
        for k, x in lone_un[:EXAMPLES * 2]:
            print(f"  - {show_key(k)} — {x['why']}")
    for k, d in row.caught_with_new_error[:EXAMPLES]:
        print(f"- caught, but the injection also made another error: {show_key(k)} — {d['code']}: {d['message'][:160]}")
    by_reason = {}
    for k, (outcome, detail) in sorted(row.inj.items(), key=lambda kv: show_key(kv[0])):
        if outcome != "caught":
            by_reason.setdefault((outcome, detail["class"]), []).append((k, detail))
    for (outcome, cls), items in sorted(by_reason.items()):
        label = {"missed": "injection missed", "skip": "not injectable", "caught-other": "injection caught",
                 "unread": "injection not a link error"}[outcome]
        print(f"- {label}: {cls} ({len(items)})")
        for k, d in items[:EXAMPLES]:
            extra = f" — {d['printed']}" if d.get("printed") else ""
            rn = f" [{d['renamed']}]" if d.get("renamed") else ""
            print(f"  - {show_key(k)}{rn}{extra}")
        if len(items) > EXAMPLES:
            print(f"  - … {len(items) - EXAMPLES} more")


def row_numbers(row):
    f = formation(row)
    c = inject_outcomes(row)
    return f, {
        "host programs": len(row.host),
        "formed programs": len(row.report.programs),
        "exact matches": len(f["exact"]),
        "extra formed": len(f["extra"]),
        "host missed": len(f["missed"]),
        "one-stage formed": len(f["lone"]),
        "one-stage with N0002": len(f["lone_noted"]),
        "one-stage without N0002": len(f["lone"]) - len(f["lone_noted"]),
        "injected": c["caught"] + c["caught-other"] + c["missed"] + c["unread"],
        "caught": c["caught"] + c["caught-other"],
        "caught, program formed differently": c["caught-other"],
        "missed": c["missed"],
        "injected input unread (W0202)": c["unread"],
        "caught, the injection also made another error": len(row.caught_with_new_error),
        "not injectable": c["skip"],
        "errors (whole tree)": sum(1 for d in row.report.diags if d["severity"] == "error"),
        "whole-tree check (s)": round(row.report.seconds, 2),
        "injection checks": row.inj_runs,
        "injection time (s)": round(row.inj_seconds, 1),
    }


def print_codebase(title, rows, meta):
    print(f"\n## {title}\n")
    for m in meta:
        print(f"- {m}")
    nums = [row_numbers(r) for r in rows]
    print()
    print("| measure | " + " | ".join(r.label for r in rows) + " |")
    print("|---|" + "---:|" * len(rows))
    for key in nums[0][1]:
        print(f"| {key} | " + " | ".join(str(n[1][key]) for n in nums) + " |")
    for r, (f, _) in zip(rows, nums):
        print_row_details(r, f)
    return [n[1] for n in nums]


# --------------------------------------------------------------------------------------------
# injection into separate fragment files (gltut, McNopper)

def inject_separate(row, ex, root, args):
    """Per distinct fragment file of row.host: rename one input, check args in root."""
    by_frag = {}
    for key, info in row.host.items():
        by_frag.setdefault(info["fragment"], []).append(key)
    for frag, keys in sorted(by_frag.items(), key=lambda kv: kv[0] or ""):
        if frag is None:
            for k in keys:
                row.inj[k] = ("skip", {"class": "no fragment stage (compute program)"})
            continue
        path = os.path.join(root, frag)
        original = read_text(path)
        clean = blank_comments(original)
        name, kind = pick_input(clean, clean, input_keywords(clean))
        if name is None:
            for k in keys:
                row.inj[k] = ("skip", {"class": kind})
            continue
        new = name + SUFFIX
        try:
            write_text(path, rename(name, new, original, clean))
            rep = ex.check(root, args)
        finally:
            write_text(path, original)
        row.inj_runs += 1
        row.inj_seconds += rep.seconds
        assert read_text(path) == original
        judge_separate(row, rep, frag, keys, name, new, kind)


def judge_separate(row, rep, frag, keys, name, new, kind):
    """Outcome per host program of one injected run: caught (the host program formed and an
    E0202/E0201 names the renamed input), caught-other (reported, but in a program formed
    differently from the host's), missed (with a class), from rep (injected run) and
    row.report (the same tree before the injection)."""
    hits = [d for d in rep.diags if d["severity"] == "error" and d["code"] in CAUGHT_CODES
            and f"`{new}`" in d["message"] and d["file"] == frag]
    multi = [k for k, _ in rep.containing(frag) if len(k) > 1]
    unread = [d for d in rep.diags if d["code"] == "W0202" and f"`{new}`" in d["message"] and d["file"] == frag]
    for k in keys:
        files = {p for _, p in k}
        detail = {"renamed": f"{kind} `{name}` -> `{new}`"}
        if k not in rep.keys:
            formed = [f"{show_key(kk)} ({f['why']}{', N0002' if len(kk) == 1 and frag in rep.alone_noted else ''})"
                      for kk, f in rep.containing(frag)]
            if hits and multi:
                row.inj[k] = ("caught-other", dict(detail, **{
                    "class": "reported in a program formed differently from the host's",
                    "printed": hits[0]["code"] + ": " + hits[0]["message"] + "; fragment formed as " + "; ".join(formed)}))
            else:
                detail["class"] = "host program not formed"
                detail["printed"] = ("fragment formed as " + "; ".join(formed)) if formed else "fragment in no program"
                row.inj[k] = ("missed", detail)
            continue
        labelled = [h for h in hits if any(norm(lab.get("file")) in files - {frag} for lab in h.get("labels", []))]
        unlabelled = [h for h in hits if not any(lab.get("file") for lab in h.get("labels", []))]
        if labelled or (hits and len(hits) >= len(multi)):
            row.inj[k] = ("caught", dict(detail, printed=hits[0]["code"] + ": " + hits[0]["message"]))
            seen = {(d["code"], d["message"]) for d in row.report.errors_on(files)}
            extra = [d for d in rep.errors_on(files) if d not in hits and d["code"] not in CAUGHT_CODES
                     and (d["code"], d["message"]) not in seen]
            if extra:
                row.caught_with_new_error.append((k, extra[0]))
            continue
        if unlabelled:
            row.inj[k] = ("caught", dict(detail, printed="unattributed: " + unlabelled[0]["message"]))
            row.notes.append(f"caught without attribution to one program: {show_key(k)}")
            continue
        before = row.report.errors_on(files)
        seen = {(d["code"], d["message"]) for d in before}
        after = [d for d in rep.errors_on(files) if (d["code"], d["message"]) not in seen]
        if unread:
            detail["class"] = "the renamed input is unread once preprocessed: W0202 (GL accepts an unmatched unread input)"
            detail["printed"] = f"W0202: {unread[0]['message']}"
            row.inj[k] = ("unread", detail)
            continue
        if before:
            detail["class"] = "the program already had errors before the injection"
            detail["printed"] = "; ".join(f"{d['code']} {d['file']}: {d['message'][:140]}" for d in before[:2]) \
                + ("; after the injection also " + "; ".join(f"{d['code']}: {d['message'][:140]}" for d in after[:2]) if after else "")
        elif after:
            detail["class"] = "the injection made another error (the stage no longer compiles as expected)"
            detail["printed"] = "; ".join(f"{d['code']}: {d['message'][:160]}" for d in after[:2])
        else:
            detail["class"] = "formed, no error reported"
            codes = sorted({d["code"] for d in rep.diags if d["file"] in files})
            detail["printed"] = "diagnostics on its files: " + (", ".join(codes) or "none")
        row.inj[k] = ("missed", detail)


# --------------------------------------------------------------------------------------------
# 1. libretro/glsl-shaders

COND = re.compile(r"(?m)^[ \t]*#[ \t]*(if|ifdef|ifndef|elif|else|endif)\b([^\n]*)")


def conditional_sections(text, macro):
    """[(start, end)] of the text of each #if/#elif branch testing `macro` (comment-free text)."""
    events = list(COND.finditer(text))
    spans = []
    tests = re.compile(rf"\bdefined\s*\(?\s*{macro}\b|^\s*{macro}\b")
    for i, m in enumerate(events):
        kind, rest = m.group(1), m.group(2)
        if kind in ("ifdef",) and re.match(rf"\s*{macro}\b", rest) or \
           kind in ("if", "elif") and tests.search(rest):
            depth = 0
            for n in events[i + 1:]:
                if n.group(1) in ("if", "ifdef", "ifndef"):
                    depth += 1
                elif n.group(1) == "endif":
                    if depth == 0:
                        spans.append((m.end(), n.start()))
                        break
                    depth -= 1
                elif depth == 0:
                    spans.append((m.end(), n.start()))
                    break
    return spans


def has_stage_conditional(text, macro):
    return bool(re.search(rf"(?m)^[ \t]*#[ \t]*(?:(?:el)?if\b[^\n]*\bdefined\s*\(?\s*{macro}\b|ifdef\s+{macro}\b)", text))


def libretro(ex, work):
    git_dir = os.path.join(MIRROR_ROOT, "libretro+glsl-shaders", "repo")
    root = os.path.join(work, "libretro-glsl-shaders")
    method, missing = extract(git_dir, root)
    with open(os.path.join(root, "effectc.toml"), "w") as fh:
        fh.write("define = { PARAMETER_UNIFORM = 1 }\n")
    row = Row("effectc.toml: define only")
    files = []
    for d, _, names in os.walk(root):
        for n in names:
            if n.endswith(".glsl"):
                files.append(os.path.relpath(os.path.join(d, n), root))
    texts = {}
    for rel in sorted(files):
        t = blank_comments(read_text(os.path.join(root, rel)))
        if has_stage_conditional(t, "VERTEX") and has_stage_conditional(t, "FRAGMENT"):
            texts[rel] = t
            row.host[frozenset({("vertex", rel), ("fragment", rel)})] = {"fragment": rel}
    row.report = ex.check(root, ["."])
    for key, info in sorted(row.host.items(), key=lambda kv: show_key(kv[0])):
        rel = info["fragment"]
        path = os.path.join(root, rel)
        original = read_text(path)
        clean = texts[rel]
        frag = conditional_sections(clean, "FRAGMENT")
        vert = conditional_sections(clean, "VERTEX")
        frag_text = "".join(clean[a:b] for a, b in frag)
        stage_text = clean
        for a, b in sorted(vert, reverse=True):
            stage_text = stage_text[:a] + " " * (b - a) + stage_text[b:]
        outside_text = stage_text
        for a, b in frag:
            outside_text = outside_text[:a] + " " * (b - a) + outside_text[b:]
        keywords = input_keywords(clean)
        name, kind = pick_input(frag_text, stage_text, keywords, outside_text)
        if name is None:
            outside = declared_inputs(outside_text, keywords)
            if kind == "no user varying input" and outside:
                kind = "inputs declared only outside the FRAGMENT section (shared with the vertex stage)"
            row.inj[key] = ("skip", {"class": kind})
            continue
        new = name + SUFFIX
        patched = original
        for a, b in sorted(frag, reverse=True):
            patched = patched[:a] + rename(name, new, patched[a:b], clean[a:b]) + patched[b:]
        try:
            write_text(path, patched)
            rep = ex.check(root, [rel])
        finally:
            write_text(path, original)
        row.inj_runs += 1
        row.inj_seconds += rep.seconds
        assert read_text(path) == original
        judge_separate(row, rep, rel, [key], name, new, kind)
    meta = [f"mirror {git_dir} HEAD {head_commit(git_dir)}; extracted with {method}"
            + (f"; {len(missing)} blobs missing" if missing else ""),
            f"{len(files)} .glsl files; {len(row.host)} hold a VERTEX and a FRAGMENT conditional",
            "effectc.toml at the root: `define = { PARAMETER_UNIFORM = 1 }` (1 line)",
            "(a)/(b): `effectc check --format json .` at the root; (c): `effectc check --format json FILE` per file"]
    return print_codebase("libretro/glsl-shaders", [row], meta), [row]


# --------------------------------------------------------------------------------------------
# 2. paroj/gltut

C_TOKEN = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|//[^\n]*|/\*.*?\*/', re.S)
SHADER_EXT = {"vert": "vertex", "frag": "fragment", "geom": "geometry"}
GL_STAGE = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry"}
LOADSHADER = re.compile(r'LoadShader\s*\(\s*GL_(VERTEX|GEOMETRY|FRAGMENT)_SHADER\s*,\s*"([^"]+)"\s*\)|CreateProgram\s*\(')


def add_host(hosts, kinds, key, src, kind):
    """Records the host program `key` (a frozenset of (stage, file)), found in `src` by the
    rule `kind`."""
    info = hosts.setdefault(key, {"sources": set(), "fragment": None})
    info["sources"].add(src)
    info["fragment"] = next((p for st, p in key if st == "fragment"), None)
    kinds.setdefault(kind, set()).add(key)


def strip_c(src):
    return C_TOKEN.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)) if m.group(0)[0] == "/" else m.group(0), src)


def literal_groups(text):
    """Shader-name string literals grouped by their innermost enclosing ( ) or { }."""
    groups, stack, i = {}, [], 0
    while i < len(text):
        ch = text[i]
        if ch in "\"'":
            m = C_TOKEN.match(text, i)
            j = m.end() if m else i + 1
            lit = text[i + 1:j - 1] if ch == '"' else ""
            ext = lit.rsplit(".", 1)[-1] if "." in lit else ""
            if ext in SHADER_EXT and re.fullmatch(r"[\w./-]+", lit):
                groups.setdefault(stack[-1] if stack else -1, []).append((SHADER_EXT[ext], lit))
            i = j
            continue
        if ch in "({":
            stack.append(i)
        elif ch in ")}" and stack:
            stack.pop()
        i += 1
    return [groups[k] for k in sorted(groups)]


def pair_group(lits):
    """Each vertex stage with the next fragment stage (and the geometry stage between)."""
    progs, verts, geoms, last = [], [], [], None
    for stage, name in lits:
        if stage == "vertex":
            if last == "fragment":
                verts, geoms = [], []
            verts.append(name)
        elif stage == "geometry":
            geoms = [name]
        elif stage == "fragment":
            for v in verts:
                progs.append([("vertex", v)] + [("geometry", g) for g in geoms] + [("fragment", name)])
        last = stage
    return progs


def gltut_hosts(root):
    hosts, unresolved, kinds = {}, [], {}

    def resolve(tut, name):
        for cand in (os.path.join(tut, "data", name), os.path.join("data", name)):
            if os.path.isfile(os.path.join(root, cand)):
                return os.path.normpath(cand)
        return None

    def add(tut, src, kind, prog):
        key = []
        for stage, name in prog:
            p = resolve(tut, name)
            if p is None:
                unresolved.append(f"{src}: {name}")
                return
            key.append((stage, p))
        add_host(hosts, kinds, frozenset(key), src, kind)

    tuts = sorted(d for d in os.listdir(root) if d.startswith("Tut ") and os.path.isdir(os.path.join(root, d)))
    no_files = []
    for tut in tuts:
        before = len(hosts)
        for fn in sorted(os.listdir(os.path.join(root, tut))):
            if not fn.endswith(".cpp"):
                continue
            src = f"{tut}/{fn}"
            text = strip_c(read_text(os.path.join(root, tut, fn)))
            pending = []
            for m in LOADSHADER.finditer(text):
                if m.group(1):
                    pending.append((GL_STAGE[m.group(1)], m.group(2)))
                elif pending:
                    add(tut, src, "LoadShader(GL_X_SHADER, \"lit\") sequence", pending)
                    pending = []
            masked = LOADSHADER.sub(lambda m: " " * len(m.group(0)) if m.group(1) else m.group(0), text)
            for group in literal_groups(masked):
                for prog in pair_group(group):
                    add(tut, src, "literals in one call or initializer", prog)
            for m in re.finditer(r'Scene\s*\(\s*"([^"]+\.xml)"\s*\)', text):
                xml = resolve(tut, m.group(1))
                if xml is None:
                    unresolved.append(f"{src}: scene {m.group(1)}")
                    continue
                for pm in re.finditer(r"<prog\b([^>]*)>", read_text(os.path.join(root, xml))):
                    attrs = dict(re.findall(r'([\w:-]+)\s*=\s*"([^"]*)"', pm.group(1)))
                    prog = [(st, attrs[a]) for st, a in (("vertex", "vert"), ("geometry", "geom"), ("fragment", "frag")) if a in attrs]
                    add(tut, f"{src} via {xml}", "Framework::Scene XML <prog>", prog)
        if len(hosts) == before:
            no_files.append(tut)
    return hosts, unresolved, kinds, no_files


def gltut_toml(hosts):
    lines = ["# programs as the tutorials' C++ links them (formation_acceptance.py)"]
    for i, key in enumerate(sorted(hosts, key=show_key)):
        stems = "-".join(os.path.basename(p).rsplit(".", 1)[0] for _, p in stage_list(key))
        lines.append("")
        lines.append("[[program]]")
        lines.append(f"name = {json.dumps(f'p{i:03d}-{stems}')}")
        for stage, p in stage_list(key):
            if re.search(r"[*?\[\]{}!\\]", p):
                raise SystemExit(f"glob character in {p}")
            lines.append(f"{stage} = {json.dumps(p)}")
    return "\n".join(lines) + "\n"


def gltut(ex, work):
    git_dir = os.path.join(MIRROR_ROOT, "paroj+gltut", "repo")
    root = os.path.join(work, "gltut")
    method, missing = extract(git_dir, root)
    hosts, unresolved, kinds, no_files = gltut_hosts(root)
    toml = gltut_toml(hosts)
    toml_path = os.path.join(root, "effectc.toml")
    rows = []
    for label, with_toml in ((f"effectc.toml: {len(hosts)} [[program]] ({toml.count(chr(10))} lines)", True),
                             ("no effectc.toml", False)):
        if with_toml:
            with open(toml_path, "w") as fh:
                fh.write(toml)
        elif os.path.exists(toml_path):
            os.remove(toml_path)
        row = Row(label)
        row.host = {k: dict(v) for k, v in hosts.items()}
        row.report = ex.check(root, ["."])
        inject_separate(row, ex, root, ["."])
        rows.append(row)
    if os.path.exists(toml_path):
        os.remove(toml_path)
    shader_files = [os.path.relpath(os.path.join(d, n), root) for d, _, ns in os.walk(root) for n in ns
                    if n.rsplit(".", 1)[-1] in SHADER_EXT]
    meta = [f"mirror {git_dir} HEAD {head_commit(git_dir)}; extracted with {method}"
            + (f"; {len(missing)} blobs missing ({', '.join(missing[:3])})" if missing else ""),
            f"{len(shader_files)} .vert/.frag/.geom files; {len(hosts)} host programs from the tutorials' .cpp: "
            + ", ".join(f"{len(v)} from {k}" for k, v in sorted(kinds.items())) + " (overlapping)",
            f"{sum(1 for k in hosts if len(k) == 3)} host programs with a geometry stage; "
            f"{sum(1 for k in hosts if any(p.startswith('data/') for _, p in k))} use a file of the shared data/ folder",
            "tutorials whose .cpp yield no file-based program: " + (", ".join(no_files) or "none")
            + " (Tut 01 compiles inline strings)",
            "names not resolved: " + ("; ".join(unresolved) or "none"),
            "effectc.toml is written at the root for the first column and removed for the second",
            "(a)/(b) and (c): `effectc check --format json .` at the root (per distinct fragment file for (c))"]
    return print_codebase("paroj/gltut", rows, meta), rows


# --------------------------------------------------------------------------------------------
# 3. McNopper/OpenGL

ARG = r"\s*((?:\([^()]*\)\s*)?&?\s*[\w.]+)\s*"
GLUS = re.compile(
    r'glusFileLoadText\(\s*"([^"]+)"\s*,\s*&\s*(\w+)\s*\)'
    rf"|glusProgram(?:Build|Create)FromSource\(\s*&\s*(\w+)\s*,{ARG},{ARG},{ARG},{ARG},{ARG}\)"
    rf"|glusProgramBuildComputeFromSource\(\s*&\s*(\w+)\s*,{ARG}\)"
    rf"|glusProgramBuildSeparableFromSource\(\s*&\s*(\w+)\s*,\s*GL_(\w+?)_SHADER\s*,{ARG}\)"
    rf"|glusProgramPipelineBuild\(\s*&\s*(\w+)\s*,{ARG},{ARG},{ARG},{ARG},{ARG}\)")
GLUS_ORDER = ["vertex", "tess_control", "tess_eval", "geometry", "fragment"]
GL_STAGES = {"VERTEX": "vertex", "FRAGMENT": "fragment", "GEOMETRY": "geometry",
             "TESS_CONTROL": "tess_control", "TESS_EVALUATION": "tess_eval", "COMPUTE": "compute"}


def var(arg):
    v = re.sub(r"\([^()]*\)|&|\s", "", arg)
    return None if v == "0" else re.sub(r"\.(text|program)$", "", v)


def mcnopper_hosts(root):
    hosts, problems, kinds = {}, [], {}
    for ex_dir in sorted(d for d in os.listdir(root) if re.fullmatch(r"Example\d+", d)):
        src_dir = os.path.join(root, ex_dir, "src")
        if not os.path.isdir(src_dir):
            continue
        for fn in sorted(os.listdir(src_dir)):
            if not fn.endswith((".c", ".cpp")):
                continue
            src = f"{ex_dir}/src/{fn}"
            text = strip_c(read_text(os.path.join(src_dir, fn)))
            loaded, separable = {}, {}

            def add(stages, kind):
                key = []
                for stage, v in stages:
                    p = loaded.get(v)
                    if p is None:
                        problems.append(f"{src}: variable {v} loads no file")
                        return
                    if not os.path.isfile(os.path.join(root, p)):
                        problems.append(f"{src}: {p} not in the tree")
                        return
                    key.append((stage, p))
                add_host(hosts, kinds, frozenset(key), src, kind)

            for m in GLUS.finditer(text):
                g = m.groups()
                if g[0]:
                    loaded[g[1]] = os.path.normpath(os.path.join(ex_dir, g[0]))
                elif g[2]:
                    args = [var(a) for a in g[3:8]]
                    add([(st, a) for st, a in zip(GLUS_ORDER, args) if a], "glusProgramBuild/CreateFromSource")
                elif g[8]:
                    add([("compute", var(g[9]))], "glusProgramBuildComputeFromSource")
                elif g[10]:
                    separable[g[10]] = (GL_STAGES.get(g[11]), var(g[12]))
                else:
                    args = [var(a) for a in g[14:19]]
                    stages = [separable[a] for a in args if a and a in separable]
                    add(stages, "separable programs in glusProgramPipelineBuild")
    return hosts, problems, kinds


def mcnopper(ex, work):
    git_dir = os.path.join(MIRROR_ROOT, "McNopper+OpenGL", "repo")
    root = os.path.join(work, "mcnopper")
    method, missing = extract(git_dir, root)
    hosts, problems, kinds = mcnopper_hosts(root)
    row = Row("no effectc.toml")
    row.host = hosts
    row.report = ex.check(root, ["."])
    inject_separate(row, ex, root, ["."])
    shader_files = [os.path.relpath(os.path.join(d, n), root) for d, _, ns in os.walk(root) for n in ns
                    if re.search(r"\.(vert|frag|geom|cont|eval|comp)\.glsl$", n)]
    miss_ext = {}
    for p in missing:
        e = p.rsplit(".", 1)[-1] if "." in os.path.basename(p) else "(none)"
        miss_ext[e] = miss_ext.get(e, 0) + 1
    meta = [f"mirror {git_dir} HEAD {head_commit(git_dir)}; extracted with {method}"
            + (f"; {len(missing)} blobs missing, none a shader or source file: "
               + ", ".join(f"{n} .{e}" for e, n in sorted(miss_ext.items())) if missing else ""),
            f"{len(shader_files)} *.{{vert,frag,geom,cont,eval,comp}}.glsl files; {len(hosts)} host programs: "
            + ", ".join(f"{len(v)} from {k}" for k, v in sorted(kinds.items())),
            f"{sum(1 for k in hosts if any(st.startswith('tess') for st, _ in k))} host programs with tessellation stages, "
            f"{sum(1 for k in hosts if any(st == 'geometry' for st, _ in k))} with a geometry stage",
            "host code not understood: " + ("; ".join(problems) or "none"),
            "(a)/(b) and (c): `effectc check --format json .` at the root (per distinct fragment file for (c))"]
    return print_codebase("McNopper/OpenGL", [row], meta), [row]


# --------------------------------------------------------------------------------------------

def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    ex = Effectc(sys.argv[1])
    work = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "/tmp/formation")
    os.makedirs(work, exist_ok=True)
    try:
        os.nice(10)
    except OSError:
        pass
    t0 = time.monotonic()
    version = subprocess.run([ex.path, "--version"], capture_output=True, text=True).stdout.strip()
    print(f"# effectc program formation on three codebases\n\n`{ex.path}` ({version}); work dir `{work}`")
    totals = []
    for fn, name in ((libretro, "libretro/glsl-shaders"), (gltut, "paroj/gltut"), (mcnopper, "McNopper/OpenGL")):
        nums, rows = fn(ex, work)
        for n, r in zip(nums, rows):
            totals.append((name, r.label, n))
    cols = ["host programs", "formed programs", "exact matches", "extra formed", "host missed",
            "one-stage formed", "one-stage with N0002", "injected", "caught", "caught, program formed differently",
            "missed", "injected input unread (W0202)", "not injectable"]
    print("\n## Totals\n")
    print("| codebase | configuration | " + " | ".join(cols) + " |")
    print("|---|---|" + "---:|" * len(cols))
    for name, label, n in totals:
        print(f"| {name} | {label} | " + " | ".join(str(n[c]) for c in cols) + " |")
    for title, want_toml in (("TOTAL, gltut with its effectc.toml", True),
                             ("TOTAL, automatic rules only (gltut without effectc.toml)", False)):
        chosen = [n for name, label, n in totals
                  if name != "paroj/gltut" or label.startswith("effectc.toml") == want_toml]
        print(f"| **{title}** | | " + " | ".join(str(sum(n[c] for n in chosen)) for c in cols) + " |")
    print(f"\n{ex.runs} effectc runs, {ex.seconds:.1f} s in effectc; {time.monotonic() - t0:.1f} s in all")
    return 0


if __name__ == "__main__":
    sys.exit(main())
