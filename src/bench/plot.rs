//! The error-against-time picture of a knob sweep, as SVG (plotters' SVG backend): x is
//! ms/frame (median, with the min–max spread as a bar), y the mean error against the
//! reference frames; each point is labelled with its knob value.

use std::path::Path;

use plotters::prelude::*;

use super::KnobReport;

/// Writes one chart per report, stacked vertically, into `path`.
pub fn write_svg(path: &Path, reports: &[KnobReport]) -> Result<(), String> {
    if reports.is_empty() {
        return Err("no sweep to plot".into());
    }
    let height = 420 * reports.len() as u32;
    let root = SVGBackend::new(path, (720, height)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    for (area, r) in root.split_evenly((reports.len(), 1)).iter().zip(reports) {
        chart(area, r).map_err(|e| format!("cannot draw the plot: {e}"))?;
    }
    root.present().map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn chart(area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>, r: &KnobReport) -> Result<(), Box<dyn std::error::Error>> {
    let x_max = r.rows.iter().map(|row| row.ms_max).fold(0.0f64, f64::max) * 1.1 + 1e-3;
    let y_max = r.rows.iter().map(|row| row.mean_error).fold(0.0f64, f64::max) * 1.15 + 1e-3;
    let mut chart = ChartBuilder::on(area)
        .caption(format!("{}: mean error vs time, knob {}", r.program, r.knob), ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(56)
        .build_cartesian_2d(0.0..x_max, 0.0..y_max)?;
    chart.configure_mesh().x_desc(format!("ms/frame ({})", r.clock)).y_desc("mean abs error vs reference (8-bit levels)").draw()?;
    let mut points: Vec<(f64, f64, f64)> = r.rows.iter().map(|row| (row.ms_median, row.mean_error, row.value)).collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    chart.draw_series(LineSeries::new(points.iter().map(|(x, y, _)| (*x, *y)), BLUE.stroke_width(2)))?;
    for row in &r.rows {
        chart.draw_series(LineSeries::new([(row.ms_min, row.mean_error), (row.ms_max, row.mean_error)], BLUE.mix(0.4)))?;
    }
    chart.draw_series(points.iter().map(|(x, y, v)| {
        EmptyElement::at((*x, *y))
            + Circle::new((0, 0), 4, BLUE.filled())
            + Text::new(super::number(*v), (6, -14), ("sans-serif", 13).into_font())
    }))?;
    Ok(())
}
