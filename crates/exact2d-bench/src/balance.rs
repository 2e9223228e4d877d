//! Whether a pile at rest is in static equilibrium, checked apart from the engine.
//!
//! Frictionless contacts push along their normals and never pull. Balls at rest under gravity
//! are in equilibrium exactly when non-negative pushes `l_k` at their contacts balance every
//! ball's weight: `A l = b`, `l >= 0`, where column `k` of `A` holds contact `k`'s unit normal
//! on each of its balls (into the ball; its opposite on the other ball of a pair) and `b` each
//! ball's `-m g`. The least `|A l - b|` over `l >= 0` is found by the active-set method of
//! Lawson and Hanson ("Solving Least Squares Problems", 1974, chapter 23), which ends in
//! finitely many steps; what is left is the force the contacts cannot supply. This is the
//! global condition: the engine's sleep criterion is checked ball by ball (each ball's own
//! weight in the cone of its contact normals), which passes a ball resting on two balls that
//! the floor cannot hold apart.
//!
//! With friction (a contact's coefficient `mu`, the geometric mean of its bodies', as the
//! engine pairs them) a contact's force may also lean off its normal, anywhere within its cone
//! `|T| <= mu N`: in the plane the cone is spanned by its two edges `n +- mu t`, so a rough
//! contact is two columns, each pushed with `l >= 0`, and the same least squares answers. This
//! is the engine's own model of friction among balls in contact (`dynamics/contact_friction.rs`
//! in the engine): forces on the balls' centres, with no balance of torques (a disk held by
//! friction at two points is also turned by it; the engine keeps spin out of its groups).

use exact2d::DVec2;
use exact2d::World;
use exact2d::geometry::Shape;

/// How close two bodies count as touching, as a share of their contact distance: `1e-3`, the
/// widest gap at which the engine still holds two balls together (its groups' `GROUP_GAP`), so
/// that no contact the engine may rely on is left out (a contact too many can only help).
const TOUCHING: f64 = 1e-3;

/// How far out of balance the balls of `world` are, frictionless: the largest force left
/// unbalanced on one ball, as a share of its weight, and the norm of all of them as a share of
/// the total weight. Zero and zero in equilibrium (to rounding).
#[must_use]
pub fn out_of_balance(world: &World) -> (f64, f64) {
    let gravity = world.gravity();
    let g = gravity.length();
    let balls: Vec<_> = world.balls().map(|(_, b)| b).collect();
    if balls.is_empty() || g == 0.0 {
        return (0.0, 0.0);
    }
    // Each contact: its balls (the second `None` for a collider), the unit normal into the
    // first, and its friction coefficient.
    let mut contacts: Vec<(usize, Option<usize>, DVec2, f64)> = Vec::new();
    let pair = |a: f64, b: f64| {
        if a > 0.0 && b > 0.0 {
            (a * b).sqrt()
        } else {
            0.0
        }
    };
    for (i, a) in balls.iter().enumerate() {
        for (j, b) in balls.iter().enumerate().skip(i + 1) {
            let reach = a.radius + b.radius;
            let d = a.position - b.position;
            let length = d.length();
            if length > 0.0 && length - reach <= TOUCHING * reach {
                contacts.push((i, Some(j), d / length, pair(a.friction, b.friction)));
            }
        }
        for (_, c) in world.colliders() {
            if c.sensor {
                continue;
            }
            let closest = match c.shape {
                Shape::Segment(s) => s.closest_point(a.position),
                Shape::Circle(k) => k.center + (a.position - k.center).normalize() * k.radius,
            };
            let d = a.position - closest;
            let length = d.length();
            if length > 0.0 && length - a.radius <= TOUCHING * a.radius {
                contacts.push((i, None, d / length, pair(a.friction, c.friction)));
            }
        }
    }
    let rows = 2 * balls.len();
    let column = |i: usize, j: Option<usize>, n: DVec2| {
        let mut v = vec![0.0; rows];
        v[2 * i] += n.x;
        v[2 * i + 1] += n.y;
        if let Some(j) = j {
            v[2 * j] -= n.x;
            v[2 * j + 1] -= n.y;
        }
        v
    };
    let mut a: Vec<Vec<f64>> = Vec::with_capacity(contacts.len());
    for &(i, j, n, mu) in &contacts {
        if mu > 0.0 {
            let t = n.perp();
            a.push(column(i, j, n + mu * t));
            a.push(column(i, j, n - mu * t));
        } else {
            a.push(column(i, j, n));
        }
    }
    let mut b = vec![0.0; rows];
    for (i, ball) in balls.iter().enumerate() {
        b[2 * i] = -ball.mass * gravity.x;
        b[2 * i + 1] = -ball.mass * gravity.y;
    }
    let l = nnls(&a, &b);
    let mut residual = b.iter().map(|x| -x).collect::<Vec<f64>>();
    for (column, &lk) in a.iter().zip(&l) {
        for (r, c) in residual.iter_mut().zip(column) {
            *r += c * lk;
        }
    }
    let mut worst = 0.0_f64;
    let mut total = 0.0_f64;
    let mut weight = 0.0;
    for (i, ball) in balls.iter().enumerate() {
        let left = DVec2::new(residual[2 * i], residual[2 * i + 1]).length();
        worst = worst.max(left / (ball.mass * g));
        total += left * left;
        weight += ball.mass * g;
    }
    (worst, total.sqrt() / weight)
}

/// The least squares `min |A l - b|` over `l >= 0` (Lawson and Hanson's active-set method),
/// `A` given by its columns.
fn nnls(a: &[Vec<f64>], b: &[f64]) -> Vec<f64> {
    let n = a.len();
    let mut x = vec![0.0; n];
    let mut passive = vec![false; n];
    // `A^T (b - A x)`: how much each push would lower the residual.
    let gradient = |x: &[f64]| -> Vec<f64> {
        let mut residual = b.to_vec();
        for (column, &xk) in a.iter().zip(x) {
            for (r, c) in residual.iter_mut().zip(column) {
                *r -= c * xk;
            }
        }
        a.iter().map(|column| dot(column, &residual)).collect()
    };
    let scale = gradient(&x)
        .iter()
        .fold(0.0_f64, |s, w| s.max(w.abs()))
        .max(f64::MIN_POSITIVE);
    for _ in 0..(3 * n + 10) {
        let w = gradient(&x);
        let Some(j) = (0..n)
            .filter(|&j| !passive[j] && w[j] > 1e-12 * scale)
            .max_by(|&p, &q| w[p].total_cmp(&w[q]))
        else {
            break;
        };
        passive[j] = true;
        loop {
            let set: Vec<usize> = (0..n).filter(|&k| passive[k]).collect();
            let z = solve_columns(a, b, &set);
            if z.iter().all(|&v| v > 0.0) {
                for (&k, &v) in set.iter().zip(&z) {
                    x[k] = v;
                }
                break;
            }
            // Step from `x` towards `z` until a passive variable reaches zero: the one that
            // blocks the step leaves (set to zero, whatever rounding left of it), and so does
            // any other the step brought to zero, so that each round ends with one fewer.
            let mut block = (1.0_f64, usize::MAX);
            for (&k, &v) in set.iter().zip(&z) {
                if v <= 0.0 {
                    let alpha = x[k] / (x[k] - v);
                    if alpha < block.0 || block.1 == usize::MAX {
                        block = (alpha.min(1.0), k);
                    }
                }
            }
            let (alpha, blocking) = block;
            for (&k, &v) in set.iter().zip(&z) {
                x[k] += alpha * (v - x[k]);
                if k == blocking || x[k] <= 1e-15 * scale {
                    x[k] = 0.0;
                    passive[k] = false;
                }
            }
        }
    }
    x
}

/// The least squares `min |A_P z - b|` over the columns `set` of `A`, by the QR factorisation
/// of those columns (modified Gram-Schmidt, twice): not the normal equations, whose condition
/// is the square of the columns'. A ball pinned in an exact-fit gap, between a wall and a peg
/// whose normals are opposite but for 3e-7 radians, is held by pushes of three million times
/// its weight, and squared that wedge is lost to rounding. A column that depends on those
/// before it (to `1e-14` of its length) gets zero.
fn solve_columns(a: &[Vec<f64>], b: &[f64], set: &[usize]) -> Vec<f64> {
    let m = set.len();
    let mut q: Vec<Vec<f64>> = Vec::with_capacity(m);
    let mut r = vec![vec![0.0; m]; m];
    let mut live = vec![false; m];
    for (j, &k) in set.iter().enumerate() {
        let mut v = a[k].clone();
        let length = dot(&v, &v).sqrt();
        for _ in 0..2 {
            for (i, qi) in q.iter().enumerate() {
                if !live[i] {
                    continue;
                }
                let c = dot(qi, &v);
                r[i][j] += c;
                for (x, y) in v.iter_mut().zip(qi) {
                    *x -= c * y;
                }
            }
        }
        let left = dot(&v, &v).sqrt();
        if left > 1e-14 * length {
            for x in &mut v {
                *x /= left;
            }
            r[j][j] = left;
            live[j] = true;
        }
        q.push(v);
    }
    // `R z = Q^T b`, a dead column's `z` zero.
    let mut z = vec![0.0; m];
    for i in (0..m).rev() {
        if !live[i] {
            continue;
        }
        let mut s = dot(&q[i], b);
        for k in i + 1..m {
            s -= r[i][k] * z[k];
        }
        z[i] = s / r[i][i];
    }
    z
}

fn dot(x: &[f64], y: &[f64]) -> f64 {
    x.iter().zip(y).map(|(p, q)| p * q).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::{BallDesc, ColliderDesc};

    /// Three balls of radius 0.5 as a triangle on a floor from -5 to 5, between walls at -1
    /// and 1 if `walls`, every body of friction `mu`.
    fn triangle(walls: bool, mu: f64) -> World {
        let mut world = World::new();
        world.set_gravity(DVec2::new(0.0, -9.81)).unwrap();
        let mut segment = |a: DVec2, b: DVec2| {
            world
                .add_collider(ColliderDesc::segment(a, b).friction(mu))
                .unwrap();
        };
        segment(DVec2::new(-5.0, 0.0), DVec2::new(5.0, 0.0));
        if walls {
            segment(DVec2::new(-1.0, 0.0), DVec2::new(-1.0, 5.0));
            segment(DVec2::new(1.0, 0.0), DVec2::new(1.0, 5.0));
        }
        let h = 0.5 + 0.75_f64.sqrt();
        for p in [
            DVec2::new(-0.5, 0.5),
            DVec2::new(0.5, 0.5),
            DVec2::new(0.0, h),
        ] {
            world.add_ball(BallDesc::new(p, 0.5).friction(mu)).unwrap();
        }
        world
    }

    /// Three balls as a triangle on a floor: out of balance alone (the floor cannot hold the
    /// lower two apart), in balance between walls that hold them in.
    #[test]
    fn a_triangle_on_a_floor_is_out_of_balance_and_in_balance_between_walls() {
        let (worst, total) = out_of_balance(&triangle(false, 0.0));
        // By symmetry the least residual has the top ball's two contacts push `t` each, the
        // floor all the lower balls need upright, and the lower balls' own contact nothing:
        // the top ball is left `1 - sqrt 3 t` of its weight short and each lower ball pushed
        // out by `t / 2`, least in all at `t = 2 sqrt 3 / 7`: a lower ball `sqrt 3 / 7` of its
        // weight out of balance, and `sqrt(1 + 6) / 7` of one weight in all, of three.
        assert!((worst - 3.0_f64.sqrt() / 7.0).abs() < 1e-9, "{worst}");
        assert!((total - 7.0_f64.sqrt() / 21.0).abs() < 1e-9, "{total}");
        let (worst, total) = out_of_balance(&triangle(true, 0.0));
        assert!(worst < 1e-12 && total < 1e-12, "{worst} {total}");
    }

    /// The same triangle on an open floor, every body of friction `mu`: in balance from
    /// `mu* = (sqrt 5 - 2) / sqrt 3` (0.1363) up. The top ball's contacts may lean towards the
    /// vertical by `atan mu`, and then push each lower ball out by `(m g / 2) tan(30 deg - atan
    /// mu)`, which the floor (pressed by `3 m g / 2`) holds while that is at most
    /// `3 mu m g / 2`: `tan(pi / 6 - atan mu) = 3 mu` at `mu*`.
    #[test]
    fn friction_holds_the_triangle_from_the_angle_derived_by_hand() {
        let worst = |mu: f64| out_of_balance(&triangle(false, mu)).0;
        let critical = (5.0_f64.sqrt() - 2.0) / 3.0_f64.sqrt();
        assert!(worst(critical * 0.98) > 1e-3, "{}", worst(critical * 0.98));
        assert!(
            worst(critical * 1.0001) < 1e-12,
            "{}",
            worst(critical * 1.0001)
        );
        assert!(worst(0.5) < 1e-12);
    }
}
