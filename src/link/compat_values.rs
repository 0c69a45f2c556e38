//! Values for the compatibility profile's uniform state (`gl_LightSource[0].diffuse`,
//! `gl_FrontMaterial.shininess`), which a program reads and no stage declares: the path
//! and the value are checked against GLSL's own declarations of that state
//! ([`compat`](crate::front::compat)), as a declared uniform's are.

use super::declared::Step;
use super::values::Shape;
use crate::diag::{Code, Diagnostic, FileId};
use crate::front::compat;
use crate::front::syntax::{GlslType, StageSyntax};
use crate::manifest::UniformDefault;

/// The diagnostics of `u` when its base name is compatibility state the program reads;
/// `None` when it is not.
pub(super) fn check(mf: FileId, u: &UniformDefault, base: &str, steps: &[Step], stages: &[StageSyntax]) -> Option<Vec<Diagnostic>> {
    let state = compat::state(base)?;
    if !compat::analyse(stages).state.iter().any(|s| s.name == base) {
        return None;
    }
    let mismatch = |message: String, label: String| {
        Some(vec![Diagnostic::new(Code::UniformPathMismatch, message)
            .at(mf, u.name_span.clone(), label)
            .with_note(format!("`{base}` is GL's built-in `{}`", type_text(&state.glsl_type())))])
    };
    let mut ty = state.glsl_type();
    let mut shown = base.to_string();
    for step in steps {
        match step {
            Step::Index(i) => match ty.dims.first().copied().flatten() {
                Some(n) if *i < u64::from(n) => {
                    ty = ty.element();
                    shown = format!("{shown}[{i}]");
                }
                Some(n) => return mismatch(format!("index {i} is out of bounds for `{shown}`"), format!("`{shown}` has {n} elements")),
                None => return mismatch(format!("`{shown}` is not an array"), format!("indexes `{shown}`")),
            },
            Step::Field(f) => match compat::struct_member(&ty.base, f).filter(|_| !ty.is_array()) {
                Some(member) => {
                    ty = GlslType::scalar(member);
                    shown = format!("{shown}.{f}");
                }
                None => {
                    let fields = compat::struct_fields(&ty.base);
                    let d = mismatch(format!("`{shown}` has no field `{f}`"), format!("`{shown}` is a `{}`", type_text(&ty)))?;
                    let members: Vec<String> = fields.iter().map(|m| format!("`{m}`")).collect();
                    return Some(d.into_iter().map(|d| d.with_help(format!("its members are {}", members.join(", ")))).collect());
                }
            },
        }
    }
    if !compat::struct_fields(&ty.base).is_empty() && !ty.is_array() {
        let members: Vec<String> = compat::struct_fields(&ty.base).iter().map(|m| format!("`{shown}.{m}`")).collect();
        return Some(vec![Diagnostic::new(
            Code::UniformDefaultType,
            format!("`{shown}` is a struct (`{}`) and cannot take one value", ty.base),
        )
        .at(mf, u.value_span.clone(), "a value for a whole struct")
        .with_help(format!("set the members one by one: {}", members.join(", ")))]);
    }
    let shape = Shape::of(&ty, &|_| false);
    let fits = u.value.as_ref().map_or(Ok(()), |v| shape.fit(v));
    Some(match fits {
        Ok(()) => Vec::new(),
        Err(why) => {
            vec![Diagnostic::new(Code::UniformDefaultType, format!("the value for `{shown}` does not fit its type `{}`", type_text(&ty)))
                .at(mf, u.value_span.clone(), why)
                .with_note(format!("a `{}` takes {}", type_text(&ty), shape.expected()))]
        }
    })
}

fn type_text(ty: &GlslType) -> String {
    format!("{}{}", ty.base, crate::front::syntax::dims_text(ty))
}
