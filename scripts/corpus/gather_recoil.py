#!/usr/bin/env python3
"""beyond-all-reason/RecoilEngine (the Spring engine): the engine's own GLSL programs
(cont/base/springcontent/shaders/GLSL/*.glsl plus the inline C++ ones), paired and defined as
the C++ that builds them does, for one fixed context and scenario.

Loading: `po = shaderHandler->CreateProgramObject(..)`, then
`po->AttachShaderObject(shaderHandler->CreateShaderObject(SRC, DEFS, GL_X_SHADER))` per stage,
`po->SetFlag(name, value)` and `po->Link()`. SRC is a VFS path ("GLSL/x.glsl" is
shaders/GLSL/x.glsl of springcontent) or, when it holds "void main()", the source itself
(IShaderObject::GetShaderSource). On link, GLSLProgramObject::Reload sets every shader
object's modDefStrs to ShaderFlags::GetString() - `#define K` per true bool flag, `#define K %d`
per int flag, `#define K %f` per float flag (bool, int, float groups in that order; within a
group the engine iterates a hash map, here the names are sorted) - and
GLSLShaderObject::CompileShaderObject passes 7 strings: "// SHADER VERSION\\n", the #version
line (taken out of the source, overridden by one in DEFS), "// SHADER FLAGS\\n",
DEFS + "\\n" + flags, "// SHADER SOURCE\\n", "#line 1\\n", the source without its #version line.
Flags set later at draw time (SetFlag before Enable) recompile the program: such variants are
separate programs here ("+shadows" ...).

Context: Mesa, GL 4.6 compatibility (ARB_clip_control, ARB_conservative_depth and
ARB_multi_draw_indirect present, so supportClipSpaceControl, supportFragDepthLayout and haveGL4
are true; GL_MAX_LIGHTS 8); springsettings defaults (MaxDynamicModelLights 1, BumpWater*
defaults, HighQualityDecals off without MSAA). Scenario for map-dependent values: a 512x512
square map (8x8), MapInfo defaults for light and water, a 1920x1080 view; the SMF ground
shaders for a plain map and for a map using every optional SMF texture with visible water.
Programs: minimap, SMF border / shading-texture / ground (forward std, forward adv, deferred
adv), model GLSL and GL4 (no-shadow/shadowed x forward/deferred), shadow generation (model,
projectile, map, model GL4), grass (near, far, shadow-gen), ground decals, modern sky (x2),
projectile FX (shadow, hard, soft), skybox and equirect converter, shapes, bump water and its
coast blur, the modern info textures (FullscreenTriangleVS + inline fragment code) and
TextureRenderAtlas. Not included: RenderBuffers.h's templated shaders and the RmlUi renderer's.
Usage: gather_recoil.py MIRROR_GIT_DIR OUT_DIR
"""
import math, os, re, struct, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program, strip_cpp_comments, c_string_vars

m, out = Mirror(sys.argv[1]), sys.argv[2]
VFS = "cont/base/springcontent/shaders/"


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def source_of(ref):
    """IShaderObject::GetShaderSource: inline text (holds "void main()") or shaders/<path>."""
    if "void main()" in ref:
        return ref
    text = m.text(VFS + ref)
    if text is None:
        raise SystemExit("missing " + VFS + ref)
    return text


def extract_version(s):
    """ExtractGlslVersion: (text without the line, the line incl. its newline) or (s, None)."""
    pos = s.find("#version ")
    if pos < 0:
        return s, None
    eol = s.find("\n", pos) + 1
    if eol == 0:
        eol = len(s)
    return s[:pos] + s[eol:], s[pos:eol]


def flag_string(flags):
    """ShaderFlags::GetString (names sorted within each type group)."""
    bits = sorted(k for k, v in flags.items() if isinstance(v, bool) and v)
    ints = sorted(k for k, v in flags.items() if isinstance(v, int) and not isinstance(v, bool))
    flts = sorted(k for k, v in flags.items() if isinstance(v, float))
    return ("".join(f"#define {k}\n" for k in bits) + "".join(f"#define {k} {flags[k]}\n" for k in ints)
            + "".join("#define %s %f\n" % (k, flags[k]) for k in flts))


def stage_text(ref, defs, flags):
    src, version = extract_version(source_of(ref))
    deflags = defs + "\n" + flag_string(flags)
    deflags, v2 = extract_version(deflags)
    version = v2 or version or ""
    if version and not version.endswith("\n"):
        version += "\n"
    if deflags and not deflags.endswith("\n"):
        deflags += "\n"
    return ("// SHADER VERSION\n" + version + "// SHADER FLAGS\n" + deflags
            + "// SHADER SOURCE\n" + "#line 1\n" + src)


_cpp = {}


def cpp(path):
    if path not in _cpp:
        _cpp[path] = strip_cpp_comments(m.text(path))
    return _cpp[path]


def check_call(path, ref):
    """The C++ file really creates a shader object from this VFS path."""
    if not re.search(r'CreateShaderObject\(\s*"' + re.escape(ref) + '"', cpp(path)):
        raise SystemExit(f"{path}: no CreateShaderObject(\"{ref}\"")


def inline(path, var):
    """A raw-string shader held in a C++ variable (`const std::string fragmentCode = R"(..)";`)."""
    vals = c_string_vars(cpp(path)).get(var)
    if not vals:
        raise SystemExit(f"{path}: no string {var}")
    return vals[0]


programs = []


def prog(name, cppfile, stages, flags=None, check=True):
    """stages: [(stage, ref, defs)]; ref a VFS path (checked against cppfile) or inline text."""
    out_stages = []
    for stage, ref, defs in stages:
        if "void main()" not in ref:
            if check:
                check_call(cppfile, ref)
            stem = os.path.basename(ref).rsplit(".", 1)[0]
        else:
            stem = "inline_" + stage[:4]
        out_stages.append((stage, stem, stage_text(ref, defs, flags or {})))
    programs.append((name, out_stages))


VF = lambda v, f, d="": [("vertex", v, d), ("fragment", f, d)]

# --- context and scenario values -------------------------------------------------------
CLIP_CONTROL, DEPTH_LAYOUT = True, True
GL_MAX_LIGHTS = 8


def config_default(path, name):
    mm = re.search(r"CONFIG\(\s*\w+\s*,\s*" + name + r"\s*\)\s*\.defaultValue\(\s*([^)]+)\)", cpp(path))
    v = mm.group(1).strip().rstrip("f")
    return {"true": True, "false": False}.get(v, v)


GB = {k: int(v) for k, v in re.findall(r"ATTACHMENT_(\w+TEX)\s*=\s*(\d+)", cpp("rts/Rendering/GL/GeometryBuffer.h"))}
GBUFFER = {f"GBUFFER_{k}_IDX": GB[k] for k in ("NORMTEX", "DIFFTEX", "SPECTEX", "EMITTEX", "MISCTEX", "ZVALTEX")}

# MiniMap, SMF border and shading texture, sky, shapes, projectile shadow: no defines
prog("MiniMap", "rts/Game/UI/MiniMap.cpp", VF("GLSL/MiniMapVertProg.glsl", "GLSL/MiniMapFragProg.glsl"))
prog("SMFBorder", "rts/Map/SMF/SMFGroundDrawer.cpp", VF("GLSL/SMFBorderVertProg.glsl", "GLSL/SMFBorderFragProg.glsl"))
prog("SMFShadingTexture", "rts/Map/SMF/SMFReadMap.cpp",
     VF("GLSL/SMFShadingTextureVertProg.glsl", "GLSL/SMFShadingTextureFragProg.glsl"))

# SMF ground (SMFRenderStateGLSL::Init / Update)
gr = cpp("rts/Rendering/GlobalRendering.h")
expr = re.search(r"SMF_INTENSITY_MULT\s*=\s*([^;]+);", gr).group(1)
intensity = f32(eval(re.sub(r"(\d+\.\d+)f", r"\1", expr)))
smf_defs = "#define SMF_TEXSQUARE_SIZE %f\n#define SMF_INTENSITY_MULT %f\n" % (1024.0, intensity)
SMF = "rts/Map/SMF/SMFRenderState.cpp"
smf_full = {"SMF_ADV_SHADING": True, "SMF_VOID_WATER": False, "SMF_VOID_GROUND": False,
            "SMF_SPECULAR_LIGHTING": True, "SMF_DETAIL_TEXTURE_SPLATTING": True,
            "SMF_DETAIL_NORMAL_TEXTURE_SPLATTING": True, "SMF_DETAIL_NORMAL_DIFFUSE_ALPHA": False,
            "SMF_WATER_ABSORPTION": True, "SMF_SKY_REFLECTIONS": True, "SMF_BLEND_NORMALS": True,
            "SMF_LIGHT_EMISSION": True, "SMF_PARALLAX_MAPPING": True}
smf_plain = {k: (k == "SMF_ADV_SHADING") for k in smf_full}
runtime_off = {"HAVE_SHADOWS": False, "HAVE_INFOTEX": False}
smf_stages = VF("GLSL/SMFVertProg.glsl", "GLSL/SMFFragProg.glsl", smf_defs)
prog("SMF-Forward-Std", SMF, smf_stages, runtime_off)
prog("SMF-Forward-Adv.plainmap", SMF, smf_stages, dict(smf_plain, **runtime_off))
prog("SMF-Forward-Adv.fullmap", SMF, smf_stages, dict(smf_full, **runtime_off))
prog("SMF-Forward-Adv.fullmap+shadows+infotex", SMF, smf_stages, dict(smf_full, HAVE_SHADOWS=True, HAVE_INFOTEX=True))
prog("SMF-Deferred-Adv.fullmap", SMF, smf_stages, dict(smf_full, DEFERRED_MODE=True, **runtime_off, **GBUFFER))

# models (CModelDrawerStateGLSL / GL4)
MDS = "rts/Rendering/Common/ModelDrawerState.cpp"
base = int(re.search(r"lightHandler\.Init\(\s*(\d+)U?", cpp("rts/Rendering/Common/ModelDrawer.cpp")).group(1))
max_lights = min(GL_MAX_LIGHTS - base, int(config_default("rts/Rendering/Units/UnitDrawer.cpp", "MaxDynamicModelLights")))
model_defs = f"#define BASE_DYNAMIC_MODEL_LIGHT {base}\n#define MAX_DYNAMIC_MODEL_LIGHTS {max_lights}\n"
for n, label in enumerate(("NoShadowStandard", "ShadowedStandard", "NoShadowDeferred", "ShadowedDeferred")):
    fl = dict(USE_SHADOWS=int(n & 1 == 1), DEFERRED_MODE=int(n >= 2), **GBUFFER)
    prog("ModelShaderGLSL-" + label, MDS, VF("GLSL/ModelVertProg.glsl", "GLSL/ModelFragProg.glsl", model_defs), fl)
    prog("ModelShaderGL4-" + label, MDS, VF("GLSL/ModelVertProgGL4.glsl", "GLSL/ModelFragProgGL4.glsl"), fl)

# shadow generation (CShadowHandler::LoadShadowGenShaders)
SH = "rts/Rendering/ShadowHandler.cpp"
ver = ["#version 130\n", "#version %d\n" % (420 if DEPTH_LAYOUT else 130)]
extra = f"#define SUPPORT_CLIP_CONTROL {int(CLIP_CONTROL)}\n#define SUPPORT_DEPTH_LAYOUT {int(DEPTH_LAYOUT)}\n"
for d, label in (("SHADOWGEN_PROGRAM_MODEL", "Model"), ("SHADOWGEN_PROGRAM_PROJ_OPAQ", "ProjectileOpaque")):
    dd = f"#define {d}\n"
    prog("ShadowGen" + label, SH, [("vertex", "GLSL/ShadowGenVertProg.glsl", ver[0] + dd + extra),
                                   ("fragment", "GLSL/ShadowGenFragProg.glsl", ver[1] + dd + extra)])
dd = "#define SHADOWGEN_PROGRAM_MAP\n"
prog("ShadowGenMap", SH, [("vertex", "GLSL/ShadowGenVertMapProg.glsl", ver[0] + dd + extra),
                          ("fragment", "GLSL/ShadowGenFragProg.glsl", ver[1] + dd + extra)])
prog("ShadowGenModelGL4", SH, VF("GLSL/ShadowGenVertProgGL4.glsl", "GLSL/ShadowGenFragProgGL4.glsl",
                                 "#define SHADOWGEN_PROGRAM_MODEL_GL4\n" + extra))

# grass (LoadGrassShaders; EnableShader sets HAVE_INFOTEX / HAVE_SHADOWS)
GD = "rts/Rendering/Env/GrassDrawer.cpp"
for d, label in (("DISTANCE_NEAR", "NearAdv"), ("DISTANCE_FAR", "DistAdv"), ("SHADOW_GEN", "ShadGen")):
    st = VF("GLSL/GrassVertProg.glsl", "GLSL/GrassFragProg.glsl", f"#define {d}\n")
    prog("grass" + label, GD, st)
    if d != "SHADOW_GEN":
        prog("grass" + label + "+shadows", GD, st, {"HAVE_INFOTEX": False, "HAVE_SHADOWS": True})

# ground decals (ReloadDecalShaders): the #version comes through the fragment DEFS
DH = "rts/Rendering/Env/Decals/GroundDecalHandler.cpp"
for hq in (False, True):
    v = "#version 400 compatibility\n" if hq else "#version 130\n"
    prog("GroundDecals" + (".hq" if hq else ""), DH,
         [("vertex", "GLSL/GroundDecalsVertProg.glsl", ""), ("fragment", "GLSL/GroundDecalsFragProg.glsl", v)],
         {"DEPTH_CLIP01": CLIP_CONTROL, "HAVE_SHADOWS": True, "HIGH_QUALITY": hq, "HAVE_INFOTEX": True,
          "SMF_WATER_ABSORPTION": True})

for i in (0, 1):
    prog(f"ModernSky-{i}", "rts/Rendering/Env/ModernSky.cpp", VF("GLSL/ModernSkyVS.glsl", "GLSL/ModernSkyFS.glsl"),
         {"SIMPLIFIED_RENDERING": int(i == 1)})

PD = "rts/Rendering/Env/Particles/ProjectileDrawer.cpp"
prog("ProjFX-shadow", PD, VF("GLSL/ProjFXVertShadowProg.glsl", "GLSL/ProjFXFragShadowProg.glsl"))
prog("ProjFX-hard", PD, VF("GLSL/ProjFXVertProg.glsl", "GLSL/ProjFXFragProg.glsl"), {"DEPTH_CLIP01": CLIP_CONTROL})
prog("ProjFX-soft", PD, VF("GLSL/ProjFXVertProg.glsl", "GLSL/ProjFXFragProg.glsl"),
     {"DEPTH_CLIP01": CLIP_CONTROL, "SMOOTH_PARTICLES": True})  # CheckSoftenExt(): GL 4.x

SB = "rts/Rendering/Env/SkyBox.cpp"
prog("EquiRectConverter", SB, VF("GLSL/CubeMapVS.glsl", "GLSL/EquiRectConverterFS.glsl"))
prog("SkyBox", SB, VF("GLSL/CubeMapVS.glsl", "GLSL/CubeMapFS.glsl"))
prog("Shapes", "rts/Rendering/GL/glExtra.cpp", VF("GLSL/ShapesVertProg.glsl", "GLSL/ShapesFragProg.glsl"))

# bump water (CBumpWater ctor: definitions string, then opt_shadows / opt_infotex at draw time)
BW = "rts/Rendering/Env/BumpWater.cpp"
mi = cpp("rts/Map/MapInfo.cpp")


def mapinfo(prefix, key):
    mm = re.search(prefix + r"\.\w+\s*=\s*\w+\.Get(Float3|Float)\(\s*\"" + key + r"\"\s*,\s*([^;]+)\);", mi)
    v = mm.group(2)
    if mm.group(1) == "Float3":
        if "float3(" in v:
            return [f32(float(x.strip().rstrip("f"))) for x in v[v.index("(") + 1:v.rindex(")")].split(",")]
        return mapinfo("light", "groundDiffuseColor")  # specularColor defaults to it
    return f32(float(v.strip().rstrip(")").rstrip("f")))


W = lambda k: mapinfo("water", k)
mapx = mapy = 512
SQ = 8
view = (1920, 1080)
sun = re.search(r'"sunDir"\s*,\s*float4\(([^)]*)\)', mi).group(1).split(",")[:3]
sun = [float(x.strip().rstrip("f")) for x in sun]
ln = math.sqrt(sum(x * x for x in sun))
sun = [f32(x / ln) for x in sun]
c = lambda *v: "(" + ",".join("%.12f" % f32(x) for x in v) + ")"
defs = ""
if int(config_default(BW, "BumpWaterReflection")) > 0: defs += "#define opt_reflection\n"
if int(config_default(BW, "BumpWaterRefraction")) > 0: defs += "#define opt_refraction\n"
if config_default(BW, "BumpWaterShoreWaves"): defs += "#define opt_shorewaves\n"
if config_default(BW, "BumpWaterUseDepthTexture"): defs += "#define opt_depth\n"
if config_default(BW, "BumpWaterBlurReflection"): defs += "#define opt_blurreflection\n"
# opt_endlessocean: needs the map's water table to have planeColor (hasWaterPlane): not here
f3 = lambda n, v: f"#define {n} vec3{c(*v)}\n"
f2 = lambda n, x, y: f"#define {n} vec2{c(x, y)}\n"
f4 = lambda n, *v: f"#define {n} vec4{c(*v)}\n"
f1 = lambda n, x: "#define %s %.12f\n" % (n, f32(x))
sc, pc, alpha = W("surfaceColor"), W("planeColor"), W("surfaceAlpha")
defs += f3("MapMid", (mapx * SQ * 0.5, 0.0, mapy * SQ * 0.5))
defs += f2("ScreenInverse", 1.0 / view[0], 1.0 / view[1])
defs += f2("ScreenTextureSizeInverse", 1.0 / view[0], 1.0 / view[1])
defs += f2("ViewPos", 0, 0)
defs += f4("SurfaceColor", *[f32(x * f32(0.4)) for x in sc], alpha)
defs += f4("PlaneColor", *[f32(x * f32(0.4)) for x in pc], alpha)
defs += f3("DiffuseColor", W("diffuseColor"))
defs += f3("SpecularColor", W("specularColor"))
defs += f1("SpecularPower", W("specularPower")) + f1("SpecularFactor", W("specularFactor"))
defs += f1("AmbientFactor", W("ambientFactor")) + f1("DiffuseFactor", W("diffuseFactor") * 15.0)
defs += f3("SunDir", sun)
defs += f1("FresnelMin", W("fresnelMin")) + f1("FresnelMax", W("fresnelMax")) + f1("FresnelPower", W("fresnelPower"))
defs += f1("ReflDistortion", W("reflectionDistortion"))
defs += f2("BlurBase", 0.0, W("blurBase") / view[1]) + f1("BlurExponent", W("blurExponent"))
defs += f1("PerlinStartFreq", W("perlinStartFreq")) + f1("PerlinLacunarity", W("perlinLacunarity"))
defs += f1("PerlinAmp", W("perlinAmplitude"))
for n, k in (("WaveOffsetFactor", "waveOffsetFactor"), ("WaveLength", "waveLength"),
             ("WaveFoamDistortion", "waveFoamDistortion"), ("WaveFoamIntensity", "waveFoamIntensity"),
             ("CausticsResolution", "causticsResolution"), ("CausticsStrength", "causticsStrength")):
    defs += f1(n, W(k))
defs += f1("shadowDensity", mapinfo("light", "groundShadowDensity"))
mx, mz = mapx * SQ, mapy * SQ
shx = shz = 1.0  # mapx / pwr2mapx
scx = (mapy >> 6) / 16.0 * mx / mz if mx > mz else (mapx >> 6) / 16.0
scz = (mapy >> 6) / 16.0 if mx > mz else (mapx >> 6) / 16.0 * mz / mx
defs += f4("TexGenPlane", 1.0 / mx, 1.0 / mz, scx / mx, scz / mz)
defs += f4("ShadingPlane", shx / mx, shz / mz, shx, shz)
water = VF("GLSL/BumpWaterVS.glsl", "GLSL/BumpWaterFS.glsl", defs)
prog("BumpWater", BW, water)
prog("BumpWater+shadows", BW, water, {"opt_shadows": True, "opt_infotex": False})
prog("BumpWaterCoastBlur", BW, VF("GLSL/BumpWaterCoastBlurVS.glsl", "GLSL/BumpWaterCoastBlurFS.glsl"))

# modern info textures: FullscreenTriangleVS (ModernInfoTexture.h's vertexCode) + inline fragment
vcode = re.search(r'vertexCode\s*=\s*"([^"]+)"', cpp("rts/Rendering/Map/InfoTexture/Modern/ModernInfoTexture.h")).group(1)
for t in ("AirLos", "Height", "Los", "MetalExtraction", "Radar"):
    path = f"rts/Rendering/Map/InfoTexture/Modern/{t}.cpp"
    if not re.search(r"CreateShaderObject\(\s*vertexCode", cpp(path)):
        raise SystemExit(path + ": no CreateShaderObject(vertexCode")
    prog("InfoTexture-" + t, path, [("vertex", vcode, ""), ("fragment", inline(path, "fragmentCode"), "")],
         check=False)

TRA = "rts/Rendering/Textures/TextureRenderAtlas.cpp"
prog("TextureRenderAtlas", TRA, [("vertex", inline(TRA, "vsTRA"), ""), ("fragment", inline(TRA, "fsTRA"), "")])

n = 0
for name, stages in programs:
    write_program(out, "recoil", name, stages)
    n += 1
print(n, "programs")
