//! The pair query: parameters, report, `mb_time_of_impact`.

use motion_bound::ca::{
    past_contact, time_of_impact, AnyPair, BoundChoice, CaError, CaOutcome, CaParams, CaReport,
    ContactCriterion, MeshWorkspace, OwnedShape, PastContact, WitnessSearch, Work,
};
use motion_bound::{RigidMotion, Vec3};
use rayon::prelude::*;

use crate::error::{guard, Failure, MbStatus, Res};
use crate::motion::{MbMotion, MbVec3};
use crate::ptr::{handle_ref, read_in, slice_from, write_out, write_slice, Plain};
use crate::shape::MbShape;

/// Which directed bound a query uses (`mb_params.bound`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbBound {
    /// EVQ wherever it costs `O(1)`; on a convex hull, NEVQ first and EVQ
    /// only when NEVQ's step would not end the query (the default).
    Auto = 0,
    /// NEVQ everywhere: cheapest, loosest.
    Nevq = 1,
    /// EVQ everywhere: tightest.
    Evq = 2,
}

/// Which pair within the contact distance a mesh contact reports as its
/// witness (`mb_params.witness`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbWitnessSearch {
    /// The closest triangle pair at the contact time (the default).
    Closest = 0,
    /// The first pair found within the contact distance (less work).
    First = 1,
}

/// The parameters of a query, a plain struct: start from
/// `mb_params_default` and change fields. Checked by each query
/// (`MB_STATUS_INVALID_PARAMETER` when out of range).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbParams {
    /// Contact is declared when the distance is at most this (positive and
    /// finite, in the scene's length unit). Default `1e-4`: set it for your
    /// scale.
    pub contact_distance: f64,
    /// A step at most this long (well before the end) ends the query with a
    /// contact by time tolerance (finite, at least `0`). Default `1e-9`.
    pub time_tolerance: f64,
    /// The factor by which each step's horizon grows (`0`, or above `1`).
    /// Default `2`.
    pub horizon_factor: f64,
    /// The most node pairs of a mesh traversal per query (default 50,000;
    /// `UINT64_MAX` for no limit).
    pub work_budget_node_pairs: u64,
    /// The most triangle pairs of a mesh traversal per query (default
    /// 10,000; `UINT64_MAX` for no limit).
    pub work_budget_triangle_pairs: u64,
    /// The most iterations for bodies that do not turn (at least `1`).
    /// Default `100`.
    pub max_iterations: u32,
    /// Iterations added per full turn the two bodies make. Default `16`.
    pub iterations_per_turn: u32,
    /// An `mb_bound` value. Default `MB_BOUND_AUTO`.
    pub bound: u32,
    /// An `mb_witness_search` value. Default `MB_WITNESS_SEARCH_CLOSEST`.
    pub witness: u32,
    /// Nonzero: bound the closing rate with one-sided bounds (never looser).
    /// Default `1`.
    pub one_sided: u32,
}

// SAFETY: a `repr(C)` struct of `f64`, `u64` and `u32` fields (and padding):
// every bit pattern of the fields is a value.
unsafe impl Plain for MbParams {}

/// What ended a query (`mb_report.outcome`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbOutcome {
    /// Contact at `time` (never later than the first time the surfaces
    /// touch).
    Contact = 0,
    /// Already within the contact distance at the start (or one body starts
    /// inside the other's solid mesh); `time` is the start.
    InitialContact = 1,
    /// No contact over the whole interval (certified).
    Separated = 2,
    /// Undecided from `time` on (the iteration limit); no contact before
    /// `time`. Treat as a possible contact at `time`.
    IterationLimit = 3,
    /// Undecided from `time` on (the work budget ran out); no contact
    /// before `time`. Treat as a possible contact at `time`.
    WorkLimit = 4,
    /// Undecided from `time` on (the contact distance is below what the
    /// placement resolves: see `resolution`); no contact before `time`.
    /// Treat as a possible contact at `time`.
    PrecisionLimit = 5,
}

/// Which tolerance declared a contact (`mb_report.criterion`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbCriterion {
    /// No contact, or an initial contact.
    None = 0,
    /// The distance fell to the contact distance.
    Distance = 1,
    /// The certified steps stalled (a very fast or grazing approach): no
    /// contact before `time`, and a contact may follow.
    TimeTolerance = 2,
}

/// A query's answer. Fields that do not apply are NaN (`time` when
/// separated; the witnesses, normal and distance when no closest points were
/// measured; `resolution` except for a precision limit).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbReport {
    /// What ended the query.
    pub outcome: MbOutcome,
    /// Which tolerance declared a contact.
    pub criterion: MbCriterion,
    /// The contact time, or the safe time an undecided query reached; NaN
    /// when separated.
    pub time: f64,
    /// The witness point on body A at `time` (world frame).
    pub witness_a: MbVec3,
    /// The witness point on body B at `time` (world frame).
    pub witness_b: MbVec3,
    /// The unit contact normal from A to B at `time`.
    pub normal: MbVec3,
    /// The distance between the witnesses.
    pub distance: f64,
    /// For a precision limit, the length the placement cannot resolve.
    pub resolution: f64,
    /// Node pairs a mesh traversal worked on.
    pub node_pairs: u64,
    /// Triangle pairs whose exact distance was computed.
    pub triangle_pairs: u64,
    /// Iterations used (at least one).
    pub iterations: u32,
}

const NAN3: MbVec3 = MbVec3 {
    x: f64::NAN,
    y: f64::NAN,
    z: f64::NAN,
};

impl MbReport {
    pub(crate) fn of(report: &CaReport<f64>) -> Self {
        let mut r = Self {
            outcome: MbOutcome::Separated,
            criterion: MbCriterion::None,
            time: f64::NAN,
            witness_a: NAN3,
            witness_b: NAN3,
            normal: NAN3,
            distance: f64::NAN,
            resolution: f64::NAN,
            node_pairs: report.work.node_pairs,
            triangle_pairs: report.work.triangle_pairs,
            iterations: report.iterations,
        };
        let contact = match report.outcome {
            CaOutcome::Contact { contact, criterion } => {
                r.outcome = MbOutcome::Contact;
                r.criterion = match criterion {
                    ContactCriterion::Distance => MbCriterion::Distance,
                    _ => MbCriterion::TimeTolerance,
                };
                Some(contact)
            }
            CaOutcome::InitialContact(contact) => {
                r.outcome = MbOutcome::InitialContact;
                Some(contact)
            }
            CaOutcome::Separated => None,
            CaOutcome::WorkLimit { time } => {
                r.outcome = MbOutcome::WorkLimit;
                r.time = time;
                None
            }
            CaOutcome::PrecisionLimit { time, resolution } => {
                r.outcome = MbOutcome::PrecisionLimit;
                r.time = time;
                r.resolution = resolution;
                None
            }
            // The iteration limit, and any future undecided outcome.
            other => {
                r.outcome = MbOutcome::IterationLimit;
                r.time = other.earliest_possible_contact().unwrap_or(0.0);
                None
            }
        };
        if let Some(c) = contact {
            r.time = c.time;
            if let Some(w) = c.witness {
                r.witness_a = MbVec3::from_array(w.on_a.to_array());
                r.witness_b = MbVec3::from_array(w.on_b.to_array());
                r.distance = w.distance;
            }
            if let Some(n) = c.normal {
                r.normal = MbVec3::from_array(n.to_array());
            }
        }
        r
    }
}

/// The default parameters (those of the Rust crate's `CaParams::default`).
///
/// **Thread safety**: any thread.
#[unsafe(no_mangle)]
pub extern "C" fn mb_params_default() -> MbParams {
    let d = CaParams::<f64>::default();
    MbParams {
        contact_distance: d.contact_distance,
        time_tolerance: d.time_tolerance,
        horizon_factor: d.horizon_factor,
        work_budget_node_pairs: d.work_budget.node_pairs,
        work_budget_triangle_pairs: d.work_budget.triangle_pairs,
        max_iterations: d.max_iterations,
        iterations_per_turn: d.iterations_per_turn,
        bound: MbBound::Auto as u32,
        witness: MbWitnessSearch::Closest as u32,
        one_sided: u32::from(d.one_sided),
    }
}

/// A pair query's refusal, naming the arguments it is about; `at` goes
/// before each name (`""`, or `"queries[3]."` in a batch).
pub(crate) fn pair_failure(e: CaError, at: &str) -> Failure {
    let (status, args) = match e {
        CaError::InvalidParameter(_) => (MbStatus::InvalidParameter, "params".to_owned()),
        CaError::Unsupported => (MbStatus::QueryError, format!("{at}shape_a, {at}shape_b")),
        CaError::Input(_) => (
            MbStatus::InvalidInput,
            format!("{at}shape_a, {at}motion_a, {at}shape_b, {at}motion_b"),
        ),
        _ => (MbStatus::QueryError, format!("{at}motion_a, {at}motion_b")),
    };
    let hint = if matches!(e, CaError::Unsupported) {
        " (two half-spaces)"
    } else {
        ""
    };
    Failure::new(status, format!("{args}: {e}{hint}"))
}

fn bad(what: &str) -> Failure {
    Failure::new(MbStatus::InvalidParameter, what)
}

/// The crate's parameters of `p` (the defaults for `None`), checked.
pub(crate) fn params(p: Option<MbParams>) -> Res<CaParams<f64>> {
    let Some(p) = p else {
        return Ok(CaParams::default());
    };
    let mut c = CaParams::<f64>::default()
        .with_contact_distance(p.contact_distance)
        .with_time_tolerance(p.time_tolerance)
        .with_max_iterations(p.max_iterations)
        .with_iterations_per_turn(p.iterations_per_turn)
        .with_work_budget(Work::new(
            p.work_budget_node_pairs,
            p.work_budget_triangle_pairs,
        ))
        .with_witness(match p.witness {
            0 => WitnessSearch::Closest,
            1 => WitnessSearch::First,
            w => {
                return Err(bad(&format!(
                    "params.witness is {w}: 0 (closest) or 1 (first)"
                )))
            }
        })
        .with_bound(match p.bound {
            0 => BoundChoice::Auto,
            1 => BoundChoice::Nevq,
            2 => BoundChoice::Evq,
            b => {
                return Err(bad(&format!(
                    "params.bound is {b}: 0 (auto), 1 (NEVQ) or 2 (EVQ)"
                )))
            }
        });
    c.horizon_factor = p.horizon_factor;
    c.one_sided = p.one_sided != 0;
    c.validate()
        .map_err(|e| Failure::new(MbStatus::InvalidParameter, format!("params: {e}")))?;
    Ok(c)
}

/// One pair query, its mesh workspace taken from and left in `ws`.
pub(crate) fn one(
    a: &OwnedShape<f64>,
    ma: &RigidMotion<f64>,
    b: &OwnedShape<f64>,
    mb: &RigidMotion<f64>,
    p: &CaParams<f64>,
    ws: &mut Option<MeshWorkspace<f64>>,
) -> Result<MbReport, CaError> {
    let (pa, pb) = (a.prepare()?, b.prepare()?);
    let pair = AnyPair::try_new(pa.shape(), pb.shape())?;
    let mut pair = pair.with_workspace(ws.take().unwrap_or_default());
    let report = time_of_impact(&mut pair, ma, mb, p);
    *ws = Some(pair.into_workspace());
    Ok(MbReport::of(&report?))
}

/// The first time bodies of shapes `shape_a` and `shape_b`, moving by
/// `motion_a` and `motion_b` (over the same interval), come within the
/// contact distance, certified: the report's time is never later than the
/// first time they touch under the exact motions. `params` may be `NULL`
/// for the defaults. Every pair of shape kinds is taken (two half-spaces
/// excepted: `MB_STATUS_QUERY_ERROR`). The report is written to `*out`.
///
/// `MB_STATUS_NULL_POINTER` / `MB_STATUS_INVALID_HANDLE` for a bad handle,
/// `MB_STATUS_INVALID_PARAMETER` for parameters out of range,
/// `MB_STATUS_QUERY_ERROR` for motions over different intervals or a
/// turning half-space.
///
/// **Thread safety**: any thread; the shapes, motions and params may be
/// shared by concurrent queries (each query has its own scratch space).
///
/// # Safety
/// The handles are not freed during the call; `params` is `NULL` or valid
/// for reading an `mb_params`; `out` is `NULL` or valid for writing an
/// `mb_report`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_time_of_impact(
    shape_a: *const MbShape,
    motion_a: *const MbMotion,
    shape_b: *const MbShape,
    motion_b: *const MbMotion,
    params: *const MbParams,
    out: *mut MbReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: the handles are not freed during the call, and `params` is
        // NULL or readable (this function's contract).
        let (sa, ma, sb, mb, p) = unsafe {
            (
                handle_ref(shape_a, "shape_a")?,
                handle_ref(motion_a, "motion_a")?,
                handle_ref(shape_b, "shape_b")?,
                handle_ref(motion_b, "motion_b")?,
                read_in(params, "params")?,
            )
        };
        let p = self::params(p)?;
        let report = one(&sa.data, &ma.motion, &sb.data, &mb.motion, &p, &mut None)
            .map_err(|e| pair_failure(e, ""))?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, report, "out") }
    })
}

/// One query of a batch (`mb_time_of_impact_batch`): two shapes and their
/// motions, as `mb_time_of_impact` takes them.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct MbPairQuery {
    /// The first body's shape.
    pub shape_a: *const MbShape,
    /// The first body's motion.
    pub motion_a: *const MbMotion,
    /// The second body's shape.
    pub shape_b: *const MbShape,
    /// The second body's motion (over the same interval).
    pub motion_b: *const MbMotion,
}

// SAFETY: a `repr(C)` struct of raw pointers: every bit pattern is a value
// (each pointer is checked before use).
unsafe impl Plain for MbPairQuery {}

/// Many pair queries on every core: `queries[k]` answered in `out[k]` for
/// `k < count`, each exactly as `mb_time_of_impact` answers it (the same
/// report, bit for bit), with one `params` for all (`NULL` for the
/// defaults). The queries run on a pool of one thread per core (rayon's
/// global pool: `RAYON_NUM_THREADS` sets its size); the call returns when
/// all are done. `count == 0` does nothing.
///
/// Errors as `mb_time_of_impact`, the message naming the query
/// (`queries[3].shape_a is NULL`); on any error nothing is written to `out`
/// (the first failing query, by index, is the one reported).
///
/// **Thread safety**: any thread; the handles may be shared between
/// queries and with other threads' queries.
///
/// # Safety
/// `queries` is `NULL` or valid for reading `count` queries, whose handles
/// are not freed during the call; `params` is `NULL` or valid for reading
/// an `mb_params`; `out` is `NULL` or valid for writing `count` reports.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_time_of_impact_batch(
    queries: *const MbPairQuery,
    count: usize,
    params: *const MbParams,
    out: *mut MbReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: `queries` is NULL or holds `count` queries, `params` is
        // NULL or readable (this function's contract).
        let (qs, p) = unsafe {
            (
                slice_from(queries, count, "queries")?,
                read_in(params, "params")?,
            )
        };
        let p = self::params(p)?;
        let mut bodies = Vec::with_capacity(count);
        for (k, q) in qs.iter().enumerate() {
            let name = |arg: &str| format!("queries[{k}].{arg}");
            // SAFETY: the handles are not freed during the call (this
            // function's contract).
            bodies.push(unsafe {
                (
                    &*handle_ref(q.shape_a, &name("shape_a"))?.data,
                    &handle_ref(q.motion_a, &name("motion_a"))?.motion,
                    &*handle_ref(q.shape_b, &name("shape_b"))?.data,
                    &handle_ref(q.motion_b, &name("motion_b"))?.motion,
                )
            });
        }
        let answers: Vec<Result<MbReport, CaError>> = bodies
            .par_iter()
            .map_init(|| None, |ws, (a, ma, b, mb)| one(a, ma, b, mb, &p, ws))
            .collect();
        let mut reports = Vec::with_capacity(count);
        for (k, answer) in answers.into_iter().enumerate() {
            reports.push(answer.map_err(|e| pair_failure(e, &format!("queries[{k}].")))?);
        }
        // SAFETY: `out` is NULL or writable for `count` reports (this
        // function's contract).
        unsafe { write_slice(out, &reports, "out") }
    })
}

/// What `mb_past_contact` found (`mb_past_report.outcome`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MbPastOutcome {
    /// Body A's extent along the normal, beyond body B's least, never grows
    /// by the contact distance over the interval (certified: it slides along
    /// B or leaves it).
    Never = 0,
    /// It may from `time` on (never later than the first time it does; the
    /// interval's start when A already reaches more than the contact
    /// distance past B along the normal).
    At = 1,
    /// Not decided (both bodies rotate, a body is a half-space, or a value
    /// overflowed): ask `mb_time_of_impact` again or hold the body.
    Undecided = 2,
}

/// `mb_past_contact`'s answer.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbPastReport {
    /// Never, from `time` on, or undecided.
    pub outcome: MbPastOutcome,
    /// For `MB_PAST_OUTCOME_AT`, the time; NaN otherwise.
    pub time: f64,
}

/// For bodies within the contact distance at the start of their motions'
/// interval (`mb_time_of_impact` answered `MB_OUTCOME_INITIAL_CONTACT`):
/// whether body A goes deeper into body B along `normal` (the report's
/// `normal`, from A to B; any nonzero vector is sound) over the interval,
/// certified, with one cast against the half-space just past the plane that
/// separates them at the start, carried along by B's translation (Rust
/// crate: `ca::past_contact`; `proofs/12-shapes.md`, Lemma 12.11). Until
/// the answer's time, A's extent along `normal` beyond B's least grows by
/// less than the contact distance. A body sliding along a surface it rests
/// on costs one cheap cast instead of a full query with a smaller contact
/// distance. B must not rotate, or A must not (the roles then swap).
/// `params` may be `NULL` for the defaults. The answer is written to `*out`.
///
/// `MB_STATUS_NULL_POINTER` / `MB_STATUS_INVALID_HANDLE` for a bad handle,
/// `MB_STATUS_INVALID_INPUT` for a zero or non-finite `normal`,
/// `MB_STATUS_INVALID_PARAMETER` for parameters out of range,
/// `MB_STATUS_QUERY_ERROR` for motions over different intervals.
///
/// **Thread safety**: any thread; the shapes, motions and params may be
/// shared by concurrent calls.
///
/// # Safety
/// The handles are not freed during the call; `params` is `NULL` or valid
/// for reading an `mb_params`; `out` is `NULL` or valid for writing an
/// `mb_past_report`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn mb_past_contact(
    shape_a: *const MbShape,
    motion_a: *const MbMotion,
    shape_b: *const MbShape,
    motion_b: *const MbMotion,
    normal: MbVec3,
    params: *const MbParams,
    out: *mut MbPastReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: the handles are not freed during the call, and `params` is
        // NULL or readable (this function's contract).
        let (sa, ma, sb, mb, p) = unsafe {
            (
                handle_ref(shape_a, "shape_a")?,
                handle_ref(motion_a, "motion_a")?,
                handle_ref(shape_b, "shape_b")?,
                handle_ref(motion_b, "motion_b")?,
                read_in(params, "params")?,
            )
        };
        let answer = touching_rule(
            (&sa.data, &ma.motion, &sb.data, &mb.motion),
            normal,
            p,
            past_contact,
        )?;
        let report = match answer {
            PastContact::Never => MbPastReport {
                outcome: MbPastOutcome::Never,
                time: f64::NAN,
            },
            PastContact::At(t) => MbPastReport {
                outcome: MbPastOutcome::At,
                time: t,
            },
            _ => MbPastReport {
                outcome: MbPastOutcome::Undecided,
                time: f64::NAN,
            },
        };
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, report, "out") }
    })
}

/// What `mb_past_contact` and `mb_past_contact_below` share once their
/// handles are read: the normal checked (zero or non-finite: named), the
/// parameters, both shapes prepared, and `rule` run with its error named.
pub(crate) fn touching_rule<R>(
    (sa, ma, sb, mb): (
        &OwnedShape<f64>,
        &RigidMotion<f64>,
        &OwnedShape<f64>,
        &RigidMotion<f64>,
    ),
    normal: MbVec3,
    p: Option<MbParams>,
    rule: impl FnOnce(
        motion_bound::ca::Shape<'_, f64>,
        &RigidMotion<f64>,
        motion_bound::ca::Shape<'_, f64>,
        &RigidMotion<f64>,
        Vec3<f64>,
        &CaParams<f64>,
    ) -> Result<R, CaError>,
) -> Res<R> {
    let n = normal.checked("normal")?;
    if n == Vec3::ZERO {
        return Err(Failure::new(
            MbStatus::InvalidInput,
            "normal: the zero vector (give the contact normal from A to B)",
        ));
    }
    let p = self::params(p)?;
    let (pa, pb) = (sa.prepare(), sb.prepare());
    let (pa, pb) = (
        pa.map_err(|e| pair_failure(e.into(), ""))?,
        pb.map_err(|e| pair_failure(e.into(), ""))?,
    );
    rule(pa.shape(), ma, pb.shape(), mb, n, &p).map_err(|e| match e {
        CaError::Input(e) => Failure::new(MbStatus::InvalidInput, format!("normal: {e}")),
        e => pair_failure(e, ""),
    })
}

/// A pair's ceiling (`mb_past_contact_below`): the overlap along its normal
/// it stays below, and whether it was held (the answer was
/// `MB_PAST_OUTCOME_AT`). Carry it to the next step's call for the same pair.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbCeiling {
    /// The overlap (A's greatest `normal . x` less B's least) the pair
    /// stays below.
    pub value: f64,
    /// Nonzero: the pair was held at the answer's time (then the next step
    /// keeps this ceiling).
    pub held: u32,
}

// SAFETY: a `repr(C)` struct of an `f64` and a `u32` (and padding): every
// bit pattern of the fields is a value.
unsafe impl Plain for MbCeiling {}

/// `mb_past_contact_below`'s answer.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MbBelowReport {
    /// Never (the overlap stays below the ceiling over the interval), from
    /// `time` on, or undecided.
    pub outcome: MbPastOutcome,
    /// For `MB_PAST_OUTCOME_AT`, the time; NaN otherwise.
    pub time: f64,
    /// An upper bound of the overlap along the normal at the start.
    pub overlap: f64,
    /// The ceiling used: carry it to the next step.
    pub ceiling: MbCeiling,
    /// Nonzero: a cast was made (`0`: decided by the closed form, a few
    /// support points).
    pub cast: u32,
}

/// For bodies touching at the start of their motions' interval (resting,
/// sliding, or overlapping by what a solver left): whether the overlap
/// along `normal` (A's greatest `normal . x` less B's least, an upper bound
/// of the penetration depth; any nonzero vector is sound, keep the same one
/// while the ceiling is carried) stays below a ceiling over the interval,
/// certified (Rust crate: `ca::past_contact_below`; `proofs/12-shapes.md`,
/// Lemma 12.14). The ceiling is `last`'s when that pair was held
/// (`last->held`): a pair stopped every step cannot creep in; otherwise
/// the start's overlap plus the contact distance, or `floor` (an overlap
/// always allowed, the solver's allowed penetration; `0` for none) when
/// that is more. A closed form decides a resting or sliding pair without a
/// cast (`out->cast` false); otherwise one cast against the half-space at
/// the ceiling, carried by the body that turns less. `last` may be `NULL`
/// (a pair not carried), `params` `NULL` for the defaults; a NaN or negative
/// `floor` counts as zero. The answer is
/// written to `*out`.
///
/// `MB_STATUS_NULL_POINTER` / `MB_STATUS_INVALID_HANDLE` for a bad handle,
/// `MB_STATUS_INVALID_INPUT` for a zero or non-finite `normal`,
/// `MB_STATUS_INVALID_PARAMETER` for parameters out of range,
/// `MB_STATUS_QUERY_ERROR` for motions over different intervals.
///
/// **Thread safety**: any thread; the shapes, motions and params may be
/// shared by concurrent calls.
///
/// # Safety
/// The handles are not freed during the call; `last` is `NULL` or valid for
/// reading an `mb_ceiling`; `params` is `NULL` or valid for reading an
/// `mb_params`; `out` is `NULL` or valid for writing an `mb_below_report`.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn mb_past_contact_below(
    shape_a: *const MbShape,
    motion_a: *const MbMotion,
    shape_b: *const MbShape,
    motion_b: *const MbMotion,
    normal: MbVec3,
    last: *const MbCeiling,
    floor: f64,
    params: *const MbParams,
    out: *mut MbBelowReport,
) -> MbStatus {
    guard(|| {
        // SAFETY: the handles are not freed during the call, and `last` and
        // `params` are NULL or readable (this function's contract).
        let (sa, ma, sb, mb, last, p) = unsafe {
            (
                handle_ref(shape_a, "shape_a")?,
                handle_ref(motion_a, "motion_a")?,
                handle_ref(shape_b, "shape_b")?,
                handle_ref(motion_b, "motion_b")?,
                read_in(last, "last")?,
                read_in(params, "params")?,
            )
        };
        let report = crate::value::below_report(
            (&sa.data, &ma.motion, &sb.data, &mb.motion),
            normal,
            last,
            floor,
            p,
        )?;
        // SAFETY: `out` is NULL or writable (this function's contract).
        unsafe { write_out(out, report, "out") }
    })
}
