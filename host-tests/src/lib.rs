//! # wrc-host-tests — validation of the wrc kernel on the host
//!
//! std-only: readers for the shared data (coefficient tables, CONTACT reference outputs, profiles),
//! the reference solvers (NORM, TANG) and case sets. The validation suites live in `tests/`.

pub mod cases;
pub mod data;
pub mod fftconv;
pub mod influence;
pub mod norm;
pub mod profiles;
pub mod realtime;
pub mod table;
pub mod tang;
pub mod tangstudy;
pub mod wear_ref;
pub mod wheelrail;
