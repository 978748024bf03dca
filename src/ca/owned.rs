//! The owning twin of [`Shape`]: what a binding or an engine adapter keeps
//! per body (a hull's points, a mesh with its tree built once, a compound's
//! parts), lent to a query as a [`Shape`] by [`OwnedShape::prepare`].
//!
//! The constructors check every argument and name it in their error
//! ([`ArgError`]), so that the Python module and the C library say
//! `half_extents[1] is negative (got -2)` in the same words.

use alloc::format;
use alloc::vec::Vec;

use super::arg_error::{ArgError, Problem};
use super::shape::{Compound, Part, Shape};
use crate::bvh::BallTree;
use crate::error::InputError;
use crate::mesh::TriMesh;
use crate::{Convex, Float, HalfSpace, Isometry, Point3, Vec3, VertexSet};

/// A primitive convex shape by its dimensions, as a user gives them (the
/// arguments of [`Convex`]'s constructors).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Primitive<T> {
    /// A ball of this radius.
    Ball(T),
    /// A capsule: half height, radius.
    Capsule(T, T),
    /// A cuboid of these half extents.
    Cuboid([T; 3]),
    /// A cylinder: half height (above 0), radius.
    Cylinder(T, T),
    /// A cone: half height (above 0), radius.
    Cone(T, T),
}

impl<T: Float> Primitive<T> {
    /// The convex shape, rounded by `rounding`, every argument checked and
    /// named (`radius`, `half_height`, `half_extents[k]`, `rounding`).
    fn try_convex(self, rounding: T) -> Result<Convex<'static, T>, ArgError> {
        let len = ArgError::length;
        let (c, names) = match self {
            Self::Ball(r) => (Convex::try_ball(len(r, "radius")?), "radius"),
            Self::Capsule(h, r) => (
                Convex::try_capsule(len(h, "half_height")?, len(r, "radius")?),
                "half_height, radius",
            ),
            Self::Cuboid(h) => {
                for (k, x) in h.iter().enumerate() {
                    len(*x, &format!("half_extents[{k}]"))?;
                }
                (Convex::try_cuboid(h), "half_extents")
            }
            Self::Cylinder(h, r) => (
                Convex::try_cylinder(ArgError::positive(h, "half_height")?, len(r, "radius")?),
                "half_height, radius",
            ),
            Self::Cone(h, r) => (
                Convex::try_cone(ArgError::positive(h, "half_height")?, len(r, "radius")?),
                "half_height, radius",
            ),
        };
        let c = c.map_err(ArgError::input(names))?;
        if len(rounding, "rounding")? == T::ZERO {
            Ok(c)
        } else {
            c.try_rounded(rounding).map_err(ArgError::input("rounding"))
        }
    }
}

/// A convex hull's points and rounding, checked.
#[derive(Clone, Debug)]
pub struct Hull<T> {
    points: Vec<[T; 3]>,
    rounding: T,
}

impl<T: Float> Hull<T> {
    /// The hull of `points` rounded by `rounding` (for an adapter with its
    /// own errors; [`OwnedShape::try_hull`] names the bad argument).
    ///
    /// # Errors
    /// No point, a bad point, a negative, NaN or infinite rounding.
    pub fn try_new(points: Vec<[T; 3]>, rounding: T) -> Result<Self, InputError> {
        let hull = Self { points, rounding };
        hull.convex(None)?;
        Ok(hull)
    }

    /// The points.
    #[must_use]
    pub fn points(&self) -> &[[T; 3]] {
        &self.points
    }

    /// The rounding radius.
    #[must_use]
    pub const fn rounding(&self) -> T {
        self.rounding
    }

    /// The hull as a [`Convex`], placed at `at` when given.
    ///
    /// # Errors
    /// None for a hull made by [`OwnedShape::try_hull`] (checked then).
    pub fn convex(&self, at: Option<Isometry<T>>) -> Result<Convex<'_, T>, InputError> {
        let mut c = Convex::polytope(VertexSet::try_new(&self.points)?);
        if self.rounding != T::ZERO {
            c = c.try_rounded(self.rounding)?;
        }
        match at {
            Some(pose) => c.try_placed(pose),
            None => Ok(c),
        }
    }
}

/// A triangle mesh and its [`BallTree`], built once.
#[derive(Clone, Debug)]
pub struct OwnedMesh<T> {
    mesh: TriMesh<T>,
    tree: BallTree<T>,
}

impl<T: Float> OwnedMesh<T> {
    /// The mesh (solid or hollow: [`TriMesh::is_solid`]).
    #[must_use]
    pub const fn mesh(&self) -> &TriMesh<T> {
        &self.mesh
    }

    /// Its tree.
    #[must_use]
    pub const fn tree(&self) -> &BallTree<T> {
        &self.tree
    }

    /// The mesh as it is (solid or hollow) with its tree (for an adapter
    /// with its own errors; [`OwnedShape::try_mesh`] names the bad
    /// argument).
    ///
    /// # Errors
    /// As [`BallTree::try_from_mesh`].
    pub fn try_from_mesh(mesh: TriMesh<T>) -> Result<Self, InputError> {
        let tree = BallTree::try_from_mesh(&mesh)?;
        Ok(Self { mesh, tree })
    }

    fn try_new(
        vertices: Vec<[T; 3]>,
        triangles: Vec<[u32; 3]>,
        solid: Option<bool>,
        names: [&str; 3],
    ) -> Result<Self, ArgError> {
        use crate::mesh::MeshError;
        let mesh = TriMesh::try_new(vertices, triangles).map_err(|e| {
            let arg = match e {
                MeshError::Vertex(_) | MeshError::NoVertices => names[0],
                _ => names[1],
            };
            ArgError::new(arg, Problem::Mesh(e))
        })?;
        let solid = solid.unwrap_or_else(|| mesh.is_closed() && mesh.signed_volume() > 0.0);
        let mesh = if solid {
            mesh.try_solid().map_err(ArgError::mesh(names[2]))?
        } else {
            mesh
        };
        let tree = BallTree::try_from_mesh(&mesh)
            .map_err(ArgError::input(&format!("{}, {}", names[0], names[1])))?;
        Ok(Self { mesh, tree })
    }

    /// The same mesh with its vertices moved by `at` (solid as it was), its
    /// tree rebuilt.
    fn placed(&self, at: &Isometry<T>, arg: &str) -> Result<Self, ArgError> {
        let v = self.mesh.vertices().iter();
        let v = v.map(|p| at.transform_point(Point3::from_array(*p)).to_array());
        let names = [arg; 3];
        Self::try_new(
            v.collect(),
            self.mesh.triangles().to_vec(),
            Some(self.mesh.is_solid()),
            names,
        )
    }
}

/// One part of an [`OwnedCompound`], in the compound's frame.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum OwnedPart<T: 'static> {
    /// A convex shape, placed.
    Convex(Convex<'static, T>),
    /// A hull and its place.
    Hull(Hull<T>, Isometry<T>),
    /// A mesh, its vertices in the compound's frame.
    Mesh(OwnedMesh<T>),
}

/// The parts of a compound, owned and checked (at least one; its reach in
/// range).
#[derive(Clone, Debug)]
pub struct OwnedCompound<T: 'static> {
    parts: Vec<OwnedPart<T>>,
}

impl<T: Float + 'static> OwnedCompound<T> {
    /// The parts.
    #[must_use]
    pub fn parts(&self) -> &[OwnedPart<T>] {
        &self.parts
    }

    fn compound(&self) -> Result<Compound<'_, T>, InputError> {
        let parts = self.parts.iter().map(|p| {
            Ok(match p {
                OwnedPart::Convex(c) => Part::Convex(*c),
                OwnedPart::Hull(h, at) => Part::Convex(h.convex(Some(*at))?),
                OwnedPart::Mesh(m) => Part::Mesh(&m.tree),
            })
        });
        Compound::try_new(parts.collect::<Result<Vec<_>, InputError>>()?)
    }
}

/// A body's shape in its own frame, owning everything (the owning twin of
/// [`Shape`]); lend it to a query with [`prepare`](Self::prepare). Every
/// constructor checks its arguments and names the bad one in its
/// [`ArgError`].
///
/// ```
/// use motion_bound::ca::{AnyPair, OwnedShape, Primitive};
/// use motion_bound::Isometry;
/// let ball = OwnedShape::try_primitive(Primitive::Ball(0.5), 0.0)?;
/// let tet = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let faces = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let mesh = OwnedShape::try_mesh(tet, faces, None, ["vertices", "faces", "solid"])?;
/// let at = Isometry::try_from_translation([3.0, 0.0, 0.0].into())?;
/// let both = OwnedShape::try_compound([(&ball, at), (&mesh, Isometry::IDENTITY)])?;
/// // Lend them to a query.
/// let (a, b) = (ball.prepare()?, both.prepare()?);
/// let _pair = AnyPair::try_new(a.shape(), b.shape())?;
/// // A bad argument is named, with its index.
/// let e = OwnedShape::try_compound([(&ball, at), (&OwnedShape::try_half_space([0.0, 0.0, 1.0])?, at)]);
/// assert!(e.unwrap_err().to_string().starts_with("parts[1] is a half_space"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum OwnedShape<T: 'static> {
    /// A convex primitive (rounded or not).
    Convex(Convex<'static, T>),
    /// A convex hull of points (rounded or not).
    Hull(Hull<T>),
    /// A triangle mesh with its tree.
    Mesh(OwnedMesh<T>),
    /// A half-space.
    HalfSpace(HalfSpace<T>),
    /// Several parts moving as one.
    Compound(OwnedCompound<T>),
}

/// An [`OwnedShape`] lent for a query: a [`Shape`], or a compound assembled
/// for it (which [`shape`](Self::shape) borrows).
#[derive(Debug)]
pub enum PreparedShape<'a, T> {
    /// A shape borrowing the owner.
    Shape(Shape<'a, T>),
    /// A compound's parts, borrowing the owner.
    Compound(Compound<'a, T>),
}

impl<T: Float> PreparedShape<'_, T> {
    /// The shape, for [`AnyPair::try_new`](super::AnyPair::try_new) or a
    /// scene.
    #[must_use]
    pub fn shape(&self) -> Shape<'_, T> {
        match self {
            Self::Shape(s) => *s,
            Self::Compound(c) => Shape::Compound(c),
        }
    }
}

impl<T: Float + 'static> OwnedShape<T> {
    /// The primitive `p` rounded by `rounding`.
    ///
    /// # Errors
    /// A negative, NaN or infinite length, a half height of a cylinder or
    /// cone that is not above 0, a magnitude beyond the range: named
    /// (`radius`, `half_height`, `half_extents[k]`, `rounding`).
    pub fn try_primitive(p: Primitive<T>, rounding: T) -> Result<Self, ArgError> {
        Ok(Self::Convex(p.try_convex(rounding)?))
    }

    /// The convex hull of `points` rounded by `rounding`.
    ///
    /// # Errors
    /// A bad `rounding`, no point or a bad one (`points`).
    pub fn try_hull(points: Vec<[T; 3]>, rounding: T) -> Result<Self, ArgError> {
        ArgError::length(rounding, "rounding")?;
        VertexSet::try_new(&points).map_err(ArgError::input("points"))?;
        let hull = Hull::try_new(points, rounding).map_err(ArgError::input("rounding"))?;
        Ok(Self::Hull(hull))
    }

    /// The triangle mesh of `vertices` and `triangles` with its tree, solid
    /// as `solid` asks: `Some(true)` solid (refused unless closed and wound
    /// outward), `Some(false)` hollow, `None` solid exactly when closed and
    /// wound outward. `names` are the binding's names of the three
    /// arguments, for the error.
    ///
    /// # Errors
    /// A bad vertex or no vertex (`names[0]`), an index out of range or no
    /// triangle (`names[1]`), a mesh that cannot be solid (`names[2]`).
    pub fn try_mesh(
        vertices: Vec<[T; 3]>,
        triangles: Vec<[u32; 3]>,
        solid: Option<bool>,
        names: [&str; 3],
    ) -> Result<Self, ArgError> {
        Ok(Self::Mesh(OwnedMesh::try_new(
            vertices, triangles, solid, names,
        )?))
    }

    /// The half-space `{x : normal . x <= 0}`.
    ///
    /// # Errors
    /// A zero, NaN or out-of-range `normal`.
    pub fn try_half_space(normal: [T; 3]) -> Result<Self, ArgError> {
        let h = HalfSpace::try_new(Vec3::from_array(normal)).map_err(ArgError::input("normal"))?;
        Ok(Self::HalfSpace(h))
    }

    /// The compound of `parts`, each a shape and its place in the
    /// compound's frame (copied: a mesh's tree is rebuilt at its place).
    ///
    /// # Errors
    /// No part (`parts`), a half-space or compound part or a part that
    /// cannot be placed (`parts[k]`).
    pub fn try_compound<'s>(
        parts: impl IntoIterator<Item = (&'s Self, Isometry<T>)>,
    ) -> Result<Self, ArgError>
    where
        T: 's,
    {
        let mut owned = Vec::new();
        for (k, (shape, at)) in parts.into_iter().enumerate() {
            let arg = format!("parts[{k}]");
            owned.push(match shape {
                Self::Convex(c) => {
                    OwnedPart::Convex(c.try_placed(at).map_err(ArgError::input(&arg))?)
                }
                Self::Hull(h) => {
                    h.convex(Some(at)).map_err(ArgError::input(&arg))?;
                    OwnedPart::Hull(h.clone(), at)
                }
                Self::Mesh(m) => OwnedPart::Mesh(m.placed(&at, &arg)?),
                Self::HalfSpace(_) => {
                    return Err(ArgError::new(arg, Problem::NotAPart("half_space")))
                }
                Self::Compound(_) => return Err(ArgError::new(arg, Problem::NotAPart("compound"))),
            });
        }
        Self::try_compound_of(owned).map_err(ArgError::input("parts"))
    }

    /// The compound of `parts`, each already in the compound's frame (for
    /// an adapter that places its parts itself).
    ///
    /// # Errors
    /// [`InputError::EmptyCompound`] for no part; a reach beyond the range.
    pub fn try_compound_of(parts: Vec<OwnedPart<T>>) -> Result<Self, InputError> {
        let c = OwnedCompound { parts };
        c.compound()?;
        Ok(Self::Compound(c))
    }

    /// This shape rounded by `radius` more (a convex primitive or hull).
    ///
    /// # Errors
    /// A negative, NaN or infinite `radius` (named `radius`); a mesh,
    /// half-space or compound ([`Problem::NotConvex`], named `shape`).
    pub fn try_rounded(&self, radius: T) -> Result<Self, ArgError> {
        ArgError::length(radius, "radius")?;
        match self {
            Self::Convex(c) => Ok(Self::Convex(
                c.try_rounded(radius).map_err(ArgError::input("radius"))?,
            )),
            Self::Hull(h) => Self::try_hull(h.points.clone(), h.rounding + radius)
                .map_err(|e| ArgError::new("radius", e.problem().clone())),
            _ => Err(ArgError::new("shape", Problem::NotConvex)),
        }
    }

    /// The shape lent for a query.
    ///
    /// # Errors
    /// None for a shape made by this type's constructors (checked then).
    pub fn prepare(&self) -> Result<PreparedShape<'_, T>, InputError> {
        Ok(match self {
            Self::Convex(c) => PreparedShape::Shape(Shape::Convex(*c)),
            Self::Hull(h) => PreparedShape::Shape(Shape::Convex(h.convex(None)?)),
            Self::Mesh(m) => PreparedShape::Shape(Shape::Mesh(&m.tree)),
            Self::HalfSpace(h) => PreparedShape::Shape(Shape::HalfSpace(*h)),
            Self::Compound(c) => PreparedShape::Compound(c.compound()?),
        })
    }
}
