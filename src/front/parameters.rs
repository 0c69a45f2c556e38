//! Parameters a stage declares for its host to set, with their ranges: RetroArch's
//! `#pragma parameter NAME "Label" default min max [step]`, read by the libretro shader
//! packs (and the tools that load them) to build a settings menu for the uniform `NAME`.

/// One declared parameter.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Parameter {
    pub name: String,
    pub default: f64,
    pub min: f64,
    pub max: f64,
    /// The menu's step (`None` when absent or not positive).
    pub step: Option<f64>,
    /// Byte offset of the `#pragma` line in the stage text.
    #[serde(skip)]
    pub at: usize,
}

/// Every well-formed parameter line of `text`, in order; a malformed one is skipped (the
/// host skips it too).
pub fn parameters(text: &str) -> Vec<Parameter> {
    let mut out = Vec::new();
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        if let Some(p) = parse_line(line, at) {
            out.push(p);
        }
        at += line.len();
    }
    out
}

fn parse_line(line: &str, at: usize) -> Option<Parameter> {
    let rest = line.trim_start().strip_prefix('#')?.trim_start().strip_prefix("pragma")?;
    let rest = rest.trim_start().strip_prefix("parameter")?;
    if !rest.starts_with(char::is_whitespace) {
        return None;
    }
    let rest = rest.trim_start();
    let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))?;
    let (name, rest) = rest.split_at(end);
    if name.is_empty() || name.starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    // The label is quoted; numbers follow its closing quote.
    let rest = rest.trim_start().strip_prefix('"')?;
    let rest = &rest[rest.find('"')? + 1..];
    let numbers: Vec<f64> = rest.split_whitespace().take(4).map_while(|w| w.parse::<f64>().ok().filter(|x| x.is_finite())).collect();
    let [default, min, max] = numbers.get(..3)?.try_into().ok()?;
    if min > max {
        return None;
    }
    let step = numbers.get(3).copied().filter(|s| *s > 0.0);
    Some(Parameter { name: name.to_string(), default, min, max, step, at })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_name_default_range_and_step() {
        let text = "#version 130\n#pragma parameter MASK_TYPE \"Mask Type\" 4.0 0.0 7.0 1.0\n  #  pragma parameter warpX \"Curvature X\" 0.03 0.00 0.20 \n";
        let p = parameters(text);
        assert_eq!(p.len(), 2);
        assert_eq!((p[0].name.as_str(), p[0].default, p[0].min, p[0].max, p[0].step), ("MASK_TYPE", 4.0, 0.0, 7.0, Some(1.0)));
        assert_eq!(p[0].at, 13);
        assert_eq!((p[1].name.as_str(), p[1].step), ("warpX", None));
    }

    #[test]
    fn skips_malformed_lines() {
        let text = "#pragma parameter x \"no numbers\"\n#pragma parameter y \"reversed\" 0 1 0\n#pragma parameterz \"a\" 0 0 1\n#pragma optimize(on)\n";
        assert_eq!(parameters(text), Vec::new());
    }
}
