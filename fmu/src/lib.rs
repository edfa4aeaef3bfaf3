//! wrc as an FMI 2.0 co-simulation FMU: the kernel's real-time step ([`wrc_kernel::step`]) of
//! one wheel on a contact table, behind the FMI 2.0 C API.
//!
//! - [`model`]: the variables (the single source of `modelDescription.xml` and of the value
//!   references), an instance's state and its evaluation; safe Rust.
//! - [`xml`]: `modelDescription.xml` and the GUID generated from [`model::variables`].
//! - [`fmi`]: the `extern "C"` entry points (`fmi2Instantiate`, `fmi2DoStep`, …), the only
//!   `unsafe` code.
//! - [`pack`]: the packaged table (S1002/UIC60 as `wrc table`) and the `.fmu` archive, used by
//!   the `wrc-fmu-pack` binary.
//!
//! Variables, units, signs and the status codes: `docs/fmu.md`.

#![warn(missing_docs)]

pub mod fmi;
pub mod model;
pub mod pack;
pub mod xml;
