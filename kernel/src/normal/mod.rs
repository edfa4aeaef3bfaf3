//! Normal contact: Hertz's closed forms and tables for elliptic patches, and STRIPES, the
//! semi-Hertzian strip method for the non-elliptic patches of real profiles.

pub mod compliance;
pub mod hertz;
pub mod hertz_table;
pub mod ritz;
pub mod stripes;
