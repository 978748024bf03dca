//! Chains from URDF files (feature `urdf`): links' collision geometry and
//! joints, read with the `urdf-rs` crate.

use std::path::{Path, PathBuf};
use std::string::{String, ToString};
use std::vec::Vec;

use crate::chain::model::{compose, turn, Chain, ChainBuilder, ChainError, JointKind, JointSpec};
use crate::{Float, Pose, TriMesh, Vec3};

/// How a URDF is read.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct UrdfOptions {
    /// Where `package://NAME/...` mesh paths are looked up first (as
    /// `package_root/NAME/...`); then beside the URDF, beside its folder, and
    /// beside the URDF without `NAME`. Plain relative paths are relative to
    /// the URDF's folder.
    pub package_root: Option<PathBuf>,
    /// Sides of the prism that stands for a cylinder (and a capsule's
    /// middle); at least 3, default 24. Cylinders, spheres and capsules
    /// become meshes that *contain* them (circumscribed), so a contact with
    /// the mesh is never later than one with the primitive.
    pub round_sides: u32,
}

impl Default for UrdfOptions {
    fn default() -> Self {
        Self {
            package_root: None,
            round_sides: 24,
        }
    }
}

fn err(msg: impl ToString) -> ChainError {
    ChainError::Urdf(msg.to_string())
}

impl<T: Float> Chain<T> {
    /// Reads a URDF file and its links' collision meshes (OBJ and STL;
    /// boxes exactly, cylinders, spheres and capsules as circumscribed
    /// meshes). Several collision elements of one link are merged into one
    /// mesh in the link's frame.
    ///
    /// ```no_run
    /// use motion_bound::chain::Chain;
    /// let panda = Chain::<f64>::from_urdf_file("data/arms/franka_panda/panda.urdf")?;
    /// assert_eq!(panda.dof(), 9); // seven arm joints and two fingers
    /// # Ok::<(), motion_bound::chain::ChainError>(())
    /// ```
    ///
    /// # Errors
    /// [`ChainError::Urdf`] for a file that cannot be read or parsed, a
    /// joint kind other than revolute, continuous, prismatic or fixed, a
    /// COLLADA (`.dae`) or other unread mesh format, a mesh file that cannot
    /// be read; and [`Chain`]'s own errors.
    pub fn from_urdf_file(path: impl AsRef<Path>) -> Result<Self, ChainError> {
        Self::from_urdf_file_with(path, &UrdfOptions::default())
    }

    /// [`from_urdf_file`](Self::from_urdf_file) with options.
    ///
    /// # Errors
    /// As [`from_urdf_file`](Self::from_urdf_file).
    pub fn from_urdf_file_with(
        path: impl AsRef<Path>,
        options: &UrdfOptions,
    ) -> Result<Self, ChainError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path)
            .map_err(|e| err(format_args!("{}: {e}", path.display())))?;
        let dir = path.parent().unwrap_or_else(|| Path::new("."));
        Self::from_urdf_str(&text, dir, options)
    }

    /// A chain from URDF text, with mesh paths relative to `dir`.
    ///
    /// # Errors
    /// As [`from_urdf_file`](Self::from_urdf_file).
    pub fn from_urdf_str(
        text: &str,
        dir: &Path,
        options: &UrdfOptions,
    ) -> Result<Self, ChainError> {
        if options.round_sides < 3 || options.round_sides > 4096 {
            return Err(ChainError::InvalidParameter(
                "round_sides must be in 3..=4096",
            ));
        }
        let robot = urdf_rs::read_from_string(text).map_err(err)?;
        let mut b = ChainBuilder::new();
        let mut index = std::collections::HashMap::new();
        for link in &robot.links {
            let mut vertices: Vec<[f64; 3]> = Vec::new();
            let mut triangles: Vec<[u32; 3]> = Vec::new();
            for c in &link.collision {
                let (v, t) = geometry(&c.geometry, dir, options)
                    .map_err(|e| err(format_args!("link {:?}: {e}", link.name)))?;
                let place = pose_of(&c.origin)?;
                let base = u32::try_from(vertices.len()).map_err(|_| err("too many vertices"))?;
                vertices.extend(v.iter().map(|p| place.transform_point(*p).to_array()));
                triangles.extend(t.iter().map(|tri| tri.map(|i| i + base)));
            }
            let mesh = if triangles.is_empty() {
                None
            } else {
                let v: Vec<[T; 3]> = vertices.iter().map(|p| p.map(T::from_f64)).collect();
                Some(
                    TriMesh::try_new(v, triangles)
                        .map_err(|e| err(format_args!("link {:?}: {e}", link.name)))?,
                )
            };
            let id = b.add_link(link.name.clone(), mesh)?;
            index.insert(link.name.clone(), id);
        }
        for joint in &robot.joints {
            let kind = match joint.joint_type {
                urdf_rs::JointType::Revolute => JointKind::Revolute,
                urdf_rs::JointType::Continuous => JointKind::Continuous,
                urdf_rs::JointType::Prismatic => JointKind::Prismatic,
                urdf_rs::JointType::Fixed => JointKind::Fixed,
                ref other => {
                    return Err(err(format_args!(
                        "joint {:?}: the kind {other:?} is not supported",
                        joint.name
                    )))
                }
            };
            let link = |name: &str| {
                index
                    .get(name)
                    .copied()
                    .ok_or_else(|| ChainError::UnknownName(name.into()))
            };
            let origin = pose_of(&joint.origin)?;
            let (lower, upper) = (joint.limit.lower, joint.limit.upper);
            let limited = matches!(kind, JointKind::Revolute | JointKind::Prismatic);
            if limited && (lower.is_nan() || upper.is_nan()) {
                // An infinite limit is no limit; a NaN one is a broken file.
                return Err(ChainError::BadLimits(joint.name.clone()));
            }
            let limits = match kind {
                JointKind::Revolute | JointKind::Prismatic
                    if lower.is_finite() && upper.is_finite() =>
                {
                    Some([
                        T::from_f64(joint.limit.lower),
                        T::from_f64(joint.limit.upper),
                    ])
                }
                _ => None,
            };
            b.add_joint(JointSpec {
                name: joint.name.clone(),
                kind,
                parent: link(&joint.parent.link)?,
                child: link(&joint.child.link)?,
                origin: Pose {
                    rotation: origin.rotation.map(|r| r.map(T::from_f64)),
                    translation: Vec3::from_array(origin.translation.to_array().map(T::from_f64)),
                },
                axis: joint.axis.xyz.0.map(T::from_f64),
                limits,
            })?;
        }
        b.build()
    }
}

/// URDF's `<origin xyz rpy>`: `Rz(yaw) Ry(pitch) Rx(roll)`, then the shift.
fn pose_of(origin: &urdf_rs::Pose) -> Result<Pose<f64>, ChainError> {
    let [r, p, y] = origin.rpy.0;
    let xyz = origin.xyz.0;
    if !(r.is_finite() && p.is_finite() && y.is_finite() && xyz.iter().all(|x| x.is_finite())) {
        return Err(err("an origin that is not finite"));
    }
    let axis = |k: usize| {
        let mut a = [0.0; 3];
        a[k] = 1.0;
        Vec3::from_array(a)
    };
    let rot = compose(
        &compose(&turn(axis(2), y), &turn(axis(1), p)),
        &turn(axis(0), r),
    );
    Ok(Pose {
        rotation: rot.rotation,
        translation: Vec3::from_array(xyz),
    })
}

type Soup = (Vec<[f64; 3]>, Vec<[u32; 3]>);

fn geometry(g: &urdf_rs::Geometry, dir: &Path, options: &UrdfOptions) -> Result<Soup, String> {
    let n = options.round_sides;
    match g {
        urdf_rs::Geometry::Box { size } => {
            let h = size.0.map(|s| s / 2.0);
            Ok(cuboid(h))
        }
        urdf_rs::Geometry::Cylinder { radius, length } => Ok(cylinder(*radius, *length, n)),
        urdf_rs::Geometry::Sphere { radius } => Ok(sphere(*radius, [0.0; 3], n)),
        urdf_rs::Geometry::Capsule { radius, length } => {
            let mut soup = cylinder(*radius, *length, n);
            for z in [-length / 2.0, length / 2.0] {
                let (v, t) = sphere(*radius, [0.0, 0.0, z], n);
                let base = soup.0.len() as u32;
                soup.0.extend(v);
                soup.1.extend(t.iter().map(|tri| tri.map(|i| i + base)));
            }
            Ok(soup)
        }
        urdf_rs::Geometry::Mesh { filename, scale } => {
            let path = resolve(filename, dir, options);
            let ext = path
                .extension()
                .and_then(|e| e.to_str())
                .unwrap_or("")
                .to_ascii_lowercase();
            let mesh: TriMesh<f64> = match ext.as_str() {
                "obj" => TriMesh::load_obj(&path).map_err(|e| format!("{}: {e}", path.display()))?,
                "stl" => TriMesh::load_stl(&path).map_err(|e| format!("{}: {e}", path.display()))?,
                "dae" => {
                    return Err(format!(
                        "{}: COLLADA (.dae) meshes are not read (no small, well-kept reader); convert it to STL or OBJ",
                        path.display()
                    ))
                }
                other => return Err(format!("{}: the mesh format {other:?} is not read", path.display())),
            };
            let s = scale.map_or([1.0; 3], |s| s.0);
            if !s.iter().all(|x| x.is_finite() && *x != 0.0) {
                return Err(format!("{}: a zero or non-finite scale", path.display()));
            }
            let (v, t) = mesh.into_parts();
            let mut t = t;
            // A mirroring scale turns the triangles inside out; flip them back.
            if s[0] * s[1] * s[2] < 0.0 {
                for tri in &mut t {
                    tri.swap(1, 2);
                }
            }
            Ok((
                v.into_iter()
                    .map(|p| [p[0] * s[0], p[1] * s[1], p[2] * s[2]])
                    .collect(),
                t,
            ))
        }
    }
}

fn resolve(filename: &str, dir: &Path, options: &UrdfOptions) -> PathBuf {
    if let Some(rest) = filename.strip_prefix("package://") {
        // ROS resolves `package://NAME/...` through its package index; without
        // one, the first of these that exists: under `package_root`, beside
        // the URDF, beside its folder, and beside the URDF without `NAME`.
        let stripped = rest.split_once('/').map_or(rest, |(_, r)| r);
        let mut candidates = Vec::new();
        if let Some(root) = &options.package_root {
            candidates.push(root.join(rest));
        }
        candidates.push(dir.join(rest));
        candidates.push(dir.parent().unwrap_or(dir).join(rest));
        candidates.push(dir.join(stripped));
        let first = candidates[0].clone();
        return candidates.into_iter().find(|c| c.exists()).unwrap_or(first);
    }
    let f = filename.strip_prefix("file://").unwrap_or(filename);
    let p = Path::new(f);
    if p.is_absolute() {
        p.to_path_buf()
    } else {
        dir.join(p)
    }
}

fn cuboid(h: [f64; 3]) -> Soup {
    let mut v = Vec::with_capacity(8);
    for i in 0..8 {
        v.push([0, 1, 2].map(|k| if i >> k & 1 == 1 { h[k] } else { -h[k] }));
    }
    let t = crate::mesh::BOX_TRIANGLES.to_vec();
    (v, t)
}

/// A prism of `n` sides circumscribing the cylinder (its sides' mid-lines
/// touch it): corner radius `r / cos(pi / n)`, rounded outward.
fn cylinder(r: f64, len: f64, n: u32) -> Soup {
    let rc = r / (core::f64::consts::PI / f64::from(n)).cos() * (1.0 + 1e-12);
    let h = len / 2.0;
    let mut v = Vec::new();
    for i in 0..n {
        let a = 2.0 * core::f64::consts::PI * f64::from(i) / f64::from(n);
        v.push([rc * a.cos(), rc * a.sin(), -h]);
        v.push([rc * a.cos(), rc * a.sin(), h]);
    }
    v.push([0.0, 0.0, -h]);
    v.push([0.0, 0.0, h]);
    let (lo, hi) = (2 * n, 2 * n + 1);
    let mut t = Vec::new();
    for i in 0..n {
        let j = (i + 1) % n;
        let (a0, a1, b0, b1) = (2 * i, 2 * i + 1, 2 * j, 2 * j + 1);
        t.push([a0, b0, a1]);
        t.push([a1, b0, b1]);
        t.push([lo, b0, a0]);
        t.push([hi, a1, b1]);
    }
    (v, t)
}

/// A latitude-longitude polyhedron scaled so that every face plane is at
/// least `r` from the centre: it contains the ball.
fn sphere(r: f64, centre: [f64; 3], n: u32) -> Soup {
    let (rings, sectors) = ((n / 2).max(2), n);
    let mut unit = vec![[0.0, 0.0, -1.0]];
    for i in 1..rings {
        let phi =
            core::f64::consts::PI * f64::from(i) / f64::from(rings) - core::f64::consts::FRAC_PI_2;
        for j in 0..sectors {
            let th = 2.0 * core::f64::consts::PI * f64::from(j) / f64::from(sectors);
            unit.push([phi.cos() * th.cos(), phi.cos() * th.sin(), phi.sin()]);
        }
    }
    unit.push([0.0, 0.0, 1.0]);
    let top = unit.len() as u32 - 1;
    let at = |i: u32, j: u32| 1 + (i - 1) * sectors + j % sectors;
    let mut t = Vec::new();
    for j in 0..sectors {
        t.push([0, at(1, j + 1), at(1, j)]);
        t.push([top, at(rings - 1, j), at(rings - 1, j + 1)]);
    }
    for i in 1..rings - 1 {
        for j in 0..sectors {
            t.push([at(i, j), at(i, j + 1), at(i + 1, j)]);
            t.push([at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)]);
        }
    }
    // The least distance of a face plane from the centre.
    let mut h = f64::INFINITY;
    for tri in &t {
        let [a, b, c] = tri.map(|k| Vec3::from_array(unit[k as usize]));
        if let Some(nrm) = (b - a).cross(c - a).try_normalize() {
            h = h.min(nrm.dot(a).abs());
        }
    }
    let s = r / h * (1.0 + 1e-12);
    let v = unit
        .iter()
        .map(|p| {
            [
                centre[0] + p[0] * s,
                centre[1] + p[1] * s,
                centre[2] + p[2] * s,
            ]
        })
        .collect();
    (v, t)
}
