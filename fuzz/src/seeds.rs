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

use motion_bound::testkit::{BodyFrame, CaseSpec, Layout, Normal, Sweep};

use crate::inputs::{MotionCase, MotionInput, Precisions, RawInput, ValidationCase};
use crate::{Num, Precision};

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
        let x = (u64::from(idx) << 32).div_ceil(u64::from(count));
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
    match s.frame {
        BodyFrame::World => e.variant(0, 3),
        BodyFrame::Oriented(q) => {
            e.variant(1, 3);
            q.iter().for_each(|&x| {
                e.f64(x);
            });
            e
        }
        BodyFrame::OrientedAbout(q, c) => {
            e.variant(2, 3);
            q.iter().for_each(|&x| {
                e.f64(x);
            });
            e.f64x3(c)
        }
    };
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

/// Encodes a [`Precisions`] value with the encoder of each variant.
pub fn precisions<S, D>(
    e: &mut Enc,
    x: &Precisions<S, D>,
    single: fn(&mut Enc, &S),
    double: fn(&mut Enc, &D),
) {
    match x {
        Precisions::Single(x) => {
            e.variant(0, 2);
            single(e, x);
        }
        Precisions::Double(x) => {
            e.variant(1, 2);
            double(e, x);
        }
    }
}

/// Encodes a [`MotionCase`].
pub fn motion_case(e: &mut Enc, m: &MotionCase) {
    precisions(e, m, motion_input, motion_input);
}

/// Encodes a [`ValidationCase`].
pub fn validation_case(e: &mut Enc, v: &ValidationCase) {
    precisions(e, v, raw_input, raw_input);
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
        frame: BodyFrame::World,
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
        ("oriented", |s| {
            s.frame = BodyFrame::Oriented([0.3, -0.5, 0.7, 0.2]);
        }),
        ("oriented-about-off-centre", |s| {
            s.frame = BodyFrame::OrientedAbout([-0.9, 0.1, 0.3, -0.2], [0.8, -0.3, 0.5]);
            s.sweep = Sweep::NearMultipleOfPi { k: 1, ulps: -1 };
        }),
        ("oriented-near-parallel", |s| {
            s.frame = BodyFrame::Oriented([0.5, 0.5, -0.5, 0.5]);
            s.normal = Normal::NearlyParallel {
                towards: [0.0, 1.0, 0.0],
                ulps: 2,
            };
        }),
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

/// A seed: its name and how it changes the base input.
type Variant<X> = (&'static str, fn(&mut X));

/// The base input with each variant applied, named `NAME-f32` / `NAME-f64`.
fn variants<T: Precision, X: Clone>(base: &X, list: &[Variant<X>]) -> Vec<(String, X)> {
    list.iter()
        .map(|(name, f)| {
            let mut x = base.clone();
            f(&mut x);
            (format!("{name}-{}", T::NAME), x)
        })
        .collect()
}

/// The same seeds in both precisions.
fn in_both<S, D>(
    single: Vec<(String, S)>,
    double: Vec<(String, D)>,
) -> Vec<(String, Precisions<S, D>)> {
    let single = single.into_iter().map(|(n, x)| (n, Precisions::Single(x)));
    let double = double.into_iter().map(|(n, x)| (n, Precisions::Double(x)));
    single.chain(double).collect()
}

/// `x` as an exact-or-nearest raw value of precision `T`.
fn raw<T: Precision>(x: f64) -> Num<T> {
    Num::Raw(T::from_f64(x))
}

/// Hard inputs for the `motion` target in precision `T`.
fn motion_inputs<T: Precision>() -> Vec<(String, MotionInput<T>)> {
    use Num::{Moderate as Mo, Special as Sp};
    let base = MotionInput::<T> {
        centre: [raw(1.0), raw(2.0), raw(3.0)],
        linear: [raw(0.5), raw(0.0), raw(-0.25)],
        angular: [raw(0.0), raw(0.0), Num::Raw(T::PI)],
        interval: [raw(0.0), raw(1.0)],
        point: [raw(1.0), raw(0.0), raw(0.5)],
        times: [raw(0.5), raw(0.25)],
        sub: [raw(0.25), raw(0.75)],
        n: [raw(0.0), raw(1.0), raw(0.0)],
    };
    variants::<T, _>(
        &base,
        &[
            ("plain", |_| {}),
            ("max-input-everywhere", |v| {
                v.angular = [Sp(7), Sp(8), Sp(7)];
                v.point = [Sp(7), Sp(8), Sp(7)];
                v.times = [Sp(7), Sp(8)];
            }),
            ("w-above-max-input", |v| {
                v.angular = [Sp(9), raw(0.0), raw(0.0)]
            }),
            ("v-nan", |v| v.linear = [raw(0.0), Sp(20), raw(0.0)]),
            ("centre-inf", |v| v.centre = [Sp(18), raw(0.0), Sp(9)]),
            ("w-tiny-length-long-time", |v| {
                v.angular = [Sp(10), Sp(10), Sp(10)];
                v.times = [Sp(7), Sp(8)];
            }),
            ("w-square-subnormal", |v| {
                // |w|^2 about 9 eta, at a time with |w| t huge
                let (w, t) = if T::NAME == "f64" {
                    (3e-162, 1e150)
                } else {
                    (3e-23, 1e17)
                };
                v.angular = [raw(w), raw(0.0), raw(0.0)];
                v.times = [Sp(7), raw(t)];
            }),
            ("point-subnormal", |v| v.point = [Sp(13), Sp(14), Sp(15)]),
            ("tiny-everything", |v| {
                v.point = [Sp(13), Sp(14), Sp(15)];
                v.angular = [Sp(10), Sp(11), Sp(12)];
            }),
            ("point-and-time-non-finite", |v| {
                v.point = [Sp(16), Sp(18), Sp(20)];
                v.times = [Sp(19), Sp(16)];
            }),
            ("moderate-values", |v| {
                v.angular = [
                    Mo {
                        mant: 1 << 30,
                        exp: 5,
                    },
                    Mo { mant: -3, exp: -60 },
                    Mo {
                        mant: i32::MAX,
                        exp: 0,
                    },
                ];
                v.times = [
                    raw(1e3),
                    Mo {
                        mant: i32::MIN,
                        exp: 10,
                    },
                ];
            }),
            ("restrict-reversed", |v| v.sub = [raw(0.75), raw(0.25)]),
            ("restrict-outside", |v| v.sub = [raw(-0.5), raw(0.5)]),
            ("restrict-nan", |v| v.sub = [Sp(20), raw(0.5)]),
            ("no-rotation", |v| v.angular = [raw(0.0); 3]),
        ],
    )
}

/// Hard inputs for the `motion` target.
#[must_use]
pub fn motion_cases() -> Vec<(String, MotionCase)> {
    in_both(motion_inputs::<f32>(), motion_inputs::<f64>())
}

/// Hard inputs for the `validation` target in precision `T`.
fn validation_inputs<T: Precision>() -> Vec<(String, RawInput<T>)> {
    use Num::Special as Sp;
    let base = RawInput::<T> {
        vertices: vec![
            [raw(1.0), raw(0.0), raw(0.0)],
            [raw(0.0), raw(-1.0), raw(0.5)],
            [raw(-0.3), raw(0.2), raw(-0.9)],
        ],
        radius: raw(2.0),
        n: [raw(1.0), raw(1.0), raw(0.0)],
        interval: [raw(0.0), raw(1.0)],
        centre: [raw(0.0); 3],
        linear: [raw(0.3), raw(0.0), raw(-1.0)],
        angular: [raw(0.0), raw(0.5), raw(2.0)],
        sub: [raw(0.25), raw(0.5)],
        gap: raw(0.1),
    };
    variants::<T, _>(
        &base,
        &[
            ("plain", |_| {}),
            ("empty-vertices", |v| v.vertices.clear()),
            ("vertex-nan-then-huge", |v| {
                v.vertices.push([Sp(20), raw(0.0), raw(0.0)]);
                v.vertices.push([Sp(9), raw(0.0), raw(0.0)]);
            }),
            ("vertex-huge-and-inf", |v| {
                v.vertices.push([Sp(9), Sp(18), raw(0.0)])
            }),
            ("negative-zero-radius-zero-direction", |v| {
                v.radius = Sp(1);
                v.n = [Sp(1), Sp(0), Sp(1)];
            }),
            ("radius-min-input-direction-max", |v| {
                v.radius = Sp(8);
                v.n = [Sp(16), Sp(17), Sp(16)];
            }),
            ("direction-subnormal", |v| v.n = [Sp(13), Sp(14), Sp(13)]),
            ("interval-reversed", |v| v.interval = [raw(1.0), raw(0.0)]),
            ("max-input-everywhere", |v| {
                v.interval = [Sp(8), Sp(7)];
                v.angular = [Sp(7), Sp(7), Sp(7)];
                v.linear = [Sp(8), Sp(7), Sp(8)];
                v.vertices = vec![[Sp(7), Sp(8), Sp(7)]];
                v.radius = Sp(7);
            }),
            ("w-at-tiny-length", |v| {
                v.angular = [Sp(10), Sp(11), Sp(10)];
                v.interval = [Sp(8), Sp(7)];
            }),
            ("w-at-tiny-length-v-subnormal", |v| {
                v.angular = [Sp(10), Sp(11), Sp(10)];
                v.linear = [Sp(13), Sp(0), Sp(0)];
            }),
            ("underflow-everywhere", |v| {
                v.angular = [Sp(13), Sp(15), Sp(12)];
                v.vertices = vec![[Sp(13), Sp(12), Sp(15)], [Sp(7), Sp(0), Sp(0)]];
            }),
            ("n-parallel-to-w", |v| {
                v.n = [raw(0.0), raw(0.5), raw(2.0)];
                v.sub = [Sp(0), Sp(2)];
            }),
            ("full-turn", |v| {
                v.interval = [raw(0.0), Sp(6)];
                v.angular = [raw(0.0), raw(0.0), raw(1.0)];
                v.n = [raw(1.0), raw(0.0), raw(0.0)];
            }),
            ("n-parallel-to-w-full-turn", |v| {
                v.n = [raw(0.0), raw(0.5), raw(2.0)];
                v.interval = [raw(0.0), Sp(6)];
            }),
            ("at-rest-infinite-gap", |v| {
                v.gap = Sp(18);
                v.linear = [raw(0.0); 3];
                v.angular = [raw(0.0); 3];
            }),
        ],
    )
}

/// Hard inputs for the `validation` target.
#[must_use]
pub fn validation_cases() -> Vec<(String, ValidationCase)> {
    in_both(validation_inputs::<f32>(), validation_inputs::<f64>())
}

/// Raw bytes for the `toi` target, written as `motion_bound_fuzz::Bytes`
/// reads them.
#[derive(Clone, Debug, Default)]
struct ToiBytes(Vec<u8>);

impl ToiBytes {
    fn u8(&mut self, b: u8) -> &mut Self {
        self.0.push(b);
        self
    }

    /// The two bytes that `Bytes::range(lo, hi)` reads as (about) `x`.
    fn value(&mut self, x: f64, lo: f64, hi: f64) -> &mut Self {
        let k = ((x - lo) / (hi - lo) * 65535.0).round().clamp(0.0, 65535.0) as u16;
        self.0.extend_from_slice(&k.to_le_bytes());
        self
    }

    fn body(&mut self, triangles: &[[[f64; 3]; 3]]) -> &mut Self {
        self.u8((triangles.len() - 1) as u8);
        for tri in triangles {
            for v in tri {
                for &x in v {
                    self.value(x, -1.0, 1.0);
                }
            }
        }
        self
    }

    fn vector(&mut self, v: [f64; 3], half: f64) -> &mut Self {
        for x in v {
            self.value(x, -half, half);
        }
        self
    }

    /// A spin: the selector byte, then the vector unless it is zero.
    fn spin(&mut self, w: Option<[f64; 3]>) -> &mut Self {
        match w {
            None => self.u8(0),
            Some(w) => self.u8(1).vector(w, 20.0),
        }
    }
}

/// Hand-made scenes for the `toi` target: each `(A's triangles, B's
/// triangles, A's centre, velocity and spin, B's, then the parameter bytes)`.
#[must_use]
pub fn toi_seeds() -> Vec<(String, Vec<u8>)> {
    let big = [[-0.9, -0.9, 0.0], [0.9, -0.9, 0.0], [0.0, 0.9, 0.0]];
    let thin = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.02, 0.0]];
    let point = [[0.3, 0.3, 0.3]; 3];
    let edge = [[-0.5, 0.0, 0.0], [0.5, 0.0, 0.0], [0.0, 0.0, 0.0]];
    type Scene = (
        &'static str,
        Vec<[[f64; 3]; 3]>,
        Vec<[[f64; 3]; 3]>,
        [[f64; 3]; 2],
        Option<[f64; 3]>,
        [[f64; 3]; 2],
        Option<[f64; 3]>,
    );
    let scenes: Vec<Scene> = vec![
        (
            "head-on-spinning",
            vec![big],
            vec![big],
            [[0.0, 0.0, 2.5], [0.0, 0.0, -4.0]],
            Some([3.0, 0.0, 1.0]),
            [[0.0; 3], [0.0; 3]],
            Some([0.0, 0.0, 2.0]),
        ),
        (
            "fast-thin-blade",
            vec![thin],
            vec![big, edge],
            [[0.0, 0.0, 0.5], [0.0, 0.0, -0.5]],
            Some([0.0, 19.0, 0.0]),
            [[0.0; 3], [0.0; 3]],
            None,
        ),
        (
            "initial-contact",
            vec![big],
            vec![big],
            [[0.1, 0.0, 0.0], [1.0, 0.0, 0.0]],
            None,
            [[0.0; 3], [0.0; 3]],
            None,
        ),
        (
            "parallel-miss",
            vec![big],
            vec![big],
            [[-2.9, 0.0, 0.5], [5.0, 0.0, 0.0]],
            None,
            [[0.0; 3], [0.0; 3]],
            None,
        ),
        (
            "degenerate-point-and-edge",
            vec![point, edge],
            vec![edge, big, thin, point],
            [[2.0, 0.3, 0.0], [-4.0, 0.0, 0.0]],
            Some([0.0, 0.0, 20.0]),
            [[0.0; 3], [0.0; 3]],
            Some([7.0, -7.0, 7.0]),
        ),
    ];
    let mut out = vec![("empty".to_string(), Vec::new())];
    for (k, (name, a, b, [ca, va], wa, [cb, vb], wb)) in scenes.into_iter().enumerate() {
        let mut e = ToiBytes::default();
        e.body(&a).body(&b);
        e.vector(ca, 3.0).vector(va, 6.0).spin(wa);
        e.vector(cb, 1.0).vector(vb, 2.0).spin(wb);
        // Bound, contact distance, horizon, far ratio, accept, one-sided:
        // a different choice per scene.
        let k = k as u8;
        e.u8(k).u8(k).u8(k).u8(k).u8(k).u8(k);
        out.push((name.to_string(), e.0));
    }
    out
}

/// Hand-made inputs for the `degenerate` target: the cases (copies
/// of a triangle of the ball's size, triangles on one point, doubled
/// vertices, zero-area triangles, a mix under fast spins), each `(kind,
/// triangles, scale index, base triangles, A's centre, velocity and spin,
/// B's spin)` against an icosphere of radius 1 (320 triangles).
#[must_use]
pub fn degenerate_seeds() -> Vec<(String, Vec<u8>)> {
    let big = [[0.0, -1.0, -1.0], [0.0, 1.0, -1.0], [0.0, 0.0, 1.0]];
    let small = [[0.1, 0.2, 0.0], [0.3, -0.1, 0.1], [-0.2, 0.0, 0.3]];
    let sliver = [[-0.9, 0.0, 0.0], [0.9, 0.0, 0.0], [0.0, 0.0, 0.0]];
    type Scene = (
        &'static str,
        u8,
        usize,
        u8,
        Vec<[[f64; 3]; 3]>,
        [[f64; 3]; 2],
        Option<[f64; 3]>,
        Option<[f64; 3]>,
    );
    let head_on = [[-2.5, 0.0, 0.0], [5.0, 0.0, 0.0]];
    let scenes: Vec<Scene> = vec![
        (
            "20000-copies-head-on",
            0,
            20_000,
            0,
            vec![big],
            head_on,
            None,
            None,
        ),
        (
            "10-copies-a-tenth-spinning",
            0,
            10,
            1,
            vec![big],
            head_on,
            Some([0.0, 15.0, 3.0]),
            None,
        ),
        (
            "20000-on-one-point",
            1,
            20_000,
            0,
            vec![small],
            [[-2.0, 0.3, 0.0], [4.0, 0.0, 0.0]],
            None,
            Some([0.0, 0.0, 5.0]),
        ),
        (
            "doubled-vertices",
            2,
            20_000,
            0,
            vec![big, small, sliver, small],
            head_on,
            Some([2.0, 0.0, 0.0]),
            None,
        ),
        (
            "zero-area",
            3,
            30_000,
            0,
            vec![sliver, small],
            [[0.0, -2.5, 0.5], [0.0, 5.0, 0.0]],
            None,
            None,
        ),
        (
            "mix-fast-spins",
            4,
            5_000,
            2,
            vec![big, sliver, small],
            [[-2.9, 0.5, 0.0], [6.0, 0.0, 0.0]],
            Some([19.0, -19.0, 10.0]),
            Some([0.0, 5.0, 0.0]),
        ),
    ];
    let mut out = vec![("empty".to_string(), Vec::new())];
    for (name, kind, count, scale, base, [centre, velocity], wa, wb) in scenes {
        let mut e = ToiBytes::default();
        let k = (count - 1) as u16;
        e.u8(kind).u8(k.to_le_bytes()[0]).u8(k.to_le_bytes()[1]);
        e.u8(scale).u8((base.len() - 1) as u8);
        for tri in &base {
            for v in tri {
                e.vector(*v, 1.0);
            }
        }
        // The icosphere: radius 1, subdivided twice.
        e.value(1.0, 0.1, 1.0).u8(2);
        e.vector(centre, 3.0)
            .vector(velocity, 6.0)
            .spin(wa)
            .spin(wb);
        e.u8(0); // the default contact distance
        out.push((name.to_string(), e.0));
    }
    out
}

/// Seeds of the `gjk` target (raw bytes, as `fuzz_targets/gjk.rs` reads
/// them): each body is a count byte (`len - 1`) and its coordinates, each a
/// selector byte, then a grid byte (selector 0: `k / 2 - 1`) or two range
/// bytes; after both bodies come the gap, its axis, the scale and the
/// precision bytes, then one placement per body (selector 1: nine matrix
/// entries and a translation, as range bytes; missing bytes: identity).
#[must_use]
pub fn gjk_seeds() -> Vec<(String, Vec<u8>)> {
    struct Scene {
        name: &'static str,
        a: Vec<[f64; 3]>,
        b: Vec<[f64; 3]>,
        /// Gap choice (0, 1e-12, 1e-9, 1e-6, 1e-3, 0.5), axis, scale choice
        /// (1, 1e-3, 1e3, 2^-40), precision (0: f64, 1: f32).
        tail: [u8; 4],
        /// A's placement by a matrix and a translation (B: identity).
        pose_a: Option<([[f64; 3]; 3], [f64; 3])>,
    }
    let cube = |lo: f64| -> Vec<[f64; 3]> {
        (0..8)
            .map(|k| {
                let c = |bit: u32| lo + f64::from((k >> bit) & 1);
                [c(0), c(1), c(2)]
            })
            .collect()
    };
    let y = 0.993_948_810_464_696_4;
    let scenes = vec![
        // A quantised variant of the unit test's case (`y` to 16 bits): two
        // segments 1e-9 apart, which certified 0 before the refined direction.
        Scene {
            name: "tiny-gap-segments",
            a: vec![[-1.0, y, 0.0], [-1.0, -1.0, 0.0], [-1.0, y, 0.0]],
            b: vec![[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-1.0, 0.5, 0.0]],
            tail: [2, 2, 0, 0],
            pose_a: None,
        },
        Scene {
            name: "touching-cubes",
            a: cube(-1.0),
            b: cube(0.0),
            tail: [0, 0, 0, 0],
            pose_a: None,
        },
        Scene {
            name: "point-in-tetrahedron",
            a: vec![
                [-1.0, -1.0, -1.0],
                [1.0, -1.0, -1.0],
                [0.0, 1.0, -1.0],
                [0.0, 0.0, 1.0],
            ],
            b: vec![[0.0, -0.5, -0.5]],
            tail: [0, 0, 0, 1],
            pose_a: None,
        },
        Scene {
            name: "square-over-triangle-1e-12",
            a: vec![
                [-1.0, -1.0, 0.0],
                [1.0, -1.0, 0.0],
                [1.0, 1.0, 0.0],
                [-1.0, 1.0, 0.0],
            ],
            b: vec![[-0.5, -0.5, 0.0], [1.0, -0.5, 0.0], [0.5, 1.0, 0.0]],
            tail: [1, 2, 2, 0],
            pose_a: None,
        },
        // A rotated by 30 degrees about z and lifted to touch B's face.
        Scene {
            name: "rotated-tetrahedron-on-a-face",
            a: vec![
                [0.0, 0.0, 0.0],
                [0.5, 0.0, 0.5],
                [0.0, 0.5, 0.5],
                [-0.5, -0.5, 0.5],
            ],
            b: vec![[-1.0, -1.0, 1.0], [1.0, -1.0, 1.0], [0.0, 1.0, 1.0]],
            tail: [3, 2, 0, 0],
            pose_a: Some((
                [[0.866, -0.5, 0.0], [0.5, 0.866, 0.0], [0.0, 0.0, 1.0]],
                [0.1, -0.2, 0.5],
            )),
        },
        Scene {
            name: "apart-tiny-scale",
            a: cube(-1.0),
            b: vec![[0.3, 0.2, 0.1], [0.9, 0.1, 0.7]],
            tail: [5, 0, 3, 1],
            pose_a: None,
        },
    ];
    let grid = |x: f64| -> Option<u8> {
        let k = (x + 1.0) * 2.0;
        (k.fract() == 0.0 && (0.0..=4.0).contains(&k)).then_some(k as u8)
    };
    let mut out = vec![("empty".to_string(), Vec::new())];
    for sc in scenes {
        let mut e = ToiBytes::default();
        for body in [&sc.a, &sc.b] {
            e.u8((body.len() - 1) as u8);
            for &x in body.iter().flatten() {
                match grid(x) {
                    Some(k) => e.u8(0).u8(k),
                    None => e.u8(1).value(x, -1.0, 1.0),
                };
            }
        }
        for t in sc.tail {
            e.u8(t);
        }
        if let Some((m, x)) = sc.pose_a {
            e.u8(1);
            for &c in m.iter().flatten() {
                e.value(c, -1.0, 1.0);
            }
            for c in x {
                e.value(c, -2.0, 2.0);
            }
            e.u8(0); // B: identity
        }
        out.push((sc.name.to_string(), e.0));
    }
    out
}

/// Seeds of the `far` target (raw bytes as its `Bytes` reader takes them):
/// the fly-by far from the origin and at extreme scales, in both
/// precisions, with the default-like budgets.
#[must_use]
pub fn far_seeds() -> Vec<(String, Vec<u8>)> {
    /// Two bytes for `v` in `[lo, hi]`, as `Bytes::range` reads them.
    fn range(out: &mut Vec<u8>, v: f64, lo: f64, hi: f64) {
        let k = (((v - lo) / (hi - lo)) * 65535.0).round() as u16;
        out.extend(k.to_le_bytes());
    }
    /// Name, precision (0 `f32`, 1 `f64`), subdivisions, offset exponent,
    /// offset mantissas, scale byte (as `i8`), contact choice.
    type Far = (&'static str, u8, u8, u8, [f64; 3], i8, u8);
    let scenes: [Far; 6] = [
        ("f32-at-1e7", 0, 1, 7, [1.0, 1.0, 1.0], 0, 0),
        (
            "f32-at-3e5-mixed-signs",
            0,
            2,
            5,
            [3.0 / 10.0, -1.0, 0.5],
            0,
            0,
        ),
        ("f64-at-1e16", 1, 1, 16, [1.0, -1.0, 1.0], 0, 0),
        ("f64-tiny-scale", 1, 1, 0, [0.0, 0.0, 0.0], -128, 1),
        ("f64-huge-scale", 1, 1, 3, [0.5, 0.5, 0.5], 120, 3),
        ("f32-tiny-scale", 0, 0, 0, [0.0, 0.0, 0.0], -100, 0),
    ];
    scenes
        .iter()
        .map(|&(name, precision, subdivisions, exp, m, scale, contact)| {
            let mut out = vec![precision, subdivisions, exp];
            for x in m {
                range(&mut out, x.clamp(-1.0, 1.0), -1.0, 1.0);
                out.push(1); // not zeroed
            }
            out.push(scale as u8);
            for (v, half) in [
                ([-1.3, 0.1, 0.0], 1.6),
                ([2.6, 0.0, 0.0], 3.0),
                ([0.0, 3.0, 1.5], 20.0),
                ([0.3, 0.0, 0.0], 5.0),
            ] {
                for x in v {
                    range(&mut out, x, -half, half);
                }
            }
            out.push(contact);
            out.extend([255, 255]); // budget: 10,200 node pairs, 2,040 triangle pairs
            (name.to_string(), out)
        })
        .collect()
}

/// Seeds of the `shapes` target (raw bytes as its `Bytes` reader takes them):
/// every pair of body kinds (mesh, compound, ground for the second, convex),
/// the rest of the bytes a fixed pattern of moderate values.
#[must_use]
pub fn shapes_seeds() -> Vec<(String, Vec<u8>)> {
    let names = ["mesh", "compound", "ground", "convex"];
    let mut out = Vec::new();
    for (i, a) in names.iter().enumerate() {
        if *a == "ground" {
            continue;
        }
        for (j, b) in names.iter().enumerate() {
            let mut bytes = vec![i as u8];
            // The first body's own bytes, then the second's kind and bytes,
            // then the motions: a pattern that reads as moderate values.
            bytes.extend((0..40u8).map(|k| k.wrapping_mul(37).wrapping_add(11)));
            bytes.push(j as u8);
            bytes.extend((0..80u8).map(|k| k.wrapping_mul(53).wrapping_add(7)));
            out.push((format!("{a}-{b}"), bytes));
        }
    }
    out
}

/// Seeds of the `chain` target (raw bytes read as bounded numbers): a few
/// patterns that read as moderate chains, segments and obstacles.
pub fn chain_seeds() -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for (name, mul, add) in [
        ("mild", 37u8, 11u8),
        ("turning", 53, 7),
        ("sliding", 91, 29),
        ("dense", 13, 201),
    ] {
        let bytes: Vec<u8> = (0..=255u8)
            .map(|k| k.wrapping_mul(mul).wrapping_add(add))
            .collect();
        out.push((name.to_string(), bytes));
    }
    out
}
