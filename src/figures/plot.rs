//! The charts of the figures: a [`Chart`] of [`Series`] over an [`XAxis`], rendered as SVG by
//! [`render`] (plotters' SVG backend), with the axes' ticks and labels chosen here
//! ([`tick_label`]) and one colour and marker per technique ([`method_color`],
//! [`method_marker`]). [`super`] and [`super::cycles`] hold what is plotted.

use crate::trace::Method;
use anyhow::{anyhow, Result};
use plotters::chart::SeriesAnno;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::prelude::*;
use std::fmt;

const RED: RGBColor = RGBColor(0xd6, 0x27, 0x28);
const BLUE_: RGBColor = RGBColor(0x1f, 0x77, 0xb4);
const GREEN_: RGBColor = RGBColor(0x2c, 0xa0, 0x2c);
/// The colour of what belongs to no technique (and of brute force).
pub(crate) const GREY: RGBColor = RGBColor(0x44, 0x44, 0x44);

/// The colour of a technique's series, the same in every chart.
pub(crate) fn method_color(m: Method) -> RGBColor {
    match m {
        Method::Conventional => RED,
        Method::Stochastic => BLUE_,
        Method::Deterministic => GREEN_,
        Method::Brute => GREY,
    }
}

/// The marker of a technique's series, the same in every chart.
pub(crate) fn method_marker(m: Method) -> Marker {
    match m {
        Method::Conventional => Marker::Square,
        Method::Stochastic => Marker::Triangle,
        _ => Marker::Circle,
    }
}

/// How the points of a series are drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Marker {
    None,
    Circle,
    Triangle,
    Square,
    Cross,
}

/// One curve of a chart.
#[derive(Clone, Debug)]
pub(crate) struct Series {
    pub(crate) label: String,
    pub(crate) points: Vec<(f64, f64)>,
    pub(crate) color: RGBColor,
    /// Join the points with a line.
    pub(crate) line: bool,
    pub(crate) marker: Marker,
    /// Text drawn next to each point (empty: none).
    pub(crate) point_labels: Vec<String>,
    /// Draw the line dashed.
    pub(crate) dashed: bool,
}

impl Series {
    pub(crate) fn new(
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        color: RGBColor,
        marker: Marker,
    ) -> Series {
        Series {
            label: label.into(),
            points,
            color,
            line: true,
            marker,
            point_labels: Vec::new(),
            dashed: false,
        }
    }
}

/// The x axis of a chart.
#[derive(Clone, Debug)]
pub(crate) enum XAxis {
    /// Log₂ scale with ticks exactly at the given values.
    Log2(Vec<f64>),
    /// Linear over the range.
    Linear(f64, f64),
}

/// A chart: title, axis labels, series. The y axis is logarithmic when every value is positive
/// and they span a factor of 10 or more, linear otherwise.
pub(crate) struct Chart {
    /// Width and height in pixels.
    pub(crate) size: (u32, u32),
    pub(crate) title: String,
    pub(crate) x_label: String,
    pub(crate) y_label: String,
    pub(crate) x: XAxis,
    pub(crate) series: Vec<Series>,
}

/// The size of a chart with a few series, in pixels.
pub(crate) const CHART_SIZE: (u32, u32) = (960, 640);

/// Formats a tick value compactly (at most 4 significant digits; powers of ten as `1e6`).
pub(crate) fn tick_label(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if !(1e-3..1e6).contains(&a) {
        let e = a.log10().floor();
        let m = v / 10f64.powf(e);
        let m = format!("{m:.2}");
        let m = m.trim_end_matches('0').trim_end_matches('.');
        return format!("{m}e{e}");
    }
    let digits = (3 - a.log10().floor() as i32).clamp(0, 6) as usize;
    let s = format!("{v:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// "Nice" linear ticks over `[lo, hi]`, about six of them.
fn linear_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = (hi - lo).max(f64::MIN_POSITIVE);
    let raw = span / 6.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0].iter().map(|m| m * mag).find(|s| *s >= raw).unwrap_or(10.0 * mag);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// Decade ticks (1, 2, 5 × 10ᵏ, or only 10ᵏ when that is too many) inside `[lo, hi]` (both > 0),
/// returned as log₁₀ values; and the light (minor) ticks 1..9 × 10ᵏ.
fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let within = |v: f64| v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
    let pick = |ms: &[f64]| -> Vec<f64> {
        (k0..=k1)
            .flat_map(|k| ms.iter().map(move |m| m * 10f64.powi(k)))
            .filter(|v| within(*v))
            .map(f64::log10)
            .collect()
    };
    let mut bold = pick(&[1.0, 2.0, 5.0]);
    if bold.len() > 10 {
        bold = pick(&[1.0]);
    }
    if bold.len() < 2 {
        bold = pick(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
    }
    let light = pick(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
    (bold, light)
}

/// A linear axis whose ticks are given: `bold` (labelled, with grid lines) and `light` (minor
/// grid lines). The charts plot transformed values (log₂ x, log₁₀ y) on it.
struct TickAxis {
    lo: f64,
    hi: f64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl Ranged for TickAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let f = (value - self.lo) / (self.hi - self.lo);
        limit.0 + (f * (limit.1 - limit.0) as f64).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }
}

/// The legend entry of a series: a short line (when the series has one) with its marker.
fn set_legend<'a, DB: DrawingBackend + 'a>(
    anno: &mut SeriesAnno<'a, DB>,
    color: RGBColor,
    line: bool,
    marker: Marker,
    dashed: bool,
) {
    let path_style =
        ShapeStyle { color: color.mix(if line { 1.0 } else { 0.0 }), filled: false, stroke_width: 2 };
    let path = move |(x, y): (i32, i32)| {
        EmptyElement::at((x, y)) + PathElement::new(vec![(-10, 0), (10, 0)], path_style)
    };
    match marker {
        Marker::None if dashed => anno.legend(move |(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(-12, 0), (-4, 0)], path_style)
                + PathElement::new(vec![(4, 0), (12, 0)], path_style)
        }),
        Marker::None => anno.legend(path),
        Marker::Circle => anno.legend(move |p| path(p) + Circle::new((0, 0), 4, color.filled())),
        Marker::Triangle => anno.legend(move |p| path(p) + TriangleMarker::new((0, 0), 5, color.filled())),
        Marker::Square => anno.legend(move |p| path(p) + Rectangle::new([(-4, -4), (4, 4)], color.filled())),
        Marker::Cross => anno.legend(move |p| path(p) + Cross::new((0, 0), 5, color.stroke_width(2))),
    };
}

/// Renders a chart as SVG text.
pub(crate) fn render(chart: &Chart) -> Result<String> {
    let pts = || chart.series.iter().flat_map(|s| s.points.iter().copied());
    let ys: Vec<f64> = pts().map(|p| p.1).filter(|y| y.is_finite()).collect();
    let (ymin, ymax) = ys.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
    let (ymin, ymax) = if ys.is_empty() { (0.0, 1.0) } else { (ymin, ymax) };
    let log_y = ymin > 0.0 && ymax / ymin >= 10.0;
    // Headroom for the legend: more for a long legend (unchanged up to four entries).
    let legend_room = (chart.series.len() as f64 / 4.0).max(1.0);

    // Transformed coordinates: log₁₀ y on a log axis, log₂ x on a log₂ axis.
    let ty = |y: f64| if log_y { y.log10() } else { y };
    let tx = |x: f64| match chart.x {
        XAxis::Log2(_) => x.log2(),
        XAxis::Linear(..) => x,
    };

    // y range with headroom for the legend.
    let (y_lo, y_hi, y_bold, y_light) = if log_y {
        let lo = ymin / 1.5;
        let hi = ymax * 3f64.powf(legend_room);
        let (b, l) = log_ticks(lo, hi);
        (lo.log10(), hi.log10(), b, l)
    } else {
        let lo = if ymin >= 0.0 { 0.0 } else { ymin - 0.05 * (ymax - ymin) };
        let hi = if ymax > lo { ymax + 0.35 * legend_room * (ymax - lo) } else { lo + 1.0 };
        (lo, hi, linear_ticks(lo, hi), Vec::new())
    };
    let (x_lo, x_hi, x_bold) = match &chart.x {
        XAxis::Log2(ticks) => {
            let t: Vec<f64> = ticks.iter().map(|v| v.log2()).collect();
            let lo = t.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = t.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let pad = if hi > lo { 0.06 * (hi - lo) } else { 0.5 };
            (lo - pad, hi + pad, t)
        }
        XAxis::Linear(lo, hi) => (*lo, *hi, linear_ticks(*lo, *hi)),
    };

    // Legend on the upper side whose data stays lower.
    let mid = 0.5 * (x_lo + x_hi);
    let side_max = |left: bool| {
        pts()
            .filter(|p| (tx(p.0) < mid) == left && p.1.is_finite() && (!log_y || p.1 > 0.0))
            .map(|p| ty(p.1))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let legend_pos = if side_max(true) <= side_max(false) {
        SeriesLabelPosition::UpperLeft
    } else {
        SeriesLabelPosition::UpperRight
    };

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, chart.size).into_drawing_area();
        let err = |e: &dyn fmt::Display| anyhow!("drawing {:?}: {e}", chart.title);
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let mut ctx = ChartBuilder::on(&root)
            .caption(&chart.title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(80)
            .build_cartesian_2d(
                TickAxis { lo: x_lo, hi: x_hi, bold: x_bold, light: Vec::new() },
                TickAxis { lo: y_lo, hi: y_hi, bold: y_bold, light: y_light },
            )
            .map_err(|e| err(&e))?;
        let is_log2 = matches!(chart.x, XAxis::Log2(_));
        let x_fmt = |x: &f64| tick_label(if is_log2 { x.exp2() } else { *x });
        let y_fmt = |y: &f64| tick_label(if log_y { 10f64.powf(*y) } else { *y });
        ctx.configure_mesh()
            .x_desc(chart.x_label.as_str())
            .y_desc(chart.y_label.as_str())
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&y_fmt)
            .axis_desc_style(("sans-serif", 17))
            .label_style(("sans-serif", 14))
            .bold_line_style(BLACK.mix(0.15))
            .light_line_style(BLACK.mix(0.05))
            .draw()
            .map_err(|e| err(&e))?;

        for s in &chart.series {
            let data: Vec<(f64, f64)> = s
                .points
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite() && (!log_y || p.1 > 0.0))
                .map(|&(x, y)| (tx(x), ty(y)))
                .collect();
            let color = s.color;
            let stroke = color.stroke_width(2);
            let fill = color.filled();
            let marker = s.marker;
            if s.line {
                let anno = if s.dashed {
                    ctx.draw_series(DashedLineSeries::new(data.iter().copied(), 9, 6, stroke))
                        .map_err(|e| err(&e))?
                } else {
                    ctx.draw_series(LineSeries::new(data.iter().copied(), stroke)).map_err(|e| err(&e))?
                };
                if marker == Marker::None {
                    set_legend(anno.label(s.label.as_str()), color, true, marker, s.dashed);
                }
            }
            let marker_anno = match marker {
                Marker::None => None,
                Marker::Circle => Some(
                    ctx.draw_series(data.iter().map(|&p| Circle::new(p, 4, fill))).map_err(|e| err(&e))?,
                ),
                Marker::Triangle => Some(
                    ctx.draw_series(data.iter().map(|&p| TriangleMarker::new(p, 5, fill)))
                        .map_err(|e| err(&e))?,
                ),
                Marker::Square => Some(
                    ctx.draw_series(
                        data.iter().map(|&p| EmptyElement::at(p) + Rectangle::new([(-4, -4), (4, 4)], fill)),
                    )
                    .map_err(|e| err(&e))?,
                ),
                Marker::Cross => Some(
                    ctx.draw_series(data.iter().map(|&p| Cross::new(p, 5, stroke))).map_err(|e| err(&e))?,
                ),
            };
            if let Some(anno) = marker_anno {
                set_legend(anno.label(s.label.as_str()), color, s.line, marker, s.dashed);
            }
            if !s.point_labels.is_empty() {
                use plotters::style::text_anchor::{HPos, Pos, VPos};
                // Right of the point in the left half of the chart, left of it in the right half.
                let font = ("sans-serif", 14).into_font().color(&color);
                let left = font.clone().pos(Pos::new(HPos::Left, VPos::Center));
                let right = font.pos(Pos::new(HPos::Right, VPos::Center));
                ctx.draw_series(data.iter().zip(&s.point_labels).map(|(&p, t)| {
                    let (dx, style) = if p.0 > mid { (-9, right.clone()) } else { (9, left.clone()) };
                    EmptyElement::at(p) + Text::new(t.clone(), (dx, 0), style)
                }))
                .map_err(|e| err(&e))?;
            }
        }
        ctx.configure_series_labels()
            .position(legend_pos)
            .label_font(("sans-serif", 15))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_and_labels() {
        assert_eq!(tick_label(8.0), "8");
        assert_eq!(tick_label(2.0f64.log2().exp2()), "2");
        assert_eq!(tick_label(0.5), "0.5");
        assert_eq!(tick_label(1e6), "1e6");
        let t = linear_ticks(0.0, 10.0);
        assert!(t.len() >= 4 && t[0] == 0.0);
        let (bold, _) = log_ticks(1.0, 1000.0);
        assert!(bold.contains(&0.0) && bold.iter().any(|v| (v - 3.0).abs() < 1e-12));
    }
}
