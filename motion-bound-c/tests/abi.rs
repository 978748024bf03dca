//! The C ABI called from Rust: the same entry points a C caller uses, with
//! answers against closed forms. (The C tests in `tests/c/` run under the
//! sanitizers; these run with `cargo test -p motion-bound-c`.)

use std::ffi::CStr;
use std::ptr;

use motion_bound_c::*;

fn pose(x: f64, y: f64, z: f64) -> MbPose {
    MbPose {
        translation: MbVec3 { x, y, z },
        rotation: MbQuat {
            w: 1.0,
            x: 0.0,
            y: 0.0,
            z: 0.0,
        },
    }
}

fn v(x: f64, y: f64, z: f64) -> MbVec3 {
    MbVec3 { x, y, z }
}

fn last_error() -> String {
    // SAFETY: the library returns a NUL-terminated string, valid until the
    // next failing call on this thread; it is copied at once.
    unsafe { CStr::from_ptr(mb_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

fn motion(p: MbPose, lin: MbVec3, ang: MbVec3, duration: f64) -> *mut MbMotion {
    let mut m = ptr::null_mut();
    // SAFETY: `&mut m` is a valid out pointer.
    let s = unsafe { mb_motion_from_velocities(p, lin, ang, duration, &mut m) };
    assert_eq!(s, MbStatus::Ok, "{}", last_error());
    m
}

#[test]
fn balls_head_on_and_bad_input() {
    let mut ball = ptr::null_mut();
    // SAFETY: valid out pointers and live handles throughout; each handle is
    // freed once, at the end.
    unsafe {
        assert_eq!(mb_shape_ball(0.5, &mut ball), MbStatus::Ok);
        let a = motion(
            pose(-2.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(0.0, 0.0, 0.0),
            2.0,
        );
        let b = motion(
            pose(2.0, 0.0, 0.0),
            v(-1.0, 0.0, 0.0),
            v(0.0, 0.0, 0.0),
            2.0,
        );
        let p = mb_params_default();
        let mut r = std::mem::MaybeUninit::<MbReport>::uninit();
        assert_eq!(
            mb_time_of_impact(ball, a, ball, b, &p, r.as_mut_ptr()),
            MbStatus::Ok
        );
        let r = r.assume_init();
        // The gap 3 closes at 2: touching at 1.5, within the contact
        // distance from (3 - d) / 2 on.
        assert_eq!(r.outcome, MbOutcome::Contact);
        assert!(
            r.time <= 1.5 && r.time >= (3.0 - p.contact_distance) / 2.0,
            "time {}",
            r.time
        );
        assert!(
            (r.witness_a.x - (r.time - 1.5)).abs() < 1e-9,
            "{:?}",
            r.witness_a
        );

        // Bad input: codes, messages, nothing written.
        let mut out = ptr::null_mut();
        assert_eq!(mb_shape_ball(f64::NAN, &mut out), MbStatus::InvalidInput);
        assert!(out.is_null());
        assert!(last_error().contains("radius"), "{}", last_error());
        let mut rep = std::mem::MaybeUninit::<MbReport>::uninit();
        assert_eq!(
            mb_time_of_impact(ptr::null(), a, ball, b, ptr::null(), rep.as_mut_ptr()),
            MbStatus::NullPointer
        );
        assert_eq!(
            mb_time_of_impact(ball, ball.cast(), ball, b, ptr::null(), rep.as_mut_ptr()),
            MbStatus::InvalidHandle
        );
        let tris = [0u32, 1, 5];
        let verts = [0.0f64, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        assert_eq!(
            mb_shape_mesh(verts.as_ptr(), 3, tris.as_ptr(), 1, 0, &mut out),
            MbStatus::InvalidMesh
        );
        assert!(out.is_null());

        assert_eq!(mb_motion_free(a), MbStatus::Ok);
        assert_eq!(mb_motion_free(b), MbStatus::Ok);
        assert_eq!(mb_shape_free(ball), MbStatus::Ok);
        assert_eq!(mb_shape_free(ball), MbStatus::InvalidHandle);
    }
}

#[test]
fn error_messages_are_per_thread() {
    let mut out = ptr::null_mut();
    // SAFETY: a valid out pointer.
    let status = unsafe { mb_shape_ball(-1.0, &mut out) };
    assert_eq!(status, MbStatus::InvalidInput);
    let here = last_error();
    let there = std::thread::spawn(last_error)
        .join()
        .expect("the thread runs");
    assert!(here.contains("radius"), "{here}");
    assert_eq!(there, "", "a new thread has no error yet");
}
