//! How much of an input effectc reads and models: the limits that keep hostile or
//! generated input bounded in memory and time, their defaults, and their names in
//! `effectc.toml`'s `[limits]` table.
//!
//! ```toml
//! [limits]
//! file-bytes = 16777216          # a stage or included file (16 MiB)
//! statement-tokens = 200000      # one statement (a sum of ~100,000 terms)
//! macro-tokens = 1048576         # what one macro may expand to (2^20)
//! stage-tokens = 600000          # the stage, includes inlined and macros expanded
//! array-elements = 65536         # one uniform or private global array
//! ```
//!
//! The defaults sit far above real shaders (the largest generated stages met are ~2 MB,
//! the longest statements a few thousand tokens) and keep what any admitted stage costs
//! under a gigabyte: the stage's tokens, macros expanded, bound the compilers' memory.
//! Nesting depth has no limit of effectc's own: glslang's parser refuses nesting past its
//! stack (~1,400 nested `if`s, ~10,000 parentheses: "memory exhausted"), and every walk of
//! effectc's runs on a stack sized for what glslang accepts.

/// The limits of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Bytes of one stage or included file.
    pub file_bytes: u64,
    /// Tokens in one statement (between `;`, `{` and `}`): glslangValidator itself
    /// crashes near 100,000 terms of a sum.
    pub statement_tokens: u64,
    /// Tokens one macro may expand to (`#define A1 A0+A0` doubling at each level).
    pub macro_tokens: u64,
    /// Tokens of a stage with its includes inlined and its macros expanded: the compilers'
    /// memory grows with them, 0.4–1.4 KB a token by the code's shape (long sums cost
    /// most: three 99,000-term sums, 594,000 tokens, take 0.8 GB to check, 0.9 to translate).
    pub stage_tokens: u64,
    /// Elements in one uniform or private global array (all dimensions): GL's uniform
    /// storage holds a few thousand (Mesa refuses more at link), and effectc models each.
    pub array_elements: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

impl Limits {
    /// The limits of a run that sets none.
    pub const DEFAULT: Limits =
        Limits { file_bytes: 16 << 20, statement_tokens: 200_000, macro_tokens: 1 << 20, stage_tokens: 600_000, array_elements: 1 << 16 };

    /// Each limit's key in `[limits]`, with its value in `self`.
    pub fn named(&self) -> [(&'static str, u64); 5] {
        [
            ("file-bytes", self.file_bytes),
            ("statement-tokens", self.statement_tokens),
            ("macro-tokens", self.macro_tokens),
            ("stage-tokens", self.stage_tokens),
            ("array-elements", self.array_elements),
        ]
    }

    /// Sets the limit called `key` (a `[limits]` key); `false` when there is none by that name.
    pub fn set(&mut self, key: &str, value: u64) -> bool {
        let slot = match key {
            "file-bytes" => &mut self.file_bytes,
            "statement-tokens" => &mut self.statement_tokens,
            "macro-tokens" => &mut self.macro_tokens,
            "stage-tokens" => &mut self.stage_tokens,
            "array-elements" => &mut self.array_elements,
            _ => return false,
        };
        *slot = value;
        true
    }

    /// The note every E0107 carries: which key raises the limit.
    pub fn how_to_raise(key: &str) -> String {
        format!("the limit is `{key}` in the `[limits]` table of `effectc.toml`")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_named_limit_can_be_set_by_its_name() {
        let mut l = Limits::default();
        for (i, (key, _)) in Limits::default().named().iter().enumerate() {
            assert!(l.set(key, i as u64 + 1));
        }
        assert_eq!(l.named().map(|(_, v)| v), [1, 2, 3, 4, 5]);
        assert!(!l.set("nesting", 3));
    }
}
