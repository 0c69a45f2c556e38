mod line_map;
pub use line_map::*;

mod text_token;
pub use text_token::*;

mod unescaped;
pub use unescaped::*;
