//! Kinematic trees: links with collision meshes, joints with origins, axes
//! and limits, and forward kinematics.

use alloc::string::String;
use alloc::vec;
use alloc::vec::Vec;
use core::fmt;

use crate::geometry::gjk::ConvexPolytope;
use crate::geometry::hull_clusters::{cluster_vertices, HullCluster};
use crate::geometry::hull_vertices::hull_vertex_indices;
use crate::math::pose::mat_mul;
use crate::{BallTree, Float, Pose, TriMesh, Vec3};

/// What a joint lets its child link do relative to its parent (URDF's joint
/// types, but `floating` and `planar`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JointKind {
    /// A turn about the axis by the joint's coordinate (radians), within its
    /// limits.
    Revolute,
    /// A turn about the axis without limits.
    Continuous,
    /// A slide along the axis by the joint's coordinate.
    Prismatic,
    /// No motion: the child is rigidly attached (no coordinate).
    Fixed,
}

impl JointKind {
    /// Whether the joint has a coordinate (every kind but [`Fixed`](Self::Fixed)).
    #[inline]
    #[must_use]
    pub const fn is_movable(self) -> bool {
        !matches!(self, Self::Fixed)
    }

    /// Whether the joint turns ([`Revolute`](Self::Revolute) or
    /// [`Continuous`](Self::Continuous)).
    #[inline]
    #[must_use]
    pub const fn is_rotational(self) -> bool {
        matches!(self, Self::Revolute | Self::Continuous)
    }
}

/// A joint as given: which link it hangs from which, where its frame sits in
/// the parent link's frame, its axis (in its own frame) and limits.
///
/// The child link's frame is `origin * J(q)`, with `J(q)` the turn by `q`
/// about `axis` or the slide by `q` along it: URDF's convention.
#[derive(Clone, Debug, PartialEq)]
pub struct JointSpec<T> {
    /// The joint's name (unique in a chain).
    pub name: String,
    /// What the joint lets the child do.
    pub kind: JointKind,
    /// The parent link's index (from [`ChainBuilder::add_link`]).
    pub parent: usize,
    /// The child link's index.
    pub child: usize,
    /// The joint frame in the parent link's frame (URDF's `<origin>`).
    pub origin: Pose<T>,
    /// The axis in the joint frame; any nonzero length (normalised).
    pub axis: [T; 3],
    /// `[lower, upper]` for a revolute or prismatic joint; `None` for none.
    pub limits: Option<[T; 2]>,
}

/// What went wrong building, loading or querying a chain.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ChainError {
    /// A link or joint name is used twice.
    DuplicateName(String),
    /// A joint names a link index that does not exist.
    NoSuchLink(usize),
    /// A name that is not in the chain.
    UnknownName(String),
    /// A link hangs from two joints.
    TwoParents(String),
    /// Not exactly one link without a parent joint (a tree has one root), or
    /// a joint cycle.
    NotATree,
    /// A joint's axis is zero or not finite, or its origin not finite.
    BadJoint(String),
    /// A joint's limits are reversed or not finite.
    BadLimits(String),
    /// A joint-space vector of the wrong length.
    WrongDof {
        /// The chain's number of coordinates.
        expected: usize,
        /// The length given.
        got: usize,
    },
    /// A joint coordinate is NaN, infinite or beyond the input range.
    NonFiniteCoordinate(usize),
    /// A joint coordinate of a segment's end is outside its joint's limits
    /// (checked unless [`ChainParams::within_limits`](crate::chain::ChainParams::within_limits)
    /// is off).
    BeyondLimits(usize),
    /// A link's mesh could not be made into a ball tree.
    Mesh(String),
    /// A query parameter is out of range.
    InvalidParameter(&'static str),
    /// A URDF that could not be read or is not understood.
    Urdf(String),
    /// A shape obstacle's input was refused.
    Shape(crate::InputError),
}

impl fmt::Display for ChainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::DuplicateName(n) => write!(f, "the name {n:?} is used twice"),
            Self::NoSuchLink(i) => write!(f, "no link has the index {i}"),
            Self::UnknownName(n) => write!(f, "no link, joint or obstacle is named {n:?}"),
            Self::TwoParents(n) => write!(f, "link {n:?} hangs from two joints"),
            Self::NotATree => f.write_str("the links and joints do not form one tree"),
            Self::BadJoint(n) => {
                write!(
                    f,
                    "joint {n:?} has a zero or non-finite axis or a non-finite origin"
                )
            }
            Self::BadLimits(n) => write!(f, "joint {n:?} has reversed or non-finite limits"),
            Self::WrongDof { expected, got } => {
                write!(
                    f,
                    "a joint-space vector of length {got} for a chain of {expected} coordinates"
                )
            }
            Self::BeyondLimits(i) => {
                write!(f, "coordinate {i} is outside its joint's limits")
            }
            Self::NonFiniteCoordinate(i) => {
                write!(
                    f,
                    "joint coordinate {i} is NaN, infinite or beyond the input range"
                )
            }
            Self::Mesh(m) => write!(f, "a link's mesh: {m}"),
            Self::InvalidParameter(p) => write!(f, "invalid parameter: {p}"),
            Self::Urdf(m) => write!(f, "URDF: {m}"),
            Self::Shape(e) => write!(f, "a shape obstacle: {e}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for ChainError {}

/// Builds a [`Chain`] link by link and joint by joint.
///
/// ```
/// use motion_bound::chain::{ChainBuilder, JointKind, JointSpec};
/// use motion_bound::{Pose, TriMesh, Vec3};
/// let rod = TriMesh::try_new(
///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.1, 0.0], [0.0, 0.0, 0.1]],
///     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
/// )?;
/// let mut b = ChainBuilder::new();
/// let base = b.add_link("base", None)?;
/// let arm = b.add_link("arm", Some(rod))?;
/// b.add_joint(JointSpec {
///     name: "shoulder".into(),
///     kind: JointKind::Revolute,
///     parent: base,
///     child: arm,
///     origin: Pose::from_translation(Vec3::new(0.0, 0.0, 0.5)),
///     axis: [0.0, 0.0, 1.0],
///     limits: Some([-3.0, 3.0]),
/// })?;
/// let chain = b.build()?;
/// assert_eq!(chain.dof(), 1);
/// let poses = chain.try_forward_kinematics(&[core::f64::consts::FRAC_PI_2])?;
/// // The arm's frame turned a quarter about z, half a unit up.
/// let tip = poses[arm].transform_point(Vec3::new(1.0, 0.0, 0.0));
/// assert!((tip - Vec3::new(0.0, 1.0, 0.5)).length() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct ChainBuilder<T> {
    links: Vec<(String, Option<TriMesh<T>>)>,
    joints: Vec<JointSpec<T>>,
}

impl<T: Float> ChainBuilder<T> {
    /// An empty builder.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            links: Vec::new(),
            joints: Vec::new(),
        }
    }

    /// Adds a link with its collision mesh in the link's frame (`None`: a
    /// link without collision geometry) and returns its index.
    ///
    /// # Errors
    /// [`ChainError::DuplicateName`].
    pub fn add_link(
        &mut self,
        name: impl Into<String>,
        mesh: Option<TriMesh<T>>,
    ) -> Result<usize, ChainError> {
        let name = name.into();
        if self.links.iter().any(|(n, _)| *n == name) {
            return Err(ChainError::DuplicateName(name));
        }
        self.links.push((name, mesh));
        Ok(self.links.len() - 1)
    }

    /// Adds a joint and returns its index.
    ///
    /// # Errors
    /// [`ChainError::DuplicateName`], [`ChainError::NoSuchLink`],
    /// [`ChainError::BadJoint`], [`ChainError::BadLimits`].
    pub fn add_joint(&mut self, joint: JointSpec<T>) -> Result<usize, ChainError> {
        if self.joints.iter().any(|j| j.name == joint.name) {
            return Err(ChainError::DuplicateName(joint.name));
        }
        for link in [joint.parent, joint.child] {
            if link >= self.links.len() {
                return Err(ChainError::NoSuchLink(link));
            }
        }
        let axis = Vec3::from_array(joint.axis);
        let origin_ok = joint.origin.is_finite()
            && joint.origin.translation.max_abs() <= T::MAX_INPUT
            && joint.origin.rotation_max_abs() <= T::TWO;
        if joint.kind.is_movable() && (!axis.is_finite() || unit_axis(axis).is_none()) {
            return Err(ChainError::BadJoint(joint.name));
        }
        if !origin_ok || joint.parent == joint.child {
            return Err(ChainError::BadJoint(joint.name));
        }
        if let Some([lo, hi]) = joint.limits {
            if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
                return Err(ChainError::BadLimits(joint.name));
            }
        }
        self.joints.push(joint);
        Ok(self.joints.len() - 1)
    }

    /// The chain: checks that links and joints form one tree, builds each
    /// link's ball tree once.
    ///
    /// # Errors
    /// [`ChainError::TwoParents`], [`ChainError::NotATree`],
    /// [`ChainError::Mesh`].
    pub fn build(self) -> Result<Chain<T>, ChainError> {
        let n = self.links.len();
        let mut parent_joint: Vec<Option<usize>> = vec![None; n];
        for (j, joint) in self.joints.iter().enumerate() {
            if parent_joint[joint.child].is_some() {
                return Err(ChainError::TwoParents(self.links[joint.child].0.clone()));
            }
            parent_joint[joint.child] = Some(j);
        }
        let roots: Vec<usize> = (0..n).filter(|&l| parent_joint[l].is_none()).collect();
        if roots.len() != 1 {
            return Err(ChainError::NotATree);
        }
        // Joints in an order that puts each parent's joint first; a joint
        // never reached from the root is on a cycle.
        let mut order = Vec::with_capacity(self.joints.len());
        let mut reached = vec![false; n];
        reached[roots[0]] = true;
        let mut frontier = vec![roots[0]];
        while let Some(link) = frontier.pop() {
            for (j, joint) in self.joints.iter().enumerate() {
                if joint.parent == link && !reached[joint.child] {
                    reached[joint.child] = true;
                    order.push(j);
                    frontier.push(joint.child);
                }
            }
        }
        if order.len() != self.joints.len() {
            return Err(ChainError::NotATree);
        }
        let mut dof_of = vec![None; self.joints.len()];
        let mut dofs = 0;
        for (j, joint) in self.joints.iter().enumerate() {
            if joint.kind.is_movable() {
                dof_of[j] = Some(dofs);
                dofs += 1;
            }
        }
        let joints: Vec<JointData<T>> = self
            .joints
            .into_iter()
            .enumerate()
            .map(|(j, s)| JointData {
                axis: if s.kind.is_movable() {
                    unit_axis(Vec3::from_array(s.axis)).unwrap_or(Vec3::new(
                        T::ZERO,
                        T::ZERO,
                        T::ONE,
                    ))
                } else {
                    Vec3::new(T::ZERO, T::ZERO, T::ONE)
                },
                origin_len: s.origin.translation.length(),
                dof: dof_of[j],
                spec: s,
            })
            .collect();
        let mut links = Vec::with_capacity(n);
        for (l, (name, mesh)) in self.links.into_iter().enumerate() {
            // The movable joints from the root down to this link.
            let mut path = Vec::new();
            let mut reach_path = T::ZERO;
            let mut at = l;
            while let Some(j) = parent_joint[at] {
                if joints[j].dof.is_some() {
                    path.push(j);
                }
                reach_path += joints[j].origin_len;
                at = joints[j].spec.parent;
            }
            path.reverse();
            let tree = match &mesh {
                Some(mesh) => Some(
                    BallTree::try_whole_from_mesh(mesh)
                        .map_err(|e| ChainError::Mesh(alloc::format!("link {name:?}: {e}")))?,
                ),
                None => None,
            };
            let reach = tree
                .as_ref()
                .map_or(T::ZERO, |t: &BallTree<T>| t.whole.reach);
            // The distinct vertices reduced to a superset of the hull's
            // vertices (Lemma 13.7, item 5): the same hull, fewer supports.
            let mut hull = mesh.as_ref().map_or_else(Vec::new, |m| {
                let all = distinct(m.vertices());
                hull_vertex_indices(&all)
                    .into_iter()
                    .map(|i| all[i])
                    .collect()
            });
            let hull_rho = ConvexPolytope::try_new(&hull, Pose::IDENTITY)
                .ok()
                .map(|p| p.radius_l1());
            // The support skips clusters that cannot hold its vertex.
            let hull_clusters = cluster_vertices(&mut hull);
            links.push(LinkData {
                name,
                mesh,
                tree,
                hull,
                hull_clusters,
                hull_rho,
                parent_joint: parent_joint[l],
                path,
                reach,
                origin_reach: reach_path,
            });
        }
        Ok(Chain {
            links,
            joints,
            order,
            root: roots[0],
            dofs,
            base: Pose::IDENTITY,
        })
    }
}

#[derive(Clone, Debug)]
pub(crate) struct JointData<T> {
    pub(crate) spec: JointSpec<T>,
    /// The unit axis in the joint frame.
    pub(crate) axis: Vec3<T>,
    /// `|origin translation|`.
    pub(crate) origin_len: T,
    /// The joint's coordinate index, for a movable joint.
    pub(crate) dof: Option<usize>,
}

#[derive(Clone, Debug)]
pub(crate) struct LinkData<T> {
    pub(crate) name: String,
    pub(crate) mesh: Option<TriMesh<T>>,
    pub(crate) tree: Option<BallTree<T>>,
    /// The mesh's distinct vertices (link frame) less points proven inside
    /// the hull of the others: their convex hull holds every triangle, the
    /// cover of `proofs/13-chains.md`, Lemma 13.7.
    pub(crate) hull: Vec<[T; 3]>,
    /// The hull's vertices' clusters, for its support (`hull` is in their
    /// order).
    pub(crate) hull_clusters: Vec<HullCluster<T>>,
    /// The hull's bound of its vertices' 1-norms, from
    /// [`ConvexPolytope::try_new`] at build (`None`: no geometry, or a vertex
    /// GJK refuses; the edge query then descends the tree alone).
    pub(crate) hull_rho: Option<T>,
    pub(crate) parent_joint: Option<usize>,
    /// The movable joints from the root to the link, root first.
    pub(crate) path: Vec<usize>,
    /// An upper bound of every node centre's and point's distance from the
    /// link frame's origin (the tree's reach).
    pub(crate) reach: T,
    /// The sum of the joint origins' lengths from the root to the link.
    pub(crate) origin_reach: T,
}

/// The distinct points of `vertices` (exact duplicates removed: a mesh
/// stored as a triangle soup repeats each corner), in some order.
pub(super) fn distinct<T: Float>(vertices: &[[T; 3]]) -> Vec<[T; 3]> {
    let mut out = vertices.to_vec();
    let key = |v: &[T; 3]| v.map(T::to_f64);
    out.sort_unstable_by(|a, b| {
        let (a, b) = (key(a), key(b));
        a[0].total_cmp(&b[0])
            .then(a[1].total_cmp(&b[1]))
            .then(a[2].total_cmp(&b[2]))
    });
    out.dedup_by(|a, b| key(a) == key(b));
    out
}

/// A kinematic tree: links with collision meshes (each with its ball tree,
/// built once) and joints, placed in the world by a base pose.
///
/// Joint coordinates `q` are ordered as the movable joints were added
/// ([`joint_names`](Self::joint_names)). See the [module](super) docs.
#[derive(Clone, Debug)]
pub struct Chain<T> {
    pub(crate) links: Vec<LinkData<T>>,
    pub(crate) joints: Vec<JointData<T>>,
    /// Joint indices, parents first.
    pub(crate) order: Vec<usize>,
    pub(crate) root: usize,
    pub(crate) dofs: usize,
    pub(crate) base: Pose<T>,
}

/// A joint's world axis and the world point its axis passes through, at one
/// configuration.
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointFrame<T> {
    pub(crate) axis: Vec3<T>,
    pub(crate) point: Vec3<T>,
}

impl<T: Float> Chain<T> {
    /// The number of joint coordinates (movable joints).
    #[inline]
    #[must_use]
    pub fn dof(&self) -> usize {
        self.dofs
    }

    /// The number of links.
    #[inline]
    #[must_use]
    pub fn link_count(&self) -> usize {
        self.links.len()
    }

    /// The root link's index.
    #[inline]
    #[must_use]
    pub fn root(&self) -> usize {
        self.root
    }

    /// A link's name.
    #[must_use]
    pub fn link_name(&self, link: usize) -> Option<&str> {
        self.links.get(link).map(|l| l.name.as_str())
    }

    /// A link's index by name.
    ///
    /// # Errors
    /// [`ChainError::UnknownName`].
    pub fn link_index(&self, name: &str) -> Result<usize, ChainError> {
        self.links
            .iter()
            .position(|l| l.name == name)
            .ok_or_else(|| ChainError::UnknownName(name.into()))
    }

    /// A link's ball tree (its collision mesh), if it has one.
    #[must_use]
    pub fn link_tree(&self, link: usize) -> Option<&BallTree<T>> {
        self.links.get(link).and_then(|l| l.tree.as_ref())
    }

    /// A link's collision mesh in its frame, if it has one.
    #[must_use]
    pub fn link_mesh(&self, link: usize) -> Option<&TriMesh<T>> {
        self.links.get(link).and_then(|l| l.mesh.as_ref())
    }

    /// Every joint as given (fixed ones included), in the order added; a
    /// joint's normalised axis is [`joint_axis`](Self::joint_axis).
    pub fn joints(&self) -> impl ExactSizeIterator<Item = &JointSpec<T>> + '_ {
        self.joints.iter().map(|j| &j.spec)
    }

    /// Joint `j`'s unit axis in its frame (what the chain turns and slides
    /// about; `+z` for a fixed joint).
    #[must_use]
    pub fn joint_axis(&self, j: usize) -> Option<Vec3<T>> {
        self.joints.get(j).map(|j| j.axis)
    }

    /// Joint `j`'s coordinate index, for a movable joint.
    #[must_use]
    pub fn joint_coordinate(&self, j: usize) -> Option<usize> {
        self.joints.get(j).and_then(|j| j.dof)
    }

    /// The link a link hangs from (`None` for the root).
    #[must_use]
    pub fn parent_link(&self, link: usize) -> Option<usize> {
        let j = self.links.get(link)?.parent_joint?;
        Some(self.joints[j].spec.parent)
    }

    /// The movable joints' names, in coordinate order.
    pub fn joint_names(&self) -> impl Iterator<Item = &str> + '_ {
        self.joints
            .iter()
            .filter(|j| j.dof.is_some())
            .map(|j| j.spec.name.as_str())
    }

    /// The limits of each coordinate, in coordinate order (`None` for a
    /// continuous joint).
    #[must_use]
    pub fn limits(&self) -> Vec<Option<[T; 2]>> {
        self.joints
            .iter()
            .filter(|j| j.dof.is_some())
            .map(|j| match j.spec.kind {
                JointKind::Continuous => None,
                _ => j.spec.limits,
            })
            .collect()
    }

    /// The kind of each coordinate's joint, in coordinate order.
    #[must_use]
    pub fn coordinate_kinds(&self) -> Vec<JointKind> {
        self.joints
            .iter()
            .filter(|j| j.dof.is_some())
            .map(|j| j.spec.kind)
            .collect()
    }

    /// The chain placed by `base` (the root link's world pose), unchecked:
    /// a base that is not finite leaves every query undecided
    /// ([`try_with_base`](Self::try_with_base) checks it).
    #[must_use]
    pub fn with_base(mut self, base: Pose<T>) -> Self {
        self.base = base;
        self
    }

    /// The chain placed by `base`, checked as a joint origin is.
    ///
    /// # Errors
    /// [`ChainError::InvalidParameter`] for a base that is not finite, beyond
    /// the input range, or whose rotation has an entry beyond 2.
    pub fn try_with_base(self, base: Pose<T>) -> Result<Self, ChainError> {
        if !base.is_finite()
            || base.translation.max_abs() > T::MAX_INPUT
            || base.rotation_max_abs() > T::TWO
        {
            return Err(ChainError::InvalidParameter("the base pose"));
        }
        Ok(self.with_base(base))
    }

    /// The root link's world pose.
    #[must_use]
    pub fn base(&self) -> Pose<T> {
        self.base
    }

    /// [`check_q`](Self::check_q), and each coordinate within its joint's
    /// limits (inclusive).
    pub(crate) fn check_q_within_limits(&self, q: &[T]) -> Result<(), ChainError> {
        self.check_q(q)?;
        let movable = self.joints.iter().filter(|j| j.dof.is_some());
        for (coordinate, joint) in movable.enumerate() {
            if let (JointKind::Revolute | JointKind::Prismatic, Some([lo, hi])) =
                (joint.spec.kind, joint.spec.limits)
            {
                let x = q[coordinate];
                if x < lo || x > hi {
                    return Err(ChainError::BeyondLimits(coordinate));
                }
            }
        }
        Ok(())
    }

    /// The number of movable joints two links' paths share (those move both
    /// rigidly: `proofs/13-chains.md`, Lemma 13.2, part 3).
    pub(crate) fn common_prefix(&self, a: usize, b: usize) -> usize {
        let (pa, pb) = (&self.links[a].path, &self.links[b].path);
        pa.iter().zip(pb.iter()).take_while(|(x, y)| x == y).count()
    }

    pub(crate) fn check_q(&self, q: &[T]) -> Result<(), ChainError> {
        if q.len() != self.dofs {
            return Err(ChainError::WrongDof {
                expected: self.dofs,
                got: q.len(),
            });
        }
        if let Some(i) = q
            .iter()
            .position(|x| !x.is_finite() || x.abs() > T::MAX_INPUT)
        {
            return Err(ChainError::NonFiniteCoordinate(i));
        }
        Ok(())
    }

    /// Every link's world pose at configuration `q`.
    ///
    /// # Errors
    /// [`ChainError::WrongDof`], [`ChainError::NonFiniteCoordinate`].
    pub fn try_forward_kinematics(&self, q: &[T]) -> Result<Vec<Pose<T>>, ChainError> {
        self.check_q(q)?;
        let mut poses = vec![Pose::IDENTITY; self.links.len()];
        let mut frames = vec![
            JointFrame {
                axis: Vec3::ZERO,
                point: Vec3::ZERO
            };
            self.joints.len()
        ];
        self.place(|dof| q[dof], &mut poses, &mut frames);
        Ok(poses)
    }

    /// Forward kinematics with each coordinate from `coord`: the links'
    /// world poses and the joints' world axes.
    pub(crate) fn place(
        &self,
        coord: impl Fn(usize) -> T,
        poses: &mut [Pose<T>],
        frames: &mut [JointFrame<T>],
    ) {
        poses[self.root] = self.base;
        for &j in &self.order {
            let joint = &self.joints[j];
            let parent = poses[joint.spec.parent];
            let frame = compose(&parent, &joint.spec.origin);
            let axis_world = frame.transform_vector(joint.axis);
            frames[j] = JointFrame {
                axis: axis_world,
                point: frame.translation,
            };
            let child = match (joint.spec.kind, joint.dof) {
                (kind, Some(dof)) if kind.is_rotational() => {
                    compose(&frame, &turn(joint.axis, coord(dof)))
                }
                (JointKind::Prismatic, Some(dof)) => Pose {
                    rotation: frame.rotation,
                    translation: frame.translation + axis_world * coord(dof),
                },
                _ => frame,
            };
            poses[joint.spec.child] = child;
        }
    }
}

/// The unit vector along `a`, scaled by its largest component first (so that
/// tiny and huge axes, whose squared length underflows or overflows, come
/// out of unit length); `None` for a zero or non-finite axis.
pub(crate) fn unit_axis<T: Float>(a: Vec3<T>) -> Option<Vec3<T>> {
    let m = a.max_abs();
    if !(m > T::ZERO && m.is_finite()) {
        return None;
    }
    Vec3::from_array(a.to_array().map(|x| x / m)).try_normalize()
}

/// `a * b` as placements: `p |-> R_a (R_b p + x_b) + x_a`.
pub(crate) fn compose<T: Float>(a: &Pose<T>, b: &Pose<T>) -> Pose<T> {
    Pose {
        rotation: mat_mul(&a.rotation, &b.rotation),
        translation: a.transform_point(b.translation),
    }
}

/// The turn by `angle` about the unit `axis` (Rodrigues), as a pose.
pub(crate) fn turn<T: Float>(axis: Vec3<T>, angle: T) -> Pose<T> {
    let (s, c) = (angle.sin(), angle.cos());
    let k = T::ONE - c;
    let [x, y, z] = axis.to_array();
    Pose {
        rotation: [
            [c + x * x * k, x * y * k - z * s, x * z * k + y * s],
            [y * x * k + z * s, c + y * y * k, y * z * k - x * s],
            [z * x * k - y * s, z * y * k + x * s, c + z * z * k],
        ],
        translation: Vec3::ZERO,
    }
}
