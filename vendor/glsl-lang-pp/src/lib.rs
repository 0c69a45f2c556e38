pub mod lexer;
mod util;
#[macro_use]
pub mod types;

#[cfg(feature = "exts")]
#[macro_use]
pub mod exts;

#[cfg(feature = "full")]
pub mod last;
#[cfg(feature = "full")]
mod parser;
#[cfg(feature = "full")]
pub mod processor;
