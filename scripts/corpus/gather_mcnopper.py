#!/usr/bin/env python3
"""Pairs McNopper/OpenGL example programs the way the examples load them (GLUS).

In each ExampleNN/src/*.c, in order: glusFileLoadText("../ExampleNN/shader/x.vert.glsl", &src)
reads the file verbatim into `src`; glusProgramBuildFromSource / glusProgramCreateFromSource
(&prog, vertex, control, evaluation, geometry, fragment), each argument `&src.text` or 0, make a
program; glusProgramBuildSeparableFromSource(&p, GL_X_SHADER, &src.text) one-stage programs
that glusProgramPipelineBuild(&pipe, v.program, 0, 0, g, f.program) puts together. Paths are
relative to the example's directory.
Usage: gather_mcnopper.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, STAGE_NAMES, cpp_ifdefs, graphics_program, strip_cpp_comments, write_program

ORDER = ["vertex", "tess-control", "tess-eval", "geometry", "fragment"]
ARG = r"\s*((?:\([^()]*\)\s*)?&?\s*[\w.]+)\s*"
STMT = re.compile(rf'glusFileLoadText\(\s*"([^"]+)"\s*,\s*&\s*(\w+)\s*\)'
                  rf"|glus(?:Program(?:Build|Create)FromSource|ProgramPipelineBuild)\(\s*&\s*(\w+)\s*,{ARG},{ARG},{ARG},{ARG},{ARG}\)"
                  rf"|glusProgramBuildSeparableFromSource\(\s*&\s*(\w+)\s*,\s*GL_(\w+?)_SHADER\s*,{ARG}\)")


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    written = 0
    for f in m.files:
        if not re.match(r"Example[^/]+/src/[^/]+\.(c|cpp)$", f):
            continue
        example = f.split("/")[0]
        unit = example if f.endswith(("/main.c", "/main.cpp")) else f"{example}.{os.path.basename(f).split('.')[0]}"
        texts, separable, seen = {}, {}, []
        var = lambda a: re.sub(r"\([^()]*\)|&|\s|\.(text|program)$", "", a)
        for s in STMT.finditer(cpp_ifdefs(strip_cpp_comments(m.text(f)))):
            if s.group(1):
                path = os.path.normpath(os.path.join(example, s.group(1)))
                texts[s.group(2)] = (os.path.basename(path).split(".")[0], m.text(path))
            elif s.group(9):
                separable[s.group(9)] = (STAGE_NAMES.get(s.group(10)), texts.get(var(s.group(11))))
            else:
                args = [var(a) for a in s.group(4, 5, 6, 7, 8)]
                if s.group(0).startswith("glusProgramPipeline"):
                    shaders = [(st,) + (separable.get(a) or (None, (None, None)))[1] for st, a in zip(ORDER, args) if a != "0"]
                else:
                    shaders = [(st,) + texts.get(a, (None, None)) for st, a in zip(ORDER, args) if a != "0"]
                if not graphics_program([(st, t) for st, _, t in shaders]) or shaders in seen:
                    continue
                seen.append(shaders)
                write_program(out, "mcnopper", f"{unit}.{s.group(3)}", shaders)
                written += 1
    print(written, "programs")


if __name__ == "__main__":
    main()
