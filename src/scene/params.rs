//! A scene query's parameters and errors.

use core::fmt;

use crate::ca::{CaError, CaParams, MeshParams};
use crate::{Float, InputError};

/// What went wrong building or querying a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SceneQueryError {
    /// A body's shape, motion or pose was rejected.
    Input(InputError),
    /// The query's parameters were rejected.
    Ca(CaError),
    /// A body's motion is over another interval than the scene's frame.
    IntervalMismatch {
        /// The body.
        body: usize,
    },
    /// No body of that number.
    UnknownBody(usize),
}

impl fmt::Display for SceneQueryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Input(e) => write!(f, "invalid input: {e}"),
            Self::Ca(e) => write!(f, "{e}"),
            Self::IntervalMismatch { body } => {
                write!(
                    f,
                    "body {body} moves over another interval than the scene's frame"
                )
            }
            Self::UnknownBody(b) => write!(f, "no body {b}"),
        }
    }
}

impl core::error::Error for SceneQueryError {}

impl From<InputError> for SceneQueryError {
    fn from(e: InputError) -> Self {
        Self::Input(e)
    }
}

impl From<CaError> for SceneQueryError {
    fn from(e: CaError) -> Self {
        Self::Ca(e)
    }
}

/// The parameters of a scene query: those of every pair's
/// conservative-advancement query, and the mesh traversal's knobs.
///
/// ```
/// use motion_bound::ca::CaParams;
/// use motion_bound::scene::SceneParams;
/// let p = SceneParams::<f64>::default().with_ca(CaParams::default().with_contact_distance(1e-3));
/// assert_eq!(p.ca.contact_distance, 1e-3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SceneParams<T> {
    /// Every pair's query parameters; the contact distance also widens the
    /// broad phase (boxes closer than it are kept).
    pub ca: CaParams<T>,
    /// The mesh traversal's knobs.
    pub mesh: MeshParams<T>,
}

impl<T: Float> Default for SceneParams<T> {
    fn default() -> Self {
        Self {
            ca: CaParams::default(),
            mesh: MeshParams::default(),
        }
    }
}

impl<T: Float> SceneParams<T> {
    /// With the pairs' query parameters `ca`.
    #[must_use]
    pub const fn with_ca(mut self, ca: CaParams<T>) -> Self {
        self.ca = ca;
        self
    }

    /// With the mesh traversal's knobs `mesh`.
    #[must_use]
    pub const fn with_mesh(mut self, mesh: MeshParams<T>) -> Self {
        self.mesh = mesh;
        self
    }

    /// Checks both parameter sets.
    ///
    /// # Errors
    /// [`CaError::InvalidParameter`] naming the first parameter out of range.
    pub fn validate(&self) -> Result<(), CaError> {
        self.ca.validate()?;
        self.mesh.validate()
    }
}
