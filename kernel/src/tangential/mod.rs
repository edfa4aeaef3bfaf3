//! Flexibilities and tangential contact: Kalker's coefficients, the strip × cell patch, the three
//! non-elliptic adaptations (Kik–Piotrowski, Linder, Ayasse–Chollet), FASTSIM and FaStrip.

pub mod adapt;
pub mod fastrip;
pub mod fastsim;
pub mod kalker;
pub mod patch;
