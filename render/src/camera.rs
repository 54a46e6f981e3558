//! A pinhole camera (docs/model.md §11).

use nalgebra::Vector3;

/// A pinhole camera: eye, viewing direction and vertical field of view.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    eye: Vector3<f32>,
    forward: Vector3<f32>,
    right: Vector3<f32>,
    up: Vector3<f32>,
    /// tan(fov/2).
    tan_half: f32,
}

impl Camera {
    /// A camera at `eye` looking at `target`, `up` roughly upward, vertical field of view
    /// `fov_deg` degrees.
    #[must_use]
    pub fn look_at(
        eye: Vector3<f32>,
        target: Vector3<f32>,
        up: Vector3<f32>,
        fov_deg: f32,
    ) -> Camera {
        let forward = (target - eye).normalize();
        let right = forward.cross(&up).normalize();
        let up = right.cross(&forward);
        Camera {
            eye,
            forward,
            right,
            up,
            tan_half: (0.5 * fov_deg.to_radians()).tan(),
        }
    }

    /// The eye (the centre of projection).
    #[must_use]
    pub fn eye(&self) -> Vector3<f32> {
        self.eye
    }

    /// The unit viewing direction, and the unit right and up vectors of the film (a raster
    /// pipeline builds its view matrix from them).
    #[must_use]
    pub fn basis(&self) -> [Vector3<f32>; 3] {
        [self.forward, self.right, self.up]
    }

    /// tan of half the vertical field of view.
    #[must_use]
    pub fn tan_half_fov(&self) -> f32 {
        self.tan_half
    }

    /// The ray through film position (x, y) in pixels (y down) of a `width` × `height`
    /// image: origin and unit direction.
    #[must_use]
    pub fn ray(&self, x: f32, y: f32, width: u32, height: u32) -> (Vector3<f32>, Vector3<f32>) {
        let aspect = width as f32 / height as f32;
        let sx = (2.0 * x / width as f32 - 1.0) * self.tan_half * aspect;
        let sy = (1.0 - 2.0 * y / height as f32) * self.tan_half;
        let d = (self.forward + self.right * sx + self.up * sy).normalize();
        (self.eye, d)
    }
}
