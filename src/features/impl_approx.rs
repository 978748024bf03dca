//! `approx` comparison traits on the public vector types (glam's layout).

use approx::{AbsDiffEq, RelativeEq, UlpsEq};

use crate::{BodyPoint, DirectedBound, Direction, Float, Point3, Vec3};

macro_rules! impl_approx_xyz {
    ($ty:ident, $get:expr) => {
        impl<T: Float + AbsDiffEq<Epsilon = T>> AbsDiffEq for $ty<T> {
            type Epsilon = T;
            fn default_epsilon() -> T {
                T::default_epsilon()
            }
            fn abs_diff_eq(&self, other: &Self, epsilon: T) -> bool {
                let (a, b): (Vec3<T>, Vec3<T>) = ($get(*self), $get(*other));
                a.x.abs_diff_eq(&b.x, epsilon)
                    && a.y.abs_diff_eq(&b.y, epsilon)
                    && a.z.abs_diff_eq(&b.z, epsilon)
            }
        }

        impl<T: Float + RelativeEq<Epsilon = T>> RelativeEq for $ty<T> {
            fn default_max_relative() -> T {
                T::default_max_relative()
            }
            fn relative_eq(&self, other: &Self, epsilon: T, max_relative: T) -> bool {
                let (a, b): (Vec3<T>, Vec3<T>) = ($get(*self), $get(*other));
                a.x.relative_eq(&b.x, epsilon, max_relative)
                    && a.y.relative_eq(&b.y, epsilon, max_relative)
                    && a.z.relative_eq(&b.z, epsilon, max_relative)
            }
        }

        impl<T: Float + UlpsEq<Epsilon = T>> UlpsEq for $ty<T> {
            fn default_max_ulps() -> u32 {
                T::default_max_ulps()
            }
            fn ulps_eq(&self, other: &Self, epsilon: T, max_ulps: u32) -> bool {
                let (a, b): (Vec3<T>, Vec3<T>) = ($get(*self), $get(*other));
                a.x.ulps_eq(&b.x, epsilon, max_ulps)
                    && a.y.ulps_eq(&b.y, epsilon, max_ulps)
                    && a.z.ulps_eq(&b.z, epsilon, max_ulps)
            }
        }
    };
}

impl_approx_xyz!(Vec3, |v: Vec3<T>| v);
impl_approx_xyz!(Point3, |p: Point3<T>| p.to_vec3());
impl_approx_xyz!(BodyPoint, |p: BodyPoint<T>| p.arm());
impl_approx_xyz!(Direction, |d: Direction<T>| d.get());

impl<T: Float + AbsDiffEq<Epsilon = T>> AbsDiffEq for DirectedBound<T> {
    type Epsilon = T;
    fn default_epsilon() -> T {
        T::default_epsilon()
    }
    fn abs_diff_eq(&self, other: &Self, epsilon: T) -> bool {
        self.speed.abs_diff_eq(&other.speed, epsilon)
            && self.displacement.abs_diff_eq(&other.displacement, epsilon)
    }
}

impl<T: Float + RelativeEq<Epsilon = T>> RelativeEq for DirectedBound<T> {
    fn default_max_relative() -> T {
        T::default_max_relative()
    }
    fn relative_eq(&self, other: &Self, epsilon: T, max_relative: T) -> bool {
        self.speed.relative_eq(&other.speed, epsilon, max_relative)
            && self
                .displacement
                .relative_eq(&other.displacement, epsilon, max_relative)
    }
}

#[cfg(test)]
mod tests {
    use crate::{Direction, Vec3};
    use approx::{assert_relative_eq, assert_ulps_eq};

    #[test]
    fn vectors_compare_with_tolerance() {
        let a = Vec3::new(0.1 + 0.2, 1.0, 2.0);
        assert_ulps_eq!(a, Vec3::new(0.3, 1.0, 2.0));
        let d = Direction::try_new(Vec3::new(1e-3, 1.0, 0.0)).unwrap();
        assert_relative_eq!(d, Direction::Y, epsilon = 1e-3);
    }
}
