// Runs three.js's WebGLRenderer (from an unpacked `three` npm package) against a recording stub
// WebGL 2 context and prints, as JSON lines, every program it links: {scene, vert, frag}.
// Used by gather_three.py; see its docstring. Usage: node gather_three_harness.mjs PACKAGE_DIR
// No GPU and no DOM: the stub answers the queries three makes (limits, precision, extensions,
// framebuffer status, compile/link status) as a WebGL 2 implementation on a desktop GPU would.
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const pkg = path.resolve(process.argv[2]);
const THREE = await import(pathToFileURL(path.join(pkg, 'src/Three.js')).href);
const { RectAreaLightUniformsLib } = await import(
    pathToFileURL(path.join(pkg, 'examples/jsm/lights/RectAreaLightUniformsLib.js')).href);

// GL enum values from the system GL headers, plus the WebGL-only ones.
const C = {};
for (const h of ['/usr/include/GL/glcorearb.h', '/usr/include/GL/glext.h', '/usr/include/GL/gl.h']) {
    if (!fs.existsSync(h)) continue;
    for (const m of fs.readFileSync(h, 'utf8').matchAll(/^#define GL_(\w+)\s+(0x[0-9A-Fa-f]+|\d+)\s*$/gm)) {
        if (!(m[1] in C)) C[m[1]] = Number(m[2]);
    }
}
Object.assign(C, { UNPACK_FLIP_Y_WEBGL: 0x9240, UNPACK_PREMULTIPLY_ALPHA_WEBGL: 0x9241,
    CONTEXT_LOST_WEBGL: 0x9242, UNPACK_COLORSPACE_CONVERSION_WEBGL: 0x9243, BROWSER_DEFAULT_WEBGL: 0x9244 });

const PARAMS = {
    [C.MAX_TEXTURE_IMAGE_UNITS]: 16, [C.MAX_VERTEX_TEXTURE_IMAGE_UNITS]: 16, [C.MAX_TEXTURE_SIZE]: 16384,
    [C.MAX_CUBE_MAP_TEXTURE_SIZE]: 16384, [C.MAX_VERTEX_ATTRIBS]: 16, [C.MAX_VERTEX_UNIFORM_VECTORS]: 4096,
    [C.MAX_VARYING_VECTORS]: 30, [C.MAX_FRAGMENT_UNIFORM_VECTORS]: 1024, [C.MAX_SAMPLES]: 4, [C.SAMPLES]: 4,
    [C.MAX_COMBINED_TEXTURE_IMAGE_UNITS]: 32, [C.VERSION]: 'WebGL 2.0 (OpenGL ES 3.0 Chromium)',
    [C.SHADING_LANGUAGE_VERSION]: 'WebGL GLSL ES 3.00', [C.MAX_ARRAY_TEXTURE_LAYERS]: 2048,
    [C.MAX_3D_TEXTURE_SIZE]: 2048, [C.MAX_DRAW_BUFFERS]: 8, [C.MAX_COLOR_ATTACHMENTS]: 8,
    [C.MAX_UNIFORM_BUFFER_BINDINGS]: 24, [C.MAX_RENDERBUFFER_SIZE]: 16384,
    [C.IMPLEMENTATION_COLOR_READ_FORMAT]: C.RGBA, [C.IMPLEMENTATION_COLOR_READ_TYPE]: C.UNSIGNED_BYTE,
    [C.MAX_TEXTURE_MAX_ANISOTROPY_EXT]: 16,
};
const EXTENSIONS = ['EXT_color_buffer_float', 'EXT_color_buffer_half_float', 'EXT_float_blend',
    'EXT_texture_filter_anisotropic', 'OES_texture_float_linear', 'WEBGL_lose_context',
    'EXT_texture_compression_bptc', 'WEBGL_compressed_texture_s3tc', 'WEBGL_compressed_texture_s3tc_srgb',
    'EXT_texture_compression_rgtc', 'EXT_disjoint_timer_query_webgl2', 'OVR_multiview2'];

let programs = [];
let nextId = 1;
function stubObject(extra = {}) { return Object.assign({ __id: nextId++ }, extra); }

function makeGL(canvas) {
    const base = {
        canvas, drawingBufferWidth: canvas.width, drawingBufferHeight: canvas.height,
        drawingBufferColorSpace: 'srgb', unpackColorSpace: 'srgb',
        getContextAttributes: () => ({ alpha: true, antialias: false, depth: true, stencil: false,
            premultipliedAlpha: true, preserveDrawingBuffer: false, powerPreference: 'default',
            failIfMajorPerformanceCaveat: false, xrCompatible: false }),
        isContextLost: () => false,
        getSupportedExtensions: () => EXTENSIONS.slice(),
        getExtension: (name) => EXTENSIONS.includes(name) ? new Proxy({}, { get: (t, p) =>
            typeof p === 'string' && /^[A-Z0-9_]+$/.test(p) ? (C[p] ?? C[p.replace(/_(EXT|OES|WEBGL|OVR|KHR)$/, '')] ?? 0x9000)
                : (typeof p === 'string' ? () => stubObject() : undefined) }) : null,
        getParameter: (p) => {
            if (p === C.VIEWPORT || p === C.SCISSOR_BOX) return new Int32Array([0, 0, canvas.width, canvas.height]);
            if (p === C.COLOR_CLEAR_VALUE) return new Float32Array([0, 0, 0, 0]);
            if (p in PARAMS) return PARAMS[p];
            return 0;
        },
        getShaderPrecisionFormat: () => ({ rangeMin: 127, rangeMax: 127, precision: 23 }),
        createShader: (type) => stubObject({ type, source: '' }),
        shaderSource: (sh, src) => { sh.source = src; },
        getShaderParameter: (sh, p) => p === C.COMPILE_STATUS ? true : 0,
        getShaderInfoLog: () => '',
        getShaderSource: (sh) => sh.source,
        createProgram: () => stubObject({ shaders: [] }),
        attachShader: (prog, sh) => { prog.shaders.push(sh); },
        linkProgram: (prog) => {
            const v = prog.shaders.find((s) => s.type === C.VERTEX_SHADER);
            const f = prog.shaders.find((s) => s.type === C.FRAGMENT_SHADER);
            programs.push({ vert: v.source, frag: f.source });
        },
        getProgramParameter: (prog, p) => (p === C.LINK_STATUS || p === C.VALIDATE_STATUS) ? true : 0,
        getProgramInfoLog: () => '',
        getAttribLocation: () => -1,
        getUniformLocation: () => null,
        getUniformBlockIndex: () => 0xFFFFFFFF,
        checkFramebufferStatus: () => C.FRAMEBUFFER_COMPLETE,
        getError: () => 0,
        fenceSync: () => stubObject(), clientWaitSync: () => C.ALREADY_SIGNALED,
        getSyncParameter: () => C.SIGNALED,
    };
    return new Proxy(base, {
        get(t, p) {
            if (p in t) return t[p];
            if (typeof p !== 'string') return undefined;
            if (/^[A-Z0-9_]+$/.test(p)) return C[p] ?? 0x9000;
            if (/^create/.test(p)) return () => stubObject();
            if (/^is[A-Z]/.test(p)) return () => true;
            return () => undefined;
        },
    });
}

const canvas = { width: 640, height: 480, style: {}, addEventListener() {}, removeEventListener() {},
    getContext() { return gl; } };
const gl = makeGL(canvas);

// --- scenes -------------------------------------------------------------------------------------
const T = THREE;
function tex(opts = {}) {
    const t = new T.DataTexture(new Uint8Array(16 * 4).fill(255), 4, 4);
    Object.assign(t, opts);
    t.needsUpdate = true;
    return t;
}
function floatTex(opts = {}) {
    const t = new T.DataTexture(new Float32Array(8 * 4 * 4).fill(1), 8, 4, T.RGBAFormat, T.FloatType);
    Object.assign(t, opts);
    t.needsUpdate = true;
    return t;
}
const box = () => new T.BoxGeometry(1, 1, 1);
const lights = {
    none: () => [],
    ambdir: () => [new T.AmbientLight(0x404040), new T.DirectionalLight(0xffffff, 1)],
    all: () => {
        const spot = new T.SpotLight(0xffffff, 1);
        const area = new T.RectAreaLight(0xffffff, 1, 2, 2);
        return [new T.AmbientLight(0x404040), new T.HemisphereLight(0xffffff, 0x444444),
            new T.DirectionalLight(0xffffff, 1), new T.DirectionalLight(0xff0000, 0.5),
            new T.PointLight(0xffffff, 1), spot, area, new T.LightProbe()];
    },
    shadows: () => {
        const d = new T.DirectionalLight(0xffffff, 1); d.castShadow = true;
        const p = new T.PointLight(0xffffff, 1); p.castShadow = true;
        const s = new T.SpotLight(0xffffff, 1); s.castShadow = true;
        return [new T.AmbientLight(0x404040), d, p, s];
    },
    spotmap: () => {
        const s = new T.SpotLight(0xffffff, 1); s.castShadow = true; s.map = tex();
        return [s];
    },
};
function meshWith(mat, geom = box()) { return new T.Mesh(geom, mat); }
function skinned(mat) {
    const g = new T.CylinderGeometry(0.5, 0.5, 2, 8, 4);
    const n = g.attributes.position.count;
    g.setAttribute('skinIndex', new T.Uint16BufferAttribute(new Uint16Array(n * 4), 4));
    g.setAttribute('skinWeight', new T.Float32BufferAttribute(new Float32Array(n * 4).fill(0.25), 4));
    const bones = [new T.Bone(), new T.Bone()];
    bones[0].add(bones[1]);
    const m = new T.SkinnedMesh(g, mat);
    m.add(bones[0]);
    m.bind(new T.Skeleton(bones));
    return m;
}
function morphed(mat, normals = true, colors = false) {
    const g = box();
    const p = g.attributes.position;
    g.morphAttributes.position = [p.clone(), p.clone()];
    if (normals) g.morphAttributes.normal = [g.attributes.normal.clone(), g.attributes.normal.clone()];
    if (colors) {
        g.setAttribute('color', new T.Float32BufferAttribute(new Float32Array(p.count * 3).fill(1), 3));
        g.morphAttributes.color = [g.attributes.color.clone(), g.attributes.color.clone()];
    }
    const m = new T.Mesh(g, mat);
    m.updateMorphTargets();
    m.morphTargetInfluences[0] = 0.5;
    return m;
}
function instanced(mat, colors = false) {
    const m = new T.InstancedMesh(box(), mat, 4);
    for (let i = 0; i < 4; i++) m.setMatrixAt(i, new T.Matrix4().makeTranslation(i, 0, 0));
    if (colors) for (let i = 0; i < 4; i++) m.setColorAt(i, new T.Color(1, 0, 0));
    return m;
}
function batched(mat) {
    const m = new T.BatchedMesh(4, 512, 1024, mat);
    const id = m.addGeometry(box());
    m.addInstance(id);
    return m;
}
function vcolored(mat, size = 3) {
    const g = box();
    g.setAttribute('color', new T.Float32BufferAttribute(new Float32Array(g.attributes.position.count * size).fill(1), size));
    return new T.Mesh(g, mat);
}
function uv1(mat) {
    const g = box();
    g.setAttribute('uv1', g.attributes.uv.clone());
    return new T.Mesh(g, mat);
}
const allMaps = () => ({ map: tex(), normalMap: tex(), aoMap: tex(), emissiveMap: tex(), alphaMap: tex(),
    bumpMap: tex(), displacementMap: tex(), lightMap: tex() });
const stdMaps = () => ({ ...allMaps(), roughnessMap: tex(), metalnessMap: tex(), emissive: new T.Color(1, 1, 1) });
const envEquirect = () => { const t = floatTex(); t.mapping = T.EquirectangularReflectionMapping; return t; };
const envCube = () => { const imgs = []; for (let i = 0; i < 6; i++) imgs.push({ width: 4, height: 4, data: new Uint8Array(64) });
    const c = new T.CubeTexture(imgs); c.isDataTexture = false; c.needsUpdate = true; return c; };

// name -> { objects, lights, fog, background, renderer settings, environment }
const S = [];
const add = (name, objects, o = {}) => S.push({ name, objects, ...o });
const M = (cls, params) => new T[cls](params);

for (const cls of ['MeshBasicMaterial', 'MeshLambertMaterial', 'MeshPhongMaterial', 'MeshStandardMaterial',
    'MeshPhysicalMaterial', 'MeshToonMaterial', 'MeshNormalMaterial', 'MeshMatcapMaterial', 'MeshDepthMaterial',
    'ShadowMaterial']) {
    const lit = !['MeshBasicMaterial', 'MeshNormalMaterial', 'MeshMatcapMaterial', 'MeshDepthMaterial',
        'MeshDistanceMaterial'].includes(cls);
    add(`${cls}.default`, () => [meshWith(M(cls))], { lights: lit ? 'ambdir' : 'none' });
}
add('MeshBasicMaterial.maps', () => [uv1(M('MeshBasicMaterial', { map: tex(), aoMap: tex(), lightMap: tex(), alphaMap: tex(),
    specularMap: tex(), envMap: envCube(), alphaTest: 0.5 }))]);
add('MeshBasicMaterial.fog_vcolor', () => [vcolored(M('MeshBasicMaterial', { vertexColors: true, transparent: true }), 4)], { fog: 'linear' });
add('MeshLambertMaterial.maps_all_lights', () => [meshWith(M('MeshLambertMaterial', { ...allMaps(), specularMap: tex(), envMap: envCube(), emissive: new T.Color(1, 0, 0) }))], { lights: 'all' });
add('MeshLambertMaterial.flat_fogexp2', () => [meshWith(M('MeshLambertMaterial', { flatShading: true }))], { lights: 'ambdir', fog: 'exp2' });
add('MeshPhongMaterial.maps_all_lights', () => [meshWith(M('MeshPhongMaterial', { ...allMaps(), specularMap: tex(), envMap: envCube(), combine: T.MixOperation, normalMapType: T.ObjectSpaceNormalMap }))], { lights: 'all' });
add('MeshPhongMaterial.shadows_pcf', () => [Object.assign(meshWith(M('MeshPhongMaterial')), { receiveShadow: true, castShadow: true })], { lights: 'shadows', shadowType: 'PCFShadowMap' });
add('MeshPhongMaterial.shadows_vsm', () => [Object.assign(meshWith(M('MeshPhongMaterial')), { receiveShadow: true, castShadow: true })], { lights: 'shadows', shadowType: 'VSMShadowMap' });
add('MeshPhongMaterial.shadows_basic_spotmap', () => [Object.assign(meshWith(M('MeshPhongMaterial')), { receiveShadow: true, castShadow: true })], { lights: 'spotmap', shadowType: 'BasicShadowMap' });
add('MeshStandardMaterial.maps_all_lights', () => [meshWith(M('MeshStandardMaterial', { ...stdMaps(), envMap: envEquirect() }))], { lights: 'all' });
add('MeshStandardMaterial.envcube', () => [meshWith(M('MeshStandardMaterial', { envMap: envCube(), roughness: 0.3 }))], { lights: 'none' });
add('MeshStandardMaterial.scene_env_bg', () => [meshWith(M('MeshStandardMaterial', { normalMap: tex() }))], { lights: 'ambdir', environment: 'equirect', background: 'equirect' });
add('MeshStandardMaterial.skinned_shadow', () => [Object.assign(skinned(M('MeshStandardMaterial', { map: tex() })), { castShadow: true, receiveShadow: true })], { lights: 'shadows', shadowType: 'PCFShadowMap' });
add('MeshStandardMaterial.morph', () => [morphed(M('MeshStandardMaterial'), true, true)], { lights: 'ambdir' });
add('MeshStandardMaterial.morph_vcolor', () => [morphed(M('MeshStandardMaterial', { vertexColors: true }), false, true)], { lights: 'ambdir' });
add('MeshStandardMaterial.instanced', () => [instanced(M('MeshStandardMaterial'), true)], { lights: 'ambdir' });
add('MeshStandardMaterial.batched', () => [batched(M('MeshStandardMaterial'))], { lights: 'ambdir' });
add('MeshStandardMaterial.clipping', () => [meshWith(M('MeshStandardMaterial', { clippingPlanes: [new T.Plane(new T.Vector3(1, 0, 0), 0), new T.Plane(new T.Vector3(0, 1, 0), 0)], clipIntersection: true }))], { lights: 'ambdir' });
add('MeshStandardMaterial.global_clipping', () => [meshWith(M('MeshStandardMaterial'))], { lights: 'ambdir', globalClipping: true });
add('MeshStandardMaterial.logdepth', () => [meshWith(M('MeshStandardMaterial', { map: tex() }))], { lights: 'ambdir', logdepth: true });
add('MeshStandardMaterial.flat_alphahash_dither', () => [meshWith(M('MeshStandardMaterial', { flatShading: true, alphaHash: true, dithering: true, side: T.DoubleSide }))], { lights: 'ambdir' });
add('MeshStandardMaterial.premultiplied_alphatobcoverage', () => [meshWith(M('MeshStandardMaterial', { premultipliedAlpha: true, alphaToCoverage: true, transparent: true }))], { lights: 'ambdir' });
add('MeshStandardMaterial.tangent_normalmap', () => { const g = box(); g.computeTangents(); return [new T.Mesh(g, M('MeshStandardMaterial', { normalMap: tex() }))]; }, { lights: 'ambdir' });
for (const tm of ['LinearToneMapping', 'ReinhardToneMapping', 'CineonToneMapping', 'ACESFilmicToneMapping', 'AgXToneMapping', 'NeutralToneMapping'])
    add(`MeshStandardMaterial.${tm}`, () => [meshWith(M('MeshStandardMaterial', { map: tex() }))], { lights: 'ambdir', toneMapping: tm });
add('MeshStandardMaterial.linear_output', () => [meshWith(M('MeshStandardMaterial', { map: tex() }))], { lights: 'ambdir', outputColorSpace: 'LinearSRGBColorSpace' });
add('MeshPhysicalMaterial.all_features', () => [uv1(M('MeshPhysicalMaterial', { ...stdMaps(), envMap: envEquirect(),
    clearcoat: 1, clearcoatMap: tex(), clearcoatRoughnessMap: tex(), clearcoatNormalMap: tex(),
    sheen: 1, sheenColorMap: tex(), sheenRoughnessMap: tex(), iridescence: 1, iridescenceMap: tex(), iridescenceThicknessMap: tex(),
    anisotropy: 1, anisotropyMap: tex(), specularIntensityMap: tex(), specularColorMap: tex(), dispersion: 0.1 }))], { lights: 'all' });
add('MeshPhysicalMaterial.transmission', () => [meshWith(M('MeshStandardMaterial')), meshWith(M('MeshPhysicalMaterial', { transmission: 1, thickness: 1, transmissionMap: tex(), thicknessMap: tex(), attenuationDistance: 1, ior: 1.4, dispersion: 0.5 }))], { lights: 'ambdir', environment: 'equirect' });
add('MeshPhysicalMaterial.clearcoat_shadows', () => [Object.assign(meshWith(M('MeshPhysicalMaterial', { clearcoat: 1, sheen: 0.5 })), { receiveShadow: true, castShadow: true })], { lights: 'shadows', shadowType: 'PCFShadowMap' });
add('MeshToonMaterial.gradient_all_lights', () => [meshWith(M('MeshToonMaterial', { ...allMaps(), gradientMap: tex() }))], { lights: 'all' });
add('MeshNormalMaterial.maps', () => [meshWith(M('MeshNormalMaterial', { normalMap: tex(), bumpMap: tex(), displacementMap: tex(), flatShading: true }))]);
add('MeshMatcapMaterial.maps', () => [meshWith(M('MeshMatcapMaterial', { matcap: tex(), map: tex(), normalMap: tex(), alphaMap: tex() }))], { fog: 'linear' });
add('MeshDepthMaterial.rgba', () => [meshWith(M('MeshDepthMaterial', { depthPacking: T.RGBADepthPacking, map: tex(), alphaMap: tex(), displacementMap: tex() }))]);
add('LineBasicMaterial.default', () => [new T.Line(box(), M('LineBasicMaterial', { color: 0xff0000 }))]);
add('LineBasicMaterial.vcolor_fog', () => { const g = box(); g.setAttribute('color', g.attributes.position.clone()); return [new T.LineSegments(g, M('LineBasicMaterial', { vertexColors: true, map: tex() }))]; }, { fog: 'exp2' });
add('LineDashedMaterial.default', () => { const l = new T.Line(box().toNonIndexed(), M('LineDashedMaterial', { dashSize: 0.1 })); l.computeLineDistances(); return [l]; });
add('PointsMaterial.default', () => [new T.Points(box(), M('PointsMaterial', { size: 2 }))]);
add('PointsMaterial.map_attenuation', () => [new T.Points(box(), M('PointsMaterial', { map: tex(), alphaMap: tex(), sizeAttenuation: false, vertexColors: true, alphaTest: 0.1 }))], { fog: 'linear' });
add('SpriteMaterial.default', () => [new T.Sprite(M('SpriteMaterial', { map: tex() }))]);
add('SpriteMaterial.alphamap_fog', () => [new T.Sprite(M('SpriteMaterial', { map: tex(), alphaMap: tex(), sizeAttenuation: false, rotation: 1 }))], { fog: 'exp2' });
add('ShadowMaterial.shadows', () => [Object.assign(meshWith(M('ShadowMaterial', { opacity: 0.5 })), { receiveShadow: true })], { lights: 'shadows', shadowType: 'PCFShadowMap' });
add('background.cube', () => [], { background: 'cube' });
add('background.texture', () => [], { background: 'texture' });
add('background.equirect_blur', () => [], { background: 'equirect', backgroundBlurriness: 0.5 });
add('ShaderMaterial.glsl1', () => [meshWith(new T.ShaderMaterial({
    uniforms: { uTime: { value: 0 } }, defines: { FOO: 2 },
    vertexShader: 'uniform float uTime;\nvarying vec2 vUv;\nvoid main() {\n  vUv = uv;\n  gl_Position = projectionMatrix * modelViewMatrix * vec4(position + normal * float(FOO) * uTime, 1.0);\n}\n',
    fragmentShader: 'varying vec2 vUv;\nvoid main() {\n  gl_FragColor = vec4(vUv, 0.0, 1.0);\n  #include <tonemapping_fragment>\n  #include <colorspace_fragment>\n}\n' }))]);
add('RawShaderMaterial.glsl3', () => [meshWith(new T.RawShaderMaterial({
    glslVersion: T.GLSL3,
    vertexShader: 'precision highp float;\nuniform mat4 modelViewMatrix;\nuniform mat4 projectionMatrix;\nin vec3 position;\nout vec3 vPos;\nvoid main() {\n  vPos = position;\n  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);\n}\n',
    fragmentShader: 'precision highp float;\nin vec3 vPos;\nout vec4 outColor;\nvoid main() {\n  outColor = vec4(vPos * 0.5 + 0.5, 1.0);\n}\n' }))]);

// PMREM filtering: equirect / cubemap sources and fromScene
add('pmrem.equirect', () => [], { pmrem: 'equirect' });
add('pmrem.cube', () => [], { pmrem: 'cube' });
add('pmrem.scene', () => [], { pmrem: 'scene' });

const results = [];
for (const s of S) {
    const renderer = new T.WebGLRenderer({ canvas, context: gl, antialias: false, logarithmicDepthBuffer: !!s.logdepth });
    renderer.setSize(640, 480, false);
    if (s.shadowType) { renderer.shadowMap.enabled = true; renderer.shadowMap.type = T[s.shadowType]; }
    if (s.toneMapping) renderer.toneMapping = T[s.toneMapping];
    if (s.outputColorSpace) renderer.outputColorSpace = T[s.outputColorSpace];
    if (s.globalClipping) renderer.clippingPlanes = [new T.Plane(new T.Vector3(0, 0, 1), 1)];
    const scene = new T.Scene();
    const camera = new T.PerspectiveCamera(50, 640 / 480, 0.1, 100);
    camera.position.set(0, 0, 5);
    if ((s.lights || 'none') === 'all') RectAreaLightUniformsLib.init();
    for (const l of lights[s.lights || 'none']()) scene.add(l);
    for (const o of s.objects()) scene.add(o);
    if (s.fog === 'linear') scene.fog = new T.Fog(0xffffff, 1, 10);
    if (s.fog === 'exp2') scene.fog = new T.FogExp2(0xffffff, 0.1);
    if (s.environment === 'equirect') scene.environment = envEquirect();
    if (s.background === 'equirect') scene.background = envEquirect();
    if (s.background === 'cube') scene.background = envCube();
    if (s.background === 'texture') scene.background = tex();
    if (s.backgroundBlurriness) scene.backgroundBlurriness = s.backgroundBlurriness;
    programs = [];
    try {
        if (s.pmrem) {
            const pmrem = new T.PMREMGenerator(renderer);
            if (s.pmrem === 'equirect') pmrem.fromEquirectangular(envEquirect());
            if (s.pmrem === 'cube') pmrem.fromCubemap(envCube());
            if (s.pmrem === 'scene') { const sc = new T.Scene(); sc.add(meshWith(M('MeshBasicMaterial'))); pmrem.fromScene(sc, 0.04); }
        } else {
            renderer.render(scene, camera);
            renderer.render(scene, camera);
        }
    } catch (e) {
        process.stderr.write(`${s.name}: ${e.stack}\n`);
    }
    for (const p of programs) results.push({ scene: s.name, vert: p.vert, frag: p.frag });
    renderer.dispose();
}
for (const r of results) process.stdout.write(JSON.stringify(r) + '\n');
