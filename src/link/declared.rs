//! What the stages declare that `effect.toml` can name: loose uniforms and members of
//! uniform blocks without an instance name (`Decls`, with every declaration site and
//! whether some stage reads it), the samplers among them by path (`tex`,
//! `material.diffuse`), and manifest uniform paths (`lights[1].color`) taken apart.
//! [`Declared`] is the summary other checks use (the pass graph, `effectc check`'s
//! per-pass view).

use std::collections::HashSet;
use std::ops::Range;

use super::values::Shape;
use super::{is_read, is_sampler_like, member_read, type_text};
use crate::diag::FileId;
use crate::front::syntax::{GlslType, StageSyntax, Storage};

/// One uniform the manifest can name: a loose uniform or a member of an anonymous block.
pub(super) struct Decl<'a> {
    /// The user's name.
    pub(super) name: String,
    /// Stage of the first declaration, where types are resolved.
    pub(super) stage: &'a StageSyntax,
    pub(super) ty: &'a GlslType,
    /// Every declaration (file, name span, stage), first one first.
    pub(super) sites: Vec<(FileId, Range<usize>, &'a StageSyntax)>,
    /// Some stage reads it.
    pub(super) read: bool,
    /// A member of an anonymous uniform block.
    pub(super) in_block: bool,
}

impl Decl<'_> {
    pub(super) fn file(&self) -> FileId {
        self.sites[0].0
    }
    pub(super) fn span(&self) -> Range<usize> {
        self.sites[0].1.clone()
    }
    pub(super) fn type_text(&self) -> String {
        type_text(self.stage, self.ty)
    }
    pub(super) fn shape(&self, ty: &GlslType) -> Shape {
        Shape::of(ty, &|b| self.stage.struct_def(b).is_some())
    }
}

/// A uniform block the manifest cannot address member by member.
pub(super) struct NamedBlock<'a> {
    pub(super) stage: &'a StageSyntax,
    pub(super) index: usize,
}

pub(super) struct Decls<'a> {
    pub(super) list: Vec<Decl<'a>>,
    pub(super) named_blocks: Vec<NamedBlock<'a>>,
    /// Blocks (named or not) no stage reads: stage, global index.
    pub(super) unread_blocks: Vec<(&'a StageSyntax, usize)>,
}

impl<'a> Decls<'a> {
    pub(super) fn collect(stages: &'a [StageSyntax]) -> Self {
        let mut d = Decls { list: Vec::new(), named_blocks: Vec::new(), unread_blocks: Vec::new() };
        let mut read_blocks: HashSet<String> = HashSet::new();
        let mut block_decls: Vec<(&StageSyntax, usize, String)> = Vec::new();
        for s in stages {
            for (i, g) in s.globals.iter().enumerate() {
                if g.storage != Storage::Uniform || s.original_name(&g.name).starts_with("gl_") {
                    continue;
                }
                match &g.block {
                    None => d.add(s, s.original_name(&g.name), &g.ty, g.name_span.clone(), is_read(s, i), false),
                    Some(b) => {
                        let bn = s.original_name(&b.block_name).to_string();
                        if is_read(s, i) {
                            read_blocks.insert(bn.clone());
                        }
                        block_decls.push((s, i, bn));
                        if b.instance.is_some() {
                            d.named_blocks.push(NamedBlock { stage: s, index: i });
                            continue;
                        }
                        for m in &b.members {
                            let read = member_read(s, i, &m.name);
                            d.add(s, s.original_name(&m.name), &m.ty, m.span.clone(), read, true);
                        }
                    }
                }
            }
        }
        let mut seen = HashSet::new();
        for (s, i, bn) in block_decls {
            if !read_blocks.contains(&bn) && seen.insert(bn) {
                d.unread_blocks.push((s, i));
            }
        }
        d
    }

    fn add(&mut self, s: &'a StageSyntax, name: &str, ty: &'a GlslType, span: Range<usize>, read: bool, in_block: bool) {
        if let Some(d) = self.list.iter_mut().find(|d| d.name == name) {
            d.read |= read;
            d.sites.push((s.file, span, s));
            return;
        }
        self.list.push(Decl { name: name.to_string(), stage: s, ty, sites: vec![(s.file, span, s)], read, in_block });
    }

    pub(super) fn get(&self, name: &str) -> Option<&Decl<'a>> {
        self.list.iter().find(|d| d.name == name)
    }

    /// A member of an instance-named uniform block addressed as GL names it,
    /// `BlockName.member` (or by the instance, `instance.member`): its declaration and the
    /// steps after the member.
    pub(super) fn block_member<'s>(&self, base: &str, steps: &'s [Step]) -> Option<(Decl<'a>, &'s [Step])> {
        let (Step::Field(member), rest) = steps.split_first()? else { return None };
        self.named_blocks.iter().find_map(|nb| {
            let s = nb.stage;
            let b = s.globals[nb.index].block.as_ref()?;
            let named = s.original_name(&b.block_name) == base || b.instance.as_deref().is_some_and(|i| s.original_name(i) == base);
            let m = b.members.iter().find(|m| named && s.original_name(&m.name) == member)?;
            let read = is_read(s, nb.index);
            let name = format!("{}.{member}", s.original_name(&b.block_name));
            Some((Decl { name, stage: s, ty: &m.ty, sites: vec![(s.file, m.span.clone(), s)], read, in_block: true }, rest))
        })
    }

    /// Every sampler the manifest can bind: its path (`tex`, `material.diffuse`), the
    /// sampler type and the declaration it lives in.
    pub(super) fn samplers(&self) -> Vec<(String, GlslType, &Decl<'a>)> {
        fn walk<'d, 'a>(decl: &'d Decl<'a>, path: String, ty: &GlslType, depth: usize, out: &mut Vec<(String, GlslType, &'d Decl<'a>)>) {
            if is_sampler_like(ty) {
                out.push((path, ty.clone(), decl));
            } else if let Some(def) = decl.stage.struct_def(&ty.base) {
                if depth < 4 {
                    for m in &def.members {
                        let p = format!("{path}.{}", decl.stage.original_name(&m.name));
                        walk(decl, p, &m.ty, depth + 1, out);
                    }
                }
            }
        }
        let mut out = Vec::new();
        for d in &self.list {
            walk(d, d.name.clone(), d.ty, 0, &mut out);
        }
        out
    }
}

/// One step of a manifest uniform path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Step {
    Index(u64),
    Field(String),
}

/// `lights[1].color` → (`lights`, [Index(1), Field(color)]); `None` if it is not a path.
pub(super) fn parse_path(s: &str) -> Option<(String, Vec<Step>)> {
    let ident = |s: &str| -> usize {
        s.char_indices().take_while(|&(i, c)| c == '_' || c.is_ascii_alphabetic() || (i > 0 && c.is_ascii_digit())).count()
    };
    let n = ident(s);
    if n == 0 {
        return None;
    }
    let base = s[..n].to_string();
    let mut rest = &s[n..];
    let mut steps = Vec::new();
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix('[') {
            let close = r.find(']')?;
            steps.push(Step::Index(r[..close].trim().parse().ok()?));
            rest = &r[close + 1..];
        } else if let Some(r) = rest.strip_prefix('.') {
            let n = ident(r);
            if n == 0 {
                return None;
            }
            steps.push(Step::Field(r[..n].to_string()));
            rest = &r[n..];
        } else {
            return None;
        }
    }
    Some((base, steps))
}

/// A texture name without array indices (`maps[2]` → `maps`).
pub(super) fn texture_path(name: &str) -> String {
    match parse_path(name) {
        Some((base, steps)) => {
            let mut p = base;
            for s in steps {
                if let Step::Field(f) = s {
                    p.push('.');
                    p.push_str(&f);
                }
            }
            p
        }
        None => name.to_string(),
    }
}

/// What a set of stages declares that a manifest can name.
#[derive(Debug, Default)]
pub struct Declared {
    /// Uniform names (loose uniforms and members of anonymous blocks).
    pub uniforms: HashSet<String>,
    /// Sampler paths (`tex`, `material.diffuse`) with their types.
    pub samplers: Vec<(String, GlslType)>,
}

impl Declared {
    /// Whether a `[uniforms]` entry (`lights[0].color`) names a uniform of these stages.
    pub fn has_uniform(&self, entry: &str) -> bool {
        let base = parse_path(entry).map_or(entry.to_string(), |(b, _)| b);
        self.uniforms.contains(&base)
    }
    /// The type of the sampler a `[textures]` entry binds, when these stages declare it.
    pub fn sampler(&self, entry: &str) -> Option<&GlslType> {
        let path = texture_path(entry);
        self.samplers.iter().find(|(p, _)| *p == path).map(|(_, t)| t)
    }
}

/// The uniforms and samplers `stages` declare.
pub fn declared(stages: &[StageSyntax]) -> Declared {
    let decls = Decls::collect(stages);
    Declared {
        uniforms: decls.list.iter().map(|d| d.name.clone()).collect(),
        samplers: decls.samplers().into_iter().map(|(p, t, _)| (p, t)).collect(),
    }
}

/// A uniform the command line or a manifest can set, as `effectc check --list-uniforms`
/// lists it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Settable {
    pub name: String,
    /// The GLSL type as written (`vec3`, `float[4]`, `Light`).
    pub ty: String,
    /// Some stage reads it.
    pub read: bool,
}

/// The settable uniforms of a program's stages (loose uniforms and members of anonymous
/// blocks; samplers and images left out), in declaration order.
pub fn settable(stages: &[StageSyntax]) -> Vec<Settable> {
    Decls::collect(stages)
        .list
        .iter()
        .filter(|d| !super::is_opaque(d.ty))
        .map(|d| Settable { name: d.name.clone(), ty: d.type_text(), read: d.read })
        .collect()
}
