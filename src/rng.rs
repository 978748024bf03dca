//! The seeded generator of the crate's test support (SplitMix64): one
//! implementation for the reference's own tests, the testkit's generators
//! (re-exported as `testkit::SplitMix64` and `testkit::toi::Rng`), and
//! through them every test, benchmark, example and fuzz target of the
//! workspace. Not a source of randomness for anything but reproducible
//! test cases.

// Without the testkit (the crate's own unit tests under the default features) this is private
// to the crate and only part of it is used.
#![cfg_attr(not(feature = "testkit"), allow(dead_code, unreachable_pub))]

/// A deterministic generator (Vigna's SplitMix64): the same sequence for the
/// same seed on every platform, so a failing case reproduces.
///
/// ```
/// use motion_bound::testkit::SplitMix64;
/// let (mut a, mut b) = (SplitMix64::new(7), SplitMix64::new(7));
/// assert_eq!(a.next_u64(), b.next_u64());
/// let x = a.range(-2.0, 3.0);
/// assert!((-2.0..3.0).contains(&x));
/// ```
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// A source seeded with `seed`.
    #[must_use]
    pub const fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform in `[-1, 1)`.
    pub fn signed_unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// A random vector with components in `[-1, 1)`.
    pub fn vec3(&mut self) -> [f64; 3] {
        [self.signed_unit(), self.signed_unit(), self.signed_unit()]
    }

    /// A uniformly distributed unit vector (rejection from the cube).
    pub fn direction(&mut self) -> [f64; 3] {
        loop {
            let v = self.vec3();
            let l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if l2 > 1e-6 && l2 <= 1.0 {
                let l = l2.sqrt();
                return v.map(|x| x / l);
            }
        }
    }
}
