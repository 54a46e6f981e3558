//! viewer's tests, one test binary (`cargo test -p viewer --test suite`; a module per concern,
//! filtered by its path: `cargo test -p viewer --test suite compare::`), so that the harness
//! runs the long tests of different files side by side.

use std::fmt::Debug;
use std::process::Output;

mod cli;
mod compare;
mod every_path;
mod render_cli;
mod sampling_cli;
mod strand;
mod version;

/// Asserts the CLI's refusal of bad input: exit code 2 and exactly one line on stderr, starting
/// `error: ` and holding every needle. `call` names the call in a failure message.
#[track_caller]
pub(crate) fn assert_refused(o: &Output, call: &dyn Debug, needles: &[&str]) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "viewer {call:?}: {err}");
    assert!(err.starts_with("error: "), "viewer {call:?}: {err:?}");
    assert!(err.ends_with('\n'), "viewer {call:?}: {err:?}");
    assert_eq!(
        err.lines().count(),
        1,
        "viewer {call:?}: one line expected: {err:?}"
    );
    for needle in needles {
        assert!(
            err.contains(needle),
            "viewer {call:?}: {err:?} should contain {needle:?}"
        );
    }
}
