use super::*;

fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| t.split_once('>').map(|(_, rest)| rest))
        .filter_map(|t| t.split_once("</text>").map(|(v, _)| v.trim().to_string()))
        .collect()
}

/// Issue 17: a series identical to another says so in the legend, a series with no
/// points is left out of it, and intervals are drawn (one error bar and two caps per
/// point).
#[test]
fn legends_name_twins_and_skip_empty_series_and_intervals_are_drawn() {
    let pts = |ci: Option<[f64; 2]>| vec![(2.0, 1.0, ci), (4.0, 2.0, ci)];
    let lines = vec![
        Line {
            name: "discriminant_f64".into(),
            colour: 0,
            pts: pts(None),
        },
        Line {
            name: "no_batch_data".into(),
            colour: 1,
            pts: Vec::new(),
        },
        Line {
            name: "discriminant".into(),
            colour: 2,
            pts: pts(None),
        },
        Line {
            name: "skala".into(),
            colour: 3,
            pts: vec![(2.0, 2.5, Some([2.0, 3.0])), (4.0, 2.5, Some([2.4, 2.6]))],
        },
    ];
    let mut svg = String::new();
    draw_chart(&mut svg, "title (w, abc1234)", (NU_AXIS, "y"), &lines, true).unwrap();
    let t = texts(&svg);
    assert!(
        t.iter().any(|x| x == "discriminant (= discriminant_f64)"),
        "{t:?}"
    );
    assert!(!t.iter().any(|x| x.contains("no_batch_data")), "{t:?}");
    // Issue 29: the canvas is wide enough for the longest entry (it was cut at
    // "discriminant (= dis"), and the twin under another line is drawn wider, so both
    // colours show.
    let width: u32 = svg
        .split("width=\"")
        .nth(1)
        .and_then(|w| w.split('"').next())
        .and_then(|w| w.parse().ok())
        .unwrap();
    let longest = "discriminant (= discriminant_f64)".len() as u32;
    assert!(width >= PLOT_WIDTH + LEGEND_TEXT_X + 7 * longest, "{width}");
    // The widest stroke of a colour's polylines inside the plot (the legend's sample
    // strokes, right of PLOT_WIDTH, are 3 px for every line).
    let strokes = |colour: &str| {
        svg.split('<')
            .filter(|e| e.starts_with("polyline") && e.contains(colour))
            .filter(|e| {
                let x = e
                    .split("points=\"")
                    .nth(1)
                    .and_then(|p| p.split(',').next());
                x.and_then(|x| x.parse::<u32>().ok())
                    .is_some_and(|x| x < PLOT_WIDTH)
            })
            .filter_map(|e| {
                e.split("stroke-width=\"")
                    .nth(1)?
                    .split('"')
                    .next()?
                    .parse::<u32>()
                    .ok()
            })
            .max()
    };
    // discriminant_f64 (COLOURS[0]) lies under discriminant (COLOURS[2]).
    assert_eq!(strokes("stroke=\"#787878\""), Some(5), "{svg}");
    assert_eq!(strokes("stroke=\"#FF7F0E\""), Some(2), "{svg}");
    assert!(t.iter().any(|x| x.contains("abc1234")), "{t:?}");
    let without = {
        let mut s = String::new();
        let no_ci: Vec<Line> = lines
            .iter()
            .map(|l| Line {
                name: l.name.clone(),
                colour: l.colour,
                pts: l.pts.iter().map(|&(x, y, _)| (x, y, None)).collect(),
            })
            .collect();
        draw_chart(&mut s, "title", (NU_AXIS, "y"), &no_ci, true).unwrap();
        s
    };
    // skala's colour (index 3): its line and markers, plus a bar and two caps for each
    // of its two intervals.
    let skala = |s: &str| {
        s.split('<')
            .filter(|e| e.starts_with("line") || e.starts_with("polyline"))
            .filter(|e| e.contains("stroke=\"#2CA02C\""))
            .count()
    };
    assert_eq!(
        skala(&svg),
        skala(&without) + 2 * 3,
        "two points with an interval: a bar and two caps each"
    );
}
