//! Merge the per-stage naga modules of a program into one module with both entry points.
//!
//! naga's GLSL front makes one module per stage, each with an entry point called `main`.
//! A wgpu user wants one WGSL file holding `vs_main` and `fs_main`, so every type,
//! constant, global and function of each stage is copied into one module with its handles
//! remapped. Shared things are shared once: identical types (naga's type arena is unique),
//! resources bound at the same (group, binding) with the same type (the program-wide
//! uniform block, textures), and constants and functions that are identical in both stages
//! (a helper both stages declare). Everything else keeps its name; naga's namer resolves
//! collisions when code is written.

use std::collections::HashMap;

use naga::{Block, Constant, EntryPoint, Expression, Function, GlobalVariable, Handle, Module, Override, Statement, Type, TypeInner};

use crate::stage::StageKind;

/// The entry point name the merged module gives a stage.
pub fn entry_name(stage: StageKind) -> &'static str {
    match stage {
        StageKind::Vertex => "vs_main",
        StageKind::Fragment => "fs_main",
        StageKind::Compute => "cs_main",
        StageKind::Geometry => "gs_main",
        StageKind::TessControl => "tcs_main",
        StageKind::TessEval => "tes_main",
        StageKind::Task => "ts_main",
        StageKind::Mesh => "ms_main",
        StageKind::RayGeneration => "rgen_main",
        StageKind::Intersection => "rint_main",
        StageKind::AnyHit => "rahit_main",
        StageKind::ClosestHit => "rchit_main",
        StageKind::Miss => "rmiss_main",
        StageKind::Callable => "rcall_main",
    }
}

/// The name the merged module gives a stage's GLSL `main` (called by the entry point).
fn main_name(stage: StageKind) -> String {
    format!("{}_glsl_main", stage.short_name())
}

/// Why the stages cannot share one module: what is in conflict, in the stage `stage`; with
/// `within_stage`, both resources are that stage's own.
#[derive(Debug, Clone, PartialEq)]
pub struct MergeConflict {
    pub message: String,
    pub stage: StageKind,
    pub within_stage: bool,
}

/// Merges the stage modules (pipeline order) into one module.
pub fn merge(stages: &[(StageKind, &Module)]) -> Result<Module, MergeConflict> {
    let mut dst = Module::default();
    for (stage, src) in stages {
        Importer::new(&mut dst, src, *stage).import()?;
    }
    Ok(dst)
}

struct Importer<'a> {
    dst: &'a mut Module,
    src: &'a Module,
    stage: StageKind,
    types: HashMap<Handle<Type>, Handle<Type>>,
    constants: HashMap<Handle<Constant>, Handle<Constant>>,
    overrides: HashMap<Handle<Override>, Handle<Override>>,
    global_exprs: HashMap<Handle<Expression>, Handle<Expression>>,
    globals: HashMap<Handle<GlobalVariable>, Handle<GlobalVariable>>,
    functions: HashMap<Handle<Function>, Handle<Function>>,
    /// Globals of `dst` from this index on were added by this stage.
    first_own_global: usize,
}

impl<'a> Importer<'a> {
    fn new(dst: &'a mut Module, src: &'a Module, stage: StageKind) -> Self {
        let first_own_global = dst.global_variables.len();
        Importer {
            dst,
            src,
            stage,
            types: HashMap::new(),
            constants: HashMap::new(),
            overrides: HashMap::new(),
            global_exprs: HashMap::new(),
            first_own_global,
            globals: HashMap::new(),
            functions: HashMap::new(),
        }
    }

    fn import(mut self) -> Result<(), MergeConflict> {
        for (h, ty) in self.src.types.iter() {
            let inner = self.type_inner(&ty.inner);
            let span = self.src.types.get_span(h);
            let new = self.dst.types.insert(Type { name: ty.name.clone(), inner }, span);
            self.types.insert(h, new);
        }
        for (h, _) in self.src.constants.iter() {
            self.constant(h);
        }
        for (h, _) in self.src.overrides.iter() {
            self.override_(h);
        }
        for (h, _) in self.src.global_expressions.iter() {
            self.global_expr(h);
        }
        for (h, g) in self.src.global_variables.iter() {
            let new = self.global(h, g)?;
            self.globals.insert(h, new);
        }
        for (h, f) in self.src.functions.iter() {
            let mut f = self.function(f);
            if f.name.as_deref() == Some("main") {
                f.name = Some(main_name(self.stage));
            }
            let span = self.src.functions.get_span(h);
            let existing = self.dst.functions.iter().find(|(_, d)| same_function(d, &f)).map(|(h, _)| h);
            let new = match existing {
                Some(existing) => existing,
                None => self.dst.functions.append(f, span),
            };
            self.functions.insert(h, new);
        }
        for ep in &self.src.entry_points {
            let mut function = self.function(&ep.function);
            function.name = Some(entry_name(self.stage).to_string());
            self.dst.entry_points.push(EntryPoint {
                name: entry_name(self.stage).to_string(),
                stage: ep.stage,
                early_depth_test: ep.early_depth_test,
                workgroup_size: ep.workgroup_size,
                workgroup_size_overrides: None,
                function,
                mesh_info: None,
                task_payload: None,
                incoming_ray_payload: None,
            });
        }
        Ok(())
    }

    fn ty(&self, h: Handle<Type>) -> Handle<Type> {
        self.types[&h]
    }

    fn type_inner(&mut self, inner: &TypeInner) -> TypeInner {
        let mut inner = inner.clone();
        match &mut inner {
            TypeInner::Pointer { base, .. } | TypeInner::BindingArray { base, .. } => *base = self.ty(*base),
            TypeInner::Array { base, size, .. } => {
                *base = self.ty(*base);
                if let naga::ArraySize::Pending(o) = size {
                    *o = self.override_(*o);
                }
            }
            TypeInner::Struct { members, .. } => {
                for m in members {
                    m.ty = self.ty(m.ty);
                }
            }
            _ => {}
        }
        inner
    }

    fn constant(&mut self, h: Handle<Constant>) -> Handle<Constant> {
        if let Some(&n) = self.constants.get(&h) {
            return n;
        }
        let c = &self.src.constants[h];
        let ty = self.ty(c.ty);
        let init = self.global_expr(c.init);
        // A constant both stages declare identically is declared once.
        let existing = self.dst.constants.iter().find(|(_, d)| {
            d.name == c.name
                && d.ty == ty
                && matches!(
                    (&self.dst.global_expressions[d.init], &self.dst.global_expressions[init]),
                    (Expression::Literal(a), Expression::Literal(b)) if a == b
                )
        });
        let new = match existing {
            Some((e, _)) => e,
            None => {
                let span = self.src.constants.get_span(h);
                self.dst.constants.append(Constant { name: c.name.clone(), ty, init }, span)
            }
        };
        self.constants.insert(h, new);
        new
    }

    fn override_(&mut self, h: Handle<Override>) -> Handle<Override> {
        if let Some(&n) = self.overrides.get(&h) {
            return n;
        }
        let o = &self.src.overrides[h];
        let ty = self.ty(o.ty);
        // A specialization constant two stages declare alike (`layout(constant_id = 0) const
        // int type = 0;` in both) is one override of the merged module: WGSL allows one per id.
        let same = |d: &Override| d.id.is_some() && d.id == o.id && d.name == o.name && d.ty == ty;
        if let Some((existing, _)) = self.dst.overrides.iter().find(|(_, d)| same(d)) {
            self.overrides.insert(h, existing);
            return existing;
        }
        let init = o.init.map(|e| self.global_expr(e));
        let span = self.src.overrides.get_span(h);
        let new = self.dst.overrides.append(Override { name: o.name.clone(), id: o.id, ty, init }, span);
        self.overrides.insert(h, new);
        new
    }

    fn global_expr(&mut self, h: Handle<Expression>) -> Handle<Expression> {
        if let Some(&n) = self.global_exprs.get(&h) {
            return n;
        }
        let mut e = self.src.global_expressions[h].clone();
        let sub = |x: &mut Handle<Expression>, me: &mut Self| *x = me.global_expr(*x);
        for_each_operand(&mut e, |x| sub(x, self));
        self.module_refs(&mut e);
        let span = self.src.global_expressions.get_span(h);
        let new = self.dst.global_expressions.append(e, span);
        self.global_exprs.insert(h, new);
        new
    }

    /// Remaps the module-level handles (types, constants, overrides, globals, functions)
    /// an expression holds; its operand expressions are left alone.
    fn module_refs(&mut self, e: &mut Expression) {
        match e {
            Expression::Constant(c) => *c = self.constant(*c),
            Expression::Override(o) => *o = self.override_(*o),
            Expression::ZeroValue(ty)
            | Expression::Compose { ty, .. }
            | Expression::AtomicResult { ty, .. }
            | Expression::WorkGroupUniformLoadResult { ty }
            | Expression::SubgroupOperationResult { ty } => *ty = self.ty(*ty),
            Expression::GlobalVariable(g) => *g = self.globals[g],
            Expression::CallResult(f) => *f = self.functions[f],
            _ => {}
        }
    }

    fn global(&mut self, h: Handle<GlobalVariable>, g: &GlobalVariable) -> Result<Handle<GlobalVariable>, MergeConflict> {
        let ty = self.ty(g.ty);
        let init = g.init.map(|e| self.global_expr(e));
        if let Some(binding) = &g.binding {
            let found = self.dst.global_variables.iter().find(|(_, d)| d.binding.as_ref() == Some(binding));
            if let Some((existing, d_ty, d_space)) = found.map(|(h, d)| (h, d.ty, d.space)) {
                if d_space == g.space && d_ty == ty {
                    return Ok(existing);
                }
                if d_space == g.space {
                    if let Some(shared) = share_layout(&mut self.dst.types, d_ty, ty) {
                        self.dst.global_variables.get_mut(existing).ty = shared;
                        return Ok(existing);
                    }
                }
                let d = &self.dst.global_variables[existing];
                let (a, b) = (
                    d.name.as_deref().or(self.dst.types[d.ty].name.as_deref()).unwrap_or("?"),
                    g.name.as_deref().or(self.src.types[g.ty].name.as_deref()).unwrap_or("?"),
                );
                let (group, index, stage) = (binding.group, binding.binding, self.stage);
                let within_stage = existing.index() >= self.first_own_global;
                let message = if within_stage {
                    format!("group {group} binding {index} holds both `{a}` and `{b}` in the {stage} stage")
                } else {
                    format!("group {group} binding {index} holds `{a}` in one stage and `{b}` in the {stage} stage")
                };
                return Err(MergeConflict { message, stage, within_stage });
            }
        }
        let span = self.src.global_variables.get_span(h);
        Ok(self.dst.global_variables.append(
            GlobalVariable { name: g.name.clone(), space: g.space, binding: g.binding, ty, init, memory_decorations: g.memory_decorations },
            span,
        ))
    }

    fn function(&mut self, f: &Function) -> Function {
        let mut f = f.clone();
        for a in &mut f.arguments {
            a.ty = self.ty(a.ty);
        }
        if let Some(r) = &mut f.result {
            r.ty = self.ty(r.ty);
        }
        for (_, l) in f.local_variables.iter_mut() {
            l.ty = self.ty(l.ty);
        }
        for (_, e) in f.expressions.iter_mut() {
            self.module_refs(e);
        }
        let functions = &self.functions;
        visit_statements(&mut f.body, &mut |s| {
            if let Statement::Call { function, .. } = s {
                *function = functions[function];
            }
        });
        f
    }
}

/// Whether two uniform block structs have the same layout (member types, offsets, size)
/// and differ only in member names: the front renames a uniform that a stage shadows with
/// its own variable (`effectc_other_<name>`). The shared type takes the user's names.
fn share_layout(types: &mut naga::UniqueArena<Type>, a: Handle<Type>, b: Handle<Type>) -> Option<Handle<Type>> {
    let (TypeInner::Struct { members: ma, span: sa }, TypeInner::Struct { members: mb, span: sb }) = (&types[a].inner, &types[b].inner)
    else {
        return None;
    };
    let same =
        sa == sb && ma.len() == mb.len() && ma.iter().zip(mb).all(|(x, y)| x.ty == y.ty && x.offset == y.offset && x.binding == y.binding);
    if !same {
        return None;
    }
    let shadowed = |m: &naga::StructMember| m.name.as_deref().is_some_and(|n| n.starts_with(crate::front::rewrite::OTHER_STAGE_PREFIX));
    let members: Vec<naga::StructMember> =
        ma.iter().zip(mb).map(|(x, y)| if shadowed(x) && !shadowed(y) { y.clone() } else { x.clone() }).collect();
    let renamed = Type { name: types[a].name.clone(), inner: TypeInner::Struct { members, span: *sa } };
    if renamed == types[a] {
        Some(a)
    } else if renamed == types[b] {
        Some(b)
    } else if types.get(&renamed).is_none() {
        types.replace(a, renamed);
        Some(a)
    } else {
        None
    }
}

/// Two functions with the same name and the same body (spans aside).
fn same_function(a: &Function, b: &Function) -> bool {
    a.name == b.name && fingerprint(a) == fingerprint(b)
}

fn fingerprint(f: &Function) -> String {
    format!("{:?}{:?}{:?}{:?}{:?}", f.arguments, f.result, f.local_variables, f.expressions, without_spans(&f.body))
}

/// Every function of a module, entry points included.
pub fn all_functions(module: &Module) -> impl Iterator<Item = &Function> {
    module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function))
}

/// Every function of a module, entry points included, mutably.
pub fn all_functions_mut(module: &mut Module) -> impl Iterator<Item = &mut Function> {
    module.functions.iter_mut().map(|(_, f)| f).chain(module.entry_points.iter_mut().map(|e| &mut e.function))
}

/// A copy of `block` whose statements (recursively) carry no spans.
pub fn without_spans(block: &Block) -> Block {
    let mut out: Vec<Statement> = block.iter().cloned().collect();
    for s in &mut out {
        for b in child_blocks(s) {
            *b = without_spans(b);
        }
    }
    Block::from_vec(out)
}

pub use crate::front::statements::{child_blocks, visit_statements};

/// Calls `f` on every operand (expression handle) of `e`.
pub fn for_each_operand(e: &mut Expression, mut f: impl FnMut(&mut Handle<Expression>)) {
    use naga::SampleLevel;
    let opt = |x: &mut Option<Handle<Expression>>, f: &mut dyn FnMut(&mut Handle<Expression>)| {
        if let Some(x) = x {
            f(x)
        }
    };
    match e {
        Expression::Access { base, index } => {
            f(base);
            f(index)
        }
        Expression::AccessIndex { base, .. } => f(base),
        Expression::Splat { value, .. } => f(value),
        Expression::Swizzle { vector, .. } => f(vector),
        Expression::Compose { components, .. } => components.iter_mut().for_each(f),
        Expression::Load { pointer } => f(pointer),
        Expression::ImageSample { image, sampler, coordinate, array_index, offset, level, depth_ref, .. } => {
            f(image);
            f(sampler);
            f(coordinate);
            opt(array_index, &mut f);
            opt(offset, &mut f);
            opt(depth_ref, &mut f);
            match level {
                SampleLevel::Exact(x) | SampleLevel::Bias(x) => f(x),
                SampleLevel::Gradient { x, y } => {
                    f(x);
                    f(y)
                }
                _ => {}
            }
        }
        Expression::ImageLoad { image, coordinate, array_index, sample, level } => {
            f(image);
            f(coordinate);
            opt(array_index, &mut f);
            opt(sample, &mut f);
            opt(level, &mut f);
        }
        Expression::ImageQuery { image, query } => {
            f(image);
            if let naga::ImageQuery::Size { level } = query {
                opt(level, &mut f);
            }
        }
        Expression::Unary { expr, .. } => f(expr),
        Expression::Binary { left, right, .. } => {
            f(left);
            f(right)
        }
        Expression::Select { condition, accept, reject } => {
            f(condition);
            f(accept);
            f(reject)
        }
        Expression::Derivative { expr, .. } => f(expr),
        Expression::Relational { argument, .. } => f(argument),
        Expression::Math { arg, arg1, arg2, arg3, .. } => {
            f(arg);
            opt(arg1, &mut f);
            opt(arg2, &mut f);
            opt(arg3, &mut f);
        }
        Expression::As { expr, .. } => f(expr),
        Expression::ArrayLength(x) => f(x),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(src: &str, stage: naga::ShaderStage) -> Module {
        naga::front::glsl::Frontend::default().parse(&naga::front::glsl::Options::from(stage), src).unwrap()
    }

    fn validate(m: &Module) -> naga::valid::ModuleInfo {
        crate::front::naga_run::validator().validate(m).unwrap_or_else(|e| panic!("{e:?}"))
    }

    const VERT: &str = "#version 450\nlayout(set=0,binding=0) uniform U { mat4 mvp; float k; };\nconst float PI = 3.14159;\nfloat twice(float x) { return 2.0 * x; }\nlayout(location=0) in vec3 pos;\nlayout(location=0) out vec2 uv;\nvoid main() { uv = pos.xy * twice(PI); gl_Position = mvp * vec4(pos, 1.0); }\n";
    const FRAG: &str = "#version 450\nlayout(set=0,binding=0) uniform U { mat4 mvp; float k; };\nconst float PI = 3.14159;\nfloat twice(float x) { return 2.0 * x; }\nlayout(location=0) in vec2 uv;\nlayout(location=0) out vec4 color;\nvoid main() { color = vec4(uv * twice(k), PI, 1.0); }\n";

    #[test]
    fn merged_module_has_both_entry_points_and_validates() {
        let v = module(VERT, naga::ShaderStage::Vertex);
        let f = module(FRAG, naga::ShaderStage::Fragment);
        let m = merge(&[(StageKind::Vertex, &v), (StageKind::Fragment, &f)]).unwrap();
        let names: Vec<_> = m.entry_points.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["vs_main", "fs_main"]);
        validate(&m);
        // The uniform block, the constant and the identical helper are shared.
        assert_eq!(m.global_variables.iter().filter(|(_, g)| g.binding.is_some()).count(), 1);
        assert_eq!(m.constants.iter().filter(|(_, c)| c.name.as_deref() == Some("PI")).count(), 1);
        assert_eq!(m.functions.iter().filter(|(_, f)| f.name.as_deref() == Some("twice")).count(), 1);
        let wgsl = naga::back::wgsl::write_string(&m, &validate(&m), naga::back::wgsl::WriterFlags::empty()).unwrap();
        assert!(wgsl.contains("fn vs_main(") && wgsl.contains("fn fs_main("), "{wgsl}");
        assert!(wgsl.contains("fn vert_glsl_main(") && wgsl.contains("fn frag_glsl_main("), "{wgsl}");
    }

    /// `layout(constant_id = 0) const int kind = 0;` in both stages is one override of the
    /// merged module (two with one id do not validate: E0305 before, on Khronos samples).
    #[test]
    fn a_specialization_constant_both_stages_declare_is_one_override() {
        let spec = "layout(constant_id = 0) const int kind = 0;\n";
        let v =
            format!("#version 450\n{spec}layout(location=0) in vec3 pos;\nvoid main() {{ gl_Position = vec4(pos * float(kind), 1.0); }}\n");
        let f = format!("#version 450\n{spec}layout(location=0) out vec4 color;\nvoid main() {{ color = vec4(float(kind)); }}\n");
        let (v, f) = (module(&v, naga::ShaderStage::Vertex), module(&f, naga::ShaderStage::Fragment));
        let m = merge(&[(StageKind::Vertex, &v), (StageKind::Fragment, &f)]).unwrap();
        validate(&m);
        assert_eq!(m.overrides.len(), 1);
    }

    #[test]
    fn same_binding_with_different_types_is_a_conflict() {
        let v = module(VERT, naga::ShaderStage::Vertex);
        let f = module(&FRAG.replace("mat4 mvp; float k;", "vec4 other; float k;"), naga::ShaderStage::Fragment);
        let err = merge(&[(StageKind::Vertex, &v), (StageKind::Fragment, &f)]).unwrap_err();
        assert!(err.message.contains("group 0 binding 0 holds `U` in one stage and `U` in the fragment stage"), "{}", err.message);
        assert_eq!((err.stage, err.within_stage), (StageKind::Fragment, false));
    }

    #[test]
    fn two_resources_of_one_stage_at_one_binding_are_named_in_that_stage() {
        let v = module(VERT, naga::ShaderStage::Vertex);
        let both = "layout(set=0,binding=1) uniform A { vec4 a; };\nlayout(set=0,binding=1) uniform B { vec2 b; };\nlayout(location=0) in vec2 uv;";
        let f =
            module(&FRAG.replace("layout(location=0) in vec2 uv;", both).replace("vec4(uv", "vec4(a.xy + b"), naga::ShaderStage::Fragment);
        let err = merge(&[(StageKind::Vertex, &v), (StageKind::Fragment, &f)]).unwrap_err();
        assert!(err.message.contains("group 0 binding 1 holds both `A` and `B` in the fragment stage"), "{}", err.message);
        assert_eq!((err.stage, err.within_stage), (StageKind::Fragment, true));
    }
}
