//! # wrc-kernel — wheel–rail rolling contact in bounded time
//!
//! `#![no_std]`, no allocator, no `unsafe`. Every loop is bounded by a constant and every iterative
//! solve reports its iterations and whether it converged. The same code runs in `f64` (host,
//! Cortex-M7) and `f32` (Cortex-M4F) through the [`Real`] trait; all maths goes through [`math`].
//!
//! Units (methods.md §0.1): lengths mm, areas mm², forces N, stresses MPa, angles rad, velocities
//! mm/s; creepages ξ, η dimensionless, spin φ in rad/mm. Tractions act on body 1 (the wheel).
#![no_std]
#![cfg_attr(feature = "hw-sqrt", feature(core_float_math))]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod adapt;
pub mod error;
pub mod fastrip;
pub mod fastsim;
pub mod geometry;
pub mod hertz;
pub mod hertz_table;
pub mod kalker;
pub mod material;
pub mod math;
pub mod patch;
pub mod pipeline;
pub mod profile;
pub mod real;
pub mod step;
pub mod stripes;
pub mod table;
pub mod wear;
pub mod wheel;

pub use error::Error;
pub use material::Material;
pub use real::Real;
