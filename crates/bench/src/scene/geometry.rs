//! The geometry the scenes need and nothing more: horizontal convex polygons above a receiver
//! plane z = 0 whose normal is +z, their projected solid angle by Lambert's polygon formula,
//! convex clipping, and ray–polygon tests. Lengths are in scene units; angles in radians.

use std::f64::consts::PI;

/// A point or direction in 3-D.
pub type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn normalized(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

/// A convex polygon in the horizontal plane z = `height` (vertices counter-clockwise seen from
/// above, in the plane's x, y coordinates).
#[derive(Debug, Clone, PartialEq)]
pub struct FlatPolygon {
    /// Vertices (x, y), counter-clockwise.
    pub vertices: Vec<[f64; 2]>,
    /// Height above the receiver plane (> 0).
    pub height: f64,
}

impl FlatPolygon {
    /// Area (shoelace), in square units.
    pub fn area(&self) -> f64 {
        shoelace(&self.vertices)
    }

    /// Whether (x, y) lies inside (boundary included).
    pub fn contains(&self, p: [f64; 2]) -> bool {
        let v = &self.vertices;
        (0..v.len()).all(|i| {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0.0
        })
    }

    /// Where the ray from `origin` (on z = 0) along `dir` (`dir[2] > 0`) crosses this plane.
    pub fn crossing(&self, origin: V3, dir: V3) -> [f64; 2] {
        let s = (self.height - origin[2]) / dir[2];
        [origin[0] + s * dir[0], origin[1] + s * dir[1]]
    }

    /// Whether the ray from `origin` along `dir` (`dir[2] > 0`) passes through the polygon.
    pub fn hit_by(&self, origin: V3, dir: V3) -> bool {
        dir[2] > 0.0 && self.contains(self.crossing(origin, dir))
    }

    /// The projected solid angle ∫ cos θ dω (steradians) the polygon subtends at `p` on the
    /// receiver plane.
    pub fn projected_solid_angle(&self, p: V3) -> f64 {
        projected_solid_angle(p, &self.lifted())
    }

    /// The vertices in 3-D.
    pub fn lifted(&self) -> Vec<V3> {
        self.vertices
            .iter()
            .map(|v| [v[0], v[1], self.height])
            .collect()
    }

    /// The central projection from `p` (on z = 0) onto the plane z = `height` (> self.height):
    /// the shadow this polygon casts on a higher plane, seen from `p`.
    pub fn projected_from(&self, p: V3, height: f64) -> FlatPolygon {
        let s = (height - p[2]) / (self.height - p[2]);
        FlatPolygon {
            vertices: self
                .vertices
                .iter()
                .map(|v| [p[0] + s * (v[0] - p[0]), p[1] + s * (v[1] - p[1])])
                .collect(),
            height,
        }
    }
}

/// Shoelace area of a counter-clockwise polygon.
pub fn shoelace(v: &[[f64; 2]]) -> f64 {
    let n = v.len();
    0.5 * (0..n)
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
}

/// Lambert's polygon formula: the projected solid angle ∫ cos θ dω of a planar polygon seen
/// from `p` on z = 0 with normal +z, (1/2)|Σ Θ_i n·Γ_i| where Θ_i is the angle between the
/// directions to vertices i and i+1 and Γ_i the unit normal of their plane. The polygon must lie
/// wholly above the plane z = `p[2]`. An empty polygon subtends 0.
pub fn projected_solid_angle(p: V3, poly: &[V3]) -> f64 {
    let n = poly.len();
    if n < 3 {
        return 0.0;
    }
    let dirs: Vec<V3> = poly.iter().map(|v| normalized(sub(*v, p))).collect();
    let mut sum = 0.0;
    for i in 0..n {
        let (a, b) = (dirs[i], dirs[(i + 1) % n]);
        let c = cross(a, b);
        let len = dot(c, c).sqrt();
        if len == 0.0 {
            continue;
        }
        // atan2 keeps the angle accurate for nearly parallel directions, where acos is not.
        let theta = len.atan2(dot(a, b));
        sum += theta * c[2] / len;
    }
    0.5 * sum.abs()
}

/// The intersection of two convex counter-clockwise polygons (Sutherland–Hodgman; possibly
/// empty).
pub fn clip_convex(subject: &[[f64; 2]], clip: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut out: Vec<[f64; 2]> = subject.to_vec();
    let m = clip.len();
    for i in 0..m {
        if out.is_empty() {
            break;
        }
        let (a, b) = (clip[i], clip[(i + 1) % m]);
        let side = |p: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        let input = std::mem::take(&mut out);
        for k in 0..input.len() {
            let (p, q) = (input[k], input[(k + 1) % input.len()]);
            let (sp, sq) = (side(p), side(q));
            if sp >= 0.0 {
                out.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                let t = sp / (sp - sq);
                out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
            }
        }
    }
    out
}

/// A cosine-distributed direction about +z from two uniforms (u0 picks sin²θ, u1 the azimuth);
/// its density is cos θ / π per steradian.
pub fn cosine_direction(u0: f64, u1: f64) -> V3 {
    let r = u0.sqrt();
    let phi = 2.0 * PI * u1;
    [r * phi.cos(), r * phi.sin(), (1.0 - u0).max(0.0).sqrt()]
}

/// The unit direction from `a` to `b` and the squared distance.
pub fn direction_to(a: V3, b: V3) -> (V3, f64) {
    let d = sub(b, a);
    let d2 = dot(d, d);
    let l = d2.sqrt();
    ([d[0] / l, d[1] / l, d[2] / l], d2)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x0: f64, y0: f64, s: f64, h: f64) -> FlatPolygon {
        FlatPolygon {
            vertices: vec![[x0, y0], [x0 + s, y0], [x0 + s, y0 + s], [x0, y0 + s]],
            height: h,
        }
    }

    #[test]
    fn a_huge_square_overhead_fills_the_hemisphere() {
        // ∫ cos dω over the hemisphere is π; a square of half-width R at height 1 misses a band
        // of order 1/R.
        let s = square(-1e4, -1e4, 2e4, 1.0);
        let psa = s.projected_solid_angle([0.0, 0.0, 0.0]);
        assert!((psa - PI).abs() < 1e-3, "{psa}");
    }

    #[test]
    fn a_small_square_overhead_subtends_area_over_distance_squared() {
        // A tiny patch of area A at height h straight above: cos θ = 1, ω = A / h².
        let s = square(-0.0005, -0.0005, 0.001, 2.0);
        let psa = s.projected_solid_angle([0.0, 0.0, 0.0]);
        assert!((psa - 1e-6 / 4.0).abs() < 1e-12, "{psa}");
    }

    #[test]
    fn the_unit_square_formula_matches_the_closed_form_for_a_corner_rectangle() {
        // Form factor from a point to a parallel rectangle with one corner overhead (a, b its
        // sides, h its height): F = (1/2π)(X/√(1+X²) atan(Y/√(1+X²)) + Y/√(1+Y²) atan(X/√(1+Y²)))
        // with X = a/h, Y = b/h; the projected solid angle is π F.
        let (a, b, h) = (0.7, 1.3, 0.9);
        let r = FlatPolygon {
            vertices: vec![[0.0, 0.0], [a, 0.0], [a, b], [0.0, b]],
            height: h,
        };
        let (x, y) = (a / h, b / h);
        let f = (x / (1.0 + x * x).sqrt() * (y / (1.0 + x * x).sqrt()).atan()
            + y / (1.0 + y * y).sqrt() * (x / (1.0 + y * y).sqrt()).atan())
            / (2.0 * PI);
        let psa = r.projected_solid_angle([0.0, 0.0, 0.0]);
        assert!((psa - PI * f).abs() < 1e-14, "{psa} vs {}", PI * f);
    }

    #[test]
    fn clipping_two_squares_gives_their_overlap() {
        let a = square(0.0, 0.0, 1.0, 1.0).vertices;
        let b = square(0.5, 0.25, 1.0, 1.0).vertices;
        assert!((shoelace(&clip_convex(&a, &b)) - 0.5 * 0.75).abs() < 1e-15);
        let far = square(3.0, 3.0, 1.0, 1.0).vertices;
        assert!(clip_convex(&a, &far).is_empty());
    }

    #[test]
    fn projection_scales_about_the_viewpoint() {
        let s = square(1.0, 1.0, 1.0, 1.0);
        let p = s.projected_from([0.0, 0.0, 0.0], 2.0);
        assert_eq!(p.vertices[0], [2.0, 2.0]);
        assert_eq!(p.vertices[2], [4.0, 4.0]);
        assert!((p.area() - 4.0).abs() < 1e-15);
    }

    #[test]
    fn rays_hit_inside_and_miss_outside() {
        let s = square(-0.5, -0.5, 1.0, 2.0);
        assert!(s.hit_by([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]));
        assert!(s.hit_by([0.0, 0.0, 0.0], normalized([0.24, 0.0, 1.0])));
        assert!(!s.hit_by([0.0, 0.0, 0.0], normalized([0.26, 0.0, 1.0])));
        assert!(!s.hit_by([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]));
    }

    #[test]
    fn cosine_directions_are_unit_and_upward() {
        for (u0, u1) in [(0.0, 0.0), (0.3, 0.7), (0.999, 0.5)] {
            let d = cosine_direction(u0, u1);
            assert!((dot(d, d) - 1.0).abs() < 1e-12);
            assert!(d[2] >= 0.0);
            assert!((d[2] * d[2] - (1.0 - u0)).abs() < 1e-12);
        }
    }
}
