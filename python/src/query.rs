//! Pair queries: `time_of_impact` and its batch form, and `past_contact`
//! for a pair touching at the start, with the GIL released while they run.

use motion_bound::ca::{
    past_contact as past, time_of_impact as toi, AnyPair, CaOutcome, CaParams, CaReport,
    MeshWorkspace, PastContact,
};
use motion_bound::RigidMotion;
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use rayon::prelude::*;
use std::time::Instant;

use crate::arrays::{floats, index, to_numpy};
use crate::body::Body;
use crate::errors::query;
use crate::motion::{Motion, MotionBatch};

/// The outcomes, by code (`BatchReport.outcome_codes`).
const OUTCOMES: [&str; 6] = [
    "contact",
    "initial_contact",
    "separated",
    "iteration_limit",
    "work_limit",
    "precision_limit",
];

/// One query's answer, flat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Flat {
    code: u8,
    time: f64,
    on_a: [f64; 3],
    on_b: [f64; 3],
    normal: [f64; 3],
    distance: f64,
    iterations: u32,
}

const NAN3: [f64; 3] = [f64::NAN; 3];

impl Flat {
    /// Every field equal, bit for bit, NaN (an absent field) equal to NaN.
    fn same(&self, other: &Self) -> bool {
        let (a, b) = (self, other);
        let same = |x: f64, y: f64| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
        let same3 = |x: [f64; 3], y: [f64; 3]| (0..3).all(|k| same(x[k], y[k]));
        a.code == b.code
            && same(a.time, b.time)
            && same3(a.on_a, b.on_a)
            && same3(a.on_b, b.on_b)
            && same3(a.normal, b.normal)
            && same(a.distance, b.distance)
            && a.iterations == b.iterations
    }

    pub(crate) fn of(report: &CaReport<f64>) -> Self {
        let mut f = Self {
            code: 2,
            time: f64::NAN,
            on_a: NAN3,
            on_b: NAN3,
            normal: NAN3,
            distance: f64::NAN,
            iterations: report.iterations,
        };
        let contact = match report.outcome {
            CaOutcome::Contact { contact, .. } => {
                f.code = 0;
                Some(contact)
            }
            CaOutcome::InitialContact(contact) => {
                f.code = 1;
                Some(contact)
            }
            CaOutcome::Separated => None,
            CaOutcome::IterationLimit { time } => {
                f.code = 3;
                f.time = time;
                None
            }
            CaOutcome::WorkLimit { time } => {
                f.code = 4;
                f.time = time;
                None
            }
            CaOutcome::PrecisionLimit { time, .. } => {
                f.code = 5;
                f.time = time;
                None
            }
            // A future outcome: reported as undecided from the start.
            _ => {
                f.code = 3;
                f.time = 0.0;
                None
            }
        };
        if let Some(c) = contact {
            f.time = c.time;
            if let Some(w) = c.witness {
                f.on_a = w.on_a.to_array();
                f.on_b = w.on_b.to_array();
                f.distance = w.distance;
            }
            if let Some(n) = c.normal {
                f.normal = n.to_array();
            }
        }
        f
    }
}

fn opt3(x: [f64; 3]) -> Option<[f64; 3]> {
    if x[0].is_nan() {
        None
    } else {
        Some(x)
    }
}

/// `x` as a `float64` numpy array of shape `(3,)`, or `None` (NaN: absent).
fn opt3_numpy<'py>(py: Python<'py>, x: [f64; 3]) -> PyResult<Option<Bound<'py, PyAny>>> {
    opt3(x).map(|v| to_numpy(py, v.to_vec(), &[3])).transpose()
}

/// An optional `(3,)` vector argument of `Report(...)`.
fn opt_vec3(obj: Option<&Bound<'_, PyAny>>, what: &str) -> PyResult<Option<[f64; 3]>> {
    match obj {
        Some(o) if !o.is_none() => Ok(Some(crate::arrays::vec3(o, what)?)),
        _ => Ok(None),
    }
}

/// One query's answer.
///
/// `outcome` is one of "contact" (first contact at `time`),
/// "initial_contact" (within the contact distance at `t = 0`), "separated"
/// (certified: no contact over the whole interval), or, when the query could
/// not decide, "iteration_limit", "work_limit" or "precision_limit" (no
/// contact before `time`, certified; treat it as a possible contact at
/// `time`). `hit` is true for every outcome but "separated". For a contact:
/// `point_a`, `point_b` (the closest points at `time`, world frame),
/// `normal` (unit, from A to B, when the points differ) and `distance`.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Clone, Debug)]
pub struct Report {
    pub(crate) flat: Flat,
}

#[pymethods]
impl Report {
    /// Rebuilds a report from its fields (what pickling does).
    #[new]
    #[pyo3(signature = (outcome, time, point_a, point_b, normal, distance, iterations))]
    fn py_new(
        outcome: &str,
        time: Option<f64>,
        point_a: Option<&Bound<'_, PyAny>>,
        point_b: Option<&Bound<'_, PyAny>>,
        normal: Option<&Bound<'_, PyAny>>,
        distance: Option<f64>,
        iterations: u32,
    ) -> PyResult<Self> {
        let point_a = opt_vec3(point_a, "point_a")?;
        let point_b = opt_vec3(point_b, "point_b")?;
        let normal = opt_vec3(normal, "normal")?;
        let code = OUTCOMES.iter().position(|o| *o == outcome).ok_or_else(|| {
            PyValueError::new_err(format!(
                "outcome: unknown outcome {outcome:?} (one of {})",
                OUTCOMES.join(", ")
            ))
        })?;
        Ok(Self {
            flat: Flat {
                code: code as u8,
                time: time.unwrap_or(f64::NAN),
                on_a: point_a.unwrap_or(NAN3),
                on_b: point_b.unwrap_or(NAN3),
                normal: normal.unwrap_or(NAN3),
                distance: distance.unwrap_or(f64::NAN),
                iterations,
            },
        })
    }

    /// What ended the query.
    #[getter]
    fn outcome(&self) -> &'static str {
        OUTCOMES[usize::from(self.flat.code)]
    }

    /// True unless the query certified that the bodies never touch.
    #[getter]
    fn hit(&self) -> bool {
        self.flat.code != 2
    }

    /// The contact's time, or the safe time reached when undecided; `None`
    /// when separated.
    #[getter]
    fn time(&self) -> Option<f64> {
        (!self.flat.time.is_nan()).then_some(self.flat.time)
    }

    /// The closest point on A at the contact (world frame; a `float64`
    /// array of shape `(3,)`, as a row of `BatchReport.points_a`), or `None`.
    #[getter]
    fn point_a<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        opt3_numpy(py, self.flat.on_a)
    }

    /// The closest point on B at the contact (world frame; a `float64`
    /// array of shape `(3,)`), or `None`.
    #[getter]
    fn point_b<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        opt3_numpy(py, self.flat.on_b)
    }

    /// The unit normal from A to B at the contact (a `float64` array of
    /// shape `(3,)`), or `None`.
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        opt3_numpy(py, self.flat.normal)
    }

    /// The distance between the witness points at the contact, or `None`.
    #[getter]
    fn distance(&self) -> Option<f64> {
        (!self.flat.distance.is_nan()).then_some(self.flat.distance)
    }

    /// Conservative-advancement iterations.
    #[getter]
    fn iterations(&self) -> u32 {
        self.flat.iterations
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let r = slf.get();
        let args = (
            r.outcome(),
            r.time(),
            opt3(r.flat.on_a),
            opt3(r.flat.on_b),
            opt3(r.flat.normal),
            r.distance(),
            r.iterations(),
        )
            .into_pyobject(py)?;
        PyTuple::new(py, [py.get_type::<Self>().into_any(), args.into_any()])
    }

    /// Equal when every field is, bit for bit (an absent field equals an absent one).
    fn __eq__(&self, other: &Self) -> bool {
        self.flat.same(&other.flat)
    }

    fn __repr__(&self) -> String {
        match self.time() {
            Some(t) => format!(
                "Report(outcome={:?}, time={t}, iterations={})",
                self.outcome(),
                self.flat.iterations
            ),
            None => format!(
                "Report(outcome={:?}, iterations={})",
                self.outcome(),
                self.flat.iterations
            ),
        }
    }
}

/// `max_iterations` as Python gave it: an int beyond `i64` is kept as its
/// text, so that [`params`] refuses it naming the argument (pyo3's own
/// conversion would raise a bare `OverflowError`); what is not an int is a
/// `TypeError` naming it.
pub(crate) struct Iterations(Result<i64, String>);

impl Iterations {
    /// The default iteration limit, 100 (the signatures' text says so).
    pub(crate) const DEFAULT: Self = Self(Ok(100));
}

impl<'a, 'py> FromPyObject<'a, 'py> for Iterations {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        match obj.extract::<i64>() {
            Ok(k) => Ok(Self(Ok(k))),
            Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => {
                Ok(Self(Err(obj.str()?.to_string())))
            }
            Err(_) => Err(PyTypeError::new_err(format!(
                "max_iterations must be an int (got {})",
                obj.get_type().name()?
            ))),
        }
    }
}

/// The query parameters from the keyword arguments, each checked here so
/// that an error names it as Python spells it.
pub(crate) fn params(
    contact_distance: f64,
    tolerance: f64,
    max_iterations: Iterations,
) -> PyResult<CaParams<f64>> {
    if !(contact_distance.is_finite() && contact_distance > 0.0) {
        return Err(crate::errors::QueryError::new_err(format!(
            "contact_distance must be positive and finite (got {contact_distance})"
        )));
    }
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(crate::errors::QueryError::new_err(format!(
            "tolerance must be finite and at least 0 (got {tolerance})"
        )));
    }
    let max_iterations = max_iterations
        .0
        .and_then(|k| {
            u32::try_from(k)
                .ok()
                .filter(|&k| k >= 1)
                .ok_or_else(|| k.to_string())
        })
        .map_err(|got| {
            crate::errors::QueryError::new_err(format!(
                "max_iterations must be an integer in 1..={} (got {got})",
                u32::MAX
            ))
        })?;
    let p = CaParams::default()
        .with_contact_distance(contact_distance)
        .with_time_tolerance(tolerance)
        .with_max_iterations(max_iterations);
    p.validate().map_err(query)?;
    Ok(p)
}

/// A pair query's refusal, naming what it is about: the two bodies' kinds
/// (`kinds`) for a pair no stepper takes or a turning half-space.
pub(crate) fn pair_error(e: motion_bound::ca::CaError, kinds: (&str, &str)) -> PyErr {
    use motion_bound::ca::CaError as E;
    match e {
        E::Unsupported => crate::errors::QueryError::new_err(format!(
            "no stepper takes the pair a={}, b={}: every pair of kinds is supported but two \
             half-spaces (a half_space meets a mesh, a convex shape or a compound; make one of \
             them a large box, say)",
            kinds.0, kinds.1
        )),
        E::TurnedHalfSpace => {
            let which = match kinds {
                ("half_space", "half_space") => "a and b",
                ("half_space", _) => "a",
                _ => "b",
            };
            crate::errors::QueryError::new_err(format!(
                "{which}: a half-space may only translate (no start orientation, no spin): give \
                 its normal in the world frame and a motion with the identity rotation and no \
                 angular velocity"
            ))
        }
        E::IntervalMismatch => crate::errors::QueryError::new_err(
            "the motions of a and b have different intervals (give them the same duration)",
        ),
        other => query(other),
    }
}

/// One pair query (the pair's stepper made for it, its workspace reused).
fn run(
    a: &motion_bound::ca::PreparedShape<'_, f64>,
    b: &motion_bound::ca::PreparedShape<'_, f64>,
    ma: &RigidMotion<f64>,
    mb: &RigidMotion<f64>,
    p: &CaParams<f64>,
    ws: &mut Option<MeshWorkspace<f64>>,
) -> Result<Flat, motion_bound::ca::CaError> {
    let mut pair =
        AnyPair::try_new(a.shape(), b.shape())?.with_workspace(ws.take().unwrap_or_default());
    let out = toi(&mut pair, ma, mb, p);
    *ws = Some(pair.into_workspace());
    Ok(Flat::of(&out?))
}

/// The first time of contact of body `a` moving by `motion_a` and body `b`
/// moving by `motion_b` (motions over the same interval), or a certified
/// "separated". Contact means a distance of at most `contact_distance`; the
/// reported time is never later than the first time the distance falls to
/// half of it (never later than touching), and a contact is never missed.
/// `tolerance` is the time tolerance, `max_iterations` the iteration limit.
/// The GIL is released while the query runs.
///
/// Raises `QueryError` for parameters out of range or motions over different
/// intervals, a turning half-space or two half-spaces.
#[pyfunction]
#[pyo3(
    signature = (a, motion_a, b, motion_b, contact_distance = 1e-4, tolerance = 1e-9, max_iterations = Iterations::DEFAULT),
    text_signature = "(a, motion_a, b, motion_b, contact_distance=1e-4, tolerance=1e-9, max_iterations=100)"
)]
#[allow(clippy::too_many_arguments)]
fn time_of_impact(
    py: Python<'_>,
    a: &Bound<'_, Body>,
    motion_a: &Bound<'_, Motion>,
    b: &Bound<'_, Body>,
    motion_b: &Bound<'_, Motion>,
    contact_distance: f64,
    tolerance: f64,
    max_iterations: Iterations,
) -> PyResult<Report> {
    let p = params(contact_distance, tolerance, max_iterations)?;
    let (ba, bb) = (a.get(), b.get());
    let (ma, mb) = (motion_a.get().motion, motion_b.get().motion);
    let flat = py.detach(|| -> PyResult<Flat> {
        let (pa, pb) = (ba.prepare()?, bb.prepare()?);
        run(&pa, &pb, &ma, &mb, &p, &mut None)
            .map_err(|e| pair_error(e, (ba.kind_name(), bb.kind_name())))
    })?;
    Ok(Report { flat })
}

/// For bodies within the contact distance at the start of their motions'
/// interval (`time_of_impact` answered "initial_contact"): whether body `a`
/// goes deeper into body `b` along `normal` (the report's `normal`, from A to
/// B; any nonzero vector is sound) over the interval, certified, with one
/// cast against the half-space just past the plane that separates them at
/// the start, carried along by B's translation (`proofs/12-shapes.md`,
/// Lemma 12.11). Until the answer's time, A's extent along `normal` beyond
/// B's least grows by less than `contact_distance`: a body sliding along a
/// surface it rests on costs one cheap cast instead of a full query with a
/// smaller contact distance. B must not rotate, or A must not (the roles
/// then swap).
///
/// Returns `(outcome, time)`: `("never", None)` (certified: A slides along
/// B or leaves it), `("at", t)` (it may from `t` on, never later than the
/// first time it does; `0.0` when A already reaches more than the contact
/// distance past B along `normal`), or `("undecided", None)` (both bodies
/// rotate, a body is a half-space, or a value overflowed: ask
/// `time_of_impact` again with a smaller contact distance, or hold the
/// body). The GIL is released while it runs.
///
/// Raises `InputError` for a zero or non-finite `normal`, `QueryError` for
/// parameters out of range or motions over different intervals.
#[pyfunction]
#[pyo3(
    signature = (a, motion_a, b, motion_b, normal, contact_distance = 1e-4, tolerance = 1e-9, max_iterations = Iterations::DEFAULT),
    text_signature = "(a, motion_a, b, motion_b, normal, contact_distance=1e-4, tolerance=1e-9, max_iterations=100)"
)]
#[allow(clippy::too_many_arguments)]
fn past_contact(
    py: Python<'_>,
    a: &Bound<'_, Body>,
    motion_a: &Bound<'_, Motion>,
    b: &Bound<'_, Body>,
    motion_b: &Bound<'_, Motion>,
    normal: &Bound<'_, PyAny>,
    contact_distance: f64,
    tolerance: f64,
    max_iterations: Iterations,
) -> PyResult<(&'static str, Option<f64>)> {
    let p = params(contact_distance, tolerance, max_iterations)?;
    let n = motion_bound::Vec3::from_array(crate::arrays::vec3(normal, "normal")?);
    let (ba, bb) = (a.get(), b.get());
    let (ma, mb) = (motion_a.get().motion, motion_b.get().motion);
    let answer = py.detach(|| -> PyResult<PastContact<f64>> {
        let (pa, pb) = (ba.prepare()?, bb.prepare()?);
        past(pa.shape(), &ma, pb.shape(), &mb, n, &p).map_err(|e| match e {
            motion_bound::ca::CaError::Input(e) => crate::errors::input_in("normal")(e),
            e => pair_error(e, (ba.kind_name(), bb.kind_name())),
        })
    })?;
    Ok(match answer {
        PastContact::Never => ("never", None),
        PastContact::At(t) => ("at", Some(t)),
        _ => ("undecided", None),
    })
}

/// Motions for a batch: one for every query, or one shared.
enum Many<'a> {
    One(&'a RigidMotion<f64>),
    Each(&'a [RigidMotion<f64>]),
}

impl<'a> Many<'a> {
    /// A `Motion` or a `MotionBatch`, borrowed (both are frozen).
    fn of(obj: &'a Bound<'_, PyAny>, what: &str) -> PyResult<Self> {
        if let Ok(m) = obj.cast::<Motion>() {
            return Ok(Self::One(&m.get().motion));
        }
        if let Ok(b) = obj.cast::<MotionBatch>() {
            return Ok(Self::Each(&b.get().motions));
        }
        Err(PyTypeError::new_err(format!(
            "{what} must be a Motion or a MotionBatch"
        )))
    }

    fn get(&self, i: usize) -> &RigidMotion<f64> {
        match self {
            Self::One(m) => m,
            Self::Each(v) => &v[i],
        }
    }

    fn len(&self) -> Option<usize> {
        match self {
            Self::One(_) => None,
            Self::Each(v) => Some(v.len()),
        }
    }
}

/// The wall time one chunk of a batch aims at: between chunks the calling
/// thread takes the GIL back, runs Python's signal handlers (Ctrl-C) and the
/// progress callback, so a chunk must be well under the tenth of a second in
/// which Ctrl-C is to be honoured, and long enough that the pause (a few
/// microseconds) and rayon's idle tail at the end of a chunk cost nothing.
const CHUNK_SECONDS: f64 = 0.02;

/// The next chunk's length from the last one's: as many queries as fit in
/// `CHUNK_SECONDS` at the last chunk's pace, at most four times the last
/// length (the next queries may be slower), at least one query per thread.
pub(crate) fn next_chunk(last: usize, seconds: f64, threads: usize) -> usize {
    let per_query = seconds / last as f64;
    let fit = if per_query > 0.0 {
        (CHUNK_SECONDS / per_query).min(usize::MAX as f64) as usize
    } else {
        usize::MAX
    };
    fit.min(last.saturating_mul(4)).max(threads)
}

/// Many queries of the same two bodies: `motions_a` and `motions_b` are each
/// a `MotionBatch` (one motion per query, the same length) or a `Motion`
/// (the same for every query). Runs on every core (rayon) with the GIL
/// released; answers as a `BatchReport`, in query order, the same as one
/// `time_of_impact` per query.
///
/// The batch runs in chunks of about 20 ms; between chunks the calling
/// thread checks for Ctrl-C (a `KeyboardInterrupt` is raised within a tenth
/// of a second, the answers so far dropped) and calls `progress(done,
/// total)` when given (with the GIL, from the calling thread; counts
/// increase and end at `total`; an exception it raises stops the batch).
#[pyfunction]
#[pyo3(
    signature = (a, motions_a, b, motions_b, contact_distance = 1e-4, tolerance = 1e-9, max_iterations = Iterations::DEFAULT, parallel = true, progress = None),
    text_signature = "(a, motions_a, b, motions_b, contact_distance=1e-4, tolerance=1e-9, max_iterations=100, parallel=True, progress=None)"
)]
#[allow(clippy::too_many_arguments)]
fn time_of_impact_batch(
    py: Python<'_>,
    a: &Bound<'_, Body>,
    motions_a: &Bound<'_, PyAny>,
    b: &Bound<'_, Body>,
    motions_b: &Bound<'_, PyAny>,
    contact_distance: f64,
    tolerance: f64,
    max_iterations: Iterations,
    parallel: bool,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<BatchReport> {
    let p = params(contact_distance, tolerance, max_iterations)?;
    let ma = Many::of(motions_a, "motions_a")?;
    let mb = Many::of(motions_b, "motions_b")?;
    if let Some(cb) = progress {
        if !cb.is_callable() {
            return Err(PyTypeError::new_err(
                "progress must be callable as progress(done, total)",
            ));
        }
    }
    let n = match (ma.len(), mb.len()) {
        (Some(x), Some(y)) if x != y => {
            return Err(PyValueError::new_err(format!(
                "motions_a has {x} motions but motions_b has {y}"
            )))
        }
        (Some(x), _) | (None, Some(x)) => x,
        (None, None) => 1,
    };
    let (ba, bb) = (a.get(), b.get());
    let (pa, pb) = py.detach(|| -> PyResult<_> { Ok((ba.prepare()?, bb.prepare()?)) })?;
    let threads = if parallel {
        rayon::current_num_threads()
    } else {
        1
    };
    let mut flats: Vec<Flat> = Vec::with_capacity(n);
    // The serial batch's workspace lives across chunks, as it did when the
    // batch was one loop.
    let mut serial_ws = None;
    let mut chunk = threads;
    while flats.len() < n {
        let (lo, hi) = (flats.len(), (flats.len() + chunk).min(n));
        let clock = Instant::now();
        py.detach(|| -> PyResult<()> {
            let one = |ws: &mut Option<MeshWorkspace<f64>>, i: usize| {
                run(&pa, &pb, ma.get(i), mb.get(i), &p, ws)
            };
            if parallel {
                let out: Result<Vec<Flat>, _> =
                    (lo..hi).into_par_iter().map_init(|| None, one).collect();
                flats.extend(out.map_err(|e| pair_error(e, (ba.kind_name(), bb.kind_name())))?);
            } else {
                for i in lo..hi {
                    flats.push(
                        one(&mut serial_ws, i)
                            .map_err(|e| pair_error(e, (ba.kind_name(), bb.kind_name())))?,
                    );
                }
            }
            Ok(())
        })?;
        chunk = next_chunk(hi - lo, clock.elapsed().as_secs_f64(), threads);
        py.check_signals()?;
        if let Some(cb) = progress {
            cb.call1((hi, n))?;
        }
    }
    Ok(BatchReport { flats })
}

/// The answers of a batch, as arrays (one entry per query): `outcome_codes`
/// (`uint8`, indices into `BatchReport.OUTCOMES`), `times` (NaN when
/// separated), `points_a`, `points_b`, `normals` (`(n, 3)`, NaN rows when
/// none), `distances`, `iterations`; `hits` (bool). `len(r)`, `r[i]` (a
/// `Report`); it pickles.
#[pyclass(frozen, module = "motion_bound")]
#[derive(Debug)]
pub struct BatchReport {
    flats: Vec<Flat>,
}

#[pymethods]
impl BatchReport {
    /// The outcome names, by code.
    #[classattr]
    #[allow(non_snake_case)]
    fn OUTCOMES() -> Vec<&'static str> {
        OUTCOMES.to_vec()
    }

    /// Rebuilds a batch report from its arrays (what pickling does).
    #[new]
    fn py_new(
        outcome_codes: &Bound<'_, PyAny>,
        times: &Bound<'_, PyAny>,
        points_a: &Bound<'_, PyAny>,
        points_b: &Bound<'_, PyAny>,
        normals: &Bound<'_, PyAny>,
        distances: &Bound<'_, PyAny>,
        iterations: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let (codes, _) = floats(outcome_codes, "outcome_codes")?;
        let (t, _) = floats(times, "times")?;
        let pa = crate::arrays::rows3(points_a, "points_a")?;
        let pb = crate::arrays::rows3(points_b, "points_b")?;
        let nm = crate::arrays::rows3(normals, "normals")?;
        let (d, _) = floats(distances, "distances")?;
        let (it, _) = floats(iterations, "iterations")?;
        let n = codes.len();
        if let Some((i, bad)) = codes
            .iter()
            .enumerate()
            .find(|(_, &c)| !(c >= 0.0 && c < OUTCOMES.len() as f64 && c.fract() == 0.0))
        {
            return Err(PyValueError::new_err(format!(
                "outcome_codes[{i}]: outcome code {bad} is not one of 0..{}",
                OUTCOMES.len()
            )));
        }
        if let Some((i, bad)) = it
            .iter()
            .enumerate()
            .find(|(_, &k)| !(k >= 0.0 && k <= f64::from(u32::MAX) && k.fract() == 0.0))
        {
            return Err(PyValueError::new_err(format!(
                "iterations[{i}]: iteration count {bad} is not a u32"
            )));
        }
        if [t.len(), pa.len(), pb.len(), nm.len(), d.len(), it.len()]
            .iter()
            .any(|&k| k != n)
        {
            return Err(PyValueError::new_err(format!(
                "times, points_a, points_b, normals, distances, iterations: each must have one \
                 entry per query, as outcome_codes ({n})"
            )));
        }
        let flats = (0..n)
            .map(|i| Flat {
                code: codes[i] as u8,
                time: t[i],
                on_a: pa[i],
                on_b: pb[i],
                normal: nm[i],
                distance: d[i],
                iterations: it[i] as u32,
            })
            .collect();
        Ok(Self { flats })
    }

    fn __len__(&self) -> usize {
        self.flats.len()
    }

    fn __getitem__(&self, i: isize) -> PyResult<Report> {
        Ok(Report {
            flat: self.flats[index(i, self.flats.len(), "query")?],
        })
    }

    /// The outcome of each query as its code (`uint8`).
    #[getter]
    fn outcome_codes<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let v: Vec<u8> = self.flats.iter().map(|f| f.code).collect();
        numpy::PyArray1::from_vec(py, v).into_any()
    }

    /// True where the query did not certify separation.
    #[getter]
    fn hits<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let v: Vec<bool> = self.flats.iter().map(|f| f.code != 2).collect();
        numpy::PyArray1::from_vec(py, v).into_any()
    }

    /// Contact times (or the safe time reached when undecided); NaN when
    /// separated.
    #[getter]
    fn times<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_numpy(
            py,
            self.flats.iter().map(|f| f.time).collect(),
            &[self.flats.len()],
        )
    }

    /// Witness points on A, `(n, 3)`.
    #[getter]
    fn points_a<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = self.flats.iter().flat_map(|f| f.on_a).collect();
        to_numpy(py, v, &[self.flats.len(), 3])
    }

    /// Witness points on B, `(n, 3)`.
    #[getter]
    fn points_b<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = self.flats.iter().flat_map(|f| f.on_b).collect();
        to_numpy(py, v, &[self.flats.len(), 3])
    }

    /// Normals from A to B, `(n, 3)`.
    #[getter]
    fn normals<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = self.flats.iter().flat_map(|f| f.normal).collect();
        to_numpy(py, v, &[self.flats.len(), 3])
    }

    /// Witness distances.
    #[getter]
    fn distances<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_numpy(
            py,
            self.flats.iter().map(|f| f.distance).collect(),
            &[self.flats.len()],
        )
    }

    /// Iterations of each query.
    #[getter]
    fn iterations<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let v: Vec<u32> = self.flats.iter().map(|f| f.iterations).collect();
        numpy::PyArray1::from_vec(py, v).into_any()
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let r = slf.get();
        let args = PyTuple::new(
            py,
            [
                r.outcome_codes(py),
                r.times(py)?,
                r.points_a(py)?,
                r.points_b(py)?,
                r.normals(py)?,
                r.distances(py)?,
                r.iterations(py),
            ],
        )?;
        PyTuple::new(py, [py.get_type::<Self>().into_any(), args.into_any()])
    }

    /// Equal when they hold as many queries and every query's report is equal (as `Report`).
    fn __eq__(&self, other: &Self) -> bool {
        self.flats.len() == other.flats.len()
            && self.flats.iter().zip(&other.flats).all(|(a, b)| a.same(b))
    }

    fn __repr__(&self) -> String {
        let hits = self.flats.iter().filter(|f| f.code != 2).count();
        format!("BatchReport({} queries, {hits} hits)", self.flats.len())
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Report>()?;
    m.add_class::<BatchReport>()?;
    m.add_function(wrap_pyfunction!(time_of_impact, m)?)?;
    m.add_function(wrap_pyfunction!(time_of_impact_batch, m)?)?;
    m.add_function(wrap_pyfunction!(past_contact, m)?)?;
    Ok(())
}
