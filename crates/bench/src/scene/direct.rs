//! Direct lighting from a polygonal area light on a Lambertian receiver past an occluder, with
//! multiple importance sampling (one light sample, one BSDF sample, balance heuristic). The
//! reference is Lambert's polygon formula for the light minus the part the occluder hides:
//! seen from the receiver point, the hidden part is the occluder's central projection onto the
//! light's plane clipped to the light, itself a convex polygon.

use super::geometry::{clip_convex, cosine_direction, direction_to, FlatPolygon, V3};
use super::{Scene, Slot};
use std::f64::consts::PI;

/// A receiver plane z = 0 (normal +z), a rectangular light facing down and a convex occluder
/// between them, both horizontal.
#[derive(Debug, Clone, PartialEq)]
pub struct Room {
    /// The light: a rectangle, corner `light_corner`, sides `light_size` along x and y.
    pub light: FlatPolygon,
    /// Corner (x, y) of the light.
    pub light_corner: [f64; 2],
    /// Sides of the light along x and y.
    pub light_size: [f64; 2],
    /// The occluder (below the light).
    pub occluder: FlatPolygon,
}

impl Default for Room {
    fn default() -> Self {
        let (corner, size, h) = ([-0.5, -0.3], [1.0, 0.6], 2.0);
        Room {
            light: FlatPolygon {
                vertices: vec![
                    corner,
                    [corner[0] + size[0], corner[1]],
                    [corner[0] + size[0], corner[1] + size[1]],
                    [corner[0], corner[1] + size[1]],
                ],
                height: h,
            },
            light_corner: corner,
            light_size: size,
            occluder: FlatPolygon {
                vertices: vec![[-0.4, -0.45], [0.65, -0.15], [-0.2, 0.55]],
                height: 1.0,
            },
        }
    }
}

impl Room {
    /// The part of the light the occluder hides from `p`, on the light's plane.
    fn hidden(&self, p: V3) -> FlatPolygon {
        let shadow = self.occluder.projected_from(p, self.light.height);
        FlatPolygon {
            vertices: clip_convex(&shadow.vertices, &self.light.vertices),
            height: self.light.height,
        }
    }

    /// Exact ∫ V(ω) cos θ dω over the light's directions from receiver point `p`
    /// (steradians): the light's projected solid angle minus the hidden part's.
    pub fn direct_exact(&self, p: V3) -> f64 {
        self.light.projected_solid_angle(p) - self.hidden(p).projected_solid_angle(p)
    }

    /// Exact ∫ cos θ dω over the sky directions from `p` that neither the light nor the
    /// occluder covers: π − light − occluder + their overlap (the hidden part of the light).
    pub fn sky_exact(&self, p: V3) -> f64 {
        PI - self.light.projected_solid_angle(p) - self.occluder.projected_solid_angle(p)
            + self.hidden(p).projected_solid_angle(p)
    }

    /// Whether the occluder blocks the ray from `p` along `w`.
    fn blocked(&self, p: V3, w: V3) -> bool {
        self.occluder.hit_by(p, w)
    }

    /// The light's solid-angle density for direction `w` from `p` when sampling its area
    /// uniformly: d² / (A cos θ_light), with d the distance along `w` to the light's plane.
    fn light_pdf(&self, p: V3, w: V3) -> f64 {
        let d = (self.light.height - p[2]) / w[2];
        d * d / (self.light_size[0] * self.light_size[1] * w[2])
    }

    /// One MIS estimate of [`Room::direct_exact`]: a uniform point on the light from `ul` and
    /// a cosine-sampled direction from `ub`, each weighted by the balance heuristic, so each
    /// contributes cos θ / (pdf_light + pdf_bsdf) when it reaches the light unblocked.
    pub fn direct_mis(&self, p: V3, ul: [f64; 2], ub: [f64; 2]) -> f64 {
        let mut sum = 0.0;
        let q = [
            self.light_corner[0] + self.light_size[0] * ul[0],
            self.light_corner[1] + self.light_size[1] * ul[1],
            self.light.height,
        ];
        let (w, _) = direction_to(p, q);
        if !self.blocked(p, w) {
            sum += w[2] / (self.light_pdf(p, w) + w[2] / PI);
        }
        let w = cosine_direction(ub[0], ub[1]);
        if w[2] > 0.0 && self.light.hit_by(p, w) && !self.blocked(p, w) {
            sum += w[2] / (self.light_pdf(p, w) + w[2] / PI);
        }
        sum
    }

    /// Whether a cosine-sampled bounce from `p` (from `ub`) escapes to the sky: it meets
    /// neither the light nor the occluder. Its mean is [`Room::sky_exact`] / π.
    pub fn escapes(&self, p: V3, ub: [f64; 2]) -> bool {
        let w = cosine_direction(ub[0], ub[1]);
        w[2] > 0.0 && !self.light.hit_by(p, w) && !self.blocked(p, w)
    }
}

const SLOTS: &[Slot] = &[
    Slot {
        name: "light",
        dims: 2,
    },
    Slot {
        name: "bsdf",
        dims: 2,
    },
];

/// Reflected radiance at one receiver point in the occluder's penumbra: ρ/π · L · ∫ V cos dω,
/// estimated by MIS (4-D).
#[derive(Debug, Clone, PartialEq)]
pub struct DirectScene {
    /// Geometry.
    pub room: Room,
    /// The receiver point.
    pub point: V3,
    /// Light radiance L.
    pub radiance: f64,
    /// Albedo ρ.
    pub albedo: f64,
}

impl Default for DirectScene {
    fn default() -> Self {
        DirectScene {
            room: Room::default(),
            point: [0.5, 0.25, 0.0],
            radiance: 5.0,
            albedo: 0.8,
        }
    }
}

impl Scene for DirectScene {
    fn name(&self) -> &'static str {
        "direct"
    }
    fn summary(&self) -> &'static str {
        "direct lighting in a penumbra: rectangle light, triangle occluder, MIS of light and BSDF samples (4-D)"
    }
    fn slots(&self) -> &'static [Slot] {
        SLOTS
    }
    fn estimate(&self, _pixel: usize, u: &[f64]) -> f64 {
        self.albedo / PI
            * self.radiance
            * self.room.direct_mis(self.point, [u[0], u[1]], [u[2], u[3]])
    }
    fn reference(&self, _pixel: usize) -> f64 {
        self.albedo / PI * self.radiance * self.room.direct_exact(self.point)
    }
    fn reference_error(&self) -> f64 {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_point_is_in_the_penumbra() {
        let room = Room::default();
        let p = DirectScene::default().point;
        let full = room.light.projected_solid_angle(p);
        let seen = room.direct_exact(p);
        assert!(seen > 0.2 * full && seen < 0.8 * full, "{seen} of {full}");
    }

    #[test]
    fn far_from_the_occluder_nothing_is_hidden() {
        let room = Room::default();
        let p = [3.0, 3.0, 0.0];
        assert_eq!(room.direct_exact(p), room.light.projected_solid_angle(p));
        let sky = room.sky_exact(p);
        let expect =
            PI - room.light.projected_solid_angle(p) - room.occluder.projected_solid_angle(p);
        assert!((sky - expect).abs() < 1e-15);
    }

    #[test]
    fn straight_under_the_occluder_the_light_is_hidden() {
        // From (0, 0, 0) the occluder's shadow on the light plane is the triangle doubled,
        // which covers the light: no direct light, and the sky misses the occluder's whole
        // projected solid angle.
        let room = Room::default();
        let p = [0.0, 0.0, 0.0];
        assert!(room.direct_exact(p).abs() < 1e-15);
        let sky = room.sky_exact(p);
        assert!((sky - (PI - room.occluder.projected_solid_angle(p))).abs() < 1e-12);
    }
}
