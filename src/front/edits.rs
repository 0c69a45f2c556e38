//! Text edits on a user's GLSL file and the offset map back from the rewritten text.
//!
//! The rewrite to GLSL 450 is a sorted list of non-overlapping replacements on the original
//! text. Applying them yields the new text plus an [`OffsetMap`] that maps any byte offset
//! in the new text to the original offset it came from, so naga's errors land on the
//! user's line and column.

use std::ops::Range;

/// Replace `range` of the original text with `text` (an empty range inserts).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Edit {
    pub range: Range<usize>,
    pub text: String,
}

/// A set of edits collected in any order; insertions at the same point keep their order.
#[derive(Debug, Default, Clone)]
pub struct Edits {
    edits: Vec<Edit>,
}

/// One piece of the rewritten text: `new` bytes that came from `old` bytes of the original
/// (copied verbatim when `copied`, else generated from that original range).
#[derive(Debug, Clone, PartialEq, Eq)]
struct Segment {
    new: Range<usize>,
    old: Range<usize>,
    copied: bool,
}

/// Maps offsets in rewritten text back to the original.
#[derive(Debug, Clone, Default)]
pub struct OffsetMap {
    segments: Vec<Segment>,
    original_len: usize,
}

impl Edits {
    pub fn new() -> Self {
        Self::default()
    }
    pub fn replace(&mut self, range: Range<usize>, text: impl Into<String>) {
        self.edits.push(Edit { range, text: text.into() });
    }
    pub fn insert(&mut self, at: usize, text: impl Into<String>) {
        self.replace(at..at, text);
    }
    pub fn delete(&mut self, range: Range<usize>) {
        self.replace(range, String::new());
    }
    pub fn is_empty(&self) -> bool {
        self.edits.is_empty()
    }

    /// Whether an edit replaces any of `range` or inserts strictly inside it.
    pub fn touches(&self, range: &Range<usize>) -> bool {
        self.edits.iter().any(|e| match e.range.is_empty() {
            true => range.start < e.range.start && e.range.start < range.end,
            false => e.range.start < range.end && range.start < e.range.end,
        })
    }

    /// `original[range]` with the edits inside `range` applied: for text the rewrite
    /// writes a second time elsewhere (a loop condition moved ahead of its body).
    pub fn text_within(&self, original: &str, range: Range<usize>) -> String {
        let mut inside: Vec<&Edit> = self.edits.iter().filter(|e| e.range.start >= range.start && e.range.end <= range.end).collect();
        inside.sort_by_key(|e| (e.range.start, !e.range.is_empty()));
        let mut out = String::new();
        let mut at = range.start;
        for e in inside {
            if e.range.start < at {
                continue;
            }
            out.push_str(&original[at..e.range.start]);
            out.push_str(&e.text);
            at = e.range.end;
        }
        out.push_str(&original[at..range.end]);
        out
    }

    /// Moves `original[range]` out of its place: its text with the edits inside it applied
    /// (as [`text_within`](Self::text_within)), which the caller writes elsewhere; the
    /// range is deleted and the edits inside it go.
    pub fn take_out(&mut self, original: &str, range: Range<usize>) -> String {
        let text = self.text_within(original, range.clone());
        self.edits.retain(|e| !(e.range.start >= range.start && e.range.end <= range.end));
        self.delete(range);
        text
    }

    /// Apply to `original`. Overlapping edits are a bug in the caller: the later one (in
    /// offset order) is dropped rather than corrupting the output, and reported in the
    /// returned list so the caller can surface it.
    pub fn apply(mut self, original: &str) -> (String, OffsetMap, Vec<Edit>) {
        // Stable sort keeps insertion order for edits at the same start; insertions
        // (empty ranges) sort before replacements starting at the same offset.
        self.edits.sort_by_key(|e| (e.range.start, !e.range.is_empty()));
        let mut out = String::with_capacity(original.len() + 256);
        let mut segments = Vec::new();
        let mut dropped = Vec::new();
        let mut cursor = 0usize;
        for edit in self.edits {
            let Range { start, end } = edit.range;
            if start < cursor || end > original.len() || start > end || !original.is_char_boundary(start) || !original.is_char_boundary(end)
            {
                dropped.push(edit);
                continue;
            }
            if start > cursor {
                let new_start = out.len();
                out.push_str(&original[cursor..start]);
                segments.push(Segment { new: new_start..out.len(), old: cursor..start, copied: true });
            }
            let new_start = out.len();
            out.push_str(&edit.text);
            segments.push(Segment { new: new_start..out.len(), old: start..end, copied: false });
            cursor = end;
        }
        if cursor < original.len() {
            let new_start = out.len();
            out.push_str(&original[cursor..]);
            segments.push(Segment { new: new_start..out.len(), old: cursor..original.len(), copied: true });
        }
        (out, OffsetMap { segments, original_len: original.len() }, dropped)
    }
}

impl OffsetMap {
    /// The identity map for text that was not edited.
    pub fn identity(len: usize) -> Self {
        OffsetMap { segments: vec![Segment { new: 0..len, old: 0..len, copied: true }], original_len: len }
    }

    /// Original offset of a byte offset in the rewritten text. Offsets inside generated
    /// text map to the start of the original range that text replaced.
    pub fn to_original(&self, offset: usize) -> usize {
        let idx = self.segments.partition_point(|s| s.new.end <= offset);
        match self.segments.get(idx) {
            Some(s) if s.new.start <= offset => {
                if s.copied {
                    s.old.start + (offset - s.new.start)
                } else {
                    s.old.start
                }
            }
            _ => self.original_len,
        }
    }

    /// Original range of a range in the rewritten text. A range that lies inside generated
    /// text maps to the whole original range that text replaced (or the insertion point).
    pub fn range_to_original(&self, range: Range<usize>) -> Range<usize> {
        let idx = self.segments.partition_point(|s| s.new.end <= range.start);
        if let Some(s) = self.segments.get(idx) {
            if !s.copied && s.new.start <= range.start && range.end <= s.new.end.max(s.new.start + 1) {
                return s.old.clone();
            }
        }
        let start = self.to_original(range.start);
        let end = if range.end > range.start { self.to_original(range.end - 1) + 1 } else { start };
        start..end.max(start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replacements_and_insertions_map_back() {
        let src = "#version 330 core\nuniform float a;\nvoid main() { a; }\n";
        let mut e = Edits::new();
        e.replace(9..12, "450");
        let decl = src.find("uniform").unwrap();
        e.delete(decl..decl + "uniform float a;".len());
        let main = src.find("void").unwrap();
        e.insert(main, "layout(binding=0) uniform U { float a; };\n");
        let (out, map, dropped) = e.apply(src);
        assert!(dropped.is_empty());
        assert!(out.starts_with("#version 450 core\n\nlayout(binding=0)"));
        let a_new = out.rfind("a;").unwrap();
        let a_old = src.rfind("a;").unwrap();
        assert_eq!(map.to_original(a_new), a_old);
        // Inside generated text: maps to the insertion point.
        let gen = out.find("uniform U").unwrap();
        assert_eq!(map.to_original(gen), main);
        assert_eq!(map.range_to_original(gen..gen + 3), main..main);
        assert_eq!(map.range_to_original(a_new..a_new + 1), a_old..a_old + 1);
    }

    #[test]
    fn overlapping_edit_is_dropped_not_applied() {
        let mut e = Edits::new();
        e.replace(0..4, "x");
        e.replace(2..6, "y");
        let (out, _, dropped) = e.apply("abcdefgh");
        assert_eq!(out, "xgh".replace("gh", "efgh"));
        assert_eq!(dropped.len(), 1);
    }

    #[test]
    fn insertions_at_same_point_keep_order() {
        let mut e = Edits::new();
        e.insert(1, "1");
        e.insert(1, "2");
        e.replace(1..2, "B");
        assert_eq!(e.apply("abc").0, "a12Bc");
    }
}
