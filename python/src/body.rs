//! Bodies: a shape in its own frame, with what a query needs built once (a
//! mesh's ball tree). Every kind is one class, `Body`, made by a factory
//! function per kind; each body remembers its factory and arguments, which
//! is how it pickles.

use motion_bound::ca::{OwnedShape, PreparedShape, Primitive, Shape};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use crate::arrays::{matrix4, rows3, to_numpy, triangles, vec3};
use crate::errors::{arg, input};
use crate::motion::{pose_arg, Pose, PoseSource};

/// How a body was made, for pickling and `repr` (what it is, the crate's
/// [`OwnedShape`], does not keep a primitive's dimensions or a half-space's
/// normal as given, or a compound's bodies).
#[derive(Debug)]
pub(crate) enum Source {
    Primitive(Primitive<f64>, f64),
    Hull,
    Mesh,
    HalfSpace([f64; 3]),
    /// The parts as given.
    Compound(Vec<(Py<Body>, Pose)>),
}

/// A body: a shape in its own frame (meshes with their ball tree, built
/// once). Made by `mesh`, `ball`, `capsule`, `box`, `cylinder`, `cone`,
/// `convex_hull`, `half_space`, `compound` or `from_trimesh`; immutable,
/// shareable between threads and queries, picklable.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Debug)]
pub struct Body {
    /// What it is: the crate's owned shape.
    pub(crate) shape: OwnedShape<f64>,
    /// How it was made.
    pub(crate) source: Source,
}

impl Body {
    /// The shapes a query borrows.
    pub(crate) fn prepare(&self) -> PyResult<PreparedShape<'_, f64>> {
        self.shape.prepare().map_err(input)
    }

    pub(crate) fn kind_name(&self) -> &'static str {
        match &self.source {
            Source::Primitive(primitive, _) => match primitive {
                Primitive::Ball(_) => "ball",
                Primitive::Capsule(..) => "capsule",
                Primitive::Cuboid(_) => "box",
                Primitive::Cylinder(..) => "cylinder",
                _ => "cone",
            },
            Source::Hull => "convex_hull",
            Source::Mesh => "mesh",
            Source::HalfSpace(_) => "half_space",
            Source::Compound(_) => "compound",
        }
    }
}

fn rows_to_numpy<'py>(py: Python<'py>, rows: &[[f64; 3]]) -> PyResult<Bound<'py, PyAny>> {
    to_numpy(py, rows.concat(), &[rows.len(), 3])
}

#[pymethods]
impl Body {
    /// The kind: "mesh", "ball", "capsule", "box", "cylinder", "cone",
    /// "convex_hull", "half_space" or "compound".
    #[getter]
    fn kind(&self) -> &'static str {
        self.kind_name()
    }

    /// A mesh's vertices as an `(n, 3)` array (`None` for other kinds).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        match &self.shape {
            OwnedShape::Mesh(m) => Ok(Some(rows_to_numpy(py, m.mesh().vertices())?)),
            OwnedShape::Hull(h) => Ok(Some(rows_to_numpy(py, h.points())?)),
            _ => Ok(None),
        }
    }

    /// A mesh's triangles as an `(m, 3)` array of indices (`None` for other
    /// kinds).
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        match &self.shape {
            OwnedShape::Mesh(m) => {
                let f = m.mesh().triangles();
                let flat: Vec<i64> = f.iter().flatten().map(|&i| i64::from(i)).collect();
                let arr = numpy::PyArray1::from_vec(py, flat);
                use numpy::PyArrayMethods;
                Ok(Some(arr.reshape(vec![f.len(), 3])?.into_any()))
            }
            _ => Ok(None),
        }
    }

    /// Whether a mesh is solid (a body starting inside it is in contact) or
    /// hollow (its triangles alone); `None` for other kinds.
    #[getter]
    fn solid(&self) -> Option<bool> {
        match &self.shape {
            OwnedShape::Mesh(m) => Some(m.mesh().is_solid()),
            _ => None,
        }
    }

    /// An upper bound of every point's distance from the body's origin
    /// (`inf` for a half-space).
    #[getter]
    fn reach(&self) -> PyResult<f64> {
        let prepared = self.prepare()?;
        Ok(match prepared.shape() {
            Shape::Convex(c) => c.reach(),
            Shape::HalfSpace(_) => f64::INFINITY,
            Shape::Compound(c) => c.reach(),
            other => {
                let ball = other.bounding_ball().map_err(input)?;
                ball.centre_norm_up() + ball.radius()
            }
        })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let module = py.import("motion_bound")?;
        let this = slf.get();
        let f = module.getattr(this.kind_name())?;
        let float = |x: f64| -> PyResult<Bound<'py, PyAny>> { Ok(x.into_pyobject(py)?.into_any()) };
        let args: Vec<Bound<'py, PyAny>> = match (&this.source, &this.shape) {
            (Source::Primitive(primitive, rounding), _) => match *primitive {
                Primitive::Ball(r) => vec![float(r)?],
                Primitive::Capsule(h, r) => vec![float(h)?, float(r)?],
                Primitive::Cuboid(h) => vec![to_numpy(py, h.to_vec(), &[3])?, float(*rounding)?],
                Primitive::Cylinder(h, r) | Primitive::Cone(h, r) => {
                    vec![float(h)?, float(r)?, float(*rounding)?]
                }
                _ => {
                    return Err(PyTypeError::new_err(
                        "a primitive this module does not make",
                    ))
                }
            },
            (_, OwnedShape::Hull(h)) => vec![rows_to_numpy(py, h.points())?, float(h.rounding())?],
            (_, OwnedShape::Mesh(m)) => {
                let b = slf.as_any();
                let solid = m.mesh().is_solid().into_pyobject(py)?.to_owned().into_any();
                vec![b.getattr("vertices")?, b.getattr("faces")?, solid]
            }
            (Source::HalfSpace(normal), _) => vec![to_numpy(py, normal.to_vec(), &[3])?],
            (Source::Compound(given), _) => {
                let items = given
                    .iter()
                    .map(|(b, p)| {
                        let pose = Bound::new(py, p.clone())?.into_any();
                        Ok(PyTuple::new(py, [b.bind(py).clone().into_any(), pose])?.into_any())
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                vec![PyList::new(py, items)?.into_any()]
            }
            _ => return Err(PyTypeError::new_err("a body this module does not make")),
        };
        PyTuple::new(py, [f, PyTuple::new(py, args)?.into_any()])
    }

    fn __repr__(&self) -> String {
        match (&self.source, &self.shape) {
            (Source::Primitive(primitive, rounding), _) => {
                let r = if *rounding == 0.0 {
                    String::new()
                } else {
                    format!(", rounding={rounding}")
                };
                match primitive {
                    Primitive::Ball(x) => format!("ball({x})"),
                    Primitive::Capsule(h, x) => format!("capsule({h}, {x})"),
                    Primitive::Cuboid(h) => format!("box({:?}{r})", h),
                    Primitive::Cylinder(h, x) => format!("cylinder({h}, {x}{r})"),
                    Primitive::Cone(h, x) => format!("cone({h}, {x}{r})"),
                    other => format!("{other:?}"),
                }
            }
            (_, OwnedShape::Hull(h)) => format!("convex_hull({} points)", h.points().len()),
            (_, OwnedShape::Mesh(m)) => format!(
                "mesh({} vertices, {} triangles, {})",
                m.mesh().vertices().len(),
                m.mesh().triangles().len(),
                if m.mesh().is_solid() {
                    "solid"
                } else {
                    "hollow"
                }
            ),
            (Source::HalfSpace(normal), _) => format!("half_space({normal:?})"),
            (Source::Compound(given), _) => format!("compound({} parts)", given.len()),
            (_, other) => format!("{other:?}"),
        }
    }
}

fn convex_body(primitive: Primitive<f64>, rounding: f64) -> PyResult<Body> {
    Ok(Body {
        shape: OwnedShape::try_primitive(primitive, rounding).map_err(arg)?,
        source: Source::Primitive(primitive, rounding),
    })
}

/// A triangle mesh from `vertices` (an `(n, 3)` array of real numbers) and
/// `faces` (an `(m, 3)` array of integer indices into `vertices`). Its ball
/// tree is built here, once; the mesh need not be closed or convex.
///
/// `solid`: a solid mesh is the region it bounds, so a body starting inside
/// it is in contact (`initial_contact`); a hollow one is its triangles
/// alone, and a body wholly inside touches nothing. `None` (the default):
/// solid when the mesh is closed (every edge shared by two triangles running
/// along it in opposite directions, trimesh's `is_watertight` and
/// `is_winding_consistent`) and wound outward (positive volume), hollow
/// otherwise. `True`: solid, or `MeshError` if it is not closed and
/// outward-wound. `False`: hollow.
///
/// Raises `InputError` for NaN, infinite or out-of-range vertices,
/// `MeshError` for an index out of range, no triangle, or a mesh that cannot
/// be solid, `ValueError` for a wrong shape, `TypeError` for a wrong dtype
/// (float indices, say).
#[pyfunction]
#[pyo3(signature = (vertices, faces, solid = None))]
fn mesh(
    vertices: &Bound<'_, PyAny>,
    faces: &Bound<'_, PyAny>,
    solid: Option<bool>,
) -> PyResult<Body> {
    let v = rows3(vertices, "vertices")?;
    let f = triangles(faces, "faces")?;
    let asked = if solid.is_some() {
        "solid=True"
    } else {
        "solid"
    };
    Ok(Body {
        shape: OwnedShape::try_mesh(v, f, solid, ["vertices", "faces", asked]).map_err(arg)?,
        source: Source::Mesh,
    })
}

/// Which of trimesh's exact primitives `obj` is (`"Sphere"`, `"Box"`,
/// `"Capsule"` or `"Cylinder"`, a class of that name in
/// `trimesh.primitives` among its type's bases), if any. trimesh itself is
/// never imported here.
fn trimesh_primitive(obj: &Bound<'_, PyAny>) -> PyResult<Option<&'static str>> {
    for cls in obj.get_type().getattr("__mro__")?.try_iter()? {
        let cls = cls?;
        let module: String = cls.getattr("__module__")?.extract().unwrap_or_default();
        if module != "trimesh.primitives" {
            continue;
        }
        let name: String = cls.getattr("__name__")?.extract()?;
        for kind in ["Sphere", "Box", "Capsule", "Cylinder"] {
            if name == kind {
                return Ok(Some(kind));
            }
        }
    }
    Ok(None)
}

/// A body placed at `matrix` in its own frame: the body itself when the
/// matrix is the identity, else a compound of one part.
fn placed(py: Python<'_>, body: Body, matrix: [f64; 16], what: &str) -> PyResult<Body> {
    let identity = [
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    if matrix == identity {
        return Ok(body);
    }
    let pose = Pose::from_source(PoseSource::Matrix(matrix)).map_err(|e| {
        let msg = e.value(py).to_string();
        crate::errors::InputError::new_err(format!("{what}: {msg}"))
    })?;
    let part = PyTuple::new(
        py,
        [
            Bound::new(py, body)?.into_any(),
            Bound::new(py, pose)?.into_any(),
        ],
    )?;
    compound(PyList::new(py, [part])?.as_any())
}

/// The body of one of trimesh's primitives as trimesh means it: its
/// `primitive` attributes (a sphere's `radius`; a box's full `extents`; a
/// capsule's `height` between its two sphere centres and a cylinder's whole
/// `height`, both along z; each at its `transform`).
fn from_trimesh_primitive(obj: &Bound<'_, PyAny>, kind: &str) -> PyResult<Body> {
    let py = obj.py();
    let prim = obj.getattr("primitive")?;
    let number = |name: &str| -> PyResult<f64> {
        prim.getattr(name)?.extract().map_err(|_| {
            PyTypeError::new_err(format!("mesh.primitive.{name} must be a real number"))
        })
    };
    let transform = matrix4(&prim.getattr("transform")?, "mesh.primitive.transform")?;
    // Ours lie along y, trimesh's along z: the quarter turn about x that
    // takes y to z, composed exactly (a permutation of the columns of the
    // transform's rotation block, one negated).
    let along_z = |m: [f64; 16]| -> [f64; 16] {
        let mut out = m;
        for row in 0..3 {
            out[4 * row + 1] = m[4 * row + 2];
            out[4 * row + 2] = -m[4 * row + 1];
        }
        out
    };
    let what = "mesh.primitive.transform";
    match kind {
        "Sphere" => placed(
            py,
            convex_body(Primitive::Ball(number("radius")?), 0.0)
                .map_err(|e| prefixed(py, e, "mesh.primitive"))?,
            transform,
            what,
        ),
        "Box" => {
            let e = vec3(&prim.getattr("extents")?, "mesh.primitive.extents")?;
            let half = [e[0] / 2.0, e[1] / 2.0, e[2] / 2.0];
            let body = convex_body(Primitive::Cuboid(half), 0.0)
                .map_err(|e| prefixed(py, e, "mesh.primitive.extents / 2"))?;
            placed(py, body, transform, what)
        }
        "Capsule" => {
            let p = Primitive::Capsule(number("height")? / 2.0, number("radius")?);
            let body =
                convex_body(p, 0.0).map_err(|e| prefixed(py, e, "mesh.primitive (height / 2)"))?;
            placed(py, body, along_z(transform), what)
        }
        _ => {
            let p = Primitive::Cylinder(number("height")? / 2.0, number("radius")?);
            let body =
                convex_body(p, 0.0).map_err(|e| prefixed(py, e, "mesh.primitive (height / 2)"))?;
            placed(py, body, along_z(transform), what)
        }
    }
}

/// `e` with its message prefixed by `what`, of the same type.
fn prefixed(py: Python<'_>, e: PyErr, what: &str) -> PyErr {
    let msg = format!("{what}: {}", e.value(py));
    if e.is_instance_of::<crate::errors::InputError>(py) {
        crate::errors::InputError::new_err(msg)
    } else {
        PyValueError::new_err(msg)
    }
}

/// The body of a trimesh object; trimesh is imported only by the caller.
///
/// trimesh's exact primitives are taken as trimesh means them, as exact
/// convex shapes (not their triangles): `trimesh.primitives.Sphere` (its
/// `radius`), `Box` (its `extents`, full lengths: halved here, since `box`
/// takes half extents), `Capsule` (its `height` between the two sphere
/// centres, along z) and `Cylinder` (its whole `height`, along z), each at
/// its `primitive.transform`. Our capsules and cylinders lie along y, so
/// these two (and every primitive whose transform is not the identity) come
/// back as a `compound` of one part, turned and placed; a sphere or box at
/// the identity comes back as a `ball` or `box`. For the primitive's
/// triangles instead, pass `mesh(m.vertices, m.faces)`.
///
/// Any other object with `vertices` and `faces` (a `trimesh.Trimesh`) is a
/// triangle mesh, `solid` as for `mesh`: by default solid when the mesh is
/// closed and outward-wound. A primitive is always solid: `solid=False` is
/// refused for one. A `trimesh.Scene` (what `trimesh.load` returns for many
/// GLB and OBJ files) is one triangle mesh of all its meshes, each placed by
/// the scene graph (`scene.to_mesh()`); a scene without triangles is refused.
#[pyfunction]
#[pyo3(signature = (mesh, solid = None))]
fn from_trimesh(mesh: &Bound<'_, PyAny>, solid: Option<bool>) -> PyResult<Body> {
    if let Some(m) = crate::trimesh_scene::scene_mesh(mesh)? {
        return from_trimesh(&m, solid);
    }
    if let Some(kind) = trimesh_primitive(mesh)? {
        if solid == Some(false) {
            return Err(PyValueError::new_err(format!(
                "solid=False: a trimesh {kind} is a solid primitive; for its triangles alone, \
                 pass mesh(m.vertices, m.faces, solid=False)"
            )));
        }
        return from_trimesh_primitive(mesh, kind);
    }
    let (Ok(v), Ok(f)) = (mesh.getattr("vertices"), mesh.getattr("faces")) else {
        return Err(PyTypeError::new_err(
            "mesh: from_trimesh takes an object with `vertices` and `faces` (a trimesh.Trimesh)",
        ));
    };
    self::mesh(&v, &f, solid)
}

/// A ball of `radius` (finite, at least 0) centred at the body origin.
#[pyfunction]
fn ball(radius: f64) -> PyResult<Body> {
    convex_body(Primitive::Ball(radius), 0.0)
}

/// A capsule along the body's **y** axis: the segment from
/// `(0, -half_height, 0)` to `(0, half_height, 0)` rounded by `radius`
/// (both finite, at least 0). trimesh's `Capsule(height, radius)` lies along
/// z with `height` between the sphere centres: it is
/// `capsule(height / 2, radius)` turned by a quarter turn about x
/// (`from_trimesh` does this).
#[pyfunction]
fn capsule(half_height: f64, radius: f64) -> PyResult<Body> {
    convex_body(Primitive::Capsule(half_height, radius), 0.0)
}

/// The box `[-h0, h0] x [-h1, h1] x [-h2, h2]` of the **half** extents
/// `h = half_extents` (three finite numbers, at least 0), rounded by
/// `rounding` (every point within `rounding` of the box). trimesh's
/// `Box(extents)` takes full extents: it is `box(extents / 2)`.
#[pyfunction]
#[pyo3(name = "box", signature = (half_extents, rounding = 0.0))]
fn cuboid(half_extents: &Bound<'_, PyAny>, rounding: f64) -> PyResult<Body> {
    convex_body(
        Primitive::Cuboid(vec3(half_extents, "half_extents")?),
        rounding,
    )
}

/// The cylinder along the body's **y** axis, `|y| <= half_height`
/// (positive), of radius `radius` (at least 0), rounded by `rounding`.
/// trimesh's `Cylinder(radius, height)` lies along z with its whole height:
/// it is `cylinder(height / 2, radius)` turned by a quarter turn about x
/// (`from_trimesh` does this).
#[pyfunction]
#[pyo3(signature = (half_height, radius, rounding = 0.0))]
fn cylinder(half_height: f64, radius: f64, rounding: f64) -> PyResult<Body> {
    convex_body(Primitive::Cylinder(half_height, radius), rounding)
}

/// The cone along the body's **y** axis, apex `(0, half_height, 0)`
/// (`half_height` positive), base of radius `radius` at `y = -half_height`,
/// rounded by `rounding`.
#[pyfunction]
#[pyo3(signature = (half_height, radius, rounding = 0.0))]
fn cone(half_height: f64, radius: f64, rounding: f64) -> PyResult<Body> {
    convex_body(Primitive::Cone(half_height, radius), rounding)
}

/// The convex hull of `points` (an `(n, 3)` array), rounded by `rounding`.
#[pyfunction]
#[pyo3(signature = (points, rounding = 0.0))]
fn convex_hull(points: &Bound<'_, PyAny>, rounding: f64) -> PyResult<Body> {
    Ok(Body {
        shape: OwnedShape::try_hull(rows3(points, "points")?, rounding).map_err(arg)?,
        source: Source::Hull,
    })
}

/// The half-space `{x : normal . x <= 0}` in the body frame (the ground for
/// `normal = (0, 0, 1)` at the identity pose, say; the normal points out of
/// the solid). It may translate but not turn.
#[pyfunction]
fn half_space(normal: &Bound<'_, PyAny>) -> PyResult<Body> {
    let n = vec3(normal, "normal")?;
    Ok(Body {
        shape: OwnedShape::try_half_space(n).map_err(arg)?,
        source: Source::HalfSpace(n),
    })
}

/// Several bodies moving as one: `parts` is a list of `(body, pose)` with
/// each body's pose in the compound's frame (a 4x4 array or a `Pose`). Parts
/// are meshes and convex shapes (not half-spaces or compounds).
#[pyfunction]
fn compound(parts: &Bound<'_, PyAny>) -> PyResult<Body> {
    let mut given = Vec::new();
    let items = parts
        .try_iter()
        .map_err(|_| PyTypeError::new_err("parts must be a list of (body, pose) pairs"))?;
    for (k, item) in items.enumerate() {
        let item = item?;
        let (body, pose): (Bound<'_, PyAny>, Bound<'_, PyAny>) = item
            .extract()
            .map_err(|_| PyTypeError::new_err(format!("parts[{k}] must be a (body, pose) pair")))?;
        let body: Bound<'_, Body> = body
            .cast_into()
            .map_err(|_| PyTypeError::new_err(format!("parts[{k}][0] must be a Body")))?;
        let pose = pose_arg(&pose, &format!("parts[{k}][1]"))?;
        given.push((body.unbind(), pose));
    }
    let shape = OwnedShape::try_compound(given.iter().map(|(b, p)| (&b.get().shape, p.iso)))
        .map_err(arg)?;
    Ok(Body {
        shape,
        source: Source::Compound(given),
    })
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Body>()?;
    m.add_function(wrap_pyfunction!(mesh, m)?)?;
    m.add_function(wrap_pyfunction!(from_trimesh, m)?)?;
    m.add_function(wrap_pyfunction!(ball, m)?)?;
    m.add_function(wrap_pyfunction!(capsule, m)?)?;
    m.add_function(wrap_pyfunction!(cuboid, m)?)?;
    m.add_function(wrap_pyfunction!(cylinder, m)?)?;
    m.add_function(wrap_pyfunction!(cone, m)?)?;
    m.add_function(wrap_pyfunction!(convex_hull, m)?)?;
    m.add_function(wrap_pyfunction!(half_space, m)?)?;
    m.add_function(wrap_pyfunction!(compound, m)?)?;
    Ok(())
}
