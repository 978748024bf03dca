//! [`CastError`]: why a query could not be answered by the certified cast.

use std::fmt;

use motion_bound::ca::CaError;
use motion_bound::InputError;

/// Why a query could not be answered by the certified cast.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum CastError {
    /// A shape kind this adapter does not take (named as parry names it:
    /// `"HeightField"`, `"Polyline"`, `"Voxels"`, `"Custom"`, a compound
    /// within a compound, a half-space within a compound), or a pair it
    /// cannot step (two half-spaces, a turning half-space).
    Unsupported(&'static str),
    /// A shape or a motion with an invalid quantity (NaN, infinite, beyond
    /// `motion-bound`'s input range, a negative radius, an empty mesh).
    Input(InputError),
    /// The conservative advancement refused the pair or its parameters.
    Ca(CaError),
    /// A NaN or infinite `start_time` or `end_time`.
    Interval,
}

impl fmt::Display for CastError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unsupported(what) => write!(f, "unsupported by the certified cast: {what}"),
            Self::Input(e) => write!(f, "invalid shape or motion: {e}"),
            Self::Ca(e) => write!(f, "conservative advancement: {e}"),
            Self::Interval => f.write_str("start_time and end_time must be finite"),
        }
    }
}

impl std::error::Error for CastError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Input(e) => Some(e),
            Self::Ca(e) => Some(e),
            _ => None,
        }
    }
}

impl From<InputError> for CastError {
    fn from(e: InputError) -> Self {
        Self::Input(e)
    }
}

impl From<CaError> for CastError {
    fn from(e: CaError) -> Self {
        match e {
            CaError::Unsupported => Self::Unsupported("two half-spaces"),
            CaError::TurnedHalfSpace => Self::Unsupported("a half-space that turns"),
            other => Self::Ca(other),
        }
    }
}
