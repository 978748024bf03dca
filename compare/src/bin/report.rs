//! Run time against error, in one command: every bound's cost against its
//! tightness, every scene's time of impact against its error for each
//! method, the seed's Table 1 with all seven rows, and the plots.
//!
//! ```sh
//! cargo run --release -p motion-bound-compare --bin report            # about 25 minutes on 2 cores
//! cargo run --release -p motion-bound-compare --bin report -- --quick # under 2 minutes (CI)
//! ```
//!
//! Writes `docs/report/` (or `--out DIR`): `bounds.svg` (ns per bound
//! against bound / exact), `toi_<scene>.svg` (ms per query against the
//! time-of-impact error, one series per method over a sweep of the contact
//! distance), `query.svg` (one query drawn step by step) and `table1.md`.
//!
//! * **Bounds.** Random blobs of `N` points (100 to 100,000), 16 motions over
//!   `[0, 1]` with sweeps from 0.3 to 8 rad and random directions. For each
//!   method, the median ns per bound (one-shot: preparing the motion
//!   included) and the mean of bound / exact, the exact value from the
//!   closed-form oracle (`motion_bound::reference`); one-sided rates against
//!   the exact signed sup, over the motions where it is positive.
//! * **Time of impact.** Each scene's queries by each method (NEVQ, EVQ,
//!   EVQ stepping as the seed does: absolute speeds and no time horizon, and
//!   the automatic policy), over a sweep of the contact distance (time
//!   tolerance `1e-9`). The error is `t_truth - t_ours`, `t_truth` the first
//!   contact found by sampling 200 times (100 with `--quick`) with an exact intersection test
//!   and bisecting on the same test to `1e-9` (`testkit::ground_truth`);
//!   MISSED and LATE as in the other reports (late: more than `1e-9` after
//!   the truth). Queries without a sampled contact count in the time, not in
//!   the error.
//! * **Rigid bodies.** `motion_bound_compare::rbd`, with EVQ and with NEVQ.
//!
//! Timings are one pass on a machine that may be busy: a report, not a
//! benchmark (`cargo bench` is the measurement to quote).

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use motion_bound::bodies::TorusKnotSize;
use motion_bound::ca::{time_of_impact, BoundChoice, CaParams, CaStep, MeshPair, StepResult, Work};
use motion_bound::reference::{exact, exact_sup_signed};
use motion_bound::testkit::ground_truth::{intersect_at, MeshRef};
use motion_bound::testkit::random_blob;
use motion_bound::testkit::table1::KnotScene;
use motion_bound::testkit::toi::{fly_by, random_rotation, reach, rotate_mesh, FlyBy, Rng};
use motion_bound::testkit::SplitMix64;
use motion_bound::{
    BallTree, BoundKind, Direction, PreparedMotion, RigidMotion, TriMesh, VertexSet, VertexTree,
};
use motion_bound_devkit::Args;

struct Opts {
    quick: bool,
    out: PathBuf,
}

fn parse() -> Opts {
    let mut args = Args::from_env("report [--quick] [--out DIR]");
    let o = Opts {
        quick: args.flag("--quick"),
        out: args.value_or(
            "--out",
            PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/report")),
        ),
    };
    args.finish();
    o
}

// ---------------------------------------------------------------- bounds

struct BoundRow {
    method: &'static str,
    n: usize,
    ns: f64,
    ratio: f64,
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs.get(xs.len() / 2).copied().unwrap_or(f64::NAN)
}

fn time_ns(reps: usize, mut f: impl FnMut() -> f64) -> (f64, f64) {
    let mut v = 0.0;
    let start = Instant::now();
    for _ in 0..reps {
        v = std::hint::black_box(f());
    }
    (start.elapsed().as_secs_f64() * 1e9 / reps as f64, v)
}

fn bounds_section(opts: &Opts, pb: &ProgressBar) -> Vec<BoundRow> {
    let sizes: &[usize] = if opts.quick {
        &[100, 1_000, 10_000]
    } else {
        &[100, 1_000, 10_000, 100_000]
    };
    let motions = if opts.quick { 6 } else { 16 };
    let mut rows = Vec::new();
    for &n in sizes {
        pb.set_message(format!("bounds, {n} points"));
        let mut rng = SplitMix64(0xB0_0000 + n as u64);
        let points = random_blob::<f64>(&mut rng, n);
        let set = VertexSet::try_new(&points).expect("valid");
        let tree = VertexTree::try_new(&set).expect("valid");
        let mut r = Rng::new(n as u64);
        let reps = (200_000 / n).clamp(3, 2_000);
        let mut per: [(Vec<f64>, Vec<f64>); 5] = Default::default();
        for k in 0..motions {
            let omega = [0.3, 1.0, 3.0, 8.0][k % 4];
            let axis = r.direction();
            let m = RigidMotion::try_from_arrays(
                [0.0; 3],
                r.direction().map(|x| x * r.unit()),
                axis.map(|x| x * omega),
            )
            .expect("finite");
            let n_dir = Direction::try_from_array(r.direction()).expect("unit");
            let ex = exact::<f64, f64>(&points, &m, n_dir).sup_speed;
            let signed: f64 = exact_sup_signed::<f64, f64>(&points, &m, n_dir);
            let prep = || PreparedMotion::new(&m).probe(n_dir);
            let methods: [(&mut dyn FnMut() -> f64, f64); 5] = [
                (&mut || prep().nevq_speed(&set.summary()), ex),
                (&mut || prep().evq_speed(&set), ex),
                (&mut || tree.evq_speed(&prep()), ex),
                (&mut || prep().rate(&set, BoundKind::Evq), signed),
                (&mut || tree.rate(&prep(), BoundKind::Evq), signed),
            ];
            for (i, (f, truth)) in methods.into_iter().enumerate() {
                let (ns, v) = time_ns(reps, f);
                per[i].0.push(ns);
                if truth > 0.05 * ex {
                    per[i].1.push(v / truth);
                }
            }
        }
        let names = [
            "NEVQ",
            "EVQ scan",
            "EVQ tree",
            "one-sided EVQ scan",
            "one-sided EVQ tree",
        ];
        for (i, (ns, ratios)) in per.into_iter().enumerate() {
            let ratio = ratios.iter().sum::<f64>() / ratios.len().max(1) as f64;
            rows.push(BoundRow {
                method: names[i],
                n,
                ns: median(ns),
                ratio,
            });
        }
        pb.inc(1);
    }
    rows
}

// ---------------------------------------------------------- time of impact

/// A scene of time-of-impact queries: two meshes and their motions.
struct ToiScene {
    name: &'static str,
    file: &'static str,
    meshes: Vec<(TriMesh<f64>, BallTree<f64>)>,
    /// (mesh of A, mesh of B, motions).
    queries: Vec<(usize, usize, FlyBy)>,
    /// How many of the first queries parry3d runs (0: none; it takes seconds each).
    parry_queries: usize,
}

fn knot_scene(size: TorusKnotSize, queries: usize) -> ToiScene {
    let s = KnotScene::new(size, queries, 2.0);
    ToiScene {
        name: match size {
            TorusKnotSize::K2_8 => "Torusknot vs Torusknot (2.8K)",
            TorusKnotSize::K11 => "Torusknot vs Torusknot (11K)",
            TorusKnotSize::K34 => "Torusknot vs Torusknot (34K)",
        },
        file: match size {
            TorusKnotSize::K2_8 => "knot_2_8k",
            TorusKnotSize::K11 => "knot_11k",
            TorusKnotSize::K34 => "knot_34k",
        },
        meshes: s.meshes.into_iter().zip(s.trees).collect(),
        queries: s
            .queries
            .into_iter()
            .map(|q| (q.a, q.b, q.motion))
            .collect(),
        parry_queries: if size == TorusKnotSize::K2_8 { 4 } else { 0 },
    }
}

fn shipped(name: &str) -> TriMesh<f64> {
    motion_bound_compare::shipped_mesh(name)
}

fn with_tree(m: TriMesh<f64>) -> (TriMesh<f64>, BallTree<f64>) {
    // A tree's hierarchy of pieces (a mesh of long triangles) is built
    // with the tree, so that no query's time holds it.
    let t = BallTree::try_from_mesh(&m).expect("valid");
    (m, t)
}

/// Two meshes in random orientations, `queries` fly-bys at `spin`.
fn pair_scene(
    name: &'static str,
    file: &'static str,
    a: &TriMesh<f64>,
    b: &TriMesh<f64>,
    queries: usize,
    spin: f64,
    seed: u64,
) -> ToiScene {
    let mut rng = Rng::new(seed);
    let mut meshes = Vec::new();
    let mut qs = Vec::new();
    for _ in 0..queries {
        let ma = rotate_mesh(a, &random_rotation(&mut rng));
        let mb = rotate_mesh(b, &random_rotation(&mut rng));
        let q = fly_by(&mut rng, reach(&ma), reach(&mb), spin);
        meshes.push(with_tree(ma));
        meshes.push(with_tree(mb));
        qs.push((meshes.len() - 2, meshes.len() - 1, q));
    }
    ToiScene {
        name,
        file,
        meshes,
        queries: qs,
        parry_queries: 0,
    }
}

/// The first contact to `1e-9`: the first of `samples` samples at which the
/// meshes intersect, then bisection on the same exact test.
fn truth(s: &ToiScene, q: &(usize, usize, FlyBy), samples: u32) -> Option<f64> {
    let (a, b) = (
        MeshRef::from(&s.meshes[q.0].0),
        MeshRef::from(&s.meshes[q.1].0),
    );
    let hit = |t: f64| intersect_at(a, &q.2.a, b, &q.2.b, t);
    let k = (0..=samples).find(|&k| hit(f64::from(k) / f64::from(samples)))?;
    if k == 0 {
        return Some(0.0);
    }
    let (mut lo, mut hi) = (
        f64::from(k - 1) / f64::from(samples),
        f64::from(k) / f64::from(samples),
    );
    while hi - lo > 1e-9 {
        let mid = 0.5 * (lo + hi);
        if hit(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

#[derive(Clone, Copy)]
struct Method {
    name: &'static str,
    bound: BoundChoice,
    seed_stepping: bool,
}

const METHODS: [Method; 4] = [
    Method {
        name: "NEVQ",
        bound: BoundChoice::Nevq,
        seed_stepping: false,
    },
    Method {
        name: "EVQ",
        bound: BoundChoice::Evq,
        seed_stepping: false,
    },
    Method {
        name: "EVQ, seed stepping",
        bound: BoundChoice::Evq,
        seed_stepping: true,
    },
    Method {
        name: "automatic",
        bound: BoundChoice::Auto,
        seed_stepping: false,
    },
];

impl Method {
    fn params(self, contact_distance: f64, time_tolerance: f64) -> CaParams<f64> {
        let p = CaParams::default()
            .with_contact_distance(contact_distance)
            .with_time_tolerance(time_tolerance)
            .with_bound(self.bound);
        if self.seed_stepping {
            p.with_one_sided(false).with_horizon_factor(0.0)
        } else {
            p
        }
    }
}

struct ToiPoint {
    method: &'static str,
    contact_distance: f64,
    time_tolerance: f64,
    ms: f64,
    iterations: f64,
    mean_error: f64,
    max_error: f64,
    missed: usize,
    late: usize,
}

fn run_toi(s: &ToiScene, truths: &[Option<f64>], m: Method, cd: f64, tol: f64) -> ToiPoint {
    let params = m.params(cd, tol);
    let (mut ms, mut it, mut errs, mut missed, mut late) = (0.0, 0u64, Vec::new(), 0, 0);
    for (q, t) in s.queries.iter().zip(truths) {
        let start = Instant::now();
        let mut pair = MeshPair::new(&s.meshes[q.0].1, &s.meshes[q.1].1);
        let r = time_of_impact(&mut pair, &q.2.a, &q.2.b, &params).expect("valid");
        ms += start.elapsed().as_secs_f64() * 1e3;
        it += u64::from(r.iterations);
        match (r.outcome.earliest_possible_contact(), t) {
            (None, Some(_)) => missed += 1,
            (Some(ours), Some(truth)) => {
                if ours > truth + 1e-9 {
                    late += 1;
                }
                errs.push((truth - ours).max(0.0));
            }
            _ => {}
        }
    }
    let n = s.queries.len().max(1) as f64;
    ToiPoint {
        method: m.name,
        contact_distance: cd,
        time_tolerance: tol,
        ms: ms / n,
        iterations: it as f64 / n,
        mean_error: errs.iter().sum::<f64>() / errs.len().max(1) as f64,
        max_error: errs.iter().copied().fold(0.0, f64::max),
        missed,
        late,
    }
}

/// parry3d's `cast_shapes_nonlinear` on the scene's first queries, with the
/// same meshes and motions (`motion_bound_compare::parry::parry_motion`).
fn run_parry(s: &ToiScene, truths: &[Option<f64>]) -> ToiPoint {
    use motion_bound_compare::parry::parry_motion;
    use parry3d_f64::math::Vector;
    use parry3d_f64::query::cast_shapes_nonlinear;
    use parry3d_f64::shape::TriMesh as ParryMesh;
    let mesh = |m: &TriMesh<f64>| {
        let v = m
            .vertices()
            .iter()
            .map(|p| Vector::new(p[0], p[1], p[2]))
            .collect();
        ParryMesh::new(v, m.triangles().to_vec()).expect("a valid mesh")
    };
    let (mut ms, mut errs, mut missed, mut late) = (0.0, Vec::new(), 0, 0);
    let n = s.parry_queries.min(s.queries.len());
    for (q, t) in s.queries.iter().zip(truths).take(n) {
        let (a, b) = (mesh(&s.meshes[q.0].0), mesh(&s.meshes[q.1].0));
        let start = Instant::now();
        let hit = cast_shapes_nonlinear(
            &parry_motion(&q.2.a),
            &a,
            &parry_motion(&q.2.b),
            &b,
            0.0,
            1.0,
            true,
        )
        .expect("parry supports mesh against mesh");
        ms += start.elapsed().as_secs_f64() * 1e3;
        match (hit.map(|h| h.time_of_impact), t) {
            (None, Some(_)) => missed += 1,
            (Some(theirs), Some(truth)) => {
                late += usize::from(theirs > truth + 1e-9);
                errs.push((truth - theirs).abs());
            }
            _ => {}
        }
    }
    ToiPoint {
        method: "parry3d",
        contact_distance: 0.0,
        time_tolerance: 0.0,
        ms: ms / n.max(1) as f64,
        iterations: f64::NAN,
        mean_error: errs.iter().sum::<f64>() / errs.len().max(1) as f64,
        max_error: errs.iter().copied().fold(0.0, f64::max),
        missed,
        late,
    }
}

// ---------------------------------------------------------------- drawing

/// A log-log scatter with lines per series, as SVG.
fn svg_plot(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[(String, Vec<(f64, f64)>)],
) -> String {
    let (w, h, ml, mb, mt, mr) = (760.0, 480.0, 80.0, 60.0, 40.0, 230.0);
    let pts: Vec<(f64, f64)> = series
        .iter()
        .flat_map(|s| s.1.iter().copied())
        .filter(|p| p.0 > 0.0 && p.1 > 0.0 && p.0.is_finite() && p.1.is_finite())
        .collect();
    let lx = |x: f64| x.log10();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &pts {
        x0 = x0.min(lx(p.0));
        x1 = x1.max(lx(p.0));
        y0 = y0.min(lx(p.1));
        y1 = y1.max(lx(p.1));
    }
    if pts.is_empty() {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    let (x0, x1) = (x0.floor(), x1.ceil().max(x0.floor() + 1.0));
    let (y0, y1) = (y0.floor(), y1.ceil().max(y0.floor() + 1.0));
    let px = |x: f64| ml + (lx(x) - x0) / (x1 - x0) * (w - ml - mr);
    let py = |y: f64| h - mb - (lx(y) - y0) / (y1 - y0) * (h - mb - mt);
    let colours = [
        "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
    ];
    let mut s = String::new();
    let _ = write!(s, "<svg xmlns='http://www.w3.org/2000/svg' width='{w}' height='{h}' font-family='sans-serif' font-size='12'>");
    let _ = write!(s, "<rect width='100%' height='100%' fill='white'/><text x='{}' y='22' font-size='15' text-anchor='middle'>{title}</text>", (w - mr + ml) / 2.0);
    for e in (x0 as i32)..=(x1 as i32) {
        let x = px(10f64.powi(e));
        let _ = write!(s, "<line x1='{x}' y1='{}' x2='{x}' y2='{}' stroke='#ddd'/><text x='{x}' y='{}' text-anchor='middle'>1e{e}</text>", mt, h - mb, h - mb + 16.0);
    }
    for e in (y0 as i32)..=(y1 as i32) {
        let y = py(10f64.powi(e));
        let _ = write!(s, "<line x1='{ml}' y1='{y}' x2='{}' y2='{y}' stroke='#ddd'/><text x='{}' y='{}' text-anchor='end'>1e{e}</text>", w - mr, ml - 6.0, y + 4.0);
    }
    let _ = write!(
        s,
        "<text x='{}' y='{}' text-anchor='middle'>{x_label}</text>",
        (w - mr + ml) / 2.0,
        h - 18.0
    );
    let _ = write!(
        s,
        "<text x='18' y='{}' text-anchor='middle' transform='rotate(-90 18 {})'>{y_label}</text>",
        (h - mb + mt) / 2.0,
        (h - mb + mt) / 2.0
    );
    for (i, (name, data)) in series.iter().enumerate() {
        let c = colours[i % colours.len()];
        let ok: Vec<&(f64, f64)> = data.iter().filter(|p| p.0 > 0.0 && p.1 > 0.0).collect();
        let path: Vec<String> = ok
            .iter()
            .map(|p| format!("{:.1},{:.1}", px(p.0), py(p.1)))
            .collect();
        if path.len() > 1 {
            let _ = write!(
                s,
                "<polyline fill='none' stroke='{c}' stroke-width='1.5' points='{}'/>",
                path.join(" ")
            );
        }
        for p in &ok {
            let _ = write!(
                s,
                "<circle cx='{:.1}' cy='{:.1}' r='3.5' fill='{c}'/>",
                px(p.0),
                py(p.1)
            );
        }
        let ly = mt + 18.0 * i as f64 + 10.0;
        let _ = write!(
            s,
            "<circle cx='{}' cy='{ly}' r='4' fill='{c}'/><text x='{}' y='{}'>{name}</text>",
            w - mr + 16.0,
            w - mr + 26.0,
            ly + 4.0
        );
    }
    s.push_str("</svg>\n");
    s
}

/// Records the times at which conservative advancement evaluates the pair.
struct Recording<'a> {
    inner: MeshPair<'a, f64>,
    times: Vec<f64>,
}

impl CaStep<f64> for Recording<'_> {
    fn step(
        &mut self,
        t: f64,
        a: &PreparedMotion<f64>,
        b: &PreparedMotion<f64>,
        params: &CaParams<f64>,
    ) -> StepResult<f64> {
        self.times.push(t);
        self.inner.step(t, a, b, params)
    }

    fn work(&self) -> Work {
        self.inner.work()
    }
}

/// One query, drawn: both knots projected on the plane of A's path, A at
/// each step of conservative advancement up to contact.
fn draw_query(s: &ToiScene) -> (String, usize, Option<f64>) {
    // The first query with a contact after a few steps.
    let params = METHODS[1].params(1e-3, 1e-9);
    let mut chosen = None;
    for q in &s.queries {
        let mut rec = Recording {
            inner: MeshPair::new(&s.meshes[q.0].1, &s.meshes[q.1].1),
            times: Vec::new(),
        };
        let r = time_of_impact(&mut rec, &q.2.a, &q.2.b, &params).expect("valid");
        if let Some(c) = r.outcome.contact() {
            if rec.times.len() >= 4 && c.time > 0.2 {
                chosen = Some((q, rec.times, c.time));
                break;
            }
        }
    }
    let Some((q, times, hit)) = chosen else {
        return (
            String::from("<svg xmlns='http://www.w3.org/2000/svg'/>"),
            0,
            None,
        );
    };
    // Project on the plane spanned by A's velocity and the world axis least
    // aligned with it.
    let v = q.2.a.linear();
    let e1 = v * (1.0 / v.length());
    let pick = if e1.x.abs() < 0.6 {
        motion_bound::Vec3::new(1.0, 0.0, 0.0)
    } else {
        motion_bound::Vec3::new(0.0, 1.0, 0.0)
    };
    let e2 = {
        let p = pick - e1 * pick.dot(e1);
        p * (1.0 / p.length())
    };
    let place = |m: &RigidMotion<f64>, r: &[f64; 3], t: f64| {
        let p = m
            .pose_at(t)
            .transform_point(motion_bound::Vec3::from_array(*r));
        (p.dot(e1), p.dot(e2))
    };
    let mut all = Vec::new();
    let outline = |mesh: &TriMesh<f64>, m: &RigidMotion<f64>, t: f64| -> Vec<(f64, f64)> {
        mesh.vertices()
            .iter()
            .step_by(3)
            .map(|r| place(m, r, t))
            .collect()
    };
    let b_pts = outline(&s.meshes[q.1].0, &q.2.b, hit);
    all.extend(b_pts.iter().copied());
    let mut a_steps = Vec::new();
    for &t in times.iter().chain(std::iter::once(&hit)) {
        let p = outline(&s.meshes[q.0].0, &q.2.a, t);
        all.extend(p.iter().copied());
        a_steps.push((t, p));
    }
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &all {
        x0 = x0.min(p.0);
        x1 = x1.max(p.0);
        y0 = y0.min(p.1);
        y1 = y1.max(p.1);
    }
    let (w, h) = (760.0, 420.0);
    let scale = ((w - 40.0) / (x1 - x0)).min((h - 70.0) / (y1 - y0));
    let px = |x: f64| 20.0 + (x - x0) * scale;
    let py = |y: f64| h - 20.0 - (y - y0) * scale;
    let mut out = String::new();
    let _ = write!(out, "<svg xmlns='http://www.w3.org/2000/svg' width='{w}' height='{h}' font-family='sans-serif' font-size='12'><rect width='100%' height='100%' fill='white'/>");
    let _ = write!(out, "<text x='20' y='20' font-size='14'>One EVQ query: knot A (blue, lighter at earlier steps) flies at knot B (grey); {} steps of conservative advancement, contact at t = {hit:.4}</text>", times.len());
    for p in &b_pts {
        let _ = write!(
            out,
            "<circle cx='{:.1}' cy='{:.1}' r='1' fill='#888'/>",
            px(p.0),
            py(p.1)
        );
    }
    let k = a_steps.len();
    for (i, (t, pts)) in a_steps.iter().enumerate() {
        let alpha = 0.15 + 0.85 * (i as f64 + 1.0) / k as f64;
        let colour = if i + 1 == k { "#d62728" } else { "#1f77b4" };
        for p in pts {
            let _ = write!(
                out,
                "<circle cx='{:.1}' cy='{:.1}' r='1' fill='{colour}' fill-opacity='{alpha:.2}'/>",
                px(p.0),
                py(p.1)
            );
        }
        let c = pts.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
        let c = (c.0 / pts.len() as f64, c.1 / pts.len() as f64);
        let _ = write!(
            out,
            "<text x='{:.1}' y='{:.1}' fill='{colour}'>t={t:.3}</text>",
            px(c.0),
            py(c.1) - 4.0 - 12.0 * (i % 2) as f64
        );
    }
    out.push_str("</svg>\n");
    (out, times.len(), Some(hit))
}

// ------------------------------------------------------------------ main

fn main() {
    let opts = parse();
    std::fs::create_dir_all(&opts.out).expect("the output folder");
    let started = Instant::now();
    let q = if opts.quick { 8 } else { 40 };
    let cds: &[f64] = if opts.quick {
        &[1e-2, 1e-3]
    } else {
        &[1e-2, 1e-3, 1e-4, 1e-5]
    };
    let frames = if opts.quick { 10 } else { 300 };
    let samples = if opts.quick { 100 } else { 200 };
    let knot_sizes: &[TorusKnotSize] = if opts.quick {
        &[TorusKnotSize::K2_8]
    } else {
        &TorusKnotSize::ALL
    };
    let scenes_n = knot_sizes.len() + 2;
    let total = (if opts.quick { 3 } else { 4 }) + scenes_n * (1 + METHODS.len() * cds.len()) + 2;
    let pb = ProgressBar::new(total as u64);
    pb.set_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} {msg}")
            .expect("a valid template")
            .progress_chars("=> "),
    );

    let bounds = bounds_section(&opts, &pb);

    pb.set_message("building scenes");
    let armadillo = shipped("armadillo.off.gz");
    // The thin board as a modeller gives it: 12 triangles (the queries take
    // its hierarchy of pieces against the armadillo).
    let board = motion_bound::bodies::board(1.0, 1.0, 0.01).expect("a valid board");
    let bunny = shipped("bunny-npm-3674.obj.gz");
    let mut scenes: Vec<ToiScene> = knot_sizes.iter().map(|&s| knot_scene(s, q)).collect();
    scenes.push(pair_scene(
        "Santa vs Thin Board (armadillo vs spinning board)",
        "board_armadillo",
        &board,
        &armadillo,
        if opts.quick { 4 } else { q },
        40.0,
        7,
    ));
    scenes.push(pair_scene(
        "Bunny vs Bunny",
        "bunny_bunny",
        &bunny,
        &bunny,
        q,
        2.0,
        8,
    ));

    let mut results: Vec<(usize, Vec<ToiPoint>)> = Vec::new();
    for (i, s) in scenes.iter().enumerate() {
        pb.set_message(format!("{}: ground truth", s.name));
        let truths: Vec<Option<f64>> = s.queries.iter().map(|qq| truth(s, qq, samples)).collect();
        pb.inc(1);
        let mut points = Vec::new();
        for &cd in cds {
            for m in METHODS {
                pb.set_message(format!("{}: {}, contact distance {cd:e}", s.name, m.name));
                points.push(run_toi(s, &truths, m, cd, 1e-9));
                pb.inc(1);
            }
        }
        for tol in [1e-3, 1e-6] {
            for m in METHODS {
                points.push(run_toi(s, &truths, m, 1e-3, tol));
            }
        }
        if !opts.quick && s.parry_queries > 0 {
            pb.set_message(format!("{}: parry3d", s.name));
            points.push(run_parry(s, &truths));
        }
        results.push((i, points));
    }

    pb.set_message("RBD scenes (EVQ)");
    let rbd_evq = motion_bound_compare::rbd::run_both(frames, BoundChoice::Evq, true);
    pb.inc(1);
    pb.set_message("RBD scenes (NEVQ)");
    let rbd_nevq = motion_bound_compare::rbd::run_both(frames, BoundChoice::Nevq, true);
    pb.inc(1);
    pb.finish_with_message(format!("done in {:.0} s", started.elapsed().as_secs_f64()));

    // ---- the tables
    let mut md = String::new();
    let _ = writeln!(md, "# Report{}\n", if opts.quick { " (quick)" } else { "" });
    let _ = writeln!(md, "`cargo run --release -p motion-bound-compare --bin report{}`, one pass on this machine (a report, not a benchmark).\n", if opts.quick { " -- --quick" } else { "" });
    let _ = writeln!(md, "## The seed's Table 1\n\nms per query (iterations) at contact distance `1e-3`, beside the seed's numbers (2006 hardware).\n");
    let _ = writeln!(md, "| benchmark | seed: old | seed: with EVQ | seed: without EVQ | ours: EVQ | ours: NEVQ | ours: automatic | missed / late (ours, all methods) |");
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|");
    let seed = |name: &str| -> (f64, f64, f64) {
        match name {
            n if n.starts_with("Santa") => (0.0647, 0.419, 0.0194),
            "Bunny vs Bunny" => (8.00, 9.55, 9.10),
            "Torusknot vs Torusknot (2.8K)" => (0.948, 0.983, 0.937),
            "Torusknot vs Torusknot (11K)" => (2.01, 2.98, 2.50),
            "Torusknot vs Torusknot (34K)" => (5.32, 5.88, 5.38),
            "RBD for Bunnies" => (0.643, 0.728, 0.501),
            _ => (0.737, 2.07, 1.89),
        }
    };
    let mut order: Vec<usize> = Vec::new();
    let by_name = |n: &str| scenes.iter().position(|s| s.name.starts_with(n));
    for n in [
        "Santa",
        "Bunny vs Bunny",
        "Torusknot vs Torusknot (2.8K)",
        "Torusknot vs Torusknot (11K)",
        "Torusknot vs Torusknot (34K)",
    ] {
        if let Some(i) = by_name(n) {
            order.push(i);
        }
    }
    let mut all_clean = true;
    for &i in &order {
        let s = &scenes[i];
        let pts = &results[i].1;
        let at = |m: &str| {
            pts.iter()
                .find(|p| p.method == m && p.contact_distance == 1e-3 && p.time_tolerance == 1e-9)
        };
        let (so, se, sn) = seed(s.name);
        let (missed, late): (usize, usize) = pts
            .iter()
            .filter(|p| p.method != "parry3d")
            .fold((0, 0), |a, p| (a.0 + p.missed, a.1 + p.late));
        all_clean &= missed == 0 && late == 0;
        let cell = |p: Option<&ToiPoint>| {
            p.map_or(String::from("-"), |p| {
                format!("{:.3} ({:.2})", p.ms, p.iterations)
            })
        };
        let _ = writeln!(
            md,
            "| {} ({} queries) | {so} | {se} | {sn} | {} | {} | {} | {missed} / {late} |",
            s.name,
            s.queries.len(),
            cell(at("EVQ")),
            cell(at("NEVQ")),
            cell(at("automatic"))
        );
    }
    for (k, name) in ["RBD for Bunnies", "RBD for Rings"].into_iter().enumerate() {
        let (so, se, sn) = seed(name);
        let (e, n) = (&rbd_evq[k], &rbd_nevq[k]);
        let per = |t: &motion_bound_compare::rbd::Tally| {
            format!(
                "{:.4} ({:.2})",
                t.query_ms / t.queries.max(1) as f64,
                t.iterations as f64 / t.queries.max(1) as f64
            )
        };
        all_clean &= e.missed + e.late + n.missed + n.late == 0;
        let _ = writeln!(
            md,
            "| {name} ({frames} frames, {} queries) | {so} | {se} | {sn} | {} | {} | - | {} / {} |",
            e.queries,
            per(e),
            per(n),
            e.missed + n.missed,
            e.late + n.late
        );
    }
    let _ = writeln!(md, "\n## Time of impact: ms per query against the error\n\nError: `t_truth - t_ours` over the queries with a contact (ours is never later); plots `toi_*.svg`.\n");
    let _ = writeln!(md, "| scene | method | contact distance | time tolerance | ms per query | iterations | mean error | max error | missed | late |");
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|---|");
    for (i, pts) in &results {
        for p in pts {
            let _ = writeln!(
                md,
                "| {} | {} | {:e} | {:e} | {:.3} | {:.2} | {:.2e} | {:.2e} | {} | {} |",
                scenes[*i].name,
                p.method,
                p.contact_distance,
                p.time_tolerance,
                p.ms,
                p.iterations,
                p.mean_error,
                p.max_error,
                p.missed,
                p.late
            );
        }
    }
    let _ = writeln!(md, "\n## Bounds: cost against tightness\n\nRandom blobs, median ns per one-shot bound, mean bound / exact; plot `bounds.svg`.\n");
    let _ = writeln!(md, "| method | points | ns per bound | bound / exact |");
    let _ = writeln!(md, "|---|---|---|---|");
    for r in &bounds {
        let _ = writeln!(
            md,
            "| {} | {} | {:.0} | {:.4} |",
            r.method, r.n, r.ns, r.ratio
        );
    }

    // ---- the plots
    let mut series: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for name in [
        "NEVQ",
        "EVQ scan",
        "EVQ tree",
        "one-sided EVQ scan",
        "one-sided EVQ tree",
    ] {
        let pts = bounds
            .iter()
            .filter(|r| r.method == name)
            .map(|r| (r.ns, r.ratio))
            .collect();
        series.push((name.to_owned(), pts));
    }
    std::fs::write(
        opts.out.join("bounds.svg"),
        svg_plot(
            "Bounds: cost against tightness (each point one body size, 100 to 100,000 points)",
            "ns per bound",
            "bound / exact",
            &series,
        ),
    )
    .expect("write");
    for (i, pts) in &results {
        let s = &scenes[*i];
        let series: Vec<(String, Vec<(f64, f64)>)> = METHODS
            .iter()
            .map(|m| {
                (
                    m.name.to_owned(),
                    pts.iter()
                        .filter(|p| p.method == m.name && p.time_tolerance == 1e-9)
                        .map(|p| (p.ms, p.mean_error.max(1e-12)))
                        .collect(),
                )
            })
            .chain(pts.iter().filter(|p| p.method == "parry3d").map(|p| {
                (
                    String::from("parry3d"),
                    vec![(p.ms, p.mean_error.max(1e-12))],
                )
            }))
            .collect();
        std::fs::write(
            opts.out.join(format!("toi_{}.svg", s.file)),
            svg_plot(
                &format!("{}: error against time (contact distance swept)", s.name),
                "ms per query",
                "mean time-of-impact error",
                &series,
            ),
        )
        .expect("write");
    }
    let (svg, steps, hit) = draw_query(&scenes[0]);
    std::fs::write(opts.out.join("query.svg"), svg).expect("write");
    let _ = writeln!(md, "\nparry3d rows (contact distance and time tolerance 0: its own): `cast_shapes_nonlinear` on the first queries of the scene, same meshes and motions; its error is `|t_truth - t_parry|`, its MISSED and LATE are not counted against ours.");
    let _ = writeln!(md, "\n`query.svg`: one query of the first scene drawn step by step ({steps} steps, contact at {hit:?}).");
    std::fs::write(opts.out.join("table1.md"), &md).expect("write");
    println!("{md}");
    println!("wrote {}", opts.out.display());
    if !all_clean {
        eprintln!("FAILED: a method missed or was late");
        std::process::exit(1);
    }
}
