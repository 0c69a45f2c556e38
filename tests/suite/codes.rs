//! The README documents every diagnostic code: its *Diagnostics* table lists each code of
//! [`Code::ALL`] (single codes in backticks, ranges `` `A`–`B` `` covering every code of
//! that letter from A to B), and no code anywhere in the README is one effectc does not have.

use std::collections::BTreeSet;

use effectc::diag::Code;

/// The codes a piece of Markdown names: `` `E0010` `` alone, and `` `A`–`B` `` (en dash)
/// expanded to every code of [`Code::ALL`] with A's letter from A to B. Codes that are not
/// in [`Code::ALL`] (and range ends of different letters) come back as errors.
fn codes_in(text: &str) -> (BTreeSet<Code>, Vec<String>) {
    let mut found = BTreeSet::new();
    let mut wrong = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find('`') {
        rest = &rest[i + 1..];
        let Some(end) = rest.find('`') else { break };
        let token = &rest[..end];
        rest = &rest[end + 1..];
        if !is_code(token) {
            continue;
        }
        let range_end = rest.strip_prefix("–`").and_then(|r| r.get(..5).filter(|t| is_code(t) && r[5..].starts_with('`')));
        let Some(last) = range_end else {
            match token.parse::<Code>() {
                Ok(c) => {
                    found.insert(c);
                }
                Err(e) => wrong.push(e.to_string()),
            }
            continue;
        };
        rest = &rest["–`".len() + 6..];
        match (token.parse::<Code>(), last.parse::<Code>()) {
            (Ok(a), Ok(b)) if a.as_str()[..1] == b.as_str()[..1] && a < b => {
                found.extend(Code::ALL.iter().copied().filter(|c| (a..=b).contains(c) && c.as_str()[..1] == a.as_str()[..1]));
            }
            (Ok(_), Ok(_)) => wrong.push(format!("`{token}`–`{last}` is not a range of one letter, low to high")),
            (a, b) => wrong.extend([a.err(), b.err()].into_iter().flatten().map(|e| format!("{e} (in `{token}`–`{last}`)"))),
        }
    }
    (found, wrong)
}

/// `[EWN]` and four digits.
fn is_code(s: &str) -> bool {
    s.len() == 5 && s.starts_with(['E', 'W', 'N']) && s[1..].bytes().all(|b| b.is_ascii_digit())
}

/// The table rows of the README's `## Diagnostics` section (up to the next heading).
fn diagnostics_table(readme: &str) -> String {
    let section = readme.split("\n## Diagnostics\n").nth(1).expect("README.md has a `## Diagnostics` section");
    section.lines().take_while(|l| !l.starts_with('#')).filter(|l| l.starts_with('|')).collect::<Vec<_>>().join("\n")
}

#[test]
fn readme_table_lists_every_code() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let (listed, wrong) = codes_in(&diagnostics_table(&readme));
    let missing: Vec<String> = Code::ALL.iter().filter(|c| !listed.contains(c)).map(|c| format!("{c} ({c:?}: {})", c.title())).collect();
    assert!(missing.is_empty(), "codes missing from the README's Diagnostics table:\n{}", missing.join("\n"));
    assert!(wrong.is_empty(), "the README's Diagnostics table names codes effectc does not have:\n{}", wrong.join("\n"));
}

#[test]
fn readme_names_no_stale_code() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let (_, wrong) = codes_in(&readme);
    assert!(wrong.is_empty(), "README.md names codes effectc does not have:\n{}", wrong.join("\n"));
}

#[test]
fn the_parser_sees_what_it_checks() {
    // Guards against a parser that finds nothing and so passes vacuously.
    let (found, wrong) = codes_in("| `E0001`–`E0003`, `W0002` and `W0120`/`E0120` | `E0405` x | `N0241` |");
    let found: Vec<&str> = found.iter().map(|c| c.as_str()).collect();
    assert_eq!(found, ["E0001", "E0002", "E0003", "E0120", "E0405", "N0241", "W0002", "W0120"]);
    assert!(wrong.is_empty(), "{wrong:?}");
    let (_, wrong) = codes_in("`E0099` and `E0001`–`W0003`, `E9998`–`E9999`");
    assert_eq!(wrong.len(), 4, "{wrong:?}");
    let table = diagnostics_table("# x\n`E0001`\n## Diagnostics\n\ntext `E0002`\n| `E0003` |\n### Next\n| `E0004` |\n");
    assert_eq!(table, "| `E0003` |");
}
