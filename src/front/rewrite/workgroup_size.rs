//! `layout(local_size_x_id = N) in;` (Vulkan GLSL: the workgroup size is specialization
//! constant N), which naga's GLSL front does not take: the size is written as the value it has
//! unspecialized, the default of `layout(constant_id = N) const … = V;`, or 1 where no such
//! constant is declared (GL_KHR_vulkan_glsl); a size also given as `local_size_x` stays.

use super::Ctx;
use crate::front::syntax::{layout_number, Storage};

impl Ctx<'_> {
    pub(super) fn spec_constant_workgroup_size(&mut self) {
        let s = self.s;
        for d in s.defaults.iter().filter(|d| d.storage == Some(Storage::In)) {
            if !d.layout.iter().any(|(k, _)| k.starts_with("local_size_") && k.ends_with("_id")) {
                continue;
            }
            let mut sizes = Vec::new();
            for axis in ["x", "y", "z"] {
                let size = match (
                    layout_number(&d.layout, &format!("local_size_{axis}")),
                    layout_number(&d.layout, &format!("local_size_{axis}_id")),
                ) {
                    (Some(n), _) => Some(n),
                    (None, Some(id)) => self.spec_constant_default(id),
                    (None, None) => None,
                };
                match size {
                    Some(n) => sizes.push(format!("local_size_{axis} = {n}")),
                    // A default naga cannot be told: the declaration stays (naga refuses it).
                    None if layout_number(&d.layout, &format!("local_size_{axis}_id")).is_some() => return,
                    None => {}
                }
            }
            self.edits.replace(d.span.clone(), format!("layout({}) in;", sizes.join(", ")));
        }
    }

    /// The integer default of specialization constant `id`: its literal initializer, or 1 when
    /// no constant has that id. `None` for an initializer that is no integer literal.
    fn spec_constant_default(&self, id: u32) -> Option<u32> {
        let s = self.s;
        let Some(g) = s.globals.iter().find(|g| layout_number(&g.layout, "constant_id") == Some(id)) else { return Some(1) };
        let init = s.text.get(g.initializer.clone()?)?.trim();
        init.trim_end_matches(['u', 'U']).parse().ok()
    }
}
