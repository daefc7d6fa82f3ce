//! A scene set up for one pipeline: per pixel its input vector and its f64 ideal (`Prepared`, `Ideal`). The
//! pipelines build it (`crate::pipeline`); the renderers run it (`crate::render`).

/// The f64 ideal of one pixel.
#[derive(Clone, Copy, Debug)]
pub struct Ideal {
    /// The shade in 8-bit units (0..255, real), on the same scale as `Pipeline::shade`.
    pub shade: f64,
    /// The blended colour, 8-bit units, real.
    pub rgb: [f64; 3],
    /// The filtered float normal and the pixel's own light direction.
    pub normal: [f64; 3],
    pub light: [f64; 3],
}

/// A scene set up for one pipeline: per pixel its input vector (in the model's port order) and its ideal, after
/// `prologue` vectors that set up the block's state for the frame (a palette's colour table; none elsewhere).
pub struct Prepared {
    pub size: usize,
    pub inputs: Vec<Vec<i64>>,
    pub prologue: usize,
    pub ideal: Vec<Ideal>,
    /// each pixel's place in the frame (row by row); empty when the pixels fill the frame in order
    pub at: Vec<usize>,
}

impl Prepared {
    pub fn new(size: usize) -> Prepared {
        Prepared { size, inputs: vec![], prologue: 0, ideal: vec![], at: vec![] }
    }

    /// Pixel k's place in the frame.
    pub fn frame_index(&self, k: usize) -> usize {
        if self.at.is_empty() {
            k
        } else {
            self.at[k]
        }
    }

    /// For each place of the frame, the pixel there, if the surface covers it.
    pub fn by_place(&self) -> Vec<Option<usize>> {
        let mut m = vec![None; self.size * self.size];
        for k in 0..self.ideal.len() {
            m[self.frame_index(k)] = Some(k);
        }
        m
    }

    /// The pixels' input vectors, the prologue left out.
    pub fn pixels(&self) -> &[Vec<i64>] {
        &self.inputs[self.prologue..]
    }
}
