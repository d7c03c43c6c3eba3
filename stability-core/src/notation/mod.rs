//! Derivative notations of other authors (the report's appendix).

pub mod avl;
