//! Conversions to and from `mint`, the interop types glam, nalgebra and
//! cgmath all convert to.

use crate::{BodyPoint, Direction, Float, InputError, Point3, Rotation, Vec3};

impl<T: Float> From<mint::Vector3<T>> for Vec3<T> {
    fn from(v: mint::Vector3<T>) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl<T: Float> From<Vec3<T>> for mint::Vector3<T> {
    fn from(v: Vec3<T>) -> Self {
        Self {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }
}

impl<T: Float> From<mint::Point3<T>> for Point3<T> {
    fn from(p: mint::Point3<T>) -> Self {
        Self::new(p.x, p.y, p.z)
    }
}

impl<T: Float> From<Point3<T>> for mint::Point3<T> {
    fn from(p: Point3<T>) -> Self {
        Self {
            x: p.x,
            y: p.y,
            z: p.z,
        }
    }
}

impl<T: Float> From<mint::Vector3<T>> for BodyPoint<T> {
    fn from(v: mint::Vector3<T>) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl<T: Float> From<BodyPoint<T>> for mint::Vector3<T> {
    fn from(p: BodyPoint<T>) -> Self {
        Self {
            x: p.x,
            y: p.y,
            z: p.z,
        }
    }
}

impl<T: Float> TryFrom<mint::Vector3<T>> for Direction<T> {
    type Error = InputError;
    fn try_from(v: mint::Vector3<T>) -> Result<Self, InputError> {
        Self::try_new(v.into())
    }
}

impl<T: Float> From<Direction<T>> for mint::Vector3<T> {
    fn from(d: Direction<T>) -> Self {
        d.get().into()
    }
}

/// A body's orientation from an engine's quaternion (`s` the real part,
/// `v` the vector part), normalised ([`Rotation::try_from_quaternion`]).
impl<T: Float> TryFrom<mint::Quaternion<T>> for Rotation<T> {
    type Error = InputError;
    fn try_from(q: mint::Quaternion<T>) -> Result<Self, InputError> {
        Self::try_from_quaternion(q.s, q.v.x, q.v.y, q.v.z)
    }
}

impl<T: Float> From<Rotation<T>> for mint::Quaternion<T> {
    fn from(r: Rotation<T>) -> Self {
        let [w, x, y, z] = r.quaternion();
        Self {
            s: w,
            v: mint::Vector3 { x, y, z },
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{Direction, Point3, Rotation, Vec3};

    #[test]
    fn quaternions_round_trip_through_mint() {
        let q = mint::Quaternion {
            s: 2.0f64,
            v: mint::Vector3 {
                x: 0.0,
                y: 0.0,
                z: 2.0,
            },
        };
        let r = Rotation::try_from(q).expect("nonzero");
        let v = r.rotate(Vec3::new(1.0, 0.0, 0.0));
        assert!(
            (v - Vec3::new(0.0, 1.0, 0.0)).length() < 1e-15,
            "a quarter turn"
        );
        let back: mint::Quaternion<f64> = r.into();
        assert!(
            (back.s - 0.5f64.sqrt()).abs() < 1e-15 && back.v.x == 0.0,
            "normalised"
        );
        let zero = mint::Quaternion {
            s: 0.0f32,
            v: mint::Vector3 {
                x: 0.0,
                y: 0.0,
                z: 0.0,
            },
        };
        assert!(Rotation::try_from(zero).is_err(), "no rotation");
    }

    #[test]
    fn round_trips_through_mint() {
        let v = Vec3::new(1.0f32, 2.0, 3.0);
        let m: mint::Vector3<f32> = v.into();
        assert_eq!(Vec3::from(m), v, "vector");
        let p = Point3::new(1.0f64, -2.0, 0.5);
        let m: mint::Point3<f64> = p.into();
        assert_eq!(Point3::from(m), p, "point");
        let d = Direction::try_from(mint::Vector3 {
            x: 0.0,
            y: 2.0,
            z: 0.0,
        })
        .unwrap();
        assert_eq!(d, Direction::Y, "direction normalised");
    }
}
