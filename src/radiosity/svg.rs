//! The picture of a solve (`shelling radiosity --svg FILE`): the scene with each patch coloured
//! by its radiosity (viridis, with a colour bar over the patches that do not emit; the lights, far
//! brighter, take the top colour), beside the convergence curve.

use super::solve::Solution;
use crate::scene::Scene;
use plotters::prelude::*;

/// The SVG text of `solution` over `scene`; `what` names the convergence measure on the y axis.
pub fn render(scene: &Scene, solution: &Solution, title: &str, what: &str) -> Result<String, String> {
    let err = |e: &dyn std::fmt::Display| format!("drawing the radiosity picture: {e}");
    let b = &solution.radiosity;
    // The colour scale spans the patches that do not emit (the lights outshine the rest by orders
    // of magnitude and are drawn at the top colour); a scene where everything emits uses all.
    let lit = |i: usize| scene.material(i).emission_or_default() > 0.0;
    let reflecting: Vec<f64> = (0..b.len()).filter(|&i| !lit(i)).map(|i| b[i]).collect();
    let scale = if reflecting.is_empty() { b.as_slice() } else { reflecting.as_slice() };
    let (lo, hi) = scale.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| (l.min(v), h.max(v)));
    let hi = if hi > lo { hi } else { lo + 1.0 };
    let bounds = scene.bounds();
    let size = bounds.size();
    let pad = 0.04 * size.x.max(size.y);

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1200, 560)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let root = root.titled(title, ("sans-serif", 22)).map_err(|e| err(&e))?;
        let (left, right) = root.split_horizontally(560);
        let (bar, curve) = right.split_horizontally(110);

        let mut scene_chart = ChartBuilder::on(&left)
            .margin(16)
            .x_label_area_size(30)
            .y_label_area_size(50)
            .build_cartesian_2d(
                (bounds.min.x - pad)..(bounds.min.x + size.x.max(size.y) + pad),
                (bounds.min.y - pad)..(bounds.min.y + size.x.max(size.y) + pad),
            )
            .map_err(|e| err(&e))?;
        scene_chart.configure_mesh().disable_mesh().draw().map_err(|e| err(&e))?;
        for (seg, &v) in scene.segments.iter().zip(b) {
            let colour = viridis((v - lo) / (hi - lo));
            scene_chart
                .draw_series(LineSeries::new(
                    [(seg.a.x, seg.a.y), (seg.b.x, seg.b.y)],
                    colour.stroke_width(4),
                ))
                .map_err(|e| err(&e))?;
        }

        let mut bar_chart = ChartBuilder::on(&bar)
            .margin_top(16)
            .margin_bottom(46)
            .y_label_area_size(60)
            .caption("B", ("sans-serif", 16))
            .build_cartesian_2d(0.0..1.0, lo..hi)
            .map_err(|e| err(&e))?;
        bar_chart
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .label_style(("sans-serif", 12))
            .draw()
            .map_err(|e| err(&e))?;
        let steps = 64;
        bar_chart
            .draw_series((0..steps).map(|k| {
                let y0 = lo + (hi - lo) * k as f64 / steps as f64;
                let y1 = lo + (hi - lo) * (k + 1) as f64 / steps as f64;
                let colour = viridis((0.5 * (y0 + y1) - lo) / (hi - lo));
                Rectangle::new([(0.0, y0), (1.0, y1)], colour.filled())
            }))
            .map_err(|e| err(&e))?;

        let history: Vec<(f64, f64)> = solution
            .history
            .iter()
            .enumerate()
            .filter(|(_, &v)| v > 0.0)
            .map(|(k, &v)| ((k + 1) as f64, v.log10()))
            .collect();
        let y_lo = history.iter().map(|p| p.1).fold(0.0f64, f64::min).floor() - 0.2;
        let x_hi = (history.len().max(1) + 1) as f64;
        let mut curve_chart = ChartBuilder::on(&curve)
            .margin(16)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .caption("convergence", ("sans-serif", 16))
            .build_cartesian_2d(0.0..x_hi, y_lo..0.2)
            .map_err(|e| err(&e))?;
        let y_fmt = |y: &f64| format!("{:.0e}", 10f64.powf(*y));
        curve_chart
            .configure_mesh()
            .x_desc("step")
            .y_desc(what)
            .y_label_formatter(&y_fmt)
            .draw()
            .map_err(|e| err(&e))?;
        curve_chart.draw_series(LineSeries::new(history, BLUE.stroke_width(2))).map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(svg)
}

/// The viridis colour map at `x ∈ [0, 1]` (clamped), interpolated between nine of its stops.
fn viridis(x: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 9] = [
        (68, 1, 84),
        (71, 44, 122),
        (59, 81, 139),
        (44, 113, 142),
        (33, 144, 141),
        (39, 173, 129),
        (92, 200, 99),
        (170, 220, 50),
        (253, 231, 37),
    ];
    let x = if x.is_finite() { x.clamp(0.0, 1.0) } else { 0.0 } * (STOPS.len() - 1) as f64;
    let k = (x as usize).min(STOPS.len() - 2);
    let f = x - k as f64;
    let mix = |a: u8, b: u8| (a as f64 + (b as f64 - a as f64) * f).round() as u8;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}
