//! Scenes: many bodies over one interval, every pair's first contact after
//! the crate's certified broad phase.

use std::sync::Arc;

use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
use motion_bound::{RigidMotion, TimeInterval};

use crate::error::{guard, Failure, MbStatus, Res};
use crate::motion::MbMotion;
use crate::ptr::{
    free_handle, handle_mut, handle_ref, read_in, write_handle, write_out, Handle, Kind,
};
use crate::query::{params, MbParams, MbReport};
use motion_bound::ca::OwnedShape;

use crate::shape::MbShape;

/// Many bodies moving over `[0, duration]`. Opaque; made by
/// `mb_scene_new`, grown by `mb_scene_add`, queried by
/// `mb_scene_query`, freed by `mb_scene_free`. It shares its bodies'
/// shapes, so a shape may be freed once added.
#[derive(Debug)]
pub struct MbScene {
    duration: f64,
    bodies: Vec<(Arc<OwnedShape<f64>>, RigidMotion<f64>)>,
}

impl Handle for MbScene {
    const KIND: Kind = Kind::Scene;
    const NAME: &'static str = "the scene";
}

/// One pair of a scene query's answer.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbScenePair {
    /// The first body's number (as `mb_scene_add` returned it), `a < b`.
    pub a: usize,
    /// The second body's number.
    pub b: usize,
    /// The pair's first contact, as `mb_time_of_impact` reports it.
    pub report: MbReport,
}

/// A scene query's answer: the pairs its broad phase could not rule out
/// (a pair not listed provably stays apart), each with its report. Opaque;
/// read with `mb_scene_result_len` and `mb_scene_result_get`, freed by
/// `mb_scene_result_free`; immutable.
#[derive(Debug)]
pub struct MbSceneResult {
    pairs: Vec<MbScenePair>,
}

impl Handle for MbSceneResult {
    const KIND: Kind = Kind::SceneResult;
    const NAME: &'static str = "the scene result";
}

/// A new empty scene over `[0, duration]`, written to `*out`.
/// `MB_STATUS_INVALID_INPUT` for a duration that is not positive and finite.
///
/// **Thread safety**: any thread.
///
/// # Safety
/// `out` is `NULL` or valid for writing a pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_new(duration: f64, out: *mut *mut MbScene) -> MbStatus {
    guard(|| {
        motion_bound::ca::ArgError::positive(duration, "duration")?;
        TimeInterval::try_new(0.0, duration)
            .map_err(motion_bound::ca::ArgError::input("duration"))?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe {
            write_handle(
                out,
                MbScene {
                    duration,
                    bodies: Vec::new(),
                },
            )
        }
    })
}

/// Adds a body of shape `shape` moving by `motion` (over the scene's
/// `[0, duration]`); writes its number (`0`, `1`, ...) to `*out_index`
/// (which may be `NULL`). `MB_STATUS_QUERY_ERROR` for a motion over another
/// interval.
///
/// **Thread safety**: no other thread may use `scene` during the call;
/// `shape` and `motion` may be shared.
///
/// # Safety
/// The handles are not freed during the call and `scene` is not used by
/// another thread; `out_index` is `NULL` or valid for writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_add(
    scene: *mut MbScene,
    shape: *const MbShape,
    motion: *const MbMotion,
    out_index: *mut usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: the handles are not freed during the call and `scene` is
        // used by no other thread (this function's contract).
        let (sc, sh, m) = unsafe {
            (
                handle_mut(scene, "scene")?,
                handle_ref(shape, "shape")?,
                handle_ref(motion, "motion")?,
            )
        };
        let i = m.motion.interval();
        if i.start() != 0.0 || i.end() != sc.duration {
            return Err(Failure::new(
                MbStatus::QueryError,
                format!(
                    "motion is over [{}, {}], the scene over [0, {}]",
                    i.start(),
                    i.end(),
                    sc.duration
                ),
            ));
        }
        sc.bodies.push((Arc::clone(&sh.data), m.motion));
        if !out_index.is_null() {
            // SAFETY: `out_index` is writable (this function's contract).
            unsafe { write_out(out_index, sc.bodies.len() - 1, "out_index") }?;
        }
        Ok(())
    })
}

/// The number of bodies in `scene`, written to `*out`.
///
/// **Thread safety**: any thread, unless another adds to `scene`.
///
/// # Safety
/// `scene` is not freed or added to during the call; `out` is `NULL` or
/// valid for writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_len(scene: *const MbScene, out: *mut usize) -> MbStatus {
    guard(|| {
        // SAFETY: `scene` is not freed or changed during the call (this function's contract).
        let sc = unsafe { handle_ref(scene, "scene") }?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, sc.bodies.len(), "out") }
    })
}

fn run(sc: &MbScene, p: &SceneParams<f64>) -> Res<Vec<MbScenePair>> {
    let prepared = sc
        .bodies
        .iter()
        .map(|(d, _)| d.prepare())
        .collect::<Result<Vec<_>, _>>()?;
    let mut scene = Scene::try_new(TimeInterval::try_new(0.0, sc.duration)?)?;
    for (prep, (_, motion)) in prepared.iter().zip(&sc.bodies) {
        scene.try_add(prep.shape(), *motion)?;
    }
    let mut ws = SceneWorkspace::new();
    let report = scene.query(&mut ws, p).map_err(|e| {
        let f = Failure::from(e);
        Failure::new(f.status, format!("scene: {}", f.message))
    })?;
    Ok(report
        .pairs()
        .iter()
        .map(|r| MbScenePair {
            a: r.a,
            b: r.b,
            report: MbReport::of(&r.report),
        })
        .collect())
}

/// Every pair's first contact in `scene` (`params` may be `NULL` for the
/// defaults), as a new result handle written to `*out` (free it with
/// `mb_scene_result_free`).
///
/// **Thread safety**: any thread; several threads may query one scene at
/// once, but none may add to it meanwhile.
///
/// # Safety
/// `scene` is not freed or added to during the call; `params` is `NULL` or
/// valid for reading an `mb_params`; `out` is `NULL` or valid for writing a
/// pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_query(
    scene: *const MbScene,
    params: *const MbParams,
    out: *mut *mut MbSceneResult,
) -> MbStatus {
    guard(|| {
        // SAFETY: `scene` is not freed or changed during the call, `params`
        // is NULL or readable (this function's contract).
        let (sc, p) = unsafe { (handle_ref(scene, "scene")?, read_in(params, "params")?) };
        let p = SceneParams::default().with_ca(self::params(p)?);
        let pairs = run(sc, &p)?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_handle(out, MbSceneResult { pairs }) }
    })
}

/// The number of pairs in `result`, written to `*out`.
///
/// **Thread safety**: any thread; `result` may be shared.
///
/// # Safety
/// `result` is not freed during the call; `out` is `NULL` or valid for
/// writing a `size_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_result_len(
    result: *const MbSceneResult,
    out: *mut usize,
) -> MbStatus {
    guard(|| {
        // SAFETY: `result` is not freed during the call (this function's contract).
        let r = unsafe { handle_ref(result, "result") }?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, r.pairs.len(), "out") }
    })
}

/// The `index`-th pair of `result` (in order of `a`, then `b`), written to
/// `*out`. `MB_STATUS_OUT_OF_RANGE` for `index` past the end.
///
/// **Thread safety**: any thread; `result` may be shared.
///
/// # Safety
/// `result` is not freed during the call; `out` is `NULL` or valid for
/// writing an `mb_scene_pair`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_result_get(
    result: *const MbSceneResult,
    index: usize,
    out: *mut MbScenePair,
) -> MbStatus {
    guard(|| {
        // SAFETY: `result` is not freed during the call (this function's contract).
        let r = unsafe { handle_ref(result, "result") }?;
        let pair = r.pairs.get(index).ok_or_else(|| {
            Failure::new(
                MbStatus::OutOfRange,
                format!(
                    "index {index} is past the end of a result of {} pairs",
                    r.pairs.len()
                ),
            )
        })?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, *pair, "out") }
    })
}

/// Frees a scene result (nothing for `NULL`).
///
/// **Thread safety**: no other thread may use `result` during or after the
/// call.
///
/// # Safety
/// As stated: `result` is not in use elsewhere.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_result_free(result: *mut MbSceneResult) -> MbStatus {
    // SAFETY: no other thread uses `result` (this function's contract).
    guard(|| unsafe { free_handle(result, "result") })
}

/// Frees a scene (nothing for `NULL`); its results stay valid.
///
/// **Thread safety**: no other thread may use `scene` during or after the
/// call.
///
/// # Safety
/// As stated: `scene` is not in use elsewhere.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_scene_free(scene: *mut MbScene) -> MbStatus {
    // SAFETY: no other thread uses `scene` (this function's contract).
    guard(|| unsafe { free_handle(scene, "scene") })
}
