//! The reference compiler's verdict: every stage of a program compiled by glslang (the
//! Khronos reference compiler, in process) for the profile and version its `#version`
//! names, and the program linked as GL links it (or as Vulkan does, for Vulkan GLSL).
//!
//! glslang decides what is legal; its errors become effectc diagnostics at the user's
//! file, line and column (included files and `#line` directives followed), with glslang's
//! wording kept. effectc's own analysis (spans, interface rules, naga) runs on top: what
//! glslang accepts is never refused because effectc's own analysis or naga cannot read it.
//!
//! - [`compiler`]: glslang's C interface (compile one stage, link a program).
//! - [`log`]: glslang's info log parsed and placed in the user's text.
//! - [`leniency`]: the text glslang judges, where glslang is stricter than the GLSL
//!   specifications and the GL drivers that follow them.

pub mod compiler;
pub mod leniency;
pub mod log;

use crate::config::{TargetEnv, VulkanVersion};
use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::stage::StageKind;

pub use compiler::Dialect;

/// glslang's verdict on one stage.
#[derive(Debug, Clone)]
pub struct StageVerdict {
    pub file: FileId,
    pub accepted: bool,
    /// glslang's errors, placed in the user's files.
    pub errors: Vec<Diagnostic>,
}

/// glslang's verdict on a program.
#[derive(Debug, Clone)]
pub struct Judgement {
    pub stages: Vec<StageVerdict>,
    /// glslang's link errors (empty when every stage compiled and the program links, or
    /// when a stage did not compile and so nothing was linked).
    pub link_errors: Vec<Diagnostic>,
    /// The dialect the program was compiled in.
    pub dialect: Dialect,
}

impl Judgement {
    /// glslang's verdict on the stage read from `file` (None: not judged).
    pub fn stage(&self, file: FileId) -> Option<&StageVerdict> {
        self.stages.iter().find(|s| s.file == file)
    }
}

/// The stage made of several files in `stages` (sorted by stage): shader objects GL links
/// into one stage.
pub fn repeated_stage(stages: &[(FileId, StageKind)]) -> Option<StageKind> {
    stages.windows(2).find(|w| w[0].1 == w[1].1).map(|w| w[0].1)
}

/// The dialect glslang compiles a program in: Vulkan GLSL when asked, or (`auto`) when the
/// text of any stage shows it (descriptor sets, push constants, separate samplers) or a
/// stage is one only Vulkan has (ray tracing).
pub fn dialect(files: &Files, stages: &[(FileId, StageKind)], env: TargetEnv) -> Dialect {
    let vulkan = match env {
        TargetEnv::OpenGl => None,
        TargetEnv::Vulkan(v) => Some(v),
        TargetEnv::Auto => stages
            .iter()
            .any(|(f, k)| k.vulkan_only() || crate::front::syntax::vulkan_source(files.text(*f)))
            .then_some(VulkanVersion::V1_0),
    };
    match vulkan {
        Some(v) => Dialect::Vulkan(v),
        None => Dialect::OpenGl,
    }
}

/// glslang's verdict on the program made of `stages` (their texts in `files`, includes
/// inlined). None when glslang could not be set up in this process.
///
/// Vulkan GLSL found by `auto` is compiled for Vulkan 1.0 first; where glslang refuses it
/// only because what it uses needs a newer SPIR-V (subgroup operations: 1.3, ray tracing
/// and mesh shading: 1.4), it is compiled for the oldest Vulkan that has it, as the project
/// would pass `--target-env vulkan1.x` to glslangValidator.
pub fn judge(files: &Files, stages: &[(FileId, StageKind)], env: TargetEnv) -> Option<Judgement> {
    let dialect = dialect(files, stages, env);
    let mut first = judge_as(files, stages, dialect)?;
    if env == TargetEnv::Auto && dialect == Dialect::OpenGl && !first.accepted() {
        first.offer_vulkan(files, stages);
    }
    if env != TargetEnv::Auto || !first.needs_newer_spirv() {
        return Some(first);
    }
    for version in [VulkanVersion::V1_1, VulkanVersion::V1_2, VulkanVersion::V1_3] {
        let newer = judge_as(files, stages, Dialect::Vulkan(version))?;
        if !newer.needs_newer_spirv() {
            return Some(newer);
        }
    }
    Some(first)
}

/// Whether glslang's message says the construct needs a newer SPIR-V than the one targeted.
fn needs_newer_spirv(message: &str) -> bool {
    message.contains("requires SPIR-V 1.") || message.contains("targeted SPIR-V version")
}

impl Judgement {
    /// Every stage compiled and the program linked.
    fn accepted(&self) -> bool {
        self.stages.iter().all(|s| s.accepted) && self.link_errors.is_empty()
    }

    /// A program `auto` read as OpenGL GLSL, which glslang refuses, that it accepts as
    /// Vulkan GLSL (`layout(offset)`s out of order, Vulkan's built-ins without a Vulkan-only
    /// declaration): the errors stand, with a help naming the option that says the program
    /// is Vulkan's.
    fn offer_vulkan(&mut self, files: &Files, stages: &[(FileId, StageKind)]) {
        if !judge_as(files, stages, Dialect::Vulkan(VulkanVersion::V1_0)).is_some_and(|j| j.accepted()) {
            return;
        }
        let help = "glslang accepts this program as Vulkan GLSL: if it is meant for Vulkan, pass `--target-env vulkan` (or `target-env` in effectc.toml)";
        for d in self.stages.iter_mut().flat_map(|s| s.errors.iter_mut()).chain(self.link_errors.iter_mut()) {
            d.help.get_or_insert_with(|| help.to_string());
        }
    }

    /// Some stage was refused for what a newer SPIR-V has.
    fn needs_newer_spirv(&self) -> bool {
        self.stages.iter().flat_map(|s| &s.errors).any(|d| needs_newer_spirv(&d.message))
    }
}

/// glslang's verdict on the program, compiled as `dialect`.
fn judge_as(files: &Files, stages: &[(FileId, StageKind)], dialect: Dialect) -> Option<Judgement> {
    let mut compiled = Vec::new();
    let mut verdicts = Vec::new();
    for &(file, kind) in stages {
        let quiet = crate::front::lexical::quiet_pragmas(files.text(file));
        let text = leniency::as_drivers_read(&quiet);
        let shader = compiler::compile(&text, kind, dialect)?;
        if std::env::var_os("EFFECTC_DUMP_REFERENCE").is_some() {
            // Debugging aid: glslang's own verdict and log for each stage, on stderr.
            eprintln!(
                "[glslang] {} {kind}: {}\n{}",
                files.path(file),
                if shader.verdict.ok { "accepted" } else { "rejected" },
                shader.verdict.log
            );
        }
        let errors = if shader.verdict.ok { Vec::new() } else { place(files, file, &shader.verdict.log) };
        verdicts.push(StageVerdict { file, accepted: shader.verdict.ok, errors });
        compiled.push(shader);
    }
    let mut link_errors = Vec::new();
    // Vulkan has no program object: each stage is compiled and linked on its own (glslc,
    // `-V` per file: an entry point, one stage's rules) and interfaces meet by location,
    // which effectc's link rules check; glslang's program link (GL's rules for same-named
    // blocks across stages) joins the stages only in GL, or the shader objects of one stage.
    let groups: Vec<&[compiler::CompiledShader]> =
        if dialect == Dialect::OpenGl || repeated_stage(stages).is_some() { vec![&compiled[..]] } else { compiled.chunks(1).collect() };
    for group in groups {
        if let Some(verdict) = compiler::link(group, dialect).filter(|v| !v.ok) {
            link_errors.extend(link_diagnostics(stages, &verdict.log));
        }
    }
    Some(Judgement { stages: verdicts, link_errors, dialect })
}

/// glslang's errors in `log` as E0105 diagnostics in `file` (an expanded stage's spans are
/// shown in the included file they come from).
fn place(files: &Files, file: FileId, log: &str) -> Vec<Diagnostic> {
    let code = Code::ReferenceRejects;
    let text = files.text(file);
    let table = log::LineTable::new(text);
    let mut out = Vec::new();
    let mut lines_seen = Vec::new();
    for m in log::parse(log).into_iter().filter(|m| m.error) {
        // glslang's first error on a line is the cause; the ones after it on that line
        // follow from it (`vec4(uv, 0.0)`: 'constructor' : not enough data, then 'assign' :
        // cannot convert the ill-formed value).
        if let Some((s, l, _)) = m.at {
            if lines_seen.contains(&(s, l)) {
                continue;
            }
            lines_seen.push((s, l));
        }
        let mut d = Diagnostic::new(code, m.text.clone());
        d = match m.at.and_then(|(s, l, c)| table.line_range(s, l).map(|r| (r, c))) {
            Some((line, column)) => d.at(file, log::span_on_line(text, line, column, &m.text), "glslang reports this here"),
            None => d.in_file(file),
        };
        for detail in &m.detail {
            d = d.with_note(detail.clone());
        }
        if needs_newer_spirv(&m.text) {
            // Legal for a newer Vulkan: the run compiled for Vulkan 1.0.
            d = d.with_help("compile for the Vulkan the program targets: `--target-env vulkan1.1` (SPIR-V 1.3) … `vulkan1.3`, or `target-env` in effectc.toml");
        }
        out.push(d.with_note("the Khronos reference compiler (glslang) rejects this stage, as a GL driver would"));
    }
    if out.is_empty() {
        out.push(
            Diagnostic::new(code, "the reference compiler (glslang) rejects this stage")
                .in_file(file)
                .with_note(format!("glslang's log: {}", log.trim())),
        );
    }
    out
}

/// glslang's link errors: `Linking fragment stage: …` is reported in that stage's file.
fn link_diagnostics(stages: &[(FileId, StageKind)], log: &str) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for m in log::parse(log).into_iter().filter(|m| m.error) {
        let (stage, text) = match m.text.strip_prefix("Linking ").and_then(|r| r.split_once(" stage:")) {
            Some((name, rest)) => (stage_named(name), rest.trim().trim_end_matches(':').to_string()),
            None => (None, m.text.clone()),
        };
        let file = stage.and_then(|k| stages.iter().find(|(_, s)| *s == k)).or(stages.first()).map(|(f, _)| *f);
        let mut d = match (text.as_str(), m.detail.first().and_then(|d| d.split_once('('))) {
            // glslang names the function by its mangled signature (`edges(s21;vf2;`).
            ("No function definition (body) found", Some((name, _))) => {
                Diagnostic::new(Code::ReferenceLinkFails, format!("`{name}` is declared but no shader object of the stage defines it"))
            }
            _ => Diagnostic::new(Code::ReferenceLinkFails, text),
        };
        if let Some(f) = file {
            d = d.in_file(f);
        }
        for detail in &m.detail {
            d = d.with_note(detail.clone());
        }
        out.push(d.with_note("the Khronos reference compiler (glslang) refuses to link the program"));
    }
    if out.is_empty() && !log.trim().is_empty() {
        let mut d = Diagnostic::new(Code::ReferenceLinkFails, "the reference compiler (glslang) refuses to link the program");
        if let Some((f, _)) = stages.first() {
            d = d.in_file(*f);
        }
        out.push(d.with_note(format!("glslang's log: {}", log.trim())));
    }
    out
}

/// The stage glslang names in a link message (`tessellation control`).
pub fn stage_named(name: &str) -> Option<StageKind> {
    Some(match name {
        "vertex" => StageKind::Vertex,
        "fragment" => StageKind::Fragment,
        "geometry" => StageKind::Geometry,
        "tessellation control" => StageKind::TessControl,
        "tessellation evaluation" => StageKind::TessEval,
        "compute" => StageKind::Compute,
        _ => return None,
    })
}
