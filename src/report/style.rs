//! Figure style: the embedded font, sizes and colours shared by every figure.

use plotters::style::{FontStyle, RGBColor};
use std::sync::OnceLock;

/// DejaVu Sans, shipped in `assets/fonts/` with its licence, so figures need no system fonts.
const DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Font family name every figure uses.
pub const FONT: &str = "sans-serif";

/// Registers the embedded font with plotters once; returns an error message if it fails.
pub fn ensure_font() -> Result<(), String> {
    static REGISTERED: OnceLock<Result<(), String>> = OnceLock::new();
    REGISTERED
        .get_or_init(|| {
            plotters::style::register_font(FONT, FontStyle::Normal, DEJAVU_SANS)
                .map_err(|_| "the embedded DejaVu Sans font could not be parsed".to_string())
        })
        .clone()
}

/// Size of every figure in pixels (fits a report page at 150 dpi: 6 × 4.7 inches).
pub const FIGURE_SIZE: (u32, u32) = (900, 700);
/// Title font size in pixels.
pub const TITLE_SIZE: u32 = 26;
/// Axis-label and legend font size in pixels.
pub const LABEL_SIZE: u32 = 18;
/// Tick-label font size in pixels.
pub const TICK_SIZE: u32 = 15;

/// The three patch colours of Codice 14: `[107, 98, 229; 141, 214, 130; 227, 201, 83]/255`.
pub const CODICE14_COLORS: [RGBColor; 3] = [
    RGBColor(107, 98, 229),
    RGBColor(141, 214, 130),
    RGBColor(227, 201, 83),
];

/// Codice 14's colour for patch row `i` (0-based): MATLAB's `colors(mod(i, 3) + 1, :)` with
/// the 1-based `i` of the listing.
pub fn codice14_color(i: usize) -> RGBColor {
    CODICE14_COLORS[(i + 1) % 3]
}

/// Face opacity of the spline figures (`'FaceAlpha', .8` in Codice 14).
pub const FACE_ALPHA: f64 = 0.8;

/// Five well-separated colours for the patches of a whole surface (Fig 7), from the
/// colour-blind-safe Okabe–Ito palette: blue, orange, green, reddish purple, yellow.
pub const PATCH_PALETTE: [RGBColor; 5] = [
    RGBColor(0, 114, 178),
    RGBColor(230, 159, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(240, 228, 66),
];

/// Colours for the series of plane figures, distinguishable by colour-blind readers: the
/// Okabe–Ito blue, vermillion, bluish green, reddish purple, orange, sky blue, and black.
pub const LINE_PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
];

/// Viridis-like colour map on `[0, 1]` (piecewise linear through five anchors of matplotlib's
/// viridis), for height shading and error maps.
pub fn colormap(x: f64) -> RGBColor {
    const ANCHORS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let x = if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let pos = x * (ANCHORS.len() - 1) as f64;
    let k = (pos.floor() as usize).min(ANCHORS.len() - 2);
    let f = pos - k as f64;
    let (a, b) = (ANCHORS[k], ANCHORS[k + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}
