//! Metrics against independent brute force, closed forms and numerical
//! integration, and against hostile input. One module per metric family;
//! `common` holds the shared helpers.

mod bad_input;
mod closed_forms;
mod common;
mod distance;
mod exact;
mod l2;
mod spectrum;
mod star;
mod stratification;
mod wraparound;
