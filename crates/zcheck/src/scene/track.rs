//! An invariant followed over a scene's run: its first and last value, its
//! range and its largest drift, and the summary the JSON report carries.

use serde::Serialize;

/// A quantity followed over a run: its first and last value, its range and
/// its largest departure from the first value.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Track {
    pub initial: f64,
    pub last: f64,
    pub min: f64,
    pub max: f64,
    pub max_abs_drift: f64,
}

impl Track {
    /// Start following a quantity at `initial`.
    pub(crate) fn new(initial: f64) -> Self {
        Track { initial, last: initial, min: initial, max: initial, max_abs_drift: 0.0 }
    }

    /// Record the next value (a NaN makes the drift NaN, so it shows).
    pub(crate) fn push(&mut self, value: f64) {
        self.last = value;
        self.min = self.min.min(value);
        self.max = self.max.max(value);
        let drift = (value - self.initial).abs();
        self.max_abs_drift = if drift.is_nan() { f64::NAN } else { self.max_abs_drift.max(drift) };
    }

    /// The summary the JSON report carries.
    pub(crate) fn summary(&self) -> Summary {
        Summary {
            initial: self.initial,
            r#final: self.last,
            max_abs_drift: self.max_abs_drift,
            max_rel_drift: if self.initial != 0.0 {
                Some(self.max_abs_drift / self.initial.abs())
            } else {
                None
            },
        }
    }
}

/// An invariant over a run: initial and final value and the largest drift,
/// absolute and relative to |initial| (none when the initial value is 0).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct Summary {
    pub initial: f64,
    pub r#final: f64,
    pub max_abs_drift: f64,
    pub max_rel_drift: Option<f64>,
}
