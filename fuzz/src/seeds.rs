//! Hand-crafted seed inputs for the hard cases, encoded in `arbitrary`'s
//! byte format (so that each decodes to exactly the intended typed value;
//! `examples/make_seeds.rs` writes them to `corpus/` and checks that by
//! decoding every seed again).
//!
//! The format, as `arbitrary` 1.x reads it: integers little-endian in their
//! width, floats as their bit patterns, `bool` as one byte (low bit), an enum
//! as a `u32` `x` selecting variant `(x * count) >> 32` followed by the
//! variant's fields, a struct or tuple as its fields in order, an array as
//! its elements, and a `Vec` (not in last position) as `1, element` per
//! element followed by a `0`.

use motion_bound::testkit::{CaseSpec, Layout, Normal, Sweep};

use crate::inputs::{MotionCase, MotionInput, RawInput, ValidationCase};
use crate::Num;

/// An `arbitrary` byte-format encoder.
#[derive(Clone, Debug, Default)]
pub struct Enc(pub Vec<u8>);

impl Enc {
    /// One byte.
    pub fn u8(&mut self, x: u8) -> &mut Self {
        self.0.push(x);
        self
    }
    /// One signed byte.
    pub fn i8(&mut self, x: i8) -> &mut Self {
        self.0.extend(x.to_le_bytes());
        self
    }
    /// A bool.
    pub fn bool(&mut self, x: bool) -> &mut Self {
        self.u8(u8::from(x))
    }
    /// A `u16`.
    pub fn u16(&mut self, x: u16) -> &mut Self {
        self.0.extend(x.to_le_bytes());
        self
    }
    /// A `u32`.
    pub fn u32(&mut self, x: u32) -> &mut Self {
        self.0.extend(x.to_le_bytes());
        self
    }
    /// An `i32`.
    pub fn i32(&mut self, x: i32) -> &mut Self {
        self.0.extend(x.to_le_bytes());
        self
    }
    /// An `f64`.
    pub fn f64(&mut self, x: f64) -> &mut Self {
        self.0.extend(x.to_bits().to_le_bytes());
        self
    }
    /// An `f32`.
    pub fn f32(&mut self, x: f32) -> &mut Self {
        self.0.extend(x.to_bits().to_le_bytes());
        self
    }
    /// `[f64; 3]`.
    pub fn f64x3(&mut self, a: [f64; 3]) -> &mut Self {
        for x in a {
            self.f64(x);
        }
        self
    }
    /// The discriminant of variant `idx` of an enum of `count` variants.
    pub fn variant(&mut self, idx: u32, count: u32) -> &mut Self {
        let x = ((u64::from(idx) << 32) + u64::from(count) - 1) / u64::from(count);
        let x = u32::try_from(x).expect("variant index below count");
        self.u32(x)
    }
}

/// Encodes a [`CaseSpec`].
pub fn case_spec(e: &mut Enc, s: &CaseSpec) {
    for v in &s.vertices {
        e.bool(true).f64x3(*v);
    }
    e.bool(false);
    let layout = match s.layout {
        Layout::Blob => 0,
        Layout::OnAxis => 1,
        Layout::HalfOnAxis => 2,
        Layout::InPlane => 3,
        Layout::FarFromCentre => 4,
        Layout::Single => 5,
    };
    e.variant(layout, 6);
    e.i8(s.size_exp)
        .f64x3(s.axis)
        .i8(s.omega_exp)
        .f64(s.omega_frac);
    match s.sweep {
        Sweep::Free(x) => e.variant(0, 3).f64(x),
        Sweep::NearMultipleOfPi { k, ulps } => e.variant(1, 3).u8(k).i8(ulps),
        Sweep::Tiny(x) => e.variant(2, 3).u8(x),
    };
    e.f64(s.start);
    match s.normal {
        Normal::Free(v) => e.variant(0, 4).f64x3(v),
        Normal::NearlyParallel { towards, ulps } => e.variant(1, 4).f64x3(towards).u8(ulps),
        Normal::Parallel => e.variant(2, 4),
        Normal::Orthogonal(v) => e.variant(3, 4).f64x3(v),
    };
    e.f64x3(s.linear).i8(s.linear_exp);
}

/// A float type `arbitrary` encodes by its bits.
pub trait Bits: Copy {
    /// Appends the bit pattern.
    fn put(self, e: &mut Enc);
}
impl Bits for f32 {
    fn put(self, e: &mut Enc) {
        e.f32(self);
    }
}
impl Bits for f64 {
    fn put(self, e: &mut Enc) {
        e.f64(self);
    }
}

/// Encodes a [`Num`].
pub fn num<T: Bits>(e: &mut Enc, n: &Num<T>) {
    match *n {
        Num::Raw(x) => {
            e.variant(0, 3);
            x.put(e);
        }
        Num::Moderate { mant, exp } => {
            e.variant(1, 3).i32(mant).i8(exp);
        }
        Num::Special(i) => {
            e.variant(2, 3).u8(i);
        }
    }
}

fn nums<T: Bits>(e: &mut Enc, a: &[Num<T>]) {
    for n in a {
        num(e, n);
    }
}

/// Encodes a [`MotionInput`].
pub fn motion_input<T: Bits>(e: &mut Enc, m: &MotionInput<T>) {
    nums(e, &m.centre);
    nums(e, &m.linear);
    nums(e, &m.angular);
    nums(e, &m.interval);
    nums(e, &m.point);
    nums(e, &m.times);
    nums(e, &m.sub);
    nums(e, &m.n);
}

/// Encodes a [`MotionCase`].
pub fn motion_case(e: &mut Enc, m: &MotionCase) {
    match m {
        MotionCase::Single(x) => {
            e.variant(0, 2);
            motion_input(e, x);
        }
        MotionCase::Double(x) => {
            e.variant(1, 2);
            motion_input(e, x);
        }
    }
}

/// Encodes a [`RawInput`].
pub fn raw_input<T: Bits>(e: &mut Enc, r: &RawInput<T>) {
    for v in &r.vertices {
        e.bool(true);
        nums(e, v);
    }
    e.bool(false);
    num(e, &r.radius);
    nums(e, &r.n);
    nums(e, &r.interval);
    nums(e, &r.centre);
    nums(e, &r.linear);
    nums(e, &r.angular);
    nums(e, &r.sub);
    num(e, &r.gap);
}

/// Encodes a [`ValidationCase`].
pub fn validation_case(e: &mut Enc, v: &ValidationCase) {
    match v {
        ValidationCase::Single(x) => {
            e.variant(0, 2);
            raw_input(e, x);
        }
        ValidationCase::Double(x) => {
            e.variant(1, 2);
            raw_input(e, x);
        }
    }
}

/// A unit-ish blob of eight vertices (a slightly irregular cube).
#[must_use]
pub fn blob() -> Vec<[f64; 3]> {
    let mut v = Vec::new();
    for i in 0..8u32 {
        let s = |k: u32| if i >> k & 1 == 1 { 0.5 } else { -0.5 };
        v.push([
            s(0) + 0.01 * f64::from(i),
            s(1),
            s(2) - 0.003 * f64::from(i),
        ]);
    }
    v
}

/// A plain case: the blob, spinning about a tilted axis, at unit scale.
#[must_use]
pub fn base_spec() -> CaseSpec {
    CaseSpec {
        vertices: blob(),
        layout: Layout::Blob,
        size_exp: 0,
        axis: [0.3, -0.4, 0.8],
        omega_exp: 0,
        omega_frac: 0.25,
        sweep: Sweep::Free(1.0),
        start: 0.0,
        normal: Normal::Free([0.6, 0.7, -0.2]),
        linear: [0.2, -0.1, 0.05],
        linear_exp: 0,
    }
}

/// The hard `CaseSpec`s, named: sweeps within ulps of pi and 2 pi (and 3 pi,
/// 4 pi), `n` parallel, nearly parallel and orthogonal to `w`, vertices on
/// the axis or in the rotation plane, a small body far from the centre, tiny
/// and huge `|w|` and body sizes, tiny sweeps, intervals away from the epoch.
#[must_use]
pub fn hard_specs() -> Vec<(String, CaseSpec)> {
    let mut out = Vec::new();
    let base = base_spec();
    out.push(("plain".to_string(), base.clone()));
    for k in 0..4u8 {
        for ulps in [-64i8, -1, 0, 1] {
            for (lname, layout) in [
                ("blob", Layout::Blob),
                ("plane", Layout::InPlane),
                ("single", Layout::Single),
            ] {
                let mut s = base.clone();
                s.sweep = Sweep::NearMultipleOfPi { k, ulps };
                s.layout = layout;
                if k % 2 == 1 {
                    s.start = 0.5;
                }
                out.push((format!("sweep-{}pi{ulps:+}ulp-{lname}", k + 1), s));
            }
        }
    }
    for (nname, normal) in [
        ("parallel", Normal::Parallel),
        (
            "nearly-parallel-1",
            Normal::NearlyParallel {
                towards: [1.0, 0.0, 0.0],
                ulps: 1,
            },
        ),
        (
            "nearly-parallel-64",
            Normal::NearlyParallel {
                towards: [0.0, 1.0, 0.3],
                ulps: 64,
            },
        ),
        ("orthogonal", Normal::Orthogonal([0.1, 0.9, 0.4])),
    ] {
        for (sname, sweep) in [
            ("pi", Sweep::NearMultipleOfPi { k: 0, ulps: 0 }),
            ("free", Sweep::Free(2.5)),
            ("tiny", Sweep::Tiny(12)),
        ] {
            for omega_exp in [-12i8, 0, 4] {
                let mut s = base.clone();
                s.normal = normal;
                s.sweep = sweep;
                s.omega_exp = omega_exp;
                out.push((format!("n-{nname}-sweep-{sname}-w1e{omega_exp}"), s));
            }
        }
    }
    for (lname, layout) in [
        ("on-axis", Layout::OnAxis),
        ("half-on-axis", Layout::HalfOnAxis),
        ("in-plane", Layout::InPlane),
        ("far-from-centre", Layout::FarFromCentre),
        ("single", Layout::Single),
    ] {
        for size_exp in [-12i8, 0, 12] {
            let mut s = base.clone();
            s.layout = layout;
            s.size_exp = size_exp;
            s.sweep = Sweep::NearMultipleOfPi { k: 1, ulps: -1 };
            out.push((format!("layout-{lname}-size1e{size_exp}"), s));
        }
    }
    for (name, f) in [
        (
            "tiny-w-huge-body",
            (|s: &mut CaseSpec| {
                s.omega_exp = -12;
                s.size_exp = 12;
            }) as fn(&mut CaseSpec),
        ),
        ("huge-w-tiny-body", |s| {
            s.omega_exp = 4;
            s.omega_frac = 1.0;
            s.size_exp = -12;
        }),
        ("tiny-sweep-1e-15", |s| s.sweep = Sweep::Tiny(12)),
        ("tiny-sweep-1e-3", |s| s.sweep = Sweep::Tiny(0)),
        ("long-sweep-20", |s| s.sweep = Sweep::Free(20.0)),
        ("zero-sweep", |s| s.sweep = Sweep::Free(0.0)),
        ("late-interval", |s| {
            s.start = 4.0;
            s.sweep = Sweep::NearMultipleOfPi { k: 0, ulps: 1 };
        }),
        ("no-linear", |s| s.linear = [0.0; 3]),
        ("linear-dominates", |s| s.linear_exp = 6),
        ("linear-negligible", |s| s.linear_exp = -6),
        ("linear-along-n", |s| {
            s.linear = [0.6, 0.7, -0.2];
            s.linear_exp = 0;
        }),
        ("vertex-at-centre", |s| {
            s.vertices = vec![[0.0; 3]];
            s.layout = Layout::Single;
        }),
        ("empty-vertices", |s| s.vertices.clear()),
        ("axis-aligned", |s| {
            s.axis = [0.0, 0.0, 1.0];
            s.normal = Normal::Free([1.0, 0.0, 0.0]);
            s.vertices = vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.5]];
        }),
        ("axis-aligned-half-turn", |s| {
            s.axis = [0.0, 0.0, 1.0];
            s.normal = Normal::Free([1.0, 0.0, 0.0]);
            s.vertices = vec![[0.0, 1.0, 0.0]];
            s.sweep = Sweep::NearMultipleOfPi { k: 0, ulps: 0 };
        }),
        ("non-finite-raw", |s| {
            s.vertices = vec![
                [f64::NAN, f64::INFINITY, -f64::INFINITY],
                [1e300, -1e300, 5e-324],
            ];
            s.axis = [f64::NAN, 0.0, 0.0];
            s.omega_frac = f64::INFINITY;
            s.start = f64::NAN;
            s.linear = [f64::MAX, f64::MIN, f64::NAN];
            s.sweep = Sweep::Free(f64::INFINITY);
        }),
        ("extreme-exponents", |s| {
            s.size_exp = i8::MAX;
            s.omega_exp = i8::MIN;
            s.linear_exp = i8::MAX;
        }),
    ] {
        let mut s = base.clone();
        f(&mut s);
        out.push((name.to_string(), s));
    }
    out
}

fn m<T>(c: [Num<T>; 3]) -> [Num<T>; 3] {
    c
}

/// Hard inputs for the `motion` target.
#[must_use]
pub fn motion_cases() -> Vec<(String, MotionCase)> {
    use Num::{Moderate as Mo, Raw, Special as Sp};
    let one = |x: f64| Raw(x);
    let mut out = Vec::new();
    let base = MotionInput::<f64> {
        centre: m([one(1.0), one(2.0), one(3.0)]),
        linear: m([one(0.5), one(0.0), one(-0.25)]),
        angular: m([one(0.0), one(0.0), one(core::f64::consts::PI)]),
        interval: [one(0.0), one(1.0)],
        point: m([one(1.0), one(0.0), one(0.5)]),
        times: [one(0.5), one(0.25)],
        sub: [one(0.25), one(0.75)],
        n: m([one(0.0), one(1.0), one(0.0)]),
    };
    out.push(("plain-f64".to_string(), MotionCase::Double(base.clone())));
    let mut v = base.clone();
    v.angular = m([Sp(7), Sp(8), Sp(7)]);
    v.point = m([Sp(7), Sp(8), Sp(7)]);
    v.times = [Sp(7), Sp(8)];
    out.push(("max-input-everywhere".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.angular = m([Sp(9), one(0.0), one(0.0)]);
    out.push(("w-above-max-input".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.linear = m([one(0.0), Sp(20), one(0.0)]);
    out.push(("v-nan".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.centre = m([Sp(18), one(0.0), Sp(9)]);
    out.push(("centre-inf".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.angular = m([Sp(10), Sp(10), Sp(10)]);
    v.times = [Sp(7), Sp(8)];
    out.push(("w-tiny-length-long-time".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.angular = m([one(3e-162), one(0.0), one(0.0)]);
    v.times = [Sp(7), one(1e150)];
    out.push(("w-square-subnormal".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.point = m([Sp(13), Sp(14), Sp(15)]);
    out.push(("point-subnormal".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.point = m([Sp(16), Sp(18), Sp(20)]);
    v.times = [Sp(19), Sp(16)];
    out.push((
        "point-and-time-non-finite".to_string(),
        MotionCase::Double(v),
    ));
    let mut v = base.clone();
    v.angular = m([
        Mo {
            mant: 1 << 30,
            exp: 5,
        },
        Mo { mant: -3, exp: -60 },
        Mo {
            mant: i32::MAX,
            exp: 0,
        },
    ]);
    v.times = [
        one(1e3),
        Mo {
            mant: i32::MIN,
            exp: 10,
        },
    ];
    out.push(("moderate-values".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.sub = [one(0.75), one(0.25)];
    out.push(("restrict-reversed".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.sub = [one(-0.5), one(0.5)];
    out.push(("restrict-outside".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.sub = [Sp(20), one(0.5)];
    out.push(("restrict-nan".to_string(), MotionCase::Double(v)));
    let mut v = base.clone();
    v.angular = m([one(0.0), one(0.0), one(0.0)]);
    out.push(("no-rotation".to_string(), MotionCase::Double(v)));

    let base32 = MotionInput::<f32> {
        centre: m([Raw(1.0), Raw(2.0), Raw(3.0)]),
        linear: m([Raw(0.5), Raw(0.0), Raw(-0.25)]),
        angular: m([Raw(0.0), Raw(0.0), Raw(core::f32::consts::PI)]),
        interval: [Raw(0.0), Raw(1.0)],
        point: m([Raw(1.0), Raw(0.0), Raw(0.5)]),
        times: [Raw(0.5), Raw(0.25)],
        sub: [Raw(0.25), Raw(0.75)],
        n: m([Raw(0.0), Raw(1.0), Raw(0.0)]),
    };
    out.push(("plain-f32".to_string(), MotionCase::Single(base32.clone())));
    let mut v = base32.clone();
    v.angular = m([Sp(7), Sp(8), Sp(7)]);
    v.point = m([Sp(7), Sp(8), Sp(7)]);
    v.times = [Sp(7), Sp(8)];
    out.push((
        "max-input-everywhere-f32".to_string(),
        MotionCase::Single(v),
    ));
    let mut v = base32.clone();
    v.angular = m([Raw(3e-23), Raw(0.0), Raw(0.0)]);
    v.times = [Sp(7), Raw(1e17)];
    out.push(("w-square-subnormal-f32".to_string(), MotionCase::Single(v)));
    let mut v = base32.clone();
    v.point = m([Sp(13), Sp(14), Sp(15)]);
    v.angular = m([Sp(10), Sp(11), Sp(12)]);
    out.push(("tiny-everything-f32".to_string(), MotionCase::Single(v)));
    out
}

/// Hard inputs for the `validation` target.
#[must_use]
pub fn validation_cases() -> Vec<(String, ValidationCase)> {
    use Num::{Raw, Special as Sp};
    let mut out = Vec::new();
    let base = RawInput::<f64> {
        vertices: vec![
            [Raw(1.0), Raw(0.0), Raw(0.0)],
            [Raw(0.0), Raw(-1.0), Raw(0.5)],
            [Raw(-0.3), Raw(0.2), Raw(-0.9)],
        ],
        radius: Raw(2.0),
        n: [Raw(1.0), Raw(1.0), Raw(0.0)],
        interval: [Raw(0.0), Raw(1.0)],
        centre: [Raw(0.0), Raw(0.0), Raw(0.0)],
        linear: [Raw(0.3), Raw(0.0), Raw(-1.0)],
        angular: [Raw(0.0), Raw(0.5), Raw(2.0)],
        sub: [Raw(0.25), Raw(0.5)],
        gap: Raw(0.1),
    };
    out.push((
        "plain-f64".to_string(),
        ValidationCase::Double(base.clone()),
    ));
    let mut v = base.clone();
    v.vertices.clear();
    out.push(("empty-vertices".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.vertices.push([Sp(20), Raw(0.0), Raw(0.0)]);
    v.vertices.push([Sp(9), Raw(0.0), Raw(0.0)]);
    out.push((
        "vertex-nan-then-huge".to_string(),
        ValidationCase::Double(v),
    ));
    let mut v = base.clone();
    v.vertices.push([Sp(9), Sp(18), Raw(0.0)]);
    out.push(("vertex-huge-and-inf".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.radius = Sp(1);
    v.n = [Sp(1), Sp(0), Sp(1)];
    out.push((
        "negative-zero-radius-zero-direction".to_string(),
        ValidationCase::Double(v),
    ));
    let mut v = base.clone();
    v.radius = Sp(8);
    v.n = [Sp(16), Sp(17), Sp(16)];
    out.push((
        "radius-min-input-direction-max".to_string(),
        ValidationCase::Double(v),
    ));
    let mut v = base.clone();
    v.n = [Sp(13), Sp(14), Sp(13)];
    out.push(("direction-subnormal".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.interval = [Raw(1.0), Raw(0.0)];
    out.push(("interval-reversed".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.interval = [Sp(8), Sp(7)];
    v.angular = [Sp(7), Sp(7), Sp(7)];
    v.linear = [Sp(8), Sp(7), Sp(8)];
    v.vertices = vec![[Sp(7), Sp(8), Sp(7)]];
    v.radius = Sp(7);
    out.push((
        "max-input-everywhere".to_string(),
        ValidationCase::Double(v),
    ));
    let mut v = base.clone();
    v.angular = [Sp(10), Sp(11), Sp(10)];
    v.interval = [Sp(8), Sp(7)];
    out.push(("w-at-tiny-length".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.angular = [Sp(13), Sp(15), Sp(12)];
    v.vertices = vec![[Sp(13), Sp(12), Sp(15)], [Sp(7), Sp(0), Sp(0)]];
    out.push((
        "underflow-everywhere".to_string(),
        ValidationCase::Double(v),
    ));
    let mut v = base.clone();
    v.n = [Raw(0.0), Raw(0.5), Raw(2.0)];
    v.sub = [Sp(0), Sp(2)];
    out.push(("n-parallel-to-w".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.interval = [Raw(0.0), Sp(6)];
    v.angular = [Raw(0.0), Raw(0.0), Raw(1.0)];
    v.n = [Raw(1.0), Raw(0.0), Raw(0.0)];
    out.push(("full-turn".to_string(), ValidationCase::Double(v)));
    let mut v = base.clone();
    v.gap = Sp(18);
    v.linear = [Raw(0.0); 3];
    v.angular = [Raw(0.0); 3];
    out.push((
        "at-rest-infinite-gap".to_string(),
        ValidationCase::Double(v),
    ));

    let base32 = RawInput::<f32> {
        vertices: vec![
            [Raw(1.0), Raw(0.0), Raw(0.0)],
            [Raw(0.0), Raw(-1.0), Raw(0.5)],
            [Raw(-0.3), Raw(0.2), Raw(-0.9)],
        ],
        radius: Raw(2.0),
        n: [Raw(1.0), Raw(1.0), Raw(0.0)],
        interval: [Raw(0.0), Raw(1.0)],
        centre: [Raw(0.0), Raw(0.0), Raw(0.0)],
        linear: [Raw(0.3), Raw(0.0), Raw(-1.0)],
        angular: [Raw(0.0), Raw(0.5), Raw(2.0)],
        sub: [Raw(0.25), Raw(0.5)],
        gap: Raw(0.1),
    };
    out.push((
        "plain-f32".to_string(),
        ValidationCase::Single(base32.clone()),
    ));
    let mut v = base32.clone();
    v.angular = [Sp(13), Sp(15), Sp(12)];
    v.vertices = vec![[Sp(13), Sp(12), Sp(15)], [Sp(7), Sp(0), Sp(0)]];
    out.push((
        "underflow-everywhere-f32".to_string(),
        ValidationCase::Single(v),
    ));
    let mut v = base32.clone();
    v.angular = [Sp(10), Sp(11), Sp(10)];
    v.linear = [Sp(13), Sp(0), Sp(0)];
    out.push((
        "w-at-tiny-length-f32".to_string(),
        ValidationCase::Single(v),
    ));
    let mut v = base32.clone();
    v.interval = [Sp(8), Sp(7)];
    v.angular = [Sp(7), Sp(7), Sp(7)];
    v.linear = [Sp(8), Sp(7), Sp(8)];
    v.vertices = vec![[Sp(7), Sp(8), Sp(7)]];
    out.push((
        "max-input-everywhere-f32".to_string(),
        ValidationCase::Single(v),
    ));
    let mut v = base32;
    v.n = [Raw(0.0), Raw(0.5), Raw(2.0)];
    v.interval = [Raw(0.0), Sp(6)];
    out.push((
        "n-parallel-to-w-full-turn-f32".to_string(),
        ValidationCase::Single(v),
    ));
    out
}
