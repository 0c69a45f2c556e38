//! Order of evaluation as GLSL defines it, in forms naga's GLSL front evaluates that way:
//! a short-circuit operator whose right operand has side effects becomes `?:` (naga
//! evaluates both operands of `&&`/`||`, and only the chosen arm of `?:`), and a `do …
//! while` whose body continues becomes a `for` loop (naga's `continue` in a `do` loop
//! skips the condition; a `for` loop's continuing step runs before its condition).

use super::Ctx;

impl Ctx<'_> {
    /// `a && f()` → `((a) ? (f()) : false)`; `a || f()` → `((a) ? true : (f()))`.
    /// Operators are listed outer before inner: an inner one in the outer's right operand
    /// may end where it ends, and must close first.
    pub(super) fn lazy_logic(&mut self) {
        for l in &self.s.lazy_logic {
            self.edits.insert(l.left.start, "((");
            self.edits.replace(l.op.clone(), if l.and { ") ? (" } else { ") ? true : (" });
        }
        for l in self.s.lazy_logic.iter().rev() {
            self.edits.insert(l.right.end, if l.and { ") : false)" } else { "))" });
        }
    }

    /// `do body while (c);` → `{ for (bool first = true; first ? true : bool(c); first =
    /// false) body if (false) bool(c); }`: the condition is written again ahead of the
    /// body (with the edits made inside it, so this runs after every other edit); the
    /// original stays where it was, never evaluated, so edits inside it still apply.
    pub(super) fn do_while_continue(&mut self) {
        for d in &self.s.do_while_continue {
            let text = &self.s.text;
            let Some(at) = text[d.tail.start..d.cond.start].find("while") else { continue };
            let cond = self.edits.text_within(text, d.cond.clone());
            let first = format!("effectc_first{}", d.keyword.start);
            self.edits.replace(d.keyword.clone(), format!("{{ for (bool {first} = true; {first} ? true : bool({cond}); {first} = false) "));
            let keyword = d.tail.start + at;
            self.edits.replace(keyword..keyword + "while".len(), "if (false) bool");
            self.edits.insert(d.tail.end, " }");
        }
    }
}
