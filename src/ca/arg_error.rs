//! An input refused, named by the argument it came in: `half_extents[1] is
//! negative (got -2)`. The bindings (Python, C) speak in their arguments'
//! names, so their messages are built here, once.

use alloc::string::String;
use core::fmt;

use crate::error::InputError;
use crate::mesh::MeshError;
use crate::Float;

/// What was wrong with an argument ([`ArgError`]).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Problem {
    /// A length (radius, half extent, rounding) that is NaN or infinite.
    NotFinite(f64),
    /// A length below zero.
    Negative(f64),
    /// A value that must be above zero and finite (a cylinder's half height,
    /// a duration) and is not.
    NotPositive(f64),
    /// The core's refusal ([`InputError`]).
    Input(InputError),
    /// A mesh's refusal ([`MeshError`]).
    Mesh(MeshError),
    /// A compound's part of a kind a compound cannot hold (a half-space, a
    /// compound), named.
    NotAPart(&'static str),
    /// A shape that is not convex where only a convex one will do
    /// (rounding a mesh, say).
    NotConvex,
}

/// An input refused, with the argument's name (and, in an array, its index:
/// `half_extents[1]`, `parts[3]`) first in its message.
///
/// ```
/// use motion_bound::ca::{ArgError, OwnedShape, Primitive};
/// let e = OwnedShape::try_primitive(Primitive::Cuboid([1.0, -2.0, 1.0]), 0.0).unwrap_err();
/// assert_eq!(e.to_string(), "half_extents[1] is negative (got -2)");
/// assert_eq!(e.arg(), "half_extents[1]");
/// assert_eq!(ArgError::length(f64::NAN, "radius").unwrap_err().to_string(),
///            "radius is not finite (got NaN)");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ArgError {
    arg: String,
    problem: Problem,
}

impl ArgError {
    /// The refusal `problem` of the argument `arg`.
    #[must_use]
    pub fn new(arg: impl Into<String>, problem: Problem) -> Self {
        Self {
            arg: arg.into(),
            problem,
        }
    }

    /// A function turning the core's refusal into one of the argument `arg`
    /// (for `map_err`).
    pub fn input(arg: &str) -> impl Fn(InputError) -> Self + '_ {
        move |e| Self::new(arg, Problem::Input(e))
    }

    /// A function turning a mesh's refusal into one of the argument `arg`.
    pub fn mesh(arg: &str) -> impl Fn(MeshError) -> Self + '_ {
        move |e| Self::new(arg, Problem::Mesh(e))
    }

    /// `x` if it is a length: finite and at least 0 (a radius, a half
    /// extent, a rounding).
    ///
    /// # Errors
    /// [`Problem::NotFinite`] or [`Problem::Negative`], naming `arg`.
    pub fn length<T: Float>(x: T, arg: &str) -> Result<T, Self> {
        if !x.is_finite() {
            Err(Self::new(arg, Problem::NotFinite(x.to_f64())))
        } else if x < T::ZERO {
            Err(Self::new(arg, Problem::Negative(x.to_f64())))
        } else {
            Ok(x)
        }
    }

    /// `x` if it is finite (a time, a coordinate).
    ///
    /// # Errors
    /// [`Problem::NotFinite`], naming `arg`.
    pub fn finite<T: Float>(x: T, arg: &str) -> Result<T, Self> {
        if x.is_finite() {
            Ok(x)
        } else {
            Err(Self::new(arg, Problem::NotFinite(x.to_f64())))
        }
    }

    /// `x` if it is finite and above 0 (a duration, a cylinder's half
    /// height).
    ///
    /// # Errors
    /// [`Problem::NotPositive`], naming `arg`.
    pub fn positive<T: Float>(x: T, arg: &str) -> Result<T, Self> {
        if x.is_finite() && x > T::ZERO {
            Ok(x)
        } else {
            Err(Self::new(arg, Problem::NotPositive(x.to_f64())))
        }
    }

    /// The argument's name, with its index in an array.
    #[must_use]
    pub fn arg(&self) -> &str {
        &self.arg
    }

    /// What was wrong.
    #[must_use]
    pub const fn problem(&self) -> &Problem {
        &self.problem
    }
}

impl fmt::Display for ArgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = &self.arg;
        match &self.problem {
            Problem::NotFinite(x) => write!(f, "{a} is not finite (got {x})"),
            Problem::Negative(x) => write!(f, "{a} is negative (got {x})"),
            Problem::NotPositive(x) => write!(f, "{a} must be positive and finite (got {x})"),
            Problem::Input(e) => write!(f, "{a}: {e}"),
            Problem::Mesh(e) => write!(f, "{a}: {e}"),
            Problem::NotAPart(kind) => write!(
                f,
                "{a} is a {kind}: a compound's parts are meshes and convex shapes (no \
                 half-space, no compound)"
            ),
            Problem::NotConvex => write!(
                f,
                "{a} is not convex: only convex shapes (primitives and hulls) can be rounded"
            ),
        }
    }
}

impl core::error::Error for ArgError {}
