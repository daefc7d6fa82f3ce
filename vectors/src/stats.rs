//! Error statistics: mean, max and where the max occurs, as every accuracy figure in the project is reported.

#[derive(Clone, Debug)]
pub struct ErrorStats {
    pub count: u64,
    pub sum: f64,
    pub max: f64,
    pub argmax: String,
}

impl Default for ErrorStats {
    fn default() -> Self {
        ErrorStats { count: 0, sum: 0.0, max: f64::NEG_INFINITY, argmax: String::new() }
    }
}

impl ErrorStats {
    pub fn add(&mut self, err: f64, at: impl FnOnce() -> String) {
        self.count += 1;
        self.sum += err;
        if err > self.max {
            self.max = err;
            self.argmax = at();
        }
    }
    pub fn mean(&self) -> f64 {
        if self.count == 0 {
            0.0
        } else {
            self.sum / self.count as f64
        }
    }
}

/// The dot product of two 3-vectors.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A 3-vector scaled to unit length; a zero vector stays as it is.
pub fn unit(v: [f64; 3]) -> [f64; 3] {
    let l = dot(v, v).sqrt();
    if l > 0.0 {
        v.map(|c| c / l)
    } else {
        v
    }
}

/// Angle in degrees between two 3-vectors; zero-length vectors give NaN (callers decide what that means).
pub fn angle_deg(a: [f64; 3], b: [f64; 3]) -> f64 {
    let la = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    let lb = (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt();
    let c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
    c.clamp(-1.0, 1.0).acos().to_degrees()
}
