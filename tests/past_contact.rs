//! `ca::past_contact` (Lemma 12.11): a pair touching at the start goes
//! deeper or not. Judged by dense sampling of the bodies' corners along the
//! exact motions, never by the code under test: until the answer's time
//! (the whole interval for `Never`), A's greatest `n . x` beyond B's least
//! (their overlap along `n`) grows by less than the contact distance over
//! its start value (or over zero, for a pair apart at the start).
//!
//! The story: a body stopped at a wall, then resting on or sliding along
//! it, was cast every step from a touching start and asked again with half
//! the gap as contact distance (Bullet's example, `bullet_worlds.cpp`),
//! a full query of many iterations for a spinning board. These cases are
//! the ones that rule must still catch (pushed in, a corner of a spinning
//! board swinging into the wall) and the ones it must let go cheaply
//! (sliding, leaving, spinning about the normal).

use motion_bound::ca::{
    past_contact, past_contact_below, CaError, CaParams, Ceiling, PastContact, Shape,
};
use motion_bound::{BallTree, BodyPoint, Convex, Float, Isometry, RigidMotion, Rotation, Vec3};

const DT: f64 = 1.0 / 60.0;
const SAMPLES: usize = 4000;

/// A small deterministic generator (SplitMix64), the test's own.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
    fn unit(&mut self) -> [f64; 3] {
        loop {
            let v = [
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            ];
            let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if l > 0.1 && l <= 1.0 {
                return v.map(|x| x / l);
            }
        }
    }
}

fn corners(h: [f64; 3]) -> Vec<[f64; 3]> {
    let mut out = Vec::new();
    for s in 0..8 {
        let sign = |k: usize| if s >> k & 1 == 1 { 1.0 } else { -1.0 };
        out.push([sign(0) * h[0], sign(1) * h[1], sign(2) * h[2]]);
    }
    out
}

fn v3<T: Float>(a: [f64; 3]) -> Vec3<T> {
    Vec3::new(T::from_f64(a[0]), T::from_f64(a[1]), T::from_f64(a[2]))
}

/// The motion of a body at `x` turned by `turn` (axis-angle), with linear
/// velocity `v` and angular velocity `w`, over one step.
fn motion<T: Float>(
    x: [f64; 3],
    turn: ([f64; 3], f64),
    v: [f64; 3],
    w: [f64; 3],
) -> RigidMotion<T> {
    let r = Rotation::try_from_axis_angle(v3(turn.0), T::from_f64(turn.1)).expect("a rotation");
    let start = Isometry::try_new(r, v3(x)).expect("a pose");
    RigidMotion::try_from_start(start, v3(v), v3(w), T::from_f64(DT)).expect("a motion")
}

/// `max` (or `min`) of `n . x` over the body points `points` at `t`, by the
/// motion's own definition of a body point's position.
fn reach<T: Float>(m: &RigidMotion<T>, points: &[[f64; 3]], n: [f64; 3], t: f64, max: bool) -> f64 {
    let dots = points.iter().map(|p| {
        let q = m.point_at(
            BodyPoint::new(T::from_f64(p[0]), T::from_f64(p[1]), T::from_f64(p[2])),
            T::from_f64(t),
        );
        let q = q.to_array().map(T::to_f64);
        q[0] * n[0] + q[1] * n[1] + q[2] * n[2]
    });
    if max {
        dots.fold(f64::NEG_INFINITY, f64::max)
    } else {
        dots.fold(f64::INFINITY, f64::min)
    }
}

/// The certified claim, sampled: before `until`, the overlap along `n`
/// grows by less than `d` (a relative `1e-9` for sampling's arithmetic,
/// `1e-5 d` more in `f32`, whose placement error is near that). Returns the
/// first sampled time the overlap grows by more than `1.5 d` (the plane).
#[allow(clippy::too_many_arguments)]
fn judge<T: Float>(
    ma: &RigidMotion<T>,
    pa: &[[f64; 3]],
    mb: &RigidMotion<T>,
    pb: &[[f64; 3]],
    n: [f64; 3],
    d: f64,
    until: f64,
    what: &str,
) -> Option<f64> {
    let overlap = |t: f64| reach(ma, pa, n, t, true) - reach(mb, pb, n, t, false);
    let start = overlap(0.0).max(0.0);
    let slack = if T::UNIT_ROUNDOFF.to_f64() > 1e-10 {
        2e-2 * d
    } else {
        1e-9
    };
    let mut first_past_plane = None;
    for k in 0..=SAMPLES {
        let t = DT * k as f64 / SAMPLES as f64;
        let grown = overlap(t) - start;
        if t < until {
            assert!(
                grown < d + slack,
                "{what}: at t = {t} (answer's time {until}) the overlap grew by {grown} >= d = {d}"
            );
        }
        if grown > 1.5 * d + slack && first_past_plane.is_none() {
            first_past_plane = Some(t);
        }
    }
    first_past_plane
}

fn time_of<T: Float>(answer: PastContact<T>) -> f64 {
    match answer {
        PastContact::Never => f64::INFINITY,
        PastContact::At(t) => t.to_f64(),
        other => panic!("undecided: {other:?}"),
    }
}

/// A board (a cuboid 0.1 x 0.4 x 0.1 half extents) within the contact
/// distance of a wall's face `x = 0.5` (a cuboid, still), spinning and
/// moving at random: sliding along, leaving, pushed in; spinning about the
/// normal (never deeper) or about any axis (a corner may swing in).
fn board_at_a_wall<T: Float>() {
    let d = 1e-3;
    let p = CaParams::<T>::default().with_contact_distance(T::from_f64(d));
    let (hb, hw) = ([0.1, 0.4, 0.1], [0.5, 2.0, 2.0]);
    let board = Convex::try_cuboid(hb.map(T::from_f64)).expect("a board");
    let wall = Convex::try_cuboid(hw.map(T::from_f64)).expect("a wall");
    let (pb, pw) = (corners(hb), corners(hw));
    let still = motion::<T>([1.0, 0.0, 0.0], ([1.0, 0.0, 0.0], 0.0), [0.0; 3], [0.0; 3]);
    let n = [1.0, 0.0, 0.0];
    let mut rng = Rng(55);
    let (mut never, mut at, mut slides) = (0, 0, 0);
    for case in 0..300 {
        let gap = rng.range(0.05, 0.95) * d;
        let kind = case % 4;
        // 0: slides (no x velocity), spinning about x; 1: leaves; 2: pushed
        // in; 3: any spin about any axis, any velocity.
        let vx = match kind {
            0 => 0.0,
            1 => -rng.range(0.1, 5.0),
            2 => rng.range(0.1, 5.0),
            _ => rng.range(-3.0, 3.0),
        };
        let v = [vx, rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)];
        let w = if kind == 3 {
            rng.unit().map(|c| c * rng.range(0.0, 80.0))
        } else {
            [rng.range(-80.0, 80.0), 0.0, 0.0]
        };
        let x = [0.5 - 0.1 - gap, rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
        let m = motion::<T>(x, ([1.0, 0.0, 0.0], rng.range(0.0, 6.0)), v, w);
        let answer = past_contact(
            Shape::Convex(board),
            &m,
            Shape::Convex(wall),
            &still,
            v3(n),
            &p,
        )
        .expect("a board and a wall");
        let until = time_of(answer);
        let what = format!("board case {case} (kind {kind})");
        let past = judge(&m, &pb, &still, &pw, n, d, until, &what);
        match answer {
            PastContact::Never => never += 1,
            _ => at += 1,
        }
        if kind <= 1 {
            // Sliding and leaving: never deeper, and said so.
            slides += 1;
            assert_eq!(answer, PastContact::Never, "{what}");
        }
        if kind == 2 {
            // Pushed in: a time after the start, no later than the sampled
            // crossing of the plane.
            assert!(
                until > 0.0 && until <= past.expect("pushed past the plane"),
                "{what}"
            );
        }
    }
    assert!(
        slides == 150 && never >= 150 && at >= 75,
        "{never} never, {at} at"
    );
}

#[test]
fn a_board_at_a_wall_goes_deeper_only_when_pushed_f64() {
    board_at_a_wall::<f64>();
}

#[test]
fn a_board_at_a_wall_goes_deeper_only_when_pushed_f32() {
    board_at_a_wall::<f32>();
}

/// A cube (a closed triangle mesh) resting on a plate of two triangles
/// (`z = 0`, zero thickness), sliding, lifting, pressed down and tumbling.
#[test]
fn a_mesh_cube_on_a_mesh_plate_goes_deeper_only_when_pressed() {
    let d = 1e-3;
    let p = CaParams::<f64>::default().with_contact_distance(d);
    let h = 0.1;
    let cube_points = corners([h; 3]);
    let cube_triangles: [[u32; 3]; 12] = [
        [0, 3, 1],
        [0, 2, 3],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [1, 3, 7],
        [1, 7, 5],
        [0, 4, 6],
        [0, 6, 2],
    ];
    let cube = BallTree::try_new(&cube_points, &cube_triangles).expect("a cube");
    let plate_points = vec![
        [-5.0, -5.0, 0.0],
        [5.0, -5.0, 0.0],
        [5.0, 5.0, 0.0],
        [-5.0, 5.0, 0.0],
    ];
    let plate = BallTree::try_new(&plate_points, &[[0, 1, 2], [0, 2, 3]]).expect("a plate");
    let still = motion::<f64>([0.0; 3], ([0.0, 0.0, 1.0], 0.0), [0.0; 3], [0.0; 3]);
    // The cube above the plate: A's least `z` is B's greatest, so `n` is
    // `-z` from the cube to the plate.
    let n = [0.0, 0.0, -1.0];
    let mut rng = Rng(12);
    for case in 0..120 {
        let kind = case % 3;
        let gap = rng.range(0.05, 0.95) * d;
        let vz = match kind {
            0 => 0.0,
            1 => rng.range(0.1, 5.0),
            _ => -rng.range(0.1, 5.0),
        };
        let v = [rng.range(-5.0, 5.0), rng.range(-5.0, 5.0), vz];
        let w = [0.0, 0.0, rng.range(-60.0, 60.0)];
        let x = [rng.range(-2.0, 2.0), rng.range(-2.0, 2.0), h + gap];
        let m = motion::<f64>(x, ([0.0, 0.0, 1.0], rng.range(0.0, 6.0)), v, w);
        let answer = past_contact(
            Shape::Mesh(&cube),
            &m,
            Shape::Mesh(&plate),
            &still,
            v3(n),
            &p,
        )
        .expect("a cube and a plate");
        let until = time_of(answer);
        let what = format!("cube case {case} (kind {kind})");
        let past = judge(&m, &cube_points, &still, &plate_points, n, d, until, &what);
        match kind {
            0 | 1 => assert_eq!(answer, PastContact::Never, "{what}"),
            _ => assert!(until > 0.0 && until <= past.expect("pressed in"), "{what}"),
        }
    }
}

/// A still ball touched by a wall spinning about its normal, sliding,
/// leaving or pushed at it (the wall is A and rotates, the ball B does not:
/// B is cast against the half-space carried by A).
#[test]
fn the_roles_swap_when_only_the_second_body_rotates() {
    let d = 1e-3;
    let p = CaParams::<f64>::default().with_contact_distance(d);
    let r = 0.05;
    let ball = Convex::try_ball(r).expect("a ball");
    let hw = [0.02, 1.0, 1.0];
    let wall = Convex::try_cuboid(hw).expect("a wall");
    // The ball's support points along +-x as body points, for sampling.
    let ball_points: Vec<[f64; 3]> = (0..400)
        .map(|k| {
            let a = core::f64::consts::TAU * k as f64 / 400.0;
            [r * a.cos(), r * a.sin(), 0.0]
        })
        .collect();
    let ball_still = motion::<f64>([0.0; 3], ([0.0, 0.0, 1.0], 0.0), [0.0; 3], [0.0; 3]);
    let n = [1.0, 0.0, 0.0];
    for (vx, wx, deeper) in [(0.0, 5.0, false), (-2.0, 5.0, false), (2.0, 3.0, true)] {
        // The wall's face x = -r - gap: the wall is A (at the ball's left).
        let gap = 0.5 * d;
        let m = motion::<f64>(
            [-r - gap - 0.02, 0.0, 0.0],
            ([0.0, 0.0, 1.0], 0.0),
            [vx, 0.0, 0.0],
            [wx, 0.0, 0.0],
        );
        let answer = past_contact(
            Shape::Convex(wall),
            &m,
            Shape::Convex(ball),
            &ball_still,
            v3(n),
            &p,
        )
        .expect("a wall and a ball");
        let until = time_of(answer);
        let past = judge(
            &m,
            &corners(hw),
            &ball_still,
            &ball_points,
            n,
            d,
            until,
            "wall at ball",
        );
        if deeper {
            assert!(
                until > 0.0 && until <= past.expect("pushed in"),
                "{answer:?}"
            );
        } else {
            assert_eq!(answer, PastContact::Never);
        }
    }
    // Both rotate, the ball about its own centre: its turn moves nothing,
    // so it carries the half-space (Lemma 12.14) and the answer holds.
    let spin = motion::<f64>(
        [-r - 0.0005 - 0.02, 0.0, 0.0],
        ([0.0, 0.0, 1.0], 0.0),
        [0.0; 3],
        [0.0, 0.0, 1.0],
    );
    let ball_spin = motion::<f64>([0.0; 3], ([0.0, 0.0, 1.0], 0.0), [0.0; 3], [0.0, 1.0, 0.0]);
    let answer = past_contact(
        Shape::Convex(wall),
        &spin,
        Shape::Convex(ball),
        &ball_spin,
        v3(n),
        &p,
    )
    .expect("a wall and a ball");
    let until = time_of(answer);
    judge(
        &spin,
        &corners(hw),
        &ball_still,
        &ball_points,
        n,
        d,
        until,
        "spinning wall at spinning ball",
    );
    // Both rotate, both boxes turning fast: not decided here.
    let cube = Convex::try_cuboid([r; 3]).expect("a cube");
    let cube_spin = motion::<f64>([0.0; 3], ([0.0, 0.0, 1.0], 0.0), [0.0; 3], [0.0, 30.0, 0.0]);
    let answer = past_contact(
        Shape::Convex(wall),
        &spin,
        Shape::Convex(cube),
        &cube_spin,
        v3(n),
        &p,
    );
    assert_eq!(answer, Ok(PastContact::Undecided));
}

/// A pair already deeper than the contact distance along the normal is
/// held at the start (else a pair stopped at the plane every step would
/// creep in), unless the cast certifies it never reaches the plane.
#[test]
fn a_pair_deeper_than_the_contact_distance_is_held_at_the_start() {
    let d = 1e-3;
    let p = CaParams::<f64>::default().with_contact_distance(d);
    let board = Convex::try_cuboid([0.1, 0.4, 0.1]).expect("a board");
    let wall = Convex::try_cuboid([0.5, 2.0, 2.0]).expect("a wall");
    let still = motion::<f64>([1.0, 0.0, 0.0], ([1.0, 0.0, 0.0], 0.0), [0.0; 3], [0.0; 3]);
    let m = motion::<f64>(
        [0.5 - 0.1 + 3.0 * d, 0.0, 0.0],
        ([1.0, 0.0, 0.0], 0.0),
        [1.0, 0.0, 0.0],
        [0.0; 3],
    );
    let n = v3::<f64>([1.0, 0.0, 0.0]);
    let answer = past_contact(Shape::Convex(board), &m, Shape::Convex(wall), &still, n, &p);
    assert_eq!(answer, Ok(PastContact::At(0.0)));
}

/// Bad input is a typed error, not a panic.
#[test]
fn a_zero_or_nan_normal_and_mismatched_intervals_are_refused() {
    let p = CaParams::<f64>::default();
    let ball = Shape::Convex(Convex::try_ball(0.5).expect("a ball"));
    let m = motion::<f64>([0.0; 3], ([1.0, 0.0, 0.0], 0.0), [0.0; 3], [0.0; 3]);
    for n in [Vec3::ZERO, Vec3::new(f64::NAN, 0.0, 0.0)] {
        assert!(matches!(
            past_contact(ball, &m, ball, &m, n, &p),
            Err(CaError::Input(_))
        ));
    }
    let unit = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0; 3]).expect("a motion");
    let n = Vec3::new(1.0, 0.0, 0.0);
    assert_eq!(
        past_contact(ball, &m, ball, &unit, n, &p),
        Err(CaError::IntervalMismatch)
    );
}

// ---------------------------------------------------------------------------
// `ca::past_contact_below` (Lemma 12.14): the ceiling carried from step to
// step, and the closed form that decides a resting pair without a cast.

/// The overlap along `n` at `t`, sampled from the boxes' corners.
fn sampled_overlap<T: Float>(
    ma: &RigidMotion<T>,
    pa: &[[f64; 3]],
    mb: &RigidMotion<T>,
    pb: &[[f64; 3]],
    n: [f64; 3],
    t: f64,
) -> f64 {
    reach(ma, pa, n, t, true) - reach(mb, pb, n, t, false)
}

/// The sampling's own slack: a relative `1e-9` in `f64`; in `f32` the
/// placement's error, near `1e-5` of the contact distance here, and the
/// corners' rounding.
fn sampling_slack<T: Float>(d: f64) -> f64 {
    if T::UNIT_ROUNDOFF.to_f64() > 1e-10 {
        2e-2 * d
    } else {
        1e-9
    }
}

/// Boards at a wall and cubes on cubes (both turning), touching or
/// overlapping by up to `4 d` at the start, some with a ceiling carried
/// from a held step, moving at random (resting, sliding, pushed, spinning):
/// until the answer's time the sampled overlap stays below the report's
/// ceiling. Both the closed form and the cast decide some.
fn ceilings_hold<T: Float>() {
    let d = 1e-3;
    let p = CaParams::<T>::default().with_contact_distance(T::from_f64(d));
    let slack = sampling_slack::<T>(d);
    let mut rng = Rng(64);
    let (mut closed, mut cast, mut held, mut undecided) = (0, 0, 0, 0);
    for case in 0..600 {
        let kind = case % 6;
        // 0 to 2: a board at a still wall (resting, sliding or pushed, any
        // spin); 3 to 5: a cube on a cube, both turning (slowly for 3 and
        // 4, fast for 5).
        let (ha, hb, n) = if kind < 3 {
            ([0.1, 0.4, 0.1], [0.5, 2.0, 2.0], [1.0, 0.0, 0.0])
        } else {
            ([0.5, 0.5, 0.5], [0.5, 0.5, 0.5], [0.0, 0.0, -1.0])
        };
        let depth = rng.range(-0.9, 4.0) * d;
        let (xa, xb) = if kind < 3 {
            ([0.5 - 0.1 + depth, 0.0, 0.0], [1.0, 0.0, 0.0])
        } else {
            ([0.0, 0.0, 1.0 - depth], [0.0, 0.0, 0.0])
        };
        let small = |rng: &mut Rng, s: f64| rng.unit().map(|c| c * rng.range(0.0, s));
        let (va, wa, vb, wb) = match kind {
            // Resting, or pressed in by 0.2 to 1.5 contact distances over
            // the step (near where the closed form stops deciding).
            0 => {
                let press = if case % 12 < 6 {
                    0.0
                } else {
                    rng.range(0.2, 1.5) * d / DT
                };
                let v = small(&mut rng, 1e-3);
                (
                    [v[0] + press, v[1], v[2]],
                    small(&mut rng, 1e-2),
                    [0.0; 3],
                    [0.0; 3],
                )
            }
            1 => (
                [0.0, rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)],
                [rng.range(-80.0, 80.0), 0.0, 0.0],
                [0.0; 3],
                [0.0; 3],
            ),
            2 => (
                [rng.range(0.0, 3.0), rng.range(-1.0, 1.0), 0.0],
                small(&mut rng, 60.0),
                [0.0; 3],
                [0.0; 3],
            ),
            // Both turning at up to 0.4 and 0.15 rad/s: the second's turn
            // moves its extent by up to about the contact distance.
            3 => (
                small(&mut rng, 2e-3),
                rng.unit().map(|c| c * 0.4),
                small(&mut rng, 2e-3),
                rng.unit().map(|c| c * 0.15),
            ),
            // The upper cube sinking by 0.2 to 1.5 contact distances.
            // The upper cube sinking, both turning about level axes, the
            // lower one a little slower (it carries the half-space, its
            // corners rising by up to about the contact distance).
            4 => {
                let level = |rng: &mut Rng| {
                    let a = rng.range(0.0, core::f64::consts::TAU);
                    [a.cos(), a.sin(), 0.0]
                };
                let wb = rng.range(0.05, 0.15);
                (
                    [0.0, 0.0, -rng.range(0.2, 1.5) * d / DT],
                    level(&mut rng).map(|c| c * wb * 1.1),
                    [0.0; 3],
                    level(&mut rng).map(|c| c * wb),
                )
            }
            _ => (
                small(&mut rng, 1.0),
                small(&mut rng, 20.0),
                small(&mut rng, 1.0),
                small(&mut rng, 20.0),
            ),
        };
        let ma = motion::<T>(xa, ([1.0, 0.0, 0.0], rng.range(-0.01, 0.01)), va, wa);
        let mb = motion::<T>(xb, ([0.0, 1.0, 0.0], rng.range(-0.01, 0.01)), vb, wb);
        let (pa, pb) = (corners(ha), corners(hb));
        let start = sampled_overlap(&ma, &pa, &mb, &pb, n, 0.0);
        // Half the cases carry a ceiling (from a held step, at or above the
        // start's overlap as a held step leaves it; or from a step not
        // held, anywhere near it), the others none.
        let last = (case % 2 == 1).then(|| Ceiling {
            value: T::from_f64(start.max(0.0) + rng.range(-0.5, 2.0) * d),
            held: case % 4 == 1,
        });
        let (a, b) = (
            Shape::Convex(Convex::try_cuboid(ha.map(T::from_f64)).expect("a box")),
            Shape::Convex(Convex::try_cuboid(hb.map(T::from_f64)).expect("a box")),
        );
        // A floor of up to 3 d for a quarter of the fresh ones and for the
        // ceilings carried from steps not held.
        let floor = if case % 4 == 0 || case % 4 == 3 {
            rng.range(0.0, 3.0) * d
        } else {
            0.0
        };
        // The floor as `T` holds it.
        let floor = T::from_f64(floor).to_f64();
        let r = past_contact_below(a, &ma, b, &mb, v3(n), last, T::from_f64(floor), &p)
            .expect("two boxes");
        let ceiling = r.ceiling.value.to_f64();
        assert!(
            r.overlap.to_f64() >= start,
            "case {case}: overlap {:?} below the sampled {start}",
            r.overlap
        );
        if let Some(l) = last.filter(|l| l.held) {
            assert_eq!(
                r.ceiling.value, l.value,
                "case {case}: a held ceiling is kept"
            );
        } else if let Some(l) = last {
            // Carried, not held: never above the last one (or the floor).
            let l = l.value.to_f64();
            assert!(
                ceiling <= l.max(floor) && ceiling >= floor,
                "case {case}: ceiling {ceiling}, last {l}, floor {floor}"
            );
        } else {
            assert!(
                ceiling <= (start.max(0.0) + d).max(floor) + 5.0 * slack && ceiling >= floor,
                "case {case}: ceiling {ceiling}, start {start}, overlap {:?}",
                r.overlap
            );
        }
        let until = match r.answer {
            PastContact::Never => f64::INFINITY,
            PastContact::At(t) => t.to_f64(),
            _ => {
                undecided += 1;
                continue;
            }
        };
        closed += usize::from(!r.cast);
        cast += usize::from(r.cast);
        held += usize::from(until < f64::INFINITY);
        for k in 0..=SAMPLES {
            let t = DT * k as f64 / SAMPLES as f64;
            if t >= until {
                break;
            }
            let o = sampled_overlap(&ma, &pa, &mb, &pb, n, t);
            assert!(
                o < ceiling + slack,
                "case {case} (kind {kind}): at t = {t} (answer's time {until}) the overlap {o} \
                 reached the ceiling {ceiling}"
            );
        }
    }
    assert!(
        closed >= 60 && cast >= 150 && held >= 80 && undecided >= 20,
        "closed form {closed}, cast {cast}, held {held}, undecided {undecided}"
    );
}

#[test]
fn a_ceiling_is_never_passed_before_the_answers_time_f64() {
    ceilings_hold::<f64>();
}

#[test]
fn a_ceiling_is_never_passed_before_the_answers_time_f32() {
    ceilings_hold::<f32>();
}

/// A board pushed into a wall at 0.5 m/s (8 contact distances a step),
/// spinning about the normal, stepped 60 times as an engine's pass does:
/// each step's motion from where the last one stopped it, stopped at the
/// answer's time, the ceiling carried. The sampled overlap never passes
/// the first step's ceiling (or the floor, an overlap always allowed, when
/// that is more): a held pair does not creep in. Without the carried
/// ceiling (each step's own start plus `d`) it creeps by about `d / 2` a
/// step and fails.
fn a_held_pair_stays_below_its_ceiling<T: Float>(floor: f64, forget_held: bool) {
    let d = 1e-3;
    let p = CaParams::<T>::default().with_contact_distance(T::from_f64(d));
    let slack = sampling_slack::<T>(d);
    let (hb, hw) = ([0.1, 0.4, 0.1], [0.5, 2.0, 2.0]);
    let board = Shape::Convex(Convex::try_cuboid(hb.map(T::from_f64)).expect("a board"));
    let wall = Shape::Convex(Convex::try_cuboid(hw.map(T::from_f64)).expect("a wall"));
    let still = motion::<T>([1.0, 0.0, 0.0], ([1.0, 0.0, 0.0], 0.0), [0.0; 3], [0.0; 3]);
    let n = [1.0, 0.0, 0.0];
    let (v, w) = ([0.5, 0.3, 0.0], [20.0, 0.0, 0.0]);
    let (mut x, mut angle) = ([0.5 - 0.1 - 0.5 * d, 0.0, 0.0], 0.3);
    let mut last: Option<Ceiling<T>> = None;
    let mut first = None;
    let mut holds = 0;
    for step in 0..60 {
        let m = motion::<T>(x, ([1.0, 0.0, 0.0], angle), v, w);
        let r = past_contact_below(board, &m, wall, &still, v3(n), last, T::from_f64(floor), &p)
            .expect("a board");
        let ceiling = *first.get_or_insert(r.ceiling.value.to_f64());
        let until = match r.answer {
            PastContact::Never => DT,
            PastContact::At(t) => t.to_f64(),
            other => panic!("step {step}: {other:?}"),
        };
        holds += usize::from(until < DT);
        for k in 0..=SAMPLES {
            let t = until * k as f64 / SAMPLES as f64;
            let o = sampled_overlap(&m, &corners(hb), &still, &corners(hw), n, t);
            assert!(
                o < ceiling + slack,
                "step {step}: the overlap {o} crept past the first ceiling {ceiling}"
            );
        }
        // Stopped at the answer's time: the next step starts there.
        x = [
            x[0] + v[0] * until,
            x[1] + v[1] * until,
            x[2] + v[2] * until,
        ];
        angle += w[0] * until;
        // A caller that drops the held flag still carries the value: the
        // ceiling never rises above it.
        last = Some(Ceiling {
            held: r.ceiling.held && !forget_held,
            ..r.ceiling
        });
    }
    assert!(holds >= 50, "held in {holds} steps of 60");
}

#[test]
fn a_held_pair_does_not_creep_in_a_step_at_a_time_f64() {
    a_held_pair_stays_below_its_ceiling::<f64>(0.0, false);
    a_held_pair_stays_below_its_ceiling::<f64>(3e-3, false);
    a_held_pair_stays_below_its_ceiling::<f64>(0.0, true);
}

#[test]
fn a_held_pair_does_not_creep_in_a_step_at_a_time_f32() {
    a_held_pair_stays_below_its_ceiling::<f32>(0.0, false);
    a_held_pair_stays_below_its_ceiling::<f32>(3e-3, false);
    a_held_pair_stays_below_its_ceiling::<f32>(0.0, true);
}

/// A ball spinning fast about its centre (or about a point near it), resting
/// on a slowly turning box or sliding over it: the spin about the centre
/// costs the closed form nothing (a ball's extent does not turn), so a
/// resting ball is decided without a cast; until the answer's time the
/// overlap, sampled from the ball's centre and the box's corners, stays
/// below the ceiling.
fn a_spinning_ball_on_a_box<T: Float>() {
    let d = 1e-3;
    let p = CaParams::<T>::default().with_contact_distance(T::from_f64(d));
    let slack = sampling_slack::<T>(d);
    let r = 0.1;
    let hb = [0.5, 0.5, 0.5];
    let ball = Shape::Convex(Convex::try_ball(T::from_f64(r)).expect("a ball"));
    let cube = Shape::Convex(Convex::try_cuboid(hb.map(T::from_f64)).expect("a box"));
    let n = [0.0, 0.0, -1.0];
    let mut rng = Rng(641);
    let (mut closed, mut decided) = (0, 0);
    for case in 0..200 {
        let depth = rng.range(-0.5, 2.0) * d;
        // About its centre (even cases) or a point 2e-3 off it.
        let off = if case % 2 == 0 { 0.0 } else { 2e-3 };
        let w = rng.unit().map(|c| c * rng.range(0.0, 200.0));
        let v = [
            rng.range(-2.0, 2.0),
            rng.range(-2.0, 2.0),
            rng.range(-1e-3, 1e-3),
        ];
        let start = Isometry::try_new(Rotation::IDENTITY, v3::<T>([0.0, 0.0, 0.5 + r - depth]))
            .expect("a pose");
        let ma = RigidMotion::try_from_start(start, v3(v), v3(w), T::from_f64(DT))
            .and_then(|m| m.try_with_local_centre(v3([off, 0.0, 0.0])))
            .expect("a motion");
        let mb = motion::<T>(
            [0.0; 3],
            ([0.0, 1.0, 0.0], rng.range(-0.01, 0.01)),
            [0.0; 3],
            rng.unit().map(|c| c * rng.range(0.0, 5e-3)),
        );
        let res =
            past_contact_below(ball, &ma, cube, &mb, v3(n), None, T::ZERO, &p).expect("a ball");
        let ceiling = res.ceiling.value.to_f64();
        let until = match res.answer {
            PastContact::Never => f64::INFINITY,
            PastContact::At(t) => t.to_f64(),
            _ => continue,
        };
        decided += 1;
        closed += usize::from(!res.cast);
        let centre = [[0.0; 3]];
        for k in 0..=SAMPLES {
            let t = DT * k as f64 / SAMPLES as f64;
            if t >= until {
                break;
            }
            let o = reach(&ma, &centre, n, t, true) + r - reach(&mb, &corners(hb), n, t, false);
            assert!(
                o < ceiling + slack,
                "case {case}: at t = {t} the overlap {o} reached the ceiling {ceiling}"
            );
        }
    }
    // Every spin about the centre decided by the closed form.
    assert!(
        closed >= 100 && decided >= 100,
        "closed form {closed}, decided {decided}"
    );
}

#[test]
fn a_spinning_ball_resting_on_a_box_is_decided_without_a_cast_f64() {
    a_spinning_ball_on_a_box::<f64>();
}

#[test]
fn a_spinning_ball_resting_on_a_box_is_decided_without_a_cast_f32() {
    a_spinning_ball_on_a_box::<f32>();
}
