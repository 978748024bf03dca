//! `from_trimesh` given a `trimesh.Scene` (what `trimesh.load` returns for many GLB, glTF and
//! OBJ files): its meshes placed by the scene graph, as one mesh.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `obj`'s meshes as one `trimesh.Trimesh`, each placed by the scene graph (trimesh's
/// `Scene.to_mesh()`, or `dump(concatenate=True)` before trimesh 4), when `obj` is a
/// `trimesh.Scene`; `None` for anything else. An error, naming `force="mesh"`, when the scene
/// holds no triangles (paths or point clouds alone) or trimesh cannot concatenate them.
pub(crate) fn scene_mesh<'py>(obj: &Bound<'py, PyAny>) -> PyResult<Option<Bound<'py, PyAny>>> {
    let py = obj.py();
    // Not a scene unless trimesh is importable and it says so.
    let Ok(trimesh) = py.import("trimesh") else {
        return Ok(None);
    };
    let Ok(scene_type) = trimesh.getattr("Scene") else {
        return Ok(None);
    };
    if !obj.is_instance(&scene_type)? {
        return Ok(None);
    }
    let refuse = |why: String| {
        PyValueError::new_err(format!(
            "mesh: {why}; load a single mesh with trimesh.load(path, force=\"mesh\"), or pass \
             one of scene.geometry's meshes"
        ))
    };
    let mesh = if obj.hasattr("to_mesh")? {
        obj.call_method0("to_mesh")
    } else {
        let kwargs = PyDict::new(py);
        kwargs.set_item("concatenate", true)?;
        obj.call_method("dump", (), Some(&kwargs))
    }
    .map_err(|e| {
        refuse(format!(
            "trimesh could not concatenate the scene's meshes ({e})"
        ))
    })?;
    let faces = mesh.getattr("faces")?.len()?;
    if faces == 0 {
        return Err(refuse(
            "the trimesh.Scene holds no triangles (no Trimesh among its geometry)".to_string(),
        ));
    }
    Ok(Some(mesh))
}
