//! Tests of the link checks.
