//! Wheel–rail contact geometry (methods.md §7): placement of a wheelset in the track, rigid gap,
//! contact regions and patches with their reference points and contact angles, per-patch samples
//! for the normal solvers (projection or isosceles-pairs correspondence), and creepages.
//!
//! Typical call sequence (no allocation; capacities are const generics):
//! ```
//! # use wrc_kernel::geometry::*;
//! # use wrc_kernel::profile::ProfileTable;
//! # fn demo(rail: &ProfileTable<f64, 2048>, wheel: &ProfileTable<f64, 2048>) -> Result<(), wrc_kernel::Error> {
//! let setup = TrackSetup::<f64>::standard();
//! let pose = WheelsetPose { dy: -2.0, yaw: -4.8e-3, roll: -1.128e-4 };
//! // gap grid: capacity 2048 rows, 0.05 mm step
//! let geom = WheelRail::<f64, 2048, 2048>::place(rail, wheel, &setup, &pose, Side::Right, 0.05)?;
//! // up to 4 patches of 64 samples at a vertical approach of 0.02 mm
//! let mut patches = Patches::<f64, 4, 64>::new();
//! contact_patches(&geom, 0.02, &PatchOptions::default(), &mut patches)?;
//! for p in patches.as_slice() {
//!     let c = creepages(&geom, &p.frame, &Kinematics::nominal(2000.0, 460.0))?;
//!     let _ = (p.frame.y_ref_rail, p.frame.angle, c.xi);
//! }
//! # Ok(()) }
//! ```
//!
//! `nalgebra` is not used: its generic vector and rotation types require `T: RealField` (simba),
//! which the kernel's [`crate::Real`] does not imply, and its maths would bypass
//! [`crate::math`] (the single door to libm / micromath). The few 2-D/3-D operations needed here
//! (a rotation, a cross and a dot product) are written out.

pub mod creep;
pub mod isosceles;
pub mod patch;
pub mod placement;
pub mod profile;
pub mod table;

pub use creep::{
    creepages, creepages_at, creepages_seed_a, creepages_trig, Creepages, Kinematics,
    Normalisation, PoseTrig,
};
pub use isosceles::{isosceles_rigid_pair, IsoscelesPair};
pub use patch::{
    contact_patches, patches_at_normal_approach, sample_patch, Correspondence, Patch, PatchFrame,
    PatchOptions, PatchSamples, Patches, ReferenceRule, LOAD_BEYOND_PROFILES,
};
pub use placement::{
    equilibrium_roll, Equilibrium, PlacedRail, PlacedWheel, RailPoint, Side, TrackSetup,
    WheelPoint, WheelRail, WheelsetPose, FLANGE_TIP_BAND,
};
