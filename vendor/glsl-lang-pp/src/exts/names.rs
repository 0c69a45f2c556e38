#![allow(dead_code)]

include!(concat!(env!("OUT_DIR"), "/ext_names.rs"));
