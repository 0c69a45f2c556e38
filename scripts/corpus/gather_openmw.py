#!/usr/bin/env python3
"""OpenMW/openmw: the programs Shader::ShaderManager builds from files/shaders/, with its
@-template system resolved as components/shader/shadermanager.cpp does it.

Loading (ShaderManager::getShaderInternal / getProgram):
- a template name without a `lib`/`compatibility`/`core` prefix gets `compatibility/`;
  `getProgram("x", defines)` is x.vert + x.frag with the same define map;
- the template text: addLineDirectivesAfterConditionalBlocks (a `#line N` after every line
  holding #endif/#elif/#else), then parseIncludes (every `#include "f"` - the first one in the
  text each time, comments included - replaced by `#line 0 K` + the include's own processed
  text + `\\n#line N 0`; a name without a root prefix is relative to the includer's directory);
- per define map: parseDefines (`@name` replaced by the call's define, else the global define;
  `@foreach`/`@endforeach`/`@link`/iterators become `$`), then parseDirectives (`$foreach it
  list` ... `$endforeach` unrolled plus `#line N`; `$link "f" [if [!]cond]` line removed and f
  compiled with the same defines and the linker's stage, attached to the program - one level);
- OSG passes the text unchanged (no #pragma import_defines define is set by default, no vertex
  attribute aliasing). The shaders carry their own #version (120; 330/430 compatibility in
  lib/core; 430/440 core compute).

Programs (each with two global define sets, de-duplicated by text):
- "default": Shader::getDefaultDefines, ShadowManager::getShadowsDisabledDefines, the light
  defines (per-object lighting, `max lights` from settings-default.cfg) and the settings-derived
  globals of RenderingManager (settings-default.cfg values, reverse z on, post-processing's
  distorionRTRatio);
- "shadows_clustered": shadows on (`number of shadow maps` splits, perspective shadow maps,
  normal offset, distance limit from settings) and clustered lighting (lighting_*.glsl 4.30 links).
ShaderVisitor materials (prefixes objects, groundcover, bs/default, bs/nolighting from
nifloader) with texture/alpha profiles built as ShaderVisitor::createProgram fills its define
map (the `<map>UV` define is the texture unit: Morrowind-style sets on units 0..7 for objects
and groundcover, the diffuse/normal/glow BSShaderTextureSet on units 0..2 for bs/default); terrain (material.cpp: three layer profiles) and terrain_composite (blendMap 0/1);
water (refraction 0/1, water settings); sky; depthclipped; globalmap; debug; gui; outline
(OpenCS); fullscreen_tri; multiview_resolve; LuminanceCalculator's and RipplesSurface's
fullscreen_tri.vert + fragment pairs; the ripple compute shaders; MWShadowTechnique's
shadowcasting program per alpha function (GL_NEVER..GL_ALWAYS); the clustered-lighting compute
shaders (cluster.comp, cull.comp) with the second global set. core/gui.* has no caller.
Usage: gather_openmw.py MIRROR_GIT_DIR OUT_DIR
"""
import os, posixpath, re, struct, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
ROOT = "files/shaders/"
DELIMS = " \n\r()[].;,"
NPOS = -1


class TemplateError(Exception):
    pass


def find_first_of(s, chars, pos=0):
    for i in range(max(pos, 0), len(s)):
        if s[i] in chars:
            return i
    return NPOS


def find_first_not_of(s, chars, pos=0):
    if pos < 0:
        return NPOS
    for i in range(pos, len(s)):
        if s[i] not in chars:
            return i
    return NPOS


def root_prefix(path):
    for p in ("lib", "compatibility", "core"):
        if path.startswith(p):
            return p
    return ""


def get_line_number(source, found, line_number, offset):
    tag = "#line"
    pos = source.rfind(tag, 0, found + len(tag))  # std::string::rfind(tag, found)
    if pos != NPOS:
        start = pos + len(tag) + 1
        end = find_first_not_of(source, "0123456789", start)
        digits = source[start:] if end == NPOS else source[start:end]
        line_number = (int(digits) if digits else 2) + offset
    else:
        pos = 0
    return line_number + source.count("\n", pos, found)


def add_line_directives(source):
    position = 0
    while position < len(source):
        cands = [p for p in (source.find("#endif", position), source.find("#elif", position),
                             source.find("#else", position)) if p != NPOS]
        if not cands:
            break
        found = find_first_of(source, "\n\r", min(cands))
        found = find_first_not_of(source, "\n\r", found)
        if found == NPOS:
            break
        n = get_line_number(source, found, 1, -1)
        source = source[:found] + f"#line {n}\n" + source[found:]
        position = found
    return source


def parse_includes(source, file_name, counter, cycle):
    if file_name in cycle:
        raise TemplateError("cyclic include " + file_name)
    cycle = cycle | {file_name}
    source = source.replace("\r\n", "\n")
    while True:
        found = source.find("#include")
        if found == NPOS:
            break
        start = source.find('"', found)
        if start == NPOS or start == len(source) - 1:
            raise TemplateError("invalid #include")
        end = source.find('"', start + 1)
        if end == NPOS:
            raise TemplateError("invalid #include")
        inc = source[start + 1:end]
        if not root_prefix(inc):
            inc = posixpath.join(posixpath.dirname(file_name), inc)
        line_number = get_line_number(source, found, 0, -1)
        text = m.text(posixpath.normpath(ROOT + inc))
        if text is None:
            raise TemplateError("missing include " + inc)
        number = counter[0]
        counter[0] += 1
        text = parse_includes(add_line_directives(text), inc, counter, cycle)
        source = source[:found] + f"#line 0 {number}\n{text}\n#line {line_number} 0\n" + source[end + 1:]
    return source


_templates = {}


def template(name):
    if name not in _templates:
        text = m.text(ROOT + name)
        if text is None:
            raise TemplateError("missing template " + name)
        _templates[name] = parse_includes(add_line_directives(text), name, [1], set())
    return _templates[name]


def parse_defines(source, defines, globals_):
    iters = []
    while True:
        found = source.find("@")
        if found == NPOS:
            return source
        end = find_first_of(source, DELIMS, found)
        if end == NPOS:
            raise TemplateError("unexpected EOF")
        name = source[found + 1:end]
        if name == "foreach":
            source = source[:found] + "$" + source[found + 1:]
            s = end + 1
            e = find_first_of(source, DELIMS, s)
            if e == NPOS:
                raise TemplateError("unexpected EOF")
            iters.append(source[s:e])
        elif name == "endforeach":
            source = source[:found] + "$" + source[found + 1:]
            if not iters:
                raise TemplateError("endforeach without foreach")
            iters.pop()
        elif name == "link" or name in iters:
            source = source[:found] + "$" + source[found + 1:]
        elif name in defines:
            source = source[:found] + defines[name] + source[end:]
        elif name in globals_:
            source = source[:found] + globals_[name] + source[end:]
        else:
            raise TemplateError("undefined " + name)


LINK = re.compile(r'\s*"([^"]+)"\s*(if\s+(!)?\s*([_a-zA-Z0-9]+)?)?\s*')


def parse_directives(source, template_name):
    links, pos = [], 0
    while True:
        found = source.find("$", pos)
        if found == NPOS:
            return source, links
        pos = found
        end = find_first_of(source, DELIMS, found)
        if end == NPOS:
            raise TemplateError("unexpected EOF")
        directive = source[found + 1:end]
        if directive == "foreach":
            s = found + len("$foreach") + 1
            e = find_first_of(source, DELIMS, s)
            if e == NPOS:
                raise TemplateError("unexpected EOF")
            it = "$" + source[s:e]
            ls = e + 1
            le = find_first_of(source, "\n\r", ls)
            if le == NPOS:
                raise TemplateError("unexpected EOF")
            lst = source[ls:le]
            elems = lst.split(",") if lst else []
            cs = find_first_not_of(source, "\n\r", le)
            ce = source.find("$endforeach", cs)
            if ce == NPOS:
                raise TemplateError("unexpected EOF")
            content = source[cs:ce]
            overall = ce + len("$endforeach")
            n = get_line_number(source, overall, 2, 0)
            rep = "".join(content.replace(it, el) for el in elems) + f"\n#line {n}"
            source = source[:found] + rep + source[overall:]
        elif directive == "link":
            s = found + 5
            le = source.find("\n", s)
            stmt = source[s:] if le == NPOS else source[s:le]
            mm = LINK.fullmatch(stmt)
            if not mm:
                raise TemplateError("expected a shader filename to link")
            target = mm.group(1)
            if mm.group(2):
                cond = not (not mm.group(4) or mm.group(4) == "0")
                if mm.group(3) == "!":
                    cond = not cond
                if not cond:
                    target = ""
            source = source[:found] + ("" if le == NPOS else source[le:])
            if target and target != template_name:
                links.append(target)
        else:
            raise TemplateError("unknown directive $" + directive)


def shader(name, defines, globals_):
    """ShaderManager::getShaderInternal: (template name, text, linked template names)."""
    if not root_prefix(name):
        name = "compatibility/" + name
    src = parse_defines(template(name), defines, globals_)
    src, links = parse_directives(src, name)
    return name, src, links


EXT_STAGE = {"vert": "vertex", "frag": "fragment", "geom": "geometry", "comp": "compute"}


def program(shaders, defines, globals_, with_links=True):
    """getProgram(vert, frag) (or a lone compute shader) plus one level of linked shaders, each
    linked one compiled with the linker's defines and stage; a template linked twice (headers
    included more than once) is the same cached osg::Shader, attached once."""
    stages, stems = [], set()
    main = []
    for tname in shaders:
        name, src, links = shader(tname, defines, globals_)
        stage = EXT_STAGE[name.rsplit(".", 1)[1]]
        main.append((stage, name, src, links))
    for stage, name, src, _ in main:
        stages.append((stage, posixpath.basename(name).rsplit(".", 1)[0], src))
    for stage, _, _, links in main:
        for ln in (links if with_links else []):
            lname, lsrc, _ = shader(ln, defines, globals_)
            stem = posixpath.basename(lname).rsplit(".", 1)[0]
            if (stage, stem, lsrc) not in stages:  # osg::Program::addShader ignores a repeat
                stages.append((stage, stem, lsrc))
    for stage, stem, _ in stages:
        if (stage, stem) in stems:
            raise TemplateError("duplicate stage file " + stem)
        stems.add((stage, stem))
    return stages


# --- define values from the sources and settings-default.cfg -------------------------------
def f32str(x):
    """std::to_string(float): %f of the float32 value."""
    return "%f" % struct.unpack("f", struct.pack("f", x))[0]


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


settings, section = {}, None
for line in m.text("files/settings-default.cfg").splitlines():
    s = line.strip()
    if s.startswith("["):
        section = s.strip("[]")
    elif "=" in s and not s.startswith("#"):
        k, v = s.split("=", 1)
        settings[(section, k.strip())] = v.strip()
S = lambda sec, key: settings[(sec, key)]
B = lambda sec, key: "1" if S(sec, key) == "true" else "0"

sm = m.text("components/shader/shadermanager.cpp")
body = sm[sm.index("DefineMap getDefaultDefines()"):]
body = body[:body.index("};")]
defaults = dict(re.findall(r'\{\s*"(\w+)"\s*,\s*"([^"]*)"\s*\}', body))
sh = m.text("components/sceneutil/shadow.cpp")
off = sh[sh.index("ShadowManager::getShadowsDisabledDefines()"):]
shadows_off = dict(re.findall(r'definesWithoutShadows\["(\w+)"\]\s*=\s*"([^"]*)"', off[:off.index("return")]))
lmh = m.text("components/sceneutil/lightmanager.hpp")
work_group = re.search(r"mClusteredWorkGroupSize\s*=\s*(\d+)", lmh).group(1)
per_cluster = re.search(r"mMaxLightsPerCluster\s*=\s*(\d+)", lmh).group(1)
rip = m.text("apps/openmw/mwrender/ripples.hpp")
rtt = re.search(r"sRTTSize\s*=\s*(\d+)", rip).group(1)
world_scale = float(re.search(r"sWorldScaleFactor\s*=\s*([\d.]+)", rip).group(1))
pp = m.text("apps/openmw/mwrender/postprocessor.cpp")
distortion = float(re.search(r"DistortionRatio\s*=\s*([\d.]+)", pp).group(1))


def global_defines(shadows, clustered):
    g = dict(defaults)
    if shadows:
        n = int(S("Shadows", "number of shadow maps"))
        g.update({"shadows_enabled": "1", "shadow_texture_unit_list": ",".join(str(i) for i in range(n)),
                  "useShadowDebugOverlay": B("Shadows", "enable debug overlay"),
                  "perspectiveShadowMaps": "1",  # osgShadow::ShadowSettings' default projection hint
                  "disableNormalOffsetShadows": "1" if float(S("Shadows", "normal offset distance")) == 0 else "0",
                  "shadowNormalOffset": f32str(float(S("Shadows", "normal offset distance"))),
                  "limitShadowMapDistance": "1" if float(S("Shadows", "maximum shadow map distance")) > 0 else "0"})
    else:
        g.update(shadows_off)
    g["forcePPL"] = B("Shaders", "force per pixel lighting")
    g["clamp"] = B("Shaders", "clamp lighting")
    g["preLightEnv"] = B("Shaders", "apply lighting to environment maps")
    g["classicFalloff"] = B("Shaders", "classic falloff")
    expfog = S("Fog", "exponential fog") == "true"
    g["radialFog"] = "1" if expfog or S("Fog", "radial fog") == "true" else "0"
    g["exponentialFog"] = "1" if expfog else "0"
    g["skyBlending"] = B("Fog", "sky blending")
    g["particlePointLighting"] = B("Shaders", "particle point lighting")
    g.update({"maxLights": S("Shaders", "max lights"), "lightingMethodClustered": "1" if clustered else "0",
              "useGPUShader4": "1" if clustered else "0", "simpleLighting": "0"})
    dist = f32(float(S("Groundcover", "rendering distance")))
    g["groundcoverFadeStart"] = f32str(dist * f32(0.9))
    g["groundcoverFadeEnd"] = f32str(dist)
    g["groundcoverStompMode"] = S("Groundcover", "stomp mode")
    g["groundcoverStompIntensity"] = S("Groundcover", "stomp intensity")
    g["reverseZ"] = B("Camera", "reverse z")
    g["distorionRTRatio"] = f32str(distortion)
    return g


GLOBALS = [("default", global_defines(False, False)), ("shadows_clustered", global_defines(True, True))]
STEREO = {"useOVR_multiview": "0", "numViews": "1"}
GL_NEVER, GL_GREATER, GL_ALWAYS = 0x0200, 0x0204, 0x0207
TEXTURES = ["diffuseMap", "normalMap", "emissiveMap", "darkMap", "detailMap", "envMap",
            "specularMap", "decalMap", "bumpMap", "glossMap"]


def material(textures, alpha_func=GL_ALWAYS, alpha_blend=False, normal_height=False,
             particle=False, soft=False, additive=False):
    """ShaderVisitor::createProgram's define map (textures: names in texture-unit order)."""
    d = {}
    for t in TEXTURES:
        d[t], d[t + "UV"] = "0", "0"
    for unit, t in enumerate(textures):
        d[t], d[t + "UV"] = "1", str(unit)
    d["diffuseParallax"] = "0"
    d["parallax"] = "1" if normal_height else "0"
    d["reconstructNormalZ"] = "0"
    d["alphaFunc"] = str(alpha_func)
    d["additiveBlending"] = "1" if additive else "0"
    d["alphaToCoverage"] = "0"   # antialias alpha test off (no MSAA target)
    d["adjustCoverage"] = "0"
    if alpha_func != GL_ALWAYS:
        if S("Shaders", "adjust coverage for alpha test") == "true" and not alpha_blend:
            d["adjustCoverage"] = "1"
        d["useGPUShader4"] = "1"  # EXT_gpu_shader4 available
    d["particle"] = "1" if particle else "0"
    if particle:
        d["forcePPL"] = "0"
    d["particleOcclusion"] = "0"
    if alpha_blend and soft:
        d["disableNormals"] = "1"
    d["softParticles"] = "1" if soft else "0"
    d.update(STEREO)
    return d


MW_MAPS = ["diffuseMap", "darkMap", "detailMap", "decalMap", "emissiveMap", "bumpMap", "normalMap", "specularMap"]
MORROWIND = [  # objects / groundcover: NiTexturingProperty-style texture sets
    ("plain", material([])),
    ("diffuse", material(["diffuseMap"])),
    ("diffuse_normal_specular", material(["diffuseMap", "normalMap", "specularMap"])),
    ("all_maps_alphatest", material(MW_MAPS, alpha_func=GL_GREATER, normal_height=True)),
    ("particle_soft", material(["diffuseMap"], alpha_blend=True, particle=True, soft=True, additive=True)),
]
BS_SET = ["diffuseMap", "normalMap", "emissiveMap"]
MATERIALS = {  # bs/*: BSShaderTextureSet slots (bs/default.vert declares texMat for all three)
    "objects": MORROWIND,
    "groundcover": MORROWIND,
    "bs/default": [("diffuse_normal_emissive", material(BS_SET)),
                   ("diffuse_normal_emissive_alphatest", material(BS_SET, alpha_func=GL_GREATER))],
    "bs/nolighting": [("plain", material([])), ("diffuse", material(["diffuseMap"])),
                      ("diffuse_alphatest", material(["diffuseMap"], alpha_func=GL_GREATER)),
                      ("particle_soft", material(["diffuseMap"], alpha_blend=True, particle=True, soft=True,
                                                 additive=True))],
}


def terrain(normal, blend, spec, parallax, reconstruct):
    d = {"normalMap": normal, "blendMap": blend, "specularMap": spec, "parallax": parallax,
         "reconstructNormalZ": reconstruct}
    d.update(STEREO)
    return d


water = {"rainRippleDetail": S("Water", "rain ripple detail"), "rippleMapWorldScale": f32str(world_scale),
         "rippleMapSize": rtt + ".0", "sunlightScattering": B("Water", "sunlight scattering"),
         "wobblyShores": B("Water", "wobbly shores")}
water.update(STEREO)
hdr = {"hdrExposureTime": f32str(float(S("Post Processing", "auto exposure speed")))}

jobs = []  # (name, [templates], defines, global sets)
for prefix in ("objects", "groundcover", "bs/default", "bs/nolighting"):
    for label, d in MATERIALS[prefix]:
        jobs.append((f"{prefix}.{label}", [prefix + ".vert", prefix + ".frag"], d, None))
for label, d in (("plain", terrain("0", "0", "0", "0", "0")), ("normal_blend_spec_parallax", terrain("1", "1", "1", "1", "0")),
                 ("rg_normal", terrain("1", "1", "0", "0", "1"))):
    jobs.append(("terrain." + label, ["terrain.vert", "terrain.frag"], d, None))
for b in ("0", "1"):
    jobs.append(("terrain_composite.blendMap" + b, ["terrain_composite.vert", "terrain_composite.frag"], {"blendMap": b}, None))
for r in ("0", "1"):
    jobs.append(("water.refraction" + r, ["water.vert", "water.frag"], dict(water, waterRefraction=r), None))
jobs.append(("sky", ["sky.vert", "sky.frag"], dict(STEREO), None))
jobs.append(("depthclipped", ["depthclipped.vert", "depthclipped.frag"], dict(STEREO), None))
for p in ("globalmap", "debug", "gui", "outline", "fullscreen_tri", "multiview_resolve"):
    jobs.append((p, [p + ".vert", p + ".frag"], {}, None))
jobs.append(("luminance", ["fullscreen_tri.vert", "luminance/luminance.frag"], hdr, None))
jobs.append(("luminance_resolve", ["fullscreen_tri.vert", "luminance/resolve.frag"], hdr, None))
for f in ("ripples_blobber", "ripples_simulate"):
    jobs.append((f, ["fullscreen_tri.vert", f + ".frag"], {"rippleMapSize": rtt + ".0"}, None))
    jobs.append((f + "_compute", [f"core/{f}.comp"], {}, None))
for af in range(GL_NEVER, GL_ALWAYS + 1):
    jobs.append((f"shadowcasting.alphaFunc{af}", ["shadowcasting.vert", "shadowcasting.frag"],
                 {"alphaFunc": str(af), "alphaToCoverage": "0", "adjustCoverage": "1", "useGPUShader4": "1"}, ["default"]))
jobs.append(("cluster_compute", ["core/lighting/cluster.comp"], {}, ["shadows_clustered"]))
jobs.append(("cull_compute", ["core/lighting/cull.comp"],
             {"workGroupSize": work_group, "maxLightsPerCluster": per_cluster}, ["shadows_clustered"]))

# MWShadowTechnique::setupCastingShader: shadowcasting.vert with an empty define map, the
# fragment shader with the four defines above, put in a new osg::Program (no $link shaders).
seen, n, errors = set(), 0, []
for name, temps, d, only in jobs:
    for gname, g in GLOBALS:
        if only and gname not in only:
            continue
        try:
            if name.startswith("shadowcasting"):  # a plain osg::Program: no linked shaders
                stages = program([temps[0]], {}, g, False) + program([temps[1]], d, g, False)
            else:
                stages = program(temps, d, g)
        except TemplateError as e:
            errors.append(f"{name} [{gname}]: {e}")
            continue
        key = tuple(stages)
        if key in seen:
            continue
        seen.add(key)
        write_program(out, "openmw", f"{name}.{gname}", stages)
        n += 1
for e in errors:
    print("skipped:", e, file=sys.stderr)
print(n, "programs")
