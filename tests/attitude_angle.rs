//! The attitude angle (`bearing::plain::attitude_angle`, one `atan2` of the
//! cross and dot products of the load line `−F` and the eccentricity `e`)
//! against its definition: the polar angle of `e` less that of `−F`, wrapped
//! into (−π, π].

#[path = "common/rng.rs"]
mod rng;

use nalgebra::Vector2;
use rng::Rng;
use rotor_bearing::bearing::plain::attitude_angle;
use std::f64::consts::PI;

/// The definition: two polar angles, their difference, wrapped into (−π, π].
fn by_polar_angles(position: &Vector2<f64>, force: &Vector2<f64>) -> f64 {
    let d = position.y.atan2(position.x) - (-force.y).atan2(-force.x);
    let wrapped = d.sin().atan2(d.cos());
    if wrapped <= -PI {
        wrapped + 2.0 * PI
    } else {
        wrapped
    }
}

/// Distance of two angles on the circle.
fn circle_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * PI);
    d.min(2.0 * PI - d)
}

#[test]
fn quarter_turns_and_the_half_turn_are_exact() {
    let e = Vector2::new(3e-5, 0.0);
    // −F along +y: e lies a quarter turn behind the load line.
    assert_eq!(attitude_angle(&e, &Vector2::new(0.0, -2.0e4)), -PI / 2.0);
    // −F along −y: a quarter turn ahead.
    assert_eq!(attitude_angle(&e, &Vector2::new(0.0, 2.0e4)), PI / 2.0);
    // −F along e: on the load line.
    assert_eq!(attitude_angle(&e, &Vector2::new(-1.0, 0.0)), 0.0);
    // −F against e, from either side of the half turn: π, never −π.
    for y in [0.0, -0.0] {
        assert_eq!(attitude_angle(&e, &Vector2::new(1.0, y)), PI);
        assert_eq!(
            attitude_angle(&Vector2::new(-3e-5, y), &Vector2::new(-1.0, 0.0)),
            PI
        );
    }
    // No eccentricity or no load: no angle.
    assert_eq!(
        attitude_angle(&Vector2::zeros(), &Vector2::new(1.0, 2.0)),
        0.0
    );
    assert_eq!(attitude_angle(&e, &Vector2::zeros()), 0.0);
}

/// Over 200 000 random pairs, magnitudes from 1e-9 to 1e6 (a journal's
/// metres and a film's newtons), every angle in (−π, π] and within 4 ulp of π
/// (1.8e-15; 1.0e-15 seen) of the definition: each route rounds its two polar angles or its
/// products and its `atan2` once, and the definition's wrap once more.
#[test]
fn matches_the_difference_of_polar_angles_to_a_few_ulp() {
    let mut rng = Rng(0x5eed_a771_7ade);
    let mut worst = 0.0f64;
    for _ in 0..200_000 {
        let vector = |rng: &mut Rng| {
            let r = rng.log_uniform(1e-9, 1e6);
            let phi = 2.0 * PI * rng.unit();
            Vector2::new(r * phi.cos(), r * phi.sin())
        };
        let (e, f) = (vector(&mut rng), vector(&mut rng));
        let got = attitude_angle(&e, &f);
        assert!(
            got > -PI && got <= PI,
            "{got} out of (−π, π] at e = {e:?}, F = {f:?}"
        );
        worst = worst.max(circle_distance(got, by_polar_angles(&e, &f)));
    }
    let ulp_of_pi = PI.next_up() - PI;
    assert!(worst <= 4.0 * ulp_of_pi, "worst {worst:e}");
}
