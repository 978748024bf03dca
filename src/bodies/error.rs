//! Why a scene generator refused its parameters.

use core::fmt;

use crate::MeshError;

/// Why a generator in [`scenes`](crate::bodies) refused its parameters.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SceneError {
    /// A count outside its documented range (segments and sides at least 3,
    /// their product at most `2^22`; `p`, `q` at least 1; icosphere
    /// subdivisions at most 7; board cells 1 to 1,024).
    Count {
        /// Which parameter.
        name: &'static str,
        /// Its value.
        value: u32,
    },
    /// A length that is not positive and finite, or that breaks a documented
    /// relation between lengths (a torus's minor radius below its major one).
    Length {
        /// Which parameter.
        name: &'static str,
    },
    /// `p` and `q` of a torus knot share a factor: the curve would close
    /// after `1 / gcd` of its length, a torus link of several components.
    NotCoprime {
        /// Turns about the axis.
        p: u32,
        /// Turns around the torus core.
        q: u32,
    },
    /// The generated mesh is not valid for `T` (a length beyond
    /// [`Float::MAX_INPUT`](crate::Float::MAX_INPUT)).
    Mesh(MeshError),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Count { name, value } => write!(f, "{name} = {value} is out of range"),
            Self::Length { name } => write!(f, "{name} is not a valid length"),
            Self::NotCoprime { p, q } => {
                write!(
                    f,
                    "p = {p} and q = {q} are not coprime (a torus link, not a knot)"
                )
            }
            Self::Mesh(e) => write!(f, "generated mesh is invalid: {e}"),
        }
    }
}

impl core::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            Self::Mesh(e) => Some(e),
            _ => None,
        }
    }
}

impl From<MeshError> for SceneError {
    fn from(e: MeshError) -> Self {
        Self::Mesh(e)
    }
}
