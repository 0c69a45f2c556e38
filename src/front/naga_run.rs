//! Runs naga's GLSL front and validator on rewritten text, mapping errors to the user's file.
//!
//! naga can panic on some inputs; every call here is wrapped in `catch_unwind`, and a panic
//! becomes an error diagnostic instead of taking the process down.

use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::diag::{Diagnostic, FileId};
use crate::front::rewrite::Rewritten;

/// A naga module that passed validation, with its analysis.
#[derive(Debug)]
pub struct Validated {
    pub module: naga::Module,
    pub info: naga::valid::ModuleInfo,
}

/// The validator every backend output goes through: all checks, WebGPU capabilities.
pub fn validator() -> naga::valid::Validator {
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::default())
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

/// Parses and validates one rewritten stage.
pub fn parse_and_validate(
    file: FileId,
    rewritten: &Rewritten,
    stage: naga::ShaderStage,
) -> Result<Validated, Vec<Diagnostic>> {
    let text = &rewritten.text;
    let map_span = |span: naga::Span| span.to_range().map(|r| rewritten.map.range_to_original(r));
    let parsed = catch_unwind(AssertUnwindSafe(|| {
        let mut frontend = naga::front::glsl::Frontend::default();
        frontend.parse(&naga::front::glsl::Options::from(stage), text)
    }));
    let module = match parsed {
        Ok(Ok(m)) => m,
        Ok(Err(errors)) => {
            return Err(errors
                .errors
                .iter()
                .map(|e| {
                    let d = Diagnostic::error("E0150", e.kind.to_string());
                    match map_span(e.meta) {
                        Some(span) => d.at(file, span, "naga's GLSL front rejects this"),
                        None => d.in_file(file),
                    }
                })
                .collect())
        }
        Err(payload) => return Err(vec![crash(file, "GLSL front", &*payload)]),
    };
    let validated = catch_unwind(AssertUnwindSafe(|| validator().validate(&module)));
    match validated {
        Ok(Ok(info)) => Ok(Validated { module, info }),
        Ok(Err(err)) => Err(vec![validation_diagnostic(file, &err, &map_span)]),
        Err(payload) => Err(vec![crash(file, "validator", &*payload)]),
    }
}

fn crash(file: FileId, part: &str, payload: &(dyn std::any::Any + Send)) -> Diagnostic {
    Diagnostic::error("E0152", format!("naga's {part} crashed on this file"))
        .in_file(file)
        .with_note(format!("panic: {}", panic_message(payload)))
        .with_note("this is a bug in naga; effectc contained it. Please report the input")
}

/// A validation error with the whole chain of causes and every span naga attached.
pub fn validation_diagnostic<E: std::error::Error>(
    file: FileId,
    err: &naga::WithSpan<E>,
    map_span: &dyn Fn(naga::Span) -> Option<std::ops::Range<usize>>,
) -> Diagnostic {
    let inner = err.as_inner();
    let mut message = inner.to_string();
    let mut source = inner.source();
    let mut notes = Vec::new();
    while let Some(s) = source {
        notes.push(s.to_string());
        source = s.source();
    }
    if let Some(first) = notes.first() {
        message = format!("{message}: {first}");
        notes.remove(0);
    }
    let mut d = Diagnostic::error("E0151", format!("naga validation: {message}"));
    let mut spans = err.spans().filter_map(|(span, label)| map_span(*span).map(|r| (r, label.clone())));
    match spans.next() {
        Some((r, label)) => {
            d = d.at(file, r, label);
            for (r, label) in spans {
                d = d.with_label(file, r, label);
            }
        }
        None => d = d.in_file(file),
    }
    for n in notes {
        d = d.with_note(n);
    }
    d
}
