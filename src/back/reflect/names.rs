//! The names naga's WGSL writer gives a module's globals, struct members and entry-point
//! arguments. They differ from the module's own where WGSL needs it: a name ending in a
//! digit gets a `_` (`light0` → `light0_`, effectc's `effectc_pad0` → `effectc_pad0_`), as
//! do keywords, and repeats get a number. The reflection gives both, so a program reading it
//! finds each thing in the WGSL by the name the WGSL declares.

use naga::proc::{NameKey, Namer};
use naga::{FastHashMap, Handle, Module, Type};

pub(super) struct WgslNames(FastHashMap<NameKey, String>);

impl WgslNames {
    /// The names of `module` exactly as `naga::back::wgsl` assigns them.
    pub(super) fn of(module: &Module) -> WgslNames {
        let mut names = FastHashMap::default();
        Namer::default().reset(
            module,
            &naga::keywords::wgsl::RESERVED_SET,
            &naga::keywords::wgsl::BUILTIN_IDENTIFIER_SET,
            naga::proc::CaseInsensitiveKeywordSet::empty(),
            // The WGSL writer's reserved prefixes.
            &["__", "_naga"],
            &mut names,
        );
        WgslNames(names)
    }

    pub(super) fn global(&self, global: Handle<naga::GlobalVariable>) -> Option<String> {
        self.0.get(&NameKey::GlobalVariable(global)).cloned()
    }

    pub(super) fn member(&self, ty: Handle<Type>, index: usize) -> Option<String> {
        self.0.get(&NameKey::StructMember(ty, index as u32)).cloned()
    }

    pub(super) fn argument(&self, entry_point: usize, index: usize) -> Option<String> {
        self.0.get(&NameKey::EntryPointArgument(entry_point as u16, index as u32)).cloned()
    }
}
