//! Rigid motions over a time interval, and what their bounds need of them
//! precomputed (the swept arc).

pub(crate) mod arc;
pub(crate) mod interval;
pub(crate) mod rigid;
