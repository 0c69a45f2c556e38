//! SARIF 2.1.0 output, for GitHub code scanning and other static-analysis dashboards.

use std::collections::BTreeSet;

use serde::Serialize;

use super::{full_message, Code, Diagnostic, FileId, Files, Severity};

const SCHEMA: &str = "https://json.schemastore.org/sarif-2.1.0.json";
const INFORMATION_URI: &str = "https://github.com/effectc/effectc";

#[derive(Serialize)]
struct Log<'a> {
    #[serde(rename = "$schema")]
    schema: &'static str,
    version: &'static str,
    runs: [Run<'a>; 1],
}

#[derive(Serialize)]
struct Run<'a> {
    tool: Tool<'a>,
    results: Vec<SarifResult<'a>>,
}

#[derive(Serialize)]
struct Tool<'a> {
    driver: Driver<'a>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Driver<'a> {
    name: &'static str,
    information_uri: &'static str,
    version: &'static str,
    rules: Vec<Rule<'a>>,
}

/// A rule as code scanning shows it: its id, a name, the code's title as the short
/// description, a sentence on what kind of finding it is as the full one, a help link, and
/// its default level.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Rule<'a> {
    id: &'a str,
    name: String,
    short_description: Message,
    full_description: Message,
    help_uri: String,
    default_configuration: Configuration,
}

#[derive(Serialize)]
struct Configuration {
    level: &'static str,
}

impl Rule<'_> {
    fn of(code: &Code) -> Rule<'_> {
        let kind = match code.severity() {
            Severity::Error => "an error: the program is wrong, or cannot be checked or translated",
            Severity::Warning => "a warning: legal, but likely not what the author meant, or a hazard at run time",
            Severity::Note => "a note: what effectc did or could not do, for the record",
        };
        Rule {
            id: code.as_str(),
            name: format!("{code:?}"),
            short_description: Message { text: code.title().to_string() },
            full_description: Message { text: format!("{} ({}). effectc reports {kind}.", code.title(), code.as_str()) },
            help_uri: format!("{INFORMATION_URI}#diagnostics"),
            default_configuration: Configuration { level: level(code.severity()) },
        }
    }
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct SarifResult<'a> {
    rule_id: &'a str,
    rule_index: usize,
    level: &'static str,
    message: Message,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    locations: Vec<Location>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    related_locations: Vec<Location>,
}

#[derive(Serialize)]
struct Message {
    text: String,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Location {
    #[serde(skip_serializing_if = "Option::is_none")]
    id: Option<usize>,
    physical_location: PhysicalLocation,
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<Message>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct PhysicalLocation {
    artifact_location: ArtifactLocation,
    #[serde(skip_serializing_if = "Option::is_none")]
    region: Option<Region>,
}

#[derive(Serialize)]
struct ArtifactLocation {
    uri: String,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Region {
    start_line: usize,
    start_column: usize,
    end_line: usize,
    end_column: usize,
    byte_offset: usize,
    byte_length: usize,
}

/// A path as a SARIF URI reference: forward slashes, absolute paths as `file://` URIs,
/// and bytes outside the URI path character set percent-encoded.
fn path_to_uri(path: &str) -> String {
    let path = path.replace('\\', "/");
    let bytes = path.as_bytes();
    let drive = bytes.len() >= 2 && bytes[0].is_ascii_alphabetic() && bytes[1] == b':';
    let mut uri = String::from(match () {
        _ if path.starts_with('/') => "file://",
        _ if drive => "file:///", // Windows drive letter
        _ => "",
    });
    for (i, &b) in bytes.iter().enumerate() {
        let keep = b.is_ascii_alphanumeric() || b"-._~/!$&'()*+,;=@".contains(&b) || (drive && i == 1);
        if keep {
            uri.push(b as char);
        } else {
            uri.push_str(&format!("%{b:02X}"));
        }
    }
    uri
}

fn location(files: &Files, file: FileId, span: Option<std::ops::Range<usize>>) -> Option<PhysicalLocation> {
    let source = files.try_get(file)?;
    let region = span.and_then(|span| files.span_location(file, span)).map(|loc| Region {
        start_line: loc.line,
        start_column: loc.column,
        end_line: loc.end_line,
        end_column: loc.end_column,
        byte_offset: loc.start,
        byte_length: loc.end - loc.start,
    });
    Some(PhysicalLocation { artifact_location: ArtifactLocation { uri: path_to_uri(&source.path) }, region })
}

fn level(s: Severity) -> &'static str {
    match s {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Note => "note",
    }
}

/// Render diagnostics as a SARIF 2.1.0 log (pretty JSON, ending in a newline) with one run
/// of the `effectc` tool. `tool.driver.rules` has one entry per distinct code, sorted by
/// code, with its name, title, description, help link and default level; each result has `ruleId`/`ruleIndex`, `level` (`error`/`warning`/`note`),
/// `message.text` (message, notes and `help: ...`, one per line), one location with a
/// region (1-based lines, 1-based character columns with an exclusive end, byte offset and
/// length) when the diagnostic has a file, and `relatedLocations` (with the label text as
/// their message) for secondary labels. Paths become URI references with forward slashes.
pub fn render_sarif(diags: &[Diagnostic], files: &Files) -> String {
    let diags = &files.resolved(diags)[..];
    // `Code`'s order is the order of the code strings.
    let codes: Vec<Code> = diags.iter().map(|d| d.code).collect::<BTreeSet<_>>().into_iter().collect();
    let results = diags
        .iter()
        .map(|d| SarifResult {
            rule_id: d.code.as_str(),
            rule_index: codes.binary_search(&d.code).expect("every code is in the rules"),
            level: level(d.severity()),
            message: Message { text: full_message(d) },
            locations: d
                .file
                .and_then(|file| location(files, file, d.span.clone()))
                .map(|physical_location| Location { id: None, physical_location, message: None })
                .into_iter()
                .collect(),
            related_locations: d
                .labels
                .iter()
                .filter_map(|l| Some((location(files, l.file, Some(l.span.clone()))?, &l.message)))
                .enumerate()
                .map(|(i, (physical_location, text))| Location {
                    id: Some(i),
                    physical_location,
                    message: Some(Message { text: text.clone() }).filter(|m| !m.text.is_empty()),
                })
                .collect(),
        })
        .collect();
    let log = Log {
        schema: SCHEMA,
        version: "2.1.0",
        runs: [Run {
            tool: Tool {
                driver: Driver {
                    name: "effectc",
                    information_uri: INFORMATION_URI,
                    version: env!("CARGO_PKG_VERSION"),
                    rules: codes.iter().map(Rule::of).collect(),
                },
            },
            results,
        }],
    };
    let mut out = serde_json::to_string_pretty(&log).expect("JSON serialization of plain data cannot fail");
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::{json, Value};

    #[test]
    fn sarif_top_level_and_results() {
        let mut files = Files::new();
        let vs = files.add("shaders\\a b.vert", "out vec3 c;\n");
        let fs = files.add("shaders/a.frag", "in vec4 c;\r\nvoid main() {}\r\n");
        let diags = vec![
            Diagnostic::new(Code::BindingConflict, "type mismatch")
                .at(fs, 8..9, "vec4 here")
                .with_label(vs, 9..10, "vec3 here")
                .with_note("types must match")
                .with_help("change one"),
            Diagnostic::new(Code::StageExtension, "run-level"),
            Diagnostic::new(Code::BindingConflict, "again").in_file(vs),
        ];
        let v: Value = serde_json::from_str(&render_sarif(&diags, &files)).unwrap();
        assert_eq!(v["$schema"], "https://json.schemastore.org/sarif-2.1.0.json");
        assert_eq!(v["version"], "2.1.0");
        assert_eq!(v["runs"].as_array().unwrap().len(), 1);
        let driver = &v["runs"][0]["tool"]["driver"];
        assert_eq!(driver["name"], "effectc");
        assert_eq!(driver["version"], env!("CARGO_PKG_VERSION"));
        assert_eq!(driver["informationUri"], INFORMATION_URI);
        let rules = driver["rules"].as_array().unwrap();
        let ids: Vec<&str> = rules.iter().map(|r| r["id"].as_str().unwrap()).collect();
        assert_eq!(ids, ["E0301", "W0001"]);
        assert_eq!(rules[0]["name"], "BindingConflict");
        assert_eq!(rules[0]["shortDescription"]["text"], Code::BindingConflict.title());
        assert!(rules[0]["fullDescription"]["text"].as_str().unwrap().contains("an error"));
        assert_eq!(rules[1]["defaultConfiguration"]["level"], "warning");
        assert!(rules.iter().all(|r| r["helpUri"].as_str().unwrap().starts_with("https://")));

        let results = v["runs"][0]["results"].as_array().unwrap();
        assert_eq!(results.len(), 3);
        assert_eq!(
            results[0],
            json!({
                "ruleId": "E0301",
                "ruleIndex": 0,
                "level": "error",
                "message": {"text": "type mismatch\ntypes must match\nhelp: change one"},
                "locations": [{"physicalLocation": {
                    "artifactLocation": {"uri": "shaders/a.frag"},
                    "region": {"startLine": 1, "startColumn": 9, "endLine": 1, "endColumn": 10,
                               "byteOffset": 8, "byteLength": 1}
                }}],
                "relatedLocations": [{
                    "id": 0,
                    "physicalLocation": {
                        "artifactLocation": {"uri": "shaders/a%20b.vert"},
                        "region": {"startLine": 1, "startColumn": 10, "endLine": 1, "endColumn": 11,
                                   "byteOffset": 9, "byteLength": 1}
                    },
                    "message": {"text": "vec3 here"}
                }]
            })
        );
        assert_eq!(results[1], json!({"ruleId": "W0001", "ruleIndex": 1, "level": "warning", "message": {"text": "run-level"}}));
        assert_eq!(results[2]["locations"], json!([{"physicalLocation": {"artifactLocation": {"uri": "shaders/a%20b.vert"}}}]));
    }

    #[test]
    fn uris() {
        assert_eq!(path_to_uri("a/b.frag"), "a/b.frag");
        assert_eq!(path_to_uri("a\\b c.frag"), "a/b%20c.frag");
        assert_eq!(path_to_uri("/abs/ü.frag"), "file:///abs/%C3%BC.frag");
        assert_eq!(path_to_uri("C:\\x\\y.frag"), "file:///C:/x/y.frag");
        assert_eq!(path_to_uri("ab:c#d%.frag"), "ab%3Ac%23d%25.frag");
    }
}
