//! The Pareto plot.

use super::figures::{PointFigures, LUT4_PER_MAC16};
use super::pareto::pareto;
use std::path::Path;

/// The Pareto plot: mean colour error against cost, one colour per scene, the Pareto set joined.
pub fn plot(rs: &[PointFigures], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let font = crate::fonts::sans()?;
    // drawn beside its place and moved there whole (the encoder picks the format by the name's extension)
    let tmp = path.with_extension("partial.png");
    {
        let root = BitMapBackend::new(&tmp, (1000, 640)).into_drawing_area();
        let e = |x: String| x;
        root.fill(&WHITE).map_err(|x| e(x.to_string()))?;
        let xmax = rs.iter().map(|r| r.cost()).max().unwrap_or(1) as f64 * 1.08;
        // the errors span two orders of magnitude (a quantized palette against one light for a whole surface):
        // a logarithmic axis
        let ymax = rs.iter().map(|r| r.colour.0).fold(0.1f64, f64::max) * 1.3;
        let ymin = rs.iter().map(|r| r.colour.0).filter(|e| *e > 0.0).fold(ymax, f64::min) * 0.7;
        let mut chart = ChartBuilder::on(&root)
            .caption("bumprtl: mean colour error against cost", (font, 22))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(60)
            .build_cartesian_2d(0f64..xmax, (ymin..ymax).log_scale())
            .map_err(|x| e(x.to_string()))?;
        chart
            .configure_mesh()
            .x_desc(format!("cost: iCE40 SB_LUT4 + {LUT4_PER_MAC16}·SB_MAC16"))
            .y_desc("mean colour error, 8-bit LSB (log scale)")
            .label_style((font, 14))
            .draw()
            .map_err(|x| e(x.to_string()))?;
        let on = pareto(rs);
        let mut scenes: Vec<&str> = vec![];
        for r in rs {
            if !scenes.contains(&r.scene.as_str()) {
                scenes.push(&r.scene);
            }
        }
        let palette = [RGBColor(31, 119, 180), RGBColor(214, 39, 40), RGBColor(44, 160, 44), RGBColor(148, 103, 189)];
        // (the point in pixels, its label, its scene's colour)
        let mut labels: Vec<((i32, i32), String, RGBColor)> = vec![];
        for (k, sc) in scenes.iter().enumerate() {
            let col = palette[k % palette.len()];
            let pts: Vec<(f64, f64, bool, &str)> = rs
                .iter()
                .zip(&on)
                .filter(|(r, _)| r.scene == *sc)
                .map(|(r, p)| (r.cost() as f64, r.colour.0, *p, r.id.as_str()))
                .collect();
            chart
                .draw_series(pts.iter().map(|&(x, y, p, _)| {
                    Circle::new((x, y), if p { 6 } else { 4 }, if p { col.filled() } else { col.stroke_width(1) })
                }))
                .map_err(|x| e(x.to_string()))?
                .label(format!("scene {sc}"))
                .legend(move |(x, y)| Circle::new((x + 8, y), 5, col.filled()));
            let mut front: Vec<(f64, f64)> = pts.iter().filter(|p| p.2).map(|p| (p.0, p.1)).collect();
            front.sort_by(|a, b| a.0.total_cmp(&b.0));
            chart.draw_series(LineSeries::new(front, col.stroke_width(2))).map_err(|x| e(x.to_string()))?;
            for &(x, y, p, id) in &pts {
                if p {
                    let label = id.split_once('.').map_or(id, |(_, rest)| rest).to_string();
                    labels.push((chart.backend_coord(&(x, y)), label, col));
                }
            }
        }
        // the Pareto points' labels, each beside its point where it overlaps no label placed before it (nearest
        // first, up or down a line at a time), joined to its point by a thin line when moved
        let style = (font, 12).into_font().color(&BLACK);
        let area = chart.plotting_area().get_pixel_range();
        labels.sort_by_key(|l| (l.0 .0, l.0 .1));
        let mut placed: Vec<(i32, i32, i32, i32)> = vec![];
        for ((px, py), label, col) in labels {
            let (w, h) = root.estimate_text_size(&label, &style).map_err(|x| e(x.to_string()))?;
            let (w, h) = (w as i32, h as i32 + 2);
            // right of the point, or left of it where the right runs off the plot
            let x0 = if px + 8 + w <= area.0.end { px + 8 } else { px - 8 - w };
            let clear = |y0: i32| {
                y0 >= area.1.start
                    && y0 + h <= area.1.end
                    && placed.iter().all(|b| x0 + w <= b.0 || b.2 <= x0 || y0 + h <= b.1 || b.3 <= y0)
            };
            let y0 =
                (0..40).flat_map(|k| [k, -k]).map(|k| py - h / 2 + k * h).find(|&y| clear(y)).unwrap_or(py - h / 2);
            placed.push((x0, y0, x0 + w, y0 + h));
            if (y0 + h / 2 - py).abs() > h / 2 {
                let end = (if x0 > px { x0 - 1 } else { x0 + w + 1 }, y0 + h / 2);
                root.draw(&PathElement::new(vec![(px, py), end], col.mix(0.5))).map_err(|x| e(x.to_string()))?;
            }
            root.draw(&Text::new(label, (x0, y0), style.clone())).map_err(|x| e(x.to_string()))?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font((font, 14))
            .draw()
            .map_err(|x| e(x.to_string()))?;
        root.present().map_err(|x| e(x.to_string()))?;
    }
    std::fs::rename(&tmp, path).map_err(|e| format!("{}: {e}", path.display()))
}
