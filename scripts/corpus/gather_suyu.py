#!/usr/bin/env python3
"""yuzu-family host shaders (src/video_core/host_shaders), read from the suyu-emu/suyu mirror
(yuzu upstream is gone; suyu master e344682 of 2024-07-02 keeps yuzu's host_shaders tree), OpenGL
and Vulkan, paired as the two renderers load them.

Build (host_shaders/CMakeLists.txt): every SHADER_FILES file not matching `vulkan.*` becomes the
string `HostShaders::<NAME>` through StringShaderHeader.cmake (`;` masked, each line of the CMake
list `"\\n"`-split text wrapped as `R"(<line>\\n)"`, so the text is the file plus one `\\n`; a
backslash-newline becomes an escaped list separator, `\\;` -> `;`, which joins the two lines with
a `;`), and the FidelityFX ffx_a.h / ffx_fsr1.h headers the same way; every file not matching
`opengl.*` is compiled on its own by `glslangValidator -V --quiet -I<externals/FidelityFX-FSR/ffx-fsr>
... --target-env spirv1.3` (glslang predefines VULKAN, so the `#ifdef VULKAN` branches and their
BINDING_* values are taken).

OpenGL (written to GL_OUT_DIR): OpenGL::CreateProgram(code, stage) compiles the one string as is
and links it alone as a GL_PROGRAM_SEPARABLE program; the programs are bound together in program
pipelines. A vertex and a fragment program are written as one program directory (the pipeline the
renderer binds): blit_image.cpp / present/fxaa.cpp (their vertex CreateProgram with each
fragment one), present/smaa.cpp's SmaaShader pairs (ReplaceInclude of `#include
"opengl_smaa.glsl"`, first occurrence), present/fsr.cpp's full-screen vertex with the easu and
rcas fragments (its `std::string v{HostShaders::X}` / ReplaceInclude sequence followed),
window_adapt_pass.cpp's OPENGL_PRESENT_VERT with each present/filters.cpp fragment (scaleforce
with its `fmt::format("#version 460\\n{}", ..)` prefix); the compute programs of util_shaders.cpp
MakeProgram and gl_shader_manager.cpp stand alone.

Vulkan (written to VK_OUT_DIR, FLAGS `-V --target-env spirv1.3 -l`): the stage files as
glslangValidator reads them, `#include "x"` inlined as its DirStackFileIncluder resolves it (the
includer's directory, then -I) between `#line 1 "x"` / `#line N "includer"`. Pairs:
blit_image.cpp's `MakeStages(*a, *b)` over its `m(BuildShader(device, X_SPV))` members, the
non-member MakeStages(*full_screen_vert, frag) (ConvertPipeline*) with every fragment member no
literal pair uses; window_adapt_pass.cpp's vertex with each present/filters.cpp fragment;
present/fsr.cpp's vertex with each fragment; present/fxaa.cpp's pair; present/smaa.cpp's
vert/frag ARRAY_TO_SPAN lists by index. Every compiled .comp is a compute program (those
vk_compute_pass.cpp / vk_turbo_mode.cpp do not load are compiled by the build all the same).
Usage: gather_suyu.py MIRROR_GIT_DIR VK_OUT_DIR GL_OUT_DIR
"""
import os
import posixpath
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from granite_common import GitTree  # noqa: E402
from mirror import write_program, strip_cpp_comments, c_string  # noqa: E402
from gather_citra import cmake_list_split  # noqa: E402

HS = "src/video_core/host_shaders/"
GL = "src/video_core/renderer_opengl/"
VK = "src/video_core/renderer_vulkan/"
EXT_STAGE = {"vert": "vertex", "frag": "fragment", "comp": "compute", "geom": "geometry"}
INC = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"')
VK_FLAGS = "-V --target-env spirv1.3 -l\n"


def embedded(text):
    """The string StringShaderHeader.cmake makes of a file (raw-string lines)."""
    text = text.replace(";", "{{SEMICOLON}}").replace("\n", ";")
    return "".join(line + "\n" for line in cmake_list_split(text, keep_empty=True)).replace("{{SEMICOLON}}", ";")


def replace_include(src, name, content):
    key = f'#include "{name}"'
    pos = src.find(key)
    assert pos >= 0, key
    return src[:pos] + content + src[pos + len(key):]


def main():
    git_dir, vk_out, gl_out = sys.argv[1:4]
    tree = GitTree(git_dir)
    cm = re.sub(r"#[^\n]*", "", tree.text(HS + "CMakeLists.txt"))
    files = re.search(r"set\(\s*SHADER_FILES\s+([^)]*)\)", cm).group(1).split()
    ffx_dir = re.search(r"set\(\s*FIDELITYFX_INCLUDE_DIR\s+\$\{CMAKE_SOURCE_DIR\}/(\S+)\s*\)", cm).group(1)
    ffx = re.search(r"set\(\s*FIDELITYFX_FILES\s+([^)]*)\)", cm).group(1).split()
    stage_of, gl_text, path_of = {}, {}, {}
    for f in files:
        name = f.replace(".", "_").upper()
        stage_of[name] = EXT_STAGE.get(f.rsplit(".", 1)[1])
        path_of[name] = HS + f
        if not f.startswith("vulkan"):
            gl_text[name] = embedded(tree.text(HS + f))
    for f in ffx:
        base = posixpath.basename(f)
        gl_text[base.replace(".", "_").upper()] = embedded(tree.text(ffx_dir + "/" + base))

    def src(path):
        return strip_cpp_comments(tree.text(path))

    def stem(name):
        return name.lower().rsplit("_", 1)[0]

    # ---- OpenGL
    gl_programs = []  # (program name, [(stage, stem, text)])

    def gl_create(text, var_text):
        m = re.fullmatch(r"\s*HostShaders::(\w+)\s*", text)
        if m:
            return m.group(1), gl_text[m.group(1)]
        return None, var_text[text.strip()]

    for f in ("blit_image.cpp", "present/fxaa.cpp"):
        s = src(GL + f)
        verts = re.findall(r"CreateProgram\(\s*HostShaders::(\w+)\s*,\s*GL_VERTEX_SHADER\s*\)", s)
        frags = re.findall(r"CreateProgram\(\s*HostShaders::(\w+)\s*,\s*GL_FRAGMENT_SHADER\s*\)", s)
        for v in verts:
            for fr in frags:
                gl_programs.append((stem(v) + "+" + stem(fr), [("vertex", stem(v), gl_text[v]),
                                                               ("fragment", stem(fr), gl_text[fr])]))
    s = src(GL + "present/smaa.cpp")
    incs = re.findall(r'ReplaceInclude\(\s*shader_source\s*,\s*"([^"]+)"\s*,\s*HostShaders::(\w+)\s*\)', s)
    calls = re.findall(r"SmaaShader\(\s*HostShaders::(\w+)\s*,\s*GL_(VERTEX|FRAGMENT)_SHADER\s*\)", s)

    def smaa(name):
        t = gl_text[name]
        for inc, what in incs:
            t = replace_include(t, inc, gl_text[what])
        return t
    pending = None
    for name, st in calls:
        if st == "VERTEX":
            pending = name
        elif pending:
            gl_programs.append((stem(pending) + "+" + stem(name), [("vertex", stem(pending), smaa(pending)),
                                                                   ("fragment", stem(name), smaa(name))]))
            pending = None
    s = src(GL + "present/fsr.cpp")
    body = re.search(r"FSR::FSR\([^)]*\)[^{]*\{(.*?)\n\}", s, re.S).group(1)
    var = {}
    vert, frags = None, []
    for m in re.finditer(r"std::string\s+(\w+)\{HostShaders::(\w+)\}|"
                         r"ReplaceInclude\(\s*(\w+)\s*,\s*\"([^\"]+)\"\s*,\s*([\w:]+)\s*\)|"
                         r"CreateProgram\(\s*([\w:]+)\s*,\s*GL_(VERTEX|FRAGMENT)_SHADER\s*\)", body):
        if m.group(1):
            var[m.group(1)] = (stem(m.group(2)), gl_text[m.group(2)])
        elif m.group(3):
            w = m.group(5)
            content = gl_text[w.split("::")[1]] if w.startswith("HostShaders::") else var[w][1]
            var[m.group(3)] = (var[m.group(3)][0], replace_include(var[m.group(3)][1], m.group(4), content))
        else:
            w = m.group(6)
            entry = (stem(w.split("::")[1]), gl_text[w.split("::")[1]]) if w.startswith("HostShaders::") else var[w]
            if m.group(7) == "VERTEX":
                vert = entry
            else:
                frags.append(entry)
    for fr in frags:
        gl_programs.append((vert[0] + "+" + fr[0], [("vertex", vert[0], vert[1]), ("fragment", fr[0], fr[1])]))
    s = src(GL + "present/window_adapt_pass.cpp")
    v = re.search(r"CreateProgram\(\s*HostShaders::(\w+)\s*,\s*GL_VERTEX_SHADER\s*\)", s).group(1)
    s = src(GL + "present/filters.cpp")
    seen = set()
    for m in re.finditer(r"make_unique<WindowAdaptPass>\((.*?)\)\s*;", s, re.S):
        args = m.group(1)
        fm = re.search(r"fmt::format\(\s*(\"(?:\\.|[^\"\\])*\")\s*,\s*HostShaders::(\w+)\s*\)", args)
        if fm:
            prefix = c_string(fm.group(1))
            assert prefix.endswith("{}")
            name, text = fm.group(2), prefix[:-2] + gl_text[fm.group(2)]
        else:
            name = re.findall(r"HostShaders::(\w+)", args)[-1]
            text = gl_text[name]
        if name in seen:
            continue
        seen.add(name)
        gl_programs.append((stem(v) + "+" + stem(name), [("vertex", stem(v), gl_text[v]),
                                                         ("fragment", stem(name), text)]))
    comps = re.findall(r"MakeProgram\(\s*(\w+)\s*\)", src(GL + "util_shaders.cpp"))
    comps += re.findall(r"CreateProgram\(\s*HostShaders::(\w+)\s*,\s*GL_COMPUTE_SHADER\s*\)",
                        src(GL + "gl_shader_manager.cpp"))
    for c in dict.fromkeys(c for c in comps if c in gl_text):
        gl_programs.append((stem(c), [("compute", stem(c), gl_text[c])]))
    for name, stages in gl_programs:
        write_program(gl_out, "suyu", name, stages)

    # ---- Vulkan
    inc_dirs = [ffx_dir]

    def expand(path, stack=(), depth=0):
        text = tree.text(path)
        dirs = list(stack) + [posixpath.dirname(path)]
        out = []
        for no, line in enumerate(text.split("\n"), start=1):
            m = INC.match(line)
            found = None
            if m and depth < 32:
                for d in list(reversed(dirs)) + list(reversed(inc_dirs)):
                    cand = posixpath.normpath(posixpath.join(d, m.group(1)))
                    if tree.text(cand) is not None:
                        found = cand
                        break
            if not found:
                out.append(line)
                continue
            body = expand(found, dirs, depth + 1)
            out.append(f'#line 1 "{found}"\n{body}\n#line {no + 1} "{path}"')
        return "\n".join(out)

    vk_names = [n for n in stage_of if not path_of[n].split("/")[-1].startswith("opengl")]

    def vk_stage(name):
        return (stage_of[name], stem(name), expand(path_of[name]))

    vk_programs = []
    s = src(VK + "blit_image.cpp")
    members = {m.group(1): m.group(2) for m in re.finditer(r"(\w+)\(BuildShader\(\s*device\s*,\s*(\w+)_SPV\s*\)\)", s)}
    used, loose_verts = set(), []
    for m in re.finditer(r"MakeStages\(\s*\*?(\w+)\s*,\s*(\*?)(\w+)\s*\)", s):
        a, b = m.group(1), m.group(3)
        if m.group(2) and b in members:
            vk_programs.append([members[a], members[b]])
            used.add(b)
        elif a in members:
            loose_verts.append(members[a])
    for a in dict.fromkeys(loose_verts):
        for b, spv in members.items():
            if b not in used and stage_of.get(spv) == "fragment":
                vk_programs.append([a, spv])
    v = re.search(r"BuildShader\(\s*device\s*,\s*(\w+)_SPV\s*\)", src(VK + "present/window_adapt_pass.cpp")).group(1)
    for f in dict.fromkeys(re.findall(r"BuildShader\(\s*device\s*,\s*(\w+)_SPV\s*\)", src(VK + "present/filters.cpp"))):
        vk_programs.append([v, f])
    fsr = re.findall(r"BuildShader\(\s*m_device\s*,\s*(\w+)_SPV\s*\)", src(VK + "present/fsr.cpp"))
    for f in fsr:
        if stage_of[f] == "fragment":
            vk_programs.append([n for n in fsr if stage_of[n] == "vertex"][:1] + [f])
    fx = re.findall(r"CreateWrappedShaderModule\(\s*m_device\s*,\s*(\w+)_SPV\s*\)", src(VK + "present/fxaa.cpp"))
    vk_programs.append(fx)
    s = src(VK + "present/smaa.cpp")
    vl = re.findall(r"ARRAY_TO_SPAN\((\w+_VERT)_SPV\)", s)
    fl = re.findall(r"ARRAY_TO_SPAN\((\w+_FRAG)_SPV\)", s)
    vk_programs += [[a, b] for a, b in zip(vl, fl)]
    vk_programs += [[n] for n in vk_names if stage_of[n] == "compute"]
    for prog in vk_programs:
        d = write_program(vk_out, "suyu", "+".join(stem(n) for n in prog), [vk_stage(n) for n in prog])
        with open(os.path.join(d, "FLAGS"), "w") as fh:
            fh.write(VK_FLAGS)
    print(len(gl_programs), "OpenGL programs,", len(vk_programs), "Vulkan programs")


main()
