#!/usr/bin/env python3
"""KhronosGroup glTF Sample Viewer / Sample Renderer (WebGL 2): the programs its renderer compiles,
for a fixed set of glTF primitives, materials and viewer settings.

Input: the unpacked npm package `@khronosgroup/gltf-viewer` (1.1.0, the release build of
KhronosGroup/glTF-Sample-Renderer that the Sample Viewer ships; `npm pack
@khronosgroup/gltf-viewer@1.1.0 && tar xzf *.tgz` gives PACKAGE_DIR=package). The git snapshots
of KhronosGroup/glTF-Sample-Viewer, glTF-Sample-Renderer and their forks are over the fetch
size limit (sample assets). The package's dist/gltf-viewer.module.js holds every shader as a
glslify-processed JS string literal (`var pbrShader = "precision highp float;\\n#define GLSLIFY
1\\n#include <tonemapping.glsl>..."`): that text is what the viewer hands to WebGL, so it is read
from there, together with the JS that builds the programs:

- `new ShaderCache(shaderSources, gl)` with the `shaderSources.set("name", var)` map: the
  renderer's (primitive.vert, pbr.frag, the .glsl includes, cubemap.vert/.frag) and the IBL
  sampler's (fullscreen.vert, panorama_to_cubemap.frag, ibl_filtering.frag; debug.frag is in
  the map but never selected). The constructor resolves includes once, in map order: for each
  source, for each map entry (live values) the first `#include <name>` is replaced by that
  entry's text and the other occurrences are removed.
- `selectShader(name, defines)`: `"#version 300 es\\n"` + one `#define D\\n` per define in list
  order + the resolved source (the version line first, the source's own `precision` line after
  the defines).
- gltfRenderer.drawPrimitive: vertex defines = primitive.defines (`HAS_<ATTR>_<TYPE> 1` per
  attribute in glTF attribute order, a TANGENT generated with MikkTSpace for triangles with NORMAL
  and TEXCOORD_0 appended last; morph targets' NUM_VERTICIES / HAS_MORPH_TARGET_X /
  MORPH_TARGET_X_OFFSET / HAS_MORPH_TARGETS) + pushVertParameterDefines (USE_SKINNING 1,
  USE_MORPHING 1 + WEIGHT_COUNT n); fragment defines = material.getDefines() (initGl's texture,
  UV transform, ALPHAMODE, MATERIAL_* defines, then the enabled KHR_materials_* ones) + the vertex
  defines + LINEAR_OUTPUT 1 (transmission pre-pass) + NOT_TRIANGLE 1 (points/lines; normal maps
  dropped without TANGENT) + pushFragParameterDefines (USE_PUNCTUAL 1 + LIGHT_COUNT n, USE_IBL 1,
  TONEMAP_*, every `DEBUG_X k` of the debug mapping with `DEBUG <X>` after the selected one).
- EnvironmentRenderer: cubemap.vert with no defines + cubemap.frag with the frame's
  pushFragParameterDefines, or ["LINEAR_OUTPUT 1"] in the transmission pre-pass.
- iblSampler: fullscreen.vert + panorama_to_cubemap.frag, fullscreen.vert + ibl_filtering.frag.

The glTF scenes are made up here (the package ships none): primitives with the usual attribute
sets (position only .. all attributes, skinned, morphed, points, lines), default and
metallic-roughness/specular-glossiness/unlit materials with and without textures and
KHR_texture_transform, each KHR_materials_* extension, viewer defaults (punctual lights on,
IBL on, KHR PBR Neutral tonemapping, no debug output), every tone mapper, lights on/off, and a
selection of debug outputs; identical programs once.
Usage: gather_gltf_viewer.py PACKAGE_DIR OUT_DIR
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import write_program  # noqa: E402

BUNDLE = "dist/gltf-viewer.module.js"


def js_strings(js):
    """`var NAME = "...";` string literals of the bundle, decoded."""
    return {m.group(1): json.loads(m.group(2))
            for m in re.finditer(r'^var (\w+) = ("(?:\\.|[^"\\\n])*");', js, re.M)}


def shader_caches(js, strings):
    """Each `const shaderSources = new Map(); shaderSources.set(..)...` block -> resolved map."""
    caches = []
    for m in re.finditer(r"const shaderSources = new Map\(\);(.*?)new ShaderCache\(shaderSources", js, re.S):
        sources = {}
        for s in re.finditer(r'shaderSources\.set\("([^"]+)",\s*(\w+)\)', m.group(1)):
            sources[s.group(1)] = strings[s.group(2)]
        # ShaderCache's constructor: one pass, map order, live values
        for key in list(sources):
            src, changed = sources[key], False
            for inc in list(sources):
                pat = "#include <" + inc + ">"
                if pat in src:
                    src = src.replace(pat, sources[inc], 1)
                    src = src.replace(pat, "")
                    changed = True
            if changed:
                sources[key] = src
        caches.append(sources)
    return caches


def select_shader(sources, name, defines):
    return "#version 300 es\n" + "".join(f"#define {d}\n" for d in defines) + sources[name]


# --- the scene description -> defines, as the renderer's JS computes them --------------------

def primitive_defines(prim):
    """gltfPrimitive.initGl: attribute defines (+ generated TANGENT), morph target defines."""
    attrs = list(prim["attributes"])
    names = [a for a, _ in attrs]
    if "TANGENT" not in names and "NORMAL" in names and "TEXCOORD_0" in names and prim.get("mode", 4) > 3:
        attrs.append(("TANGENT", "VEC4"))
    defs = [f"HAS_{a}_{t} 1" for a, t in attrs]
    targets = prim.get("targets")
    if targets:
        tattrs = []
        for t in targets:
            for a in t:
                if a not in tattrs:
                    tattrs.append(a)
        defs.append(f"NUM_VERTICIES {prim['vertices']}")
        off = 0
        for a in tattrs:
            defs += [f"HAS_MORPH_TARGET_{a} 1", f"MORPH_TARGET_{a}_OFFSET {off}"]
            off += len(targets)
        defs.append("HAS_MORPH_TARGETS 1")
    return defs, [a for a, _ in attrs]


def vert_defines(prim, params):
    defs, attrs = primitive_defines(prim)
    extra = []
    if params["skinning"] and prim.get("skin") and any(a.startswith("WEIGHTS") for a in attrs) \
            and any(a.startswith("JOINTS") for a in attrs):
        extra.append("USE_SKINNING 1")
    if params["morphing"] and prim.get("targets") and prim.get("weights"):
        extra += ["USE_MORPHING 1", f"WEIGHT_COUNT {prim['weights']}"]
    return defs + extra


TEXTURES = [("normalTexture", "Normal", "HAS_NORMAL_MAP"), ("occlusionTexture", "Occlusion", "HAS_OCCLUSION_MAP"),
            ("emissiveTexture", "Emissive", "HAS_EMISSIVE_MAP"),
            ("baseColorTexture", "BaseColor", "HAS_BASE_COLOR_MAP"),
            ("metallicRoughnessTexture", "MetallicRoughness", "HAS_METALLIC_ROUGHNESS_MAP"),
            ("diffuseTexture", "Diffuse", "HAS_DIFFUSE_MAP"),
            ("specularGlossinessTexture", "SpecularGlossiness", "HAS_SPECULAR_GLOSSINESS_MAP")]
EXT_TEXTURES = [
    ("KHR_materials_clearcoat", [("clearcoatTexture", "Clearcoat", "HAS_CLEARCOAT_MAP"),
                                 ("clearcoatRoughnessTexture", "ClearcoatRoughness", "HAS_CLEARCOAT_ROUGHNESS_MAP"),
                                 ("clearcoatNormalTexture", "ClearcoatNormal", "HAS_CLEARCOAT_NORMAL_MAP")]),
    ("KHR_materials_sheen", [("sheenRoughnessTexture", "SheenRoughness", "HAS_SHEEN_ROUGHNESS_MAP"),
                             ("sheenColorTexture", "SheenColor", "HAS_SHEEN_COLOR_MAP")]),
    ("KHR_materials_specular", [("specularTexture", "Specular", "HAS_SPECULAR_MAP"),
                                ("specularColorTexture", "SpecularColor", "HAS_SPECULAR_COLOR_MAP")]),
    ("KHR_materials_emissive_strength", []),
    ("KHR_materials_transmission", [("transmissionTexture", "Transmission", "HAS_TRANSMISSION_MAP")]),
    ("KHR_materials_diffuse_transmission",
     [("diffuseTransmissionTexture", "DiffuseTransmission", "HAS_DIFFUSE_TRANSMISSION_MAP"),
      ("diffuseTransmissionColorTexture", "DiffuseTransmissionColor", "HAS_DIFFUSE_TRANSMISSION_COLOR_MAP")]),
    ("KHR_materials_ior", []),
    ("KHR_materials_volume", [("thicknessTexture", "Thickness", "HAS_THICKNESS_MAP")]),
    ("KHR_materials_iridescence", [("iridescenceTexture", "Iridescence", "HAS_IRIDESCENCE_MAP"),
                                   ("iridescenceThicknessTexture", "IridescenceThickness",
                                    "HAS_IRIDESCENCE_THICKNESS_MAP")]),
    ("KHR_materials_anisotropy", [("anisotropyTexture", "Anisotropy", "HAS_ANISOTROPY_MAP")]),
    ("KHR_materials_dispersion", [])]
GET_DEFINES = [("KHR_materials_clearcoat", "MATERIAL_CLEARCOAT"), ("KHR_materials_sheen", "MATERIAL_SHEEN"),
               ("KHR_materials_transmission", "MATERIAL_TRANSMISSION"),
               ("KHR_materials_diffuse_transmission", "MATERIAL_DIFFUSE_TRANSMISSION"),
               ("KHR_materials_volume", "MATERIAL_VOLUME"), ("KHR_materials_ior", "MATERIAL_IOR"),
               ("KHR_materials_specular", "MATERIAL_SPECULAR"),
               ("KHR_materials_iridescence", "MATERIAL_IRIDESCENCE"),
               ("KHR_materials_emissive_strength", "MATERIAL_EMISSIVE_STRENGTH"),
               ("KHR_materials_anisotropy", "MATERIAL_ANISOTROPY"),
               ("KHR_materials_dispersion", "MATERIAL_DISPERSION")]


def material_defines(mat):
    """gltfMaterial: createDefault / fromJson type, initGl defines, getDefines (all extensions on).
    mat: None for the default material, else a dict {textures: {name: transform?}, alphaMode,
    pbrMR: bool, ext: {KHR_x: {textureName: transform?}}}."""
    if mat is None:
        return ["MATERIAL_METALLICROUGHNESS 1", "ALPHAMODE_OPAQUE 0", "ALPHAMODE_MASK 1", "ALPHAMODE_BLEND 2",
                "ALPHAMODE ALPHAMODE_OPAQUE", "MATERIAL_METALLICROUGHNESS 1"]
    ext = mat.get("ext", {})
    tex = dict(mat.get("textures", {}))
    tex.update(ext.get("KHR_materials_pbrSpecularGlossiness", {}))
    mtype = "unlit"
    if "KHR_materials_pbrSpecularGlossiness" in ext:
        mtype = "SG"
    if "KHR_materials_unlit" in ext:
        mtype = "unlit"
    if mat.get("pbrMR") and mtype != "SG":
        mtype = "MR"
    defs = []

    def texture(name, key, define, table):
        if name in table:
            if table[name]:
                defs.append(f"HAS_{key.upper()}_UV_TRANSFORM 1")
            defs.append(f"{define} 1")
    for name, key, define in TEXTURES:
        if name in ("baseColorTexture", "metallicRoughnessTexture") and mtype == "SG":
            continue  # pbrMetallicRoughness is not read for SG materials
        texture(name, key, define, tex)
    defs += ["ALPHAMODE_OPAQUE 0", "ALPHAMODE_MASK 1", "ALPHAMODE_BLEND 2"]
    defs.append("ALPHAMODE ALPHAMODE_" + {"MASK": "MASK", "OPAQUE": "OPAQUE"}.get(mat.get("alphaMode", "OPAQUE"), "BLEND"))
    if mtype != "SG":
        defs.append("MATERIAL_METALLICROUGHNESS 1")
    if "KHR_materials_unlit" in ext:
        defs.append("MATERIAL_UNLIT 1")
    if "KHR_materials_pbrSpecularGlossiness" in ext:
        defs.append("MATERIAL_SPECULARGLOSSINESS 1")
    for e, texs in EXT_TEXTURES:
        if e in ext:
            for name, key, define in texs:
                texture(name, key, define, ext[e])
    for e, define in GET_DEFINES:
        if e in ext:
            defs.append(f"{define} 1")
    return defs


class Renderer:
    def __init__(self, js):
        body = js[js.index("pushFragParameterDefines(fragDefines, state)\n"):]
        body = body[:body.index("applyLights()")]
        self.tonemaps = dict(re.findall(r"GltfState\.ToneMaps\.(\w+)\):\s*fragDefines\.push\(\"([^\"]+)\"\)", body))
        dbg = js[js.index("GltfState.DebugOutput = {"):]
        dbg = re.sub(r"/\*.*?\*/", "", dbg[:dbg.index("\n};")], flags=re.S)
        known = {"NONE"}
        for g in re.finditer(r"(\w+): \{(.*?)\}", dbg, re.S):
            known |= {f"{g.group(1)}.{k}" for k in re.findall(r"(\w+):", g.group(2))}
        self.debug = [(path, d, path in known) for path, d in
                      re.findall(r"debugOutput: GltfState\.DebugOutput\.([\w.]+), shaderDefine: \"(\w+)\"", body)]

    def frag_params(self, params, lights):
        defs = []
        if params["usePunctual"]:
            n = lights
            if n == 0 and not params["useIBL"] and params["useDirectionalLightsWithDisabledIBL"]:
                n = 2  # lightKey + lightFill
            defs += ["USE_PUNCTUAL 1", f"LIGHT_COUNT {n}"]
        if params["useIBL"]:  # an environment is always loaded by the viewer
            defs.append("USE_IBL 1")
        if params["toneMap"] in self.tonemaps:
            defs.append(self.tonemaps[params["toneMap"]])
        found = False
        for k, (path, define, reachable) in enumerate(self.debug):
            defs.append(f"{define} {k}")
            if reachable and path == params["debugOutput"]:
                defs.append(f"DEBUG {define}")
                found = True
        if not found:
            defs.append("DEBUG DEBUG_NONE")
        return defs


DEFAULT_PARAMS = {"skinning": True, "morphing": True, "usePunctual": True, "useIBL": True,
                  "useDirectionalLightsWithDisabledIBL": False, "toneMap": "KHR_PBR_NEUTRAL", "debugOutput": "NONE"}

V3, V4, V2 = "VEC3", "VEC4", "VEC2"
PRIMS = {
    "pos": {"attributes": [("POSITION", V3)]},
    "pn": {"attributes": [("POSITION", V3), ("NORMAL", V3)]},
    "pnt": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TEXCOORD_0", V2)]},  # MikkTSpace tangent
    "pntan": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TANGENT", V4), ("TEXCOORD_0", V2)]},
    "full": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TANGENT", V4), ("TEXCOORD_0", V2),
                            ("TEXCOORD_1", V2), ("COLOR_0", V4)]},
    "color3": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("COLOR_0", V3)]},
    "skin": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TEXCOORD_0", V2), ("JOINTS_0", V4),
                            ("WEIGHTS_0", V4)], "skin": True},
    "skin8": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TANGENT", V4), ("TEXCOORD_0", V2),
                             ("JOINTS_0", V4), ("WEIGHTS_0", V4), ("JOINTS_1", V4), ("WEIGHTS_1", V4)],
              "skin": True},
    "morph": {"attributes": [("POSITION", V3), ("NORMAL", V3)], "targets": [["POSITION", "NORMAL"]] * 2,
              "vertices": 24, "weights": 2},
    "morphall": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TEXCOORD_0", V2), ("TEXCOORD_1", V2),
                                ("COLOR_0", V4)],
                 "targets": [["POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "TEXCOORD_1", "COLOR_0"]] * 3,
                 "vertices": 1089, "weights": 3},
    "skinmorph": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TEXCOORD_0", V2), ("JOINTS_0", V4),
                                 ("WEIGHTS_0", V4)], "skin": True, "targets": [["POSITION"]] * 4,
                  "vertices": 500, "weights": 4},
    "points": {"attributes": [("POSITION", V3), ("COLOR_0", V4)], "mode": 0},
    "lines": {"attributes": [("POSITION", V3), ("NORMAL", V3)], "mode": 1},
    "linestan": {"attributes": [("POSITION", V3), ("NORMAL", V3), ("TANGENT", V4), ("TEXCOORD_0", V2)],
                 "mode": 3},
}
T5 = {"baseColorTexture": False, "metallicRoughnessTexture": False, "normalTexture": False,
      "occlusionTexture": False, "emissiveTexture": False}
MATS = {
    "default": None,
    "mr": {"pbrMR": True},
    "mrtex": {"pbrMR": True, "textures": T5},
    "mrxform": {"pbrMR": True, "textures": dict(T5, baseColorTexture=True, normalTexture=True)},
    "mask": {"pbrMR": True, "alphaMode": "MASK", "textures": {"baseColorTexture": False}},
    "blend": {"pbrMR": True, "alphaMode": "BLEND"},
    "unlit": {"pbrMR": True, "textures": {"baseColorTexture": False}, "ext": {"KHR_materials_unlit": {}}},
    "unlitbare": {"ext": {"KHR_materials_unlit": {}}},
    "sg": {"textures": {"normalTexture": False}, "ext": {"KHR_materials_pbrSpecularGlossiness": {
        "diffuseTexture": False, "specularGlossinessTexture": False}}},
    "sgbare": {"ext": {"KHR_materials_pbrSpecularGlossiness": {}}},
    "sgxform": {"alphaMode": "MASK", "ext": {"KHR_materials_pbrSpecularGlossiness": {"diffuseTexture": True}}},
    "clearcoat": {"pbrMR": True, "textures": T5, "ext": {"KHR_materials_clearcoat": {
        "clearcoatTexture": False, "clearcoatRoughnessTexture": False, "clearcoatNormalTexture": True}}},
    "clearcoatbare": {"pbrMR": True, "ext": {"KHR_materials_clearcoat": {}}},
    "sheen": {"pbrMR": True, "textures": T5, "ext": {"KHR_materials_sheen": {
        "sheenRoughnessTexture": False, "sheenColorTexture": False}}},
    "transmission": {"pbrMR": True, "textures": T5, "ext": {
        "KHR_materials_transmission": {"transmissionTexture": False}, "KHR_materials_ior": {},
        "KHR_materials_volume": {"thicknessTexture": False}}},
    "transmissionbare": {"pbrMR": True, "alphaMode": "BLEND", "ext": {"KHR_materials_transmission": {}}},
    "volume": {"pbrMR": True, "ext": {"KHR_materials_volume": {}, "KHR_materials_ior": {}}},
    "specular": {"pbrMR": True, "textures": T5, "ext": {"KHR_materials_specular": {
        "specularTexture": False, "specularColorTexture": True}}},
    "iridescence": {"pbrMR": True, "textures": T5, "ext": {"KHR_materials_iridescence": {
        "iridescenceTexture": False, "iridescenceThicknessTexture": False}}},
    "anisotropy": {"pbrMR": True, "textures": T5, "ext": {"KHR_materials_anisotropy": {"anisotropyTexture": False}}},
    "difftrans": {"pbrMR": True, "textures": T5, "ext": {
        "KHR_materials_diffuse_transmission": {"diffuseTransmissionTexture": False,
                                               "diffuseTransmissionColorTexture": False},
        "KHR_materials_volume": {}}},
    "dispersion": {"pbrMR": True, "ext": {"KHR_materials_transmission": {}, "KHR_materials_volume": {},
                                          "KHR_materials_ior": {}, "KHR_materials_dispersion": {}}},
    "emissive": {"pbrMR": True, "textures": {"emissiveTexture": True},
                 "ext": {"KHR_materials_emissive_strength": {}}},
    "all": {"pbrMR": True, "textures": T5, "ext": {
        "KHR_materials_clearcoat": {"clearcoatNormalTexture": False}, "KHR_materials_sheen": {"sheenColorTexture": False},
        "KHR_materials_specular": {"specularColorTexture": False}, "KHR_materials_ior": {},
        "KHR_materials_iridescence": {"iridescenceThicknessTexture": False},
        "KHR_materials_emissive_strength": {}, "KHR_materials_anisotropy": {"anisotropyTexture": False}}},
}

# (program name, primitive, material, lights in the scene, params overrides, linear output)
PBR = [
    ("default.pos", "pos", "default", 0, {}, False),
    ("default.pn", "pn", "default", 0, {}, False),
    ("mr.pn", "pn", "mr", 0, {}, False),
    ("mrtex.pnt", "pnt", "mrtex", 0, {}, False),
    ("mrtex.full", "full", "mrtex", 0, {}, False),
    ("mrxform.pntan", "pntan", "mrxform", 0, {}, False),
    ("mask.pnt", "pnt", "mask", 0, {}, False),
    ("blend.color3", "color3", "blend", 0, {}, False),
    ("unlit.pnt", "pnt", "unlit", 0, {}, False),
    ("unlitbare.pos", "pos", "unlitbare", 0, {}, False),
    ("sg.pnt", "pnt", "sg", 0, {}, False),
    ("sgbare.pn", "pn", "sgbare", 0, {}, False),
    ("sgxform.full", "full", "sgxform", 0, {}, False),
    ("clearcoat.pnt", "pnt", "clearcoat", 0, {}, False),
    ("clearcoatbare.pn", "pn", "clearcoatbare", 0, {}, False),
    ("sheen.pnt", "pnt", "sheen", 0, {}, False),
    ("transmission.pnt", "pnt", "transmission", 0, {}, False),
    ("transmissionbare.pn", "pn", "transmissionbare", 0, {}, False),
    ("volume.pn", "pn", "volume", 0, {}, False),
    ("specular.pnt", "pnt", "specular", 0, {}, False),
    ("iridescence.pnt", "pnt", "iridescence", 0, {}, False),
    ("anisotropy.pntan", "pntan", "anisotropy", 0, {}, False),
    ("difftrans.pnt", "pnt", "difftrans", 0, {}, False),
    ("dispersion.pn", "pn", "dispersion", 0, {}, False),
    ("emissive.pnt", "pnt", "emissive", 0, {}, False),
    ("all.full", "full", "all", 0, {}, False),
    ("mrtex.skin", "skin", "mrtex", 0, {}, False),
    ("mrtex.skin8", "skin8", "mrtex", 0, {}, False),
    ("mr.morph", "morph", "mr", 0, {}, False),
    ("mrtex.morphall", "morphall", "mrtex", 0, {}, False),
    ("mrtex.skinmorph", "skinmorph", "mrtex", 0, {}, False),
    ("mrtex.skin.noanim", "skin", "mrtex", 0, {"skinning": False, "morphing": False}, False),
    ("default.points", "points", "default", 0, {}, False),
    ("mrtex.lines", "lines", "mrtex", 0, {}, False),
    ("clearcoat.linestan", "linestan", "clearcoat", 0, {}, False),
    ("mrtex.pnt.lights3", "pnt", "mrtex", 3, {}, False),
    ("all.full.lights1", "full", "all", 1, {}, False),
    ("mrtex.pnt.noibl", "pnt", "mrtex", 0, {"useIBL": False, "useDirectionalLightsWithDisabledIBL": True}, False),
    ("mrtex.pnt.noibl_nolights", "pnt", "mrtex", 0, {"useIBL": False}, False),
    ("mrtex.pnt.nopunctual", "pnt", "mrtex", 2, {"usePunctual": False}, False),
    ("mrtex.pnt.linear", "pnt", "mrtex", 0, {}, True),
    ("blend.color3.linear", "color3", "blend", 1, {}, True),
] + [(f"mrtex.pnt.{tm.lower()}", "pnt", "mrtex", 0, {"toneMap": tm}, False)
     for tm in ("ACES_NARKOWICZ", "ACES_HILL", "ACES_HILL_EXPOSURE_BOOST", "NONE")] + [
    (f"{mat}.{prim}.debug_{path.split('.')[-1].lower()}", prim, mat, 1, {"debugOutput": path}, False)
    for mat, prim, path in [
        ("all", "full", "generic.UV_COORDS_0"), ("all", "full", "generic.UV_COORDS_1"),
        ("all", "full", "generic.NORMAL"), ("all", "full", "generic.WORLDSPACENORMAL"),
        ("all", "full", "generic.GEOMETRYNORMAL"), ("all", "full", "generic.TANGENT"),
        ("all", "full", "generic.ALPHA"), ("all", "full", "generic.OCCLUSION"), ("all", "full", "generic.EMISSIVE"),
        ("all", "full", "mr.BASECOLOR"), ("all", "full", "mr.METALLIC"),
        ("all", "full", "clearcoat.CLEARCOAT_NORMAL"), ("all", "full", "sheen.SHEEN_ROUGHNESS"),
        ("all", "full", "specular.SPECULAR_COLOR"), ("all", "full", "iridescence.IRIDESCENCE_THICKNESS"),
        ("all", "full", "anisotropy.ANISOTROPIC_DIRECTION"),
        ("transmission", "pnt", "transmission.TRANSMISSION_FACTOR"),
        ("transmission", "pnt", "transmission.VOLUME_THICKNESS"),
        ("difftrans", "pnt", "diffuseTransmission.DIFFUSE_TRANSMISSION_COLOR_FACTOR"),
        ("sg", "pnt", "mr.ROUGHNESS")]]
# (program name, lights, params overrides, linear pre-pass)
CUBEMAP = [("default", 0, {}, False), ("linear", 0, {}, True), ("lights2", 2, {}, False),
           ("tonemap_none", 0, {"toneMap": "NONE"}, False), ("aces_hill", 0, {"toneMap": "ACES_HILL"}, False),
           ("noibl", 0, {"useIBL": False, "useDirectionalLightsWithDisabledIBL": True}, False),
           ("debug_normal", 0, {"debugOutput": "generic.WORLDSPACENORMAL"}, False)]


def main():
    pkg, out = sys.argv[1], sys.argv[2]
    js = open(os.path.join(pkg, BUNDLE), encoding="utf-8").read()
    strings = js_strings(js)
    caches = shader_caches(js, strings)
    render = next(c for c in caches if "pbr.frag" in c)
    ibl = next(c for c in caches if "ibl_filtering.frag" in c)
    r = Renderer(js)
    n, seen = 0, set()

    def emit(name, stages):
        nonlocal n
        key = tuple(t for _, _, t in stages)
        if key in seen:
            return
        seen.add(key)
        write_program(out, "gltf_viewer", name, stages)
        n += 1

    for name, pk, mk, lights, over, linear in PBR:
        params = dict(DEFAULT_PARAMS, **over)
        prim = PRIMS[pk]
        vdefs = vert_defines(prim, params)
        fdefs = material_defines(MATS[mk]) + vdefs
        if linear:
            fdefs.append("LINEAR_OUTPUT 1")
        if prim.get("mode", 4) < 4:
            fdefs.append("NOT_TRIANGLE 1")
            names = [a for a, _ in prim["attributes"]]
            if "NORMAL" in names and "TANGENT" not in names:
                fdefs = [d for d in fdefs if d not in ("HAS_NORMAL_MAP 1", "HAS_CLEARCOAT_NORMAL_MAP 1")]
        fdefs += r.frag_params(params, lights)
        emit("pbr." + name, [("vertex", "primitive", select_shader(render, "primitive.vert", vdefs)),
                             ("fragment", "pbr", select_shader(render, "pbr.frag", fdefs))])
    for name, lights, over, linear in CUBEMAP:
        fdefs = ["LINEAR_OUTPUT 1"] if linear else r.frag_params(dict(DEFAULT_PARAMS, **over), lights)
        emit("cubemap." + name, [("vertex", "cubemap", select_shader(render, "cubemap.vert", [])),
                                 ("fragment", "cubemap", select_shader(render, "cubemap.frag", fdefs))])
    for frag in ("panorama_to_cubemap.frag", "ibl_filtering.frag"):
        emit(frag[:-5], [("vertex", "fullscreen", select_shader(ibl, "fullscreen.vert", [])),
                         ("fragment", frag[:-5], select_shader(ibl, frag, []))])
    print(n, "programs")


main()
