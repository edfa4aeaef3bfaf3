//! # wrc-kernel — wheel–rail rolling contact in bounded time
//!
//! `#![no_std]`, no allocator, no `unsafe`. Every loop is bounded by a constant and every iterative
//! solve reports its iterations and whether it converged. The same code runs in `f64` (host,
//! Cortex-M7) and `f32` (Cortex-M4F) through the [`Real`] trait; all maths goes through [`math`].
//!
//! Units (methods.md §0.1): lengths mm, areas mm², forces N, stresses MPa, angles rad, velocities
//! mm/s; creepages ξ, η dimensionless, spin φ in rad/mm. Tractions act on body 1 (the wheel).
//!
//! Capacities are const generics. Where a count varies with the state — the patches of a wheel
//! ([`wheel::WheelResult::patches`]), the regions of a patch ([`pipeline::PatchResult::regions`]) —
//! results hold a `heapless::Vec` of that capacity; the real-time step's slots stay a fixed array
//! ([`step::StepResult::slots`]): slot k is the contact table's slot k, evaluated in every state
//! whether it carries a patch or not (its load is then 0); the geometry's
//! [`geometry::Patches`] are filled in place in the caller's workspace (see there). `nalgebra` is
//! not used (see [`geometry`]).
#![no_std]
#![cfg_attr(feature = "hw-sqrt", feature(core_float_math))]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The modules follow the data flow of one wheel's contact:
// geometry (profiles, placement, patches, creepages, contact tables) → normal contact (Hertz,
// STRIPES) → flexibilities and tangential contact (Kalker, adaptations, FASTSIM, FaStrip) → wear →
// the per-wheel solve (converged) and the real-time step (fixed cost, `wheel::step`).
pub mod geometry;
pub mod normal;
pub mod tangential;
pub mod wear;
pub mod wheel;

mod lanes;

pub mod error;
pub mod material;
pub mod math;
pub mod real;

// Short paths (`wrc_kernel::stripes`, `wrc_kernel::step`, …) for the modules of the folders above.
pub use geometry::{profile, table};
pub use normal::{compliance, hertz, hertz_table, ritz, stripes};
pub use tangential::{adapt, fastrip, fastsim, kalker, patch};
pub use wheel::{pipeline, step};

pub use error::Error;
pub use material::Material;
pub use real::Real;
