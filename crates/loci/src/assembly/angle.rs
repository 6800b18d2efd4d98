//! The angle mate as the seed describes it: the target's normalisation, the tolerance, and
//! the measurement kept in the mate's persistent data.
//!
//! The seed measures the signed angle about `a × b`, recomputed at every measurement, so its
//! sign turns over whenever the parts pass through 0 or 180 degrees (the measured angle is
//! then never negative). Here the axis is taken from `a × b` once, when the mate is first
//! solved, and then held in A's frame: the signed angle is continuous through 0 and 180
//! degrees and a negative target is reached by turning the other way, not by a flip.
//!
//! The simultaneous solve writes the angle as one core equation: B's direction is
//! perpendicular to `c = -sin(t) a + cos(t) (n × a)`, a direction fixed in A's frame. It is
//! well conditioned at every target, 0 and 180 degrees included (a cosine equation has a
//! double root there), and its only other root, half a turn away, is kept out of reach by
//! turning the parts to within a quarter turn first ([`Assembly::solve_stepped`](super::Assembly::solve_stepped)).

/// The largest rotation one stepped iteration applies to a component (10 degrees), as the
/// seed's parallel alignment utilities have it.
pub const MAX_ROTATION_PER_ITERATION: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// The smallest angular tolerance (0.001 degree, in radians), the seed's `ANGLE_TOLERANCE`.
pub const ANGLE_TOLERANCE: f64 = 0.001 * std::f64::consts::PI / 180.0;

/// A target in degrees as the seed normalises it: clamped to `[-360, 360]`, then wrapped to
/// `(-180, 180]`, with 180 kept as -180 when the request was negative. Not a number gives 0.
#[must_use]
pub fn normalise_degrees(value: f64) -> f64 {
    if !value.is_finite() {
        return 0.0;
    }
    let v = value.clamp(-360.0, 360.0);
    let wrapped = v.rem_euclid(360.0);
    if wrapped == 180.0 {
        return if v < 0.0 { -180.0 } else { 180.0 };
    }
    if wrapped > 180.0 {
        wrapped - 360.0
    } else {
        wrapped
    }
}

/// The angular tolerance in radians: the request's `angle_tolerance` when given (never below
/// [`ANGLE_TOLERANCE`]), else ten times the positional tolerance (never below it either).
#[must_use]
pub fn angle_tolerance(angle_tolerance: Option<f64>, positional: f64) -> f64 {
    match angle_tolerance {
        Some(t) if t.is_finite() && t.abs() > 0.0 => t.abs().max(ANGLE_TOLERANCE),
        _ => (positional.abs() * 10.0).max(ANGLE_TOLERANCE),
    }
}

/// An angle mate's reading.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AngleReading {
    /// The unsigned angle between the two directions, radians in `[0, pi]`.
    pub angle: f64,
    /// The same in degrees.
    pub angle_deg: f64,
    /// The signed angle from A's direction to B's about the held axis, radians in `(-pi, pi]`.
    pub signed: f64,
    /// The same in degrees.
    pub signed_deg: f64,
    /// The signed angle less the target, wrapped to `(-pi, pi]`.
    pub error: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_normalise_as_the_seed_does() {
        assert_eq!(normalise_degrees(30.0), 30.0);
        assert_eq!(normalise_degrees(-30.0), -30.0);
        assert_eq!(normalise_degrees(270.0), -90.0);
        assert_eq!(normalise_degrees(-270.0), 90.0);
        assert_eq!(normalise_degrees(720.0), 0.0);
        assert_eq!(normalise_degrees(-500.0), 0.0);
        assert_eq!(normalise_degrees(180.0), 180.0);
        assert_eq!(normalise_degrees(-180.0), -180.0);
        assert_eq!(normalise_degrees(540.0), 0.0);
        assert_eq!(normalise_degrees(f64::NAN), 0.0);
    }

    #[test]
    fn tolerance_from_request_or_from_position() {
        assert_eq!(angle_tolerance(Some(0.01), 1e-10), 0.01);
        assert_eq!(angle_tolerance(Some(1e-9), 1e-10), ANGLE_TOLERANCE);
        assert_eq!(angle_tolerance(None, 1e-3), 1e-2);
        assert_eq!(angle_tolerance(None, 1e-10), ANGLE_TOLERANCE);
    }
}
