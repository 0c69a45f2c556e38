#[macro_use]
pub mod keywords;
#[macro_use]
pub mod type_names;

pub mod token;
pub use token::{Token, TypeName};

pub mod path;
