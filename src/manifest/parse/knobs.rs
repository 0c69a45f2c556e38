//! `[knobs]`: quality knobs for `effectc bench`.
//!
//! `numLayers = { values = [4, 8, 16, 32, 64], reference = 64 }`: the uniform `numLayers`
//! (an entry of `[uniforms]`) is swept over `values`; `reference` (default: the last value)
//! is the most accurate setting, whose frames the others are compared with.

use toml::de::{DeTable, DeValue};

use super::{entries, key, Ctx};
use crate::diag::Code;
use crate::manifest::KnobDecl;

const KNOB_KEYS: &[&str] = &["values", "reference"];
/// At most this many values per knob (each renders the frames several times).
const MAX_VALUES: usize = 32;

impl Ctx<'_> {
    pub(super) fn knobs(&mut self, t: &DeTable<'_>) -> Vec<KnobDecl> {
        let mut out = Vec::new();
        for (k, v) in entries(t) {
            let name = key(k);
            if !self.check_uniform_name(name, k.span()) {
                continue;
            }
            let Some(spec) = self.table(v, &format!("knob `{name}`")) else { continue };
            let mut values = None;
            let mut reference = None;
            for (k2, v2) in entries(spec) {
                let what = format!("`knobs.{name}.{}`", key(k2));
                match key(k2) {
                    "values" => match v2.get_ref() {
                        DeValue::Array(items) if !items.is_empty() && items.len() <= MAX_VALUES => {
                            let parsed: Vec<Option<f64>> = items.iter().map(|i| self.number(i, &what)).collect();
                            if parsed.iter().all(Option::is_some) {
                                values = Some(parsed.into_iter().flatten().collect::<Vec<f64>>());
                            }
                        }
                        DeValue::Array(_) => {
                            self.report(Code::ManifestValue, v2.span(), format!("{what} needs 1 to {MAX_VALUES} values"), "wrong length");
                        }
                        _ => self.wrong_type(v2, &what, "an array of numbers"),
                    },
                    "reference" => reference = self.number(v2, &what).map(|r| (r, v2.span())),
                    other => self.unknown_key(other, k2.span(), &format!("in knob `{name}`"), KNOB_KEYS),
                }
            }
            let Some(values) = values else {
                if !spec.contains_key("values") {
                    let d = self.report(Code::ManifestMissing, k.span(), format!("knob `{name}` has no `values`"), "no values to sweep");
                    d.help = Some("add e.g. `values = [4, 8, 16, 32]`".into());
                }
                continue;
            };
            let reference = match reference {
                Some((r, span)) if !values.contains(&r) => {
                    let d = self.report(
                        Code::ManifestValue,
                        span,
                        format!("the reference of knob `{name}` is not one of its values"),
                        "not in `values`",
                    );
                    d.help = Some("the reference is the most accurate of the swept values".into());
                    continue;
                }
                Some((r, _)) => r,
                None => *values.last().expect("non-empty"),
            };
            out.push(KnobDecl { name: name.to_owned(), name_span: k.span(), values, reference });
        }
        out
    }
}
