//! Anti-aliased bitmaps: a drawing backend that takes the coordinates of a `w × h` picture and
//! draws them `k` times larger on the backend it wraps, so that averaging each `k × k` block
//! afterwards ([`downsample`]) gives smooth edges. Plotters' bitmap backend draws lines and
//! polygons without anti-aliasing; its text is already smooth and stays so.
//!
//! Every length the elements compute (stroke widths, radii, font sizes, text extents) is in
//! the small picture's pixels and is scaled here, so a figure drawn through this backend is
//! the same drawing as on the SVG backend, only sharper.

use plotters::style::{FontDesc, TextStyle};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};

/// Draws on `inner` (of size `k·w × k·h`) what is drawn on it in `w × h` coordinates.
pub struct Supersampled<B> {
    inner: B,
    k: i32,
}

impl<B: DrawingBackend> Supersampled<B> {
    /// Wraps `inner`, whose size must be `k` times the size of the picture drawn.
    pub fn new(inner: B, k: u32) -> Self {
        Self {
            inner,
            k: k.max(1) as i32,
        }
    }

    fn at(&self, (x, y): BackendCoord) -> BackendCoord {
        (x * self.k, y * self.k)
    }
}

/// A style with its stroke width scaled.
struct Wider {
    color: BackendColor,
    width: u32,
}

impl BackendStyle for Wider {
    fn color(&self) -> BackendColor {
        self.color
    }
    fn stroke_width(&self) -> u32 {
        self.width
    }
}

impl<B: DrawingBackend> Supersampled<B> {
    fn wider<S: BackendStyle>(&self, style: &S) -> Wider {
        Wider {
            color: style.color(),
            width: style.stroke_width() * self.k as u32,
        }
    }
}

impl<B: DrawingBackend> DrawingBackend for Supersampled<B> {
    type ErrorType = B::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        let (w, h) = self.inner.get_size();
        (w / self.k as u32, h / self.k as u32)
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        self.inner.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let (x, y) = self.at(point);
        let k = self.k;
        self.inner
            .draw_rect((x, y), (x + k - 1, y + k - 1), &color, true)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let style = self.wider(style);
        let (a, b) = (self.at(from), self.at(to));
        if style.width <= 1 {
            self.inner.draw_line(a, b, &style)
        } else {
            self.inner.draw_path([a, b], &style)
        }
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let (a, b) = (self.at(upper_left), self.at(bottom_right));
        let k = self.k;
        if fill {
            self.inner
                .draw_rect(a, (b.0 + k - 1, b.1 + k - 1), &style.color(), true)
        } else {
            let style = self.wider(style);
            let ring = [a, (b.0, a.1), b, (a.0, b.1), a];
            self.inner.draw_path(ring, &style)
        }
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        // Segment by segment, with round joins: a wide polyline polygonized as a whole gets
        // miter spikes at sharp turns (plotters' `polygonize`), which at this scale would
        // streak across the picture.
        let style = self.wider(style);
        let k = self.k;
        let points: Vec<BackendCoord> = path.into_iter().map(|(x, y)| (x * k, y * k)).collect();
        for w in points.windows(2) {
            self.inner.draw_path([w[0], w[1]], &style)?;
        }
        if style.width > 2 {
            let r = style.width / 2;
            for p in points.iter().skip(1).take(points.len().saturating_sub(2)) {
                self.inner.draw_circle(*p, r, &style.color, true)?;
            }
        }
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let style = self.wider(style);
        self.inner
            .draw_circle(self.at(center), radius * self.k as u32, &style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let k = self.k;
        let points: Vec<BackendCoord> = vert.into_iter().map(|(x, y)| (x * k, y * k)).collect();
        self.inner.fill_polygon(points, &style.color())
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        let font = FontDesc::new(style.family(), style.size() * self.k as f64, style.style())
            .transform(style.transform());
        let scaled = TextStyle {
            font,
            color: style.color(),
            pos: style.anchor(),
        };
        self.inner.draw_text(text, &scaled, self.at(pos))
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        (iw, ih): (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<B::ErrorType>> {
        // nearest-neighbour enlargement of an RGB bitmap
        let k = self.k as u32;
        let mut big = vec![0u8; (iw * k * ih * k * 3) as usize];
        for y in 0..ih * k {
            for x in 0..iw * k {
                let s = (((y / k) * iw + x / k) * 3) as usize;
                let d = ((y * iw * k + x) * 3) as usize;
                if let (Some(from), Some(to)) = (src.get(s..s + 3), big.get_mut(d..d + 3)) {
                    to.copy_from_slice(from);
                }
            }
        }
        self.inner.blit_bitmap(self.at(pos), (iw * k, ih * k), &big)
    }
}

/// Averages each `k × k` block of an RGB buffer of `k·w × k·h` pixels into one pixel of a
/// `w × h` buffer (a box filter: `k²` coverage levels per edge pixel).
pub fn downsample(big: &[u8], (w, h): (u32, u32), k: u32) -> Vec<u8> {
    let (w, h, k) = (w as usize, h as usize, k.max(1) as usize);
    let big_w = w * k;
    let mut out = vec![0u8; w * h * 3];
    let area = (k * k) as u32;
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0u32; 3];
            for dy in 0..k {
                let row = ((y * k + dy) * big_w + x * k) * 3;
                for dx in 0..k {
                    let p = row + dx * 3;
                    for (c, s) in sum.iter_mut().enumerate() {
                        *s += u32::from(big.get(p + c).copied().unwrap_or(255));
                    }
                }
            }
            let o = (y * w + x) * 3;
            for c in 0..3 {
                out[o + c] = ((sum[c] + area / 2) / area) as u8;
            }
        }
    }
    out
}
