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
    /// A parry `TriMesh` flagged `TriMeshFlags::ORIENTED`, which parry takes
    /// as the solid it bounds, that `motion-bound` cannot take as solid
    /// (`TriMesh::try_solid`): not closed (`closed` false: a hole, a crack,
    /// a flipped or doubled triangle), or closed but wound inward or
    /// enclosing nothing (`closed` true). A mesh without the flag is a
    /// surface (hollow), whatever its shape.
    NotSolid {
        /// Whether the mesh is closed (then it is wound inward).
        closed: bool,
    },
}

impl fmt::Display for CastError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unsupported(what) => write!(f, "unsupported by the certified cast: {what}"),
            Self::Input(e) => write!(f, "invalid shape or motion: {e}"),
            Self::Ca(e) => write!(f, "conservative advancement: {e}"),
            Self::Interval => f.write_str("start_time and end_time must be finite"),
            Self::NotSolid { closed: false } => f.write_str(
                "a TriMesh flagged ORIENTED is solid, but this one is not closed (a hole or a crack)",
            ),
            Self::NotSolid { closed: true } => f.write_str(
                "a TriMesh flagged ORIENTED is solid, but this one is wound inward (negative volume)",
            ),
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
