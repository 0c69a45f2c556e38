//! `[textures]`: the image bound to each sampler uniform, from a file, six cube faces or a
//! procedural generator, with its kind, filter and wrap mode. Generator parameters that do
//! not apply are errors on loaded images and warnings on generators that ignore them.

use std::ops::Range;
use std::path::PathBuf;

use toml::de::{DeTable, DeValue};

use super::{entries, key, Ctx, Key, Val};
use crate::diag::Code;
use crate::manifest::{
    Filter, Generator, GeneratorParams, TexelFormat, TexelKind, TextureDecl, TextureKind, TextureSource, Wrap, DEFAULT_TEXTURE_SIZE,
    MAX_TEXTURE_SIZE,
};

const TEXTURE_KEYS: &[&str] =
    &["file", "cube", "generate", "kind", "size", "colors", "cells", "seed", "octaves", "filter", "wrap", "format"];
const MAX_CELLS: u32 = 4096;
const MAX_OCTAVES: u32 = 16;

const FACE_ORDER: &str = "+x, -x, +y, -y, +z, -z";
/// Generated-texture parameter keys (besides the source itself).
const GEN_PARAMS: &[&str] = &["size", "colors", "cells", "seed", "octaves"];

/// What the keys of one texture table gave, before they are checked against each other.
struct TextureFields {
    /// Every key was known and its value read without a problem.
    ok: bool,
    /// The source keys given (`file`, `cube`, `generate`), with their key spans.
    sources: Vec<(&'static str, Range<usize>)>,
    file: Option<PathBuf>,
    faces: Option<[PathBuf; 6]>,
    generator: Option<Generator>,
    kind: Option<(TextureKind, Range<usize>)>,
    /// The generator parameter keys given, with their key spans.
    params_given: Vec<(&'static str, Range<usize>)>,
    size: u32,
    params: GeneratorParams,
    filter: Filter,
    wrap: Wrap,
    format: (TexelFormat, Option<Range<usize>>),
    filter_given: bool,
    /// The span of `colors`' value.
    colors_span: Option<Range<usize>>,
}

impl TextureFields {
    fn new() -> Self {
        TextureFields {
            ok: true,
            sources: Vec::new(),
            file: None,
            faces: None,
            generator: None,
            kind: None,
            params_given: Vec::new(),
            size: DEFAULT_TEXTURE_SIZE,
            params: GeneratorParams::default(),
            filter: Filter::default(),
            wrap: Wrap::default(),
            format: (TexelFormat::default(), None),
            filter_given: false,
            colors_span: None,
        }
    }
}

impl Ctx<'_> {
    pub(super) fn textures(&mut self, t: &DeTable<'_>) -> Vec<TextureDecl> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let name = key(k);
            let name_ok = self.check_uniform_name(name, k.span());
            let what = format!("texture `{name}`");
            let decl = match v.get_ref() {
                DeValue::String(_) => self.file_path(v, &what, Code::AssetNotFound, "texture file").map(|path| TextureDecl {
                    name: name.to_owned(),
                    name_span: k.span(),
                    kind: TextureKind::D2,
                    source: TextureSource::File(path),
                    span: v.span(),
                    filter: Filter::default(),
                    wrap: Wrap::default(),
                    format: TexelFormat::default(),
                }),
                DeValue::Table(tt) => self.texture_table(name, k, v, tt),
                _ => {
                    self.wrong_type(v, &what, "an image path or a table");
                    let d = self.diags.last_mut().expect("just pushed");
                    d.help = Some("write `{ file = \"image.png\" }`, `{ cube = [six images] }` or `{ generate = \"checker\" }`".into());
                    None
                }
            };
            if let (Some(d), true) = (decl, name_ok) {
                out.push(d);
            }
        }
        out
    }

    fn texture_table(&mut self, name: &str, k: &Key<'_>, v: &Val<'_>, t: &DeTable<'_>) -> Option<TextureDecl> {
        let f = self.texture_fields(name, t);
        let source_kind = self.texture_source(name, v, &f.sources)?;
        let tex_kind = self.texture_kind(name, source_kind, f.kind.clone());
        let params_ok = self.check_generator_params(name, source_kind, f.generator, &f.params_given);
        let format_ok = self.check_format(name, &f, tex_kind);
        if !(f.ok && tex_kind.is_some() && params_ok && format_ok) {
            return None;
        }
        let source = match source_kind {
            "file" => TextureSource::File(f.file?),
            "cube" => TextureSource::Faces(f.faces?),
            _ => TextureSource::Generated { generator: f.generator?, size: f.size, params: f.params },
        };
        Some(TextureDecl {
            name: name.to_owned(),
            name_span: k.span(),
            kind: tex_kind?,
            source,
            span: v.span(),
            // Integer textures are read texel by texel.
            filter: if f.format.0.filterable() { f.filter } else { Filter::Nearest },
            wrap: f.wrap,
            format: f.format.0,
        })
    }

    /// An integer format takes integer colours in its range, is sampled with `nearest` (GL
    /// filters no integer texture) and is 2D; a filter asked of it is an error.
    fn check_format(&mut self, name: &str, f: &TextureFields, kind: Option<TextureKind>) -> bool {
        let (format, Some(span)) = (f.format.0, f.format.1.clone()) else { return true };
        let (lo, hi) = match format.kind() {
            TexelKind::Float => return true,
            TexelKind::Sint => (f64::from(i32::MIN), f64::from(i32::MAX)),
            TexelKind::Uint => (0.0, f64::from(u32::MAX)),
        };
        let mut ok = true;
        if f.filter == Filter::Linear && f.filter_given {
            let d = self.report(
                Code::ManifestConflict,
                span.clone(),
                format!("texture `{name}`: an integer format cannot be filtered linearly"),
                "integer format",
            );
            d.help = Some("drop `filter` or write `filter = \"nearest\"`: integer textures are read texel by texel".into());
            ok = false;
        }
        if kind == Some(TextureKind::Cube) {
            let d = self.report(
                Code::ManifestConflict,
                span.clone(),
                format!("texture `{name}`: integer cube maps are not supported"),
                "integer format",
            );
            d.help = Some("use a 2D texture, or a floating-point format".into());
            ok = false;
        }
        let bad = f.params.colors.iter().flatten().any(|c| c.fract() != 0.0 || *c < lo || *c > hi);
        if bad {
            let at = f.colors_span.clone().unwrap_or(span);
            let d = self.report(
                Code::ManifestValue,
                at,
                format!("texture `{name}`: `{}` holds integers; its colours must be whole numbers in [{lo}, {hi}]", format.name()),
                "not an integer of this format",
            );
            d.help = Some("write the integer each texel holds, such as `colors = [[0, 0, 0, 0], [7, 1, 255, 1]]`".into());
            ok = false;
        }
        ok
    }

    /// Reads every key of a texture table; what they say together is checked by the caller.
    fn texture_fields(&mut self, name: &str, t: &DeTable<'_>) -> TextureFields {
        let mut f = TextureFields::new();
        for (k2, v2) in entries(t) {
            let what = format!("`textures.{name}.{}`", key(k2));
            let what = what.as_str();
            match key(k2) {
                "file" => {
                    f.sources.push(("file", k2.span()));
                    f.file = self.file_path(v2, what, Code::AssetNotFound, "texture file");
                    f.ok &= f.file.is_some();
                }
                "cube" => {
                    f.sources.push(("cube", k2.span()));
                    f.faces = self.faces(v2, what);
                    f.ok &= f.faces.is_some();
                }
                "generate" => {
                    f.sources.push(("generate", k2.span()));
                    let choices: Vec<_> = Generator::ALL.iter().map(|g| (g.name(), *g)).collect();
                    f.generator = self.choice(v2, what, "generator", &choices);
                    f.ok &= f.generator.is_some();
                }
                "kind" => {
                    let choices = [("2d", TextureKind::D2), ("cube", TextureKind::Cube)];
                    match self.choice(v2, what, "texture kind", &choices) {
                        Some(x) => f.kind = Some((x, k2.span())),
                        None => f.ok = false,
                    }
                }
                p @ ("size" | "colors" | "cells" | "seed" | "octaves") => {
                    let p = GEN_PARAMS.iter().copied().find(|g| *g == p).unwrap_or("size");
                    f.params_given.push((p, k2.span()));
                    let parsed = match p {
                        "size" => self.uint(v2, what, 1, MAX_TEXTURE_SIZE).map(|n| f.size = n),
                        "colors" => self.colors(v2, what).map(|c| {
                            f.params.colors = c;
                            f.colors_span = Some(v2.span());
                        }),
                        "cells" => self.uint(v2, what, 1, MAX_CELLS).map(|n| f.params.cells = n),
                        "seed" => self.uint(v2, what, 0, u32::MAX).map(|n| f.params.seed = n),
                        _ => self.uint(v2, what, 1, MAX_OCTAVES).map(|n| f.params.octaves = n),
                    };
                    f.ok &= parsed.is_some();
                }
                "filter" => {
                    let choices = [("linear", Filter::Linear), ("nearest", Filter::Nearest)];
                    match self.choice(v2, what, "filter", &choices) {
                        Some(x) => {
                            f.filter = x;
                            f.filter_given = true;
                        }
                        None => f.ok = false,
                    }
                }
                "format" => {
                    let choices: Vec<_> = TexelFormat::ALL.iter().map(|x| (x.name(), *x)).collect();
                    match self.choice(v2, what, "texel format", &choices) {
                        Some(x) => f.format = (x, Some(v2.span())),
                        None => f.ok = false,
                    }
                }
                "wrap" => {
                    let choices = [("repeat", Wrap::Repeat), ("clamp", Wrap::Clamp), ("mirror", Wrap::Mirror)];
                    match self.choice(v2, what, "wrap mode", &choices) {
                        Some(w) => f.wrap = w,
                        None => f.ok = false,
                    }
                }
                other => {
                    self.unknown_key(other, k2.span(), &format!("in texture `{name}`"), TEXTURE_KEYS);
                    f.ok = false;
                }
            }
        }
        f
    }

    /// The one source key (`file`, `cube` or `generate`) of a texture table.
    fn texture_source(&mut self, name: &str, v: &Val<'_>, sources: &[(&'static str, Range<usize>)]) -> Option<&'static str> {
        match sources {
            [] => {
                let d = self.report(
                    Code::ManifestMissing,
                    v.span(),
                    format!("texture `{name}` has no source"),
                    "no `file`, `cube` or `generate`",
                );
                d.help = Some("add `file = \"image.png\"`, `cube = [six images]` or `generate = \"checker\"`".into());
                None
            }
            [(s, _)] => Some(*s),
            [(_, first), (_, second), ..] => {
                let file_id = self.file;
                let (first, second) = (first.clone(), second.clone());
                let d = self.report(Code::ManifestConflict, second, format!("texture `{name}` has more than one source"), "second source");
                d.labels.push(crate::diag::Label { file: file_id, span: first, message: "first source".into() });
                d.help = Some("keep exactly one of `file`, `cube` and `generate`".into());
                None
            }
        }
    }

    /// The texture's kind: `cube = [...]` is a cube; `file` is 2D; `generate` is either
    /// (default 2D). `None` when an explicit `kind` contradicts the source (reported).
    fn texture_kind(&mut self, name: &str, source_kind: &str, kind: Option<(TextureKind, Range<usize>)>) -> Option<TextureKind> {
        let natural = if source_kind == "cube" { TextureKind::Cube } else { TextureKind::D2 };
        match kind {
            Some((want, span)) if source_kind != "generate" && want != natural => {
                let msg = match source_kind {
                    "cube" => {
                        format!("texture `{name}` lists six cube faces but says `kind = \"2d\"`")
                    }
                    _ => format!("texture `{name}` is a single image but says `kind = \"cube\"`"),
                };
                let d = self.report(Code::ManifestConflict, span, msg, "conflicts with the source");
                d.help = Some("a cube map comes from `cube = [six images]` or from `generate` with `kind = \"cube\"`".into());
                None
            }
            Some((want, _)) => Some(want),
            None => Some(natural),
        }
    }

    /// Generator parameters on a loaded image are errors; parameters the chosen generator
    /// ignores are warnings. False when an error was reported.
    fn check_generator_params(
        &mut self,
        name: &str,
        source_kind: &str,
        generator: Option<Generator>,
        params_given: &[(&'static str, Range<usize>)],
    ) -> bool {
        let mut ok = true;
        if source_kind != "generate" {
            for (p, span) in params_given {
                let d = self.report(
                    Code::ManifestConflict,
                    span.clone(),
                    format!("`{p}` only applies to generated textures"),
                    format!("texture `{name}` is loaded from {}", if source_kind == "cube" { "images" } else { "a file" }),
                );
                d.help = Some(format!("remove `{p}`"));
                ok = false;
            }
        } else if let Some(g) = generator {
            for (p, span) in params_given {
                if *p != "size" && !g.params().contains(p) {
                    let d = self.report(
                        Code::UnusedGeneratorParam,
                        span.clone(),
                        format!("`{p}` has no effect on the `{}` generator", g.name()),
                        "ignored",
                    );
                    d.notes.push(format!("`{}` uses: size, {}", g.name(), g.params().join(", ")));
                }
            }
        }
        ok
    }

    fn faces(&mut self, v: &Val<'_>, what: &str) -> Option<[PathBuf; 6]> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, "an array of six image paths");
            let d = self.diags.last_mut().expect("just pushed");
            d.notes.push(format!("faces are listed in the order {FACE_ORDER}"));
            return None;
        };
        if items.len() != 6 {
            let d = self.report(
                Code::ManifestValue,
                v.span(),
                format!("{what} needs exactly six images, found {}", items.len()),
                "expected six paths",
            );
            d.notes.push(format!("faces are listed in the order {FACE_ORDER}"));
            return None;
        }
        let paths: Vec<Option<PathBuf>> =
            items.iter().map(|item| self.file_path(item, what, Code::AssetNotFound, "cube face image")).collect();
        let paths: Option<Vec<PathBuf>> = paths.into_iter().collect();
        paths?.try_into().ok()
    }

    /// `colors = [a, b]` (each 3 or 4 numbers), `colors = [a]`, or a single colour `[r, g, b(, a)]`.
    fn colors(&mut self, v: &Val<'_>, what: &str) -> Option<[[f64; 4]; 2]> {
        const EXPECTED: &str = "one or two colours of 3 or 4 numbers (`[[1, 0, 0], [0, 0, 1]]`)";
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, EXPECTED);
            return None;
        };
        let mut out = GeneratorParams::default().colors;
        let single = items.first().is_some_and(|i| !matches!(i.get_ref(), DeValue::Array(_)));
        let colours: Vec<&Val<'_>> = if single { vec![v] } else { items.iter().collect() };
        if colours.is_empty() || colours.len() > 2 {
            self.report(Code::ManifestValue, v.span(), format!("{what} must be {EXPECTED}"), format!("found {} colours", colours.len()));
            return None;
        }
        let mut ok = true;
        for (slot, c) in colours.into_iter().enumerate() {
            match self.colour(c, what) {
                Some(rgba) => out[slot] = rgba,
                None => ok = false,
            }
        }
        ok.then_some(out)
    }

    fn colour(&mut self, v: &Val<'_>, what: &str) -> Option<[f64; 4]> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, "a colour of 3 or 4 numbers");
            return None;
        };
        if !(3..=4).contains(&items.len()) {
            self.report(
                Code::ManifestValue,
                v.span(),
                format!("{what}: a colour has 3 or 4 components, found {}", items.len()),
                "expected [r, g, b] or [r, g, b, a]",
            );
            return None;
        }
        let mut rgba = [1.0f64; 4];
        let mut ok = true;
        for (i, item) in items.iter().enumerate() {
            match self.number(item, what) {
                Some(x) if (x as f32).is_finite() => rgba[i] = x,
                Some(_) => {
                    self.report(Code::ManifestValue, item.span(), format!("{what}: component is too large"), "beyond f32 range");
                    ok = false;
                }
                None => ok = false,
            }
        }
        ok.then_some(rgba)
    }
}
