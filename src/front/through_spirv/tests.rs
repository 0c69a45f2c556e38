//! The route through SPIR-V on small programs: what each of its passes makes of glslang's SPIR-V.

use super::*;

#[test]
fn the_rewrite_is_read_as_vulkan_glsl_with_its_lines_kept() {
    let text = "#version 450\nlayout(location = 0) in vec4 gl_Vertex;\n#line 40\nvoid main() {}\n";
    let vulkan = as_vulkan_glsl(text, "#extension GL_EXT_nonuniform_qualifier : enable\n");
    assert_eq!(
        vulkan,
        "#version 450\n#extension GL_EXT_spirv_intrinsics : enable\n#extension GL_EXT_samplerless_texture_functions : enable\n\
         #extension GL_EXT_nonuniform_qualifier : enable\n#line 2\nlayout(location = 0) in vec4 gl_Vertex;\n        \nvoid main() {}\n"
    );
}

/// The rewrite blanks `#extension` lines; a Vulkan program's are enabled again (in any
/// conditional group, not in comments, not where disabled) and it compiles for its own
/// Vulkan version: subgroup operations need SPIR-V 1.3.
#[test]
fn a_vulkan_rewrite_keeps_its_extensions_and_vulkan_version() {
    let original =
        "#version 450\n#extension GL_KHR_shader_subgroup_basic : require\n#ifdef RQ\n#extension GL_EXT_ray_query : enable\n#endif\n\
                    // #extension GL_EXT_commented_out : enable\n#extension GL_EXT_gone : disable\n";
    assert_eq!(extensions_enabled(original), "#extension GL_KHR_shader_subgroup_basic : enable\n#extension GL_EXT_ray_query : enable\n");
    let subgroups = "#version 450\n                                              \nlayout(local_size_x = 64) in;\n\
                     layout(std430, binding = 0) buffer B { uint n[]; } b;\n\
                     void main() { b.n[gl_LocalInvocationIndex] = gl_SubgroupSize; }\n";
    let stages = [(subgroups, StageKind::Compute)];
    let without = compile_rewritten(&stages, &Plan::default(), Dialect::Vulkan(VulkanVersion::V1_1), &[]).unwrap_err().message;
    assert!(without.contains("glslang makes no SPIR-V"), "the rewrite alone lacks the extension: {without}");
    // glslang compiles it with the extension (the subgroup's size is that of a subgroup of one).
    compile_rewritten(&stages, &Plan::default(), Dialect::Vulkan(VulkanVersion::V1_1), &[original]).expect("through SPIR-V");
    let samplerless = "#version 450\n\nlayout(binding = 0) uniform texture2D t;\nlayout(location = 0) out vec4 o;\n\
                       void main() { o = texelFetch(t, ivec2(gl_FragCoord.xy), 0); }\n";
    let stages = [(samplerless, StageKind::Fragment)];
    // Enabled for every rewrite: it reads subpass inputs so.
    compile_rewritten(&stages, &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
}

/// A function that can fall off its end (legal GLSL) and a declaration named `gl_…`
/// (the rewrite's fixed-function attribute): glslang compiles the rewrite, naga's SPIR-V
/// front reads it, and the module validates, with spans on the rewrite's lines.
#[test]
fn a_rewritten_stage_goes_through_spirv() {
    let text = "#version 450\nlayout(location = 0) in vec4 gl_Vertex;\nfloat f(float x) {\n    for (int i = 0; i < 2; i++) {\n        if (x < float(i)) return 1.0;\n    }\n}\nvoid main() {\n    gl_Position = gl_Vertex * f(gl_Vertex.x);\n}\n";
    let validated = compile_rewritten(&[(text, StageKind::Vertex)], &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
    let module = &validated[0].module;
    assert!(module.entry_points[0].function.arguments.iter().any(|a| a.name.as_deref() == Some("gl_Vertex")));
    let f = module.functions.iter().find(|(_, f)| f.name.as_deref() == Some("f")).expect("f").1;
    let lines: Vec<&str> = f.body.span_iter().filter_map(|(_, s)| s.to_range()).map(|r| &text[r]).collect();
    assert!(lines.contains(&"for (int i = 0; i < 2; i++) {"), "{lines:?}");
}

/// glslang writes `OpUndef` for what a function returns when its end is reachable; the
/// sampler splitter used to delete it with the instructions it blanks out, and naga
/// then met an undefined id.
#[test]
fn a_function_that_can_fall_off_its_end_keeps_its_undefined_value_beside_a_sampler() {
    let text = "#version 450\nlayout(binding = 0) uniform sampler2D tex;\nlayout(location = 0) in vec2 uv;\n\
                layout(location = 0) out vec4 c;\nvec4 pick(float x) {\n    if (x < 0.5) return vec4(1.0);\n    \
                else if (x < 2.0) return texture(tex, uv);\n}\nvoid main() { c = pick(uv.x); }\n";
    compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
}

/// A shadow sampler passed to a function that compares with it (`texture`, `textureGather`
/// with a reference) reaches the function as a depth texture and a comparison sampler.
#[test]
fn a_shadow_sampler_passed_to_a_function_compares_there() {
    let text = "#version 450\nlayout(binding = 0) uniform sampler2DShadow s;\nlayout(location = 0) in vec3 p;\n\
                layout(location = 0) out vec4 c;\nfloat pcf(sampler2DShadow t, vec3 q) { return texture(t, q) + textureGather(t, q.xy, q.z).x; }\n\
                void main() { c = vec4(pcf(s, p)); }\n";
    let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
    let module = &validated[0].module;
    let pcf = module.functions.iter().find(|(_, f)| f.name.as_deref() == Some("pcf")).expect("pcf").1;
    let kinds: Vec<&TypeInner> = pcf.arguments.iter().map(|a| &module.types[a.ty].inner).collect();
    assert!(kinds.iter().any(|k| matches!(k, TypeInner::Image { class: naga::ImageClass::Depth { .. }, .. })), "{kinds:?}");
    assert!(kinds.iter().any(|k| matches!(k, TypeInner::Sampler { comparison: true })), "{kinds:?}");
    let names: Vec<Option<&str>> = pcf.arguments.iter().map(|a| a.name.as_deref()).collect();
    assert_eq!(names, [Some("t"), Some("t_sampler"), Some("q")]);
}

/// The sampler split off a combined one takes a binding no other resource holds, the
/// same on every run (the splitter alone moved colliding bindings in hash-map order).
#[test]
fn split_samplers_take_bindings_no_other_resource_holds() {
    let text = "#version 450\nlayout(binding = 0) uniform sampler2D a;\nlayout(binding = 1) uniform sampler2D b;\n\
                layout(binding = 2) uniform U { vec4 k; } u;\nlayout(location = 0) out vec4 c;\n\
                void main() { c = texture(a, vec2(0.5)) + texture(b, vec2(0.5)) + u.k; }\n";
    let bindings = || {
        let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
        validated[0].module.global_variables.iter().filter_map(|(_, g)| g.binding.map(|b| (b.binding, g.name.clone()))).collect::<Vec<_>>()
    };
    let first = bindings();
    let mut numbers: Vec<u32> = first.iter().map(|(b, _)| *b).collect();
    numbers.sort_unstable();
    numbers.dedup();
    assert_eq!(numbers.len(), 5, "{first:?}");
    for _ in 0..4 {
        assert_eq!(bindings(), first);
    }
}

/// OpenGL GLSL matches varyings by name: an output and the next stage's input of one name
/// take one location, whatever order each stage declares them in.
#[test]
fn opengl_varyings_meet_by_name() {
    let mut files = Files::new();
    let vertex =
        files.add("a.vert", "#version 330 core\nout vec4 a;\nout float b;\nvoid main() { a = vec4(1.0); b = 2.0; gl_Position = a; }\n");
    let fragment = files.add("a.frag", "#version 330 core\nin float b;\nin vec4 a;\nout vec4 c;\nvoid main() { c = a * b; }\n");
    let ordered = [(vertex, StageKind::Vertex), (fragment, StageKind::Fragment)];
    let stages = compile(&files, &ordered, Dialect::OpenGl, &Plan::default()).expect("through SPIR-V");
    let location = |m: &Module, arguments: bool, name: &str| -> Option<u32> {
        let ep = &m.entry_points[0];
        let members: Vec<(Option<String>, Option<naga::Binding>)> = if arguments {
            ep.function.arguments.iter().map(|a| (a.name.clone(), a.binding.clone())).collect()
        } else {
            let ty = ep.function.result.as_ref()?.ty;
            let TypeInner::Struct { members, .. } = &m.types[ty].inner else { return None };
            members.iter().map(|s| (s.name.clone(), s.binding.clone())).collect()
        };
        members.into_iter().find(|(n, _)| n.as_deref() == Some(name)).and_then(|(_, b)| match b {
            Some(naga::Binding::Location { location, .. }) => Some(location),
            _ => None,
        })
    };
    for name in ["a", "b"] {
        let out = location(&stages[0].validated.module, false, name);
        assert!(out.is_some(), "{name} has a location");
        assert_eq!(out, location(&stages[1].validated.module, true, name), "{name}");
    }
}

/// An interface block's members are varyings at GL's locations: the block's, counted on
/// (a `vec4` takes one, a `mat2` two), a member's own and what follows it, with the
/// block's and the member's interpolation, named as the members.
#[test]
fn interface_blocks_become_one_varying_per_member() {
    let block = "layout(location = 2) BLOCK {\n    vec4 a;\n    flat ivec2 b;\n    layout(location = 7) vec2 c;\n    vec3 d;\n} s;\n";
    let vertex = format!(
        "#version 450\n{}void main() {{ s.a = vec4(1.0); s.b = ivec2(2); s.c = vec2(3.0); s.d = vec3(4.0); gl_Position = s.a; }}\n",
        block.replace("BLOCK", "out Block")
    );
    let fragment = format!(
        "#version 450\n{}layout(location = 0) out vec4 o;\nvoid main() {{ o = s.a + vec4(s.b, s.c) + s.d.xyzx; }}\n",
        block.replace("BLOCK", "in Block")
    );
    let stages = [(vertex.as_str(), StageKind::Vertex), (fragment.as_str(), StageKind::Fragment)];
    let validated = compile_rewritten(&stages, &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
    let location = |b: &Option<naga::Binding>| match b {
        Some(naga::Binding::Location { location, interpolation, .. }) => Some((*location, *interpolation)),
        _ => None,
    };
    let (flat, perspective) = (Some(naga::Interpolation::Flat), Some(naga::Interpolation::Perspective));
    let expected = [(2, perspective), (3, flat), (7, perspective), (8, perspective)];
    let vs = &validated[0].module;
    let result = vs.entry_points[0].function.result.as_ref().expect("outputs");
    let TypeInner::Struct { members, .. } = &vs.types[result.ty].inner else { panic!("a struct of outputs") };
    let outputs: Vec<_> = members.iter().filter_map(|m| location(&m.binding)).collect();
    assert_eq!(outputs, expected);
    let fs = &validated[1].module.entry_points[0].function;
    let inputs: Vec<_> = fs.arguments.iter().filter_map(|a| Some((a.name.clone()?, location(&a.binding)?))).collect();
    let names: Vec<&str> = inputs.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["a", "b", "c", "d"]);
    assert_eq!(inputs.iter().map(|(_, l)| *l).collect::<Vec<_>>(), expected);
}

/// std140 puts a `mat2` array's matrices 32 bytes apart and their columns 16; naga's IR
/// has 8-byte columns, so reading it as written would move every second column (silently
/// wrong SPIR-V once, refused since). Its columns are stored as `vec4`s: each matrix an
/// array of two, 32 bytes apart as in std140. A `mat4` array is read as it is.
#[test]
fn an_array_of_two_row_matrices_in_a_uniform_block_is_stored_as_columns() {
    let block = |members: &str| {
        format!(
            "#version 450\nlayout(std140, binding = 0) uniform Block {{ {members} }} b;\n\
             layout(location = 0) out vec4 c;\nvoid main() {{ c = vec4(b.m[1][1][1]) + b.x; }}\n"
        )
    };
    let two_rows = block("vec4 x; mat2 m[2];");
    let modules = compile_rewritten(&[(&two_rows, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("read as columns");
    let module = &modules[0].module;
    let member = module.types.iter().find_map(|(_, t)| match &t.inner {
        naga::TypeInner::Struct { members, .. } if t.name.as_deref() == Some("Block") => {
            members.iter().find(|m| m.name.as_deref() == Some("m")).cloned()
        }
        _ => None,
    });
    let member = member.expect("the block's m");
    let naga::TypeInner::Array { base, stride: 32, .. } = module.types[member.ty].inner else { panic!("{member:?}") };
    let naga::TypeInner::Array { base: column, stride: 16, .. } = module.types[base].inner else { panic!("{:?}", module.types[base]) };
    assert!(matches!(module.types[column].inner, naga::TypeInner::Vector { size: naga::VectorSize::Quad, .. }));
    assert_eq!(member.offset, 16);
    let mat4 = block("vec4 x; mat4 m[2];");
    compile_rewritten(&[(&mat4, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("mat4 arrays are read");
}

/// `index = 0` on the only colour output is an ordinary output in GL; naga takes a blend
/// source only as half of a dual-source pair.
#[test]
fn a_lone_index_zero_output_is_an_ordinary_colour() {
    let text = "#version 450\nlayout(location = 0, index = 0) out vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
    let result = validated[0].module.entry_points[0].function.result.as_ref().expect("a result");
    assert!(matches!(result.binding, Some(naga::Binding::Location { location: 0, blend_src: None, .. })), "{:?}", result.binding);
}

/// Varyings of aggregate type (an array, a matrix, a block member array; here a fragment
/// stage's inputs) reach naga as one scalar or vector input per element or column, at the
/// locations GL gives them, with their interpolation; the stage reads the array through a
/// private copy, so a run-time index still works.
#[test]
fn aggregate_varyings_become_one_input_per_element() {
    let text = "#version 450\nlayout(location = 0) in vec4 offsets[3];\nlayout(location = 3) in mat2 spin;\n\
                layout(location = 5) flat in ivec2 cells[2];\nlayout(location = 7) in Surface { vec2 uv[2]; float w; } s;\n\
                layout(location = 0) out vec4 c;\n\
                void main() { c = offsets[cells[0].x] + vec4(spin * s.uv[1], s.w, float(cells[1].y)); }\n";
    let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::OpenGl, &[]).expect("through SPIR-V");
    let module = &validated[0].module;
    let inputs: Vec<(String, u32, bool)> = module.entry_points[0]
        .function
        .arguments
        .iter()
        .filter_map(|a| match a.binding {
            Some(naga::Binding::Location { location, interpolation, .. }) => {
                Some((a.name.clone().unwrap_or_default(), location, interpolation == Some(naga::Interpolation::Flat)))
            }
            _ => None,
        })
        .collect();
    let expected: Vec<(String, u32, bool)> = [
        ("offsets_0", 0, false),
        ("offsets_1", 1, false),
        ("offsets_2", 2, false),
        ("spin_0", 3, false),
        ("spin_1", 4, false),
        ("cells_0", 5, true),
        ("cells_1", 6, true),
        ("uv_0", 7, false),
        ("uv_1", 8, false),
        ("w", 9, false),
    ]
    .iter()
    .map(|(n, l, f)| (n.to_string(), *l, *f))
    .collect();
    let mut sorted = inputs.clone();
    sorted.sort_by_key(|(_, l, _)| *l);
    assert_eq!(sorted, expected);
    assert!(
        module.global_variables.iter().any(|(_, g)| g.space == naga::AddressSpace::Private && g.name.as_deref() == Some("offsets")),
        "the array stays as a private copy"
    );
}

/// Buffer textures and buffer images become storage buffers of 4-vectors: `texelFetch` and
/// `imageLoad` read an element, `imageStore` writes one, `imageSize` is the array's length.
#[test]
fn texel_buffers_are_read_and_written_as_storage_buffers() {
    let text = "#version 450\n\
                layout(local_size_x = 64) in;\n\
                layout(set = 0, binding = 0) uniform usamplerBuffer indices;\n\
                layout(set = 0, binding = 1, rgba32f) uniform imageBuffer points;\n\
                layout(set = 0, binding = 2, r32i) uniform readonly iimageBuffer weights;\n\
                void main() {\n\
                    int i = int(gl_GlobalInvocationID.x) % imageSize(points);\n\
                    uvec4 n = texelFetch(indices, i);\n\
                    imageStore(points, i, imageLoad(points, int(n.x)) * float(imageLoad(weights, i).x));\n\
                }\n";
    let validated = compile_rewritten(&[(text, StageKind::Compute)], &Plan::default(), Dialect::Vulkan(VulkanVersion::V1_0), &[])
        .expect("through SPIR-V");
    let m = &validated[0].module;
    let storage: Vec<(String, naga::StorageAccess)> = m
        .global_variables
        .iter()
        .filter_map(|(_, g)| match g.space {
            AddressSpace::Storage { access } => Some((g.name.clone().unwrap_or_default(), access)),
            _ => None,
        })
        .collect();
    let access = |name: &str| storage.iter().find(|(n, _)| n == name).map(|(_, a)| *a);
    assert_eq!(access("indices"), Some(naga::StorageAccess::LOAD), "a buffer texture is read-only: {storage:?}");
    assert_eq!(access("points"), Some(naga::StorageAccess::LOAD | naga::StorageAccess::STORE));
    assert_eq!(access("weights"), Some(naga::StorageAccess::LOAD));
    assert!(!m.types.iter().any(|(_, t)| matches!(t.inner, TypeInner::Image { .. })), "no image is left");
    let functions = m.functions.iter().map(|(_, f)| f).chain(m.entry_points.iter().map(|e| &e.function));
    let lengths = functions.flat_map(|f| f.expressions.iter()).filter(|(_, e)| matches!(e, naga::Expression::ArrayLength(_))).count();
    assert_eq!(lengths, 1, "imageSize is the array's length");
}

/// Subpass inputs, plain and multisampled, declared through a macro (the GLSL route's rewrite
/// does not see those) become 2D textures read at the fragment's pixel.
#[test]
fn subpass_inputs_are_textures_read_at_the_fragments_pixel() {
    let text = "#version 450\n#define INPUT subpassInput\n\
                layout(input_attachment_index = 0, set = 0, binding = 0) uniform INPUT color;\n\
                layout(input_attachment_index = 1, set = 0, binding = 1) uniform subpassInputMS moments;\n\
                layout(location = 0) out vec4 o;\n\
                void main() { o = subpassLoad(color) + subpassLoad(moments, 2); }\n";
    let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::Vulkan(VulkanVersion::V1_0), &[])
        .expect("through SPIR-V");
    let m = &validated[0].module;
    let images: Vec<(String, bool)> = m
        .global_variables
        .iter()
        .filter_map(|(_, g)| match m.types[g.ty].inner {
            TypeInner::Image { dim: naga::ImageDimension::D2, class: naga::ImageClass::Sampled { multi, .. }, .. } => {
                Some((g.name.clone().unwrap_or_default(), multi))
            }
            _ => None,
        })
        .collect();
    assert_eq!(images, [("color".to_string(), false), ("moments".to_string(), true)]);
    let frag_coord = m.entry_points[0]
        .function
        .arguments
        .iter()
        .any(|a| matches!(a.binding, Some(naga::Binding::BuiltIn(naga::BuiltIn::Position { .. }))));
    assert!(frag_coord, "the stage reads gl_FragCoord");
    let functions = m.functions.iter().map(|(_, f)| f).chain(m.entry_points.iter().map(|e| &e.function));
    let loads: Vec<bool> = functions
        .flat_map(|f| f.expressions.iter())
        .filter_map(|(_, e)| match e {
            naga::Expression::ImageLoad { sample, level, .. } => Some(sample.is_some() && level.is_none()),
            _ => None,
        })
        .collect();
    assert_eq!(loads.iter().filter(|s| **s).count(), 1, "one load of a sample: {loads:?}");
    assert_eq!(loads.len(), 2);
}

/// `isnan`/`isinf`, which WGSL lacks, are computed from the float's bits, scalar and vector.
#[test]
fn float_tests_are_computed_from_bits() {
    let text = "#version 450\nlayout(location = 0) in vec3 v;\nlayout(location = 0) out vec4 o;\n\
                void main() { o = vec4(isnan(v.x) ? 1.0 : 0.0, any(isinf(v)) ? 1.0 : 0.0, 0.0, 1.0); }\n";
    let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::Vulkan(VulkanVersion::V1_0), &[])
        .expect("through SPIR-V");
    let m = &validated[0].module;
    let expressions =
        || m.functions.iter().map(|(_, f)| f).chain(m.entry_points.iter().map(|e| &e.function)).flat_map(|f| f.expressions.iter());
    assert!(!expressions().any(|(_, e)| matches!(
        e,
        naga::Expression::Relational { fun: naga::RelationalFunction::IsNan | naga::RelationalFunction::IsInf, .. }
    )));
    let literal = |bits: u32| {
        m.global_expressions.iter().any(|(_, e)| matches!(e, naga::Expression::Literal(naga::Literal::U32(b)) if *b == bits))
            || expressions().any(|(_, e)| matches!(e, naga::Expression::Literal(naga::Literal::U32(b)) if *b == bits))
    };
    assert!(literal(0x7fff_ffff) && literal(0x7f80_0000), "the magnitude mask and infinity's bits");
    let comparisons: Vec<naga::BinaryOperator> = expressions()
        .filter_map(|(_, e)| match e {
            naga::Expression::Binary { op: op @ (naga::BinaryOperator::Greater | naga::BinaryOperator::Equal), .. } => Some(*op),
            _ => None,
        })
        .collect();
    assert!(comparisons.contains(&naga::BinaryOperator::Greater) && comparisons.contains(&naga::BinaryOperator::Equal), "{comparisons:?}");
}

/// `gl_PointCoord` is the centre of a one-pixel point, as on the GLSL route (N0104).
#[test]
fn the_point_coordinate_is_the_centre() {
    let text = "#version 450\nlayout(binding = 0) uniform sampler2D sprite;\nlayout(location = 0) out vec4 o;\n\
                void main() { o = texture(sprite, gl_PointCoord) * vec4(gl_PointCoord, 0.0, 1.0); }\n";
    let validated = compile_rewritten(&[(text, StageKind::Fragment)], &Plan::default(), Dialect::Vulkan(VulkanVersion::V1_0), &[])
        .expect("through SPIR-V");
    let m = &validated[0].module;
    let arguments = &m.entry_points[0].function.arguments;
    assert!(!arguments.iter().any(|a| matches!(a.binding, Some(naga::Binding::BuiltIn(naga::BuiltIn::PointCoord)))), "{arguments:?}");
    let g = m
        .global_variables
        .iter()
        .find(|(_, g)| g.name.as_deref() == Some("gl_PointCoord"))
        .map(|(_, g)| g)
        .expect("a private gl_PointCoord");
    assert_eq!(g.space, AddressSpace::Private);
    // naga reads the initialiser as a constant: its value is the composite of two halves.
    let mut init = g.init.expect("initialised");
    while let naga::Expression::Constant(c) = m.global_expressions[init] {
        init = m.constants[c].init;
    }
    let naga::Expression::Compose { components, .. } = &m.global_expressions[init] else { panic!("{:?}", m.global_expressions[init]) };
    for c in components {
        let mut c = *c;
        while let naga::Expression::Constant(k) = m.global_expressions[c] {
            c = m.constants[k].init;
        }
        assert!(matches!(m.global_expressions[c], naga::Expression::Literal(naga::Literal::F32(h)) if h == 0.5));
    }
}

/// One Vulkan GLSL stage through SPIR-V as `compile` takes a program: its module.
fn vulkan_stage(text: &str, kind: StageKind, version: VulkanVersion) -> Module {
    let mut files = Files::new();
    let file = files.add("a.glsl", text);
    let stages = compile(&files, &[(file, kind)], Dialect::Vulkan(version), &Plan::default()).expect("through SPIR-V");
    stages.into_iter().next().expect("a stage").validated.module
}

/// Arrays of textures and samplers become one binding per element (4 for a runtime-sized
/// one), resources above them move up, and a lookup at a run-time index reads every
/// element (every pair for a texture and a sampler chosen apart) and keeps the indexed one.
#[test]
fn arrays_of_textures_become_one_binding_per_element() {
    let text = "#version 450\n#extension GL_EXT_nonuniform_qualifier : require\n\
                layout(location = 0) in vec2 uv;\nlayout(location = 1) flat in uint id;\nlayout(location = 0) out vec4 o;\n\
                layout(set = 0, binding = 2) uniform sampler2D textures[];\n\
                layout(set = 0, binding = 3) uniform texture2D planes[2];\nlayout(set = 0, binding = 4) uniform sampler samplers[2];\n\
                layout(set = 0, binding = 5) uniform Params { vec4 tint; } params;\n\
                void main() {\n    o = texture(textures[nonuniformEXT(id)], uv) * params.tint + texture(textures[1], uv);\n    \
                o += texture(nonuniformEXT(sampler2D(planes[id], samplers[id + 1u])), uv);\n}\n";
    let module = vulkan_stage(text, StageKind::Fragment, VulkanVersion::V1_2);
    let m = &module;
    assert!(!m.types.iter().any(|(_, t)| matches!(t.inner, TypeInner::BindingArray { .. })), "no binding arrays left");
    let binding = |name: &str| {
        let g = m.global_variables.iter().find(|(_, g)| g.name.as_deref() == Some(name)).map(|(_, g)| g);
        g.and_then(|g| g.binding.as_ref()).map(|b| b.binding)
    };
    let textures: Vec<Option<u32>> = (0..4).map(|k| binding(&format!("textures_{k}"))).collect();
    assert!(textures.iter().all(Option::is_some), "{textures:?}");
    assert_eq!(binding("textures_4"), None, "a runtime-sized array has {} elements", crate::front::spirv_binding_arrays::RUNTIME_ELEMENTS);
    let mut all: Vec<u32> = m.global_variables.iter().filter_map(|(_, g)| g.binding.as_ref().map(|b| b.binding)).collect();
    let count = all.len();
    all.sort_unstable();
    all.dedup();
    assert_eq!(all.len(), count, "every resource has a binding of its own");
    assert!(binding("params") > binding("samplers_1"), "the block moved above the elements");
    let functions = m.functions.iter().map(|(_, f)| f).chain(m.entry_points.iter().map(|e| &e.function));
    let samples = functions.flat_map(|f| f.expressions.iter()).filter(|(_, e)| matches!(e, naga::Expression::ImageSample { .. })).count();
    assert_eq!(samples, 4 + 1 + 2 * 2, "every element, the constant element once, every texture and sampler pair");
}

/// 64-bit integers in a buffer are held as two 32-bit words: compared, added, narrowed and
/// converted from the words, and the module has no 64-bit type left.
#[test]
fn wide_integers_are_held_as_two_words() {
    let text = "#version 450\n#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require\n\
                layout(std430, binding = 0) buffer Materials { int64_t offset; uint64_t handle[]; } m;\nlayout(location = 0) out vec4 o;\n\
                void main() {\n    uint64_t h = m.handle[1] + 5ul;\n    int64_t s = m.offset - int64_t(-3);\n    \
                o = vec4(h < 2000ul ? float(uint(h)) : 0.0, float(h), s >= 0l ? 1.0 : 0.0, float(s));\n    m.handle[0] = uint64_t(7u);\n}\n";
    let module = vulkan_stage(text, StageKind::Fragment, VulkanVersion::V1_0);
    let m = &module;
    let wide = |t: &naga::Type| matches!(t.inner, TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } if s.width == 8);
    assert!(!m.types.iter().any(|(_, t)| wide(t)), "no 64-bit type left");
    let block = m.global_variables.iter().find(|(_, g)| matches!(g.space, AddressSpace::Storage { .. })).expect("the buffer").1;
    let TypeInner::Struct { members, .. } = &m.types[block.ty].inner else { panic!("a block") };
    assert_eq!(members.iter().map(|x| x.offset).collect::<Vec<_>>(), [0, 8], "the layout is the 64-bit one");
    let TypeInner::Array { stride, .. } = m.types[members[1].ty].inner else { panic!("the handles") };
    assert_eq!(stride, 8);
}

/// `gl_BaseInstance` and `gl_DrawID` are 0 in effectc's draws, which WGSL has no built-ins
/// for; the stage keeps the names.
#[test]
fn draw_parameters_are_zero() {
    let text = "#version 460\nlayout(location = 0) in vec4 p;\nlayout(location = 0) flat out int id;\n\
                void main() { id = gl_BaseInstance + gl_DrawID + gl_BaseVertex; gl_Position = p; }\n";
    let module = vulkan_stage(text, StageKind::Vertex, VulkanVersion::V1_1);
    let m = &module;
    let arguments = &m.entry_points[0].function.arguments;
    assert!(arguments
        .iter()
        .all(|a| !matches!(a.binding, Some(naga::Binding::BuiltIn(naga::BuiltIn::BaseInstance | naga::BuiltIn::DrawIndex)))));
    for name in ["gl_BaseInstance", "gl_DrawID", "gl_BaseVertex"] {
        let g = m.global_variables.iter().find(|(_, g)| g.name.as_deref() == Some(name)).map(|(_, g)| g).expect(name);
        assert_eq!(g.space, AddressSpace::Private, "{name}");
        assert!(g.init.is_some(), "{name} is initialised");
    }
}

/// Subgroup operations are computed for a subgroup of one invocation: no subgroup
/// operation or built-in is left for naga, and the module validates without the capability.
#[test]
fn subgroup_operations_are_those_of_a_subgroup_of_one() {
    let text = "#version 450\n#extension GL_KHR_shader_subgroup_ballot : require\n#extension GL_KHR_shader_subgroup_arithmetic : require\n\
                #extension GL_KHR_shader_subgroup_vote : require\n\
                layout(local_size_x = 64) in;\nlayout(std430, binding = 0) buffer B { uint n[]; } b;\n\
                void main() {\n    uint i = gl_LocalInvocationIndex;\n    uvec4 ballot = subgroupBallot(b.n[i] > 3u);\n    \
                b.n[i] = subgroupBallotBitCount(ballot) + subgroupBallotExclusiveBitCount(ballot) + subgroupMax(i) + subgroupExclusiveAdd(i);\n    \
                if (subgroupElect() && subgroupAny(i == 0u)) { b.n[0] = subgroupBroadcastFirst(i) + gl_SubgroupSize + gl_SubgroupInvocationID; }\n    \
                subgroupBarrier();\n    b.n[1] = subgroupOr(i) | subgroupExclusiveMin(i);\n}\n";
    let module = vulkan_stage(text, StageKind::Compute, VulkanVersion::V1_1);
    let m = &module;
    let f = &m.entry_points[0].function;
    let subgroup = |s: &naga::Statement| {
        matches!(
            s,
            naga::Statement::SubgroupBallot { .. }
                | naga::Statement::SubgroupCollectiveOperation { .. }
                | naga::Statement::SubgroupGather { .. }
        )
    };
    fn walk<'a>(b: &'a naga::Block, out: &mut Vec<&'a naga::Statement>) {
        for s in b.iter() {
            out.push(s);
            match s {
                naga::Statement::Block(x) => walk(x, out),
                naga::Statement::If { accept, reject, .. } => {
                    walk(accept, out);
                    walk(reject, out);
                }
                naga::Statement::Loop { body, continuing, .. } => {
                    walk(body, out);
                    walk(continuing, out);
                }
                _ => {}
            }
        }
    }
    let mut all = Vec::new();
    walk(&f.body, &mut all);
    assert!(!all.iter().any(|s| subgroup(s)), "no subgroup operation left");
    assert!(!f
        .arguments
        .iter()
        .any(|a| matches!(a.binding, Some(naga::Binding::BuiltIn(naga::BuiltIn::SubgroupSize | naga::BuiltIn::SubgroupInvocationId)))));
    let size = m.global_variables.iter().find(|(_, g)| g.name.as_deref() == Some("gl_SubgroupSize")).expect("a private gl_SubgroupSize").1;
    let mut init = size.init.expect("initialised");
    while let naga::Expression::Constant(c) = m.global_expressions[init] {
        init = m.constants[c].init;
    }
    assert!(matches!(m.global_expressions[init], naga::Expression::Literal(naga::Literal::U32(1))), "{:?}", m.global_expressions[init]);
}

/// A store to an image chosen at run time is a `switch` on the index, one case per element
/// (the last one also for an index past the end).
#[test]
fn a_store_to_an_image_chosen_at_run_time_is_a_switch() {
    let text = "#version 450\nlayout(local_size_x = 8) in;\nlayout(set = 0, binding = 0, r32f) writeonly uniform image2D images[3];\n\
                layout(push_constant) uniform P { int level; } p;\n\
                void main() {\n    float v = float(gl_LocalInvocationIndex);\n    \
                if (v > 2.0) {\n        imageStore(images[p.level], ivec2(gl_GlobalInvocationID.xy), vec4(v));\n    }\n}\n";
    let module = vulkan_stage(text, StageKind::Compute, VulkanVersion::V1_0);
    let m = &module;
    assert!(!m.types.iter().any(|(_, t)| matches!(t.inner, TypeInner::BindingArray { .. })), "no binding arrays left");
    let images = m.global_variables.iter().filter(|(_, g)| matches!(m.types[g.ty].inner, TypeInner::Image { .. })).count();
    assert_eq!(images, 3);
    fn switches(b: &naga::Block) -> Vec<usize> {
        let mut out = Vec::new();
        for s in b.iter() {
            match s {
                naga::Statement::Switch { cases, .. } => out.push(cases.len()),
                naga::Statement::Block(x) => out.extend(switches(x)),
                naga::Statement::If { accept, reject, .. } => {
                    out.extend(switches(accept));
                    out.extend(switches(reject));
                }
                _ => {}
            }
        }
        out
    }
    let found: Vec<usize> =
        m.functions.iter().map(|(_, f)| f).chain(m.entry_points.iter().map(|e| &e.function)).flat_map(|f| switches(&f.body)).collect();
    assert_eq!(found, [3], "cases 0 and 1, and the default (element 2)");
}
