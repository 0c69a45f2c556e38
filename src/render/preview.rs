//! What `render` would warn about a manifest's scenes, found without a device: the
//! guessed mesh, vertex inputs matched by a guess or reading zeros, uniforms given a
//! guessed value and samplers reading a placeholder, for every pass that runs. `effectc
//! check` of a manifest adds these to its report, so that a lint and a render of the same
//! manifest say the same things.

use crate::back::TranslateOptions;
use crate::check::{Checked, Outcome};
use crate::diag::Diagnostic;
use crate::render::drawer::{prepare, with_overrides, BuildSettings};
use crate::render::scene::plan::{plan, PlanInput};

/// The scene warnings of `c` when it comes from a manifest and checked clean (a program
/// with errors, or bare stage files, gets none: bare files have no manifest to fill in).
/// `gl_defaults`: uniforms nobody set are zero (`--gl-defaults`), not guessed.
pub fn warnings(c: &Checked, gl_defaults: bool) -> Vec<Diagnostic> {
    if c.effect.is_none() {
        return Vec::new();
    }
    let settings =
        BuildSettings { back: TranslateOptions::for_rendering(true), size: None, dump_targets: false, timestamps: false, gl_defaults };
    // Translation errors are translate's and render's to report, not the lint's.
    let mut scratch = Outcome::default();
    let Some(prepared) = prepare(c, &mut scratch, &settings, None) else { return Vec::new() };
    let multi_pass = c.multi_pass();
    let mut out: Vec<Diagnostic> = Vec::new();
    for (index, translation, _) in &prepared.units {
        let Some(unit) = c.unit(*index) else { continue };
        let effect = unit.effect.as_ref().map(|e| with_overrides(e, &c.values));
        let pass = multi_pass.map(|e| e.passes[*index].samples.iter().map(|s| (s.sampler.clone(), s.target.name.clone())).collect());
        let input = PlanInput {
            translation,
            program: &unit.program,
            effect: effect.as_ref(),
            pass,
            overrides: if multi_pass.is_some() { &[] } else { &c.values },
            gl_defaults,
        };
        match plan(&input) {
            Ok(p) => out.extend(p.warnings),
            Err(errors) => out.extend(errors),
        }
    }
    // Passes sharing a stage file would report the same guess once each.
    crate::diag::dedup(&mut out);
    out
}
