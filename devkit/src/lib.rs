//! What the workspace's examples, comparison programs (`compare/`), benchmarks and tests
//! (`motion-bound-parry/`) share, written once; not published.
//!
//! * [`Rng`]: the seeded generator. It is the testkit's
//!   (`motion_bound::testkit::toi::Rng`, SplitMix64), re-exported, so that the tests, the fuzz
//!   targets, the benchmarks and the examples draw from one implementation; [`direction`] adds
//!   the unit vectors the parry and rapier programs draw.
//! * [`cpu_name`]: the processor's name, for the header line of a timing.
//! * [`Args`]: command-line flags (`--name value`, `--name`) and positional arguments.

use std::fmt::Display;
use std::str::FromStr;

/// The seeded generator (SplitMix64): the testkit's, with its draws (`new`, `next_u64`,
/// `unit` in `[0, 1)`, `range(lo, hi)`, `signed_unit`, `vec3`, `direction`).
pub use motion_bound::testkit::toi::Rng;

/// A random unit vector: three `rng.range(-1.0, 1.0)` (a point of the cube), drawn again until
/// the point's length is in `(min_length, 1]`, then divided by its length. The length is
/// `(x * x + y * y + z * z).sqrt()`, the operations and order of glam's `DVec3::length`, so
/// that a program that drew with `Vector::new(..)` and `v / v.length()` gets the same floats.
#[must_use]
pub fn direction(rng: &mut Rng, min_length: f64) -> [f64; 3] {
    loop {
        let v = [
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        ];
        let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if length > min_length && length <= 1.0 {
            return v.map(|x| x / length);
        }
    }
}

/// The processor's name: the first `model name` line of `/proc/cpuinfo`, or `unknown CPU`
/// where there is none (other systems, some ARM kernels).
#[must_use]
pub fn cpu_name() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, name)| name.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".into())
}

/// A program's command-line arguments, taken one by one: flags with a value
/// ([`value`](Self::value), [`value_or`](Self::value_or)), flags alone ([`flag`](Self::flag)),
/// then positional arguments ([`positional`](Self::positional)); [`finish`](Self::finish)
/// rejects what is left. `-h` or `--help` prints the usage and exits; a missing or malformed
/// value, or an unknown argument, prints the problem and the usage to standard error and exits
/// with status 2. A flag given twice: the last one counts.
///
/// ```
/// use motion_bound_devkit::Args;
///
/// let mut args = Args::new("demo [--segments N] [--quick]", ["--segments", "5"].map(String::from));
/// assert_eq!(args.value_or("--segments", 1000), 5);
/// assert!(!args.flag("--quick"));
/// args.finish();
/// ```
#[derive(Clone, Debug)]
pub struct Args {
    usage: String,
    rest: Vec<String>,
}

impl Args {
    /// The program's arguments (after its name); `usage` is what `--help` and errors print.
    #[must_use]
    pub fn from_env(usage: &str) -> Self {
        Self::new(usage, std::env::args().skip(1))
    }

    /// The arguments `args`; `usage` is what `--help` and errors print.
    #[must_use]
    pub fn new(usage: &str, args: impl IntoIterator<Item = String>) -> Self {
        let args = Self {
            usage: usage.to_owned(),
            rest: args.into_iter().collect(),
        };
        if args.rest.iter().any(|a| a == "-h" || a == "--help") {
            println!("usage: {}", args.usage);
            std::process::exit(0);
        }
        args
    }

    /// Whether `name` (a flag without a value) is given.
    pub fn flag(&mut self, name: &str) -> bool {
        let before = self.rest.len();
        self.rest.retain(|a| a != name);
        self.rest.len() < before
    }

    /// The value after `name`, parsed, when `name` is given.
    pub fn value<T>(&mut self, name: &str) -> Option<T>
    where
        T: FromStr,
        T::Err: Display,
    {
        let mut found = None;
        while let Some(i) = self.rest.iter().position(|a| a == name) {
            if i + 1 == self.rest.len() {
                self.fail(&format!("{name} needs a value"));
            }
            found = Some(self.rest.remove(i + 1));
            self.rest.remove(i);
        }
        found.map(|v| self.parse(name, v))
    }

    /// The value after `name`, parsed, or `default` when `name` is not given.
    pub fn value_or<T>(&mut self, name: &str, default: T) -> T
    where
        T: FromStr,
        T::Err: Display,
    {
        self.value(name).unwrap_or(default)
    }

    /// The next positional argument (`what` names it in errors), parsed; `None` when there is
    /// none left. Take the flags first: an argument starting with `--` here is unknown.
    pub fn positional<T>(&mut self, what: &str) -> Option<T>
    where
        T: FromStr,
        T::Err: Display,
    {
        if self.rest.is_empty() {
            return None;
        }
        if self.rest[0].starts_with("--") {
            self.finish();
        }
        let v = self.rest.remove(0);
        Some(self.parse(what, v))
    }

    /// Rejects any argument not taken yet (unknown to the program).
    pub fn finish(&self) {
        if let Some(a) = self.rest.first() {
            self.fail(&format!("unknown argument {a}"));
        }
    }

    /// Prints `message` and the usage to standard error and exits with status 2 (a usage
    /// error), for a program's own checks of the values.
    pub fn fail(&self, message: &str) -> ! {
        eprintln!("{message}\nusage: {}", self.usage);
        std::process::exit(2)
    }

    fn parse<T>(&self, what: &str, value: String) -> T
    where
        T: FromStr,
        T::Err: Display,
    {
        value
            .parse()
            .unwrap_or_else(|e| self.fail(&format!("{what} {value}: {e}")))
    }
}

#[cfg(test)]
mod tests {
    use super::{direction, Args, Rng};

    fn args(list: &[&str]) -> Args {
        Args::new("test", list.iter().map(|s| (*s).to_owned()))
    }

    #[test]
    fn flags_values_and_positionals() {
        let mut a = args(&[
            "FILE", "--n", "5", "--quick", "--name", "x", "--n", "6", "7",
        ]);
        assert_eq!(a.value_or("--n", 1), 6, "the last --n counts");
        assert_eq!(
            a.value::<String>("--name").as_deref(),
            Some("x"),
            "a string"
        );
        assert_eq!(a.value::<f64>("--spin"), None, "absent");
        assert_eq!(a.value_or("--spin", 2.0), 2.0, "absent: the default");
        assert!(a.flag("--quick"), "present");
        assert!(!a.flag("--quick"), "taken already");
        assert_eq!(
            a.positional::<String>("FILE").as_deref(),
            Some("FILE"),
            "first"
        );
        assert_eq!(a.positional::<usize>("REPEATS"), Some(7), "second");
        assert_eq!(a.positional::<usize>("MORE"), None, "none left");
        a.finish();
    }

    /// The generators this crate replaced drew `lo + (hi - lo) * unit` (the examples) and
    /// `lo + (hi - lo) * bits / 2^53` (the parry tests, multiplying first): the same floats as
    /// `range`, dividing by a power of two being exact.
    #[test]
    fn range_is_the_replaced_generators_uniform() {
        for (lo, hi) in [
            (-1.0, 1.0),
            (0.0, std::f64::consts::PI),
            (8.0, 30.0),
            (-0.5, 0.0),
        ] {
            let (mut a, mut b) = (Rng::new(2027), Rng::new(2027));
            for _ in 0..20_000 {
                let bits = a.next_u64() >> 11;
                let old = lo + (hi - lo) * bits as f64 / (1u64 << 53) as f64;
                assert_eq!(
                    b.range(lo, hi).to_bits(),
                    old.to_bits(),
                    "range({lo}, {hi})"
                );
            }
        }
    }

    #[test]
    fn directions_are_unit_vectors() {
        let mut rng = Rng::new(7);
        for _ in 0..1000 {
            let d = direction(&mut rng, 0.1);
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            assert!((l - 1.0).abs() < 1e-12, "length {l}");
        }
    }
}
