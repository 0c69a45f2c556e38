"""Shared helper of the Vulkan post-processing gatherers (gather_vkbasalt.py, gather_gamescope.py,
...): `#include "x"` inlined as glslangValidator's DirStackFileIncluder resolves it.

Resolution order: the includer's directory, then the directories of the files that included it
(innermost first), then the -I directories (last to first). The inlined text is what glslang's
preprocessor sees: `#line 1 "<path>"`, the file (expanded the same way), `#line <next>
"<includer>"`. Lines inside a /* */ comment are left alone; an include that cannot be found is
left for the checker to report. No shader text lives here: it is read from the mirror at run time.
"""
import posixpath
import re

INC = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"')


def _in_comment_states(lines):
    """For each line, whether it starts inside a /* */ comment."""
    states, inside = [], False
    for line in lines:
        states.append(inside)
        i = 0
        while i < len(line):
            if inside:
                j = line.find("*/", i)
                if j < 0:
                    break
                inside, i = False, j + 2
            else:
                k = line.find("/*", i)
                s = line.find("//", i)
                if k < 0 or (0 <= s < k):
                    break
                inside, i = True, k + 2
    return states


def expand(mirror, root, path, ext_dirs=(), stack=(), depth=0):
    """The text of `root`/`path` (paths relative to `root`) with its includes inlined."""
    text = mirror.text(posixpath.join(root, path))
    dirs = list(stack) + [posixpath.dirname(path)]
    lines = text.split("\n")
    out = []
    for no, (line, commented) in enumerate(zip(lines, _in_comment_states(lines)), start=1):
        m = None if commented else INC.match(line)
        found = None
        if m and depth < 32:
            for d in list(reversed(dirs)) + list(reversed(list(ext_dirs))):
                cand = posixpath.normpath(posixpath.join(d, m.group(1)))
                if mirror.exists(posixpath.normpath(posixpath.join(root, cand))):
                    found = cand
                    break
        if not found:
            out.append(line)
            continue
        body = expand(mirror, root, found, ext_dirs, dirs, depth + 1)
        out.append(f'#line 1 "{found}"\n{body}\n#line {no + 1} "{path}"')
    return "\n".join(out)


def write_flags(d, flags):
    with open(posixpath.join(d, "FLAGS"), "w") as fh:
        fh.write(flags + "\n")
