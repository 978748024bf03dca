//! Status codes, the per-thread error message, and the guard that turns every
//! failure (and every panic) into a status.

use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// What a call of this library ended with. `MB_STATUS_OK` (`0`) is success;
/// on any other status nothing was written through the call's `out`
/// pointers, and `mb_last_error_message` says what went wrong.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MbStatus {
    /// Success.
    Ok = 0,
    /// A required pointer (a handle, an array or an `out` pointer) was `NULL`.
    NullPointer = 1,
    /// A handle that this library did not give out, has already freed, or
    /// that is of another type (a motion passed as a shape, say).
    InvalidHandle = 2,
    /// A number the core refuses: NaN or infinite, beyond the input range
    /// (`2^507`), a negative radius, a zero direction or quaternion, a
    /// non-positive duration, a zero height.
    InvalidInput = 3,
    /// A triangle mesh the library cannot use: no vertex or no triangle, an
    /// index out of range, a mesh asked to be solid that is not closed and
    /// wound outward.
    InvalidMesh = 4,
    /// A count or array that cannot be right: zero items where some are
    /// needed, a size that overflows, a misaligned array.
    InvalidSize = 5,
    /// A query parameter out of range (`mb_params`).
    InvalidParameter = 6,
    /// A query that cannot run on these inputs: motions over different
    /// intervals, a turning half-space, two half-spaces, a body added to a
    /// scene with another duration.
    QueryError = 7,
    /// An index past the end (of a scene result).
    OutOfRange = 8,
    /// A bug in this library (a Rust panic, caught at the boundary).
    InternalError = 9,
    /// A URDF the library cannot use: unreadable or malformed, an
    /// unsupported joint kind or mesh format, links and joints that do not
    /// form one tree (`mb_chain_from_urdf_*`).
    InvalidUrdf = 10,
    /// A name that is not a link's (`mb_chain_*`).
    UnknownName = 11,
}

/// A failure: its status and message.
#[derive(Debug)]
pub(crate) struct Failure {
    pub(crate) status: MbStatus,
    pub(crate) message: String,
}

impl Failure {
    pub(crate) fn new(status: MbStatus, message: impl Into<String>) -> Self {
        Self {
            status,
            message: message.into(),
        }
    }
}

impl From<motion_bound::InputError> for Failure {
    fn from(e: motion_bound::InputError) -> Self {
        match e {
            motion_bound::InputError::NoTriangles
            | motion_bound::InputError::TriangleIndexOutOfRange { .. } => {
                Self::new(MbStatus::InvalidMesh, e.to_string())
            }
            _ => Self::new(MbStatus::InvalidInput, e.to_string()),
        }
    }
}

impl From<motion_bound::ca::ArgError> for Failure {
    fn from(e: motion_bound::ca::ArgError) -> Self {
        use motion_bound::ca::Problem;
        use motion_bound::{InputError, MeshError};
        let status = match e.problem() {
            Problem::Mesh(MeshError::Vertex(_)) => MbStatus::InvalidInput,
            Problem::Mesh(_)
            | Problem::Input(
                InputError::NoTriangles | InputError::TriangleIndexOutOfRange { .. },
            ) => MbStatus::InvalidMesh,
            _ => MbStatus::InvalidInput,
        };
        Self::new(status, e.to_string())
    }
}

/// The core's refusal of a motion's input, named by the C argument it came
/// in (the quantity it is about says which).
pub(crate) fn motion_input(e: motion_bound::InputError) -> Failure {
    use motion_bound::{InputError as E, Quantity as Q};
    let q = match e {
        E::NonFinite(q) | E::TooLarge(q) => Some(q),
        _ => None,
    };
    let arg = match (e, q) {
        (_, Some(Q::LinearVelocity)) => "linear",
        (_, Some(Q::AngularVelocity)) => "angular",
        (_, Some(Q::Centre)) => "centre",
        (_, Some(Q::LocalCentre)) => "local_centre",
        (_, Some(Q::Orientation)) | (E::ZeroQuaternion, _) => "rotation",
        (E::NonPositiveDuration, _) | (_, Some(Q::Duration | Q::Time)) => "duration",
        _ => "start, end",
    };
    motion_bound::ca::ArgError::input(arg)(e).into()
}

impl From<motion_bound::MeshError> for Failure {
    fn from(e: motion_bound::MeshError) -> Self {
        match e {
            // A NaN, infinite or out-of-range vertex: a bad number, as elsewhere.
            motion_bound::MeshError::Vertex(_) => Self::new(MbStatus::InvalidInput, e.to_string()),
            _ => Self::new(MbStatus::InvalidMesh, e.to_string()),
        }
    }
}

impl From<motion_bound::ca::CaError> for Failure {
    fn from(e: motion_bound::ca::CaError) -> Self {
        use motion_bound::ca::CaError;
        match e {
            CaError::Input(i) => i.into(),
            CaError::InvalidParameter(_) => Self::new(MbStatus::InvalidParameter, e.to_string()),
            _ => Self::new(MbStatus::QueryError, e.to_string()),
        }
    }
}

impl From<motion_bound::scene::SceneQueryError> for Failure {
    fn from(e: motion_bound::scene::SceneQueryError) -> Self {
        use motion_bound::scene::SceneQueryError;
        match e {
            SceneQueryError::Input(i) => i.into(),
            SceneQueryError::Ca(c) => c.into(),
            _ => Self::new(MbStatus::QueryError, e.to_string()),
        }
    }
}

/// What the functions' bodies return.
pub(crate) type Res<T> = Result<T, Failure>;

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

fn set_last_error(message: &str) {
    let c = CString::new(message.replace('\0', " ")).unwrap_or_default();
    LAST_ERROR.with(|last| *last.borrow_mut() = c);
}

/// Runs `body`, catching a panic: its failure's message is stored for
/// `mb_last_error_message` and its status returned.
pub(crate) fn guard(body: impl FnOnce() -> Res<()>) -> MbStatus {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => MbStatus::Ok,
        Ok(Err(f)) => {
            set_last_error(&f.message);
            f.status
        }
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".to_owned());
            set_last_error(&format!("internal error (a panic in motion-bound): {what}"));
            MbStatus::InternalError
        }
    }
}

/// The message of the last call on this thread that failed, as a
/// NUL-terminated UTF-8 string (empty when no call has failed on this
/// thread). Never `NULL`.
///
/// **Lifetime**: the string is owned by the library and stays valid until
/// the next failing call of this library on the same thread (or the
/// thread's exit); copy it to keep it. Do not free it.
///
/// **Thread safety**: the message is per thread; any thread may call this
/// at any time and reads its own last error.
#[unsafe(no_mangle)]
pub extern "C" fn mb_last_error_message() -> *const c_char {
    // A thread-local access cannot fail here (only during the thread's
    // destruction, when no C code of that thread runs); an empty static
    // string stands in should it ever.
    LAST_ERROR
        .try_with(|last| last.borrow().as_ptr())
        .unwrap_or(c"".as_ptr())
}

/// The library's version, as a static NUL-terminated string (`"0.1.0"`).
///
/// **Thread safety**: any thread, any time; the string is static.
#[unsafe(no_mangle)]
pub extern "C" fn mb_version() -> *const c_char {
    const VERSION: &std::ffi::CStr = match std::ffi::CStr::from_bytes_with_nul(
        concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes(),
    ) {
        Ok(v) => v,
        Err(_) => c"unknown",
    };
    VERSION.as_ptr()
}
