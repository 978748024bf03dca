//! The scene: its bodies and frame, and the query (the broad phase then the
//! narrow phase, each in its own file).

use alloc::vec::Vec;

use super::body::{Groups, SceneBody};
use super::params::{SceneParams, SceneQueryError};
use super::report::{SceneReport, SceneWorkspace};
use crate::ca::Shape;
use crate::{Float, Isometry, RigidMotion, TimeInterval, Vec3};

/// Many bodies moving over one frame, and the query that finds every pair's
/// first contact while skipping what cannot touch.
///
/// A query runs in two phases. The **broad phase** computes each body's
/// certified swept box ([`SweptBox`](super::SweptBox)) once, and a sweep and prune keeps the
/// pairs whose boxes come within the contact distance (pairs of two static
/// bodies are never kept); the caller's filter and the bodies' [`Groups`]
/// then drop pairs the engine excludes. The **narrow phase** runs
/// conservative advancement on each kept pair with the stepper of its shapes
/// ([`AnyPair`](crate::ca::AnyPair), the one dispatch), reusing one mesh
/// workspace. Every skip is sound (`proofs/11-scene.md`) and counted in
/// [`SceneStats`](super::SceneStats).
///
/// ```
/// use motion_bound::ca::Shape;
/// use motion_bound::scene::{Scene, SceneParams, SceneWorkspace};
/// use motion_bound::{BoundingBall, Isometry, RigidMotion, TimeInterval, Vec3};
/// let ball = Shape::Ball(BoundingBall::try_new([0.0; 3], 0.5)?);
/// let mut scene = Scene::try_new(TimeInterval::try_new(0.0, 1.0)?)?;
/// // A ball flying at a static one, and a third far away.
/// let a = scene.try_add(ball, RigidMotion::try_from_arrays([-3.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0; 3])?)?;
/// let b = scene.try_add_static(ball, Isometry::try_from_translation(Vec3::new(0.0, 0.0, 0.0))?)?;
/// let _far = scene.try_add(ball, RigidMotion::try_from_arrays([0.0, 50.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 3.0])?)?;
/// let mut ws = SceneWorkspace::new();
/// let report = scene.query(&mut ws, &SceneParams::default())?;
/// assert_eq!(report.pairs().len(), 1); // the far ball was culled
/// let (t, other) = report.earliest_for(a).unwrap();
/// assert_eq!(other, b);
/// assert!(t <= 0.5 && t > 0.5 - 1e-4); // the balls touch at t = 2 / 4
/// assert_eq!(report.stats().pairs_culled, 2);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scene<'a, T> {
    pub(super) interval: TimeInterval<T>,
    pub(super) bodies: Vec<SceneBody<'a, T>>,
}

impl<'a, T: Float> Scene<'a, T> {
    /// An empty scene over the frame `interval`.
    ///
    /// # Errors
    /// None today; kept fallible for future checks of the frame.
    pub fn try_new(interval: TimeInterval<T>) -> Result<Self, SceneQueryError> {
        Ok(Self {
            interval,
            bodies: Vec::new(),
        })
    }

    /// The frame.
    #[must_use]
    pub const fn interval(&self) -> TimeInterval<T> {
        self.interval
    }

    /// The bodies, numbered in the order they were added.
    #[must_use]
    pub fn bodies(&self) -> &[SceneBody<'a, T>] {
        &self.bodies
    }

    /// The number of bodies.
    #[must_use]
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// Whether the scene has no body.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// Adds a body moving by `motion` over the scene's frame; returns its
    /// number.
    ///
    /// # Errors
    /// [`SceneQueryError::IntervalMismatch`], or [`SceneQueryError::Input`]
    /// for a vertex set too large for its bounding ball.
    pub fn try_add(
        &mut self,
        shape: Shape<'a, T>,
        motion: RigidMotion<T>,
    ) -> Result<usize, SceneQueryError> {
        let body = self.bodies.len();
        self.check(body, &shape, &motion)?;
        self.bodies
            .push(SceneBody::try_new(shape, motion, Groups::ALL)?);
        Ok(body)
    }

    /// Adds a static body at `pose`; returns its number.
    ///
    /// # Errors
    /// As [`try_add`](Self::try_add).
    pub fn try_add_static(
        &mut self,
        shape: Shape<'a, T>,
        pose: Isometry<T>,
    ) -> Result<usize, SceneQueryError> {
        let motion = RigidMotion::try_new(
            crate::Point3::from_vec3(pose.translation()),
            Vec3::ZERO,
            Vec3::ZERO,
            self.interval,
        )?
        .with_orientation(pose.rotation());
        self.try_add(shape, motion)
    }

    /// Replaces a body's motion (the next frame's, in a frame loop).
    ///
    /// # Errors
    /// [`SceneQueryError::UnknownBody`], [`SceneQueryError::IntervalMismatch`].
    pub fn try_set_motion(
        &mut self,
        body: usize,
        motion: RigidMotion<T>,
    ) -> Result<(), SceneQueryError> {
        if motion.interval() != self.interval {
            return Err(SceneQueryError::IntervalMismatch { body });
        }
        let b = self
            .bodies
            .get_mut(body)
            .ok_or(SceneQueryError::UnknownBody(body))?;
        b.motion = motion;
        Ok(())
    }

    /// Sets a body's interaction groups.
    ///
    /// # Errors
    /// [`SceneQueryError::UnknownBody`].
    pub fn try_set_groups(&mut self, body: usize, groups: Groups) -> Result<(), SceneQueryError> {
        self.bodies
            .get_mut(body)
            .ok_or(SceneQueryError::UnknownBody(body))?
            .groups = groups;
        Ok(())
    }

    /// Moves every body to the frame `interval` (their motions must then be
    /// replaced by ones over it before the next query).
    pub fn set_interval(&mut self, interval: TimeInterval<T>) {
        self.interval = interval;
    }

    fn check(
        &self,
        body: usize,
        shape: &Shape<'a, T>,
        motion: &RigidMotion<T>,
    ) -> Result<(), SceneQueryError> {
        let _ = shape;
        if motion.interval() != self.interval {
            return Err(SceneQueryError::IntervalMismatch { body });
        }
        Ok(())
    }

    /// Every pair's first contact over the frame: [`broad_phase`](Self::broad_phase)
    /// then [`narrow_phase`](Self::narrow_phase), with every pair the
    /// bodies' groups allow.
    ///
    /// # Errors
    /// [`SceneQueryError::Ca`] for bad parameters, [`SceneQueryError::IntervalMismatch`]
    /// for a body left on another frame.
    pub fn query<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        self.query_filtered(ws, params, |_, _| true)
    }

    /// As [`query`](Self::query), testing only the pairs `(a, b)` (`a < b`)
    /// for which `filter(a, b)` holds (and the groups allow).
    ///
    /// # Errors
    /// As [`query`](Self::query).
    pub fn query_filtered<'w>(
        &self,
        ws: &'w mut SceneWorkspace<T>,
        params: &SceneParams<T>,
        filter: impl FnMut(usize, usize) -> bool,
    ) -> Result<&'w SceneReport<T>, SceneQueryError> {
        self.broad_phase(ws, params, filter)?;
        self.narrow_phase(ws, params)
    }
}
