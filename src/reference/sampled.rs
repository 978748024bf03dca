//! Batched dense sampling of the directed speed with faer: a third,
//! independent computation to cross-check the closed-form reference.
//!
//! The directed speeds of `N` body points at `T` sample times form the matrix
//!
//! ```text
//! S = a 1 + V D,     V = [r_i^T] (N x 3),     D = [R(t_j)^T c] (3 x T),
//! ```
//!
//! because `p_i'(t) . n = v . n + c . R(t) r_i = a + (R(t)^T c) . r_i`, with
//! `r_i` the lever arm `Q0 (r_i - c)` at the epoch. One dense product gives
//! every speed at once.

extern crate std;
use std::vec::Vec;

use faer::Mat;

use crate::{Direction, Float, RigidMotion};

/// The directed-speed samples of a body, `N x T`, in `f64`.
#[derive(Clone, Debug)]
pub struct SpeedSamples {
    /// `speeds[(i, j)]` is the directed speed of vertex `i` at `times[j]`.
    pub speeds: Mat<f64>,
    /// The sample times, `T` of them, evenly spaced over the interval.
    pub times: Vec<f64>,
}

/// Samples the directed speed of every vertex at `samples >= 2` evenly spaced
/// times of the motion's interval (ends included).
///
/// ```
/// use motion_bound::{reference::sampled::sample_speeds, Direction, RigidMotion};
/// let m = RigidMotion::try_from_arrays([0.0; 3], [0.0; 3], [0.0, 0.0, 1.0]).unwrap();
/// let s = sample_speeds(&[[1.0, 0.0, 0.0]], &m, Direction::Y, 3);
/// assert!((s.speeds[(0, 0)] - 1.0).abs() < 1e-15); // w x r = y at t = 0
/// ```
#[must_use]
pub fn sample_speeds<T: Float>(
    vertices: &[[T; 3]],
    motion: &RigidMotion<T>,
    n: Direction<T>,
    samples: usize,
) -> SpeedSamples {
    let samples = samples.max(2);
    let wide = |a: [T; 3]| a.map(Float::to_f64);
    let n = wide(n.to_array());
    let nl = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let n = [n[0] / nl, n[1] / nl, n[2] / nl];
    let v = wide(motion.linear().to_array());
    let w = wide(motion.angular().to_array());
    let a = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    let c = [
        n[1] * w[2] - n[2] * w[1],
        n[2] * w[0] - n[0] * w[2],
        n[0] * w[1] - n[1] * w[0],
    ];
    let omega = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    let k = if omega > 0.0 {
        [w[0] / omega, w[1] / omega, w[2] / omega]
    } else {
        [0.0; 3]
    };
    let iv = motion.interval();
    let (ta, tb) = (iv.start().to_f64(), iv.end().to_f64());
    let times: Vec<f64> = (0..samples)
        .map(|j| ta + (tb - ta) * j as f64 / (samples - 1) as f64)
        .collect();

    // D = [R(t_j)^T c]: c rotated by -|w| t_j about k (Rodrigues).
    let kxc = [
        k[1] * c[2] - k[2] * c[1],
        k[2] * c[0] - k[0] * c[2],
        k[0] * c[1] - k[1] * c[0],
    ];
    let kc = k[0] * c[0] + k[1] * c[1] + k[2] * c[2];
    let d = Mat::from_fn(3, samples, |row, j| {
        let th = -omega * times[j];
        let (s, co) = (th.sin(), th.cos());
        c[row] * co + kxc[row] * s + k[row] * kc * (1.0 - co)
    });
    // V = [(Q0 (r_i - c))^T]: the lever arms at the epoch, with the start
    // orientation's quaternion normalised here.
    let [q0, q1, q2, q3] = motion.orientation().quaternion().map(Float::to_f64);
    let ql = (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3).sqrt();
    let (qw, qv) = (q0 / ql, [q1 / ql, q2 / ql, q3 / ql]);
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let centre = wide(motion.local_centre().to_array());
    let arms: Vec<[f64; 3]> = vertices
        .iter()
        .map(|r| {
            let d = [0, 1, 2].map(|k| r[k].to_f64() - centre[k]);
            let c1 = cross(qv, d);
            let c2 = cross(qv, c1);
            [0, 1, 2].map(|k| d[k] + 2.0 * qw * c1[k] + 2.0 * c2[k])
        })
        .collect();
    let vm = Mat::from_fn(vertices.len(), 3, |i, col| arms[i][col]);
    let mut speeds = &vm * &d;
    for j in 0..samples {
        for i in 0..vertices.len() {
            speeds[(i, j)] += a;
        }
    }
    SpeedSamples { speeds, times }
}

impl SpeedSamples {
    /// `max_{i,j} |S_ij|`: a lower estimate of the sup of the directed speed.
    #[must_use]
    pub fn max_abs(&self) -> f64 {
        let mut m = 0.0f64;
        for j in 0..self.speeds.ncols() {
            for i in 0..self.speeds.nrows() {
                m = m.max(self.speeds[(i, j)].abs());
            }
        }
        m
    }

    /// `max_i` of the trapezoid rule for `integral |S_i(t)| dt`.
    #[must_use]
    pub fn max_trapezoid(&self) -> f64 {
        let mut best = 0.0f64;
        for i in 0..self.speeds.nrows() {
            let mut acc = 0.0;
            for j in 1..self.speeds.ncols() {
                let h = self.times[j] - self.times[j - 1];
                acc += 0.5 * h * (self.speeds[(i, j)].abs() + self.speeds[(i, j - 1)].abs());
            }
            best = best.max(acc);
        }
        best
    }
}
