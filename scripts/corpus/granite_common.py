"""Themaister/Granite's GLSL front end (compiler/compiler.cpp), shared by gather_granite.py and
gather_parallel_rdp.py.

GLSLCompiler::preprocess -> parse_variants, line by line: text after `//` is dropped; a line
containing `#include "x"` becomes `#line 1 "<path>"`, the included file (handled the same way,
every time it is included: no once-only), `#line <next> "<includer>"`; the include is looked up
relative to the including file (Path::relpath), then in each include directory; `#pragma
optimize on|off` becomes a `// #pragma ...` comment, other `#pragma X` lines `// #pragma X`
(collected); a line `#endif` (alone) is followed by `#line <next> "<file>"`. GLSLCompiler::compile
hands the result to shaderc with the variant defines (AddMacroDefinition name, value) and then
`STAGE_<VERTEX|FRAGMENT|COMPUTE> 1`; shaderc puts these in glslang's preamble together with
`#extension GL_GOOGLE_include_directive : enable` (which makes `#line N "file"` legal), so they are
written after the #version line, in that order. Target: shaderc vulkan1.1/SPIR-V 1.3, or
vulkan1.3/SPIR-V 1.6 for Target::Vulkan13 (ShaderManager on a Vulkan 1.3 device).

Paths use Granite's protocols: `builtin://x` is Granite's assets/x, other protocols are mapped
by the caller's `resolve(path) -> (git tree, repo path)`.
"""
import posixpath
import re
import subprocess

STAGE_DEFINE = {"vertex": "STAGE_VERTEX", "fragment": "STAGE_FRAGMENT", "compute": "STAGE_COMPUTE"}
EXT_STAGE = {"vert": "vertex", "frag": "fragment", "comp": "compute"}


class GitTree:
    """Files of a bare git directory at one commit (default HEAD)."""

    def __init__(self, git_dir, commit="HEAD"):
        self.git_dir, self.commit = git_dir, commit
        out = subprocess.run(["git", f"--git-dir={git_dir}", "ls-tree", "-r", "--name-only", commit],
                             capture_output=True, text=True, check=True).stdout
        self.files = out.splitlines()
        self._set = set(self.files)
        self._cache = {}

    def text(self, path):
        if path not in self._set:
            return None
        if path not in self._cache:
            self._cache[path] = subprocess.run(
                ["git", f"--git-dir={self.git_dir}", "show", f"{self.commit}:{path}"],
                capture_output=True, check=True).stdout.decode("utf-8", "replace")
        return self._cache[path]


def relpath(base, rel):
    """Path::relpath: rel joined to base's directory (protocol kept), unless rel has a protocol."""
    if "://" in rel:
        return rel
    proto, sep, p = base.rpartition("://")
    joined = posixpath.normpath(posixpath.join(posixpath.dirname(p), rel))
    return f"{proto}{sep}{joined}"


def join(d, rel):
    proto, sep, p = d.rpartition("://")
    return f"{proto}{sep}{posixpath.normpath(posixpath.join(p, rel))}"


class GraniteCompiler:
    def __init__(self, resolve, include_dirs=()):
        self.resolve, self.include_dirs = resolve, list(include_dirs)

    def load(self, path):
        tree, repo_path = self.resolve(path)
        return None if tree is None else tree.text(repo_path)

    def find_include(self, src_path, inc):
        cand = relpath(src_path, inc)
        text = self.load(cand)
        if text is not None:
            return cand, text
        for d in self.include_dirs:
            cand = join(d, inc)
            text = self.load(cand)
            if text is not None:
                return cand, text
        raise KeyError(f"include {inc!r} from {src_path}")

    def parse(self, text, path):
        out = []
        for idx, line in enumerate(text.split("\n"), start=1):
            k = line.find("//")
            if k >= 0:
                line = line[:k]
            k = line.find('#include "')
            if k >= 0:
                inc = line[k + 10:]
                if inc.endswith('"'):
                    inc = inc[:-1]
                inc_path, inc_text = self.find_include(path, inc)
                out.append(f'#line 1 "{inc_path}"\n')
                out.append(self.parse(inc_text, inc_path))
                out.append(f'#line {idx + 1} "{path}"\n')
            elif line.startswith("#pragma optimize off") or line.startswith("#pragma optimize on"):
                out.append("// " + line.strip() + "\n")
            elif line.startswith("#pragma stage "):
                raise ValueError("multi-stage source")
            elif line.startswith("#pragma "):
                out.append("// " + line + "\n")
            else:
                out.append(line + "\n")
                s = line.lstrip(" ")
                if s.startswith("#") and s[1:].split(" ") == ["endif"]:
                    out.append(f'#line {idx + 1} "{path}"\n')
        return "".join(out)

    def stage_text(self, path, stage, defines=()):
        """The text shaderc compiles for `path` as `stage` with (name, int) defines."""
        body = self.parse(self.load(path), path)
        pre = "#extension GL_GOOGLE_include_directive : enable\n"
        pre += "".join(f"#define {n} {v}\n" for n, v in defines)
        pre += f"#define {STAGE_DEFINE[stage]} 1\n"
        v = re.search(r"^[ \t]*#version[^\n]*\n", body, re.M)
        return body[:v.end()] + pre + body[v.end():] if v else pre + body
