#!/usr/bin/env python3
"""glslang's own link tests as a corpus of link groups, with glslang's verdicts.

Usage: gather_glslang_link.py MIRROR_GIT_DIR OUT_DIR

Reads, at HEAD of a bare mirror of KhronosGroup/glslang:
  - gtests/Link.FromFile.cpp       (OpenGL semantics, AST)          suite `Link`
  - gtests/Link.FromFile.Vk.cpp    (Vulkan semantics, auto-map loc) suite `LinkVk`
  - gtests/GlslMapIO.FromFile.cpp  (per-entry Semantics::OpenGL/Vulkan, SPIR-V, auto-map)
  - gtests/VkRelaxed.FromFile.cpp  (Vulkan relaxed rules)           suite `VkRelaxed`
  - Test/runtests                  (standalone `run` lines naming more than one stage file)
and writes one directory per link group, `OUT_DIR/<suite>__<first file or result name>/`, with
  - the stage files under their original names (glslang takes the stage from the last suffix),
  - EXPECTED   `accept` or `reject`: reject when glslang's expected output
               (Test/baseResults/<first file>.out, or the runtests redirect target) holds an
               `ERROR:` line (compile or link error), else accept,
  - ENV        `opengl` or `vulkan` (the semantics the test links under),
  - MULTIUNIT  `yes` when some stage has more than one compilation unit, else `no`,
  - FLAGS      glslangValidator options reproducing the test's semantics (files appended),
  - SOURCE     where the group comes from, and REASON: the baseResults `ERROR:` lines.
"""
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, safe_name  # noqa: E402

SHADER_EXT = ("vert", "frag", "geom", "tesc", "tese", "comp", "mesh", "task",
              "rgen", "rint", "rahit", "rchit", "rmiss", "rcall")
FILE_RE = re.compile(r'"([^"]+\.(?:%s))"' % "|".join(SHADER_EXT))


def suffix(name):
    return name.rsplit(".", 1)[-1]


def instantiate_body(text):
    """The argument text of INSTANTIATE_TEST_SUITE_P(...)."""
    i = text.index("INSTANTIATE_TEST_SUITE_P")
    start = text.index("(", i)
    depth = 0
    for j in range(start, len(text)):
        if text[j] == "(":
            depth += 1
        elif text[j] == ")":
            depth -= 1
            if depth == 0:
                return text[start + 1:j]
    raise ValueError("unbalanced INSTANTIATE_TEST_SUITE_P")


def innermost_lists(body):
    """(list_text, following_text) for each innermost `{...}` holding shader file names."""
    out = []
    for m in re.finditer(r"\{([^{}]*)\}", body):
        files = FILE_RE.findall(m.group(1))
        if files:
            out.append((files, body[m.end():m.end() + 80]))
    return out


def gtest_groups(mirror, path, suite, env, flags, per_entry_semantics=False):
    body = instantiate_body(mirror.text(path))
    groups = []
    for files, after in innermost_lists(body):
        e, f = env, flags
        if per_entry_semantics:
            m = re.match(r"\s*,\s*Semantics::(\w+)", after)
            sem = m.group(1) if m else "OpenGL"
            e = "vulkan" if sem == "Vulkan" else "opengl"
            f = "-V --aml --amb -l" if e == "vulkan" else "-G --aml --amb -l"
        extra = ""
        if suite == "VkRelaxed":
            m = re.match(r"\s*,\s*\{(.*?)\}\s*\}", after, re.S)
            sets = re.findall(r'\{\s*"(\w+)"\s*\}', m.group(1)) if m else []
            if sets and len(sets) == len(files):
                extra = " " + " ".join(f"--rsb {suffix(n)} {s}" for n, s in zip(files, sets))
        groups.append({
            "suite": suite, "name": files[0], "files": files, "env": e, "flags": f + extra,
            "result": f"Test/baseResults/{files[0]}.out", "source": f"{path}",
        })
    return groups


def runtests_groups(mirror):
    """`run` lines of Test/runtests that name two or more stage files."""
    text = mirror.text("Test/runtests")
    text = re.sub(r"\\\n", " ", text)
    groups = []
    seen = set()
    for line in text.splitlines():
        line = line.strip()
        m = re.match(r'run\s+(.*?)>\s*"?\$TARGETDIR/([^"\s]+)"?', line)
        if not m:
            continue
        args, outname = m.group(1).split(), m.group(2)
        files = [a for a in args if not a.startswith("-") and re.fullmatch(r"[\w.-]+\.(%s)" % "|".join(SHADER_EXT), a)]
        if len(files) < 2:
            continue
        key = tuple(files)
        if key in seen:  # reflection.linked twice: plain and with reflection options
            continue
        seen.add(key)
        opts = [a for a in args if a not in files]
        env = "vulkan" if any(o == "-V" or o.startswith("-V1") or o == "--target-env" and "vulkan" in line
                              for o in opts) else "opengl"
        if "-l" not in opts:
            opts.append("-l")
        groups.append({
            "suite": "runtests", "name": re.sub(r"\.out$", "", outname), "files": files, "env": env,
            "flags": " ".join(opts), "result": f"Test/baseResults/{outname}", "source": "Test/runtests",
        })
    return groups


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: gather_glslang_link.py MIRROR_GIT_DIR OUT_DIR")
    mirror = Mirror(sys.argv[1])
    out = sys.argv[2]
    groups = []
    groups += gtest_groups(mirror, "gtests/Link.FromFile.cpp", "Link", "opengl", "-l")
    groups += gtest_groups(mirror, "gtests/Link.FromFile.Vk.cpp", "LinkVk", "vulkan", "-V --aml -l")
    groups += gtest_groups(mirror, "gtests/GlslMapIO.FromFile.cpp", "GlslMapIO", None, None,
                           per_entry_semantics=True)
    groups += gtest_groups(mirror, "gtests/VkRelaxed.FromFile.cpp", "VkRelaxed", "vulkan",
                           "-V -R --aml --amb -l")
    groups += runtests_groups(mirror)

    if os.path.isdir(out):
        for d in os.listdir(out):
            if "__" in d:
                shutil.rmtree(os.path.join(out, d))
    os.makedirs(out, exist_ok=True)
    counts = {}
    for g in groups:
        result = mirror.text(g["result"])
        if result is None:
            print(f"skip {g['suite']} {g['name']}: no {g['result']}", file=sys.stderr)
            continue
        missing = [f for f in g["files"] if not mirror.exists(f"Test/{f}")]
        if missing:
            print(f"skip {g['suite']} {g['name']}: missing {missing}", file=sys.stderr)
            continue
        errors = [ln for ln in result.splitlines() if "ERROR:" in ln]
        expected = "reject" if errors else "accept"
        stages = [suffix(f) for f in g["files"]]
        multi = "yes" if len(set(stages)) < len(stages) else "no"
        d = os.path.join(out, f"{g['suite']}__{safe_name(g['name'])}")
        os.makedirs(d, exist_ok=True)
        for f in g["files"]:
            with open(os.path.join(d, f), "wb") as fh:
                fh.write(mirror.show(f"Test/{f}"))
        for fname, value in (("EXPECTED", expected), ("ENV", g["env"]), ("MULTIUNIT", multi),
                             ("FLAGS", g["flags"]),
                             ("SOURCE", f"{g['source']}: {' '.join(g['files'])} -> {g['result']}"),
                             ("REASON", "\n".join(errors))):
            with open(os.path.join(d, fname), "w") as fh:
                fh.write(value + "\n")
        with open(os.path.join(d, "FILES"), "w") as fh:
            fh.write("\n".join(g["files"]) + "\n")
        k = (g["env"], multi, expected)
        counts[k] = counts.get(k, 0) + 1
    for (env, multi, expected), n in sorted(counts.items()):
        print(f"{env:7} multi-unit={multi:3} {expected:7} {n}")
    print(f"{sum(counts.values())} groups in {out}")


if __name__ == "__main__":
    main()
