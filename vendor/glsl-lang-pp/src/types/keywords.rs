#![allow(dead_code)]

include!(concat!(env!("OUT_DIR"), "/keywords.rs"));
